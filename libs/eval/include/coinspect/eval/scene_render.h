// Headless pictures of a scenario: ray-cast through the world's own Embree scene, so they need
// no GPU, no GL context and no display, and are identical on every machine.
#pragma once

#include <vector>

#include "coinspect/eval/image.h"
#include "coinspect/world/oriented_box.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::eval {

using world::Vec3;

struct ViewCamera {
  Vec3 eye{-60.0, -80.0, 60.0};
  Vec3 target = Vec3::Zero();
  Vec3 up = Vec3::UnitZ();
  double verticalFovDeg = 40.0;
  int width = 960;
  int height = 540;

  // A three-quarter view from the south-west, above, framing the given bounds.
  static ViewCamera overview(const world::Aabb& bounds, int width, int height);
  // Pixel coordinates of a world point; false when it is behind the camera.
  bool project(const Vec3& p, double& x, double& y, double& depth) const;
  // Unit ray direction through pixel centre (x + 0.5, y + 0.5).
  Vec3 rayThrough(double x, double y) const;
};

struct PointMarker {
  Vec3 position;
  Rgb color;
  double radiusPx = 2.0;
};

struct SceneOverlay {
  std::vector<world::OrientedBox> boxes;
  Rgb boxColor{40, 120, 220};
  std::vector<PointMarker> points;  // drawn only where not hidden behind geometry
  std::vector<std::vector<Vec3>> paths;
  Rgb pathColor{200, 40, 160};
};

RgbImage renderScene(const world::RayCaster& caster, const ViewCamera& camera,
                     const SceneOverlay& overlay = {});

}  // namespace coinspect::eval
