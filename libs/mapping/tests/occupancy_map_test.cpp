#include "coinspect/mapping/occupancy_map.h"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>

namespace coinspect::mapping {
namespace {

using Points = std::vector<Eigen::Vector3f>;

// Points of the plane x = `x` over [-half, half]^2 in y and z (offset by `centre`), every `step`.
Points wallAt(double x, const Vec3& centre, double half, double step) {
  Points points;
  for (double y = -half; y <= half + 1e-9; y += step)
    for (double z = -half; z <= half + 1e-9; z += step)
      points.emplace_back(static_cast<float>(x), static_cast<float>(centre.y() + y),
                          static_cast<float>(centre.z() + z));
  return points;
}

// A floor (z = 0.25) seen from `origin`: points on a polar pattern around it.
Points floorAround(const Vec3& origin, double radius) {
  Points points;
  for (double r = 1.0; r <= radius; r += 0.4)
    for (int a = 0; a < 90; ++a) {
      const double angle = 2.0 * M_PI * a / 90.0;
      points.emplace_back(static_cast<float>(origin.x() + r * std::cos(angle)),
                          static_cast<float>(origin.y() + r * std::sin(angle)), 0.25f);
    }
  return points;
}

// One scan from (0.1, 0.2, 1.3): a 4 x 4 m wall at x = 6.25 and the floor around.
OccupancyMap wallAndFloorMap() {
  OccupancyMap map({0.5, 30.0});
  const Vec3 origin(0.1, 0.2, 1.3);
  Points scan = wallAt(6.25, origin, 2.0, 0.07);
  for (const auto& p : floorAround(origin, 5.0))
    scan.push_back(p);
  map.insertScan(origin, scan);
  return map;
}

// Every known cell as (key, log-odds), in key order: the whole content of a map.
std::map<std::tuple<int, int, int>, float> leaves(const OccupancyMap& map) {
  std::map<std::tuple<int, int, int>, float> out;
  for (const auto& cell : map.knownCells())
    out[{cell.key[0], cell.key[1], cell.key[2]}] = cell.logOdds;
  return out;
}

TEST(OccupancyMap, WallScanIsOccupiedFreeInFrontUnknownBehind) {
  OccupancyMap map({0.5, 30.0});
  const Vec3 origin(0.1, 0.2, 1.3);
  const Points wall = wallAt(10.25, origin, 3.0, 0.05);
  map.insertScan(origin, wall);
  EXPECT_EQ(map.revision(), 1U);
  for (double y = -2.0; y <= 2.0; y += 0.5)
    for (double z = -2.0; z <= 2.0; z += 0.5) {
      const Vec3 onWall(10.25, origin.y() + y, origin.z() + z);
      EXPECT_EQ(map.state(onWall), CellState::Occupied) << y << " " << z;
      for (const double t : {0.05, 0.3, 0.6, 0.9})
        EXPECT_EQ(map.state(origin + t * (onWall - origin)), CellState::Free) << t;
      EXPECT_EQ(map.state(onWall + Vec3(0.5, 0, 0)), CellState::Unknown);
      EXPECT_EQ(map.state(onWall + Vec3(3.0, 0, 0)), CellState::Unknown);
    }
  EXPECT_EQ(map.state(Vec3(-3.0, 0.2, 1.3)), CellState::Unknown);  // behind the sensor
  // The wall is 13 x 13 cells of 0.5 m (6 m of points from y = -2.8 to 3.2 and so on).
  EXPECT_EQ(map.occupiedCount(), 13U * 13U);
  size_t occupied = 0;
  const auto all = leaves(map);
  for (const auto& [key, logOdds] : all)
    occupied += logOdds >= 0.0f ? 1 : 0;
  EXPECT_EQ(occupied, map.occupiedCount());
  EXPECT_EQ(all.size(), map.knownCount());
  EXPECT_GT(map.knownCount(), 13U * 13U * 5U);  // the free pyramid in front of the wall
}

TEST(OccupancyMap, ReturnsBeyondTheRangeCapOnlyClearUpToTheCap) {
  OccupancyMap map({0.5, 5.0});
  const Vec3 origin(0.1, 0.2, 1.3);
  map.insertScan(origin, wallAt(10.25, origin, 1.0, 0.1));
  EXPECT_EQ(map.occupiedCount(), 0U);
  EXPECT_EQ(map.state(Vec3(2.0, 0.2, 1.3)), CellState::Free);
  EXPECT_EQ(map.state(Vec3(4.25, 0.2, 1.3)), CellState::Free);
  EXPECT_EQ(map.state(Vec3(5.75, 0.2, 1.3)), CellState::Unknown);
  EXPECT_EQ(map.state(Vec3(10.25, 0.2, 1.3)), CellState::Unknown);
  // A return inside the cap still marks its cell occupied.
  map.insertScan(origin, {Eigen::Vector3f(4.25f, 0.2f, 1.3f)});
  EXPECT_EQ(map.state(Vec3(4.25, 0.2, 1.3)), CellState::Occupied);
}

TEST(OccupancyMap, EachCellIsUpdatedOncePerScanWhateverThePointOrder) {
  const Vec3 origin(0.1, 0.2, 1.3);
  Points scan = wallAt(8.25, origin, 2.0, 0.05);
  const Points floor = floorAround(origin, 7.0);
  scan.insert(scan.end(), floor.begin(), floor.end());
  OccupancyMap a({0.5, 30.0}), b({0.5, 30.0});
  a.insertScan(origin, scan);
  std::reverse(scan.begin(), scan.end());
  b.insertScan(origin, scan);
  EXPECT_EQ(leaves(a), leaves(b));
  // One observation per cell: the log-odds of a single hit or miss, never more.
  const float hit = a.hitLogOdds(), miss = a.missLogOdds();
  for (const auto& [key, logOdds] : leaves(a))
    EXPECT_TRUE(logOdds == hit || logOdds == miss) << logOdds;
}

// The same scans applied to a plain OcTree with OctoMap's own ray walk (computeRayKeys from the
// sensor to the centre of each distinct end cell, ends capped at the range as insertScan does,
// occupied winning, one update per cell) give the same leaves, log-odds for log-odds. The scans
// are made for the walk's ties: sensors on cell corners and centres, points on a lattice of
// quarter cells (rays along the axes, along exact diagonals, through edges and corners), random
// points beyond the cap and inside the sensor's own cell.
TEST(OccupancyMap, InsertScanWalksTheCellsOctoMapsRayWalkDoes) {
  const double resolution = 0.5, maxRange = 12.0;
  OccupancyMap map({resolution, maxRange});
  octomap::OcTree reference(resolution);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const std::vector<Vec3> sensors = {Vec3(0, 0, 0),         Vec3(0.25, 0.25, 0.25),
                                     Vec3(0.5, -1.0, 2.0),  Vec3(-3.75, 2.25, -0.5),
                                     Vec3(1.1, -0.3, 0.77), Vec3(-0.01, 3.4999, 1.5001)};
  for (const Vec3& sensor : sensors) {
    Points scan;
    for (double x = -4.0; x <= 4.0; x += 0.25)
      for (double y = -4.0; y <= 4.0; y += 0.25)
        for (const double z : {-2.0, -0.25, 0.0, 0.5, 1.75})
          scan.emplace_back(static_cast<float>(sensor.x() + x), static_cast<float>(sensor.y() + y),
                            static_cast<float>(sensor.z() + z));
    for (int i = 0; i < 4000; ++i) {
      const double reach = i % 10 == 0 ? 0.2 : 18.0;  // some in the sensor's cell, some capped
      scan.emplace_back(
          (sensor + reach * Vec3(unit(random), unit(random), unit(random))).cast<float>());
    }
    map.insertScan(sensor, scan);

    octomap::KeySet free, occupied;
    std::set<octomap::OcTreeKey, bool (*)(const octomap::OcTreeKey&, const octomap::OcTreeKey&)>
        ends([](const octomap::OcTreeKey& a, const octomap::OcTreeKey& b) {
          return std::tie(a[0], a[1], a[2]) < std::tie(b[0], b[1], b[2]);
        });
    for (const auto& point : scan) {
      const Vec3 offset = point.cast<double>() - sensor;
      const bool capped = offset.norm() > maxRange;
      const Vec3 end =
          capped ? Vec3(sensor + offset * (maxRange / offset.norm())) : Vec3(point.cast<double>());
      octomap::OcTreeKey key;
      ASSERT_TRUE(reference.coordToKeyChecked(end.x(), end.y(), end.z(), key));
      ends.insert(key);
      if (!capped) occupied.insert(key);
    }
    octomap::KeyRay ray;
    const octomap::point3d origin(static_cast<float>(sensor.x()), static_cast<float>(sensor.y()),
                                  static_cast<float>(sensor.z()));
    for (const auto& key : ends) {
      ASSERT_TRUE(reference.computeRayKeys(origin, reference.keyToCoord(key), ray));
      for (const auto& cell : ray)
        if (!occupied.count(cell)) free.insert(cell);
    }
    for (const auto& key : free)
      reference.updateNode(key, false);
    for (const auto& key : occupied)
      reference.updateNode(key, true);
  }
  reference.expand();  // OctoMap prunes equal siblings; the map never does
  std::map<std::tuple<int, int, int>, float> expected;
  for (auto it = reference.begin_leafs(), end = reference.end_leafs(); it != end; ++it)
    expected[{it.getKey()[0], it.getKey()[1], it.getKey()[2]}] = it->getLogOdds();
  const auto actual = leaves(map);
  EXPECT_GT(actual.size(), 10000U);
  EXPECT_EQ(actual.size(), expected.size());
  EXPECT_TRUE(actual == expected);
}

// A thin plate seen once, then passed at a grazing angle by rays hitting a wall behind it:
// OctoMap's rule erases the plate, the static-world rule keeps it, and a robot's body (a free
// observation through observeCells) still clears a cell under either rule.
TEST(OccupancyMap, RaysLeaveOccupiedCellsWhenTheyMayNotClearThem) {
  const Vec3 above(0.1, 0.2, 3.3);
  Points plate;  // z = 0.3: the cells of 0 <= z < 0.5, x and y from 2 to 6
  for (double x = 2.1; x < 6.0; x += 0.2)
    for (double y = 2.1; y < 6.0; y += 0.2)
      plate.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.3f);
  // Grazing rays from beside the plate, just above it (z 0.45 at the plate, inside its cells),
  // ending on a wall at x = 12.25.
  const Vec3 side(0.1, 4.0, 0.45);
  const Points wall = wallAt(12.25, side, 0.05, 0.05);
  for (const bool raysClear : {true, false}) {
    OccupancyMap map({0.5, 30.0, raysClear});
    map.insertScan(above, plate);
    ASSERT_EQ(map.state(Vec3(4.25, 4.25, 0.25)), CellState::Occupied);
    for (int i = 0; i < 12; ++i)
      map.insertScan(side, wall);
    EXPECT_EQ(map.state(Vec3(4.25, 4.25, 0.25)), raysClear ? CellState::Free : CellState::Occupied)
        << raysClear;
    EXPECT_EQ(map.state(Vec3(9.25, 4.25, 0.25)), CellState::Free);  // beyond the plate
    EXPECT_EQ(map.state(Vec3(12.25, 4.25, 0.25)), CellState::Occupied);
    for (int i = 0; i < 12; ++i)
      map.observeCells({Vec3(4.25, 4.25, 0.25)}, {});
    EXPECT_EQ(map.state(Vec3(4.25, 4.25, 0.25)), CellState::Free) << raysClear;
  }
}

// Under the static-world rule, rays still clear occupied cells where raysClearAt allows it: a
// UAV seen from afar (a small blob in the open) leaves the map once rays pass where it was,
// structure where the robot knows structure can be stays.
TEST(OccupancyMap, RaysClearOccupiedCellsWhereTheRobotAllowsIt) {
  const Vec3 origin(0.1, 0.2, 1.3);
  // Two blobs in front of a wall at x = 12.25: one at y = 0.25 (may clear), one at y = 4.25.
  const Points blobs{{6.2f, 0.2f, 1.3f}, {6.2f, 4.2f, 1.3f}};
  const Points wall = wallAt(12.25, origin, 6.0, 0.05);
  OccupancyMap map({0.5, 30.0, false});
  map.setRaysClearAt([](const Vec3& cell) { return cell.y() < 2.0; });
  map.insertScan(origin, blobs);
  ASSERT_EQ(map.state(Vec3(6.25, 0.25, 1.25)), CellState::Occupied);
  ASSERT_EQ(map.state(Vec3(6.25, 4.25, 1.25)), CellState::Occupied);
  for (int i = 0; i < 12; ++i)
    map.insertScan(origin, wall);
  EXPECT_EQ(map.state(Vec3(6.25, 0.25, 1.25)), CellState::Free);
  EXPECT_EQ(map.state(Vec3(6.25, 4.25, 1.25)), CellState::Occupied);
  EXPECT_EQ(map.state(Vec3(12.25, 0.25, 1.25)), CellState::Occupied);  // the wall itself stays
}

// Merging a map that saw a cell free does not clear it either under the static-world rule.
TEST(OccupancyMap, MergeLeavesOccupiedCellsWhenRaysMayNotClearThem) {
  const Vec3 origin(0.1, 0.2, 1.3);
  OccupancyMap walls({0.5, 30.0, false}), open({0.5, 30.0, false});
  walls.insertScan(origin, wallAt(6.25, origin, 1.0, 0.1));
  open.insertScan(origin, wallAt(10.25, origin, 1.0, 0.1));  // sees x = 6.25 free
  const size_t before = walls.occupiedCount();
  for (int i = 0; i < 12; ++i)
    walls.merge(open);
  EXPECT_EQ(walls.state(Vec3(6.25, 0.2, 1.3)), CellState::Occupied);
  EXPECT_EQ(walls.occupiedCount(), before + open.occupiedCount());
}

TEST(OccupancyMap, MergeOfTwoHalfMapsEqualsTheMapOfBothScans) {
  const Vec3 first(0.1, 0.2, 1.3), second(3.7, -2.4, 2.1);
  Points scan1 = wallAt(8.25, first, 3.0, 0.07), scan2 = wallAt(9.75, second, 3.0, 0.07);
  for (const auto& p : floorAround(first, 6.0))
    scan1.push_back(p);
  for (const auto& p : floorAround(second, 6.0))
    scan2.push_back(p);
  OccupancyMap both({0.5, 30.0}), half1({0.5, 30.0}), half2({0.5, 30.0});
  both.insertScan(first, scan1);
  both.insertScan(second, scan2);
  half1.insertScan(first, scan1);
  half2.insertScan(second, scan2);
  const uint64_t before = half1.revision();
  half1.merge(half2);
  EXPECT_GT(half1.revision(), before);
  const auto expected = leaves(both), merged = leaves(half1);
  ASSERT_EQ(expected.size(), merged.size());
  for (const auto& [key, logOdds] : expected) {
    const auto it = merged.find(key);
    ASSERT_NE(it, merged.end());
    EXPECT_EQ(logOdds >= 0.0f, it->second >= 0.0f);  // the state of every cell
    EXPECT_FLOAT_EQ(logOdds, it->second);
  }
  EXPECT_EQ(both.occupiedCount(), half1.occupiedCount());
  EXPECT_EQ(both.knownCount(), half1.knownCount());
}

// The cells of a scan found by one map and applied to others leave each as insertScan would:
// the same cells with the same log-odds and counts, under either clearing rule, with the
// receiver's own raysClearAt, over what the receiver already held (a wall in front of a blob).
TEST(OccupancyMap, ScanCellsFoundOnceApplyAsInsertScanDoes) {
  const Vec3 origin(0.1, 0.2, 1.3), other(-1.3, 2.2, 2.7);
  Points scan = wallAt(12.25, origin, 6.0, 0.07);
  for (const auto& p : floorAround(origin, 30.0))
    scan.push_back(p);
  scan.emplace_back(45.0f, 0.2f, 1.3f);  // beyond the range cap: clears up to it only
  const Points blobs{{6.2f, 0.2f, 1.3f}, {6.2f, 4.2f, 1.3f}};
  for (const bool raysClear : {true, false}) {
    const OccupancyMap finder({0.5, 30.0, raysClear});
    const OccupancyMap::ScanCells cells = finder.scanCells(origin, scan);
    EXPECT_TRUE(std::is_sorted(cells.codes.begin(), cells.codes.end()));
    OccupancyMap inserted({0.5, 30.0, raysClear}), applied({0.5, 30.0, raysClear});
    for (OccupancyMap* map : {&inserted, &applied}) {
      map->setRaysClearAt([](const Vec3& cell) { return cell.y() < 2.0; });
      map->insertScan(other, blobs);
    }
    const uint64_t before = applied.revision();
    for (int i = 0; i < 3; ++i) {  // three misses clear a hit where rays may clear
      inserted.insertScan(origin, scan);
      applied.insertScanCells(cells);
    }
    EXPECT_EQ(applied.revision(), before + 3);
    EXPECT_EQ(leaves(applied), leaves(inserted)) << raysClear;
    EXPECT_EQ(applied.knownCount(), inserted.knownCount());
    EXPECT_EQ(applied.occupiedCount(), inserted.occupiedCount());
    EXPECT_EQ(applied.state(Vec3(6.25, 0.25, 1.25)), CellState::Free) << raysClear;
    EXPECT_EQ(applied.state(Vec3(6.25, 4.25, 1.25)),
              raysClear ? CellState::Free : CellState::Occupied);
  }
}

TEST(OccupancyMapDeathTest, ScanCellsApplyOnlyToMapsOfTheirResolutionAndRangeCap) {
  const Vec3 origin(0.1, 0.2, 1.3);
  const auto cells = OccupancyMap({0.5, 30.0}).scanCells(origin, wallAt(6.25, origin, 1.0, 0.1));
  OccupancyMap coarse({1.0, 30.0}), shortSighted({0.5, 20.0});
  EXPECT_DEATH(coarse.insertScanCells(cells), "resolution");
  EXPECT_DEATH(shortSighted.insertScanCells(cells), "maxRange");
}

TEST(OccupancyMap, MergingAMapIntoItselfRepeatsEveryObservation) {
  OccupancyMap map({0.5, 30.0});
  const Vec3 origin(0.1, 0.2, 1.3);
  map.insertScan(origin, wallAt(6.25, origin, 2.0, 0.1));
  const auto before = leaves(map);
  const size_t known = map.knownCount(), occupied = map.occupiedCount();
  map.merge(map);
  const auto after = leaves(map);
  ASSERT_EQ(after.size(), before.size());
  const float hit = map.hitLogOdds(), miss = map.missLogOdds();
  for (const auto& [key, logOdds] : before)
    EXPECT_FLOAT_EQ(after.at(key), logOdds + (logOdds >= 0.0f ? hit : miss));
  EXPECT_EQ(map.knownCount(), known);
  EXPECT_EQ(map.occupiedCount(), occupied);
}

TEST(OccupancyMapDeathTest, MergeRequiresTheSameResolution) {
  OccupancyMap fine({0.5, 30.0}), coarse({1.0, 30.0});
  EXPECT_DEATH(fine.merge(coarse), "resolution");
}

// Free cells at res 1.0: cube A (3 x 3 x 3 at the origin) with an occupied wall on its -x side,
// cube B (2 x 2 x 2 at x = 10), and one lone free cell at x = 20.
OccupancyMap frontierScene() {
  OccupancyMap map({1.0, 30.0});
  std::vector<Vec3> freeCells, occupiedCells;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x)
        freeCells.emplace_back(x + 0.5, y + 0.5, z + 0.5);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        freeCells.emplace_back(10.5 + x, y + 0.5, z + 0.5);
  freeCells.emplace_back(20.5, 0.5, 0.5);
  for (int z = -1; z < 4; ++z)
    for (int y = -1; y < 4; ++y)
      occupiedCells.emplace_back(-0.5, y + 0.5, z + 0.5);
  map.observeCells(freeCells, occupiedCells);
  return map;
}

TEST(OccupancyMap, FrontierClustersOfASyntheticScene) {
  const OccupancyMap map = frontierScene();
  const auto clusters = map.frontierClusters(Vec3(-5, -5, -5), Vec3(25, 5, 5), 2);
  ASSERT_EQ(clusters.size(), 2U);
  // Cube A: all 27 cells but its centre (every face neighbour free) and the centre of its -x
  // face (the wall, four free neighbours, nothing unknown): 25 cells.
  EXPECT_EQ(clusters[0].cells.size(), 25U);
  const Vec3 expectedA =
      (27.0 * Vec3(1.5, 1.5, 1.5) - Vec3(1.5, 1.5, 1.5) - Vec3(0.5, 1.5, 1.5)) / 25.0;
  EXPECT_LT((clusters[0].centroid - expectedA).norm(), 1e-12);
  EXPECT_EQ(clusters[1].cells.size(), 8U);
  EXPECT_LT((clusters[1].centroid - Vec3(11.0, 1.0, 1.0)).norm(), 1e-12);
  EXPECT_TRUE(std::is_sorted(
      clusters[0].cells.begin(), clusters[0].cells.end(), [](const Vec3& a, const Vec3& b) {
        return std::make_tuple(a.z(), a.y(), a.x()) < std::make_tuple(b.z(), b.y(), b.x());
      }));
  // The lone cell is a cluster of one; a region around cube B sees only B.
  EXPECT_EQ(map.frontierClusters(Vec3(-5, -5, -5), Vec3(25, 5, 5), 1).size(), 3U);
  const auto onlyB = map.frontierClusters(Vec3(9, -1, -1), Vec3(13, 3, 3), 1);
  ASSERT_EQ(onlyB.size(), 1U);
  EXPECT_EQ(onlyB[0].cells.size(), 8U);
}

// A frontier along a 10 m roof ridge, cut into 4 m cubes: three parts, each with its own centroid;
// a cluster inside one cube stays as it was.
TEST(OccupancyMap, LargeFrontierClustersAreSplitIntoCubes) {
  FrontierCluster ridge;
  for (double x = 0.25; x < 10.0; x += 0.5)
    ridge.cells.push_back(Vec3(x, 1.25, 6.25));
  FrontierCluster small;
  small.cells = {Vec3(20.25, 1.25, 1.25), Vec3(20.75, 1.25, 1.25)};
  small.centroid = Vec3(20.5, 1.25, 1.25);
  const auto parts = splitFrontierClusters({ridge, small}, 4.0);
  ASSERT_EQ(parts.size(), 4U);
  EXPECT_EQ(parts[0].cells.size(), 8U);  // x in [0, 4)
  EXPECT_EQ(parts[1].cells.size(), 8U);  // [4, 8)
  EXPECT_EQ(parts[2].cells.size(), 4U);  // [8, 10)
  EXPECT_LT((parts[0].centroid - Vec3(2.0, 1.25, 6.25)).norm(), 1e-12);
  EXPECT_LT((parts[2].centroid - Vec3(9.0, 1.25, 6.25)).norm(), 1e-12);
  EXPECT_EQ(parts[3].cells, small.cells);
  EXPECT_LT((parts[3].centroid - small.centroid).norm(), 1e-12);
  EXPECT_TRUE(splitFrontierClusters({}, 4.0).empty());
}

// An axis-aligned box seen from far away along each axis: face cells of 0.5 m from 2.0 to 6.0.
TEST(OccupancyMap, SurfaceVoxelsOfABoxHaveOutwardNormals) {
  OccupancyMap map({0.5, 60.0});
  const double lo = 2.25, hi = 5.75, mid = 4.0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-1.0, 1.0}) {
      Vec3 origin = Vec3::Constant(mid);
      origin[axis] += side * 40.0;
      Points face;
      for (double u = lo; u <= hi + 1e-9; u += 0.1)
        for (double v = lo; v <= hi + 1e-9; v += 0.1) {
          Vec3 p;
          p[axis] = side < 0 ? lo : hi;
          p[(axis + 1) % 3] = u;
          p[(axis + 2) % 3] = v;
          face.push_back(p.cast<float>());
        }
      map.insertScan(origin, face);
    }
  const auto surface = map.surfaceVoxels(Vec3::Zero(), Vec3::Constant(8.0));
  size_t faceInterior = 0;
  for (const auto& voxel : surface) {
    EXPECT_NEAR(voxel.normal.norm(), 1.0, 1e-12);
    Vec3 outward = Vec3::Zero();
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_GE(voxel.centre[axis], lo - 1e-9);  // every surface voxel belongs to the box
      ASSERT_LE(voxel.centre[axis], hi + 1e-9);
      if (std::abs(voxel.centre[axis] - lo) < 1e-9) outward[axis] = -1.0;
      if (std::abs(voxel.centre[axis] - hi) < 1e-9) outward[axis] = 1.0;
    }
    ASSERT_GT(outward.squaredNorm(), 0.0);
    if (outward.squaredNorm() == 1.0) {
      ++faceInterior;
      EXPECT_LT((voxel.normal - outward).norm(), 1e-12) << voxel.centre.transpose();
    } else {
      EXPECT_GT(voxel.normal.dot(outward.normalized()), 0.8) << voxel.centre.transpose();
    }
  }
  EXPECT_EQ(faceInterior, 6U * 6U * 6U);  // 6 faces of 8 x 8 cells, 6 x 6 away from the edges
  EXPECT_EQ(surface.size(), 8U * 8U * 8U - 6U * 6U * 6U);
}

TEST(OccupancyMap, VoxelGridAgreesWithStateAndTheLeafRule) {
  OccupancyMap map({0.5, 30.0});
  const Vec3 first(0.1, 0.2, 1.3), second(3.7, -2.4, 2.1);
  Points scan = wallAt(8.25, first, 3.0, 0.07);
  for (const auto& p : floorAround(first, 6.0))
    scan.push_back(p);
  map.insertScan(first, scan);
  map.insertScan(second, wallAt(-4.75, second, 2.0, 0.07));
  const Vec3 min(-6.0, -8.0, -2.0), max(10.0, 6.0, 6.0);  // aligned with cells up to 2 m
  for (const double resolution : {0.25, 0.5, 1.0, 2.0})
    for (const Vec3& shift : {Vec3(0, 0, 0), Vec3(0.1, 0.2, 0.3)}) {
      const VoxelGrid grid = map.toVoxelGrid(min + shift, max + shift, resolution);
      if (resolution < 0.5) {
        // Dense cells finer than the map's: each reads the map cell holding its centre.
        for (int z = 0; z < grid.size().z(); ++z)
          for (int y = 0; y < grid.size().y(); ++y)
            for (int x = 0; x < grid.size().x(); ++x) {
              const Index3 cell(x, y, z);
              ASSERT_EQ(grid.state(cell), map.state(grid.centre(cell)))
                  << x << " " << y << " " << z;
            }
        continue;
      }
      ASSERT_EQ(grid.size(), (Vec3(16, 14, 8) / resolution).cast<int>());
      // The rule, by brute force over the leaves.
      VoxelGrid expected(grid.origin(), resolution, grid.size());
      for (const auto& known : map.knownCells()) {
        const Index3 cell = expected.cellOf(known.centre);
        if (!expected.contains(cell)) continue;
        if (known.occupied)
          expected.set(cell, CellState::Occupied);
        else if (expected.state(cell) == CellState::Unknown)
          expected.set(cell, CellState::Free);
      }
      size_t counts[3] = {0, 0, 0};
      for (int z = 0; z < grid.size().z(); ++z)
        for (int y = 0; y < grid.size().y(); ++y)
          for (int x = 0; x < grid.size().x(); ++x) {
            const Index3 cell(x, y, z);
            ASSERT_EQ(grid.state(cell), expected.state(cell)) << resolution << " " << x << y << z;
            if (resolution == 0.5) {
              ASSERT_EQ(grid.state(cell), map.state(grid.centre(cell)));
            }
            ++counts[static_cast<int>(grid.state(cell))];
          }
      EXPECT_GT(counts[0], 0U);  // the scene has all three states
      EXPECT_GT(counts[1], 0U);
      EXPECT_GT(counts[2], 0U);
    }
}

TEST(OccupancyMap, ClearanceMatchesBruteForce) {
  const OccupancyMap map = wallAndFloorMap();
  std::vector<Vec3> occupied;
  for (const auto& cell : map.knownCells())
    if (cell.occupied) occupied.push_back(cell.centre);
  ASSERT_EQ(occupied.size(), map.occupiedCount());
  for (int i = 0; i < 400; ++i) {
    // A deterministic scatter over the scene, some points far from everything.
    const Vec3 q(-4.0 + 0.37 * (i % 37), -5.0 + 0.61 * ((i * 7) % 19),
                 -1.0 + 0.29 * ((i * 3) % 23));
    // The last cap reaches every cell of the map (the search walks all its blocks).
    for (const double cap : {0.8, 3.0, 1e6}) {
      double best = cap;
      for (const auto& c : occupied)
        best = std::min(best, (c - q).norm());
      EXPECT_NEAR(map.clearance(q, cap), best, 1e-9) << q.transpose() << " cap " << cap;
    }
  }
  EXPECT_EQ(OccupancyMap().clearance(Vec3::Zero(), 2.5), 2.5);
}

// The changed centres bound exactly the cells whose state changed: every known cell after the
// first scan, nothing after a repeat that changes no state, one cell after one observation.
TEST(OccupancyMap, ChangedCentresBoundTheCellsWhoseStateChanged) {
  OccupancyMap map({0.5, 30.0});
  EXPECT_FALSE(map.takeChangedCentres());
  const Vec3 origin(0.1, 0.2, 1.3);
  const Points wall = wallAt(6.25, origin, 2.0, 0.07);
  map.insertScan(origin, wall);
  const auto first = map.takeChangedCentres();
  ASSERT_TRUE(first);
  Vec3 low = Vec3::Constant(1e9), high = Vec3::Constant(-1e9);
  for (const auto& cell : map.knownCells()) {
    low = low.cwiseMin(cell.centre);
    high = high.cwiseMax(cell.centre);
  }
  EXPECT_LT((first->first - low).norm(), 1e-9);
  EXPECT_LT((first->second - high).norm(), 1e-9);
  EXPECT_FALSE(map.takeChangedCentres());  // taken
  map.insertScan(origin, wall);            // free stays free, occupied stays occupied
  EXPECT_FALSE(map.takeChangedCentres());
  map.observeCells({Vec3(-3.1, 2.2, 0.4)}, {});
  const auto one = map.takeChangedCentres();
  ASSERT_TRUE(one);
  EXPECT_LT((one->first - Vec3(-3.25, 2.25, 0.25)).norm(), 1e-9);
  EXPECT_LT((one->second - one->first).norm(), 1e-9);
}

// A part of a grid reads as the same cells of the whole grid, aligned with the map's cells or
// not.
TEST(OccupancyMap, PartOfAVoxelGridReadsAsTheSameCells) {
  const OccupancyMap map = wallAndFloorMap();
  for (const double resolution : {0.5, 1.0})
    for (const Vec3& shift : {Vec3(0, 0, 0), Vec3(0.1, 0.2, 0.3)}) {
      const Vec3 min = Vec3(-6.0, -6.0, -1.0) + shift;
      const VoxelGrid whole = map.toVoxelGrid(min, min + Vec3(14.0, 12.0, 6.0), resolution);
      const Index3 from(3, 2, 1), size(7, 5, 4);
      const VoxelGrid part = map.toVoxelGrid(whole.frame(), from, from + size - Index3::Ones());
      ASSERT_EQ(part.size(), size);
      size_t known = 0;
      for (int z = 0; z < size.z(); ++z)
        for (int y = 0; y < size.y(); ++y)
          for (int x = 0; x < size.x(); ++x) {
            const Index3 cell(x, y, z);
            ASSERT_EQ(part.state(cell), whole.state(cell + from))
                << resolution << " " << x << y << z;
            known += part.state(cell) != CellState::Unknown;
          }
      EXPECT_GT(known, 0U);
    }
}

// Cells are kept in blocks of 8^3: cells on both sides of block borders, at negative and positive
// coordinates and at the two ends of the key range (+-2^15 cells around the origin) read back as
// observed, cells beyond the range are not stored, and the counts and the content agree.
TEST(OccupancyMap, CellsAcrossBlockBordersAndAtTheEndsOfTheKeyRange) {
  OccupancyMap map({0.5, 30.0});
  std::vector<Vec3> freeCells, occupiedCells;
  for (int i = -9; i <= 9; ++i)  // across the borders at -4 m, 0 and 4 m on each axis
    for (int j = -9; j <= 9; j += 3) {
      freeCells.emplace_back(0.5 * i + 0.25, 0.5 * j + 0.25, -0.25);
      occupiedCells.emplace_back(-0.25, 0.5 * i + 0.25, 0.5 * j + 0.25);
    }
  const double edge = 0.5 * 32768;  // the keys reach from -edge to edge
  occupiedCells.emplace_back(-edge + 0.1, -edge + 0.1, -edge + 0.1);  // key 0
  occupiedCells.emplace_back(edge - 0.1, edge - 0.1, edge - 0.1);     // key 65535
  freeCells.emplace_back(edge + 0.1, 0.0, 0.0);                       // beyond: skipped
  freeCells.emplace_back(0.0, -edge - 0.1, 0.0);
  map.observeCells(freeCells, occupiedCells);
  for (const Vec3& p : freeCells)
    if ((p.array().abs() < edge).all()) {
      EXPECT_EQ(map.state(p), CellState::Free) << p.transpose();
    }
  for (const Vec3& p : occupiedCells)
    EXPECT_EQ(map.state(p), CellState::Occupied) << p.transpose();
  EXPECT_EQ(map.state(Vec3(edge + 0.1, 0.0, 0.0)), CellState::Unknown);
  EXPECT_EQ(map.state(Vec3(0.75, 0.75, 0.75)), CellState::Unknown);
  EXPECT_EQ(map.occupiedCount(), 19U * 7U + 2U);
  EXPECT_EQ(map.knownCount(), 2U * 19U * 7U + 2U);
  const auto cells = map.knownCells();
  ASSERT_EQ(cells.size(), map.knownCount());
  EXPECT_EQ(cells.front().key, (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(cells.back().key, (std::array<int, 3>{65535, 65535, 65535}));
  for (const auto& cell : cells) {
    EXPECT_EQ(map.state(cell.centre), cell.occupied ? CellState::Occupied : CellState::Free);
    EXPECT_EQ(cell.logOdds, cell.occupied ? map.hitLogOdds() : map.missLogOdds());
  }
  EXPECT_NEAR(map.clearance(Vec3(edge - 2.0, edge - 2.0, edge - 2.0), 10.0), std::sqrt(3.0) * 1.75,
              1e-9);
}

TEST(OccupancyMap, CellCentreMatchesTheOctreeCells) {
  const OccupancyMap map({0.5, 30.0});
  EXPECT_LT((map.cellCentre(Vec3(0.1, -0.1, 2.49)) - Vec3(0.25, -0.25, 2.25)).norm(), 1e-12);
}

}  // namespace
}  // namespace coinspect::mapping
