#include "coinspect/strategies/coinspect/exploration_layers.h"

#include <gtest/gtest.h>

#include "test_boxes.h"

namespace coinspect::strategies::coinspect_strategy {
namespace {

using test::makeBox;

using agent::Vec3;

TEST(ExplorationLayers, TallBoxesGetTwoLayersShortOnesOneAndFreeRoofsOneAbove) {
  const auto tower = makeBox(Vec3(0, 0, 30), Vec3(20, 10, 50));  // z 5..55
  const auto shed = makeBox(Vec3(60, 0, 5), Vec3(10, 10, 10));   // z 0..10
  const std::vector<agent::BoxView> boxes = {tower, shed};
  const auto towerLayers = explorationLayers(tower, boxes, 3.0, 3.0);
  ASSERT_EQ(towerLayers.size(), 3u);
  EXPECT_DOUBLE_EQ(towerLayers[0], 5.0 + 0.3 * 50.0);
  EXPECT_DOUBLE_EQ(towerLayers[1], 5.0 + 0.75 * 50.0);
  EXPECT_DOUBLE_EQ(towerLayers[2], 58.0);
  // The shed starts on the ground: its layer is above the take-off height, then its roof.
  const auto shedLayers = explorationLayers(shed, boxes, 3.0, 3.0);
  ASSERT_EQ(shedLayers.size(), 2u);
  EXPECT_DOUBLE_EQ(shedLayers[0], 6.5);
  EXPECT_DOUBLE_EQ(shedLayers[1], 13.0);
}

TEST(ExplorationLayers, OnlyABoxStartingAtOrAboveARoofCoversIt) {
  const auto tower = makeBox(Vec3(0, 0, 30), Vec3(20, 10, 50));  // z 5..55
  const auto mast = makeBox(Vec3(40, 0, 20), Vec3(4, 4, 20));    // z 10..30
  // A deck box 2 m above both roofs covers them; its own roof gets a layer.
  const auto high = makeBox(Vec3(10, 0, 63), Vec3(80, 20, 12));  // z 57..69
  EXPECT_EQ(explorationLayers(tower, {tower, high, mast}, 3.0, 3.0).size(), 2u);
  EXPECT_EQ(explorationLayers(mast, {tower, high, mast}, 3.0, 3.0).size(), 1u);
  const auto deckLayers = explorationLayers(high, {tower, high, mast}, 3.0, 3.0);
  ASSERT_EQ(deckLayers.size(), 2u);
  EXPECT_DOUBLE_EQ(deckLayers[1], 72.0);
  // CARIC MBS: the sky deck's box starts below the towers' tops; the towers keep their layer
  // 3 m above the top (it maps the deck's sides, see the header).
  const auto deck = makeBox(Vec3(10, 0, 56), Vec3(80, 20, 12));  // z 50..62
  EXPECT_EQ(explorationLayers(tower, {tower, deck}, 3.0, 3.0).size(), 3u);
  // A box beside the tower, reaching higher but not over it, does not cover it either.
  const auto beside = makeBox(Vec3(30, 0, 70), Vec3(10, 10, 20));
  EXPECT_EQ(explorationLayers(tower, {tower, beside}, 3.0, 3.0).size(), 3u);
}

}  // namespace
}  // namespace coinspect::strategies::coinspect_strategy
