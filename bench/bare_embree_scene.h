// The baseline of the ray-casting benchmarks: the same triangles and ground plane as
// world::RayCaster builds, in a scene made directly with Embree, so that rows of one run compare
// our wrapper with the bare library.
#pragma once

#include <embree3/rtcore.h>

#include <array>
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

}  // namespace coinspect::bench
