#include "coinspect/world/ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/testing/paths.h"
#include "coinspect/world/mesh_io.h"
#include "test_meshes.h"

namespace coinspect::world {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Embree works in single precision: distances of ~10 m are exact to a few micrometres.
constexpr double kFloatTolerance = 1e-5;

RayCaster unitCube(std::optional<double> groundZ = std::nullopt) {
  return RayCaster({test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1))}, groundZ);
}

TEST(RayCaster, ClosestHitOnUnitCube) {
  const RayCaster caster = unitCube();
  EXPECT_EQ(caster.meshTriangleCount(), 12u);
  EXPECT_FALSE(caster.hasGround());

  auto hit = caster.closestHit(Vec3(-2, 0.5, 0.5), Vec3(1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 2.0, kFloatTolerance);
  EXPECT_EQ(hit->geometry, 0u);
  EXPECT_TRUE(hit->normal.isApprox(Vec3(-1, 0, 0), 1e-9)) << hit->normal.transpose();

  // The direction's length does not matter: distances are in metres.
  hit = caster.closestHit(Vec3(0.5, 0.25, 3), Vec3(0, 0, -5));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 2.0, kFloatTolerance);
  EXPECT_TRUE(hit->normal.isApprox(Vec3(0, 0, 1), 1e-9)) << hit->normal.transpose();

  // Oblique: from (-1, 0.25, 0.5) along (1, 0.25, 0) the face x = 0 is reached at (0, 0.5, 0.5),
  // sqrt(1 + 1/16) away.
  hit = caster.closestHit(Vec3(-1, 0.25, 0.5), Vec3(1, 0.25, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, std::sqrt(1.0625), kFloatTolerance);
  EXPECT_TRUE(hit->normal.isApprox(Vec3(-1, 0, 0), 1e-9));

  // From inside, the far face is hit (no back-face culling) and reports its own normal.
  hit = caster.closestHit(Vec3(0.5, 0.5, 0.5), Vec3(1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 0.5, kFloatTolerance);
  EXPECT_TRUE(hit->normal.isApprox(Vec3(1, 0, 0), 1e-9));
}

TEST(RayCaster, MissesParallelAndAwayRays) {
  const RayCaster caster = unitCube();
  EXPECT_FALSE(caster.closestHit(Vec3(-2, 2, 0.5), Vec3(1, 0, 0)));     // passes beside
  EXPECT_FALSE(caster.closestHit(Vec3(-2, 0.5, 0.5), Vec3(-1, 0, 0)));  // points away
  EXPECT_FALSE(caster.closestHit(Vec3(-2, 0.5, 2), Vec3(1, 0, 0)));     // parallel to the top
  EXPECT_FALSE(caster.closestHit(Vec3(-2, 0.5, 0.5), Vec3(0, 0, 0)));   // no direction
}

TEST(RayCaster, MaxRangeIsRespected) {
  const RayCaster caster = unitCube();
  EXPECT_FALSE(caster.closestHit(Vec3(-2, 0.5, 0.5), Vec3(1, 0, 0), 1.99));
  const auto hit = caster.closestHit(Vec3(-2, 0.5, 0.5), Vec3(3, 0, 0), 2.01);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 2.0, kFloatTolerance);
}

// A wall at x = 10 facing the origin; segments along +x from the origin.
class SegmentClearTest : public ::testing::Test {
 protected:
  RayCaster caster{{test::wallMesh(10.0, 5.0)}, std::nullopt};
  bool clear(double length, double tolerance) const {
    return caster.segmentClear(Vec3(0, 0, 0), Vec3(length, 0, 0), tolerance);
  }
};

TEST_F(SegmentClearTest, LinkToleranceBoundary) {
  // Clear iff the hit at 10 is >= length - 0.1, i.e. length <= 10.1.
  EXPECT_TRUE(clear(9.0, kLinkClearanceTolerance));
  EXPECT_TRUE(clear(10.0, kLinkClearanceTolerance));
  EXPECT_TRUE(clear(10.1 - 1e-4, kLinkClearanceTolerance));
  // Exactly at the boundary the hit is at length - tolerance: "first hit >= length - tolerance".
  EXPECT_TRUE(clear(10.1, kLinkClearanceTolerance));
  EXPECT_FALSE(clear(10.1 + 1e-4, kLinkClearanceTolerance));
  EXPECT_FALSE(clear(12.0, kLinkClearanceTolerance));
}

TEST_F(SegmentClearTest, PointVisibilityToleranceBoundary) {
  EXPECT_TRUE(clear(10.0, kPointVisibilityTolerance));  // a point on the wall is seen
  EXPECT_TRUE(clear(10.025 - 1e-4, kPointVisibilityTolerance));
  EXPECT_TRUE(clear(10.025, kPointVisibilityTolerance));
  EXPECT_FALSE(clear(10.025 + 1e-4, kPointVisibilityTolerance));
  EXPECT_FALSE(clear(10.5, kPointVisibilityTolerance));  // a point behind the wall is not
}

TEST_F(SegmentClearTest, FromTheOtherSide) {
  // From x = 20 towards -x the wall is 10 away: clear iff length <= 10.1.
  EXPECT_TRUE(caster.segmentClear(Vec3(20, 0, 0), Vec3(9.95, 0, 0), kLinkClearanceTolerance));
  EXPECT_FALSE(caster.segmentClear(Vec3(20, 0, 0), Vec3(9.85, 0, 0), kLinkClearanceTolerance));
  // Segments shorter than the tolerance are always clear, even through the wall.
  EXPECT_TRUE(caster.segmentClear(Vec3(9.96, 0, 0), Vec3(10.04, 0, 0), kLinkClearanceTolerance));
  EXPECT_TRUE(caster.segmentClear(Vec3(3, 3, 3), Vec3(3, 3, 3), kPointVisibilityTolerance));
  // Beside the wall (|y| > 5) nothing blocks.
  EXPECT_TRUE(caster.segmentClear(Vec3(0, 6, 0), Vec3(20, 6, 0), kLinkClearanceTolerance));
}

TEST(RayCaster, GroundPlane) {
  // A cube lifted to z in [2, 3]; its footprint centre (0.5, 0.5) centres the ground square.
  const TriangleMesh lifted = test::boxMesh(Vec3(0, 0, 2), Vec3(1, 1, 3));
  const RayCaster withGround({lifted}, 0.0, 100.0);
  EXPECT_TRUE(withGround.hasGround());
  EXPECT_EQ(withGround.groundZ(), 0.0);
  EXPECT_EQ(withGround.meshTriangleCount(), 12u);  // the ground is not a mesh triangle
  auto hit = withGround.closestHit(Vec3(5, 5, 10), Vec3(0, 0, -1));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 10.0, kFloatTolerance);
  EXPECT_EQ(hit->geometry, 1u);  // meshes.size()
  EXPECT_TRUE(hit->normal.isApprox(Vec3(0, 0, 1), 1e-9));
  // The cube is in front of the ground when looking down on it.
  hit = withGround.closestHit(Vec3(0.5, 0.5, 10), Vec3(0, 0, -1));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->geometry, 0u);
  EXPECT_NEAR(hit->distance, 7.0, kFloatTolerance);
  // The square spans centre +- 100: x = 100.4 is on it, x = 100.6 is not.
  EXPECT_TRUE(withGround.closestHit(Vec3(100.4, 0.5, 10), Vec3(0, 0, -1)));
  EXPECT_FALSE(withGround.closestHit(Vec3(100.6, 0.5, 10), Vec3(0, 0, -1)));
  // Seen from below too (a vehicle under the ground level still sees it).
  EXPECT_TRUE(withGround.closestHit(Vec3(5, 5, -1), Vec3(0, 0, 1)));
  EXPECT_FALSE(withGround.segmentClear(Vec3(5, 5, 1), Vec3(5, 5, -1), kLinkClearanceTolerance));

  const RayCaster lower({lifted}, -1.5, 100.0);
  hit = lower.closestHit(Vec3(5, 5, 10), Vec3(0, 0, -1));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 11.5, kFloatTolerance);

  const RayCaster noGround({lifted}, std::nullopt);
  EXPECT_FALSE(noGround.hasGround());
  EXPECT_FALSE(noGround.closestHit(Vec3(5, 5, 10), Vec3(0, 0, -1)));
  EXPECT_TRUE(noGround.segmentClear(Vec3(5, 5, 1), Vec3(5, 5, -1), kLinkClearanceTolerance));
}

TEST(RayCaster, DistanceToSurfaceOfABox) {
  const RayCaster caster = unitCube(0.0);
  EXPECT_NEAR(caster.distanceToSurface(Vec3(2, 0.5, 0.5)), 1.0, 1e-9);           // face
  EXPECT_NEAR(caster.distanceToSurface(Vec3(2, 2, 0.5)), std::sqrt(2.0), 1e-9);  // edge
  EXPECT_NEAR(caster.distanceToSurface(Vec3(2, 2, 2)), std::sqrt(3.0), 1e-9);    // corner
  EXPECT_NEAR(caster.distanceToSurface(Vec3(-0.5, 0.3, 1.25)), std::hypot(0.5, 0.25), 1e-9);
  EXPECT_NEAR(caster.distanceToSurface(Vec3(0.5, 0.5, 0.5)), 0.5, 1e-9);  // inside: centre
  EXPECT_NEAR(caster.distanceToSurface(Vec3(0.2, 0.6, 0.5)), 0.2, 1e-9);  // inside, near x = 0
  EXPECT_NEAR(caster.distanceToSurface(Vec3(1, 0.5, 0.5)), 0.0, 1e-9);    // on the surface
  // maxDistance: nothing within 0.5 of a point 1 away; found within 1.5.
  EXPECT_EQ(caster.distanceToSurface(Vec3(2, 0.5, 0.5), 0.5), kInf);
  EXPECT_NEAR(caster.distanceToSurface(Vec3(2, 0.5, 0.5), 1.5), 1.0, 1e-9);
  // The ground is not a surface to collide with here: far above it, far beside the cube.
  EXPECT_NEAR(caster.distanceToSurface(Vec3(10.5, 0.5, 0.1)), 9.5, 1e-6);

  const RayCaster empty({}, 0.0);
  EXPECT_EQ(empty.distanceToSurface(Vec3(0, 0, 1)), kInf);
}

TEST(RayCaster, BatchedQueriesEqualSingleOnes) {
  TriangleMesh cube = test::boxMesh(Vec3(-1, -1, 1), Vec3(1, 1, 3));
  const RayCaster caster({cube, test::wallMesh(6.0, 4.0)}, 0.0, 50.0);
  Rng rng(20240607);
  for (const size_t n : {0u, 1u, 15u, 16u, 17u, 100u, 1003u}) {
    std::vector<Vec3> origins(n), directions(n), targets(n);
    for (size_t i = 0; i < n; ++i) {
      origins[i] = Vec3(rng.uniform(-8, 8), rng.uniform(-8, 8), rng.uniform(0.2, 6));
      // Non-unit directions, some zero-length to check they are reported as misses.
      const Vec3 direction(rng.normal(), rng.normal(), rng.normal());
      directions[i] =
          i % 97 == 5 ? Vec3::Zero().eval() : (direction * rng.uniform(0.1, 3.0)).eval();
      targets[i] = Vec3(rng.uniform(-8, 8), rng.uniform(-8, 8), rng.uniform(-1, 6));
    }
    std::vector<double> distances;
    caster.closestHits(origins, directions, 9.0, distances);
    ASSERT_EQ(distances.size(), n);
    std::vector<uint8_t> clear;
    caster.segmentsClear(origins, targets, kLinkClearanceTolerance, clear);
    ASSERT_EQ(clear.size(), n);
    size_t hits = 0, blocked = 0;
    for (size_t i = 0; i < n; ++i) {
      const auto single = caster.closestHit(origins[i], directions[i], 9.0);
      if (single) {
        ++hits;
        EXPECT_NEAR(distances[i], single->distance, 1e-4) << "ray " << i << " of " << n;
      } else {
        EXPECT_EQ(distances[i], kInf) << "ray " << i << " of " << n;
      }
      const bool singleClear = caster.segmentClear(origins[i], targets[i], kLinkClearanceTolerance);
      blocked += singleClear ? 0 : 1;
      EXPECT_EQ(clear[i] != 0, singleClear) << "segment " << i << " of " << n;
    }
    // The scene must be hit by a good share of the rays, or the comparison proves nothing.
    if (n >= 100) {
      EXPECT_GT(hits, n / 5);
      EXPECT_GT(blocked, n / 10);
      EXPECT_LT(blocked, n);
    }
  }
}

TEST(RayCaster, ConstQueriesFromSeveralThreads) {
  const RayCaster caster = unitCube(0.0);
  std::vector<double> results(4, 0.0);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < results.size(); ++t)
    threads.emplace_back([&caster, &results, t] {
      double sum = 0.0;
      for (int i = 0; i < 2000; ++i) {
        const double y = 0.1 + 0.8 * (i % 100) / 100.0;
        sum += caster.closestHit(Vec3(-2, y, 0.5), Vec3(1, 0, 0))->distance;
        sum += caster.distanceToSurface(Vec3(-1, y, 0.5));
      }
      results[t] = sum;
    });
  for (auto& thread : threads)
    thread.join();
  // Each iteration adds 2 (ray) + 1 (distance to the face x = 0).
  for (const double r : results)
    EXPECT_NEAR(r, 2000 * 3.0, 1e-3);
}

TEST(RayCaster, MovedCasterStillWorks) {
  RayCaster a = unitCube();
  RayCaster b = std::move(a);
  ASSERT_TRUE(b.closestHit(Vec3(-2, 0.5, 0.5), Vec3(1, 0, 0)));
  RayCaster c({test::wallMesh(3.0, 1.0)}, std::nullopt);
  c = std::move(b);
  EXPECT_EQ(c.meshTriangleCount(), 12u);
}

TEST(RayCaster, RaysTowardTheMbsMeshHitIt) {
  COINSPECT_REQUIRE_CARIC_MBS();
  const TriangleMesh mbs = loadMesh(testing::caricMbsDir() / "mbs.stl");
  const RayCaster caster({mbs}, 0.0);
  EXPECT_EQ(caster.meshTriangleCount(), 67956u);
  const Aabb box = mbs.bounds();
  const Vec3 centre = 0.5 * (box.min + box.max);
  // Viewpoints on a circle 150 m around the structure at 30 m height, each aiming at the
  // centroid of a facet of the mesh: the first hit cannot lie beyond that point, and it lies on
  // the mesh.
  int tested = 0;
  for (size_t t = 0; t < mbs.triangleCount(); t += mbs.triangleCount() / 23) {
    const double angle = 2.0 * kPi * tested / 23.0;
    const Vec3 eye(centre.x() + 150.0 * std::cos(angle), centre.y() + 150.0 * std::sin(angle), 30);
    const auto& facet = mbs.triangles[t];
    const Vec3 target = (mbs.vertex(facet[0]) + mbs.vertex(facet[1]) + mbs.vertex(facet[2])) / 3;
    const auto hit = caster.closestHit(eye, target - eye);
    ASSERT_TRUE(hit) << "toward triangle " << t;
    EXPECT_LE(hit->distance, (target - eye).norm() + 1e-3);
    EXPECT_EQ(hit->geometry, 0u);
    EXPECT_NEAR(caster.distanceToSurface(target), 0.0, 1e-5);
    ++tested;
  }
  EXPECT_GE(tested, 23);
  // Straight down from above the bounding box beside the structure, the ground is hit.
  const auto down = caster.closestHit(Vec3(box.max.x() + 10, centre.y(), 100), Vec3(0, 0, -1));
  ASSERT_TRUE(down);
  EXPECT_EQ(down->geometry, 1u);
  EXPECT_NEAR(down->distance, 100.0, 1e-4);
}

}  // namespace
}  // namespace coinspect::world
