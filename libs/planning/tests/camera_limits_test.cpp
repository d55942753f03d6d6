#include "coinspect/planning/camera_limits.h"

#include <gtest/gtest.h>

namespace coinspect::planning {
namespace {

// The reference numbers of doc/scoring.md: 0.271875 mm/px per metre, 3.678 px per (m/s / m).
TEST(CameraLimits, MatchTheCaricRulesOfThumb) {
  const CameraOptics mbs;
  EXPECT_NEAR(fullResolutionDistance(mbs), 2.0 / 0.271875, 1e-9);  // 7.356 m
  EXPECT_NEAR(blurFreeSpeed(mbs, 5.0), 5.0 / 3.678, 1e-3);
  CameraOptics hangar;
  hangar.desiredMmPerPixel = 1.0;
  EXPECT_NEAR(fullResolutionDistance(hangar), 3.678, 1e-3);
}

}  // namespace
}  // namespace coinspect::planning
