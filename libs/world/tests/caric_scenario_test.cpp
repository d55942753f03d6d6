#include "coinspect/world/caric_scenario.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "coinspect/core/error.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"

namespace coinspect::world {
namespace {

namespace fs = std::filesystem;
using coinspect::testing::caricMbsDir;
using coinspect::testing::messageOf;
using coinspect::testing::scratchDir;

// A scratch copy of the MBS folder made of symbolic links (the data is never copied), minus
// the files named in `skip`.
fs::path linkedMbs(const std::string& name, const std::vector<std::string>& skip) {
  const fs::path dir = scratchDir(name) / "caric-mbs";
  fs::create_directories(dir);
  for (const auto& entry : fs::directory_iterator(caricMbsDir())) {
    const std::string file = entry.path().filename().string();
    if (std::find(skip.begin(), skip.end(), file) == skip.end())
      fs::create_symlink(fs::absolute(entry.path()), dir / file);
  }
  return dir;
}

TEST(CaricScenario, ImportsMbs) {
  COINSPECT_REQUIRE_CARIC_MBS();
  const Scenario s = importCaricScenario(caricMbsDir());
  EXPECT_EQ(s.name, "caric-mbs");
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.triangleCount(), 67956u);
  EXPECT_EQ(s.boxes.size(), 4u);
  EXPECT_EQ(s.interestPoints.size(), 3973u);
  EXPECT_EQ(s.missionBudget, 600.0);
  EXPECT_EQ(s.groundZ, 0.0);
  ASSERT_EQ(s.fleet.size(), 6u);
  const std::pair<const char*, UnitRole> roles[6] = {
      {"gcs", UnitRole::GroundStation},   {"jurong", UnitRole::Explorer},
      {"raffles", UnitRole::Explorer},    {"sentosa", UnitRole::Photographer},
      {"changi", UnitRole::Photographer}, {"nanyang", UnitRole::Photographer}};
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(s.fleet[i].name, roles[i].first);
    EXPECT_EQ(s.fleet[i].role, roles[i].second) << roles[i].first;
  }
  EXPECT_EQ(s.fleet[0].startPosition, Vec3(-2, 8, 20));
  EXPECT_EQ(s.fleet[3].startPosition, Vec3(58, -13, 0.1));
  EXPECT_EQ(s.fleet[1].antennaOffset, 0.2);
  // The mesh spans the boxes: every box centre lies within the mesh bounds.
  const Aabb bounds = s.bounds();
  for (const auto& box : s.boxes)
    EXPECT_TRUE((box.center.array() >= bounds.min.array()).all() &&
                (box.center.array() <= bounds.max.array()).all())
        << box.name;
}

TEST(CaricScenario, MissingFolderOrFilesAreNamed) {
  EXPECT_MENTIONS(messageOf([] { importCaricScenario("no-such-folder"); }), "no-such-folder");
  COINSPECT_REQUIRE_CARIC_MBS();

  fs::path dir = linkedMbs("caric_scenario_no_yaml", {"box_description.yaml"});
  EXPECT_MENTIONS(messageOf([&] { importCaricScenario(dir); }), "box_description.yaml");

  dir = linkedMbs("caric_scenario_no_network", {"caric_ppcom_network_mbs.txt"});
  std::string message = messageOf([&] { importCaricScenario(dir); });
  EXPECT_MENTIONS(message, dir.string());
  EXPECT_MENTIONS(message, "caric_ppcom_network_");

  dir = linkedMbs("caric_scenario_no_points", {"mbs_interest_points.pcd"});
  EXPECT_MENTIONS(messageOf([&] { importCaricScenario(dir); }), "_interest_points.pcd");

  dir = linkedMbs("caric_scenario_no_mesh", {"mbs.stl"});
  EXPECT_MENTIONS(messageOf([&] { importCaricScenario(dir); }), ".stl");
}

TEST(CaricScenario, WithoutLaunchFileUnitsStandInARow) {
  COINSPECT_REQUIRE_CARIC_MBS();
  const fs::path dir = linkedMbs("caric_scenario_no_launch", {"run_mbs.launch"});
  const Scenario s = importCaricScenario(dir);
  ASSERT_EQ(s.fleet.size(), 6u);
  EXPECT_EQ(s.fleet[0].role, UnitRole::GroundStation);
  EXPECT_EQ(s.fleet[1].role, UnitRole::Explorer);  // by name: jurong
  EXPECT_EQ(s.fleet[5].role, UnitRole::Photographer);
  EXPECT_EQ(s.fleet[2].startPosition, Vec3(0, 4, 0.1));
}

}  // namespace
}  // namespace coinspect::world
