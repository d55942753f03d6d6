// coinspect's own scenario format: an INI file that names mesh files, boxes, interest points
// and the fleet (every key is documented in doc/config.md).
#pragma once

#include <filesystem>

#include "coinspect/world/scenario.h"

namespace coinspect::world {

// Loads `scenario.ini` (and the files it names, relative to its folder). Unknown keys, missing
// files and malformed values throw InputError naming the file and key.
Scenario loadScenario(const std::filesystem::path& iniPath);

// Writes <folder>/scenario.ini, meshes as binary STL and interest points as CARIC PCD, so that
// loadScenario reads back the same scenario (same contentHash).
void saveScenario(const Scenario& scenario, const std::filesystem::path& folder);

// Exports for other tools: meshes as one STL or PLY (by extension) and interest points as PCD or
// CSV (x,y,z,nx,ny,nz,idx).
void exportInterestPointsCsv(const InterestPointSet& points, const std::filesystem::path& path);

}  // namespace coinspect::world
