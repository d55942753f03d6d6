#include "coinspect/strategies/kios/sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coinspect::strategies::kios {

int longHorizontalAxis(const Aabb& volume) {
  const Vec3 size = volume.size();
  return size.y() > size.x() ? 1 : 0;
}

std::vector<Aabb> splitSlabs(const Aabb& volume, size_t parts) {
  parts = std::max<size_t>(1, parts);
  const int axis = longHorizontalAxis(volume);
  const double length = volume.size()[axis];
  std::vector<Aabb> slabs;
  for (size_t k = 0; k < parts; ++k) {
    Aabb slab = volume;
    slab.min[axis] = volume.min[axis] + length * static_cast<double>(k) / parts;
    slab.max[axis] = volume.min[axis] + length * static_cast<double>(k + 1) / parts;
    slabs.push_back(slab);
  }
  return slabs;
}

namespace {

// Points every `spacing` m (both ends included) from a to b.
void appendPass(const Vec3& a, const Vec3& b, double spacing, std::vector<Vec3>* route) {
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
  for (int i = 0; i <= steps; ++i)
    route->push_back(a + (b - a) * (static_cast<double>(i) / steps));
}

// The route starting at the low end of the long axis and on the low side across it.
std::vector<Vec3> baseSweep(const Aabb& volume, const Aabb& slab, const SweepOptions& options,
                            bool flipLong, bool flipSide) {
  const int along = longHorizontalAxis(volume);
  const int across = 1 - along;
  const double lowSide = volume.min[across] - options.standoff;
  const double highSide = volume.max[across] + options.standoff;
  double ends[2] = {slab.min[along], slab.max[along]};
  double sides[2] = {lowSide, highSide};
  if (flipLong) std::swap(ends[0], ends[1]);
  if (flipSide) std::swap(sides[0], sides[1]);
  const auto point = [&](double a, double c, double z) {
    Vec3 p;
    p[along] = a;
    p[across] = c;
    p.z() = z;
    return p;
  };
  std::vector<Vec3> route;
  int end = 0;  // which long end the unit is at
  for (const double z : options.heights) {
    // Along the first side, then back along the other: ends where it started along the axis.
    appendPass(point(ends[end], sides[0], z), point(ends[1 - end], sides[0], z), options.spacing,
               &route);
    appendPass(point(ends[1 - end], sides[1], z), point(ends[end], sides[1], z), options.spacing,
               &route);
    std::swap(sides[0], sides[1]);
  }
  // Passes above the top, across the whole width (the side passes see the top only obliquely).
  const double top = volume.max.z() + options.topClearance;
  const double width = volume.size()[across];
  const int lanes = std::max(1, static_cast<int>(std::ceil(width / options.laneSpacing)));
  for (int lane = 0; lane < lanes; ++lane) {
    const double t = (lane + 0.5) / lanes;
    const double c =
        sides[0] < sides[1] ? volume.min[across] + t * width : volume.max[across] - t * width;
    appendPass(point(ends[end], c, top), point(ends[1 - end], c, top), options.spacing, &route);
    end = 1 - end;
  }
  return route;
}

}  // namespace

std::vector<Vec3> lawnmowerSweep(const Aabb& volume, const Aabb& slab, const SweepOptions& options,
                                 const Vec3& near) {
  std::vector<Vec3> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const bool flipSide : {false, true})
    for (const bool flipLong : {false, true}) {
      auto route = baseSweep(volume, slab, options, flipLong, flipSide);
      if (route.empty()) continue;
      const double d = (route.front() - near).norm();
      if (d < bestDistance - 1e-9) bestDistance = d, best = std::move(route);
    }
  return best;
}

}  // namespace coinspect::strategies::kios
