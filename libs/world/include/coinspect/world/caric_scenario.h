// Import of a reference CARIC scenario folder as a coinspect Scenario.
#pragma once

#include <filesystem>

#include "coinspect/world/scenario.h"

namespace coinspect::world {

// The folder holds one *.stl mesh, one *_interest_points.pcd, box_description.yaml, one
// caric_ppcom_network_*.txt and optionally a run_*.launch with start positions. Roles: the
// network's manager is the ground station; peers with a LiDAR in the reference (jurong, raffles)
// are explorers, the others photographers. Throws InputError naming the missing or bad file.
Scenario importCaricScenario(const std::filesystem::path& folder);

}  // namespace coinspect::world
