// Every picture of a recorded run in one call (what `coinspect render` writes).
#pragma once

#include <filesystem>
#include <vector>

#include "coinspect/eval/run_tracks.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval {

// Writes into `folder` (created if missing), each width x height: score.png, top.png, side.png,
// final3d.png, and scene.3Dscene; returns their paths in that order. Throws InputError naming a
// file that cannot be written, std::runtime_error when no EGL context can be created.
std::vector<std::filesystem::path> writeRunPictures(const world::Scenario& scenario,
                                                    const RunTracks& tracks,
                                                    const std::filesystem::path& folder, int width,
                                                    int height);

}  // namespace coinspect::eval
