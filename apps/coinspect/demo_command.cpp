// `coinspect demo`: scores ideal captures without flying. Loads a scenario, places each
// photographer's camera at the ideal standoff in front of the interest points (one capture per
// point not yet counted), scores every capture with the reference's InspectionScorer, merges the
// photographers' logs at the ground station and prints a summary plus a picture.
//
// The viewpoints are chosen with full knowledge of the interest points: this is a demonstration
// of the scorer and an upper-bound reference for strategies, not a strategy (strategies never see
// the interest points).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "coinspect/core/error.h"
#include "coinspect/eval/scene_render.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sensing/score_log.h"
#include "coinspect/world/ray_caster.h"
#include "coinspect/world/scenario_source.h"
#include "commands.h"
#include "option_checks.h"

namespace coinspect::app {

namespace {

struct DemoOptions {
  std::string scenario = "mbs";
  uint64_t seed = 1;
  std::string mode = "caric";
  std::string out = "out/demo";
  int width = 1200;
  int height = 720;
};

// The clearance a viewpoint needs from any surface (the photographer's collision radius is
// about 0.32 m; keep a margin) and from the ground.
constexpr double kViewpointClearance = 1.0;
constexpr double kMinimumHeight = 0.5;

void runDemo(const DemoOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto mode = sensing::parseScoringMode(options.mode, "--mode");
  const auto started = Clock::now();
  const world::Scenario scenario = world::loadScenarioSource(options.scenario, options.seed);
  const world::RayCaster caster(scenario.meshes, scenario.groundZ);
  const auto loaded = Clock::now();

  std::vector<const world::UnitSpec*> photographers;
  for (const auto& unit : scenario.fleet)
    if (unit.role == world::UnitRole::Photographer) photographers.push_back(&unit);
  if (photographers.empty())
    for (const auto& unit : scenario.fleet)
      if (unit.role != world::UnitRole::GroundStation) photographers.push_back(&unit);
  if (photographers.empty())
    throw InputError(options.scenario, "fleet", "no UAV to carry a camera");

  const auto& points = scenario.interestPoints;
  sensing::InspectionScorer scorer(points, caster, mode);
  std::vector<sensing::ScoreLog> logs(photographers.size(), sensing::ScoreLog(points.size()));
  std::vector<sensing::PointScore> scores;
  const sensing::Occluders noOccluders;
  size_t captures = 0, blocked = 0, scoredPoints = 0;

  // Visit the points in index order; a point already counted by any photographer needs no
  // viewpoint of its own. Captures rotate over the photographers.
  std::vector<uint8_t> counted(points.size(), 0);
  for (const auto& point : points.points()) {
    if (counted[point.index]) continue;
    const auto& unit = *photographers[captures % photographers.size()];
    const double standoff = sensing::nominalDistance(unit.camera);
    sensing::CaptureState state;
    bool feasible = false;
    // The ideal standoff first, then closer ones when the ideal spot is inside something.
    for (const double fraction : {1.0, 0.75, 0.5}) {
      state = sensing::aimCamera(unit.camera, point.position, -point.normal, fraction * standoff);
      feasible =
          state.position.z() > scenario.groundZ + kMinimumHeight &&
          caster.distanceToSurface(state.position, kViewpointClearance) >= kViewpointClearance;
      if (feasible) break;
    }
    if (!feasible) {
      ++blocked;
      continue;
    }
    scorer.score(unit.camera, state, noOccluders, scores);
    scoredPoints += scores.size();
    logs[captures % photographers.size()].record(scores);
    for (const auto& s : scores)
      if (s.counted) counted[s.index] = 1;
    ++captures;
  }
  const auto scored = Clock::now();

  // No links are simulated yet: every log reaches the ground station at the end.
  sensing::GroundStationTally tally(points.size(), mode);
  for (const auto& log : logs)
    tally.merge(log);

  const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
  const auto bounds = scenario.bounds();
  std::printf("scenario   %s (seed %llu): %zu triangles, extent %.0f x %.0f x %.0f m, %zu boxes\n",
              scenario.name.c_str(), static_cast<unsigned long long>(options.seed),
              scenario.triangleCount(), bounds.size().x(), bounds.size().y(), bounds.size().z(),
              scenario.boxes.size());
  std::printf("points     %zu interest points, %zu photographers, scoring mode %s\n", points.size(),
              photographers.size(), sensing::toString(mode));
  std::printf(
      "captures   %zu (one per uncovered point at %.2f m standoff), %zu points without a "
      "clear viewpoint\n",
      captures, sensing::nominalDistance(photographers.front()->camera), blocked);
  for (size_t i = 0; i < photographers.size(); ++i)
    std::printf("  %-10s detected %5zu, score %8.1f\n", photographers[i]->name.c_str(),
                logs[i].detectedCount(), logs[i].totalScore());
  std::printf("gcs tally  detected %zu / %zu, score Q = %.1f (%.1f %% of the maximum %zu)\n",
              tally.detectedCount(), points.size(), tally.totalScore(),
              points.empty() ? 0.0 : 100.0 * tally.totalScore() / points.size(), points.size());
  const double scoringSeconds = seconds(scored - loaded);
  std::printf("timing     load %.2f s; scoring %.3f s = %.0f captures/s, %.0f points/s\n",
              seconds(loaded - started), scoringSeconds,
              scoringSeconds > 0 ? captures / scoringSeconds : 0.0,
              scoringSeconds > 0 ? scoredPoints / scoringSeconds : 0.0);

  eval::SceneOverlay overlay;
  overlay.boxes = scenario.boxes;
  // Dense point sets (tens of thousands on the tall CARIC-like scenes) need smaller markers to
  // leave the structure visible.
  const double markerRadius = points.size() > 5000 ? 1.3 : 2.2;
  for (const auto& point : points.points())
    overlay.points.push_back(
        {point.position, eval::scoreColor(tally.value(point.index)), markerRadius});
  const auto camera = eval::ViewCamera::overview(bounds, options.width, options.height);
  std::filesystem::create_directories(options.out);
  const auto picture = std::filesystem::path(options.out) / "demo.png";
  eval::writePng(eval::renderScene(caster, camera, overlay), picture);
  std::printf("picture    %s\n", picture.string().c_str());
}

}  // namespace

void addDemoCommand(CLI::App& root) {
  auto options = std::make_shared<DemoOptions>();
  auto* demo =
      root.add_subcommand("demo", "Score ideal camera captures on a scenario and print a summary");
  demo->add_option("--scenario", options->scenario, "generator name, scenario.ini or CARIC folder")
      ->check(nonEmptyPath())
      ->capture_default_str();
  demo->add_option("--seed", options->seed, "generator seed")
      ->check(seedNumber())
      ->capture_default_str();
  demo->add_option("--mode", options->mode, "scoring mode: caric or strict")->capture_default_str();
  demo->add_option("--out", options->out, "folder for the picture")
      ->check(nonEmptyPath())
      ->capture_default_str();
  demo->add_option("--width", options->width, "picture width (px)")
      ->check(CLI::Range(64, 8192))
      ->capture_default_str();
  demo->add_option("--height", options->height, "picture height (px)")
      ->check(CLI::Range(64, 8192))
      ->capture_default_str();
  demo->callback([options] { runDemo(*options); });
}

}  // namespace coinspect::app
