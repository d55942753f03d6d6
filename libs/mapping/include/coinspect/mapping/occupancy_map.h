// One robot's occupancy memory, fed by its own LiDAR sweeps and by the key frames it received,
// with the queries planners need. Cells, their keys and their log-odds are OctoMap's (an
// octomap::OcTree fed the same updates holds the same cells: unit tests compare them), stored in
// blocks of 8^3 cells instead of a tree (src/cell_blocks.h: a sixth of the memory). Every query
// is deterministic and independent of the order in which equal information arrived only as far
// as OctoMap's log-odds clamping allows.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::mapping {

class CellBlocks;  // src/cell_blocks.h: the cells

struct OccupancyMapOptions {
  double resolution = 0.5;  // m, leaf size
  double maxRange = 30.0;   // m; returns farther away only clear free space up to this range
  // false: a ray passing through a cell that is occupied leaves it occupied (insertScan, merge);
  // only observeCells' free observations clear it. For static worlds: thin structure (a wing's
  // trailing edge, a railing) is hit by few rays and passed by many at grazing angles, which
  // otherwise erase it from the map although it is still there.
  bool raysClearOccupied = true;
};

// A free cell of the map next to unknown space (what exploration is after).
struct FrontierCluster {
  std::vector<Vec3> cells;  // centres, deterministic order
  Vec3 centroid = Vec3::Zero();
};

// Each cluster cut into the parts that fall in one cube of `chunk` m (cubes aligned with the
// origin), parts in ascending cube order, cells in their order within the cluster; a cluster
// inside one cube stays whole. FUEL splits large frontiers the same way (it halves them along
// their principal axis): one viewpoint per part instead of one for a frontier that spans a
// whole roof.
std::vector<FrontierCluster> splitFrontierClusters(const std::vector<FrontierCluster>& clusters,
                                                   double chunk);

// An occupied cell next to free space, with an outward normal estimated from its neighbourhood.
struct SurfaceVoxel {
  Vec3 centre = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, pointing into free space
};

class OccupancyMap {
 public:
  explicit OccupancyMap(const OccupancyMapOptions& options = {});
  ~OccupancyMap();
  OccupancyMap(OccupancyMap&&) noexcept;
  OccupancyMap& operator=(OccupancyMap&&) noexcept;
  OccupancyMap(const OccupancyMap&) = delete;
  OccupancyMap& operator=(const OccupancyMap&) = delete;

  const OccupancyMapOptions& options() const { return options_; }

  // Inserts one scan (points in the world frame, returns only) taken from `origin`: cells along
  // each ray become more likely free, end cells more likely occupied; each cell is updated once
  // per scan. Used for own sweeps and for received key frames alike. Points beyond the key range
  // extent (+-16 km at 0.5 m) are skipped; a non-finite point or origin is a bug (assert).
  void insertScan(const Vec3& origin, const std::vector<Eigen::Vector3f>& worldPoints);
  // insertScan in two halves: the cells a scan observes depend only on the scan, the resolution
  // and the range cap, so robots inserting the same relayed key frame can find them once and
  // apply them each to their own map (the same result as insertScan, cell for cell).
  struct ScanCells {
    double resolution = 0.0;
    double maxRange = 0.0;
    std::vector<uint64_t> codes;  // sorted update codes, one per cell (see src/cell_blocks.h)
  };
  ScanCells scanCells(const Vec3& origin, const std::vector<Eigen::Vector3f>& worldPoints) const;
  // Applies cells found by a map of the same resolution and range cap (assert).
  void insertScanCells(const ScanCells& cells);
  // Adds every known cell of `other` (same resolution required) as one observation each.
  void merge(const OccupancyMap& other);
  // One free observation for the cell of each of `freePoints`, one occupied observation for the
  // cell of each of `occupiedPoints` (occupied wins for a cell in both), as one scan would give:
  // for synthetic maps (tests, planners' fixtures) and for cells known free for certain (a
  // robot's body is there), which is why these free observations apply even when
  // `raysClearOccupied` is false.
  void observeCells(const std::vector<Vec3>& freePoints, const std::vector<Vec3>& occupiedPoints);
  // With raysClearOccupied false: where rays clear occupied cells after all (called with the
  // cell's centre; empty: nowhere). A robot that knows where structure can be keeps it there and
  // lets moving things elsewhere (another UAV seen from afar) leave its map once rays pass.
  void setRaysClearAt(std::function<bool(const Vec3&)> clearAt) {
    raysClearAt_ = std::move(clearAt);
  }

  CellState state(const Vec3& point) const;
  // Distance (m) from `point` to the nearest occupied cell centre, `maxDistance` if none nearer.
  double clearance(const Vec3& point, double maxDistance) const;
  // A dense snapshot of [min, max] at `resolution` (a multiple of the map's works best), for
  // path search; a dense cell is Occupied if any map leaf inside it is, else Free if any is, else
  // Unknown.
  VoxelGrid toVoxelGrid(const Vec3& min, const Vec3& max, double resolution) const;
  // The cells [from, to] (inclusive, inside `whole`) of a grid of frame `whole`, as a grid of
  // their own (its cell c is the whole grid's from + c): each reads as in the whole grid, at
  // the cost of the part only.
  VoxelGrid toVoxelGrid(const GridFrame& whole, const Index3& from, const Index3& to) const;
  // The bounds of the centres of the map cells whose state changed (unknown to known, free to
  // occupied or back) since the last call, which forgets them; nothing when none did. Grids
  // derived from the map need to be read again there only.
  std::optional<std::pair<Vec3, Vec3>> takeChangedCentres();

  // Free cells with an unknown face neighbour inside [min, max], grouped by 26-connectivity into
  // clusters of at least `minClusterSize` cells; deterministic order.
  std::vector<FrontierCluster> frontierClusters(const Vec3& min, const Vec3& max,
                                                size_t minClusterSize) const;
  // Occupied cells with a free face neighbour inside [min, max], deterministic order.
  std::vector<SurfaceVoxel> surfaceVoxels(const Vec3& min, const Vec3& max) const;

  size_t occupiedCount() const;
  size_t knownCount() const;
  // Centre of the map cell holding `point` (cells are cubes of the resolution aligned with 0).
  Vec3 cellCentre(const Vec3& point) const;
  // Bumped by every insertScan/merge: lets callers rebuild derived grids only when needed.
  uint64_t revision() const { return revision_; }

  // OctoMap's log-odds of one hit and of one miss (its default sensor model).
  float hitLogOdds() const;
  float missLogOdds() const;
  // Every known cell: OctoMap's key of the cell (16 bits per axis, 32768 at the origin), its
  // centre and log-odds; in ascending key order (z, then y, then x).
  struct KnownCell {
    std::array<int, 3> key{};
    Vec3 centre = Vec3::Zero();
    float logOdds = 0.0f;
    bool occupied = false;
  };
  std::vector<KnownCell> knownCells() const;

 private:
  // Sorts and deduplicates the update codes in scratch_ (occupied wins) and applies them.
  void applyScratch(bool missesClearOccupied);
  // The unsorted update codes of one scan (repeats possible) appended to `codes`.
  void collectScan(const Vec3& origin, const std::vector<Eigen::Vector3f>& worldPoints,
                   std::vector<uint64_t>& codes, std::vector<uint64_t>& sortBuffer) const;

  OccupancyMapOptions options_;
  std::function<bool(const Vec3&)> raysClearAt_;
  std::unique_ptr<CellBlocks> cells_;
  std::vector<uint64_t> scratch_;     // update codes of the current scan (reused)
  std::vector<uint64_t> sortBuffer_;  // radix sort buffer (reused)
  uint64_t revision_ = 0;
};

}  // namespace coinspect::mapping
