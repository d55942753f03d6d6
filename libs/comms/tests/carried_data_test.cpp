#include "coinspect/comms/carried_data.h"

#include <gtest/gtest.h>

#include "coinspect/testing/input_errors.h"

namespace coinspect::comms {
namespace {

// 0 - 1 - 2 in a chain, 3 alone.
LinkMatrix chain() {
  LinkMatrix links(4);
  links.setLinked(0, 1, true);
  links.setLinked(1, 2, true);
  return links;
}

const std::vector<bool> kAllAlive(4, true);

TEST(CarriedData, ItemsCrossOneLinkPerExchange) {
  CarriedData data(4, 3);
  EXPECT_TRUE(data.add(2, 1));
  EXPECT_FALSE(data.add(2, 1));
  auto first = data.exchange(chain(), kAllAlive);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].unit, 1u);
  EXPECT_EQ(first[0].item, 1u);
  EXPECT_EQ(first[0].from, 2u);
  EXPECT_FALSE(data.holds(0, 1));  // two links away: not yet
  const auto second = data.exchange(chain(), kAllAlive);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].unit, 0u);
  EXPECT_EQ(second[0].from, 1u);
  EXPECT_TRUE(data.exchange(chain(), kAllAlive).empty());
  EXPECT_FALSE(data.holds(3, 1));  // never linked
  EXPECT_EQ(data.heldCount(0), 1u);
}

TEST(CarriedData, TheMiddleTakesFromBothSidesAndTheLowestNeighbourIsTheSender) {
  CarriedData data(4, 3);
  data.add(0, 0);
  data.add(2, 0);
  data.add(2, 2);
  const auto out = data.exchange(chain(), kAllAlive);
  // 0 and 2 see only 1, which held nothing before the exchange; 1 takes item 0 (both ends hold
  // it: 0 is named) and item 2 from 2.
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].unit, 1u);
  EXPECT_EQ(out[0].item, 0u);
  EXPECT_EQ(out[0].from, 0u);
  EXPECT_EQ(out[1].unit, 1u);
  EXPECT_EQ(out[1].item, 2u);
  EXPECT_EQ(out[1].from, 2u);
  EXPECT_FALSE(data.holds(0, 2));
}

TEST(CarriedData, DeadUnitsNeitherGiveNorTakeAndLoseWhatTheyHeld) {
  CarriedData data(4, 2);
  data.add(1, 0);
  std::vector<bool> alive = kAllAlive;
  alive[1] = false;
  EXPECT_TRUE(data.exchange(chain(), alive).empty());
  data.drop(1);
  EXPECT_FALSE(data.holds(1, 0));
  EXPECT_EQ(data.heldCount(1), 0u);
}

TEST(MeetingCounter, ALinkComingUpAfterTheGapIsOneMeeting) {
  MeetingCounter counter(3, 2.0);
  LinkMatrix links(3);
  links.setLinked(0, 1, true);
  EXPECT_TRUE(counter.update(0.0, links).empty());  // linked at the start: not a meeting
  links.setLinked(0, 1, false);
  EXPECT_TRUE(counter.update(1.0, links).empty());
  links.setLinked(0, 1, true);
  EXPECT_TRUE(counter.update(2.5, links).empty());  // back after 1.5 s < gap: same meeting
  links.setLinked(0, 1, false);
  counter.update(3.0, links);
  links.setLinked(0, 1, true);
  links.setLinked(1, 2, true);  // never linked before: a meeting at once
  const auto met = counter.update(5.0, links);
  ASSERT_EQ(met.size(), 2u);
  EXPECT_EQ(met[0], (std::pair<uint32_t, uint32_t>{0, 1}));
  EXPECT_EQ(met[1], (std::pair<uint32_t, uint32_t>{1, 2}));
  EXPECT_TRUE(counter.update(6.0, links).empty());  // still linked
  EXPECT_THROW(MeetingCounter(2, -1.0), InputError);
}

}  // namespace
}  // namespace coinspect::comms
