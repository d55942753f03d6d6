#include "coinspect/world/ray_caster.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::world {
namespace {

static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "vertices are copied as float triples");
static_assert(sizeof(std::array<uint32_t, 3>) == 3 * sizeof(uint32_t),
              "triangles are copied as index triples");

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr size_t kPacket = 16;

// Embree tests hits with t <= tfar, so a facet exactly at the far end would count; the rule
// "clear when the first hit is >= length - tolerance" wants it excluded. Returns 0 when no
// positive float lies below t (then nothing can block). Steps the float's bits directly, since
// std::nextafter is an out-of-line libm call on the hot path of segment queries.
float justBelow(double t) {
  const float f = static_cast<float>(t);
  if (!(f > 0.0f)) return 0.0f;
  if (f == kInfinity) return std::numeric_limits<float>::max();
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  --bits;  // positive finite floats are ordered like their bit patterns
  float below;
  std::memcpy(&below, &bits, sizeof below);
  return below;
}

// Closest point to p on triangle (a, b, c), by the Voronoi regions of its vertices, edges and
// face (Ericson, Real-Time Collision Detection, 5.1.5), in double precision.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = va + vb + vc;
  // Degenerate (zero-area) facets end here with a zero denominator: any vertex is as good.
  if (!(denominator > 0.0)) return a;
  return a + ab * (vb / denominator) + ac * (vc / denominator);
}

void initRay(RTCRay& ray, const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
             float tfar) {
  ray.org_x = origin.x();
  ray.org_y = origin.y();
  ray.org_z = origin.z();
  ray.tnear = 0.0f;
  ray.dir_x = direction.x();
  ray.dir_y = direction.y();
  ray.dir_z = direction.z();
  ray.time = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xffffffffu;
  ray.id = 0;
  ray.flags = 0;
}

// initRay for lane k of a packet (its id is the lane).
inline void initLane(RTCRay16& packet, size_t k, const Eigen::Vector3f& origin,
                     const Eigen::Vector3f& direction, float tfar) {
  packet.org_x[k] = origin.x();
  packet.org_y[k] = origin.y();
  packet.org_z[k] = origin.z();
  packet.dir_x[k] = direction.x();
  packet.dir_y[k] = direction.y();
  packet.dir_z[k] = direction.z();
  packet.tnear[k] = 0.0f;
  packet.tfar[k] = tfar;
  packet.time[k] = 0.0f;
  packet.mask[k] = 0xffffffffu;
  packet.id[k] = static_cast<unsigned>(k);
  packet.flags[k] = 0;
}

RTCRay16& rayOf(RTCRay16& packet) {
  return packet;
}
RTCRay16& rayOf(RTCRayHit16& packet) {
  return packet.ray;
}

// A lane no query uses. Embree honours the valid mask only where the CPU has native 16-wide
// kernels (AVX-512); elsewhere rtcIntersect16/rtcOccluded16 go through its ray-stream path,
// which takes every lane with tnear <= tfar as active and asserts that it is a valid ray. So
// idle lanes get a finite ray with tfar < tnear, never leftovers of an earlier packet.
inline void idleLane(RTCRay16& packet, size_t k) {
  initLane(packet, k, Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitZ(), -1.0f);
}

// Runs n queries through Embree kPacket at a time, without allocating. setUp(i, packet, k) fills
// lane k for query i and returns false when that query needs no ray; trace(valid, packet) calls
// Embree; collect(i, packet, k) then reads the result of each lane that was traced.
template <class Packet, class SetUp, class Trace, class Collect>
inline void tracePackets(size_t n, const SetUp& setUp, const Trace& trace, const Collect& collect) {
  alignas(64) Packet packet;
  alignas(64) int valid[kPacket];
  for (size_t start = 0; start < n; start += kPacket) {
    const size_t count = std::min(kPacket, n - start);
    for (size_t k = 0; k < kPacket; ++k) {
      valid[k] = k < count && setUp(start + k, packet, k) ? -1 : 0;
      if (valid[k] == 0) idleLane(rayOf(packet), k);
    }
    trace(valid, packet);
    for (size_t k = 0; k < count; ++k)
      if (valid[k] != 0) collect(start + k, packet, k);
  }
}

}  // namespace

struct RayCaster::Impl {
  struct Geometry {
    const float* vertices = nullptr;  // Embree-owned buffers, alive as long as the scene
    const uint32_t* indices = nullptr;
  };

  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<Geometry> geometries;  // by geometry id; the ground is the last when present
  uint32_t groundId = RTC_INVALID_GEOMETRY_ID;
  double groundZ = 0.0;
  size_t meshTriangles = 0;
  std::mutex errorMutex;
  std::string firstError;

  ~Impl() {
    if (scene != nullptr) rtcReleaseScene(scene);
    if (device != nullptr) rtcReleaseDevice(device);
  }

  // Embree reports errors through a C callback: throwing across its frames is not safe, so the
  // message is kept and thrown from check() once control is back in our code.
  static void onError(void* user, RTCError, const char* message) {
    auto* self = static_cast<Impl*>(user);
    std::lock_guard<std::mutex> lock(self->errorMutex);
    if (self->firstError.empty()) self->firstError = message != nullptr ? message : "unknown";
  }

  void check(const char* step) {
    const RTCError code = rtcGetDeviceError(device);
    std::lock_guard<std::mutex> lock(errorMutex);
    if (code == RTC_ERROR_NONE && firstError.empty()) return;
    throw std::runtime_error(
        std::string("Embree failed while ") + step + ": " +
        (firstError.empty() ? "error code " + std::to_string(code) : firstError));
  }

  void addTriangles(uint32_t id, const std::vector<Eigen::Vector3f>& vertices,
                    const std::vector<std::array<uint32_t, 3>>& triangles) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    check("creating a geometry");
    // Embree allocates (and pads) its own buffers: one copy, and the caster does not depend on
    // the caller keeping the meshes alive.
    auto* vertexBuffer = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), vertices.size()));
    auto* indexBuffer = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), triangles.size()));
    check("allocating geometry buffers");
    std::memcpy(vertexBuffer, vertices.data(), vertices.size() * 3 * sizeof(float));
    std::memcpy(indexBuffer, triangles.data(), triangles.size() * 3 * sizeof(uint32_t));
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, id);
    rtcReleaseGeometry(geometry);
    check("attaching a geometry");
    geometries[id] = {vertexBuffer, indexBuffer};
  }

  Vec3 vertex(const Geometry& g, uint32_t index) const {
    const float* v = g.vertices + 3 * static_cast<size_t>(index);
    return Vec3(v[0], v[1], v[2]);
  }

  // Right-hand-rule unit normal, the convention of TriangleMesh::facetNormal (computed from the
  // vertices rather than Embree's Ng so it does not depend on Embree's winding convention).
  Vec3 facetNormal(uint32_t geometry, uint32_t triangle) const {
    const Geometry& g = geometries[geometry];
    const uint32_t* t = g.indices + 3 * static_cast<size_t>(triangle);
    const Vec3 a = vertex(g, t[0]);
    const Vec3 n = (vertex(g, t[1]) - a).cross(vertex(g, t[2]) - a);
    const double length = n.norm();
    return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
  }

  struct PointQueryState {
    const Impl* impl;
    Vec3 point;
    double best;
  };

  static bool onPointQuery(RTCPointQueryFunctionArguments* args) {
    auto* state = static_cast<PointQueryState*>(args->userPtr);
    const Impl& impl = *state->impl;
    if (args->geomID == impl.groundId) return false;
    const Geometry& g = impl.geometries[args->geomID];
    const uint32_t* t = g.indices + 3 * static_cast<size_t>(args->primID);
    const Vec3 closest = closestPointOnTriangle(state->point, impl.vertex(g, t[0]),
                                                impl.vertex(g, t[1]), impl.vertex(g, t[2]));
    const double distance = (closest - state->point).norm();
    if (distance >= state->best) return false;
    state->best = distance;
    // Rounded up so that float rounding never prunes a facet closer than the best so far.
    const float radius = std::nextafter(static_cast<float>(distance), kInfinity);
    if (radius >= args->query->radius) return false;
    args->query->radius = radius;
    return true;
  }
};

RayCaster::RayCaster(const std::vector<TriangleMesh>& meshes, std::optional<double> groundZ,
                     double groundHalfExtent)
    : impl_(std::make_unique<Impl>()) {
  Impl& impl = *impl_;
  impl.device = rtcNewDevice(nullptr);
  if (impl.device == nullptr)
    throw std::runtime_error("Embree failed to create a device (error code " +
                             std::to_string(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceErrorFunction(impl.device, &Impl::onError, &impl);
  impl.scene = rtcNewScene(impl.device);
  impl.check("creating the scene");
  // Robust mode. Measured here: rays from inside a closed tessellated sphere aimed exactly at
  // its vertices and edge midpoints (2.8M rays) escaped through the surface 14% of the time in
  // Embree's default mode and 0.14% in robust mode. Lines of sight aimed at mesh vertices (as
  // interest points often are) must not leak, so robust it is; on the MBS mesh it costs 6-15%
  // of the ray rate (bench/ray_caster_bench.cpp, BM_Bare*/0 against /1).
  rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl.scene, RTC_BUILD_QUALITY_MEDIUM);

  impl.geometries.resize(meshes.size() + (groundZ ? 1 : 0));
  Aabb box;
  for (size_t i = 0; i < meshes.size(); ++i) {
    const TriangleMesh& mesh = meshes[i];
    if (mesh.triangles.empty()) continue;
    for (const auto& t : mesh.triangles)
      for (const uint32_t v : t)
        COINSPECT_ASSERT(v < mesh.vertices.size());
    impl.addTriangles(static_cast<uint32_t>(i), mesh.vertices, mesh.triangles);
    impl.meshTriangles += mesh.triangles.size();
    const Aabb b = mesh.bounds();
    box.extend(b.min);
    box.extend(b.max);
  }
  if (groundZ) {
    impl.groundId = static_cast<uint32_t>(meshes.size());
    impl.groundZ = *groundZ;
    const Vec3 centre = box.empty() ? Vec3::Zero() : Vec3(0.5 * (box.min + box.max));
    const auto corner = [&](double sx, double sy) {
      return Eigen::Vector3f(static_cast<float>(centre.x() + sx * groundHalfExtent),
                             static_cast<float>(centre.y() + sy * groundHalfExtent),
                             static_cast<float>(*groundZ));
    };
    // Counter-clockwise seen from above: the right-hand normal points up.
    const std::vector<Eigen::Vector3f> vertices{corner(-1, -1), corner(1, -1), corner(1, 1),
                                                corner(-1, 1)};
    const std::vector<std::array<uint32_t, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
    impl.addTriangles(impl.groundId, vertices, triangles);
  }
  rtcCommitScene(impl.scene);
  impl.check("building the scene");
}

RayCaster::~RayCaster() = default;
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;

std::optional<RayHit> RayCaster::closestHit(const Vec3& origin, const Vec3& direction,
                                            double maxRange) const {
  const double norm = direction.norm();
  if (!(norm > 0.0) || !(maxRange > 0.0)) return std::nullopt;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  initRay(rayHit.ray, origin.cast<float>(), (direction / norm).cast<float>(),
          static_cast<float>(maxRange));
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  RayHit hit;
  hit.distance = rayHit.ray.tfar;
  hit.geometry = rayHit.hit.geomID;
  hit.triangle = rayHit.hit.primID;
  hit.normal = impl_->facetNormal(hit.geometry, hit.triangle);
  return hit;
}

bool RayCaster::segmentClear(const Vec3& a, const Vec3& b, double tolerance) const {
  const Vec3 delta = b - a;
  const double length = delta.norm();
  const float reach = justBelow(length - tolerance);
  if (!(reach > 0.0f)) return true;  // no hit can be closer than a non-positive distance
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  initRay(ray, a.cast<float>(), (delta * (1.0 / length)).cast<float>(), reach);
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar >= 0.0f;  // Embree sets tfar to -inf when something blocks the ray
}

void RayCaster::closestHits(const std::vector<Vec3>& origins, const std::vector<Vec3>& directions,
                            double maxRange, std::vector<double>& distances) const {
  COINSPECT_ASSERT(origins.size() == directions.size());
  const size_t n = origins.size();
  distances.assign(n, std::numeric_limits<double>::infinity());
  if (!(maxRange > 0.0)) return;
  const float tfar = static_cast<float>(maxRange);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  tracePackets<RTCRayHit16>(
      n,
      [&](size_t i, RTCRayHit16& packet, size_t k) {
        const Vec3& d = directions[i];
        const double norm = d.norm();
        if (!(norm > 0.0)) return false;
        initLane(packet.ray, k, origins[i].cast<float>(), (d / norm).cast<float>(), tfar);
        packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        return true;
      },
      [&](const int* valid, RTCRayHit16& packet) {
        rtcIntersect16(valid, impl_->scene, &context, &packet);
      },
      [&](size_t i, const RTCRayHit16& packet, size_t k) {
        if (packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID) distances[i] = packet.ray.tfar[k];
      });
}

void RayCaster::segmentsClear(const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                              double tolerance, std::vector<uint8_t>& clear) const {
  COINSPECT_ASSERT(from.size() == to.size());
  const size_t n = from.size();
  clear.assign(n, 1);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  tracePackets<RTCRay16>(
      n,
      [&](size_t i, RTCRay16& packet, size_t k) {
        const Vec3& a = from[i];
        const Vec3 delta = to[i] - a;
        const double length = delta.norm();
        const float reach = justBelow(length - tolerance);
        if (!(reach > 0.0f)) return false;
        const double inverse = 1.0 / length;
        initLane(packet, k, a.cast<float>(), (delta * inverse).cast<float>(), reach);
        return true;
      },
      [&](const int* valid, RTCRay16& packet) {
        rtcOccluded16(valid, impl_->scene, &context, &packet);
      },
      [&](size_t i, const RTCRay16& packet, size_t k) {
        if (!(packet.tfar[k] >= 0.0f)) clear[i] = 0;
      });
}

double RayCaster::distanceToSurface(const Vec3& p, double maxDistance) const {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  if (impl_->meshTriangles == 0 || maxDistance < 0.0) return kNone;
  RTCPointQuery query;
  query.x = static_cast<float>(p.x());
  query.y = static_cast<float>(p.y());
  query.z = static_cast<float>(p.z());
  query.time = 0.0f;
  query.radius = maxDistance >= static_cast<double>(std::numeric_limits<float>::max())
                     ? kInfinity
                     : std::nextafter(static_cast<float>(maxDistance), kInfinity);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  Impl::PointQueryState state{impl_.get(), p, kNone};
  rtcPointQuery(impl_->scene, &query, &context, &Impl::onPointQuery, &state);
  return state.best <= maxDistance ? state.best : kNone;
}

size_t RayCaster::meshTriangleCount() const {
  return impl_->meshTriangles;
}
bool RayCaster::hasGround() const {
  return impl_->groundId != RTC_INVALID_GEOMETRY_ID;
}
double RayCaster::groundZ() const {
  return impl_->groundZ;
}

}  // namespace coinspect::world
