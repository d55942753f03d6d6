#include "coinspect/strategies/runtime/box_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::strategies::runtime {

namespace {

// The other two axes of `axis`, in increasing order.
std::pair<int, int> otherAxes(int axis) {
  return {axis == 0 ? 1 : 0, axis == 2 ? 1 : 2};
}

}  // namespace

Aabb boxBounds(const BoxView& box) {
  // Half extent of the world bounds along each world axis: sum of |R_ij| * half size_j.
  const Vec3 half = box.rotation.cwiseAbs() * (0.5 * box.size);
  return {box.center - half, box.center + half};
}

Aabb missionRegion(const std::vector<BoxView>& boxes, double margin, double groundZ) {
  COINSPECT_ASSERT(!boxes.empty());
  Aabb region = boxBounds(boxes.front());
  for (const auto& box : boxes) {
    const Aabb b = boxBounds(box);
    region.min = region.min.cwiseMin(b.min);
    region.max = region.max.cwiseMax(b.max);
  }
  const double bottom = std::min(groundZ, region.min.z());
  region.min -= Vec3::Constant(margin);
  region.max += Vec3::Constant(margin);
  region.min.z() = bottom;
  return region;
}

int longestAxis(const BoxView& box) {
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (box.size[k] > box.size[best]) best = k;
  return best;
}

int verticalAxis(const BoxView& box) {
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(box.rotation(2, k)) > std::abs(box.rotation(2, best))) best = k;
  return best;
}

std::pair<BoxView, BoxView> cutBox(const BoxView& box, double fraction) {
  COINSPECT_ASSERT(fraction > 0.0 && fraction < 1.0);
  const int a = longestAxis(box);
  const double length = box.size[a];
  const Vec3 axis = box.rotation.col(a);
  BoxView first = box, rest = box;
  first.size[a] = fraction * length;
  first.center = box.center + axis * (0.5 * (fraction - 1.0) * length);
  rest.size[a] = (1.0 - fraction) * length;
  rest.center = box.center + axis * (0.5 * fraction * length);
  return {first, rest};
}

std::vector<BoxView> splitBox(const BoxView& box, int parts) {
  COINSPECT_ASSERT(parts >= 1);
  std::vector<BoxView> out;
  BoxView rest = box;
  for (int k = parts; k > 1; --k) {
    auto [first, remainder] = cutBox(rest, 1.0 / k);
    out.push_back(first);
    rest = remainder;
  }
  out.push_back(rest);
  return out;
}

BoxView extendToGround(const BoxView& box, double groundZ) {
  const int v = verticalAxis(box);
  const Vec3 up = box.rotation.col(v) * (box.rotation(2, v) >= 0.0 ? 1.0 : -1.0);
  const double bottomZ = box.center.z() - up.z() * 0.5 * box.size[v];
  if (up.z() <= 1e-9 || bottomZ <= groundZ) return box;
  const double extra = (bottomZ - groundZ) / up.z();
  BoxView out = box;
  out.size[v] += extra;
  out.center -= up * (0.5 * extra);
  return out;
}

std::vector<double> boxLayers(const BoxView& box, double layerHeight, double minZ) {
  COINSPECT_ASSERT(layerHeight > 0.0);
  const Aabb bounds = boxBounds(box);
  const double height = bounds.max.z() - bounds.min.z();
  const int count = std::max(1, static_cast<int>(std::ceil(height / layerHeight - 1e-9)));
  std::vector<double> out;
  for (int i = 0; i < count; ++i) {
    const double z = std::max(minZ, bounds.min.z() + (i + 0.5) * height / count);
    if (out.empty() || z > out.back() + 1e-9) out.push_back(z);
  }
  return out;
}

double Footprint::perimeterAt(double distance) const {
  return 4.0 * (half[0] + half[1]) + 2.0 * M_PI * distance;
}

Footprint footprintOf(const BoxView& box) {
  const auto [i, j] = otherAxes(verticalAxis(box));
  Footprint out;
  out.centre = box.center.head<2>();
  Vec2 a = box.rotation.col(i).head<2>();
  out.axis[0] = a.norm() > 1e-9 ? Vec2(a.normalized()) : Vec2::UnitX();
  out.axis[1] = Vec2(-out.axis[0].y(), out.axis[0].x());  // counter-clockwise by construction
  out.half[0] = 0.5 * box.size[i];
  out.half[1] = 0.5 * box.size[j];
  return out;
}

std::vector<Vec3> standoffOrbit(const BoxView& box, double z, double distance, double spacing,
                                const Vec3& near) {
  COINSPECT_ASSERT(distance >= 0.0 && spacing > 0.0);
  const Footprint f = footprintOf(box);
  const double hu = f.half[0], hv = f.half[1], d = distance;
  // Four sides, each followed by a quarter circle: side k runs along direction dir[k] on the
  // line offset by d along normal[k], from corner k to corner k + 1 (local u, v coordinates).
  const Vec2 corner[4] = {{-hu, -hv}, {hu, -hv}, {hu, hv}, {-hu, hv}};
  const Vec2 normal[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  const double sideLength[4] = {2 * hu, 2 * hv, 2 * hu, 2 * hv};
  const double arcLength = 0.5 * M_PI * d;
  const double perimeter = f.perimeterAt(d);
  const auto local = [&](double s) -> Vec2 {
    for (int k = 0; k < 4; ++k) {
      if (s <= sideLength[k]) {
        const Vec2 dir = (corner[(k + 1) % 4] - corner[k]).normalized();
        return corner[k] + normal[k] * d + dir * s;
      }
      s -= sideLength[k];
      if (s <= arcLength || k == 3) {
        const double start = std::atan2(normal[k].y(), normal[k].x());
        const double angle = start + (d > 0.0 ? s / d : 0.0);
        return corner[(k + 1) % 4] + d * Vec2(std::cos(angle), std::sin(angle));
      }
      s -= arcLength;
    }
    return corner[0] + normal[0] * d;
  };
  const int count = std::max(8, static_cast<int>(std::ceil(perimeter / spacing - 1e-9)));
  std::vector<Vec3> out;
  out.reserve(count);
  size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (int n = 0; n < count; ++n) {
    const Vec2 uv = local(perimeter * n / count);
    const Vec2 xy = f.centre + f.axis[0] * uv.x() + f.axis[1] * uv.y();
    const double gap = (xy - near.head<2>()).squaredNorm();
    if (gap < best) {
      best = gap;
      nearest = out.size();
    }
    out.emplace_back(xy.x(), xy.y(), z);
  }
  std::rotate(out.begin(), out.begin() + static_cast<long>(nearest), out.end());
  return out;
}

Vec3 closestPointOnBox(const BoxView& box, const Vec3& p) {
  const Vec3 half = 0.5 * box.size;
  const Vec3 local = box.rotation.transpose() * (p - box.center);
  return box.center + box.rotation * local.cwiseMax(-half).cwiseMin(half);
}

double distanceToBox(const BoxView& box, const Vec3& p) {
  return (p - closestPointOnBox(box, p)).norm();
}

std::vector<BoxFace> boxFaces(const BoxView& box) {
  std::vector<BoxFace> out;
  for (int k = 0; k < 3; ++k) {
    const auto [i, j] = otherAxes(k);
    for (const double sign : {-1.0, 1.0}) {
      BoxFace face;
      face.normal = sign * box.rotation.col(k);
      face.centre = box.center + face.normal * (0.5 * box.size[k]);
      face.axis[0] = box.rotation.col(i);
      face.axis[1] = box.rotation.col(j);
      face.half[0] = 0.5 * box.size[i];
      face.half[1] = 0.5 * box.size[j];
      out.push_back(face);
    }
  }
  return out;
}

}  // namespace coinspect::strategies::runtime
