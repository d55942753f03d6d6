// A check of a PLY file's layout before Assimp reads it: Assimp's PLY reader never returns on a
// file cut inside its header, and pads a body cut short (missing vertices and faces) instead of
// failing, so that a truncated file would load as a smaller or wrong mesh. Found by fuzzing.
#pragma once

#include <filesystem>
#include <string>

namespace coinspect::world::detail {

// When the file starts as a PLY file ("ply" on the first line; only then is it read whole):
// throws InputError naming `source` unless the header ends (end_header) with known formats and
// property types and the body holds every element it declares (ASCII: enough numbers; binary:
// exactly as many bytes, list counts read in the file's byte order). Other formats pass
// unchecked.
void checkPlyLayout(const std::filesystem::path& path, const std::string& source);

}  // namespace coinspect::world::detail
