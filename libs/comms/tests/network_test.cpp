// The message network: single-hop delivery only over live links, drop accounting, bandwidth cap.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "coinspect/comms/network.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/world/ray_caster.h"
#include "comms_scenes.h"

namespace coinspect::comms {
namespace {

Message message(uint32_t from, uint32_t to, size_t payloadBytes, double time = 0.0,
                const std::string& topic = "test") {
  Message m;
  m.from = from;
  m.to = to;
  m.topic = topic;
  m.payload.assign(payloadBytes, static_cast<uint8_t>(from));
  m.sentTime = time;
  return m;
}

// Units 0-1 and 1-2 linked, 0-2 not.
LinkMatrix chain() {
  LinkMatrix links(3);
  links.setLinked(0, 1, true);
  links.setLinked(1, 2, true);
  return links;
}

TEST(Network, DeliversOverALinkInSendOrder) {
  Network net(3);
  net.setTopology(chain(), {true, true, true}, 0.0);
  EXPECT_TRUE(net.send(message(0, 1, 10, 0.0, "a")));
  EXPECT_TRUE(net.send(message(2, 1, 20, 0.0, "b")));
  EXPECT_TRUE(net.send(message(0, 1, 30, 0.0, "c")));
  const std::vector<Message> inbox = net.takeInbox(1);
  ASSERT_EQ(inbox.size(), 3u);
  EXPECT_EQ(inbox[0].topic, "a");
  EXPECT_EQ(inbox[1].topic, "b");
  EXPECT_EQ(inbox[2].topic, "c");
  EXPECT_EQ(inbox[1].from, 2u);
  EXPECT_EQ(inbox[1].payload.size(), 20u);
  EXPECT_EQ(inbox[0].sequence, 0u);
  EXPECT_EQ(inbox[2].sequence, 2u);
  EXPECT_TRUE(net.takeInbox(1).empty());  // taken once
}

TEST(Network, SingleHopOnlyWithoutLinkIsDroppedAndCounted) {
  Network net(3);
  net.setTopology(chain(), {true, true, true}, 0.0);
  // 0 and 2 both see 1 but not each other: no relay through 1.
  EXPECT_FALSE(net.send(message(0, 2, 68)));
  EXPECT_TRUE(net.takeInbox(2).empty());
  EXPECT_TRUE(net.takeInbox(1).empty());
  const LinkCounters& c = net.counters(0, 2);
  EXPECT_EQ(c.sentMessages, 1u);
  EXPECT_EQ(c.sentBytes, 100u);  // 68 payload + 32 header
  EXPECT_EQ(c.droppedMessages, 1u);
  EXPECT_EQ(c.droppedBytes, 100u);
  EXPECT_EQ(c.deliveredMessages, 0u);
  EXPECT_EQ(c.overBudgetMessages, 0u);
}

TEST(Network, BothEndsMustBeAlive) {
  Network net(3);
  net.setTopology(chain(), {true, false, true}, 0.0);
  EXPECT_FALSE(net.send(message(0, 1, 1)));  // dead receiver
  EXPECT_FALSE(net.send(message(1, 2, 1)));  // dead sender
  EXPECT_EQ(net.totals().droppedMessages, 2u);
  EXPECT_EQ(net.inboxSize(1) + net.inboxSize(2), 0u);
}

TEST(Network, NeverBuffersAcrossTopologyChanges) {
  Network net(2);
  LinkMatrix up(2);
  up.setLinked(0, 1, true);
  net.setTopology(LinkMatrix(2), {true, true}, 0.0);
  EXPECT_FALSE(net.send(message(0, 1, 5, 0.0)));
  net.setTopology(up, {true, true}, 0.02);
  EXPECT_TRUE(net.takeInbox(1).empty());  // the dropped one does not reappear
  EXPECT_TRUE(net.send(message(0, 1, 5, 0.02)));
  EXPECT_EQ(net.takeInbox(1).size(), 1u);
}

TEST(Network, CountsBytesPerDirectedLinkAndInTotal) {
  Network net(3);
  net.setTopology(chain(), {true, true, true}, 0.0);
  net.send(message(0, 1, 8));    // 40 bytes delivered
  net.send(message(0, 1, 18));   // 50 bytes delivered
  net.send(message(1, 0, 0));    // 32 bytes delivered, the other direction
  net.send(message(2, 0, 100));  // 132 bytes dropped
  EXPECT_EQ(net.counters(0, 1).deliveredMessages, 2u);
  EXPECT_EQ(net.counters(0, 1).deliveredBytes, 90u);
  EXPECT_EQ(net.counters(1, 0).deliveredBytes, 32u);
  EXPECT_EQ(net.counters(2, 1).sentMessages, 0u);
  const LinkCounters total = net.totals();
  EXPECT_EQ(total.sentMessages, 4u);
  EXPECT_EQ(total.sentBytes, 40u + 50u + 32u + 132u);
  EXPECT_EQ(total.deliveredBytes, 122u);
  EXPECT_EQ(total.droppedBytes, 132u);
}

TEST(Network, BroadcastReachesCurrentNeighboursOnly) {
  Network net(3);
  net.setTopology(chain(), {true, true, true}, 1.5);
  EXPECT_EQ(net.broadcast(1, "odom", {1, 2, 3}), 2u);
  EXPECT_EQ(net.broadcast(0, "odom", {4}), 1u);
  const std::vector<Message> at0 = net.takeInbox(0);
  const std::vector<Message> at2 = net.takeInbox(2);
  ASSERT_EQ(at0.size(), 1u);
  ASSERT_EQ(at2.size(), 1u);
  EXPECT_EQ(at0[0].from, 1u);
  EXPECT_DOUBLE_EQ(at0[0].sentTime, 1.5);
  EXPECT_EQ(at2[0].payload, (std::vector<uint8_t>{1, 2, 3}));
  EXPECT_EQ(net.takeInbox(1).size(), 1u);
  EXPECT_EQ(net.counters(0, 2).sentMessages, 0u);  // no attempt towards a non-neighbour
}

// The recorder's view of traffic: every send, broadcast copies included, with its fate.
TEST(Network, SendObserverSeesEveryMessageAndItsFate) {
  Network net(3);
  net.setTopology(chain(), {true, true, true}, 2.0);
  std::vector<std::tuple<uint32_t, uint32_t, std::string, size_t, bool>> seen;
  net.setSendObserver([&](const Message& m, bool delivered) {
    seen.emplace_back(m.from, m.to, m.topic, m.sizeBytes(), delivered);
  });
  net.send(message(0, 1, 10, 2.0, "a"));
  net.send(message(0, 2, 5, 2.0, "b"));  // no link: dropped
  net.broadcast(1, "c", {7});
  const decltype(seen) expected = {
      {0, 1, "a", 42, true}, {0, 2, "b", 37, false}, {1, 0, "c", 33, true}, {1, 2, "c", 33, true}};
  EXPECT_EQ(seen, expected);
}

TEST(Network, BandwidthCapDropsWhatExceedsTheTokenBucket) {
  // 1000 B/s, 1 s burst: the bucket holds 1000 bytes; messages of 68 + 32 = 100 bytes.
  Network net(3, BandwidthCap{1000.0, 1.0});
  net.setTopology(chain(), {true, true, true}, 0.0);
  for (int k = 0; k < 10; ++k)
    EXPECT_TRUE(net.send(message(0, 1, 68, 0.0))) << k;
  EXPECT_FALSE(net.send(message(0, 1, 68, 0.0)));  // bucket empty
  // Each directed link has its own bucket.
  EXPECT_TRUE(net.send(message(1, 0, 68, 0.0)));
  EXPECT_TRUE(net.send(message(1, 2, 68, 0.0)));
  // Half a second refills 500 bytes: five more.
  for (int k = 0; k < 5; ++k)
    EXPECT_TRUE(net.send(message(0, 1, 68, 0.5))) << k;
  EXPECT_FALSE(net.send(message(0, 1, 68, 0.5)));
  const LinkCounters& c = net.counters(0, 1);
  EXPECT_EQ(c.deliveredMessages, 15u);
  EXPECT_EQ(c.droppedMessages, 2u);
  EXPECT_EQ(c.overBudgetMessages, 2u);
  EXPECT_EQ(c.overBudgetBytes, 200u);
  // The bucket never holds more than one burst: after 10 s idle, still 10 messages only.
  for (int k = 0; k < 10; ++k)
    EXPECT_TRUE(net.send(message(0, 1, 68, 10.0))) << k;
  EXPECT_FALSE(net.send(message(0, 1, 68, 10.0)));
  // Larger than the bucket: never deliverable.
  EXPECT_FALSE(net.send(message(1, 2, 2000, 100.0)));
}

TEST(Network, RejectsABadBandwidthCap) {
  EXPECT_MENTIONS(testing::messageOf([] { Network(2, BandwidthCap{0.0, 1.0}); }), "bandwidth");
  EXPECT_THROW(Network(2, BandwidthCap{100.0, -1.0}), InputError);
}

// End to end with the reference's link model: a message across a wall is dropped, and gets
// through once the receiver has gone around the wall.
TEST(Network, MessageWithoutLineOfSightIsDropped) {
  const world::RayCaster caster({test::wallAcrossX(3.0)}, 0.0);
  std::vector<LinkEndpoint> units{test::endpoint(world::Vec3(-5, 0, 1.5)),
                                  test::endpoint(world::Vec3(5, 0, 1.5))};
  const CaricLinkModel model;
  LinkMatrix links;
  model.update(caster, units, links);
  Network net(2);
  net.setTopology(links, {true, true}, 0.0);
  EXPECT_FALSE(net.send(message(0, 1, 10, 0.0)));
  EXPECT_EQ(net.counters(0, 1).droppedMessages, 1u);
  units[1].position = world::Vec3(1, 7, 1.5);
  model.update(caster, units, links);
  net.setTopology(links, {true, true}, 0.02);
  EXPECT_TRUE(net.send(message(0, 1, 10, 0.02)));
  EXPECT_EQ(net.takeInbox(1).size(), 1u);
}

}  // namespace
}  // namespace coinspect::comms
