#include "coinspect/world/generators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "coinspect/core/error.h"
#include "coinspect/testing/paths.h"
#include "coinspect/world/ray_caster.h"
#include "coinspect/world/scenario_files.h"

namespace coinspect::world {
namespace {

// Specification of each generator (from the task statement and the reference scenarios), not
// from program output.
struct Spec {
  std::string family;
  std::optional<Vec3> extent;  // overall mesh extent, +-15 %
  size_t minBoxes;
  double budget;
  std::optional<double> desiredMmPerPx;
};

const std::map<std::string, Spec>& specs() {
  static const std::map<std::string, Spec> table{
      {"mbs", {"caric", Vec3(140, 65, 60), 4, 600.0, 2.0}},
      {"hangar", {"caric", std::nullopt, 1, 420.0, 1.0}},
      {"crane", {"caric", std::nullopt, 2, 600.0, 1.5}},
      {"burj-khalifa", {"caric", std::nullopt, 1, 0.0, 2.0}},
      {"burj-al-arab", {"caric", std::nullopt, 1, 0.0, 2.0}},
      {"slei-a", {"slei", Vec3(60, 50, 9), 8, 0.0, std::nullopt}},
      {"slei-b", {"slei", Vec3(18, 20, 15), 1, 0.0, std::nullopt}},
      {"slei-c", {"slei", Vec3(70, 60, 30), 1, 0.0, std::nullopt}},
      {"slei-d", {"slei", Vec3(120, 160, 20), 1, 0.0, std::nullopt}},
  };
  return table;
}

// Scenarios are generated once per process (the checks below are read-only).
const Scenario& scenario(const std::string& name) {
  static std::map<std::string, Scenario> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, generateScenario(name, 1)).first;
  return it->second;
}

double medianSpacing(const InterestPointSet& points) {
  std::vector<double> d;
  for (size_t i = 0; i < points.size(); ++i)
    d.push_back(points.nearestNeighbourDistance(i));
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

// Inside a closed, outward mesh every ray from p leaves through a back face first (its normal
// along the ray); outside, at least one of the six axis rays escapes or meets a front face.
bool insideSolid(const RayCaster& caster, const Vec3& p) {
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {-1.0, 1.0}) {
      Vec3 dir = Vec3::Zero();
      dir[axis] = sign;
      const auto hit = caster.closestHit(p, dir);
      if (!hit || hit->geometry >= 1000000 || hit->normal.dot(dir) <= 0.0) return false;
    }
  return true;
}

TEST(Generators, ListsEveryScenarioOnceInAFixedOrder) {
  const auto& list = scenarioGenerators();
  ASSERT_EQ(list.size(), specs().size());
  std::set<std::string> seen;
  for (const auto& info : list) {
    EXPECT_TRUE(seen.insert(info.name).second) << info.name;
    ASSERT_TRUE(specs().count(info.name)) << info.name;
    EXPECT_EQ(info.family, specs().at(info.name).family) << info.name;
    EXPECT_FALSE(info.description.empty());
    EXPECT_EQ(info.description.find('\n'), std::string::npos);
  }
  EXPECT_EQ(list.front().name, "mbs");
}

TEST(Generators, UnknownNameThrowsListingTheKnownOnes) {
  try {
    generateScenario("no-such-scenario", 1);
    FAIL() << "no exception";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no-such-scenario"), std::string::npos) << message;
    for (const auto& info : scenarioGenerators())
      EXPECT_NE(message.find(info.name), std::string::npos) << message;
  }
}

// `[mission] fleet`: another fleet on the same scene (the paper's scale test flies 5 + 10 + 60 in
// scene A). Stations are numbered when there are several; the scene and features stay.
TEST(Generators, ASleiSceneTakesAnotherFleetSize) {
  const Scenario own = generateScenario("slei-a", 3);
  EXPECT_EQ(generateScenario("slei-a", 3, SleiFleet{1, 2, 4}).contentHash(), own.contentHash());
  const Scenario big = generateScenario("slei-a", 3, SleiFleet{5, 10, 60});
  std::map<UnitRole, int> count;
  std::set<std::string> names;
  for (const UnitSpec& unit : big.fleet) {
    ++count[unit.role];
    EXPECT_TRUE(names.insert(unit.name).second) << unit.name;
  }
  EXPECT_EQ(count[UnitRole::GroundStation], 5);
  EXPECT_EQ(count[UnitRole::Explorer], 10);
  EXPECT_EQ(count[UnitRole::Photographer], 60);
  EXPECT_TRUE(names.count("gcs1") && names.count("gcs5") && !names.count("gcs"));
  EXPECT_TRUE(names.count("explorer10") && names.count("inspector60"));
  for (size_t i = 0; i < big.fleet.size(); ++i)
    for (size_t j = i + 1; j < big.fleet.size(); ++j)
      EXPECT_GT((big.fleet[i].startPosition - big.fleet[j].startPosition).norm(), 2.0)
          << big.fleet[i].name << " " << big.fleet[j].name;
  const RayCaster caster(big.meshes);
  for (const UnitSpec& unit : big.fleet)
    EXPECT_GT(caster.distanceToSurface(unit.startPosition, 5.0), 0.7) << unit.name;
  EXPECT_EQ(big.interestPoints.size(), own.interestPoints.size());
  EXPECT_EQ(big.meshes.size(), own.meshes.size());
}

TEST(Generators, AFleetSizeIsRefusedForCaricScenesAndOutOfRange) {
  const auto refused = [](const std::string& name, const SleiFleet& fleet,
                          const std::string& part) {
    try {
      generateScenario(name, 1, fleet);
      ADD_FAILURE() << name << ": no exception";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
  };
  refused("hangar", SleiFleet{}, "slei-* scenes only");
  refused("slei-a", SleiFleet{0, 2, 4}, "stations");
  refused("slei-a", SleiFleet{1, 0, 4}, "explorers");
  refused("slei-a", SleiFleet{1, 2, -1}, "inspectors");
  refused("slei-c", SleiFleet{21, 2, 4}, "stations");
  refused("slei-c", SleiFleet{1, 101, 4}, "explorers");
  refused("slei-c", SleiFleet{1, 2, 401}, "inspectors");
  EXPECT_EQ(sleiFleetProblem(SleiFleet{20, 100, 400}), "");
}

class EachGenerator : public ::testing::TestWithParam<std::string> {};

TEST_P(EachGenerator, PassesValidationWithModestMeshes) {
  const Scenario& s = scenario(GetParam());
  EXPECT_NO_THROW(validateScenario(s, GetParam()));
  EXPECT_EQ(s.name, GetParam());
  EXPECT_FALSE(s.description.empty());
  EXPECT_GE(s.triangleCount(), 1000u);
  EXPECT_LE(s.triangleCount(), 60000u);
  EXPECT_EQ(s.groundZ, 0.0);
  EXPECT_NEAR(s.bounds().min.z(), 0.0, 1e-6) << "structures stand on the ground";
  EXPECT_GE(s.boxes.size(), specs().at(GetParam()).minBoxes);
}

TEST_P(EachGenerator, MeshesAreClosedAndFaceOutwards) {
  for (const TriangleMesh& mesh : scenario(GetParam()).meshes) {
    // Closed with consistent winding: each directed edge is matched by its reverse.
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (const auto& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        ++edges[{t[static_cast<size_t>(k)], t[static_cast<size_t>((k + 1) % 3)]}];
        --edges[{t[static_cast<size_t>((k + 1) % 3)], t[static_cast<size_t>(k)]}];
      }
    for (const auto& [edge, balance] : edges)
      ASSERT_EQ(balance, 0) << mesh.name << " edge " << edge.first << "-" << edge.second;
    double volume = 0.0;
    const Vec3 origin = mesh.vertex(0);
    for (const auto& t : mesh.triangles)
      volume += (mesh.vertex(t[0]) - origin)
                    .dot((mesh.vertex(t[1]) - origin).cross(mesh.vertex(t[2]) - origin));
    EXPECT_GT(volume, 0.0) << mesh.name;
  }
}

TEST_P(EachGenerator, ExtentsMatchTheSpecification) {
  const std::string& name = GetParam();
  const Scenario& s = scenario(name);
  const Vec3 size = s.bounds().size();
  if (const auto& extent = specs().at(name).extent) {
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(size[k], (*extent)[k], 0.15 * (*extent)[k]) << name << " axis " << k;
  }
  if (name == "hangar") {
    const auto plane = std::find_if(s.meshes.begin(), s.meshes.end(),
                                    [](const TriangleMesh& m) { return m.name == "aircraft"; });
    ASSERT_NE(plane, s.meshes.end());
    const Vec3 aircraft = plane->bounds().size();
    EXPECT_NEAR(aircraft.y(), 40.0, 6.0) << "fuselage length";
    EXPECT_NEAR(aircraft.x(), 35.0, 5.25) << "wing span";
    EXPECT_LT(s.bounds().max.z(), 30.0);
  }
  if (name == "crane") {
    EXPECT_GE(size.z(), 40.0);
    EXPECT_LE(size.z(), 65.0);
    EXPECT_GE(s.meshes.size(), 2u);
  }
  if (name == "burj-khalifa") {
    EXPECT_GE(size.z(), 150.0);
    EXPECT_LE(size.z(), 200.0);
  }
  if (name == "burj-al-arab") {
    EXPECT_GE(size.z(), 100.0);
    EXPECT_LE(size.z(), 150.0);
  }
}

TEST_P(EachGenerator, InterestPointsLieOnTheMeshesInsideTheBoxes) {
  const Scenario& s = scenario(GetParam());
  ASSERT_FALSE(s.interestPoints.empty());
  const RayCaster caster(s.meshes);
  for (const InterestPoint& p : s.interestPoints.points()) {
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-9) << p.index;
    bool inBox = false;
    for (const OrientedBox& box : s.boxes)
      inBox = inBox || box.contains(p.position, 1e-6);
    EXPECT_TRUE(inBox) << "point " << p.index << " outside every box";
    EXPECT_LT(caster.distanceToSurface(p.position, 1.0), 2e-3) << "point " << p.index;
    EXPECT_GT(p.position.z(), 0.0) << p.index;
    // The facet normal faces free space: a ray out along it does not start inside a solid.
    const auto out = caster.closestHit(p.position + 0.02 * p.normal, p.normal);
    if (out) {
      EXPECT_LE(out->normal.dot(p.normal), 0.0) << "point " << p.index << " is buried";
    }
    if (::testing::Test::HasFailure()) break;
  }
}

TEST_P(EachGenerator, PointCountAndSpacingFollowTheFamily) {
  const std::string& name = GetParam();
  const Scenario& s = scenario(name);
  if (specs().at(name).family == "slei") {
    EXPECT_EQ(s.interestPoints.size(), 150u);
    // As the reference's feature server: none within 1 m of the ground.
    for (const InterestPoint& p : s.interestPoints.points())
      EXPECT_GT(p.position.z(), 1.0) << name << " point " << p.index;
  } else {
    const double median = medianSpacing(s.interestPoints);
    EXPECT_GE(median, 0.6) << name;
    EXPECT_LE(median, 1.0) << name;
  }
}

TEST_P(EachGenerator, FleetStartsOnOpenGroundWithItsBudget) {
  const std::string& name = GetParam();
  const Scenario& s = scenario(name);
  const Spec& spec = specs().at(name);
  std::map<std::string, UnitRole> roles;
  for (const UnitSpec& unit : s.fleet)
    roles[unit.name] = unit.role;
  if (spec.family == "caric") {
    const bool hangar = name == "hangar";
    EXPECT_EQ(s.fleet.size(), hangar ? 4u : 6u);
    EXPECT_EQ(roles["gcs"], UnitRole::GroundStation);
    EXPECT_EQ(roles["jurong"], UnitRole::Explorer);
    EXPECT_EQ(roles["sentosa"], UnitRole::Photographer);
    EXPECT_EQ(roles["changi"], UnitRole::Photographer);
    if (!hangar) {
      EXPECT_EQ(roles["raffles"], UnitRole::Explorer);
      EXPECT_EQ(roles["nanyang"], UnitRole::Photographer);
    }
  } else {
    std::map<UnitRole, int> count;
    for (const UnitSpec& unit : s.fleet)
      ++count[unit.role];
    // The paper's fleets: 2 + 4 in A (and B), 4 + 8 in C, 8 + 40 in D.
    const std::map<std::string, std::pair<int, int>> fleets{{"slei-c", {4, 8}},
                                                            {"slei-d", {8, 40}}};
    const auto fleet = fleets.count(name) ? fleets.at(name) : std::pair<int, int>(2, 4);
    EXPECT_EQ(count[UnitRole::GroundStation], 1);
    EXPECT_EQ(count[UnitRole::Explorer], fleet.first);
    EXPECT_EQ(count[UnitRole::Photographer], fleet.second);
  }
  // No two units start within two collision radii of each other.
  for (size_t i = 0; i < s.fleet.size(); ++i)
    for (size_t j = i + 1; j < s.fleet.size(); ++j)
      EXPECT_GT((s.fleet[i].startPosition - s.fleet[j].startPosition).norm(), 2.0)
          << s.fleet[i].name << " " << s.fleet[j].name;
  if (spec.budget > 0.0) {
    EXPECT_EQ(s.missionBudget, spec.budget);
  }
  EXPECT_GT(s.missionBudget, 0.0);

  const RayCaster caster(s.meshes);
  for (const UnitSpec& unit : s.fleet) {
    if (spec.desiredMmPerPx) {
      EXPECT_EQ(unit.camera.desiredMmPerPixel, *spec.desiredMmPerPx);
    }
    EXPECT_GT(unit.startPosition.z(), 0.0) << unit.name;
    if (unit.role != UnitRole::GroundStation) {
      EXPECT_NEAR(unit.startPosition.z(), 0.1, 1e-12);
    }
    EXPECT_FALSE(insideSolid(caster, unit.startPosition)) << unit.name;
    EXPECT_GT(caster.distanceToSurface(unit.startPosition, 5.0), 0.7) << unit.name;
  }
}

TEST_P(EachGenerator, SeedDecidesTheContent) {
  const std::string& name = GetParam();
  const uint64_t first = scenario(name).contentHash();
  EXPECT_EQ(generateScenario(name, 1).contentHash(), first);
  const Scenario other = generateScenario(name, 2);
  EXPECT_NE(other.contentHash(), first);
  // Same shape: the extent moves by a few percent at most.
  const Vec3 a = scenario(name).bounds().size(), b = other.bounds().size();
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(a[k], b[k], 0.1 * a[k]) << name << " axis " << k;
}

TEST_P(EachGenerator, SavedScenarioLoadsBackIdentical) {
  // What `coinspect scenario generate` writes must load (mesh files pass validation once their
  // vertices are welded by the loader) and be the same scenario.
  const Scenario& s = scenario(GetParam());
  const auto folder = coinspect::testing::scratchDir("generator-roundtrip-" + GetParam());
  saveScenario(s, folder);
  const Scenario loaded = loadScenario(folder / "scenario.ini");
  EXPECT_EQ(loaded.contentHash(), s.contentHash());
  EXPECT_EQ(loaded.interestPoints.size(), s.interestPoints.size());
  EXPECT_EQ(loaded.boxes.size(), s.boxes.size());
}

INSTANTIATE_TEST_SUITE_P(All, EachGenerator,
                         ::testing::Values("mbs", "hangar", "crane", "burj-khalifa", "burj-al-arab",
                                           "slei-a", "slei-b", "slei-c", "slei-d"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace coinspect::world
