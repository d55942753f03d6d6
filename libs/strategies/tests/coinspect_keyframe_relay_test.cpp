#include "coinspect/strategies/coinspect/keyframe_relay.h"

#include <gtest/gtest.h>

#include <memory>

namespace coinspect::strategies::coinspect_strategy {
namespace {

const std::vector<std::string> kFleet = {"gcs", "jurong", "raffles", "sentosa"};

agent::KeyFrameView frameOf(const std::string& producer, uint64_t id, double time,
                            std::vector<Eigen::Vector3f> points) {
  auto frame = std::make_shared<agent::KeyFrame>();
  frame->producer = producer;
  frame->id = id;
  frame->time = time;
  frame->position = agent::Vec3(10, -4, 12);
  frame->bodyOrientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, agent::Vec3::UnitZ()));
  frame->points = std::move(points);
  return frame;
}

agent::AgentView viewOf(const std::string& name, double time, agent::Vec3 position,
                        std::vector<std::string> neighbours) {
  agent::AgentView view;
  view.name = name;
  view.time = time;
  view.odometry.position = position;
  for (const auto& n : neighbours)
    view.neighbours.push_back({n, agent::Role::Photographer, {}});
  return view;
}

std::vector<agent::OutgoingMessage> framesIn(const std::vector<agent::OutgoingMessage>& messages) {
  std::vector<agent::OutgoingMessage> frames;
  for (const auto& m : messages)
    if (m.topic == kFrameTopic) frames.push_back(m);
  return frames;
}

TEST(KeyFrameRelay, FrameRoundTripKeepsPointsWithinOneCentimetre) {
  const auto frame = frameOf("raffles", 7, 12.5, {{10.004f, 30.f, -5.f}, {-35.f, 2.f, 40.f}});
  const auto bytes = encodeKeyFrame(*frame, 2);
  const auto back = decodeKeyFrame(bytes, kFleet);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->producer, "raffles");
  EXPECT_EQ(back->id, 7u);
  EXPECT_DOUBLE_EQ(back->time, 12.5);
  EXPECT_EQ(back->position, frame->position);
  EXPECT_NEAR(back->bodyOrientation.angularDistance(frame->bodyOrientation), 0.0, 1e-12);
  ASSERT_EQ(back->points.size(), 2u);
  for (size_t i = 0; i < 2; ++i)
    EXPECT_LE((back->points[i] - frame->points[i]).norm(), 0.01f);
}

TEST(KeyFrameRelay, MalformedMessagesAreRejected) {
  const auto bytes = encodeKeyFrame(*frameOf("raffles", 7, 12.5, {{1, 2, 3}}), 2);
  EXPECT_FALSE(decodeKeyFrame({bytes.begin(), bytes.end() - 1}, kFleet));            // truncated
  EXPECT_FALSE(decodeKeyFrame(encodeKeyFrame(*frameOf("x", 1, 0, {}), 9), kFleet));  // producer
  auto extra = bytes;
  extra.push_back(0);
  EXPECT_FALSE(decodeKeyFrame(extra, kFleet));
  EXPECT_FALSE(decodeDigest({1, 0, 9, 0}, kFleet.size()));  // producer 9 of 4, then cut
  const IdRanges ranges = {{1, {{0, 4}, {9, 9}}}, {3, {{2, 3}}}};
  EXPECT_EQ(*decodeDigest(encodeDigest(ranges), kFleet.size()), ranges);
  auto bad = encodeDigest({{1, {{5, 4}}}});  // last < first
  EXPECT_FALSE(decodeDigest(bad, kFleet.size()));
}

TEST(KeyFrameRelay, SendsWhatANeighbourLacksNewestFirstAndDropsUavPoints) {
  RelayOptions options;
  options.framesPerReply = 2;
  KeyFrameRelay explorer(options, kFleet), photographer(options, kFleet);

  // The explorer scans three frames; the second holds a point on the photographer beside it.
  auto view = viewOf("jurong", 1.0, {0, 0, 10}, {});
  view.ownKeyFrames = {frameOf("jurong", 0, 1.0, {{30, 0, 0}}),
                       frameOf("jurong", 1, 2.0, {{30, 1, 0}, {5.5f, 0, 10}}),
                       frameOf("jurong", 2, 3.0, {{30, 2, 0}})};
  view.neighbours.push_back({"sentosa", agent::Role::Photographer, {}});
  view.neighbours.back().odometry.position = {5, 0, 10};
  explorer.exchange(view);
  EXPECT_EQ(explorer.known(), 3u);
  EXPECT_EQ(explorer.takeNew(10).size(), 3u);

  // The photographer, with nothing, digests; the explorer answers with the two newest frames.
  auto digest = photographer.exchange(viewOf("sentosa", 5.0, {5, 0, 10}, {"jurong"}));
  ASSERT_EQ(digest.size(), 1u);
  EXPECT_EQ(digest[0].topic, kDigestTopic);
  EXPECT_TRUE(digest[0].to.empty());
  auto reception = viewOf("jurong", 5.0, {0, 0, 10}, {"sentosa"});
  reception.messages.push_back({"sentosa", kDigestTopic, digest[0].bytes, 5.0});
  const auto frames = framesIn(explorer.exchange(reception));
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].to, "sentosa");

  auto arrival = viewOf("sentosa", 5.1, {5, 0, 10}, {"jurong"});
  for (const auto& m : frames)
    arrival.messages.push_back({"jurong", m.topic, m.bytes, 5.0});
  photographer.exchange(arrival);
  EXPECT_EQ(photographer.relayedIn(), 2u);
  const auto got = photographer.takeNew(10);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0]->id, 2u);
  EXPECT_EQ(got[1]->id, 1u);
  EXPECT_EQ(got[1]->points.size(), 1u);  // the point on the photographer was dropped

  // The next digest covers ids 1-2: the explorer now sends only id 0; a digest from a robot out
  // of sight gets nothing.
  auto second = photographer.exchange(viewOf("sentosa", 8.0, {5, 0, 10}, {"jurong"}));
  ASSERT_EQ(second.size(), 1u);
  auto again = viewOf("jurong", 8.0, {0, 0, 10}, {"sentosa"});
  again.messages.push_back({"sentosa", kDigestTopic, second[0].bytes, 8.0});
  const auto rest = framesIn(explorer.exchange(again));
  ASSERT_EQ(rest.size(), 1u);
  EXPECT_EQ(decodeKeyFrame(rest[0].bytes, kFleet)->id, 0u);
  auto unseen = viewOf("jurong", 8.5, {0, 0, 10}, {});
  unseen.messages.push_back({"sentosa", kDigestTopic, second[0].bytes, 8.5});
  EXPECT_TRUE(explorer.exchange(unseen).empty());
}

// A frame relayed to two robots as the same bytes is decoded into one object both hold; the same
// producer and id with other points (cleaned by another robot) is a frame of its own.
TEST(KeyFrameRelay, RobotsReceivingTheSameFrameShareOneDecodedCopy) {
  const auto received = [](const std::string& name, const std::vector<uint8_t>& bytes) {
    KeyFrameRelay relay(RelayOptions{}, kFleet);
    auto view = viewOf(name, 5.0, {5, 0, 10}, {"jurong"});
    view.messages.push_back({"jurong", kFrameTopic, bytes, 5.0});
    relay.exchange(view);
    auto got = relay.takeNew(10);
    EXPECT_EQ(got.size(), 1u);
    return got.empty() ? nullptr : got[0];
  };
  const auto bytes = encodeKeyFrame(*frameOf("jurong", 4, 2.0, {{30, 1, 0}, {31, 1, 0}}), 1);
  const auto cleaned = encodeKeyFrame(*frameOf("jurong", 4, 2.0, {{30, 1, 0}}), 1);
  const auto first = received("raffles", bytes);
  const auto second = received("sentosa", bytes);
  const auto other = received("gcs", cleaned);
  ASSERT_TRUE(first && second && other);
  EXPECT_EQ(first.get(), second.get());
  EXPECT_NE(first.get(), other.get());
  EXPECT_EQ(first->points.size(), 2u);
  EXPECT_EQ(other->points.size(), 1u);
}

}  // namespace
}  // namespace coinspect::strategies::coinspect_strategy
