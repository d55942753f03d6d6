// Link models: the reference's 36-antenna rule, the range rule, and the batched computation.
#include <gtest/gtest.h>

#include "coinspect/comms/link_model.h"
#include "coinspect/core/random.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "coinspect/world/mesh_io.h"
#include "coinspect/world/ray_caster.h"
#include "comms_scenes.h"

namespace coinspect::comms {
namespace {

using test::endpoint;
using world::Vec3;

LinkMatrix caricLinks(const world::RayCaster& caster, const std::vector<LinkEndpoint>& units) {
  LinkMatrix links;
  CaricLinkModel().update(caster, units, links);
  return links;
}

TEST(AntennaPositions, SixAlongWorldAxesInReferenceOrder) {
  const auto a = antennaPositions(endpoint(Vec3(1, 2, 3), 0.2), true, 0.0);
  EXPECT_TRUE(a[0].isApprox(Vec3(1.2, 2, 3)));
  EXPECT_TRUE(a[1].isApprox(Vec3(0.8, 2, 3)));
  EXPECT_TRUE(a[2].isApprox(Vec3(1, 2.2, 3)));
  EXPECT_TRUE(a[3].isApprox(Vec3(1, 1.8, 3)));
  EXPECT_TRUE(a[4].isApprox(Vec3(1, 2, 3.2)));
  EXPECT_TRUE(a[5].isApprox(Vec3(1, 2, 2.8)));
}

TEST(AntennaPositions, MinusZClampedToTenCentimetresAboveGround) {
  // A unit resting on the ground, centre 5 cm up: its -z antenna would be 15 cm underground.
  const LinkEndpoint grounded = endpoint(Vec3(0, 0, 0.05), 0.2);
  EXPECT_DOUBLE_EQ(antennaPositions(grounded, true, 0.0)[5].z(), 0.1);
  // Only the -z antenna is clamped; the +-x and +-y ones stay at the centre's height.
  EXPECT_DOUBLE_EQ(antennaPositions(grounded, true, 0.0)[0].z(), 0.05);
  // The clamp follows the ground height, and there is none without a ground.
  EXPECT_DOUBLE_EQ(antennaPositions(grounded, true, -1.0)[5].z(), -0.15);
  EXPECT_DOUBLE_EQ(antennaPositions(endpoint(Vec3(0, 0, 2.0), 0.2), true, 2.0)[5].z(), 2.1);
  EXPECT_DOUBLE_EQ(antennaPositions(grounded, false, 0.0)[5].z(), -0.15);
}

TEST(CaricLinkModel, ClampedAntennaAloneKeepsASunkenUnitLinked) {
  // Centre 0.5 m below the ground, offset 0.2: five antennas are underground (z <= -0.3) and
  // every segment from them hits the ground; the clamped -z antenna at z = 0.1 sees the peer.
  const world::RayCaster caster({}, 0.0);
  const std::vector<LinkEndpoint> units{endpoint(Vec3(0, 0, -0.5)), endpoint(Vec3(10, 0, 5))};
  EXPECT_TRUE(caricLinks(caster, units).linked(0, 1));
  // The same pair under the range model (centre to centre) is blocked by the ground.
  LinkMatrix range;
  RangeLinkModel(100.0).update(caster, units, range);
  EXPECT_FALSE(range.linked(0, 1));
}

TEST(CaricLinkModel, WallBlocksAndGoingAroundItRestores) {
  const world::RayCaster caster({test::wallAcrossX(3.0)}, 0.0);
  // Both at 1.5 m, 5 m either side of a 3 m wall: every antenna (z 1.3..1.7, |y| <= 0.2) is
  // behind it, so all 36 segments cross the wall.
  std::vector<LinkEndpoint> units{endpoint(Vec3(-5, 0, 1.5)), endpoint(Vec3(5, 0, 1.5))};
  EXPECT_FALSE(caricLinks(caster, units).linked(0, 1));
  // Beyond the wall's end: moved to (1, 7), every segment crosses x = -0.1 at
  // y >= -0.2 + 7 * 4.9 / 6 = 5.52 > 5, past the end of the wall.
  units[1].position = Vec3(1, 7, 1.5);
  EXPECT_TRUE(caricLinks(caster, units).linked(0, 1));
  // Back behind it.
  units[1].position = Vec3(5, 0, 1.5);
  EXPECT_FALSE(caricLinks(caster, units).linked(0, 1));
}

TEST(CaricLinkModel, AntennasOverALowWallLinkWhileTheCentresAreBlocked) {
  // Wall top at 1.6 m, centres at 1.5 m: the centre segment hits the wall, but the +z antennas
  // at 1.7 m see each other over it, which is enough in the reference.
  const world::RayCaster caster({test::wallAcrossX(1.6)}, 0.0);
  const std::vector<LinkEndpoint> units{endpoint(Vec3(-5, 0, 1.5)), endpoint(Vec3(5, 0, 1.5))};
  EXPECT_FALSE(caster.segmentClear(units[0].position, units[1].position, 0.1));
  EXPECT_TRUE(caricLinks(caster, units).linked(0, 1));
  // With 5 cm offsets every antenna is at or below 1.55 m: blocked.
  const std::vector<LinkEndpoint> small{endpoint(Vec3(-5, 0, 1.5), 0.05),
                                        endpoint(Vec3(5, 0, 1.5), 0.05)};
  EXPECT_FALSE(caricLinks(caster, small).linked(0, 1));
}

TEST(CaricLinkModel, NoRangeLimit) {
  const world::RayCaster caster({}, 0.0);
  const std::vector<LinkEndpoint> units{endpoint(Vec3(0, 0, 10)), endpoint(Vec3(1500, 0, 10))};
  EXPECT_TRUE(caricLinks(caster, units).linked(0, 1));
}

TEST(CaricLinkModel, DeadUnitsHaveNoLinks) {
  const world::RayCaster caster({}, 0.0);
  const std::vector<LinkEndpoint> units{
      endpoint(Vec3(0, 0, 5)), endpoint(Vec3(5, 0, 5), 0.2, false), endpoint(Vec3(0, 5, 5))};
  const LinkMatrix links = caricLinks(caster, units);
  EXPECT_TRUE(links.linked(0, 2));
  EXPECT_FALSE(links.linked(0, 1));
  EXPECT_FALSE(links.linked(1, 2));
}

TEST(RangeLinkModel, LinkedWithinRangeOnly) {
  const world::RayCaster caster({}, 0.0);
  RangeLinkModel model(5.0);
  LinkMatrix links;
  model.update(caster, {endpoint(Vec3(0, 0, 2)), endpoint(Vec3(4.9, 0, 2))}, links);
  EXPECT_TRUE(links.linked(0, 1));
  model.update(caster, {endpoint(Vec3(0, 0, 2)), endpoint(Vec3(5.1, 0, 2))}, links);
  EXPECT_FALSE(links.linked(0, 1));
}

TEST(RangeLinkModel, NeedsLineOfSightBetweenCentres) {
  // 4.9 m apart across a low wall: the caric model links them over it (antennas), range does not.
  const world::RayCaster caster({test::wallAcrossX(1.6)}, 0.0);
  const std::vector<LinkEndpoint> units{endpoint(Vec3(-2.45, 0, 1.5)),
                                        endpoint(Vec3(2.45, 0, 1.5))};
  LinkMatrix links;
  RangeLinkModel(5.0).update(caster, units, links);
  EXPECT_FALSE(links.linked(0, 1));
  EXPECT_TRUE(caricLinks(caster, units).linked(0, 1));
}

TEST(RangeLinkModel, HitWithinTenCentimetresOfTheFarEndCountsAsClear) {
  // A panel at x = 0; from x = -3 the hit is at 3.0 m. At x = 0.05 the segment is 3.05 m long
  // and 3.0 >= 3.05 - 0.1: clear. At x = 0.15 it is 3.15 m long and 3.0 < 3.05: blocked.
  const world::RayCaster caster({test::thinPanelAtXZero()}, 0.0);
  RangeLinkModel model(5.0);
  LinkMatrix links;
  model.update(caster, {endpoint(Vec3(-3, 0, 1)), endpoint(Vec3(0.05, 0, 1))}, links);
  EXPECT_TRUE(links.linked(0, 1));
  model.update(caster, {endpoint(Vec3(-3, 0, 1)), endpoint(Vec3(0.15, 0, 1))}, links);
  EXPECT_FALSE(links.linked(0, 1));
}

TEST(MakeLinkModel, ByNameAndRejectsBadInput) {
  EXPECT_EQ(makeLinkModel("caric", 0.0)->name(), "caric");
  const auto range = makeLinkModel("range", 5.0);
  EXPECT_EQ(range->name(), "range");
  EXPECT_DOUBLE_EQ(dynamic_cast<const RangeLinkModel&>(*range).range(), 5.0);
  const std::string unknown = testing::messageOf([] { makeLinkModel("radio", 5.0, "a.ini"); });
  EXPECT_MENTIONS(unknown, "a.ini");
  EXPECT_MENTIONS(unknown, "radio");
  EXPECT_MENTIONS(testing::messageOf([] { makeLinkModel("range", -1.0); }), "range");
  EXPECT_THROW(makeLinkModel("range", std::nan("")), InputError);
}

// 75 units around and between a few buildings: the staged batches give exactly the per-pair
// answer, the matrix is symmetric, and a second update gives the same matrix.
TEST(CaricLinkModel, BatchedEqualsNaivePerPairLoopFor75Units) {
  const world::RayCaster caster({test::boxMesh(Vec3(-10, -10, 0), Vec3(10, 10, 30), "tower"),
                                 test::boxMesh(Vec3(15, -30, 0), Vec3(18, 30, 6), "long wall"),
                                 test::boxMesh(Vec3(-40, 20, 0), Vec3(-20, 24, 12), "block")},
                                0.0);
  Rng rng(20240601);
  std::vector<LinkEndpoint> units;
  for (int k = 0; k < 75; ++k) {
    Vec3 p(rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(0.05, 35));
    // Keep out of the buildings (a unit inside one is not a situation the sim produces).
    if (p.x() > -11 && p.x() < 11 && p.y() > -11 && p.y() < 11) p.x() += 25;
    units.push_back(endpoint(p, k % 3 == 0 ? 0.2 : 0.1, k % 17 != 5));
  }
  const LinkMatrix batched = caricLinks(caster, units);
  const LinkMatrix naive = test::naiveCaricTopology(caster, units);
  EXPECT_EQ(batched, naive);
  // Both linked and blocked pairs occur, so the comparison means something.
  EXPECT_GT(batched.linkCount(), 100u);
  EXPECT_LT(batched.linkCount(), 75u * 74u / 2u - 100u);
  for (uint32_t i = 0; i < 75; ++i)
    for (uint32_t j = 0; j < 75; ++j)
      EXPECT_EQ(batched.linked(i, j), batched.linked(j, i));
  EXPECT_EQ(caricLinks(caster, units), batched);
}

// The same on the real CARIC MBS structure, 75 units in and around it.
TEST(CaricLinkModel, BatchedEqualsNaivePerPairLoopOnMbs) {
  COINSPECT_REQUIRE_CARIC_MBS();
  const world::TriangleMesh mbs = world::loadMesh(testing::caricMbsDir() / "mbs.stl");
  const world::RayCaster caster({mbs}, 0.0);
  const world::Aabb box = mbs.bounds();
  Rng rng(75);
  std::vector<LinkEndpoint> units;
  while (units.size() < 75) {
    const Vec3 p(rng.uniform(box.min.x() - 10, box.max.x() + 10),
                 rng.uniform(box.min.y() - 10, box.max.y() + 10),
                 rng.uniform(0.05, box.max.z() + 5));
    if (caster.distanceToSurface(p, 1.0) > 1.0)
      units.push_back(endpoint(p, 0.1 + 0.1 * (p.z() > 10)));
  }
  const LinkMatrix batched = caricLinks(caster, units);
  EXPECT_EQ(batched, test::naiveCaricTopology(caster, units));
  EXPECT_GT(batched.linkCount(), 0u);
  EXPECT_LT(batched.linkCount(), 75u * 74u / 2u);
}

}  // namespace
}  // namespace coinspect::comms
