#include "coinspect/strategies/coinspect/shared_progress.h"

#include <gtest/gtest.h>

namespace coinspect::strategies::coinspect_strategy {
namespace {

agent::AgentView viewAt(double time, bool neighbour) {
  agent::AgentView view;
  view.time = time;
  if (neighbour) view.neighbours.push_back({"raffles", agent::Role::Photographer, {}});
  return view;
}

std::vector<uint64_t> keysOf(const std::optional<agent::OutgoingMessage>& message) {
  EXPECT_TRUE(message);
  return message ? *decodePatchKeys(message->bytes) : std::vector<uint64_t>{};
}

TEST(SharedProgress, ReportsNewKeysThenEverythingPeriodically) {
  SharedProgress progress(3.0, 30.0);
  progress.markViewed(7);
  progress.markViewed(3);
  EXPECT_FALSE(progress.exchange(viewAt(1.0, false)));  // nobody in sight: nothing sent
  EXPECT_EQ(keysOf(progress.exchange(viewAt(2.0, true))), (std::vector<uint64_t>{3, 7}));
  progress.markViewed(9);
  EXPECT_FALSE(progress.exchange(viewAt(4.0, true)));  // within the period
  EXPECT_EQ(keysOf(progress.exchange(viewAt(5.0, true))), (std::vector<uint64_t>{9}));
  EXPECT_FALSE(progress.exchange(viewAt(9.0, true)));  // nothing new
  EXPECT_EQ(keysOf(progress.exchange(viewAt(33.0, true))), (std::vector<uint64_t>{3, 7, 9}));
}

TEST(SharedProgress, LearnsAndRelaysWhatNeighboursReport) {
  SharedProgress progress;
  auto view = viewAt(1.0, true);
  view.messages.push_back({"raffles", kInspectedTopic, encodePatchKeys({4, 5}), 1.0});
  view.messages.push_back({"raffles", kInspectedTopic, {1, 2, 3}, 1.0});  // malformed: ignored
  view.messages.push_back({"raffles", "other", encodePatchKeys({6}), 1.0});
  const auto report = progress.exchange(view);
  EXPECT_TRUE(progress.done(4));
  EXPECT_TRUE(progress.done(5));
  EXPECT_FALSE(progress.done(6));
  EXPECT_EQ(progress.knownCount(), 2u);
  EXPECT_EQ(keysOf(report), (std::vector<uint64_t>{4, 5}));
  EXPECT_FALSE(decodePatchKeys({1, 2, 3}));
}

}  // namespace
}  // namespace coinspect::strategies::coinspect_strategy
