#include "coinspect/planning/path_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::planning {

using mapping::CellState;

const char* toString(PathStatus status) {
  switch (status) {
    case PathStatus::Found:
      return "found";
    case PathStatus::NoPath:
      return "no-path";
    case PathStatus::StartBlocked:
      return "start-blocked";
    case PathStatus::GoalBlocked:
      return "goal-blocked";
    case PathStatus::BudgetExhausted:
      return "budget-exhausted";
  }
  return "?";
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr uint8_t kClosed = 1;
constexpr uint8_t kVerified = 2;  // Theta*: g_ is the exact cost through parent_

void checkOptions(const VoxelGrid& grid, const PathSearchOptions& options) {
  COINSPECT_ASSERT(options.clearance >= 0.0 && options.softClearance >= 0.0);
  COINSPECT_ASSERT(options.softWeight >= 0.0 && options.unknownPenalty >= 0.0);
  COINSPECT_ASSERT(options.snapRadius >= 0 && options.heuristicWeight >= 1.0);
  COINSPECT_ASSERT(grid.hasClearance() ||
                   (options.clearance <= 0.0 && options.softClearance <= 0.0));
}

// One of the 26 moves, with the cells of its bounding box that it grazes (no corner cutting).
struct Move {
  Index3 delta;
  double length;               // in cells
  std::vector<Index3> grazed;  // the other non-zero sub-moves of `delta`
};

const std::vector<Move>& moves() {
  static const std::vector<Move> all = [] {
    std::vector<Move> out;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0 && dz == 0) continue;
          Move move{Index3(dx, dy, dz), Index3(dx, dy, dz).cast<double>().norm(), {}};
          for (int mask = 1; mask < 7; ++mask) {
            const Index3 sub((mask & 1) ? dx : 0, (mask & 2) ? dy : 0, (mask & 4) ? dz : 0);
            if (sub != Index3::Zero() && sub != move.delta &&
                std::find(move.grazed.begin(), move.grazed.end(), sub) == move.grazed.end())
              move.grazed.push_back(sub);
          }
          out.push_back(move);
        }
    return out;
  }();
  return all;
}

// The six face neighbours, in the order the floods (reachableCells, PathSearcher::flood) visit
// them.
const Index3 kFaces[6] = {Index3(1, 0, 0),  Index3(-1, 0, 0), Index3(0, 1, 0),
                          Index3(0, -1, 0), Index3(0, 0, 1),  Index3(0, 0, -1)};

// Exact 26-connected distance in free space (cells): the A* heuristic.
double octile(const Index3& a, const Index3& b) {
  std::array<int, 3> d{std::abs(a.x() - b.x()), std::abs(a.y() - b.y()), std::abs(a.z() - b.z())};
  std::sort(d.begin(), d.end());
  return d[2] + (std::sqrt(2.0) - 1.0) * d[1] + (std::sqrt(3.0) - std::sqrt(2.0)) * d[0];
}

}  // namespace

bool cellTraversable(const VoxelGrid& grid, const Index3& cell, const PathSearchOptions& options) {
  if (!grid.contains(cell)) return false;
  const CellState state = grid.state(cell);
  if (state == CellState::Occupied) return false;
  if (state == CellState::Unknown && options.unknown == UnknownPolicy::Blocked) return false;
  if (options.clearance > 0.0 && grid.clearance(cell) < options.clearance) return false;
  if (options.avoid.empty()) return true;
  const Vec3 centre = grid.centre(cell);
  for (const auto& sphere : options.avoid)
    if ((centre - sphere.centre).squaredNorm() < sphere.radius * sphere.radius) return false;
  return true;
}

double cellCostMultiplier(const VoxelGrid& grid, const Index3& cell,
                          const PathSearchOptions& options) {
  double multiplier = 1.0;
  if (options.softClearance > 0.0 && options.softWeight > 0.0) {
    const double shortfall = 1.0 - grid.clearance(cell) / options.softClearance;
    if (shortfall > 0.0) multiplier += options.softWeight * shortfall;
  }
  if (options.unknown == UnknownPolicy::FreeWithCost && grid.state(cell) == CellState::Unknown)
    multiplier += options.unknownPenalty;
  return multiplier;
}

namespace {

double cellWeight(const VoxelGrid& grid, const Index3& cell, const PathSearchOptions& options) {
  return cellTraversable(grid, cell, options) ? cellCostMultiplier(grid, cell, options) : 0.0;
}

// Amanatides-Woo traversal in cell coordinates (u = (p - origin) / resolution) that also visits
// the cells a segment only touches at an edge or a corner, integrating the cost multiplier.
// `weightOf(cell)` is the cell's multiplier, 0 when it is not traversable (outside included).
template <class WeightOf>
bool walkSegment(const Vec3& u0, const Vec3& u1, double resolution, WeightOf&& weightOf,
                 double* cost) {
  Index3 cell(static_cast<int>(std::floor(u0.x())), static_cast<int>(std::floor(u0.y())),
              static_cast<int>(std::floor(u0.z())));
  double weight = weightOf(cell);
  if (weight <= 0.0) return false;
  const Vec3 d = u1 - u0;
  Index3 step;
  Vec3 tMax, tDelta;
  for (int i = 0; i < 3; ++i) {
    if (d[i] > 0.0) {
      step[i] = 1;
      tMax[i] = (std::floor(u0[i]) + 1.0 - u0[i]) / d[i];
      tDelta[i] = 1.0 / d[i];
    } else if (d[i] < 0.0) {
      step[i] = -1;
      tMax[i] = (u0[i] - std::floor(u0[i])) / -d[i];
      tDelta[i] = -1.0 / d[i];
    } else {
      step[i] = 0;
      tMax[i] = kInf;
      tDelta[i] = kInf;
    }
  }
  constexpr double kTie = 1e-9;  // crossings this close in t are one crossing of an edge/corner
  double t = 0.0, weighted = 0.0;
  const bool wantCost = cost != nullptr;
  while (true) {
    const double next = tMax.minCoeff();
    if (next >= 1.0) {
      if (wantCost) weighted += (1.0 - t) * weight;
      break;
    }
    if (wantCost) weighted += (next - t) * weight;
    t = next;
    int mask = 0;
    for (int i = 0; i < 3; ++i)
      if (tMax[i] <= next + kTie) mask |= 1 << i;
    if (mask != 1 && mask != 2 && mask != 4) {
      // Several boundaries at once: the segment grazes the cells of every partial step.
      for (int sub = 1; sub < 7; ++sub) {
        if ((sub & mask) != sub || sub == mask) continue;
        Index3 grazed = cell;
        for (int i = 0; i < 3; ++i)
          if (sub & (1 << i)) grazed[i] += step[i];
        if (weightOf(grazed) <= 0.0) return false;
      }
    }
    for (int i = 0; i < 3; ++i)
      if (mask & (1 << i)) {
        cell[i] += step[i];
        tMax[i] += tDelta[i];
      }
    weight = weightOf(cell);
    if (weight <= 0.0) return false;
  }
  if (wantCost) *cost = weighted * d.norm() * resolution;
  return true;
}

}  // namespace

bool segmentTraversable(const VoxelGrid& grid, const Vec3& a, const Vec3& b,
                        const PathSearchOptions& options, double* cost) {
  const double scale = 1.0 / grid.resolution();
  return walkSegment((a - grid.origin()) * scale, (b - grid.origin()) * scale, grid.resolution(),
                     [&](const Index3& cell) { return cellWeight(grid, cell, options); }, cost);
}

bool nearestTraversableCell(const VoxelGrid& grid, const Vec3& point, int radius,
                            const PathSearchOptions& options, Index3* cell) {
  const Index3 home = grid.cellOf(point);
  if (cellTraversable(grid, home, options)) {
    *cell = home;
    return true;
  }
  double best = kInf;
  for (int dz = -radius; dz <= radius; ++dz)
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const Index3 candidate = home + Index3(dx, dy, dz);
        if (!cellTraversable(grid, candidate, options)) continue;
        const double distance = (grid.centre(candidate) - point).squaredNorm();
        // Scan order is increasing linear index, so strict < keeps the lowest index on ties.
        if (distance < best) {
          best = distance;
          *cell = candidate;
        }
      }
  return best < kInf;
}

// One query's view of the grid, with a lazily filled per-cell weight cache (a cell is looked at
// from up to 26 neighbours and by line-of-sight walks; the cache makes each look one load).
struct PathSearcher::Query {
  const VoxelGrid& grid;
  const PathSearchOptions& options;
  CellArray<uint32_t>& weightStamp;
  CellArray<double>& weight;
  uint32_t generation;
  int sx, sy, sz;
  std::vector<int32_t> moveOffset;                 // linear offset of each move's target
  std::vector<std::vector<int32_t>> grazedOffset;  // and of its grazed cells

  Query(const VoxelGrid& g, const PathSearchOptions& o, CellArray<uint32_t>& stamps,
        CellArray<double>& weights, uint32_t gen)
      : grid(g),
        options(o),
        weightStamp(stamps),
        weight(weights),
        generation(gen),
        sx(g.size().x()),
        sy(g.size().y()),
        sz(g.size().z()) {
    const auto offsetOf = [&](const Index3& d) { return d.x() + sx * (d.y() + sy * d.z()); };
    for (const auto& move : moves()) {
      moveOffset.push_back(offsetOf(move.delta));
      grazedOffset.emplace_back();
      for (const auto& sub : move.grazed)
        grazedOffset.back().push_back(offsetOf(sub));
    }
  }

  Index3 cellOf(int32_t index) const {
    return Index3(index % sx, (index / sx) % sy, index / (sx * sy));
  }
  int32_t indexOf(const Index3& cell) const { return static_cast<int32_t>(grid.linear(cell)); }
  bool inside(const Index3& c) const {
    return c.x() >= 0 && c.y() >= 0 && c.z() >= 0 && c.x() < sx && c.y() < sy && c.z() < sz;
  }
  // The cell's cost multiplier, 0 when not traversable.
  double weightAt(int32_t index, const Index3& cell) {
    if (weightStamp[index] != generation) {
      weightStamp[index] = generation;
      weight[index] = cellWeight(grid, cell, options);
    }
    return weight[index];
  }
  double weightOf(const Index3& cell) { return inside(cell) ? weightAt(indexOf(cell), cell) : 0.0; }
  // Move number `m` from `from` (traversable): allowed (no corner cutting), and its cost.
  bool step(const Index3& from, int32_t fromIndex, size_t m, double* cost) {
    const Move& move = moves()[m];
    const Index3 to = from + move.delta;
    if (!inside(to)) return false;
    const double toWeight = weightAt(fromIndex + moveOffset[m], to);
    if (toWeight <= 0.0) return false;
    for (size_t k = 0; k < move.grazed.size(); ++k)
      if (weightAt(fromIndex + grazedOffset[m][k], from + move.grazed[k]) <= 0.0) return false;
    *cost = move.length * grid.resolution() * 0.5 * (weightAt(fromIndex, from) + toWeight);
    return true;
  }
  bool lineOfSight(const Index3& a, const Index3& b, double* cost) {
    return walkSegment(
        a.cast<double>().array() + 0.5, b.cast<double>().array() + 0.5, grid.resolution(),
        [this](const Index3& cell) { return weightOf(cell); }, cost);
  }
};

void PathSearcher::prepare(const VoxelGrid& grid) {
  const size_t n = grid.cellCount();
  COINSPECT_ASSERT(n < static_cast<size_t>(std::numeric_limits<int32_t>::max()));
  if (stamp_.size() < n) {
    // Only the stamps need their zeros; a cell's other entries are written when it is stamped.
    // A smaller grid later uses the first cells: their stamps are older generations.
    stamp_.reset(n);
    weightStamp_.reset(n);
    g_.reset(n);
    parent_.reset(n);
    flags_.reset(n);
    weight_.reset(n);
    generation_ = 0;
  }
  if (++generation_ == 0) {  // wrapped: forget every stamp once
    stamp_.zero();
    weightStamp_.zero();
    generation_ = 1;
  }
}

size_t PathSearcher::flood(const VoxelGrid& grid, const PathSearchOptions& options,
                           const Index3& from, const Index3& stopAt, size_t limit, bool* reached) {
  Query query(grid, options, weightStamp_, weight_, generation_);
  // A flooded cell is stamped as a search touches it (g infinite, no parent, no flags): to a
  // search of the same generation it reads as a cell not reached yet.
  const auto mark = [&](int32_t index) {
    stamp_[index] = generation_;
    g_[index] = kInf;
    parent_[index] = -1;
    flags_[index] = 0;
  };
  *reached = false;
  queue_.assign(1, from);
  mark(query.indexOf(from));
  for (size_t head = 0; head < queue_.size() && queue_.size() < limit; ++head)
    for (const Index3& face : kFaces) {
      const Index3 next = queue_[head] + face;
      if (!query.inside(next)) continue;
      const int32_t index = query.indexOf(next);
      if (stamp_[index] == generation_ || query.weightAt(index, next) <= 0.0) continue;
      if (next == stopAt) {
        *reached = true;
        return queue_.size();
      }
      mark(index);
      queue_.push_back(next);
    }
  return queue_.size();
}

// A search closes each cell of the start's component once (the traversable cells 6-connected to
// it: a move without corner cutting crosses traversable face neighbours only, in both
// directions) and stops at the goal or after maxExpansions closures. So when the goal's
// component, flooded whole, does not hold the start, the search would end in NoPath after
// closing the start's component, or in BudgetExhausted when that component has maxExpansions
// cells or more: a second flood, of at most the budget, tells which. The goal's side is flooded
// up to kPocketCells only: an unreachable goal is typically in a small pocket (78 cells in each
// of the 23 searches that spent a whole budget in the first 150 s of a slei-c mission), and a
// reachable one costs that flood on top of its search (whose weight cache it fills).
bool PathSearcher::provedUnreachable(const VoxelGrid& grid, const PathSearchOptions& options,
                                     const Index3& startCell, const Index3& goalCell,
                                     PathResult* result) {
  constexpr size_t kPocketCells = 4096;
  const size_t limit = std::min(kPocketCells, options.maxExpansions);
  if (limit == 0 || startCell == goalCell) return false;
  bool reached = false;
  const size_t goalSide = flood(grid, options, goalCell, startCell, limit, &reached);
  if (reached || goalSide >= limit) return false;
  prepare(grid);  // a fresh generation: the start's side is flooded from scratch
  const size_t startSide =
      flood(grid, options, startCell, goalCell, options.maxExpansions, &reached);
  COINSPECT_ASSERT(!reached);  // the goal's component, flooded whole, did not hold the start
  result->status =
      startSide < options.maxExpansions ? PathStatus::NoPath : PathStatus::BudgetExhausted;
  result->expansions = std::min(startSide, options.maxExpansions);
  return true;
}

PathResult PathSearcher::aStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                               const PathSearchOptions& options) {
  return search(grid, start, goal, options, false);
}

PathResult PathSearcher::thetaStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                                   const PathSearchOptions& options) {
  return search(grid, start, goal, options, true);
}

PathResult PathSearcher::search(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                                const PathSearchOptions& options, bool anyAngle) {
  checkOptions(grid, options);
  PathResult result;
  Index3 startCell, goalCell;
  if (!nearestTraversableCell(grid, start, options.snapRadius, options, &startCell)) {
    result.status = PathStatus::StartBlocked;
    return result;
  }
  if (!nearestTraversableCell(grid, goal, options.snapRadius, options, &goalCell)) {
    result.status = PathStatus::GoalBlocked;
    return result;
  }
  result.startSnapped = startCell != grid.cellOf(start);
  result.goalSnapped = goalCell != grid.cellOf(goal);

  prepare(grid);
  if (!options.partialPath && provedUnreachable(grid, options, startCell, goalCell, &result))
    return result;
  Query query(grid, options, weightStamp_, weight_, generation_);
  const int32_t startIndex = query.indexOf(startCell);
  const int32_t goalIndex = query.indexOf(goalCell);
  const double resolution = grid.resolution();
  const double weight = options.heuristicWeight * resolution;
  const auto heuristic = [&](const Index3& cell) {
    return anyAngle ? (cell - goalCell).cast<double>().norm() * weight
                    : octile(cell, goalCell) * weight;
  };
  const auto touch = [&](int32_t index) {
    if (stamp_[index] != generation_) {
      stamp_[index] = generation_;
      g_[index] = kInf;
      parent_[index] = -1;
      flags_[index] = 0;
    }
  };

  // Open list: least f first; ties to the larger g (deeper, fewer re-expansions), then index.
  struct Entry {
    double f, g;
    int32_t index;
  };
  const auto later = [](const Entry& a, const Entry& b) {
    if (a.f != b.f) return a.f > b.f;
    if (a.g != b.g) return a.g < b.g;
    return a.index > b.index;
  };
  std::vector<Entry> open;
  const auto push = [&](int32_t index, const Index3& cell) {
    open.push_back({g_[index] + heuristic(cell), g_[index], index});
    std::push_heap(open.begin(), open.end(), later);
  };

  touch(startIndex);
  g_[startIndex] = 0.0;
  parent_[startIndex] = startIndex;
  flags_[startIndex] = kVerified;
  push(startIndex, startCell);
  int32_t nearest = startIndex;
  double nearestDistance = kInf;
  bool found = false, exhausted = false;
  const auto& allMoves = moves();

  while (!open.empty()) {
    std::pop_heap(open.begin(), open.end(), later);
    const Entry entry = open.back();
    open.pop_back();
    const int32_t index = entry.index;
    if ((flags_[index] & kClosed) || entry.g != g_[index]) continue;  // stale entry
    const Index3 cell = query.cellOf(index);

    if (anyAngle && !(flags_[index] & kVerified)) {
      // Lazy Theta*: the entry assumed line of sight from the parent at the lowest possible
      // cost. Check it now, and compare with the best expanded neighbour (also the fallback
      // without line of sight): with cost fields a straight segment through expensive cells
      // can cost more than the grid step, and this keeps g <= g(neighbour) + step.
      const int32_t parent = parent_[index];
      const Index3 parentCell = query.cellOf(parent);
      double cost = 0.0;
      double exact = kInf;
      if (query.lineOfSight(parentCell, cell, &cost)) exact = g_[parent] + cost;
      for (size_t m = 0; m < allMoves.size(); ++m) {
        const Index3 from = cell - allMoves[m].delta;
        if (!query.inside(from)) continue;
        const int32_t fromIndex = index - query.moveOffset[m];
        if (stamp_[fromIndex] != generation_ || !(flags_[fromIndex] & kClosed)) continue;
        double stepCost = 0.0;
        if (!query.step(from, fromIndex, m, &stepCost)) continue;
        if (g_[fromIndex] + stepCost < exact) {
          exact = g_[fromIndex] + stepCost;
          parent_[index] = fromIndex;
        }
      }
      COINSPECT_ASSERT(exact < kInf);  // the expanding neighbour is always a valid fallback
      flags_[index] |= kVerified;
      // The walk sums per-cell pieces: allow its rounding before calling the guess too low.
      const bool raised = exact > g_[index] + 1e-9 * (1.0 + g_[index]);
      g_[index] = exact;
      if (raised) {
        push(index, cell);
        continue;
      }
    }

    flags_[index] |= kClosed;
    ++result.expansions;
    const double distance = (cell - goalCell).cast<double>().squaredNorm();
    if (distance < nearestDistance) {
      nearestDistance = distance;
      nearest = index;
    }
    if (index == goalIndex) {
      found = true;
      break;
    }
    if (result.expansions >= options.maxExpansions) {
      exhausted = true;
      break;
    }

    const int32_t grandParent = parent_[index];
    const Index3 grandParentCell = query.cellOf(grandParent);
    for (size_t m = 0; m < allMoves.size(); ++m) {
      double stepCost = 0.0;
      if (!query.step(cell, index, m, &stepCost)) continue;
      const Index3 next = cell + allMoves[m].delta;
      const int32_t nextIndex = index + query.moveOffset[m];
      touch(nextIndex);
      if (flags_[nextIndex] & kClosed) continue;
      double candidate;
      int32_t candidateParent;
      uint8_t verified;
      if (anyAngle && grandParent != index) {
        // Optimistic: straight from the grandparent at multiplier 1 (checked when popped).
        candidate = g_[grandParent] + (next - grandParentCell).cast<double>().norm() * resolution;
        candidateParent = grandParent;
        verified = 0;
      } else {
        candidate = g_[index] + stepCost;
        candidateParent = index;
        verified = kVerified;
      }
      if (candidate < g_[nextIndex]) {
        g_[nextIndex] = candidate;
        parent_[nextIndex] = candidateParent;
        flags_[nextIndex] = verified;
        push(nextIndex, next);
      }
    }
  }

  if (!found && !exhausted) {
    result.status = PathStatus::NoPath;
    return result;
  }
  result.status = found ? PathStatus::Found : PathStatus::BudgetExhausted;
  const int32_t last = found ? goalIndex : nearest;
  for (int32_t index = last;; index = parent_[index]) {
    result.cells.push_back(query.cellOf(index));
    if (index == startIndex) break;
  }
  std::reverse(result.cells.begin(), result.cells.end());
  result.cost = g_[last];
  constexpr double kSame = 1e-9;
  if ((grid.centre(result.cells.front()) - start).norm() > kSame) result.points.push_back(start);
  for (const auto& cell : result.cells)
    result.points.push_back(grid.centre(cell));
  if (found && !result.goalSnapped && (result.points.back() - goal).norm() > kSame)
    result.points.push_back(goal);
  return result;
}

PathSearcher& threadPathSearcher() {
  thread_local PathSearcher searcher;
  return searcher;
}

PathResult findPathAStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                         const PathSearchOptions& options) {
  PathSearcher searcher;
  return searcher.aStar(grid, start, goal, options);
}

PathResult findPathThetaStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                             const PathSearchOptions& options) {
  PathSearcher searcher;
  return searcher.thetaStar(grid, start, goal, options);
}

std::vector<uint8_t> reachableCells(const VoxelGrid& grid, const Vec3& start,
                                    const PathSearchOptions& options) {
  std::vector<uint8_t> reached(grid.cellCount(), 0);
  Index3 first;
  if (!nearestTraversableCell(grid, start, options.snapRadius, options, &first)) return reached;
  // Reused: a flood of a whole grid grew a fresh queue of up to millions of cells per call.
  thread_local std::vector<Index3> queue;
  queue.assign(1, first);
  reached[grid.linear(first)] = 1;
  for (size_t head = 0; head < queue.size(); ++head)
    for (const Index3& face : kFaces) {
      const Index3 next = queue[head] + face;
      if (!grid.contains(next) || reached[grid.linear(next)] ||
          !cellTraversable(grid, next, options))
        continue;
      reached[grid.linear(next)] = 1;
      queue.push_back(next);
    }
  return reached;
}

bool ReachableCellsCache::sameQuestion(const VoxelGrid& grid, uint64_t gridVersion,
                                       const PathSearchOptions& options) const {
  if (grid_ != &grid || gridVersion_ != gridVersion || reached_.size() != grid.cellCount())
    return false;
  if (options_.clearance != options.clearance || options_.unknown != options.unknown ||
      options_.snapRadius != options.snapRadius || options_.avoid.size() != options.avoid.size())
    return false;
  for (size_t i = 0; i < options.avoid.size(); ++i)
    if (options_.avoid[i].centre != options.avoid[i].centre ||
        options_.avoid[i].radius != options.avoid[i].radius)
      return false;
  return true;
}

const std::vector<uint8_t>& ReachableCellsCache::from(const VoxelGrid& grid, uint64_t gridVersion,
                                                      const Vec3& start,
                                                      const PathSearchOptions& options) {
  Index3 first;
  // A start with no traversable cell near reaches nothing: flooded anew (all 0), never reused.
  if (sameQuestion(grid, gridVersion, options) &&
      nearestTraversableCell(grid, start, options.snapRadius, options, &first) &&
      reached_[grid.linear(first)])
    return reached_;
  reached_ = reachableCells(grid, start, options);
  ++floods_;
  grid_ = &grid;
  gridVersion_ = gridVersion;
  options_ = options;
  return reached_;
}

}  // namespace coinspect::planning
