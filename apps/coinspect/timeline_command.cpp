// `coinspect plot-timeline --out FILE.png [--size WxH] RUN`: the status timeline of a feature
// mission (the SLEI3D paper's Fig. 12): what each unit reported doing over mission time, its
// meetings and its loss, from the run's rawlog (doc/evaluation.md, "Status timeline").
#include <cstdio>
#include <memory>
#include <system_error>

#include "coinspect/core/config.h"
#include "coinspect/core/error.h"
#include "coinspect/eval/run_tracks.h"
#include "coinspect/eval/status_timeline.h"
#include "commands.h"
#include "option_checks.h"
#include "picture_options.h"

namespace coinspect::app {

namespace {

struct PlotTimelineOptions {
  std::string out;
  std::string size = "1200x800";
  std::string run;
};

constexpr int kStatusDamaged = 1;

// A run folder holds run.rawlog; a file is taken as the rawlog itself.
std::filesystem::path rawlogOf(const std::filesystem::path& run) {
  std::error_code error;
  if (std::filesystem::is_directory(run, error)) {
    const auto rawlog = run / "run.rawlog";
    if (!std::filesystem::exists(rawlog, error))
      throw InputError(rawlog.string(), "",
                       "no run.rawlog in the run folder (coinspect run --out writes it unless "
                       "[record] rawlog = false)");
    return rawlog;
  }
  if (std::filesystem::exists(run, error)) return run;
  throw InputError(run.string(), "", "no such run folder or rawlog");
}

// "unit status over mission time (<strategy>, <scenario>)" from the recorded config.
std::string titleOf(const eval::RunTracks& tracks, const std::filesystem::path& rawlog) {
  const Config config =
      Config::fromText(tracks.header.configIni, rawlog.string() + " (run header)");
  std::string what = config.getString("strategy", "name", "");
  const std::string scenario = config.getString("mission", "scenario", "");
  if (!scenario.empty()) what += (what.empty() ? "" : ", ") + scenario;
  return "unit status over mission time" + (what.empty() ? "" : " (" + what + ")");
}

void createParentFolder(const std::filesystem::path& out) {
  if (!out.has_parent_path()) return;
  std::error_code error;
  std::filesystem::create_directories(out.parent_path(), error);
  if (error)
    throw InputError(out.parent_path().string(), "--out",
                     "cannot create the folder: " + error.message());
}

void plotTimeline(const PlotTimelineOptions& options) {
  const PictureSize size = parsePictureSize(options.size, "--size");
  const std::filesystem::path rawlog = rawlogOf(options.run);
  const eval::RunTracks tracks = eval::readRunTracks(rawlog);
  const auto reportDamage = [&](const char* what) {
    std::fprintf(stderr, "coinspect: rawlog damaged, %s: %s\n", what,
                 tracks.status.message.c_str());
    throw CommandStatus{kStatusDamaged};
  };
  eval::StatusTimeline timeline;
  try {
    timeline = eval::statusTimeline(tracks, rawlog.string());
  } catch (const InputError&) {
    // Cut before its first activity event, a feature run reads as another kind: say why.
    if (!tracks.status.clean) reportDamage("no timeline before the damage");
    throw;
  }
  const std::filesystem::path out(options.out);
  createParentFolder(out);
  eval::writePng(
      eval::renderStatusTimeline(timeline, titleOf(tracks, rawlog), size.width, size.height), out);
  std::printf("%s\n", out.string().c_str());
  std::fflush(stdout);
  if (!tracks.status.clean) reportDamage("the timeline shows the run up to the damage");
}

}  // namespace

void addPlotTimelineCommand(CLI::App& root) {
  auto options = std::make_shared<PlotTimelineOptions>();
  auto* plot = root.add_subcommand(
      "plot-timeline",
      "Draw what each unit of a feature-mission run did over mission time, with its meetings");
  plot->add_option("--out", options->out, "the PNG to write")->check(nonEmptyPath())->required();
  plot->add_option("--size", options->size, "picture size, WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  plot->add_option("RUN", options->run,
                   "run folder written by coinspect run --out (or its run.rawlog)")
      ->required();
  plot->footer(
      "One row per unit in fleet order: its reported activity as coloured segments, meetings as "
      "markers on both units' rows joined by a line, a cross where a unit was lost. Reads the "
      "rawlog's activity-changed, meeting and death events and prints the PNG's path. Exit "
      "status: 0, 1 when the rawlog is damaged (the picture shows the run up to the damage), 2 "
      "for bad input (a missing run, a run without activity events, a bad option).");
  plot->callback([options] { plotTimeline(*options); });
}

}  // namespace coinspect::app
