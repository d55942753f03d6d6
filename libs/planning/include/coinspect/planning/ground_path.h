// Paths for a ground vehicle (a SLEI3D ground station): 8-connected A* on a 2-D occupancy grid
// of the ground plane, then string pulling. Obstacles are what the vehicle knows: the footprints
// of the inspection boxes (a structure stands in each), inflated by its radius and a margin, and
// the places where it found its way blocked (walls outside every box: it stops at them).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace coinspect::planning {

using Vec2 = Eigen::Vector2d;

class GroundGrid {
 public:
  // Covers [min, max] (m) at `resolution`; every cell free.
  GroundGrid(const Vec2& min, const Vec2& max, double resolution);

  // Blocks the cells whose centre lies within `inflate` of the rectangle centred at `centre`
  // with half extents `half` along the unit axes `axisX` and its perpendicular.
  void blockRectangle(const Vec2& centre, const Vec2& axisX, const Vec2& half, double inflate);
  // Blocks the cells whose centre lies within `radius` of `p`; returns how many were free.
  size_t blockDisc(const Vec2& p, double radius);

  bool blocked(const Vec2& p) const;  // outside the grid: blocked
  double resolution() const { return resolution_; }

  // Waypoints from `start` to `goal` (the start excluded, the goal last), or empty when no
  // path exists. A blocked start or goal is moved to the nearest free cell within 3 m first
  // (the path then ends there); straight stretches between waypoints cross free cells only.
  std::vector<Vec2> path(const Vec2& start, const Vec2& goal) const;
  // The centre of the free cell nearest `goal` among those a path from `start` reaches
  // (8-connected; a blocked start moved as in path()); `goal` itself when no cell is reached.
  // Where a vehicle can be closest to a place that may lie inside an obstacle.
  Vec2 nearestReachable(const Vec2& start, const Vec2& goal) const;

 private:
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < nx_ && y < ny_; }
  bool freeCell(int x, int y) const { return inside(x, y) && !blocked_[index(x, y)]; }
  size_t index(int x, int y) const { return static_cast<size_t>(y) * nx_ + x; }
  Eigen::Vector2i cellOf(const Vec2& p) const;
  Vec2 centre(int x, int y) const;
  bool nearestFree(const Vec2& p, Eigen::Vector2i* cell) const;
  bool clearLine(const Vec2& a, const Vec2& b) const;

  Vec2 min_;
  double resolution_;
  int nx_ = 0, ny_ = 0;
  std::vector<uint8_t> blocked_;
};

}  // namespace coinspect::planning
