#include <gtest/gtest.h>

#include <array>

#include "coinspect/strategies/runtime/inspection_tour.h"

namespace coinspect::strategies::runtime {
namespace {

PatchStop stopAt(double x, std::vector<uint64_t> patches) {
  PatchStop stop;
  stop.body = Vec3(x, 0, 5);
  stop.patches = std::move(patches);
  return stop;
}

InspectionTour<PatchStop> tourOf(const std::vector<double>& xs) {
  InspectionTour<PatchStop> tour(1.0, 2);
  uint64_t key = 0;
  for (const double x : xs)
    tour.stops().push_back(stopAt(x, {key++}));
  return tour;
}

TEST(InspectionTour, AReachedStopCompletesTheStopsPassedBeforeIt) {
  auto tour = tourOf({0, 10, 20, 30, 40});
  EXPECT_TRUE(tour.takeReached(Vec3(5, 0, 5)).empty());  // between stops
  const auto done = tour.takeReached(Vec3(20.5, 0, 5));  // the third one
  ASSERT_EQ(done.size(), 3u);
  EXPECT_EQ(done[0].patches.front(), 0u);
  EXPECT_EQ(done[2].patches.front(), 2u);
  ASSERT_EQ(tour.stops().size(), 2u);
  EXPECT_EQ(tour.stops().front().body.x(), 30.0);
}

TEST(InspectionTour, OnlyTheNextThreeStopsCount) {
  auto tour = tourOf({0, 10, 20, 30});
  EXPECT_TRUE(tour.takeReached(Vec3(30, 0, 5)).empty());  // fourth: passing by, not in order
  EXPECT_EQ(tour.stops().size(), 4u);
}

TEST(InspectionTour, KeysOfAbandonedStopsAreGivenUpAfterTheirAttempts) {
  InspectionTour<PatchStop> tour(1.0, 2);
  tour.stops() = {stopAt(0, {1, 2}), stopAt(10, {3})};
  EXPECT_TRUE(tour.abandon(patchKeys).empty());  // first failure of 1, 2, 3
  EXPECT_TRUE(tour.stops().empty());
  tour.stops() = {stopAt(0, {2}), stopAt(10, {4})};
  EXPECT_EQ(tour.abandon(patchKeys), std::vector<uint64_t>{2});  // 2 failed twice, 4 once
  // Keys no viewpoint was found for count the same attempts.
  EXPECT_EQ(tour.fail({4, 5}), std::vector<uint64_t>{4});
  EXPECT_EQ(tour.fail({5}), std::vector<uint64_t>{5});
  // A stop type of its own, one key per stop.
  struct Waypoint {
    Vec3 body;
    uint64_t id;
  };
  InspectionTour<Waypoint> waypoints(1.0, 1);
  waypoints.stops() = {{Vec3::Zero(), 7}};
  const auto id = [](const Waypoint& w) { return std::array<uint64_t, 1>{w.id}; };
  EXPECT_EQ(waypoints.abandon(id), std::vector<uint64_t>{7});
}

}  // namespace
}  // namespace coinspect::strategies::runtime
