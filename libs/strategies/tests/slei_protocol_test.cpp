#include "coinspect/strategies/slei/protocol.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coinspect::strategies::slei {
namespace {

// Aggregates with the fields a test sets; the rest default.
Report makeReport(int32_t box, bool finished, double remaining, uint32_t number,
                  double energy = 1.0) {
  Report r;
  r.box = box, r.boxFinished = finished, r.remaining = remaining, r.meetingNumber = number;
  r.energy = energy;
  return r;
}
Reply makeReply(uint32_t number, int32_t box, Meeting next, std::vector<Meeting> stops = {},
                std::vector<Adoption> adopt = {}, bool drop = false, double chargeFrom = 0.0) {
  Reply r;
  r.meetingNumber = number, r.box = box, r.next = next, r.stops = std::move(stops);
  r.adopt = std::move(adopt), r.dropInspectors = drop, r.chargeFrom = chargeFrom;
  return r;
}

TEST(SleiProtocol, EveryMessageRoundTrips) {
  FleetPlan plan;
  plan.subgroups.push_back({1, {2, 4}, 3, {Vec3(1, 2, 0), 81.5}, 7});
  plan.subgroups.push_back({3, {}, -1, {Vec3::Zero(), 0.0}});
  const auto decodedPlan = decodePlan(encode(plan));
  ASSERT_TRUE(decodedPlan);
  ASSERT_EQ(decodedPlan->subgroups.size(), 2u);
  EXPECT_EQ(decodedPlan->subgroups[0].inspectors, (std::vector<uint32_t>{2, 4}));
  EXPECT_EQ(decodedPlan->subgroups[0].box, 3);
  EXPECT_EQ(decodedPlan->subgroups[0].firstMeeting.place, Vec3(1, 2, 0));
  EXPECT_EQ(decodedPlan->subgroups[0].station, 7u);
  EXPECT_EQ(decodedPlan->subgroups[1].box, -1);

  const auto report = decodeReport(encode(makeReport(2, true, 75.25, 4, 0.375)));
  ASSERT_TRUE(report);
  EXPECT_EQ(report->box, 2);
  EXPECT_TRUE(report->boxFinished);
  EXPECT_EQ(report->remaining, 75.25);
  EXPECT_EQ(report->meetingNumber, 4u);
  EXPECT_EQ(report->energy, 0.375);

  const auto reply = decodeReply(encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0},
                                                  {{Vec3(1, 1, 0), 150.0}, {Vec3(3, 4, 5), 200.0}},
                                                  {{6, Vec3(7, 8, 9)}}, true, 180.5)));
  ASSERT_TRUE(reply);
  EXPECT_TRUE(reply->dropInspectors);
  EXPECT_EQ(reply->chargeFrom, 180.5);
  ASSERT_EQ(reply->adopt.size(), 1u);
  EXPECT_EQ(reply->adopt[0].inspector, 6u);
  EXPECT_EQ(reply->adopt[0].place, Vec3(7, 8, 9));
  EXPECT_EQ(reply->box, 5);
  EXPECT_EQ(reply->next.time, 200.0);
  ASSERT_EQ(reply->stops.size(), 2u);
  EXPECT_EQ(reply->stops[0].place, Vec3(1, 1, 0));
  EXPECT_EQ(reply->stops[1].time, 200.0);
  auto replyBytes =
      encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0}, {{Vec3(1, 1, 0), 150.0}}, {}, false));
  // No next box, no shape flag, no charger time, no flag, no adoptions, a stop cut short.
  replyBytes.resize(replyBytes.size() - 4 - 1 - 8 - 1 - 4 - 8);
  EXPECT_FALSE(decodeReply(replyBytes));
  replyBytes = encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0}, {}, {{6, Vec3(7, 8, 9)}}, false));
  replyBytes.resize(replyBytes.size() - 4 - 1 - 8 - 1 - 8);  // an adoption cut short
  EXPECT_FALSE(decodeReply(replyBytes));
  replyBytes = encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0}, {}, {}, false));
  replyBytes[replyBytes.size() - 15] = 2;  // not a flag
  EXPECT_FALSE(decodeReply(replyBytes));
  replyBytes = encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0}, {}, {}, false));
  replyBytes[replyBytes.size() - 6] = 2;  // not a shape flag
  EXPECT_FALSE(decodeReply(replyBytes));
  // The reserved next box: none by default, a box index, nothing below -1.
  EXPECT_EQ(decodeReply(encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0})))->nextBox, -1);
  Reply reserving = makeReply(4, 5, {Vec3(3, 4, 5), 200.0});
  reserving.nextBox = 6;
  EXPECT_EQ(decodeReply(encode(reserving))->nextBox, 6);
  reserving.nextBox = -2;
  EXPECT_FALSE(decodeReply(encode(reserving)));
  replyBytes = encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0}));
  replyBytes.resize(replyBytes.size() - 2);  // the next box cut short
  EXPECT_FALSE(decodeReply(replyBytes));
  replyBytes = encode(makeReply(4, 5, {Vec3(3, 4, 5), 200.0}));
  replyBytes.back() = 2;  // not a next-box shape flag
  EXPECT_FALSE(decodeReply(replyBytes));

  // The unknown workspace's parts: a report's remainder and a reply's box shape.
  Report parts = makeReport(1, false, 60.0, 3);
  parts.remainder.resize(2);
  parts.remainder[0].center = Vec3(1, 2, 3);
  parts.remainder[0].size = Vec3(4, 5, 6);
  parts.remainder[1].center = Vec3(-1, 0, 2);
  parts.remainder[1].size = Vec3(8, 8, 4);
  parts.remainder[1].highPriority = true;
  const auto decodedParts = decodeReport(encode(parts));
  ASSERT_TRUE(decodedParts);
  ASSERT_EQ(decodedParts->remainder.size(), 2u);
  EXPECT_EQ(decodedParts->remainder[0].center, Vec3(1, 2, 3));
  EXPECT_EQ(decodedParts->remainder[0].size, Vec3(4, 5, 6));
  EXPECT_FALSE(decodedParts->remainder[0].highPriority);
  EXPECT_TRUE(decodedParts->remainder[1].highPriority);
  parts.remainder[1].size.z() = 0.0;  // not a box
  EXPECT_FALSE(decodeReport(encode(parts)));
  Reply shaped = makeReply(4, 9, {Vec3(3, 4, 5), 200.0});
  shaped.boxShape = parts.remainder[0];
  const auto decodedShape = decodeReply(encode(shaped));
  ASSERT_TRUE(decodedShape && decodedShape->boxShape);
  EXPECT_EQ(decodedShape->boxShape->center, Vec3(1, 2, 3));
  EXPECT_EQ(decodedShape->boxShape->size, Vec3(4, 5, 6));
  EXPECT_FALSE(decodeReply(encode(makeReply(4, 9, {Vec3(3, 4, 5), 200.0})))->boxShape);
  shaped.nextBox = 10;  // a part reserved next
  shaped.nextBoxShape = parts.remainder[1];
  shaped.nextBoxShape->size = Vec3(8, 8, 4);
  const auto decodedNext = decodeReply(encode(shaped));
  ASSERT_TRUE(decodedNext && decodedNext->nextBoxShape);
  EXPECT_EQ(decodedNext->nextBoxShape->center, Vec3(-1, 0, 2));
  EXPECT_TRUE(decodedNext->nextBoxShape->highPriority);
  EXPECT_FALSE(decodeReply(encode(makeReply(4, 9, {Vec3(3, 4, 5), 200.0})))->nextBoxShape);

  Orders orders;
  orders.sequence = 7;
  orders.tasks.push_back({9, Vec3(1, 1, 1), Vec3(0, -1, 0), Vec3(1, -3, 2), 1.5});
  orders.waitAt = Vec3(8, 8, 6);
  const auto decodedOrders = decodeOrders(encode(orders));
  ASSERT_TRUE(decodedOrders);
  EXPECT_EQ(decodedOrders->sequence, 7u);
  ASSERT_EQ(decodedOrders->tasks.size(), 1u);
  EXPECT_EQ(decodedOrders->tasks[0].viewPosition, Vec3(1, -3, 2));
  EXPECT_EQ(decodedOrders->tasks[0].viewYaw, 1.5);
  EXPECT_EQ(decodedOrders->waitAt, Vec3(8, 8, 6));
  orders.waitAt.reset();
  EXPECT_FALSE(decodeOrders(encode(orders))->waitAt);

  const auto status = decodeStatus(encode(Status{7, {1, 5, 9}, 4}));
  ASSERT_TRUE(status);
  EXPECT_EQ(status->lastOrders, 7u);
  EXPECT_EQ(status->inspected, (std::vector<uint32_t>{1, 5, 9}));
  EXPECT_EQ(status->listLeft, 4u);
}

TEST(SleiProtocol, MalformedMessagesAreRejected) {
  auto bytes = encode(makeReport(2, true, 1.0, 1));
  bytes.pop_back();  // truncated
  EXPECT_FALSE(decodeReport(bytes));
  bytes = encode(makeReport(2, true, 1.0, 1));
  bytes.push_back(0);  // trailing garbage
  EXPECT_FALSE(decodeReport(bytes));
  bytes = encode(makeReport(2, true, 1.0, 1));
  bytes[4] = 7;  // a flag that is neither 0 nor 1
  EXPECT_FALSE(decodeReport(bytes));
  EXPECT_FALSE(decodeReport(encode(makeReport(2, true, 1.0, 1, 1.5))));  // not a battery level
  EXPECT_FALSE(decodeReport(encode(makeReport(2, true, 1.0, 1, std::nan("")))));
  // A list length larger than the message could hold.
  std::vector<uint8_t> huge{0xff, 0xff, 0xff, 0x7f};
  EXPECT_FALSE(decodePlan(huge));
  EXPECT_FALSE(decodeStatus({1, 0, 0, 0, 0xff, 0xff, 0, 0}));
  EXPECT_FALSE(decodeOrders({}));
}

}  // namespace
}  // namespace coinspect::strategies::slei
