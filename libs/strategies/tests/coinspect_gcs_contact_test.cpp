#include "coinspect/strategies/coinspect/gcs_contact.h"

#include <gtest/gtest.h>

namespace coinspect::strategies::coinspect_strategy {
namespace {

agent::AgentView viewAt(double missionTime, const Vec3& position, bool gcsInSight,
                        double gained = 0.0) {
  agent::AgentView view;
  view.started = true;
  view.missionTime = missionTime;
  view.timeLeft = 600.0 - missionTime;
  view.odometry.position = position;
  if (gcsInSight) view.neighbours.push_back({"gcs", agent::Role::GroundStation, {}});
  if (gained > 0.0) view.captures.push_back({missionTime, 3, 3, gained});
  return view;
}

TEST(GcsContact, RemembersContactPointsAndDeliversPeriodically) {
  DeliveryOptions options;
  GcsContact contact(options);
  EXPECT_FALSE(contact.nearestContactPoint(Vec3::Zero()));
  contact.observe(viewAt(1.0, Vec3(0, 0, 5), true));
  contact.observe(viewAt(2.0, Vec3(3, 0, 5), true));  // closer than the spacing: not kept
  contact.observe(viewAt(3.0, Vec3(20, 0, 5), true));
  EXPECT_EQ(*contact.nearestContactPoint(Vec3(18, 1, 5)), Vec3(20, 0, 5));
  EXPECT_EQ(*contact.nearestContactPoint(Vec3(4, 0, 5)), Vec3(0, 0, 5));

  contact.observe(viewAt(10.0, Vec3(60, 0, 5), false, 30.0));
  EXPECT_DOUBLE_EQ(contact.undeliveredGain(), 30.0);
  EXPECT_FALSE(contact.shouldDeliver(viewAt(100.0, Vec3(60, 0, 5), false)));
  EXPECT_TRUE(contact.shouldDeliver(viewAt(3.0 + options.period, Vec3(60, 0, 5), false)));
  contact.observe(viewAt(200.0, Vec3(20, 0, 5), true));
  EXPECT_DOUBLE_EQ(contact.undeliveredGain(), 0.0);
}

TEST(GcsContact, HeadsHomeBeforeTheEnd) {
  GcsContact contact;
  contact.observe(viewAt(1.0, Vec3(0, 0, 5), true));
  // 90 m away at 3 m/s: 30 s of travel + 25 s margin.
  const auto early = viewAt(600.0 - 60.0, Vec3(90, 0, 5), false);
  contact.observe(early);
  EXPECT_FALSE(contact.shouldDeliver(early));
  const auto late = viewAt(600.0 - 54.0, Vec3(90, 0, 5), false);
  contact.observe(late);
  EXPECT_TRUE(contact.shouldDeliver(late));
}

}  // namespace
}  // namespace coinspect::strategies::coinspect_strategy
