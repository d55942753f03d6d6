// Per-UAV best-score logs and the ground station tally.
#include <gtest/gtest.h>

#include "coinspect/sensing/score_log.h"

namespace coinspect::sensing {
namespace {

PointScore counted(uint32_t index, double score) {
  PointScore ps;
  ps.index = index;
  ps.seen = true;
  ps.score = score;
  ps.counted = score >= kCountThreshold;
  return ps;
}

TEST(ScoreLog, KeepsTheMaximumPerPoint) {
  ScoreLog log(4);
  EXPECT_TRUE(log.record(1, 0.5));
  EXPECT_FALSE(log.record(1, 0.4));  // worse: ignored
  EXPECT_TRUE(log.record(1, 0.75));
  EXPECT_FALSE(log.record(1, 0.75));  // equal: not an improvement
  EXPECT_FLOAT_EQ(log.best(1), 0.75f);
  EXPECT_EQ(log.best(0), 0.0f);
  EXPECT_EQ(log.detectedCount(), 1u);
}

TEST(ScoreLog, ThresholdIsInclusive) {
  ScoreLog log(3);
  EXPECT_TRUE(log.record(0, 0.2));
  EXPECT_FALSE(log.record(1, 0.19999));
  EXPECT_EQ(log.detectedCount(), 1u);
  EXPECT_FLOAT_EQ(log.best(0), 0.2f);
  EXPECT_EQ(log.best(1), 0.0f);
}

TEST(ScoreLog, RecordsOnlyCountedEntriesOfACapture) {
  ScoreLog log(5);
  std::vector<PointScore> capture{counted(0, 0.9), counted(2, 0.1), counted(4, 0.3)};
  capture.push_back(PointScore{});  // index 0, not seen
  EXPECT_EQ(log.record(capture), 2u);
  EXPECT_FLOAT_EQ(log.best(0), 0.9f);
  EXPECT_EQ(log.best(2), 0.0f);
  EXPECT_FLOAT_EQ(log.best(4), 0.3f);
  // 0.9 and 0.3 stored as floats, summed in double.
  EXPECT_DOUBLE_EQ(log.totalScore(), double(0.9f) + double(0.3f));
}

TEST(ScoreLog, StoresSinglePrecisionLikeTheReference) {
  ScoreLog log(1);
  log.record(0, 0.723456789012345);
  EXPECT_EQ(log.best(0), 0.723456789012345f);
}

TEST(GroundStationTally, MergesMaxPerPointAndSums) {
  ScoreLog a(4), b(4);
  a.record(0, 0.5);
  a.record(1, 0.9);
  b.record(0, 0.8);
  b.record(2, 0.25);
  GroundStationTally gcs(4);
  EXPECT_EQ(gcs.merge(a), 2u);
  EXPECT_EQ(gcs.merge(b), 2u);  // point 0 improves 0.5 -> 0.8, point 2 is new
  EXPECT_EQ(gcs.merge(a), 0u);  // merging again changes nothing
  EXPECT_FLOAT_EQ(gcs.value(0), 0.8f);
  EXPECT_FLOAT_EQ(gcs.value(1), 0.9f);
  EXPECT_FLOAT_EQ(gcs.value(2), 0.25f);
  EXPECT_EQ(gcs.value(3), 0.0f);
  EXPECT_EQ(gcs.detectedCount(), 3u);
  EXPECT_NEAR(gcs.totalScore(), 0.8 + 0.9 + 0.25, 1e-6);
}

TEST(GroundStationTally, CrashedUavMergedOnlyInCaricMode) {
  ScoreLog log(2);
  log.record(1, 0.6);
  GroundStationTally caric(2, ScoringMode::Caric);
  EXPECT_EQ(caric.merge(log, /*uavAlive=*/false), 1u);
  EXPECT_FLOAT_EQ(caric.value(1), 0.6f);
  GroundStationTally strict(2, ScoringMode::Strict);
  EXPECT_EQ(strict.merge(log, /*uavAlive=*/false), 0u);
  EXPECT_EQ(strict.value(1), 0.0f);
  EXPECT_EQ(strict.merge(log, /*uavAlive=*/true), 1u);
}

// Merging only the points a log improved since its last merge gives what merging it all gives.
TEST(GroundStationTally, MergePointsEqualsMergeOfTheChangedPoints) {
  ScoreLog a(5), b(5);
  a.record(0, 0.5);
  a.record(3, 0.3);
  GroundStationTally whole(5), sparse(5);
  whole.merge(a);
  sparse.mergePoints(a, {0, 3});
  b.record(0, 0.7);
  b.record(4, 0.9);
  a.record(3, 0.6);  // improved since a's merge
  EXPECT_EQ(whole.merge(b) + whole.merge(a), 3u);
  EXPECT_EQ(sparse.mergePoints(b, {0, 4}) + sparse.mergePoints(a, {3}), 3u);
  EXPECT_EQ(whole.values(), sparse.values());
  EXPECT_EQ(whole.detectedCount(), sparse.detectedCount());
  GroundStationTally strict(5, ScoringMode::Strict);
  EXPECT_EQ(strict.mergePoints(a, {0, 3}, /*uavAlive=*/false), 0u);
  EXPECT_EQ(strict.detectedCount(), 0u);
}

TEST(ScoringPolicy, ReferenceQuirksOnlyInCaricMode) {
  EXPECT_TRUE(capturesWhenCrashed(ScoringMode::Caric));
  EXPECT_FALSE(capturesWhenCrashed(ScoringMode::Strict));
  EXPECT_TRUE(scoresAfterMissionEnd(ScoringMode::Caric));
  EXPECT_FALSE(scoresAfterMissionEnd(ScoringMode::Strict));
}

}  // namespace
}  // namespace coinspect::sensing
