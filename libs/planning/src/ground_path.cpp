#include "coinspect/planning/ground_path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "coinspect/core/error.h"

namespace coinspect::planning {

GroundGrid::GroundGrid(const Vec2& min, const Vec2& max, double resolution)
    : min_(min), resolution_(resolution) {
  if (!(resolution > 0.0) || !(max.array() > min.array()).all())
    throw InputError("ground path", "grid", "needs a positive resolution and max > min");
  nx_ = static_cast<int>(std::ceil((max.x() - min.x()) / resolution));
  ny_ = static_cast<int>(std::ceil((max.y() - min.y()) / resolution));
  blocked_.assign(static_cast<size_t>(nx_) * ny_, 0);
}

Eigen::Vector2i GroundGrid::cellOf(const Vec2& p) const {
  return {static_cast<int>(std::floor((p.x() - min_.x()) / resolution_)),
          static_cast<int>(std::floor((p.y() - min_.y()) / resolution_))};
}

Vec2 GroundGrid::centre(int x, int y) const {
  return min_ + Vec2(x + 0.5, y + 0.5) * resolution_;
}

void GroundGrid::blockRectangle(const Vec2& centre, const Vec2& axisX, const Vec2& half,
                                double inflate) {
  const Vec2 u = axisX.normalized(), v(-u.y(), u.x());
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x) {
      const Vec2 d = this->centre(x, y) - centre;
      const double du = std::max(0.0, std::abs(d.dot(u)) - half.x());
      const double dv = std::max(0.0, std::abs(d.dot(v)) - half.y());
      if (std::hypot(du, dv) <= inflate) blocked_[index(x, y)] = 1;
    }
}

size_t GroundGrid::blockDisc(const Vec2& p, double radius) {
  const auto c = cellOf(p);
  const int r = static_cast<int>(std::ceil(radius / resolution_)) + 1;
  size_t newly = 0;
  for (int y = c.y() - r; y <= c.y() + r; ++y)
    for (int x = c.x() - r; x <= c.x() + r; ++x)
      if (inside(x, y) && (centre(x, y) - p).norm() <= radius) {
        newly += blocked_[index(x, y)] == 0;
        blocked_[index(x, y)] = 1;
      }
  return newly;
}

bool GroundGrid::blocked(const Vec2& p) const {
  const auto c = cellOf(p);
  return !freeCell(c.x(), c.y());
}

bool GroundGrid::nearestFree(const Vec2& p, Eigen::Vector2i* cell) const {
  const auto c = cellOf(p);
  if (freeCell(c.x(), c.y())) {
    *cell = c;
    return true;
  }
  const int r = static_cast<int>(std::ceil(3.0 / resolution_));
  double best = std::numeric_limits<double>::infinity();
  for (int y = c.y() - r; y <= c.y() + r; ++y)
    for (int x = c.x() - r; x <= c.x() + r; ++x) {
      if (!freeCell(x, y)) continue;
      const double d = (centre(x, y) - p).squaredNorm();
      if (d < best) best = d, *cell = {x, y};
    }
  return std::isfinite(best);
}

// Samples the segment every quarter cell: every sample's cell must be free.
bool GroundGrid::clearLine(const Vec2& a, const Vec2& b) const {
  const int steps = static_cast<int>(std::ceil((b - a).norm() / (0.25 * resolution_))) + 1;
  for (int i = 0; i <= steps; ++i)
    if (blocked(a + (b - a) * (static_cast<double>(i) / steps))) return false;
  return true;
}

Vec2 GroundGrid::nearestReachable(const Vec2& start, const Vec2& goal) const {
  Eigen::Vector2i from;
  if (!nearestFree(start, &from)) return goal;
  std::vector<uint8_t> seen(blocked_.size(), 0);
  std::vector<Eigen::Vector2i> queue = {from};
  seen[index(from.x(), from.y())] = 1;
  Vec2 best = centre(from.x(), from.y());
  double bestDistance = (best - goal).squaredNorm();
  for (size_t next = 0; next < queue.size(); ++next) {
    const Eigen::Vector2i c = queue[next];
    const double d = (centre(c.x(), c.y()) - goal).squaredNorm();
    if (d < bestDistance) bestDistance = d, best = centre(c.x(), c.y());
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = c.x() + dx, y = c.y() + dy;
        if (!freeCell(x, y) || seen[index(x, y)]) continue;
        seen[index(x, y)] = 1;
        queue.emplace_back(x, y);
      }
  }
  return best;
}

std::vector<Vec2> GroundGrid::path(const Vec2& start, const Vec2& goal) const {
  Eigen::Vector2i s, g;
  if (!nearestFree(start, &s) || !nearestFree(goal, &g)) return {};
  const size_t n = blocked_.size();
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<int64_t> parent(n, -1);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto h = [&](int x, int y) {
    const double dx = std::abs(x - g.x()), dy = std::abs(y - g.y());
    return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
  };
  cost[index(s.x(), s.y())] = 0.0;
  open.push({h(s.x(), s.y()), index(s.x(), s.y())});
  const size_t target = index(g.x(), g.y());
  while (!open.empty()) {
    const auto [f, i] = open.top();
    open.pop();
    if (i == target) break;
    const int x = static_cast<int>(i % nx_), y = static_cast<int>(i / nx_);
    if (f > cost[i] + h(x, y) + 1e-9) continue;  // stale entry
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !freeCell(x + dx, y + dy)) continue;
        // No corner cutting: a diagonal move needs both side cells free.
        if (dx != 0 && dy != 0 && (!freeCell(x + dx, y) || !freeCell(x, y + dy))) continue;
        const size_t j = index(x + dx, y + dy);
        const double c = cost[i] + ((dx != 0 && dy != 0) ? std::sqrt(2.0) : 1.0);
        if (c < cost[j]) {
          cost[j] = c;
          parent[j] = static_cast<int64_t>(i);
          open.push({c + h(x + dx, y + dy), j});
        }
      }
  }
  if (!std::isfinite(cost[target])) return {};
  std::vector<Vec2> cells;
  for (int64_t i = static_cast<int64_t>(target); i >= 0; i = parent[static_cast<size_t>(i)])
    cells.push_back(centre(static_cast<int>(i % nx_), static_cast<int>(i / nx_)));
  std::reverse(cells.begin(), cells.end());
  // The exact goal when it is free, else the free cell found for it.
  if (!blocked(goal)) cells.back() = goal;
  // String pulling from the real start.
  std::vector<Vec2> out;
  Vec2 from = blocked(start) ? cells.front() : start;
  size_t at = 0;
  while (at + 1 < cells.size()) {
    size_t far = at + 1;
    for (size_t k = cells.size() - 1; k > at + 1; --k)
      if (clearLine(from, cells[k])) {
        far = k;
        break;
      }
    out.push_back(cells[far]);
    from = cells[far];
    at = far;
  }
  if (out.empty()) out.push_back(cells.back());
  return out;
}

}  // namespace coinspect::planning
