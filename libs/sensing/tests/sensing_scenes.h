// Small hand-built scenes for the sensing tests (walls, panels and points on them).
#pragma once

#include <vector>

#include "coinspect/sensing/capture_state.h"
#include "coinspect/world/fleet.h"
#include "coinspect/world/interest_points.h"
#include "coinspect/world/mesh.h"

namespace coinspect::sensing::test {

// Rectangle in the plane x = x0 over [y0, y1] x [z0, z1], facing -x (towards the origin).
inline world::TriangleMesh wallX(double x0, double y0, double y1, double z0, double z1) {
  world::TriangleMesh mesh;
  mesh.name = "wall";
  const auto f = [](double v) { return static_cast<float>(v); };
  mesh.vertices = {
      {f(x0), f(y0), f(z0)}, {f(x0), f(y1), f(z0)}, {f(x0), f(y1), f(z1)}, {f(x0), f(y0), f(z1)}};
  // (v1 - v0) x (v2 - v0) points along +x, so both triangles are reversed to face -x.
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
  return mesh;
}

inline world::InterestPoint facingMinusX(double x, double y, double z) {
  world::InterestPoint p;
  p.position = Vec3(x, y, z);
  p.normal = Vec3(-1.0, 0.0, 0.0);
  return p;
}

// A level, static UAV whose camera (default spec offset) sits exactly at `camera`, looking +x.
inline CaptureState cameraAt(const world::CameraSpec& spec, const Vec3& camera) {
  CaptureState state;
  state.position = camera - spec.positionInBody;
  return state;
}

}  // namespace coinspect::sensing::test
