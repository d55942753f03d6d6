// `coinspect replay RAWLOG [--scenario SOURCE] [--out DIR] [--fps N] [--size WxH]
// [--view overview|chase:<unit>]`: prints the run's events as the replay reaches them and writes
// one PNG frame per 1/fps s of mission time to DIR/frames/000000.png, ... (doc/evaluation.md,
// "Replay frames"). A video is left to the user's own tools (e.g. ffmpeg): an MP4 writer would
// need OpenCV, which coinspect does not depend on.
#include <cinttypes>
#include <cstdio>
#include <memory>
#include <system_error>

#include "coinspect/core/error.h"
#include "coinspect/eval/run_scene3d.h"
#include "coinspect/eval/run_tracks.h"
#include "commands.h"
#include "option_checks.h"
#include "picture_options.h"
#include "progress.h"
#include "recorded_run.h"

namespace coinspect::app {

namespace {

struct ReplayOptions {
  std::string rawlog;
  std::string scenario;
  std::string out;  // default: the rawlog's folder
  double fps = 10.0;
  std::string size = "960x540";
  std::string view = "overview";
};

constexpr int kStatusDamaged = 1;

std::string frameName(size_t index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06zu.png", index);
  return name;
}

// Tally totals at time t (the last record not after it).
void tallyAt(const eval::RunTracks& tracks, double t, double& score, uint64_t& detected) {
  score = 0.0;
  detected = 0;
  for (const auto& sample : tracks.tally) {
    if (sample.time > t) break;
    score = sample.totalScore;
    detected = sample.detected;
  }
}

void replayRecordedRun(const ReplayOptions& options) {
  const PictureSize size = parsePictureSize(options.size, "--size");
  const RecordedRun run = openRecordedRun(options.rawlog, options.scenario);
  const eval::RunTracks tracks = eval::readRunTracks(run.rawlog, run.latestTime());
  const eval::CameraView view = eval::parseCameraView(options.view, tracks, "--view");
  const std::filesystem::path folder =
      (options.out.empty() ? run.rawlog.parent_path() : std::filesystem::path(options.out)) /
      "frames";
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "", "cannot create the folder: " + error.message());

  const size_t frames = eval::replayFrameCount(tracks.endTime, options.fps);
  eval::ReplayRenderer renderer(run.scenario, tracks, size.width, size.height, view);
  ProgressLine progress(stderr, "replay", tracks.endTime);
  size_t nextEvent = 0;
  for (size_t k = 0; k < frames; ++k) {
    const double t = static_cast<double>(k) / options.fps;
    // Events up to this frame's time, as they happen (the last frame takes any left).
    while (nextEvent < tracks.events.size() &&
           (tracks.events[nextEvent].time <= t || k + 1 == frames)) {
      const auto& event = tracks.events[nextEvent++];
      std::printf("%10.3f s  %-16s %-12s %s\n", event.time, eval::eventKindName(event.kind).c_str(),
                  event.unit.empty() ? "-" : event.unit.c_str(), event.detail.c_str());
    }
    std::fflush(stdout);
    eval::writePng(renderer.frameAt(t), folder / frameName(k), eval::kPngFast);
    double score;
    uint64_t detected;
    tallyAt(tracks, t, score, detected);
    progress.update(t, score, detected, tracks.pointCount);
  }
  progress.finish();
  std::printf("frames     %zu at %g fps for t = 0 to %.3f s in %s (%s to %s)\n", frames,
              options.fps, tracks.endTime, folder.string().c_str(), frameName(0).c_str(),
              frameName(frames - 1).c_str());
  std::fflush(stdout);
  if (!tracks.status.clean) {
    std::fprintf(stderr, "coinspect: rawlog damaged, the replay ends at the damage: %s\n",
                 tracks.status.message.c_str());
    throw CommandStatus{kStatusDamaged};
  }
}

}  // namespace

void addReplayCommand(CLI::App& root) {
  auto options = std::make_shared<ReplayOptions>();
  auto* replay = root.add_subcommand(
      "replay", "Replay a recorded run: print its events, write one PNG frame per 1/fps s");
  replay->add_option("rawlog", options->rawlog, "run.rawlog written by coinspect run --out")
      ->required();
  replay
      ->add_option("--scenario", options->scenario,
                   "scenario SOURCE when the recorded one cannot be found (content hash must "
                   "match)")
      ->check(nonEmptyPath());
  replay
      ->add_option("--out", options->out,
                   "folder whose frames/ subfolder gets the frames (default: the rawlog's)")
      ->check(nonEmptyPath());
  replay->add_option("--fps", options->fps, "frames per second of mission time")
      ->check(finiteNumberIn(0.01, 1000.0))
      ->capture_default_str();
  replay->add_option("--size", options->size, "frame size, WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  replay
      ->add_option("--view", options->view,
                   "camera: overview, or chase:<unit> (behind the unit, along its heading)")
      ->capture_default_str();
  replay->footer(
      "Frames are DIR/frames/000000.png, 000001.png, ... at t = 0, 1/fps, ... to the end of the "
      "run. Make a video with your own tools, e.g. ffmpeg -framerate 10 -i frames/%06d.png "
      "-pix_fmt yuv420p replay.mp4. Exit status: 0, 1 when the rawlog is damaged (the replay "
      "ends at the damage), 2 for bad input.");
  replay->callback([options] { replayRecordedRun(*options); });
}

}  // namespace coinspect::app
