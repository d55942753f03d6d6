// Shortest paths with clearance on a dense VoxelGrid: A* (26-connected) and Lazy Theta* (any
// angle). Both use one cost model and one traversability rule, shared with path smoothing:
//
//   traversable(cell) = inside the grid, not Occupied, not Unknown under UnknownPolicy::Blocked,
//                       grid.clearance(cell) >= PathSearchOptions::clearance, and the cell's
//                       centre outside every PathSearchOptions::avoid sphere
//   cost of a segment = sum over the cells it crosses of (length inside the cell) x multiplier,
//   multiplier(cell)  = 1 + softWeight x max(0, 1 - clearance(cell) / softClearance)
//                         + unknownPenalty (Unknown cells under UnknownPolicy::FreeWithCost)
//
// A move or segment is allowed only when every cell it touches is traversable, including cells it
// only grazes at an edge or a corner (no corner cutting): every point of a returned path lies in a
// traversable cell. The clearance field (VoxelGrid::computeClearance) is the caller's: it decides
// whether unknown cells count as obstacles for the distance; its cap must exceed the required
// clearance. Multipliers are >= 1, so the heuristics (3-D octile for A*, Euclidean for Theta*)
// stay admissible and A* returns a least-cost 26-connected path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::planning {

using mapping::Index3;
using mapping::Vec3;
using mapping::VoxelGrid;

enum class UnknownPolicy {
  Blocked,      // unknown cells are never entered
  Free,         // unknown cells are entered like free ones
  FreeWithCost  // entered, at (1 + unknownPenalty) times the cost per metre
};

// Space a path must keep out of that is not in the map (e.g. another robot holding there).
struct AvoidSphere {
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
};

struct PathSearchOptions {
  double clearance = 0.0;  // m, required distance field value (robot radius + margin)
  UnknownPolicy unknown = UnknownPolicy::Blocked;
  double unknownPenalty = 1.0;  // extra cost per metre in unknown cells (FreeWithCost)
  double softClearance = 0.0;   // m; cells closer than this to an obstacle cost more (0: off)
  double softWeight = 0.0;      // extra cost per metre at zero clearance, falling linearly to 0
  // f = g + heuristicWeight x h. 1 gives least-cost paths (A*); w > 1 (weighted A*) returns a
  // path costing at most w times the least and expands far fewer cells around obstacles.
  double heuristicWeight = 1.0;
  size_t maxExpansions = 1000000;
  int snapRadius = 3;  // cells: a blocked start or goal moves to the nearest traversable cell
  std::vector<AvoidSphere> avoid;  // cells whose centre is inside one are not traversable
  // false: a search that does not reach the goal may leave out the partial path of
  // BudgetExhausted (points and cells empty; status and expansions are still the search's).
  // That lets it prove a goal unreachable by flooding the goal's side first, which costs the
  // goal's enclosed pocket instead of the whole budget spent searching from the start.
  bool partialPath = true;
};

enum class PathStatus { Found, NoPath, StartBlocked, GoalBlocked, BudgetExhausted };
const char* toString(PathStatus status);

struct PathResult {
  PathStatus status = PathStatus::NoPath;
  // Found: the start point, the cell centres of the path's vertices, the goal point (the start
  // and goal points are dropped when they coincide with their cell centre). BudgetExhausted: the
  // start point and the vertices up to the expanded cell nearest the goal. Otherwise empty.
  std::vector<Vec3> points;
  std::vector<Index3> cells;  // the vertices' cells (A*: consecutive cells are neighbours)
  double cost = 0.0;          // weighted length (m) between the first and last cell centres
  size_t expansions = 0;
  bool startSnapped = false;  // the start (goal) cell was blocked; the search used the nearest
  bool goalSnapped = false;   // traversable cell within snapRadius
};

// A per-cell array of a searcher, zeroed by the system: calloc maps a large block to zero pages
// that cost neither time nor memory until written, so a search pays for the cells it touches
// only. std::vector's fill touched every page of every array up front (48 searchers on the
// 6 M-cell grids of `slei-d`: 8 GB, and page faults were a third of the mission's first 30 s).
template <class T>
class CellArray {
 public:
  size_t size() const { return size_; }
  void reset(size_t n) {  // n zeroed elements
    data_.reset(static_cast<T*>(std::calloc(n, sizeof(T))));
    if (!data_ && n > 0) throw std::bad_alloc();
    size_ = n;
  }
  void zero() {
    if (size_ > 0) std::memset(data_.get(), 0, size_ * sizeof(T));
  }
  T& operator[](size_t i) { return data_[i]; }

 private:
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T[], Free> data_;
  size_t size_ = 0;
};

// Reusable search state: the per-cell arrays are allocated for the largest grid seen and reset in
// O(1) between queries by a generation stamp, so repeated queries on a large grid cost only what
// they touch. A query's answer does not depend on the searcher's earlier queries, on this grid or
// another. Not thread-safe; use one searcher per thread (threadPathSearcher()).
class PathSearcher {
 public:
  // The grid must have a clearance field when clearance or softClearance is > 0.
  PathResult aStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                   const PathSearchOptions& options);
  PathResult thetaStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                       const PathSearchOptions& options);

 private:
  struct Query;
  void prepare(const VoxelGrid& grid);
  // Counts the traversable cells 6-connected to `from` (itself included) in this generation,
  // stopping after `limit` or at `stopAt`; sets *reached when it got to `stopAt`.
  size_t flood(const VoxelGrid& grid, const PathSearchOptions& options, const Index3& from,
               const Index3& stopAt, size_t limit, bool* reached);
  bool provedUnreachable(const VoxelGrid& grid, const PathSearchOptions& options,
                         const Index3& startCell, const Index3& goalCell, PathResult* result);
  PathResult search(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                    const PathSearchOptions& options, bool anyAngle);

  CellArray<double> g_;
  CellArray<int32_t> parent_;
  CellArray<uint32_t> stamp_;  // == generation_: g_/parent_/flags_ are valid for this query
  CellArray<uint8_t> flags_;
  CellArray<uint32_t> weightStamp_;  // == generation_: weight_ holds the cell's multiplier
  CellArray<double> weight_;         // (0: not traversable) under this query's options
  std::vector<Index3> queue_;        // flood()'s
  uint32_t generation_ = 0;
};

// This thread's searcher, for planners that search on behalf of many units. Each unit holding
// its own kept arrays of 29 bytes per cell of its grid, and over a long mission its searches
// touch most of them: 48 UAVs on `slei-d`'s 6 M-cell grids held 1.8 of the mission's 9.5 GB.
// A thread's units share one set instead; since no answer depends on earlier queries (above),
// which thread a unit decides on changes nothing.
PathSearcher& threadPathSearcher();

// One-shot conveniences (allocate a searcher).
PathResult findPathAStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                         const PathSearchOptions& options);
PathResult findPathThetaStar(const VoxelGrid& grid, const Vec3& start, const Vec3& goal,
                             const PathSearchOptions& options);

// The rule and cost model above, for other planners and for checking paths.
bool cellTraversable(const VoxelGrid& grid, const Index3& cell, const PathSearchOptions& options);
double cellCostMultiplier(const VoxelGrid& grid, const Index3& cell,
                          const PathSearchOptions& options);

// Walks the straight segment a -> b through the grid. Returns false when it touches a
// non-traversable cell; otherwise true and, when `cost` is given, its weighted length.
bool segmentTraversable(const VoxelGrid& grid, const Vec3& a, const Vec3& b,
                        const PathSearchOptions& options, double* cost = nullptr);

// The nearest traversable cell to `point` within `radius` cells (Euclidean distance of cell
// centres to the point; ties to the lowest linear index). False when there is none.
bool nearestTraversableCell(const VoxelGrid& grid, const Vec3& point, int radius,
                            const PathSearchOptions& options, Index3* cell);

// Per cell (VoxelGrid::linear), 1 when a path search from `start` (snapped as a search start
// is, within options.snapRadius) can reach it: the traversable cells 6-connected to the start's
// (a 26-connected move without corner cutting crosses only traversable face neighbours, so the
// two connectivities reach the same cells). All 0 when the start has no traversable cell near.
// One breadth-first pass, O(cells): lets a planner drop goals no search would reach before it
// spends a search budget on each.
std::vector<uint8_t> reachableCells(const VoxelGrid& grid, const Vec3& start,
                                    const PathSearchOptions& options);

// reachableCells kept while the grid is unchanged. The cells reachable from a start are its
// snapped cell's component, the same set from any start that snaps into it, so a planner asking
// from near where it asked before (a meeting point for each of several partners, then its own
// views) floods the grid once per grid version instead of once per question: on `slei-d`'s
// 6 M-cell grids the floods were a quarter of a profile at 650 s. `gridVersion` must change
// whenever the grid's cells do (runtime::RobotMap::gridVersion).
class ReachableCellsCache {
 public:
  const std::vector<uint8_t>& from(const VoxelGrid& grid, uint64_t gridVersion, const Vec3& start,
                                   const PathSearchOptions& options);
  size_t floods() const { return floods_; }

 private:
  bool sameQuestion(const VoxelGrid& grid, uint64_t gridVersion,
                    const PathSearchOptions& options) const;

  std::vector<uint8_t> reached_;
  const VoxelGrid* grid_ = nullptr;
  uint64_t gridVersion_ = 0;
  PathSearchOptions options_;  // the fields a flood reads: clearance, unknown, snapRadius, avoid
  size_t floods_ = 0;
};

}  // namespace coinspect::planning
