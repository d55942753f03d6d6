#include "coinspect/strategies/coinspect/patch_choice.h"

#include <gtest/gtest.h>

#include <set>

namespace coinspect::strategies::coinspect_strategy {
namespace {

planning::InspectionPatch patchAt(uint64_t key, double x) {
  planning::InspectionPatch patch;
  patch.key = key;
  patch.centre = agent::Vec3(x, 0, 5);
  return patch;
}

std::vector<uint64_t> keysOf(const std::vector<planning::InspectionPatch>& patches) {
  std::vector<uint64_t> keys;
  for (const auto& p : patches)
    keys.push_back(p.key);
  return keys;
}

// Region 0 has patches 1-3 (x = 10..30), region 1 has patches 4-6 (x = 40..60).
const std::vector<planning::InspectionPatch> kPatches = {
    patchAt(1, 10), patchAt(2, 20), patchAt(3, 30), patchAt(4, 40), patchAt(5, 50), patchAt(6, 60)};
const std::vector<uint32_t> kOwners = {0, 0, 0, 1, 1, 1};

TEST(PatchChoice, OwnRegionFirstWithoutWhatIsDone) {
  const std::set<uint64_t> done = {5};
  const auto chosen = choosePatches(
      kPatches, kOwners, 1, [&](uint64_t k) { return done.count(k) != 0; }, agent::Vec3(0, 0, 5),
      10);
  EXPECT_EQ(keysOf(chosen), (std::vector<uint64_t>{4, 6}));
}

TEST(PatchChoice, AFinishedRobotTakesOverTheRestNearestFirst) {
  // Region 1 is done (say its robot failed after its own was finished, or this robot finished
  // it): the robot at x = 35 helps with region 0, nearest first, capped at two.
  const std::set<uint64_t> done = {4, 5, 6};
  const auto chosen = choosePatches(
      kPatches, kOwners, 1, [&](uint64_t k) { return done.count(k) != 0; }, agent::Vec3(35, 0, 5),
      2);
  EXPECT_EQ(keysOf(chosen), (std::vector<uint64_t>{3, 2}));
  // Everything done: nothing to plan.
  EXPECT_TRUE(choosePatches(
                  kPatches, kOwners, 0, [](uint64_t) { return true; }, agent::Vec3::Zero(), 9)
                  .empty());
}

}  // namespace
}  // namespace coinspect::strategies::coinspect_strategy
