// The link matrix, one-time key-frame delivery and neighbour odometry.
#include <gtest/gtest.h>

#include "coinspect/comms/key_frame_exchange.h"
#include "coinspect/comms/link_matrix.h"
#include "coinspect/comms/neighbour_odometry.h"

namespace coinspect::comms {
namespace {

TEST(LinkMatrix, SymmetricWithNeighboursInIndexOrder) {
  LinkMatrix links(4);
  links.setLinked(3, 1, true);
  links.setLinked(1, 0, true);
  EXPECT_TRUE(links.linked(1, 3));
  EXPECT_TRUE(links.linked(3, 1));
  EXPECT_FALSE(links.linked(0, 3));
  EXPECT_EQ(links.neighbours(1), (std::vector<uint32_t>{0, 3}));
  EXPECT_EQ(links.linkCount(), 2u);
  links.setLinked(1, 3, false);
  EXPECT_FALSE(links.linked(3, 1));
}

TEST(LinkMatrix, ChangedSinceListsEachChangedPairOnce) {
  LinkMatrix before(4);
  before.setLinked(0, 1, true);
  before.setLinked(2, 3, true);
  LinkMatrix after = before;
  EXPECT_TRUE(after.changedSince(before).empty());
  after.setLinked(2, 3, false);
  after.setLinked(1, 2, true);
  const std::vector<LinkChange> expected{{1, 2, true}, {2, 3, false}};
  EXPECT_EQ(after.changedSince(before), expected);
}

// Units 0-1 and 0-2 linked; 3 out of sight.
LinkMatrix star() {
  LinkMatrix links(4);
  links.setLinked(0, 1, true);
  links.setLinked(0, 2, true);
  return links;
}

TEST(KeyFrameExchange, DeliveredOnceToNeighboursInSightAtPublication) {
  KeyFrameExchange exchange(4);
  EXPECT_EQ(exchange.publish(0, 7, star(), {true, true, true, true}, 3.0), 2u);
  const std::vector<KeyFrameDelivery> at1 = exchange.takeDeliveries(1);
  ASSERT_EQ(at1.size(), 1u);
  EXPECT_EQ(at1[0], (KeyFrameDelivery{0, 1, 7, 3.0}));
  EXPECT_EQ(exchange.takeDeliveries(2).size(), 1u);
  EXPECT_TRUE(exchange.takeDeliveries(3).empty());
  // Unit 3 comes into sight later: the old key frame is not re-sent, even if published again.
  LinkMatrix later = star();
  later.setLinked(0, 3, true);
  EXPECT_EQ(exchange.publish(0, 7, later, {true, true, true, true}, 4.0), 0u);
  EXPECT_TRUE(exchange.takeDeliveries(3).empty());
  EXPECT_TRUE(exchange.takeDeliveries(1).empty());
  // A new one reaches all three.
  EXPECT_EQ(exchange.publish(0, 8, later, {true, true, true, true}, 4.0), 3u);
  EXPECT_EQ(exchange.takeDeliveries(3).size(), 1u);
  EXPECT_EQ(exchange.deliveryCount(), 5u);
  // Ids are per unit: unit 1 may publish its own key frame 7.
  EXPECT_EQ(exchange.publish(1, 7, later, {true, true, true, true}, 4.0), 1u);
}

TEST(KeyFrameExchange, DeadUnitsNeitherSendNorReceive) {
  KeyFrameExchange exchange(4);
  EXPECT_EQ(exchange.publish(0, 1, star(), {true, false, true, true}, 0.0), 1u);
  EXPECT_TRUE(exchange.takeDeliveries(1).empty());
  EXPECT_EQ(exchange.publish(1, 1, star(), {true, false, true, true}, 0.0), 0u);
  EXPECT_TRUE(exchange.takeDeliveries(0).empty());
}

TEST(NeighbourOdometry, OnlyAliveNeighboursInSight) {
  std::vector<UnitOdometry> all(4);
  for (uint32_t k = 0; k < 4; ++k) {
    all[k].unit = k;
    all[k].position = world::Vec3(k, 0, 1);
  }
  const auto seen = neighbourOdometry(0, star(), {true, true, false, true}, all);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].unit, 1u);
  EXPECT_TRUE(neighbourOdometry(3, star(), {true, true, true, true}, all).empty());
  EXPECT_TRUE(neighbourOdometry(1, star(), {true, false, true, true}, all).empty());
  EXPECT_EQ(neighbourOdometry(0, star(), {true, true, true, true}, all).size(), 2u);
}

}  // namespace
}  // namespace coinspect::comms
