#include "coinspect/eval/run_pictures.h"

#include <system_error>

#include "coinspect/core/error.h"
#include "coinspect/eval/run_plots.h"
#include "coinspect/eval/run_scene3d.h"

namespace coinspect::eval {

std::vector<std::filesystem::path> writeRunPictures(const world::Scenario& scenario,
                                                    const RunTracks& tracks,
                                                    const std::filesystem::path& folder, int width,
                                                    int height) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "", "cannot create the folder: " + error.message());
  const std::vector<std::filesystem::path> paths = {folder / "score.png", folder / "top.png",
                                                    folder / "side.png", folder / "final3d.png",
                                                    folder / "scene.3Dscene"};
  writePng(renderScorePlot(tracks, scenario.name, width, height), paths[0]);
  writePng(renderPlanView(scenario, tracks, PlanAxis::Top, width, height), paths[1]);
  writePng(renderPlanView(scenario, tracks, PlanAxis::Side, width, height), paths[2]);
  writeFinalScene3d(scenario, tracks, paths[3], paths[4], width, height);
  return paths;
}

}  // namespace coinspect::eval
