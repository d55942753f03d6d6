// Inspection coverage: which camera positions see a set of surface patches well enough, chosen
// greedily so that few viewpoints cover many patches (set cover, ln n of the optimum). A patch
// counts as covered by a viewpoint when it is within `maxDistance` (q_res stays near 1), faces
// the camera within `maxIncidence`, lies inside the camera's view cone and is visible through
// known-free cells of the planning grid.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "coinspect/mapping/occupancy_map.h"
#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::planning {

using mapping::Vec3;

struct InspectionPatch {
  Vec3 centre = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, outward
  uint32_t weight = 1;          // surface voxels merged into the patch (a workload measure)
  // The patch's bin (position cell and normal axis): stable while the map grows, so a robot
  // can remember which patches it has already inspected.
  uint64_t key = 0;
};

// Groups surface voxels into patches of about `patchSize` m with similar normals (voxels are
// binned by position and by the dominant axis of their normal); deterministic order.
std::vector<InspectionPatch> groupSurface(const std::vector<mapping::SurfaceVoxel>& voxels,
                                          double patchSize);

// The mapped ground under the boxes (it lies inside them: boxes reach down to it): a voxel
// whose centre is within 1.25 cells of `groundZ` and whose normal points up (z > 0.8). No
// scenario has interest points there (the lowest, on the hangar's landing gear, face sideways),
// and on the generated hangar it was half of the surface a photographer planned over.
bool isGroundSurface(const mapping::SurfaceVoxel& voxel, double groundZ, double resolution);

struct CoverageOptions {
  double distance = 6.5;       // m, preferred camera-to-patch distance
  double maxDistance = 8.0;    // m, farther patches do not count as covered
  double maxIncidence = 1.05;  // rad between the patch normal and the direction to the camera
  double halfFov = 0.45;       // rad, cone around the optical axis that counts as in view
  double clearance = 1.5;      // m, required clearance of the camera position in the grid
  double minHeight = 1.5;      // m, camera height above `groundZ`
  double groundZ = 0.0;        // m
  // false: only occupied cells hide a patch from a camera; unknown ones do not. The patch was
  // mapped, so rays reached it through or beside that space, which is mostly empty; the camera
  // position itself must still be free with the clearance above.
  bool unknownHides = true;
};

struct CoverageView {
  Vec3 camera = Vec3::Zero();     // where the camera should be
  Vec3 target = Vec3::Zero();     // the point it looks at (the seed patch centre)
  std::vector<uint32_t> covered;  // indices of the patches it covers (newly, at selection time)
};

// Picks viewpoints until every coverable patch is covered; patches for which no safe camera
// position exists are reported in `uncoverable` (may be null). Cost: O(patches x neighbours x
// ray length); about a second or less for the few thousand patches of a CARIC scene.
std::vector<CoverageView> coverPatches(const std::vector<InspectionPatch>& patches,
                                       const mapping::VoxelGrid& grid,
                                       const CoverageOptions& options,
                                       std::vector<uint32_t>* uncoverable = nullptr);

// Where rays to a patch end: just outside its voxel face, so neighbouring surface voxels grazed
// by an oblique ray do not hide the patch, while anything in front of the surface still does.
Vec3 patchFace(const mapping::VoxelGrid& grid, const InspectionPatch& patch);

// Lazy greedy weighted set cover: `sees[c]` lists the patches candidate c covers (ascending).
// Returns the chosen candidates in the order picked, each with the patches it newly covers;
// ties go to the lower candidate index.
std::vector<std::pair<uint32_t, std::vector<uint32_t>>> greedyCover(
    const std::vector<std::vector<uint32_t>>& sees, const std::vector<InspectionPatch>& patches);

// True when the segment a-b crosses only Free cells of the grid (Unknown and Occupied block).
bool freeLineOfSight(const mapping::VoxelGrid& grid, const Vec3& a, const Vec3& b);
// The same with Unknown cells blocking only when `unknownBlocks`.
bool lineOfSight(const mapping::VoxelGrid& grid, const Vec3& a, const Vec3& b, bool unknownBlocks);

}  // namespace coinspect::planning
