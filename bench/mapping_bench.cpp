// Occupancy maps (libs/mapping) fed by realistic LiDAR on the CARIC MBS mesh.
//
// Sweeps: the CARIC tilting VLP-16 (7,040 rays, 0.9-50 m) of an explorer flying a ring around the
// structure at 3 m/s and 10 Hz (0.3 m between sweeps), 5 m above the mid-height of the ring's
// 48 m band; key frames: the same sweeps voxel-downsampled at 0.5 m (the reference's
// kf_voxsize). Every insertion benchmark cycles through kSweeps consecutive sweeps, one sweep per
// iteration, into one map that persists across iterations (as a robot's map does), so the time
// per iteration is the cost of one sweep. The ray casting of the same sweeps is measured beside
// them for ratios. Queries run on a "full" map: 160 sweeps spread all around the structure at
// four heights, about what two explorers gather in a mission.
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <octomap/OcTree.h>

#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "caric_mbs_fixture.h"
#include "coinspect/mapping/occupancy_map.h"
#include "coinspect/sensing/key_frames.h"
#include "coinspect/sensing/lidar.h"

namespace {

using coinspect::mapping::OccupancyMap;
using coinspect::mapping::OccupancyMapOptions;
using coinspect::mapping::Vec3;
using coinspect::sensing::LidarScan;
using coinspect::sensing::LidarSimulator;
using coinspect::sensing::LidarSpec;
using Points = std::vector<Eigen::Vector3f>;

constexpr int kSweeps = 40;       // 4 s of one explorer's flight
constexpr int kFullSweeps = 160;  // the "full" map for the queries
constexpr double kMaxRange = 50.0;

LidarSpec caricVlp16() {
  LidarSpec spec;  // the defaults are the reference VLP-16
  spec.tiltAmplitude = M_PI / 2.0;
  spec.tiltPeriod = 8.0;
  spec.mountOffset = Eigen::Vector3d(0.0, 0.0, 0.2);
  return spec;
}

struct Sweep {
  Vec3 origin;
  Points points;    // world frame
  Points keyFrame;  // the same, voxel-downsampled at 0.5 m
};

struct Setup {
  bool ok = false;
  std::vector<Sweep> path;    // kSweeps consecutive sweeps
  std::vector<Sweep> around;  // kFullSweeps all around
  std::vector<Eigen::Isometry3d> pathBodies;
  Vec3 regionMin, regionMax;  // the structure's bounds, 5 m of margin (ground excluded)
  const coinspect::bench::CaricMbs* mbs = nullptr;

  Setup() {
    mbs = coinspect::bench::caricMbs();
    if (mbs == nullptr) return;
    const auto box = mbs->scenario.bounds();
    const Vec3 centre = 0.5 * (box.min + box.max), half = 0.5 * box.size();
    // Whole metres, so that grids of 1 m (and 2 m) are aligned with the octree's nodes.
    regionMin = Vec3(box.min.x() - 5.0, box.min.y() - 5.0, mbs->scenario.groundZ);
    regionMax = box.max + Vec3::Constant(5.0);
    regionMin = (regionMin / 2.0).array().floor() * 2.0;
    regionMax = (regionMax / 2.0).array().ceil() * 2.0;
    LidarSimulator lidar(caricVlp16(), 1);
    LidarScan scan;
    const auto sweepAt = [&](double angle, double z, double t) {
      Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
      body.translation() = Vec3(centre.x() + (half.x() + 15.0) * std::cos(angle),
                                centre.y() + (half.y() + 15.0) * std::sin(angle), z);
      body.linear() = Eigen::AngleAxisd(angle + M_PI / 2.0, Vec3::UnitZ()).toRotationMatrix();
      lidar.sweepFromBody(*mbs->caster, t, body, scan);
      Sweep sweep;
      sweep.origin = scan.sensorPose.translation();
      sweep.points.reserve(scan.points.size());
      for (const auto& p : scan.points)
        sweep.points.push_back((scan.sensorPose * p.cast<double>()).cast<float>());
      sweep.keyFrame = coinspect::sensing::voxelDownsample(sweep.points, 0.5);
      return sweep;
    };
    // Along the ring at 3 m/s: 0.3 m of arc per sweep.
    const double ringRadius = 0.5 * (half.x() + half.y()) + 15.0;
    for (int i = 0; i < kSweeps; ++i)
      path.push_back(sweepAt(0.3 * i / ringRadius, centre.z() + 5.0, 0.1 * i));
    for (int i = 0; i < kFullSweeps; ++i)
      around.push_back(
          sweepAt(2.0 * M_PI * i / 40.0, box.min.z() + 8.0 + 14.0 * (i / 40), 0.1 * i));
    ok = true;
  }

  double meanReturns(bool keyFrames) const {
    double n = 0;
    for (const auto& s : path)
      n += static_cast<double>(keyFrames ? s.keyFrame.size() : s.points.size());
    return n / static_cast<double>(path.size());
  }
};

const Setup& setup() {
  static const Setup s;
  return s;
}

bool ready(benchmark::State& state) {
  if (setup().ok) return true;
  state.SkipWithError("CARIC MBS mesh not found under COINSPECT_SHARED_DIR");
  return false;
}

double resolutionOf(const benchmark::State& state) {
  return state.range(0) / 1000.0;
}

// The full map at each resolution, built once.
const OccupancyMap& fullMap(double resolution) {
  static std::map<double, std::unique_ptr<OccupancyMap>> maps;
  auto& map = maps[resolution];
  if (!map) {
    map = std::make_unique<OccupancyMap>(OccupancyMapOptions{resolution, kMaxRange});
    for (const auto& sweep : setup().around)
      map->insertScan(sweep.origin, sweep.points);
  }
  return *map;
}

void mapCounters(benchmark::State& state, const OccupancyMap& map) {
  state.counters["known_cells"] = static_cast<double>(map.knownCount());
  state.counters["occupied_cells"] = static_cast<double>(map.occupiedCount());
}

// The ray casting that produced the sweeps (the reference cost for the ratios).
void BM_RayCastSweep(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  LidarSimulator lidar(caricVlp16(), 1);
  LidarScan scan;
  const auto box = s.mbs->scenario.bounds();
  const Vec3 centre = 0.5 * (box.min + box.max), half = 0.5 * box.size();
  const double ringRadius = 0.5 * (half.x() + half.y()) + 15.0;
  int i = 0;
  for (auto _ : state) {
    const double angle = 0.3 * (i % kSweeps) / ringRadius;
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.translation() = Vec3(centre.x() + (half.x() + 15.0) * std::cos(angle),
                              centre.y() + (half.y() + 15.0) * std::sin(angle), centre.z() + 5.0);
    body.linear() = Eigen::AngleAxisd(angle + M_PI / 2.0, Vec3::UnitZ()).toRotationMatrix();
    lidar.sweepFromBody(*s.mbs->caster, 0.1 * (i % kSweeps), body, scan);
    benchmark::DoNotOptimize(scan.points.data());
    ++i;
  }
  state.counters["returns_per_sweep"] = s.meanReturns(false);
}

void insertBench(benchmark::State& state, bool keyFrames) {
  if (!ready(state)) return;
  const Setup& s = setup();
  OccupancyMap map({resolutionOf(state), kMaxRange});
  int i = 0;
  for (auto _ : state) {
    const Sweep& sweep = s.path[i++ % kSweeps];
    map.insertScan(sweep.origin, keyFrames ? sweep.keyFrame : sweep.points);
  }
  state.counters["points_per_scan"] = s.meanReturns(keyFrames);
  mapCounters(state, map);
}

void BM_InsertSweep(benchmark::State& state) {
  insertBench(state, false);
}

// The same 40 sweeps into a fresh map each iteration (every cell new at first): the time per
// iteration / 40 is the cost of a sweep into unexplored space.
void BM_InsertSweepsIntoEmptyMap(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  std::unique_ptr<OccupancyMap> map;
  for (auto _ : state) {
    state.PauseTiming();
    map = std::make_unique<OccupancyMap>(OccupancyMapOptions{resolutionOf(state), kMaxRange});
    state.ResumeTiming();
    for (const auto& sweep : s.path)
      map->insertScan(sweep.origin, sweep.points);
  }
  state.counters["sweeps"] = kSweeps;
  mapCounters(state, *map);
}
void BM_InsertKeyFrame(benchmark::State& state) {
  insertBench(state, true);
}

// OctoMap's own batched insertion of the same sweeps (discretize on), for comparison: lazy
// (inner nodes left stale, as MRPT's COctoMap does) and not lazy (inner nodes kept current).
void BM_OctomapInsertPointCloud(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const bool lazy = state.range(1) != 0;
  octomap::OcTree tree(resolutionOf(state));
  std::vector<octomap::Pointcloud> clouds(kSweeps);
  for (int k = 0; k < kSweeps; ++k)
    for (const auto& p : s.path[k].points)
      clouds[k].push_back(p.x(), p.y(), p.z());
  int i = 0;
  for (auto _ : state) {
    const int k = i++ % kSweeps;
    const Vec3& o = s.path[k].origin;
    tree.insertPointCloud(clouds[k], octomap::point3d(o.x(), o.y(), o.z()), kMaxRange, lazy, true);
  }
}

// Merging a neighbour's map (the full map) into a robot's map of its own 40 sweeps, rebuilt
// (untimed) before each merge so that every merge meets the same mostly unknown cells.
void BM_Merge(benchmark::State& state) {
  if (!ready(state)) return;
  const double resolution = resolutionOf(state);
  const OccupancyMap& other = fullMap(resolution);
  std::unique_ptr<OccupancyMap> map;
  for (auto _ : state) {
    state.PauseTiming();
    map = std::make_unique<OccupancyMap>(OccupancyMapOptions{resolution, kMaxRange});
    for (const auto& sweep : setup().path)
      map->insertScan(sweep.origin, sweep.points);
    state.ResumeTiming();
    map->merge(other);
  }
  state.counters["merged_cells"] = static_cast<double>(other.knownCount());
  mapCounters(state, *map);
}

void BM_ToVoxelGrid(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const OccupancyMap& map = fullMap(resolutionOf(state));
  const double gridResolution = state.range(1) / 1000.0;
  size_t cells = 0;
  for (auto _ : state) {
    const auto grid = map.toVoxelGrid(s.regionMin, s.regionMax, gridResolution);
    cells = grid.cellCount();
    benchmark::DoNotOptimize(grid.origin());
  }
  state.counters["grid_cells"] = static_cast<double>(cells);
  const Vec3 extent = s.regionMax - s.regionMin;
  state.counters["region_x"] = extent.x();
  state.counters["region_y"] = extent.y();
  state.counters["region_z"] = extent.z();
  mapCounters(state, map);
}

void BM_FrontierClusters(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const OccupancyMap& map = fullMap(resolutionOf(state));
  size_t clusters = 0, cells = 0;
  for (auto _ : state) {
    const auto found = map.frontierClusters(s.regionMin, s.regionMax, 5);
    clusters = found.size();
    cells = 0;
    for (const auto& c : found)
      cells += c.cells.size();
  }
  state.counters["clusters"] = static_cast<double>(clusters);
  state.counters["frontier_cells"] = static_cast<double>(cells);
}

void BM_SurfaceVoxels(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const OccupancyMap& map = fullMap(resolutionOf(state));
  size_t voxels = 0;
  for (auto _ : state)
    voxels = map.surfaceVoxels(s.regionMin, s.regionMax).size();
  state.counters["surface_voxels"] = static_cast<double>(voxels);
}

void BM_Clearance(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const OccupancyMap& map = fullMap(resolutionOf(state));
  const double cap = state.range(1) / 1000.0;
  size_t i = 0;
  for (auto _ : state) {
    // Points spread over the region, the same sequence each run.
    const double u = (i * 7919 % 1000) / 1000.0, v = (i * 104729 % 997) / 997.0,
                 w = (i * 1299709 % 991) / 991.0;
    ++i;
    const Vec3 q = s.regionMin + (s.regionMax - s.regionMin).cwiseProduct(Vec3(u, v, w));
    benchmark::DoNotOptimize(map.clearance(q, cap));
  }
}

// Heap held by the full map (glibc's count of bytes in use, chunk headers included), against an
// octomap::OcTree holding the same cells with the same log-odds, never pruned (as the map's
// cells were kept before 2026-12-07: one leaf per cell).
size_t heapInUse() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

void BM_MapHeap(benchmark::State& state) {
  if (!ready(state)) return;
  const double resolution = resolutionOf(state);
  size_t ours = 0, tree = 0, cells = 0;
  for (auto _ : state) {
    size_t before = heapInUse();
    auto map = std::make_unique<OccupancyMap>(OccupancyMapOptions{resolution, kMaxRange});
    for (const auto& sweep : setup().around)
      map->insertScan(sweep.origin, sweep.points);
    ours = heapInUse() - before;
    const auto known = map->knownCells();
    cells = known.size();
    auto octree = std::make_unique<octomap::OcTree>(resolution);
    before = heapInUse();
    for (const auto& cell : known) {
      const octomap::OcTreeKey key(static_cast<octomap::key_type>(cell.key[0]),
                                   static_cast<octomap::key_type>(cell.key[1]),
                                   static_cast<octomap::key_type>(cell.key[2]));
      octree->setNodeValue(key, cell.logOdds, true);  // lazy: never pruned
    }
    tree = heapInUse() - before;
    benchmark::DoNotOptimize(octree->size());
  }
  state.counters["known_cells"] = static_cast<double>(cells);
  state.counters["map_MB"] = static_cast<double>(ours) / 1e6;
  state.counters["octree_MB"] = static_cast<double>(tree) / 1e6;
  state.counters["map_B_per_cell"] = static_cast<double>(ours) / static_cast<double>(cells);
  state.counters["octree_B_per_cell"] = static_cast<double>(tree) / static_cast<double>(cells);
}

BENCHMARK(BM_RayCastSweep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InsertSweep)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InsertSweepsIntoEmptyMap)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InsertKeyFrame)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OctomapInsertPointCloud)
    ->Args({500, 1})
    ->Args({500, 0})
    ->Args({1000, 1})
    ->Args({1000, 0})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Merge)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ToVoxelGrid)
    ->Args({500, 500})
    ->Args({500, 1000})
    ->Args({1000, 1000})
    ->Args({1000, 2000})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrontierClusters)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SurfaceVoxels)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Clearance)->Args({500, 3000})->Args({1000, 3000})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MapHeap)->Arg(500)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
