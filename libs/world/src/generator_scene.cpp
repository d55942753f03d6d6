// The scene of closed parts, interest point sampling and scenario assembly for the generators.
#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"
#include "generator_detail.h"

namespace coinspect::world::detail {

namespace {

// Parity rays need a direction that is unlikely to graze the axis-aligned edges and faces the
// primitives are made of.
const Vec3 kParityDirection = Vec3(0.3713, 0.5121, 0.7741).normalized();
// Coordinates across the parity direction (the plane the triangles' shadows are bucketed in).
const Vec3 kAcross1 = kParityDirection.cross(Vec3::UnitZ()).normalized();
const Vec3 kAcross2 = kParityDirection.cross(kAcross1);

Vec2 shadow(const Vec3& p) {
  return {p.dot(kAcross1), p.dot(kAcross2)};
}

// Möller-Trumbore: does the ray origin + t dir, t > 0, cross the triangle?
bool rayCrossesTriangle(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b,
                        const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 h = dir.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-14) return false;
  const double inv = 1.0 / det;
  const Vec3 s = origin - a;
  const double u = inv * s.dot(h);
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 q = s.cross(e1);
  const double v = inv * dir.dot(q);
  if (v < 0.0 || u + v > 1.0) return false;
  return inv * e2.dot(q) > 1e-12;
}

int64_t packCell(int64_t x, int64_t y, int64_t z) {
  constexpr int64_t bias = int64_t{1} << 20;
  return ((x + bias) << 42) | ((y + bias) << 21) | (z + bias);
}

int cellOf(double value, double cell) {
  return static_cast<int>(std::floor(value / cell));
}

}  // namespace

// ---- SceneBuilder ----------------------------------------------------------------------------

void SceneBuilder::add(const std::string& structure, TriangleMesh part) {
  COINSPECT_ASSERT(!part.triangles.empty());
  part.name = structure;
  Part entry{structure, std::move(part), Aabb{}};
  entry.bounds = entry.mesh.bounds();
  parts_.push_back(std::move(entry));
}

std::vector<TriangleMesh> SceneBuilder::meshes() const {
  std::vector<TriangleMesh> result;
  for (const Part& part : parts_) {
    auto it = std::find_if(result.begin(), result.end(),
                           [&](const TriangleMesh& m) { return m.name == part.structure; });
    if (it == result.end()) {
      result.push_back(TriangleMesh{});
      result.back().name = part.structure;
      it = result.end() - 1;
    }
    it->append(part.mesh);
  }
  return result;
}

Aabb SceneBuilder::bounds() const {
  Aabb box;
  for (const Part& part : parts_) {
    box.extend(part.bounds.min);
    box.extend(part.bounds.max);
  }
  return box;
}

Aabb SceneBuilder::bounds(const std::string& structure) const {
  Aabb box;
  for (const Part& part : parts_)
    if (part.structure == structure) {
      box.extend(part.bounds.min);
      box.extend(part.bounds.max);
    }
  return box;
}

// ---- SolidIndex ------------------------------------------------------------------------------

SolidIndex::SolidIndex(const SceneBuilder& scene, double cellSize) : cell_(cellSize) {
  const auto& parts = scene.parts();
  for (size_t i = 0; i < parts.size(); ++i) {
    parts_.push_back(prepare(parts[i].mesh, parts[i].bounds));
    const Aabb& b = parts[i].bounds;
    for (int x = cellOf(b.min.x(), cell_); x <= cellOf(b.max.x(), cell_); ++x)
      for (int y = cellOf(b.min.y(), cell_); y <= cellOf(b.max.y(), cell_); ++y)
        for (int z = cellOf(b.min.z(), cell_); z <= cellOf(b.max.z(), cell_); ++z)
          cells_[key(x, y, z)].push_back(static_cast<uint32_t>(i));
  }
}

SolidIndex::PartRays SolidIndex::prepare(const TriangleMesh& mesh, const Aabb& bounds) {
  PartRays part;
  part.bounds = bounds;
  Eigen::AlignedBox2d all;
  std::vector<Eigen::AlignedBox2d> shadows;
  for (const auto& t : mesh.triangles) {
    part.triangles.push_back({mesh.vertex(t[0]), mesh.vertex(t[1]), mesh.vertex(t[2])});
    Eigen::AlignedBox2d box;
    for (const Vec3& v : part.triangles.back())
      box.extend(shadow(v));
    all.extend(box);
    shadows.push_back(box);
  }
  // About one bucket per triangle, at most 64 x 64.
  const Vec2 size = all.sizes().cwiseMax(1e-6);
  const double side = std::sqrt(size.x() * size.y() / static_cast<double>(shadows.size()));
  part.cell = std::max({side, size.x() / 64.0, size.y() / 64.0});
  part.origin = all.min();
  part.nx = static_cast<int>(size.x() / part.cell) + 1;
  part.ny = static_cast<int>(size.y() / part.cell) + 1;
  part.buckets.resize(static_cast<size_t>(part.nx * part.ny));
  for (size_t i = 0; i < shadows.size(); ++i) {
    const Vec2 lo = (shadows[i].min() - part.origin) / part.cell;
    const Vec2 hi = (shadows[i].max() - part.origin) / part.cell;
    for (int y = static_cast<int>(lo.y()); y <= std::min(static_cast<int>(hi.y()), part.ny - 1);
         ++y)
      for (int x = static_cast<int>(lo.x()); x <= std::min(static_cast<int>(hi.x()), part.nx - 1);
           ++x)
        part.buckets[static_cast<size_t>(y * part.nx + x)].push_back(static_cast<uint32_t>(i));
  }
  return part;
}

bool SolidIndex::insidePart(const PartRays& part, const Vec3& p) const {
  if ((p.array() < part.bounds.min.array()).any() || (p.array() > part.bounds.max.array()).any())
    return false;
  const Vec2 g = (shadow(p) - part.origin) / part.cell;
  if (g.x() < 0.0 || g.y() < 0.0) return false;
  const int x = static_cast<int>(g.x()), y = static_cast<int>(g.y());
  if (x >= part.nx || y >= part.ny) return false;
  int crossings = 0;
  for (const uint32_t i : part.buckets[static_cast<size_t>(y * part.nx + x)]) {
    const auto& t = part.triangles[i];
    if (rayCrossesTriangle(p, kParityDirection, t[0], t[1], t[2])) ++crossings;
  }
  return crossings % 2 == 1;
}

int64_t SolidIndex::key(int x, int y, int z) const {
  return packCell(x, y, z);
}

bool SolidIndex::inside(const Vec3& p) const {
  const auto it =
      cells_.find(key(cellOf(p.x(), cell_), cellOf(p.y(), cell_), cellOf(p.z(), cell_)));
  if (it == cells_.end()) return false;
  for (const uint32_t i : it->second)
    if (insidePart(parts_[i], p)) return true;
  return false;
}

bool SolidIndex::clear(const Vec3& p, double radius, double groundZ) const {
  if (p.z() <= groundZ || inside(p)) return false;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {-1.0, 1.0}) {
      Vec3 q = p;
      q[axis] += sign * radius;
      // Vehicles start on the ground: the probe below them may touch it, not the parts.
      if (inside(q)) return false;
    }
  return true;
}

// ---- Interest points -------------------------------------------------------------------------

bool insideAnyBox(const std::vector<OrientedBox>& boxes, const Vec3& p, double margin) {
  for (const OrientedBox& box : boxes) {
    const Vec3 q = box.toBox(p);
    if ((q.cwiseAbs().array() <= (0.5 * box.size.array() + margin)).all()) return true;
  }
  return false;
}

std::vector<InterestPoint> sampleSurfacePoints(const SceneBuilder& scene,
                                               const std::vector<OrientedBox>& boxes,
                                               const SurfaceSampling& sampling, Rng& rng) {
  COINSPECT_ASSERT(sampling.minSpacing > 0.0 && sampling.candidateFactor > 0.0);
  const double density = sampling.candidateFactor / (sampling.minSpacing * sampling.minSpacing);

  // World-axis bounds of the boxes: facets entirely outside them need no candidates.
  std::vector<Aabb> boxBounds;
  for (const OrientedBox& box : boxes) {
    const Vec3 half = box.rotation.cwiseAbs() * (0.5 * box.size);
    boxBounds.push_back(Aabb{box.center - half, box.center + half});
  }
  const auto nearSomeBox = [&](const Aabb& facet) {
    for (const Aabb& b : boxBounds)
      if ((facet.min.array() <= b.max.array()).all() && (facet.max.array() >= b.min.array()).all())
        return true;
    return false;
  };

  struct Candidate {
    Vec3 position;
    uint32_t part, triangle;
  };
  std::vector<Candidate> candidates;
  const auto& parts = scene.parts();
  for (size_t pi = 0; pi < parts.size(); ++pi) {
    const TriangleMesh& mesh = parts[pi].mesh;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Vec3 a = mesh.vertex(mesh.triangles[t][0]);
      const Vec3 b = mesh.vertex(mesh.triangles[t][1]);
      const Vec3 c = mesh.vertex(mesh.triangles[t][2]);
      Aabb facet;
      facet.extend(a);
      facet.extend(b);
      facet.extend(c);
      if (!nearSomeBox(facet)) continue;
      const double expected = mesh.facetArea(t) * density;
      if (expected <= 0.0) continue;
      // Integer part plus a Bernoulli draw for the fraction: unbiased for small facets.
      auto count = static_cast<size_t>(expected);
      if (rng.uniform() < expected - static_cast<double>(count)) ++count;
      for (size_t k = 0; k < count; ++k) {
        double u = rng.uniform(), v = rng.uniform();
        if (u + v > 1.0) {
          u = 1.0 - u;
          v = 1.0 - v;
        }
        const Vec3 p = a + u * (b - a) + v * (c - a);
        if (insideAnyBox(boxes, p))
          candidates.push_back({p, static_cast<uint32_t>(pi), static_cast<uint32_t>(t)});
      }
    }
  }
  if (candidates.empty()) return {};
  // Random order makes the thinning a random sequential addition: no directional bias.
  for (size_t i = candidates.size(); i > 1; --i)
    std::swap(candidates[i - 1], candidates[rng.below(i)]);

  // Dense grid of cells at least minSpacing wide, each heading a list of accepted points: a
  // conflict can only be in the 27 cells around a candidate.
  Aabb extent;
  for (const Candidate& c : candidates)
    extent.extend(c.position);
  double cell = sampling.minSpacing;
  const auto cellsAlong = [&](int axis) {
    return static_cast<int64_t>(std::floor(extent.size()[axis] / cell)) + 1;
  };
  while (cellsAlong(0) * cellsAlong(1) * cellsAlong(2) > (int64_t{1} << 24))
    cell *= 1.5;
  const int64_t nx = cellsAlong(0), ny = cellsAlong(1), nz = cellsAlong(2);
  std::vector<int32_t> head(static_cast<size_t>(nx * ny * nz), -1);
  std::vector<int32_t> next;
  const auto cellIndex = [&](int64_t x, int64_t y, int64_t z) {
    return static_cast<size_t>((z * ny + y) * nx + x);
  };

  const SolidIndex solids(scene);
  const double r2 = sampling.minSpacing * sampling.minSpacing;
  std::vector<InterestPoint> accepted;
  for (const Candidate& candidate : candidates) {
    const Vec3& p = candidate.position;
    const Vec3 g = (p - extent.min) / cell;
    const int64_t cx = std::min<int64_t>(static_cast<int64_t>(g.x()), nx - 1);
    const int64_t cy = std::min<int64_t>(static_cast<int64_t>(g.y()), ny - 1);
    const int64_t cz = std::min<int64_t>(static_cast<int64_t>(g.z()), nz - 1);
    bool tooClose = false;
    for (int64_t z = std::max<int64_t>(cz - 1, 0); z <= std::min(cz + 1, nz - 1) && !tooClose; ++z)
      for (int64_t y = std::max<int64_t>(cy - 1, 0); y <= std::min(cy + 1, ny - 1) && !tooClose;
           ++y)
        for (int64_t x = std::max<int64_t>(cx - 1, 0); x <= std::min(cx + 1, nx - 1) && !tooClose;
             ++x)
          for (int32_t j = head[cellIndex(x, y, z)]; j >= 0; j = next[static_cast<size_t>(j)])
            if ((accepted[static_cast<size_t>(j)].position - p).squaredNorm() < r2) {
              tooClose = true;
              break;
            }
    if (tooClose) continue;
    // Checked only now (expensive, and most candidates fall to the spacing test first).
    const Vec3 normal = parts[candidate.part].mesh.facetNormal(candidate.triangle);
    bool buried = false;
    for (const double offset : sampling.probeOffsets) {
      const Vec3 probe = p + offset * normal;
      if (probe.z() <= sampling.groundZ || solids.inside(probe)) {
        buried = true;
        break;
      }
    }
    if (buried) continue;
    const size_t home = cellIndex(cx, cy, cz);
    next.push_back(head[home]);
    head[home] = static_cast<int32_t>(accepted.size());
    InterestPoint point;
    point.position = p;
    point.normal = normal;
    point.index = static_cast<uint32_t>(accepted.size());
    accepted.push_back(point);
  }
  return accepted;
}

std::vector<InterestPoint> farthestPointSubset(const std::vector<InterestPoint>& points,
                                               size_t count, Rng& rng) {
  COINSPECT_ASSERT(points.size() >= count);
  if (count == 0) return {};
  std::vector<double> distance(points.size(), std::numeric_limits<double>::infinity());
  std::vector<InterestPoint> chosen;
  size_t next = rng.below(points.size());
  while (chosen.size() < count) {
    chosen.push_back(points[next]);
    chosen.back().index = static_cast<uint32_t>(chosen.size() - 1);
    const Vec3 p = points[next].position;
    double best = -1.0;
    for (size_t i = 0; i < points.size(); ++i) {
      distance[i] = std::min(distance[i], (points[i].position - p).squaredNorm());
      if (distance[i] > best) {
        best = distance[i];
        next = i;
      }
    }
  }
  return chosen;
}

// ---- Boxes, fleet, assembly ------------------------------------------------------------------

OrientedBox makeInspectionBox(const std::string& name, const Vec3& center, const Vec3& size,
                              double yaw) {
  OrientedBox box;
  box.name = name;
  box.center = center;
  box.size = size;
  box.rotation = yawRotation(yaw);
  return box;
}

OrientedBox boxAround(const std::string& name, const Aabb& bounds, double margin) {
  COINSPECT_ASSERT(!bounds.empty());
  Vec3 low = bounds.min.array() - margin;
  const Vec3 high = bounds.max.array() + margin;
  low.z() = std::max(low.z(), 0.0);
  return makeInspectionBox(name, 0.5 * (low + high), high - low);
}

UnitSpec makeUnit(const std::string& name, UnitRole role, const Vec3& start,
                  double desiredMmPerPx) {
  UnitSpec unit;
  unit.name = name;
  unit.role = role;
  unit.startPosition = start;
  unit.startYaw = 0.0;
  unit.antennaOffset = role == UnitRole::Explorer ? 0.2 : 0.1;
  unit.camera.desiredMmPerPixel = desiredMmPerPx;
  return unit;
}

Scenario assembleScenario(const std::string& name, const std::string& description,
                          const SceneBuilder& scene, std::vector<OrientedBox> boxes,
                          std::vector<InterestPoint> points, std::vector<UnitSpec> fleet,
                          double missionBudget) {
  const SolidIndex solids(scene);
  // 0.7 m: the explorer's collision radius with rotors is about 0.63 m.
  for (const UnitSpec& unit : fleet)
    COINSPECT_ASSERT(solids.clear(unit.startPosition, 0.7));
  Scenario scenario;
  scenario.name = name;
  scenario.description = description;
  scenario.meshes = scene.meshes();
  scenario.boxes = std::move(boxes);
  scenario.interestPoints = InterestPointSet(std::move(points));
  scenario.fleet = std::move(fleet);
  scenario.groundZ = 0.0;
  scenario.missionBudget = missionBudget;
  return scenario;
}

}  // namespace coinspect::world::detail
