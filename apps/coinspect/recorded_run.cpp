#include "recorded_run.h"

#include <cinttypes>
#include <cstdio>

#include "coinspect/core/error.h"
#include "coinspect/record/rawlog_reader.h"
#include "coinspect/world/scenario_source.h"

namespace coinspect::app {

namespace {

std::string hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016" PRIx64, value);
  return text;
}

}  // namespace

RecordedRun openRecordedRun(const std::filesystem::path& rawlog,
                            const std::string& scenarioSource) {
  RecordedRun run;
  run.rawlog = rawlog;
  run.header = record::RawlogReader(rawlog).header();
  // The recorded config is read as the run read it, with the recorded seed (it may have come
  // from --seed rather than the file), its relative paths from the rawlog's folder (the run
  // recorded them so: makeRunHeader).
  const auto config = Config::fromText(run.header.configIni, rawlog.string() + " (run header)",
                                       rawlog.parent_path());
  run.mission = sim::MissionConfig::read(config, run.header.seed);
  try {
    run.scenario = scenarioSource.empty()
                       ? sim::loadMissionScenario(run.mission)
                       : world::loadScenarioSource(scenarioSource, run.mission.scenarioSeed,
                                                   run.mission.fleet);
  } catch (const InputError& e) {
    if (!scenarioSource.empty()) throw;
    throw InputError(rawlog.string(), "run header [mission] scenario",
                     std::string(e.what()) + " (give the scenario with --scenario)");
  }
  const std::string hash = hex(run.scenario.contentHash());
  if (hash != run.header.scenarioHash)
    throw InputError(rawlog.string(), "run header scenario_hash",
                     "recorded with scenario " + run.header.scenarioHash + ", but " +
                         (scenarioSource.empty() ? run.mission.scenario : scenarioSource) +
                         " has content hash " + hash);
  return run;
}

}  // namespace coinspect::app
