#include "coinspect/eval/scene_render.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coinspect::eval {

namespace {

struct CameraFrame {
  Vec3 forward, right, up;
  double focalPx;
};

CameraFrame frameOf(const ViewCamera& camera) {
  CameraFrame frame;
  frame.forward = (camera.target - camera.eye).normalized();
  frame.right = frame.forward.cross(camera.up).normalized();
  frame.up = frame.right.cross(frame.forward);
  frame.focalPx = 0.5 * camera.height / std::tan(0.5 * camera.verticalFovDeg * M_PI / 180.0);
  return frame;
}

Rgb shade(const Rgb& base, double light) {
  const auto scale = [light](uint8_t c) {
    return static_cast<uint8_t>(std::clamp(std::lround(c * light), 0L, 255L));
  };
  return {scale(base.r), scale(base.g), scale(base.b)};
}

Rgb sky(double heightFraction) {
  // Pale at the horizon, deeper blue above.
  const double t = std::clamp(heightFraction, 0.0, 1.0);
  return {static_cast<uint8_t>(225 - 95 * t), static_cast<uint8_t>(235 - 70 * t),
          static_cast<uint8_t>(245 - 20 * t)};
}

}  // namespace

ViewCamera ViewCamera::overview(const world::Aabb& bounds, int width, int height) {
  ViewCamera camera;
  camera.width = width;
  camera.height = height;
  const Vec3 center = 0.5 * (bounds.min + bounds.max);
  const double radius = 0.5 * bounds.size().norm();
  camera.target = center - Vec3(0, 0, 0.15 * bounds.size().z());
  const double distance = radius / std::sin(0.5 * camera.verticalFovDeg * M_PI / 180.0) * 0.95;
  const Vec3 direction = Vec3(-0.55, -0.75, 0.42).normalized();
  camera.eye = center + distance * direction;
  return camera;
}

bool ViewCamera::project(const Vec3& p, double& x, double& y, double& depth) const {
  const CameraFrame frame = frameOf(*this);
  const Vec3 d = p - eye;
  depth = d.dot(frame.forward);
  if (depth <= 1e-6) return false;
  x = 0.5 * width + frame.focalPx * d.dot(frame.right) / depth;
  y = 0.5 * height - frame.focalPx * d.dot(frame.up) / depth;
  return true;
}

Vec3 ViewCamera::rayThrough(double x, double y) const {
  const CameraFrame frame = frameOf(*this);
  return (frame.forward * frame.focalPx + frame.right * (x + 0.5 - 0.5 * width) -
          frame.up * (y + 0.5 - 0.5 * height))
      .normalized();
}

RgbImage renderScene(const world::RayCaster& caster, const ViewCamera& camera,
                     const SceneOverlay& overlay) {
  RgbImage image(camera.width, camera.height);
  const CameraFrame frame = frameOf(camera);
  std::vector<double> depth(static_cast<size_t>(camera.width) * camera.height,
                            std::numeric_limits<double>::infinity());
  const Vec3 light = Vec3(0.35, 0.25, 0.9).normalized();
  const Rgb structure{205, 198, 188};

  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const Vec3 direction = camera.rayThrough(x, y);
      const auto hit = caster.closestHit(camera.eye, direction);
      if (!hit) {
        image.at(x, y) = sky(direction.dot(Vec3::UnitZ()) * 2.0);
        continue;
      }
      depth[static_cast<size_t>(y) * camera.width + x] =
          hit->distance * direction.dot(frame.forward);
      const Vec3 point = camera.eye + hit->distance * direction;
      const bool ground = caster.hasGround() && std::abs(point.z() - caster.groundZ()) < 1e-3 &&
                          std::abs(hit->normal.z()) > 0.999;
      // Facing the viewer: flip back-facing normals so both sides of thin walls are lit.
      Vec3 normal = hit->normal;
      if (normal.dot(direction) > 0) normal = -normal;
      double lit = 0.45 + 0.55 * std::max(0.0, normal.dot(light));
      // Shadows make shapes readable: one occlusion ray toward the light.
      if (!caster.segmentClear(point + 0.02 * normal, point + 500.0 * light, 0.0)) lit *= 0.6;
      Rgb base = structure;
      if (ground) {
        const bool checker = (static_cast<long>(std::floor(point.x() / 10.0)) +
                              static_cast<long>(std::floor(point.y() / 10.0))) %
                                 2 ==
                             0;
        base = checker ? Rgb{150, 165, 140} : Rgb{140, 155, 130};
      }
      // Distance haze toward the horizon colour.
      const double haze = std::clamp(hit->distance / 1500.0, 0.0, 0.7);
      const Rgb shaded = shade(base, lit), horizon = sky(0.0);
      image.at(x, y) = {static_cast<uint8_t>(shaded.r + haze * (horizon.r - shaded.r)),
                        static_cast<uint8_t>(shaded.g + haze * (horizon.g - shaded.g)),
                        static_cast<uint8_t>(shaded.b + haze * (horizon.b - shaded.b))};
    }
  }

  for (const auto& box : overlay.boxes) {
    const auto corners = box.vertices();
    // Bottom face 0-1-2-3, top face 4-5-6-7, verticals i -> i+4 (the reference vertex order).
    static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& edge : kEdges) {
      double x0, y0, d0, x1, y1, d1;
      if (camera.project(corners[edge[0]], x0, y0, d0) &&
          camera.project(corners[edge[1]], x1, y1, d1))
        image.drawLine(x0, y0, x1, y1, overlay.boxColor);
    }
  }
  for (const auto& path : overlay.paths)
    for (size_t i = 1; i < path.size(); ++i) {
      double x0, y0, d0, x1, y1, d1;
      if (camera.project(path[i - 1], x0, y0, d0) && camera.project(path[i], x1, y1, d1))
        image.drawLine(x0, y0, x1, y1, overlay.pathColor);
    }
  for (const auto& marker : overlay.points) {
    double x, y, d;
    if (!camera.project(marker.position, x, y, d)) continue;
    const int px = static_cast<int>(std::floor(x)), py = static_cast<int>(std::floor(y));
    if (!image.inside(px, py)) continue;
    // Points lie on surfaces: hidden when the surface seen at that pixel is clearly nearer.
    if (depth[static_cast<size_t>(py) * camera.width + px] < d - 0.5) continue;
    image.fillDisc(x, y, marker.radiusPx, marker.color);
  }
  return image;
}

}  // namespace coinspect::eval
