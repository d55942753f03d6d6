// The baseline of the ray-casting benchmarks: the same triangles and ground plane as
// world::RayCaster builds, in a scene made directly with Embree, so that rows of one run compare
// our wrapper with the bare library.
#pragma once

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "coinspect/world/mesh.h"

namespace coinspect::bench {

struct BareEmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;

  // `robust` as RayCaster builds its scene (RTC_SCENE_FLAG_ROBUST); the ground is a square of
  // `groundHalfExtent` around the mesh centre at z = 0, as RayCaster's default.
  BareEmbreeScene(const world::TriangleMesh& mesh, double groundHalfExtent, bool robust) {
    device = rtcNewDevice(nullptr);
    scene = rtcNewScene(device);
    if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    add(mesh.vertices, mesh.triangles);
    const auto box = mesh.bounds();
    const world::Vec3 c = 0.5 * (box.min + box.max);
    const float h = static_cast<float>(groundHalfExtent);
    const float cx = static_cast<float>(c.x()), cy = static_cast<float>(c.y());
    add({{cx - h, cy - h, 0}, {cx + h, cy - h, 0}, {cx + h, cy + h, 0}, {cx - h, cy + h, 0}},
        {{0, 1, 2}, {0, 2, 3}});
    rtcCommitScene(scene);
  }
  ~BareEmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  BareEmbreeScene(const BareEmbreeScene&) = delete;
  BareEmbreeScene& operator=(const BareEmbreeScene&) = delete;

 private:
  void add(const std::vector<Eigen::Vector3f>& vertices,
           const std::vector<std::array<uint32_t, 3>>& triangles) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
    auto* t = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles.size()));
    std::memcpy(v, vertices.data(), vertices.size() * 3 * sizeof(float));
    std::memcpy(t, triangles.data(), triangles.size() * 3 * sizeof(uint32_t));
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
  }
};

// The bare baseline loop of the ray benchmarks: rays [0, count) (origins and directions as 3
// floats each) cast in packets of 16 with rtcIntersect16 from tnear 0 to `tfar`; out(ray, hit,
// distance) is called for every ray, packet by packet.
template <typename Out>
void intersectPackets16(RTCScene scene, const float* origins, const float* directions, size_t count,
                        float tfar, Out out) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(64) RTCRayHit16 p;
  alignas(64) int valid[16];
  for (size_t start = 0; start < count; start += 16) {
    const size_t n = std::min<size_t>(16, count - start);
    for (size_t k = 0; k < 16; ++k) {
      valid[k] = k < n ? -1 : 0;
      if (k >= n) {  // without AVX-512 Embree ignores `valid` and traces lanes with tnear <= tfar
        p.ray.org_x[k] = p.ray.org_y[k] = p.ray.org_z[k] = 0.0f;
        p.ray.dir_x[k] = p.ray.dir_y[k] = 0.0f;
        p.ray.dir_z[k] = 1.0f;
        p.ray.tnear[k] = 0.0f;
        p.ray.tfar[k] = -1.0f;
        continue;
      }
      const float* o = &origins[3 * (start + k)];
      const float* d = &directions[3 * (start + k)];
      p.ray.org_x[k] = o[0];
      p.ray.org_y[k] = o[1];
      p.ray.org_z[k] = o[2];
      p.ray.dir_x[k] = d[0];
      p.ray.dir_y[k] = d[1];
      p.ray.dir_z[k] = d[2];
      p.ray.tnear[k] = 0.0f;
      p.ray.tfar[k] = tfar;
      p.ray.time[k] = 0.0f;
      p.ray.mask[k] = 0xffffffffu;
      p.ray.id[k] = static_cast<unsigned>(k);
      p.ray.flags[k] = 0;
      p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      p.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, scene, &context, &p);
    for (size_t k = 0; k < n; ++k)
      out(start + k, p.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID, p.ray.tfar[k]);
  }
}

}  // namespace coinspect::bench
