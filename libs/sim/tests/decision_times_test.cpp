#include <gtest/gtest.h>

#include "coinspect/sim/mission_summary.h"

namespace coinspect::sim {
namespace {

// Nearest-rank quantiles: p50 of 1..100 ms is 50 ms, p95 is 95 ms, whatever the sample order.
TEST(DecisionTimes, QuantilesAreNearestRank) {
  DecisionTimes times;
  EXPECT_EQ(times.quantile(0.95), 0.0);
  for (int i = 100; i >= 1; --i)
    times.samples.push_back(static_cast<float>(i) * 1e-3f);
  EXPECT_NEAR(times.quantile(0.5), 0.050, 1e-7);
  EXPECT_NEAR(times.quantile(0.95), 0.095, 1e-7);
  EXPECT_NEAR(times.quantile(1.0), 0.100, 1e-7);
  EXPECT_NEAR(times.quantile(0.0), 0.001, 1e-7);
}

}  // namespace
}  // namespace coinspect::sim
