// The evaluator on hand-written rawlogs: when the ground station merges, dead units in both
// scoring modes, the per-unit figures and damaged files.
#include "coinspect/eval/evaluate_run.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "synthetic_run.h"

namespace coinspect::eval {
namespace {

using test::SyntheticRun;
using test::wallScenario;

RunEvaluation evaluate(const std::filesystem::path& path, const world::Scenario& scenario,
                       sensing::ScoringMode mode, const ProgressCallback& progress = {}) {
  record::RawlogReader reader(path);
  EvaluationParams params;
  params.scoring = mode;
  params.physicsStep = test::kStep;
  params.source = path.string();
  return evaluateRun(reader, scenario, params, progress);
}

// A capture taken at a topology tick comes after that tick's merge: when the link drops at the
// next topology tick, the ground station never gets it. One tick earlier, it does.
TEST(EvaluateRun, CaptureAtATopologyTickMissesAMergeThatALinkDropThenPrevents) {
  const auto dir = coinspect::testing::scratchDir("eval_merge_timing");
  const auto scenario = wallScenario();
  for (const long long captureTick : {15LL, 16LL}) {
    const auto path = dir / ("capture-" + std::to_string(captureTick) + ".rawlog");
    {
      SyntheticRun run(path, scenario, sensing::ScoringMode::Caric);
      run.link(0, "gcs", "a", true);
      run.capture(captureTick, "a", 5.0);
      run.link(24, "gcs", "a", false);  // set before the merge of tick 24
      run.end(40);
    }
    const auto result = evaluate(path, scenario, sensing::ScoringMode::Caric);
    EXPECT_TRUE(result.read.clean) << result.read.message;
    EXPECT_TRUE(result.missionEnded);
    ASSERT_EQ(result.units.size(), 3u);
    const auto& a = result.units[1];
    EXPECT_EQ(a.captures, 1u);
    EXPECT_EQ(a.detected, 45u);
    EXPECT_DOUBLE_EQ(a.ownScore, 45.0);
    EXPECT_DOUBLE_EQ(a.lineOfSightTime, 24 * test::kStep);
    if (captureTick == 15) {  // merged at tick 16
      EXPECT_EQ(result.detected, 45u);
      EXPECT_DOUBLE_EQ(result.score, 45.0);
      ASSERT_EQ(result.coverage.size(), 1u);
      EXPECT_DOUBLE_EQ(result.coverage[0].time, 16 * test::kStep);
      EXPECT_EQ(a.holdsGcsValue, 45u);
    } else {  // the merge of tick 16 was before it, the one of tick 24 after the drop
      EXPECT_EQ(result.detected, 0u);
      EXPECT_TRUE(result.coverage.empty());
      EXPECT_EQ(a.holdsGcsValue, 0u);
    }
    EXPECT_EQ(a.onlyDetector, 45u);
    EXPECT_EQ(a.quality.samples(), 45u);
    EXPECT_EQ(a.quality.qBlur[9], 45u);
    EXPECT_EQ(a.quality.qRes[9], 45u);
    EXPECT_EQ(result.quality.samples(), 45u);
    EXPECT_EQ(result.capturesCompared, 1u);
    EXPECT_EQ(result.pointMismatches, 0u);
    // No tally record was written: the recorded tally is empty.
    EXPECT_EQ(result.tallyRecords, 0u);
    EXPECT_EQ(result.equal(), captureTick == 16);
    EXPECT_EQ(result.valueMismatches, captureTick == 15 ? 45u : 0u);
  }
}

// The recorded tally, written after the merge that improved it, agrees with the re-scored one.
TEST(EvaluateRun, RecordedTallyWrittenAfterTheMergeIsEqual) {
  const auto dir = coinspect::testing::scratchDir("eval_recorded_tally");
  const auto scenario = wallScenario();
  const auto path = dir / "run.rawlog";
  {
    SyntheticRun run(path, scenario, sensing::ScoringMode::Caric);
    run.link(0, "gcs", "b", true);
    run.capture(3, "b", 5.0);
    std::vector<record::TallyChangeRecord> changes;
    double total = 0.0;
    for (const auto& s : run.lastScores()) {
      if (!s.counted) continue;
      changes.push_back({s.index, static_cast<float>(s.score)});
      total += static_cast<float>(s.score);
    }
    run.pose(8, "b");  // ground truth of tick 8 comes before its merge
    run.tally(8, changes, changes.size(), total);
    run.end(12);
  }
  const auto result = evaluate(path, scenario, sensing::ScoringMode::Caric);
  EXPECT_EQ(result.tallyRecords, 1u);
  EXPECT_EQ(result.tallyRecordMismatches, 0u);
  EXPECT_EQ(result.recordedDetected, 45u);
  EXPECT_TRUE(result.equal());
  ASSERT_EQ(result.coverage.size(), 1u);
  EXPECT_DOUBLE_EQ(result.coverage[0].time, 8 * test::kStep);
}

// A unit that dies stays linked: in caric mode its log (captures before and after the death) is
// still merged; in strict mode its camera is off and the station skips it. A ground station's
// death stops every merge.
TEST(EvaluateRun, DeadUnitsFollowTheScoringMode) {
  const auto dir = coinspect::testing::scratchDir("eval_dead_units");
  const auto scenario = wallScenario();
  for (const auto mode : {sensing::ScoringMode::Caric, sensing::ScoringMode::Strict}) {
    const auto path = dir / (std::string(sensing::toString(mode)) + ".rawlog");
    {
      SyntheticRun run(path, scenario, mode);
      run.link(0, "gcs", "a", true);
      run.link(0, "gcs", "b", true);
      run.capture(17, "a", 3.0);  // 7 m: every point scores 1; before the death
      run.death(20, "a");
      run.capture(30, "a", 5.0);   // after the death: caric only
      run.capture(30, "b", -2.0);  // alive, 12 m away: lower scores, merged at 32
      run.end(48);
    }
    const auto result = evaluate(path, scenario, mode);
    const auto& a = result.units[1];
    const auto& b = result.units[2];
    EXPECT_FALSE(a.alive);
    EXPECT_DOUBLE_EQ(a.deathTime, 20 * test::kStep);
    EXPECT_TRUE(b.alive);
    EXPECT_GT(b.detected, 0u);
    EXPECT_LT(b.ownScore, 45.0);
    if (mode == sensing::ScoringMode::Caric) {
      EXPECT_EQ(a.captures, 2u);
      EXPECT_EQ(a.capturesIgnored, 0u);
      EXPECT_EQ(result.detected, 45u);
      EXPECT_DOUBLE_EQ(result.score, a.ownScore);
      EXPECT_EQ(a.holdsGcsValue, 45u);
      EXPECT_EQ(b.holdsGcsValue, 0u);
    } else {
      EXPECT_EQ(a.captures, 1u);
      EXPECT_EQ(a.capturesIgnored, 1u);
      EXPECT_EQ(result.detected, b.detected);
      EXPECT_DOUBLE_EQ(result.score, b.ownScore);
      EXPECT_EQ(a.holdsGcsValue, 0u);
      EXPECT_EQ(b.holdsGcsValue, b.detected);
    }
  }
  // The station dies at tick 10: the capture merged nowhere.
  const auto path = dir / "station.rawlog";
  {
    SyntheticRun run(path, scenario, sensing::ScoringMode::Caric);
    run.link(0, "gcs", "a", true);
    run.capture(5, "a", 5.0);
    run.death(8, "gcs");
    run.end(40);
  }
  const auto result = evaluate(path, scenario, sensing::ScoringMode::Caric);
  EXPECT_EQ(result.units[1].detected, 45u);
  EXPECT_EQ(result.detected, 0u);
}

// A truncated rawlog is evaluated up to the damage, and the result carries the reader's message.
TEST(EvaluateRun, TruncatedRawlogIsEvaluatedUpToTheDamage) {
  const auto dir = coinspect::testing::scratchDir("eval_truncated");
  const auto scenario = wallScenario();
  const auto path = dir / "run.rawlog";
  {
    SyntheticRun run(path, scenario, sensing::ScoringMode::Caric);
    run.link(0, "gcs", "a", true);
    for (long long tick = 1; tick < 2000; tick += 41)
      run.capture(tick, "a", 4.0 + 0.002 * static_cast<double>(tick));
    run.end(2000);
  }
  const auto whole = evaluate(path, scenario, sensing::ScoringMode::Caric);
  ASSERT_TRUE(whole.read.clean);
  const auto bytes = coinspect::testing::readFile(path);
  const auto cut = dir / "cut.rawlog";
  coinspect::testing::writeFile(cut, bytes.substr(0, bytes.size() / 2));
  std::vector<double> progressTimes;
  const auto result =
      evaluate(cut, scenario, sensing::ScoringMode::Caric,
               [&](const EvaluationProgress& p) { progressTimes.push_back(p.time); });
  EXPECT_FALSE(result.read.clean);
  EXPECT_GT(result.read.objects, 2u);
  EXPECT_LT(result.read.objects, whole.read.objects);
  EXPECT_GT(result.read.offset, 0u);
  EXPECT_MENTIONS(result.read.message, std::to_string(result.read.objects) + " objects read");
  EXPECT_MENTIONS(result.read.message, "byte offset " + std::to_string(result.read.offset));
  EXPECT_FALSE(result.missionEnded);
  EXPECT_LT(result.units[1].captures, whole.units[1].captures);
  EXPECT_GT(result.units[1].captures, 0u);
  EXPECT_LT(result.endTime, whole.endTime);
  ASSERT_FALSE(progressTimes.empty());
  EXPECT_DOUBLE_EQ(progressTimes.back(), result.endTime);
}

TEST(EvaluateRun, UnitMissingFromTheFleetIsAnInputError) {
  const auto dir = coinspect::testing::scratchDir("eval_unknown_unit");
  const auto scenario = wallScenario();
  const auto path = dir / "run.rawlog";
  {
    SyntheticRun run(path, scenario, sensing::ScoringMode::Caric);
    run.link(0, "gcs", "zeppelin", true);
    run.end(8);
  }
  const auto message =
      coinspect::testing::messageOf([&] { evaluate(path, scenario, sensing::ScoringMode::Caric); });
  EXPECT_MENTIONS(message, path.string());
  EXPECT_MENTIONS(message, "zeppelin");
  EXPECT_MENTIONS(message, "object 2");
}

TEST(QualityHistogram, BinsCoverZeroToOneInclusive) {
  QualityHistogram h;
  h.add(0.0, 1.0);
  h.add(0.0999, 0.95);
  h.add(0.1, 0.5);
  EXPECT_EQ(h.samples(), 3u);
  EXPECT_EQ(h.qBlur[0], 2u);
  EXPECT_EQ(h.qBlur[1], 1u);
  EXPECT_EQ(h.qRes[9], 2u);
  EXPECT_EQ(h.qRes[5], 1u);
}

}  // namespace
}  // namespace coinspect::eval
