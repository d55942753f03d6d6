// Full LiDAR sweeps on the CARIC MBS mesh: LidarSimulator::sweep against a bare Embree loop.
//
// One iteration = one VLP-16 sweep (16 x 440 = 7,040 rays, 0.9-50 m) from each of 8 poses on a
// ring around the structure, the head tilted as the CARIC servo would at 8 instants. The bare
// loop builds its own robust scene from the same triangles and ground and traces the same world
// rays (precomputed in float) with rtcIntersect16, keeping the ranges inside the band; the
// simulator also rotates its rays, applies the band and writes sensor-frame points.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "bare_embree_scene.h"
#include "coinspect/sensing/lidar.h"
#include "coinspect/world/mesh_io.h"
#include "coinspect/world/ray_caster.h"

namespace {

using coinspect::sensing::LidarScan;
using coinspect::sensing::LidarSimulator;
using coinspect::sensing::LidarSpec;
using coinspect::world::RayCaster;
using coinspect::world::TriangleMesh;
using coinspect::world::Vec3;

constexpr int kPoses = 8;
constexpr double kGroundHalfExtent = 5000.0;

using BareScene = coinspect::bench::BareEmbreeScene;

LidarSpec caricVlp16() {
  LidarSpec spec;  // the defaults are the reference VLP-16
  spec.tiltAmplitude = M_PI / 2.0;
  spec.tiltPeriod = 8.0;
  spec.mountOffset = Eigen::Vector3d(0.0, 0.0, 0.2);
  return spec;
}

struct Setup {
  bool ok = false;
  LidarSpec spec = caricVlp16();
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<BareScene> bare;
  std::vector<Eigen::Isometry3d> sensorPoses;
  std::vector<float> o, d;  // world rays of every pose, 3 floats each, for the bare loop

  Setup() {
    const auto path = std::filesystem::path(COINSPECT_SHARED_DIR) / "data/caric-mbs/mbs.stl";
    if (!std::filesystem::exists(path)) return;
    const TriangleMesh mesh = coinspect::world::loadMesh(path);
    caster = std::make_unique<RayCaster>(std::vector<TriangleMesh>{mesh}, 0.0, kGroundHalfExtent);
    bare = std::make_unique<BareScene>(mesh, kGroundHalfExtent, true);  // robust, as RayCaster
    const auto box = mesh.bounds();
    const Vec3 centre = 0.5 * (box.min + box.max);
    const Vec3 half = 0.5 * box.size();
    const LidarSimulator directions(spec, 0);
    for (int view = 0; view < kPoses; ++view) {
      const double a = 2.0 * M_PI * view / kPoses;
      Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
      body.translation() = Vec3(centre.x() + (half.x() + 15.0) * std::cos(a),
                                centre.y() + (half.y() + 15.0) * std::sin(a), 10.0 + 6.0 * view);
      // Facing the structure, the servo at 8 different phases.
      body.linear() = Eigen::AngleAxisd(a + M_PI, Vec3::UnitZ()).toRotationMatrix();
      const Eigen::Isometry3d sensor =
          body * coinspect::sensing::lidarPoseInBody(spec, 0.7 + 1.3 * view);
      sensorPoses.push_back(sensor);
      for (const auto& u : directions.directions()) {
        const Vec3 w = sensor.linear() * u;
        for (int k = 0; k < 3; ++k) {
          o.push_back(static_cast<float>(sensor.translation()[k]));
          d.push_back(static_cast<float>(w[k]));
        }
      }
    }
    ok = true;
  }
  size_t rays() const { return o.size() / 3; }
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

void finish(benchmark::State& state, size_t returns) {
  const auto sweeps = static_cast<double>(kPoses * state.iterations());
  state.counters["sweeps_per_s"] = benchmark::Counter(sweeps, benchmark::Counter::kIsRate);
  state.counters["rays_per_s"] = benchmark::Counter(
      static_cast<double>(setup().rays() * state.iterations()), benchmark::Counter::kIsRate);
  state.counters["returns_per_sweep"] = static_cast<double>(returns) / sweeps;
}

void BM_LidarSimulatorSweep(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  LidarSimulator lidar(s.spec, 1);
  LidarScan scan;
  size_t returns = 0;
  for (auto _ : state) {
    for (const auto& pose : s.sensorPoses) {
      lidar.sweep(*s.caster, pose, scan);
      returns += scan.points.size();
      benchmark::DoNotOptimize(scan.points.data());
    }
  }
  finish(state, returns);
}

void BM_BareEmbreeSweep(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const float minRange = static_cast<float>(s.spec.minRange);
  const float maxRange = static_cast<float>(s.spec.maxRange);
  std::vector<float> ranges(s.rays());
  size_t returns = 0;
  for (auto _ : state) {
    coinspect::bench::intersectPackets16(s.bare->scene, s.o.data(), s.d.data(), s.rays(), maxRange,
                                         [&](size_t ray, bool hit, float r) {
                                           const bool kept = hit && minRange < r && r < maxRange;
                                           ranges[ray] = kept ? r : INFINITY;
                                           returns += kept ? 1 : 0;
                                         });
    benchmark::DoNotOptimize(ranges.data());
  }
  finish(state, returns);
}

BENCHMARK(BM_LidarSimulatorSweep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BareEmbreeSweep)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
