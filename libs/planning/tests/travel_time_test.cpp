#include "coinspect/planning/travel_time.h"

#include <gtest/gtest.h>

namespace coinspect::planning {
namespace {

TEST(TravelTime, TrapezoidAndTriangleMeetAtTheRampDistance) {
  const TravelLimits limits;  // 2 m/s, 1 m/s^2: ramps cover 4 m in 4 s
  EXPECT_DOUBLE_EQ(travelTime(0.0, limits), 0.0);
  EXPECT_DOUBLE_EQ(travelTime(-1.0, limits), 0.0);
  EXPECT_DOUBLE_EQ(travelTime(4.0, limits), 4.0);
  EXPECT_DOUBLE_EQ(travelTime(10.0, limits), 7.0);  // 4 s of ramps + 6 m at 2 m/s
  EXPECT_DOUBLE_EQ(travelTime(1.0, limits), 2.0);   // 0.5 m up to 1 m/s in 1 s, 1 s down
  // Continuous at the switch.
  EXPECT_NEAR(travelTime(4.0 - 1e-9, limits), travelTime(4.0 + 1e-9, limits), 1e-6);
}

}  // namespace
}  // namespace coinspect::planning
