// Team STAR's inspection pieces: the deterministic split of the boxes' surface between units of
// one role, the "star/inspected" message (keys of the surface patches a unit has covered), and
// the clustering of inspection viewpoints by proximity and mutual visibility.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/mapping/voxel_grid.h"
#include "coinspect/planning/coverage.h"
#include "coinspect/strategies/coinspect/work_partition.h"

namespace coinspect::strategies::star {

using agent::Vec3;

inline constexpr const char* kInspectedTopic = "star/inspected";

// The boxes' faces sampled and cut into `parts` compact regions of about equal area (the
// coinspect work partition, every unit computes the same); a point belongs to the region of the
// nearest sample.
class SurfaceSplit {
 public:
  SurfaceSplit(const std::vector<agent::BoxView>& boxes, double groundZ, size_t parts);

  size_t parts() const { return parts_; }
  uint32_t ownerOf(const Vec3& point) const;
  // The sample of region `part` nearest `near`, moved `standoff` m out along its face normal
  // (where a unit waits for its region to be mapped). None for an empty region.
  std::optional<Vec3> standoffPoint(uint32_t part, const Vec3& near, double standoff) const;

 private:
  size_t parts_;
  std::vector<coinspect_strategy::WorkItem> items_;
  std::vector<uint32_t> region_;
};

// Message bytes: the keys sorted and deduplicated, as LEB128 varints of the differences.
std::vector<uint8_t> encodeKeys(std::vector<uint64_t> keys);
// False (and `out` untouched) for malformed bytes.
bool decodeKeys(const std::vector<uint8_t>& bytes, std::vector<uint64_t>* out);

// The patches whose key is not in `inspected`, in their order.
std::vector<planning::InspectionPatch> dropInspected(
    const std::vector<planning::InspectionPatch>& patches, const std::set<uint64_t>& inspected);

// Greedy clustering of camera positions: each joins the first cluster whose first member is
// within `radius` and in free line of sight in `grid` (when given), else starts a new one.
// Clusters hold indices into `cameras`, in order.
std::vector<std::vector<size_t>> clusterViews(const std::vector<Vec3>& cameras, double radius,
                                              const mapping::VoxelGrid* grid);

}  // namespace coinspect::strategies::star
