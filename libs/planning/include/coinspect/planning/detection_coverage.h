// Where an explorer must fly for its feature detector (doc/features.md) to pass over mapped
// surface: the detector sees a short range, a yaw sector about the heading and an elevation band
// about the horizontal, so a camera-style viewpoint (along the surface normal, looking at it)
// does not do: a roof seen from straight above lies outside the elevation band. Viewpoints here
// stand beside or above a patch, level, heading at it, inside conservative bounds of the real
// detector (the map's surface and normals are approximate).
#pragma once

#include <vector>

#include "coinspect/planning/coverage.h"

namespace coinspect::planning {

// The detector as planning assumes it: a margin inside the real one (5 m, +-45 deg, +-30 deg).
struct DetectorModel {
  double range = 4.8;          // m
  double halfYaw = 0.7;        // rad about the heading
  double halfElevation = 0.5;  // rad about the horizontal
  double minFacing = 0.15;     // cosine between the patch normal and the direction to the sensor
};

struct DetectionCoverageOptions {
  DetectorModel detector;
  std::vector<double> standoffs = {3.0, 4.0};  // m, horizontal distance from a patch
  double clearance = 1.5;                      // m, required clearance of a viewpoint in the grid
  double minHeight = 1.0;                      // m above `groundZ`
  double groundZ = 0.0;
  bool unknownHides = false;  // as CoverageOptions::unknownHides
  size_t candidatesPerPatch = 3;
  // Per grid cell, nonzero where the explorer can fly to (planning::reachableCells); null: all.
  const std::vector<uint8_t>* reachable = nullptr;
};

struct DetectionView {
  Vec3 position = Vec3::Zero();
  double yaw = 0.0;
  Vec3 target = Vec3::Zero();     // the patch it was placed for
  std::vector<uint32_t> covered;  // patches it newly covers (indices into the input)
};

// True when the detector at `position` heading `yaw` would see the patch (range, sector, band,
// facing, line of sight in the grid).
bool detects(const DetectorModel& detector, const mapping::VoxelGrid& grid, const Vec3& position,
             double yaw, const InspectionPatch& patch, bool unknownHides);

// Viewpoints (greedy set cover, largest newly covered weight first) until every patch that has a
// safe viewpoint is covered; patches without one are listed in `uncoverable` (may be null).
std::vector<DetectionView> detectionViews(const std::vector<InspectionPatch>& patches,
                                          const mapping::VoxelGrid& grid,
                                          const DetectionCoverageOptions& options,
                                          std::vector<uint32_t>* uncoverable = nullptr);

}  // namespace coinspect::planning
