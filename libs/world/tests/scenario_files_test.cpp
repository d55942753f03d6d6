#include "coinspect/world/scenario_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "coinspect/core/error.h"
#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "coinspect/world/caric_formats.h"
#include "coinspect/world/caric_scenario.h"
#include "coinspect/world/mesh_io.h"

namespace coinspect::world {
namespace {

namespace fs = std::filesystem;
using coinspect::testing::caricMbsDir;
using coinspect::testing::messageOf;
using coinspect::testing::readFile;
using coinspect::testing::scratchDir;
using coinspect::testing::writeFile;

TriangleMesh cube() {
  TriangleMesh mesh;
  mesh.name = "cube";
  // Vertices deliberately not in first-use order, plus one unused: reading an STL back indexes
  // them differently, which the content hash must not see.
  mesh.vertices = {{1, 1, 1}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                   {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {5, 5, 5}};
  mesh.triangles = {{1, 3, 2}, {1, 4, 3}, {5, 6, 0}, {5, 0, 7}, {1, 2, 6}, {1, 6, 5},
                    {2, 3, 0}, {2, 0, 6}, {3, 4, 7}, {3, 7, 0}, {4, 1, 5}, {4, 5, 7}};
  return mesh;
}

Scenario handMade() {
  Scenario s;
  s.name = "hand-made";
  s.description = "two meshes, two boxes, three units";
  s.meshes.push_back(cube());
  TriangleMesh roof;
  roof.name = "roof part";
  roof.vertices = {{0.1f, 0.2f, 3.3f}, {10.7f, 0.2f, 3.3f}, {0.1f, 7.9f, 4.1f}};
  roof.triangles = {{0, 1, 2}};
  s.meshes.push_back(roof);

  OrientedBox tilted;
  tilted.name = "b one";
  tilted.center = Vec3(0.1, 0.2, 0.3);
  tilted.size = Vec3(1.0 / 3.0, 2.5, 7.0);
  tilted.rotation = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  s.boxes.push_back(tilted);
  OrientedBox plain;
  plain.name = "a";
  plain.center = Vec3(5, 5, 5);
  plain.size = Vec3(1, 1, 1);
  s.boxes.push_back(plain);

  std::vector<InterestPoint> points(3);
  points[0].position = Vec3(0.1, 0.2, 0.3);  // not representable in float
  points[1].position = Vec3(1, 0.5, 0.25);
  points[1].normal = Vec3(1, 2, 2) / 3.0;
  points[2].position = Vec3(-3, 4, 1e-3);
  points[2].normal = -Vec3::UnitY();
  s.interestPoints = InterestPointSet(points);

  UnitSpec gcs;
  gcs.name = "zeta";
  gcs.role = UnitRole::GroundStation;
  gcs.startPosition = Vec3(-2, 8, 20);
  UnitSpec explorer;
  explorer.name = "alpha";
  explorer.role = UnitRole::Explorer;
  explorer.startPosition = Vec3(0.1, 0.7, 0.1);
  explorer.startYaw = 0.3;
  explorer.antennaOffset = 0.2;
  UnitSpec photographer;
  photographer.name = "mid";
  photographer.startPosition = Vec3(1, 2, 0.1);
  photographer.startYaw = -M_PI / 2;
  photographer.camera.horizontalFov = 1.0;
  photographer.camera.verticalFov = 0.7;
  photographer.camera.positionInBody = Vec3(0.1, 0.05, -0.2);
  photographer.camera.exposureTime = 0.0005;
  photographer.camera.triggerInterval = 0.25;
  photographer.camera.focalLength = 0.012;
  photographer.camera.pixelSize = 3.45e-6;
  photographer.camera.desiredMmPerPixel = 1.5;
  photographer.camera.gimbalPitchMax = 1.2;
  photographer.camera.gimbalYawMax = 2.9;
  photographer.camera.gimbalRateMax = 0.5;
  s.fleet = {gcs, explorer, photographer};
  s.groundZ = -0.25;
  s.missionBudget = 420.0;
  return s;
}

void expectSameScenario(const Scenario& a, const Scenario& b) {
  EXPECT_EQ(a.contentHash(), b.contentHash());
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  EXPECT_EQ(a.triangleCount(), b.triangleCount());
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  for (size_t i = 0; i < a.boxes.size(); ++i) {
    EXPECT_EQ(a.boxes[i].name, b.boxes[i].name);
    EXPECT_EQ(a.boxes[i].center, b.boxes[i].center);  // written with round-trip precision
    EXPECT_EQ(a.boxes[i].size, b.boxes[i].size);
    EXPECT_EQ(a.boxes[i].rotation, b.boxes[i].rotation);
  }
  ASSERT_EQ(a.interestPoints.size(), b.interestPoints.size());
  for (size_t i = 0; i < a.interestPoints.size(); ++i) {
    // PCD stores float32.
    EXPECT_LT((a.interestPoints[i].position - b.interestPoints[i].position).norm(), 1e-6);
    EXPECT_LT((a.interestPoints[i].normal - b.interestPoints[i].normal).norm(), 1e-6);
  }
  ASSERT_EQ(a.fleet.size(), b.fleet.size());
  for (size_t i = 0; i < a.fleet.size(); ++i) {
    const UnitSpec& u = a.fleet[i];
    const UnitSpec& v = b.fleet[i];
    EXPECT_EQ(u.name, v.name);
    EXPECT_EQ(u.role, v.role);
    EXPECT_EQ(u.startPosition, v.startPosition);
    EXPECT_DOUBLE_EQ(u.startYaw, v.startYaw);
    EXPECT_EQ(u.antennaOffset, v.antennaOffset);
    EXPECT_DOUBLE_EQ(u.camera.horizontalFov, v.camera.horizontalFov);
    EXPECT_DOUBLE_EQ(u.camera.verticalFov, v.camera.verticalFov);
    EXPECT_EQ(u.camera.positionInBody, v.camera.positionInBody);
    EXPECT_EQ(u.camera.exposureTime, v.camera.exposureTime);
    EXPECT_EQ(u.camera.triggerInterval, v.camera.triggerInterval);
    EXPECT_EQ(u.camera.focalLength, v.camera.focalLength);
    EXPECT_EQ(u.camera.pixelSize, v.camera.pixelSize);
    EXPECT_EQ(u.camera.desiredMmPerPixel, v.camera.desiredMmPerPixel);
    EXPECT_DOUBLE_EQ(u.camera.gimbalPitchMax, v.camera.gimbalPitchMax);
    EXPECT_DOUBLE_EQ(u.camera.gimbalYawMax, v.camera.gimbalYawMax);
    EXPECT_DOUBLE_EQ(u.camera.gimbalRateMax, v.camera.gimbalRateMax);
  }
  EXPECT_EQ(a.groundZ, b.groundZ);
  EXPECT_EQ(a.missionBudget, b.missionBudget);
}

TEST(ScenarioFiles, HandMadeRoundTrip) {
  const auto dir = scratchDir("scenario_files_round_trip");
  const Scenario original = handMade();
  saveScenario(original, dir);
  EXPECT_TRUE(fs::exists(dir / "scenario.ini"));
  EXPECT_TRUE(fs::exists(dir / "interest_points.pcd"));
  const Scenario loaded = loadScenario(dir / "scenario.ini");
  expectSameScenario(original, loaded);
  EXPECT_EQ(loaded.meshes[1].name, "roof part");
  // The unused vertex is gone and the rest re-indexed; the triangles are the same.
  EXPECT_EQ(loaded.meshes[0].vertices.size(), 8u);
  for (size_t t = 0; t < 12; ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(loaded.meshes[0].vertex(loaded.meshes[0].triangles[t][k]),
                original.meshes[0].vertex(original.meshes[0].triangles[t][k]));
  // CARIC default angles come back as the same doubles, not merely close ones.
  EXPECT_EQ(loaded.fleet[0].camera.horizontalFov, CameraSpec().horizontalFov);
  EXPECT_EQ(loaded.fleet[0].camera.gimbalRateMax, CameraSpec().gimbalRateMax);
  EXPECT_NE(readFile(dir / "scenario.ini").find("hfov = 80\n"), std::string::npos);

  // After one round trip the files are stable: saving what was loaded again writes the same INI.
  const auto again = scratchDir("scenario_files_round_trip_again");
  saveScenario(loaded, again);
  const auto third = scratchDir("scenario_files_round_trip_third");
  saveScenario(loadScenario(again / "scenario.ini"), third);
  EXPECT_EQ(readFile(again / "scenario.ini"), readFile(third / "scenario.ini"));
  EXPECT_EQ(loadScenario(third / "scenario.ini").contentHash(), original.contentHash());
}

TEST(ScenarioFiles, CaricMbsRoundTrip) {
  COINSPECT_REQUIRE_CARIC_MBS();
  const Scenario original = importCaricScenario(caricMbsDir());
  const auto dir = scratchDir("scenario_files_mbs");
  saveScenario(original, dir);
  const Scenario loaded = loadScenario(dir / "scenario.ini");
  expectSameScenario(original, loaded);
  EXPECT_EQ(loaded.triangleCount(), 67956u);
  EXPECT_EQ(loaded.interestPoints.size(), 3973u);
}

TEST(ScenarioFiles, ContentHashCoversContentOnly) {
  const Scenario base = handMade();
  const uint64_t hash = base.contentHash();
  EXPECT_EQ(Scenario(base).contentHash(), hash);

  Scenario renamed = handMade();
  renamed.name = "other";
  renamed.description = "";
  renamed.meshes[0].name = "x";
  renamed.boxes[0].name = "y";
  EXPECT_EQ(renamed.contentHash(), hash);

  // The same triangles over a permuted vertex list.
  Scenario reindexed = handMade();
  TriangleMesh& mesh = reindexed.meshes[0];
  std::reverse(mesh.vertices.begin(), mesh.vertices.end());
  const auto last = static_cast<uint32_t>(mesh.vertices.size() - 1);
  for (auto& t : mesh.triangles)
    for (auto& v : t)
      v = last - v;
  EXPECT_EQ(reindexed.contentHash(), hash);

  Scenario moved = handMade();
  auto points = moved.interestPoints.points();
  points[1].position.x() += 1e-3;
  moved.interestPoints = InterestPointSet(points);
  EXPECT_NE(moved.contentHash(), hash);

  Scenario unitRenamed = handMade();
  unitRenamed.fleet[1].name = "beta";
  EXPECT_NE(unitRenamed.contentHash(), hash);

  Scenario budget = handMade();
  budget.missionBudget = 600.0;
  EXPECT_NE(budget.contentHash(), hash);

  Scenario turned = handMade();
  std::swap(turned.meshes[0].triangles[0][0], turned.meshes[0].triangles[0][1]);
  EXPECT_NE(turned.contentHash(), hash);
}

// A hand-written file: sections out of alphabetical order, degrees, defaults.
const char* kIni = R"(# test scenario
[unit.zeta]
role = gcs
start = 1 2 3

[scenario]
name = demo
description = written by hand
ground_z = -1.5
mission_budget = 300
interest_points = pts.pcd

[box.b2]
center = 0 0 5
size = 2 2 2
yaw = 90

[box.a1]
center = 1, 1, 1
size = 1 2 3

[mesh.ground]
file = tri.stl
scale = 2
translation = 0 0 1
yaw = 90

[unit.alpha]
role = explorer
start = 0 0 0.1
yaw = 180
hfov = 90
)";

fs::path handWritten(const std::string& name, const std::string& from = "",
                     const std::string& to = "") {
  const auto dir = scratchDir(name);
  TriangleMesh tri;
  tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.triangles = {{0, 1, 2}};
  writeStl(tri, dir / "tri.stl");
  std::vector<InterestPoint> points(2);
  points[1].position = Vec3(1, 2, 3);
  writeCaricInterestPoints(points, dir / "pts.pcd");
  std::string text = kIni;
  if (!from.empty()) text.replace(text.find(from), from.size(), to);
  writeFile(dir / "scenario.ini", text);
  return dir / "scenario.ini";
}

TEST(ScenarioFiles, HandWrittenFile) {
  const Scenario s = loadScenario(handWritten("scenario_files_hand"));
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.description, "written by hand");
  EXPECT_EQ(s.groundZ, -1.5);
  EXPECT_EQ(s.missionBudget, 300.0);
  EXPECT_EQ(s.interestPoints.size(), 2u);
  // File order, not MRPT's alphabetical order.
  ASSERT_EQ(s.fleet.size(), 2u);
  EXPECT_EQ(s.fleet[0].name, "zeta");
  EXPECT_EQ(s.fleet[1].name, "alpha");
  ASSERT_EQ(s.boxes.size(), 2u);
  EXPECT_EQ(s.boxes[0].name, "b2");
  EXPECT_EQ(s.boxes[1].name, "a1");
  EXPECT_TRUE(s.boxes[0].rotation.col(0).isApprox(Vec3(0, 1, 0)));
  EXPECT_EQ(s.boxes[1].center, Vec3(1, 1, 1));
  EXPECT_EQ(s.boxes[1].rotation, Eigen::Matrix3d::Identity());

  EXPECT_EQ(s.fleet[0].role, UnitRole::GroundStation);
  EXPECT_EQ(s.fleet[0].antennaOffset, 0.1);
  EXPECT_EQ(s.fleet[0].startYaw, 0.0);
  EXPECT_EQ(s.fleet[1].role, UnitRole::Explorer);
  EXPECT_EQ(s.fleet[1].antennaOffset, 0.2);  // explorers' default
  EXPECT_DOUBLE_EQ(s.fleet[1].startYaw, M_PI);
  EXPECT_DOUBLE_EQ(s.fleet[1].camera.horizontalFov, M_PI / 2);
  EXPECT_DOUBLE_EQ(s.fleet[1].camera.verticalFov, M_PI / 3);  // default 60 deg
  EXPECT_EQ(s.fleet[1].camera.pixelSize, 4.35e-6);

  // Triangle (0,0,0) (1,0,0) (0,1,0), scaled by 2, turned 90 deg about z, lifted by 1.
  ASSERT_EQ(s.meshes.size(), 1u);
  const TriangleMesh& m = s.meshes[0];
  EXPECT_EQ(m.name, "ground");
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_TRUE(m.vertex(m.triangles[0][0]).isApprox(Vec3(0, 0, 1), 1e-6));
  EXPECT_TRUE(m.vertex(m.triangles[0][1]).isApprox(Vec3(0, 2, 1), 1e-6));
  EXPECT_TRUE(m.vertex(m.triangles[0][2]).isApprox(Vec3(-2, 0, 1), 1e-6));
}

TEST(ScenarioFiles, BadFilesNameFileAndKey) {
  std::string message = messageOf([] {
    loadScenario(handWritten("scenario_files_unknown", "hfov = 90", "hfov = 90\ncolour = red"));
  });
  EXPECT_MENTIONS(message, "scenario.ini");
  EXPECT_MENTIONS(message, "[unit.alpha] colour");

  message = messageOf([] {
    loadScenario(handWritten("scenario_files_malformed", "start = 0 0 0.1", "start = 0 zero 0.1"));
  });
  EXPECT_MENTIONS(message, "scenario.ini");
  EXPECT_MENTIONS(message, "[unit.alpha] start");
  EXPECT_MENTIONS(message, "zero");

  message = messageOf(
      [] { loadScenario(handWritten("scenario_files_nan", "start = 1 2 3", "start = nan 2 3")); });
  EXPECT_MENTIONS(message, "[unit.zeta] start");

  message = messageOf([] {
    loadScenario(handWritten("scenario_files_no_mesh", "file = tri.stl", "file = nothere.stl"));
  });
  EXPECT_MENTIONS(message, "scenario.ini");
  EXPECT_MENTIONS(message, "[mesh.ground] file");
  EXPECT_MENTIONS(message, "nothere.stl");

  message = messageOf(
      [] { loadScenario(handWritten("scenario_files_duplicate", "[unit.alpha]", "[unit.Zeta]")); });
  EXPECT_MENTIONS(message, "line 28");
  EXPECT_MENTIONS(message, "section [unit.Zeta] given twice");
  EXPECT_MENTIONS(message, "line 2");

  message = messageOf(
      [] { loadScenario(handWritten("scenario_files_section", "[box.a1]", "[boxes.a1]")); });
  EXPECT_MENTIONS(message, "unknown section [boxes.a1]");

  message = messageOf([] {
    loadScenario(handWritten("scenario_files_both", "yaw = 90\n\n[box.a1]",
                             "yaw = 90\nrotation = 1 0 0 0 1 0 0 0 1\n\n[box.a1]"));
  });
  EXPECT_MENTIONS(message, "[box.b2]");

  message = messageOf(
      [] { loadScenario(handWritten("scenario_files_size", "size = 1 2 3", "size = 1 -2 3")); });
  EXPECT_MENTIONS(message, "a1");
  EXPECT_MENTIONS(message, "positive");

  message = messageOf(
      [] { loadScenario(handWritten("scenario_files_role", "role = gcs", "role = boss")); });
  EXPECT_MENTIONS(message, "[unit.zeta]");
  EXPECT_MENTIONS(message, "boss");

  message = messageOf([] { loadScenario("no-such-dir/scenario.ini"); });
  EXPECT_MENTIONS(message, "no-such-dir");
}

TEST(ScenarioFiles, DuplicateUnitNamesAreRejected) {
  Scenario s = handMade();
  s.fleet[2].name = "Alpha";  // INI sections compare case-insensitively
  const std::string message = messageOf([&] { validateFleet(s.fleet, "fleet"); });
  EXPECT_MENTIONS(message, "Alpha");
  EXPECT_MENTIONS(message, "duplicate");
  EXPECT_THROW(saveScenario(s, scratchDir("scenario_files_dup_units")), InputError);
}

TEST(ScenarioFiles, InterestPointsCsv) {
  const auto dir = scratchDir("scenario_files_csv");
  exportInterestPointsCsv(handMade().interestPoints, dir / "p.csv");
  std::istringstream lines(readFile(dir / "p.csv"));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "x,y,z,nx,ny,nz,idx");
  std::getline(lines, line);
  EXPECT_EQ(line, "0.1,0.2,0.3,0,0,1,0");
  std::getline(lines, line);
  std::getline(lines, line);
  EXPECT_EQ(line, "-3,4,0.001,0,-1,0,2");
  EXPECT_FALSE(std::getline(lines, line));
}

}  // namespace
}  // namespace coinspect::world
