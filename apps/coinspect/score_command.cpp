// `coinspect score`: scores camera captures read as JSON lines against a scenario, printing every
// term of the reference scoring for each candidate point (a debugging and verification tool).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "coinspect/core/error.h"
#include "coinspect/sensing/camera_model.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sensing/score_log.h"
#include "coinspect/world/ray_caster.h"
#include "coinspect/world/scenario_source.h"
#include "commands.h"
#include "option_checks.h"

namespace coinspect::app {
namespace {

using nlohmann::json;
using sensing::Vec3;

constexpr double kDeg = M_PI / 180.0;

struct ScoreOptions {
  std::string scenario;
  uint64_t seed = 1;
  std::string unit;
  std::string mode = "caric";
  std::string input = "-";
  bool all = false;
};

// One parsed line.
struct Capture {
  size_t line = 0;
  std::string unit;
  double time = std::nan("");
  sensing::CaptureState state;
  sensing::Occluders occluders;
};

const char* const kFieldHelp =
    "Each input line is one JSON object (blank lines and lines starting with # are skipped):\n"
    "  unit              string   unit whose camera is used (default: --unit, else the first\n"
    "                             unit that is not the ground station)\n"
    "  t                 number   time label, only printed\n"
    "  position          [x,y,z]  body position, world frame, m\n"
    "  attitude_ypr_deg  [y,p,r]  body yaw, pitch, roll (Z-Y-X), degrees; default 0\n"
    "  velocity          [x,y,z]  body linear velocity, WORLD frame, m/s; default 0\n"
    "  angular_velocity  [x,y,z]  body angular velocity, BODY frame, rad/s; default 0\n"
    "  gimbal_deg        [yaw,pitch]          gimbal angles, degrees (pitch > 0 looks down)\n"
    "  gimbal_rate_deg   [yaw_rate,pitch_rate] gimbal rates, deg/s\n"
    "  aim_at_point      index    instead of position/attitude/gimbal: a level camera looking\n"
    "                             at that interest point against its normal\n"
    "  standoff          number   distance for aim_at_point, m; default 5\n"
    "  occluders         [{\"center\":[x,y,z],\"radius\":r}, ...]  other UAVs as spheres\n";

class LineParser {
 public:
  LineParser(const std::string& input, size_t line) : input_(input), line_(line) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(input_, "line " + std::to_string(line_), what);
  }

  double number(const json& value, const std::string& key) const {
    if (!value.is_number()) fail("'" + key + "' must be a number");
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail("'" + key + "' must be finite");
    return v;
  }

  std::vector<double> numbers(const json& object, const std::string& key, size_t count) const {
    const json& value = object.at(key);
    if (!value.is_array() || value.size() != count) {
      fail("'" + key + "' must be an array of " + std::to_string(count) + " numbers");
    }
    std::vector<double> out;
    for (const json& item : value)
      out.push_back(number(item, key));
    return out;
  }

  Vec3 vec3(const json& object, const std::string& key) const {
    const std::vector<double> v = numbers(object, key, 3);
    return Vec3(v[0], v[1], v[2]);
  }

 private:
  const std::string& input_;
  size_t line_;
};

Capture parseCapture(const std::string& text, const std::string& input, size_t line,
                     const world::Scenario& scenario, const world::UnitSpec*& unitOut,
                     const std::map<std::string, const world::UnitSpec*>& units,
                     const world::UnitSpec* defaultUnit) {
  const LineParser p(input, line);
  json object;
  try {
    object = json::parse(text);
  } catch (const json::parse_error& error) {
    p.fail(std::string("malformed JSON: ") + error.what());
  }
  if (!object.is_object()) p.fail("expected a JSON object");
  static const char* const kKnown[] = {"unit",         "t",
                                       "position",     "attitude_ypr_deg",
                                       "velocity",     "angular_velocity",
                                       "gimbal_deg",   "gimbal_rate_deg",
                                       "aim_at_point", "standoff",
                                       "occluders"};
  for (const auto& item : object.items()) {
    bool known = false;
    for (const char* key : kKnown)
      known = known || item.key() == key;
    if (!known) p.fail("unknown field '" + item.key() + "'");
  }

  Capture capture;
  capture.line = line;
  const world::UnitSpec* unit = defaultUnit;
  if (object.contains("unit")) {
    if (!object["unit"].is_string()) p.fail("'unit' must be a string");
    const auto found = units.find(object["unit"].get<std::string>());
    if (found == units.end()) p.fail("unknown unit '" + object["unit"].get<std::string>() + "'");
    unit = found->second;
  }
  if (unit == nullptr) p.fail("no unit with a camera in the scenario");
  if (unit->role == world::UnitRole::GroundStation) {
    p.fail("unit '" + unit->name + "' is the ground station, which takes no pictures");
  }
  unitOut = unit;
  capture.unit = unit->name;
  if (object.contains("t")) capture.time = p.number(object["t"], "t");

  sensing::CaptureState& state = capture.state;
  if (object.contains("aim_at_point")) {
    for (const char* key : {"position", "attitude_ypr_deg", "gimbal_deg"}) {
      if (object.contains(key)) p.fail(std::string("'aim_at_point' excludes '") + key + "'");
    }
    const json& index = object["aim_at_point"];
    if (!index.is_number_unsigned() || index.get<uint64_t>() >= scenario.interestPoints.size()) {
      p.fail("'aim_at_point' must be an interest point index below " +
             std::to_string(scenario.interestPoints.size()));
    }
    const double standoff =
        object.contains("standoff") ? p.number(object["standoff"], "standoff") : 5.0;
    if (!(standoff > 0.0)) p.fail("'standoff' must be positive");
    const world::InterestPoint& target = scenario.interestPoints[index.get<uint64_t>()];
    state = sensing::aimCamera(unit->camera, target.position, -target.normal, standoff);
  } else {
    if (object.contains("standoff")) p.fail("'standoff' needs 'aim_at_point'");
    if (!object.contains("position")) p.fail("missing 'position' (or 'aim_at_point')");
    state.position = p.vec3(object, "position");
    if (object.contains("attitude_ypr_deg")) {
      const std::vector<double> ypr = p.numbers(object, "attitude_ypr_deg", 3);
      state.yaw = ypr[0] * kDeg;
      state.pitch = ypr[1] * kDeg;
      state.roll = ypr[2] * kDeg;
    }
    if (object.contains("gimbal_deg")) {
      const std::vector<double> g = p.numbers(object, "gimbal_deg", 2);
      state.gimbalYaw = g[0] * kDeg;
      state.gimbalPitch = g[1] * kDeg;
    }
  }
  if (object.contains("velocity")) state.linearVelocity = p.vec3(object, "velocity");
  if (object.contains("angular_velocity")) {
    state.angularVelocity = p.vec3(object, "angular_velocity");
  }
  if (object.contains("gimbal_rate_deg")) {
    const std::vector<double> r = p.numbers(object, "gimbal_rate_deg", 2);
    state.gimbalYawRate = r[0] * kDeg;
    state.gimbalPitchRate = r[1] * kDeg;
  }
  if (object.contains("occluders")) {
    const json& list = object["occluders"];
    if (!list.is_array()) p.fail("'occluders' must be an array");
    for (const json& item : list) {
      if (!item.is_object() || !item.contains("center") || !item.contains("radius")) {
        p.fail("each occluder needs 'center' and 'radius'");
      }
      sensing::SphereOccluder sphere;
      sphere.center = p.vec3(item, "center");
      sphere.radius = p.number(item["radius"], "radius");
      if (!(sphere.radius > 0.0)) p.fail("occluder 'radius' must be positive");
      capture.occluders.spheres.push_back(sphere);
    }
  }
  return capture;
}

void printCapture(size_t number, const Capture& capture, const world::CameraSpec& spec,
                  const std::vector<sensing::PointScore>& scores, bool all) {
  const sensing::CameraPose pose = sensing::cameraPose(spec, capture.state);
  size_t seen = 0, counted = 0;
  double sum = 0.0;
  for (const sensing::PointScore& ps : scores) {
    seen += ps.seen ? 1 : 0;
    if (ps.counted) {
      ++counted;
      sum += ps.score;
    }
  }
  std::printf("capture %zu (line %zu) unit %s", number, capture.line, capture.unit.c_str());
  if (!std::isnan(capture.time)) std::printf(" t %.3f", capture.time);
  const Vec3 axis = pose.opticalAxis();
  std::printf(": camera (%.3f, %.3f, %.3f) axis (%.3f, %.3f, %.3f)\n", pose.position.x(),
              pose.position.y(), pose.position.z(), axis.x(), axis.y(), axis.z());
  std::printf("  %zu candidates within %.3f m, %zu seen, %zu counted, sum %.4f\n", scores.size(),
              sensing::candidateRadius(spec), seen, counted, sum);
  bool header = false;
  for (const sensing::PointScore& ps : scores) {
    if (!all && !ps.seen) continue;
    if (!header) {
      std::printf("  %7s %8s %-24s %7s %7s %7s %8s %7s %s\n", "point", "dist_m", "q_seen",
                  "blur_px", "q_blur", "mm_px", "q_res", "score", "counted");
      header = true;
    }
    std::string seenText = ps.seen ? "1" : std::string("0 ") + sensing::toString(ps.reason);
    std::printf("  %7u %8.3f %-24s %7.3f %7.4f %7.3f %8.4f %7.4f %s\n", ps.index, ps.distance,
                seenText.c_str(), ps.blurPixels, ps.qBlur, ps.mmPerPixel, ps.qRes, ps.score,
                ps.counted ? "yes" : "no");
  }
}

void runScore(const ScoreOptions& options) {
  const sensing::ScoringMode mode = sensing::parseScoringMode(options.mode, "--mode");
  const world::Scenario scenario = world::loadScenarioSource(options.scenario, options.seed);
  const world::RayCaster caster(scenario.meshes, scenario.groundZ);
  sensing::InspectionScorer scorer(scenario.interestPoints, caster, mode);

  std::map<std::string, const world::UnitSpec*> units;
  const world::UnitSpec* defaultUnit = nullptr;
  for (const world::UnitSpec& unit : scenario.fleet) {
    units[unit.name] = &unit;
    if (defaultUnit == nullptr && unit.role != world::UnitRole::GroundStation) {
      defaultUnit = &unit;
    }
  }
  if (!options.unit.empty()) {
    const auto found = units.find(options.unit);
    if (found == units.end()) {
      throw InputError("--unit", options.unit, "no such unit in " + options.scenario);
    }
    defaultUnit = found->second;
  }

  std::ifstream file;
  std::istream* in = &std::cin;
  const std::string inputName = options.input == "-" ? "<stdin>" : options.input;
  if (options.input != "-") {
    file.open(options.input);
    if (!file) throw InputError(options.input, "", "cannot open the capture file");
    in = &file;
  }

  std::printf("scenario %s: %zu interest points, mode %s\n", scenario.name.c_str(),
              scenario.interestPoints.size(), sensing::toString(mode));
  std::map<std::string, sensing::ScoreLog> logs;
  std::vector<sensing::PointScore> scores;
  std::string text;
  size_t line = 0, captures = 0;
  while (std::getline(*in, text)) {
    ++line;
    const size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    const world::UnitSpec* unit = nullptr;
    const Capture capture = parseCapture(text, inputName, line, scenario, unit, units, defaultUnit);
    scorer.score(unit->camera, capture.state, capture.occluders, scores);
    ++captures;
    printCapture(captures, capture, unit->camera, scores, options.all);
    auto log = logs.try_emplace(unit->name, scenario.interestPoints.size()).first;
    log->second.record(scores);
  }
  sensing::GroundStationTally tally(scenario.interestPoints.size(), mode);
  for (const auto& entry : logs) {
    std::printf("unit %s: %zu points detected, best-score sum %.4f\n", entry.first.c_str(),
                entry.second.detectedCount(), entry.second.totalScore());
    tally.merge(entry.second);
  }
  std::printf("total: %zu captures, %zu of %zu points detected, Q = %.4f\n", captures,
              tally.detectedCount(), tally.size(), tally.totalScore());
}

}  // namespace

void addScoreCommand(CLI::App& root) {
  auto options = std::make_shared<ScoreOptions>();
  CLI::App* command = root.add_subcommand(
      "score", "Score camera captures (JSON lines) against a scenario, term by term");
  command->footer(std::string("\n") + kFieldHelp +
                  "\nThe total merges each unit's best score per point as the ground station "
                  "would with every unit in line of sight. Formulas: doc/scoring.md.");
  command
      ->add_option("--scenario", options->scenario,
                   "CARIC folder, scenario.ini (or its folder) or generator name")
      ->check(nonEmptyPath())
      ->required();
  command->add_option("--seed", options->seed, "Generator seed (generator names only)")
      ->check(seedNumber());
  command->add_option("--unit", options->unit, "Unit whose camera scores lines without \"unit\"");
  command->add_option("--mode", options->mode, "Scoring mode: caric (reference) or strict")
      ->check(CLI::IsMember({"caric", "strict"}));
  command->add_option("--input", options->input, "Capture file, JSON lines; - for stdin")
      ->check(nonEmptyPath());
  command->add_flag("--all", options->all, "Also list candidate points that are not seen");
  command->callback([options]() { runScore(*options); });
}

}  // namespace coinspect::app
