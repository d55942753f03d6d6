// THE test of the evaluator: fly a mission while recording it, then evaluate the rawlog; the
// re-scored ground-station tally must equal the live mission's, value by value, in both scoring
// modes, on two generated scenarios (one run with a failing UAV and a blackout).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "coinspect/core/config.h"
#include "coinspect/eval/evaluate_run.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"
#include "coinspect/testing/paths.h"

namespace coinspect::eval {
namespace {

struct LiveRun {
  std::vector<float> values;
  double score = 0.0;
  std::vector<bool> alive;
};

// Flies config/<config> with the overrides, recording to <dir>/run.rawlog.
LiveRun flyAndRecord(const std::string& config, const std::vector<std::string>& overrides,
                     const std::filesystem::path& rawlog, world::Scenario& scenario,
                     sim::MissionConfig& missionConfig) {
  auto ini = Config::fromFile(coinspect::testing::sourceDir() / "config" / config);
  for (const auto& assignment : overrides)
    ini.applyOverride(assignment);
  agent::StrategyRegistry registry;
  strategies::registerBuiltinStrategies(registry);
  sim::Mission mission(ini, registry);
  mission.startRecording(rawlog,
                         record::RunHeader{"test", mission.config().seed, "0", ini.toText()});
  mission.run();
  EXPECT_FALSE(mission.recordingError().has_value());
  LiveRun live;
  live.values = mission.gcsValues();
  live.score = mission.gcsScore();
  for (size_t i = 0; i < mission.scenario().fleet.size(); ++i)
    live.alive.push_back(mission.unitAlive(i));
  scenario = mission.scenario();
  missionConfig = mission.config();
  return live;
}

void expectEvalEqualsLive(const std::string& name, const std::string& config,
                          const std::vector<std::string>& overrides) {
  const auto dir = coinspect::testing::scratchDir("eval_equals_live_" + name);
  const auto rawlog = dir / "run.rawlog";
  world::Scenario scenario;
  sim::MissionConfig missionConfig;
  const LiveRun live = flyAndRecord(config, overrides, rawlog, scenario, missionConfig);
  ASSERT_GT(live.score, 0.0) << "the mission scored nothing: the test would prove little";

  record::RawlogReader reader(rawlog);
  EvaluationParams params;
  params.scoring = missionConfig.scoring;
  params.physicsStep = missionConfig.physicsStep;
  params.source = rawlog.string();
  const RunEvaluation result = evaluateRun(reader, scenario, params);

  EXPECT_TRUE(result.read.clean) << result.read.message;
  EXPECT_TRUE(result.missionEnded);
  ASSERT_EQ(result.values.size(), live.values.size());
  size_t differing = 0;
  for (size_t i = 0; i < live.values.size(); ++i)
    differing += result.values[i] == live.values[i] ? 0 : 1;
  EXPECT_EQ(differing, 0u) << "points whose re-scored value differs from the live one";
  EXPECT_EQ(result.score, live.score);  // exactly: same values summed in the same order
  EXPECT_TRUE(result.equal()) << result.valueMismatches << " values, "
                              << result.tallyRecordMismatches << " tally records differ";
  EXPECT_GT(result.tallyRecords, 0u);
  EXPECT_EQ(result.pointMismatches, 0u);
  EXPECT_GT(result.capturesCompared, 0u);
  EXPECT_EQ(result.capturesNotRescored, 0u);
  ASSERT_FALSE(result.coverage.empty());
  EXPECT_EQ(result.coverage.back().score, live.score);
  for (size_t i = 0; i < live.alive.size(); ++i)
    EXPECT_EQ(result.units[i].alive, live.alive[i]) << result.units[i].name;
}

TEST(EvalEqualsLive, SleiBCaricWithAFailureAndABlackout) {
  expectEvalEqualsLive("slei_caric", "quick.ini",
                       {"mission.budget=30", "mission.scoring=caric", "fault.1.unit=inspector2",
                        "fault.1.at=12", "blackout.1.from=5", "blackout.1.to=8"});
}

TEST(EvalEqualsLive, SleiBStrictWithAFailure) {
  expectEvalEqualsLive(
      "slei_strict", "quick.ini",
      {"mission.budget=30", "mission.scoring=strict", "fault.1.unit=inspector2", "fault.1.at=12"});
}

TEST(EvalEqualsLive, HangarCaric) {
  expectEvalEqualsLive("hangar_caric", "hangar.ini",
                       {"mission.budget=40", "mission.scoring=caric"});
}

TEST(EvalEqualsLive, HangarStrict) {
  expectEvalEqualsLive("hangar_strict", "hangar.ini",
                       {"mission.budget=40", "mission.scoring=strict"});
}

}  // namespace
}  // namespace coinspect::eval
