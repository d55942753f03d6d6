// `coinspect render RAWLOG [--scenario SOURCE] [--out DIR] [--size WxH]`: the pictures of a
// recorded run (doc/evaluation.md, "Pictures"): score.png, top.png, side.png, final3d.png and
// scene.3Dscene. Exit status 1 when the rawlog is damaged (the pictures show the run up to the
// damage), as for `coinspect eval`.
#include <cstdio>
#include <memory>

#include "coinspect/eval/run_pictures.h"
#include "coinspect/eval/run_tracks.h"
#include "commands.h"
#include "option_checks.h"
#include "picture_options.h"
#include "recorded_run.h"

namespace coinspect::app {

namespace {

struct RenderOptions {
  std::string rawlog;
  std::string scenario;
  std::string out;  // default: the rawlog's folder
  std::string size = "1200x800";
};

constexpr int kStatusDamaged = 1;

void renderRecordedRun(const RenderOptions& options) {
  const PictureSize size = parsePictureSize(options.size, "--size");
  const RecordedRun run = openRecordedRun(options.rawlog, options.scenario);
  const eval::RunTracks tracks = eval::readRunTracks(run.rawlog, run.latestTime());
  const std::filesystem::path folder =
      options.out.empty() ? run.rawlog.parent_path() : std::filesystem::path(options.out);
  const auto paths = eval::writeRunPictures(run.scenario, tracks, folder.empty() ? "." : folder,
                                            size.width, size.height);
  for (const auto& path : paths)
    std::printf("%s\n", path.string().c_str());
  std::fflush(stdout);
  if (!tracks.status.clean) {
    std::fprintf(stderr, "coinspect: rawlog damaged, pictures show the run up to the damage: %s\n",
                 tracks.status.message.c_str());
    throw CommandStatus{kStatusDamaged};
  }
}

}  // namespace

void addRenderCommand(CLI::App& root) {
  auto options = std::make_shared<RenderOptions>();
  auto* render = root.add_subcommand(
      "render", "Draw a recorded run: score plot, top and side views, 3D render, .3Dscene");
  render->add_option("rawlog", options->rawlog, "run.rawlog written by coinspect run --out")
      ->required();
  render
      ->add_option("--scenario", options->scenario,
                   "scenario SOURCE (generator, scenario.ini, CARIC folder) when the recorded "
                   "one cannot be found; its content hash must match the recorded one")
      ->check(nonEmptyPath());
  render->add_option("--out", options->out, "folder for the pictures (default: the rawlog's)")
      ->check(nonEmptyPath());
  render->add_option("--size", options->size, "size of every picture, WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  render->footer(
      "Writes score.png, top.png, side.png, final3d.png and scene.3Dscene (open it with MRPT's "
      "SceneViewer3D) and prints their paths. Exit status: 0, 1 when the rawlog is damaged (the "
      "pictures show the run up to the damage), 2 for bad input.");
  render->callback([options] { renderRecordedRun(*options); });
}

}  // namespace coinspect::app
