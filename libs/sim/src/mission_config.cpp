#include "coinspect/sim/mission_config.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"
#include "coinspect/world/generators.h"
#include "coinspect/world/scenario_source.h"

namespace coinspect::sim {

namespace {

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

double positive(const Config& config, const std::string& section, const std::string& key,
                double value) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw InputError(config.source(), "[" + section + "] " + key, "must be a positive number");
  return value;
}

uint64_t nonNegative(const Config& config, const std::string& section, const std::string& key,
                     long long value) {
  if (value < 0)
    throw InputError(config.source(), "[" + section + "] " + key, "must not be negative");
  return static_cast<uint64_t>(value);
}

RunMode parseRunMode(const Config& config, const std::string& text) {
  if (text == "lockstep") return RunMode::Lockstep;
  if (text == "latency") return RunMode::Latency;
  if (text == "realtime") return RunMode::Realtime;
  throw InputError(config.source(), "[mission] run_mode",
                   "'" + text + "' is not a run mode (lockstep, latency or realtime)");
}

Objective parseObjective(const Config& config, const std::string& text) {
  if (text == "points") return Objective::Points;
  if (text == "features") return Objective::Features;
  throw InputError(config.source(), "[mission] objective",
                   "'" + text + "' is not an objective (points or features)");
}

// `[mission] fleet = <stations> <explorers> <inspectors>`: a generated slei-* scene's fleet size.
world::SleiFleet parseFleet(const Config& config, const std::string& text) {
  const std::string key = "[mission] fleet";
  const auto tokens = splitTokens(text);
  std::vector<int> counts;
  for (const auto& token : tokens) {
    const auto value = parseInteger(token);
    if (!value || *value < 0 || *value > 100000)
      throw InputError(config.source(), key, "'" + token + "' is not a count");
    counts.push_back(static_cast<int>(*value));
  }
  if (counts.size() != 3)
    throw InputError(config.source(), key,
                     "'" + text + "': give three counts, stations explorers inspectors");
  const world::SleiFleet fleet{counts[0], counts[1], counts[2]};
  const std::string problem = world::sleiFleetProblem(fleet);
  if (!problem.empty()) throw InputError(config.source(), key, problem);
  return fleet;
}

double angleDegrees(const Config& config, const std::string& key, double fallbackRadians) {
  const double degrees = config.getDouble("features", key, fallbackRadians * 180.0 / M_PI);
  if (!(degrees > 0.0 && degrees <= 180.0))
    throw InputError(config.source(), "[features] " + key, "must be in (0, 180] degrees");
  return degrees * M_PI / 180.0;
}

EnergyConfig readEnergy(const Config& config) {
  const std::string e = "energy";
  EnergyConfig out;
  out.capacity = positive(config, e, "capacity", config.getDouble(e, "capacity"));
  out.chargeTime = positive(config, e, "charge_time", config.getDouble(e, "charge_time"));
  out.chargeRange =
      positive(config, e, "charge_range", config.getDouble(e, "charge_range", out.chargeRange));
  out.startLevel = config.getDouble(e, "start_level", out.startLevel);
  if (!(out.startLevel > 0.0 && out.startLevel <= 1.0))
    throw InputError(config.source(), "[energy] start_level", "must be in (0, 1]");
  return out;
}

FeatureConfig readFeatures(const Config& config) {
  const std::string f = "features";
  FeatureConfig out;
  out.sensor.range =
      positive(config, f, "detect_range", config.getDouble(f, "detect_range", out.sensor.range));
  // Checked against the fleet's explorers when the mission is built (mission_features.cpp).
  for (const auto& token : splitTokens(config.getString(f, "explorer_ranges", ""))) {
    const auto value = parseFiniteDouble(token);
    if (!value || !(*value > 0.0))
      throw InputError(config.source(), "[features] explorer_ranges",
                       "'" + token + "' is not a positive range in m");
    out.explorerRanges.push_back(*value);
  }
  out.sensor.halfYaw = angleDegrees(config, "detect_half_yaw", out.sensor.halfYaw);
  out.sensor.halfElevation =
      angleDegrees(config, "detect_half_elevation", out.sensor.halfElevation);
  out.sensor.lineOfSight = config.getBool(f, "detect_line_of_sight", out.sensor.lineOfSight);
  out.inspectTime = config.getDouble(f, "inspect_time", out.inspectTime);
  if (!(out.inspectTime >= 0.0) || !std::isfinite(out.inspectTime))
    throw InputError(config.source(), "[features] inspect_time", "must be a finite time >= 0 s");
  out.inspectScore = config.getDouble(f, "inspect_score", out.inspectScore);
  if (!(out.inspectScore > 0.0 && out.inspectScore <= 1.0))
    throw InputError(config.source(), "[features] inspect_score", "must be in (0, 1]");
  out.meetingGap = config.getDouble(f, "meeting_gap", out.meetingGap);
  if (!(out.meetingGap >= 0.0) || !std::isfinite(out.meetingGap))
    throw InputError(config.source(), "[features] meeting_gap", "must be a finite time >= 0 s");
  out.endWhenCollected = config.getBool(f, "end_when_collected", out.endWhenCollected);
  out.punctualityTolerance = config.getDouble(f, "punctuality_tolerance", out.punctualityTolerance);
  if (!(out.punctualityTolerance >= 0.0) || !std::isfinite(out.punctualityTolerance))
    throw InputError(config.source(), "[features] punctuality_tolerance",
                     "must be a finite time >= 0 s");
  // Box names, separated by spaces; checked against the scenario's boxes when the mission is
  // built (mission.cpp).
  std::istringstream names(config.getString(f, "priority_boxes", ""));
  for (std::string name; names >> name;)
    out.priorityBoxes.push_back(name);
  return out;
}

}  // namespace

std::string toString(RunMode mode) {
  switch (mode) {
    case RunMode::Lockstep:
      return "lockstep";
    case RunMode::Latency:
      return "latency";
    case RunMode::Realtime:
      return "realtime";
  }
  return "lockstep";
}

std::filesystem::path defaultShareDir() {
  return COINSPECT_SHARE_DIR;
}

MissionConfig MissionConfig::read(const Config& config, std::optional<uint64_t> seedOverride) {
  MissionConfig out;
  out.source = config.source();
  const std::string m = "mission";
  const std::string scenario = config.getString(m, "scenario", "");
  // A generator's name stays a name (world::loadScenarioSource); anything else is a path, taken
  // from the INI's folder when relative.
  out.scenario = scenario.empty() || world::isGeneratorName(scenario)
                     ? scenario
                     : (config.folder() / scenario).string();
  out.scenarioSeed = nonNegative(config, m, "scenario_seed", config.getInt(m, "scenario_seed", 1));
  if (config.has(m, "fleet")) out.fleet = parseFleet(config, config.getString(m, "fleet"));
  out.seed =
      seedOverride ? *seedOverride : nonNegative(config, m, "seed", config.getInt(m, "seed", 1));
  if (config.has(m, "budget"))
    out.budget = positive(config, m, "budget", config.getDouble(m, "budget"));
  out.scoring = sensing::parseScoringMode(config.getString(m, "scoring", "caric"),
                                          config.source() + ": [mission] scoring");
  out.links = config.getString(m, "links", out.links);
  out.linkRange =
      positive(config, m, "link_range", config.getDouble(m, "link_range", out.linkRange));
  out.startHeight = config.getDouble(m, "start_height", out.startHeight);
  out.startSpeed = config.getDouble(m, "start_speed", out.startSpeed);
  if (out.startHeight < 0.0 || out.startSpeed < 0.0)
    throw InputError(config.source(), "[mission] start_height/start_speed", "must not be negative");
  out.physicsStep =
      positive(config, m, "physics_step", config.getDouble(m, "physics_step", out.physicsStep));
  if (out.physicsStep > 0.01)
    throw InputError(config.source(), "[mission] physics_step", "must be at most 0.01 s");
  out.startTimeout =
      positive(config, m, "start_timeout", config.getDouble(m, "start_timeout", out.startTimeout));
  out.gcsSpeed = config.getDouble(m, "gcs_speed", out.gcsSpeed);
  if (!(out.gcsSpeed >= 0.0) || !std::isfinite(out.gcsSpeed))
    throw InputError(config.source(), "[mission] gcs_speed", "must be a finite speed >= 0 m/s");
  out.airframes = config.has(m, "airframes") ? config.getPath(m, "airframes")
                                             : defaultShareDir() / "airframes.ini";
  out.explorerAirframe = config.getString(m, "explorer_airframe", out.explorerAirframe);
  out.photographerAirframe = config.getString(m, "photographer_airframe", out.photographerAirframe);
  out.lidars =
      config.has(m, "lidars") ? config.getPath(m, "lidars") : defaultShareDir() / "lidars.ini";
  out.explorerLidar = config.getString(m, "explorer_lidar", out.explorerLidar);
  out.runMode = parseRunMode(config, config.getString(m, "run_mode", "lockstep"));
  // A factor that would be ignored is an error rather than a silent no-op.
  if (config.has(m, "realtime_factor")) {
    if (out.runMode != RunMode::Realtime)
      throw InputError(config.source(), "[mission] realtime_factor",
                       "only allowed with run_mode = realtime");
    out.realtimeFactor =
        positive(config, m, "realtime_factor", config.getDouble(m, "realtime_factor"));
  }
  out.objective = parseObjective(config, config.getString(m, "objective", "points"));
  if (out.objective == Objective::Features)
    out.features = readFeatures(config);
  else if (config.hasSection("features"))
    throw InputError(config.source(), "[features]",
                     "only allowed with [mission] objective = features");
  if (config.hasSection("energy")) out.energy = readEnergy(config);
  out.strategy = config.getString("strategy", "name");
  out.record = RecordConfig::read(config, out.physicsStep);

  for (const auto& section : config.sections()) {
    if (startsWith(section, "fault.")) {
      FaultSpec fault;
      fault.unit = config.getString(section, "unit");
      fault.at = config.getDouble(section, "at");
      if (fault.at < 0.0)
        throw InputError(config.source(), "[" + section + "] at", "must not be negative");
      out.faults.push_back(fault);
    } else if (startsWith(section, "blackout.")) {
      BlackoutSpec blackout;
      blackout.from = config.getDouble(section, "from");
      blackout.to = config.getDouble(section, "to");
      if (!(blackout.to > blackout.from))
        throw InputError(config.source(), "[" + section + "] to", "must be after 'from'");
      blackout.units = splitTokens(config.getString(section, "units", ""), " \t,");
      out.blackouts.push_back(blackout);
    }
  }
  return out;
}

world::Scenario loadMissionScenario(const MissionConfig& config) {
  if (config.scenario.empty())
    throw InputError(config.source, "[mission] scenario", "missing: name a generator or a path");
  if (config.fleet) {
    const bool generator = world::isGeneratorName(config.scenario);
    if (!generator && std::filesystem::exists(config.scenario))
      throw InputError(config.source, "[mission] fleet",
                       "only for a generated slei-* scenario, not the files of " + config.scenario);
    for (const auto& g : world::scenarioGenerators())
      if (generator && g.name == config.scenario && g.family != "slei")
        throw InputError(config.source, "[mission] fleet",
                         "only for a generated slei-* scenario, not " + config.scenario);
  }
  return world::loadScenarioSource(config.scenario, config.scenarioSeed, config.fleet,
                                   config.source, "[mission] scenario");
}

}  // namespace coinspect::sim
