// Rays per second of the RayCaster wrapper against bare Embree loops on the CARIC MBS mesh.
//
// Every benchmark traces the same precomputed rays: LiDAR-like sweeps (16 channels from -15 to
// +15 degrees, 900 azimuths) from 7 viewpoints around the structure, 100,800 rays, range 100 m,
// ground plane at z = 0. Segments run from each viewpoint to the ray's point at 60 m.
// The bare loops build their own device and scene from the same triangles and ground.
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
#include "coinspect/world/mesh_io.h"
#include "coinspect/world/ray_caster.h"

namespace {

using coinspect::world::RayCaster;
using coinspect::world::TriangleMesh;
using coinspect::world::Vec3;

constexpr double kRange = 100.0;
constexpr double kSegmentLength = 60.0;
constexpr double kPi = 3.14159265358979323846;

using BareScene = coinspect::bench::BareEmbreeScene;

struct Setup {
  bool ok = false;
  TriangleMesh mesh;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<BareScene> bareRobust, bareFast;
  std::vector<Vec3> origins, directions, ends;
  std::vector<float> o, d;  // float copies for the bare loops, 3 per ray

  Setup() {
    const auto path = std::filesystem::path(COINSPECT_SHARED_DIR) / "data/caric-mbs/mbs.stl";
    if (!std::filesystem::exists(path)) return;
    mesh = coinspect::world::loadMesh(path);
    caster = std::make_unique<RayCaster>(std::vector<TriangleMesh>{mesh}, 0.0, 5000.0);
    bareRobust = std::make_unique<BareScene>(mesh, 5000.0, true);
    bareFast = std::make_unique<BareScene>(mesh, 5000.0, false);
    const auto box = mesh.bounds();
    const Vec3 centre = 0.5 * (box.min + box.max);
    for (int view = 0; view < 7; ++view) {
      const double a = 2.0 * kPi * view / 7.0;
      const Vec3 eye(centre.x() + 90.0 * std::cos(a), centre.y() + 70.0 * std::sin(a),
                     15.0 + 7.0 * view);
      for (int azimuth = 0; azimuth < 900; ++azimuth)
        for (int channel = 0; channel < 16; ++channel) {
          const double yaw = 2.0 * kPi * azimuth / 900.0;
          const double pitch = (-15.0 + 2.0 * channel) * kPi / 180.0;
          const Vec3 dir(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                         std::sin(pitch));
          origins.push_back(eye);
          directions.push_back(dir);
          ends.push_back(eye + kSegmentLength * dir);
          for (int k = 0; k < 3; ++k) {
            o.push_back(static_cast<float>(eye[k]));
            d.push_back(static_cast<float>(dir[k]));
          }
        }
    }
    ok = true;
  }
  size_t size() const { return origins.size(); }
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

void finish(benchmark::State& state, size_t raysPerIteration) {
  state.counters["rays_per_s"] = benchmark::Counter(
      static_cast<double>(raysPerIteration * state.iterations()), benchmark::Counter::kIsRate);
}

void BM_WrapperClosestHit(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  size_t hits = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < s.size(); ++i)
      hits += s.caster->closestHit(s.origins[i], s.directions[i], kRange).has_value();
    benchmark::DoNotOptimize(hits);
  }
  state.counters["hit_fraction"] =
      static_cast<double>(hits) / static_cast<double>(s.size() * state.iterations());
  finish(state, s.size());
}

void BM_WrapperClosestHits(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  std::vector<double> distances;
  for (auto _ : state) {
    s.caster->closestHits(s.origins, s.directions, kRange, distances);
    benchmark::DoNotOptimize(distances.data());
  }
  finish(state, s.size());
}

void BM_WrapperSegmentClear(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  size_t clear = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < s.size(); ++i)
      clear += s.caster->segmentClear(s.origins[i], s.ends[i],
                                      coinspect::world::kLinkClearanceTolerance);
    benchmark::DoNotOptimize(clear);
  }
  state.counters["clear_fraction"] =
      static_cast<double>(clear) / static_cast<double>(s.size() * state.iterations());
  finish(state, s.size());
}

void BM_WrapperSegmentsClear(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  std::vector<uint8_t> clear;
  for (auto _ : state) {
    s.caster->segmentsClear(s.origins, s.ends, coinspect::world::kLinkClearanceTolerance, clear);
    benchmark::DoNotOptimize(clear.data());
  }
  finish(state, s.size());
}

void fillRay(RTCRay& ray, const float* o, const float* d, float tfar) {
  ray.org_x = o[0];
  ray.org_y = o[1];
  ray.org_z = o[2];
  ray.tnear = 0.0f;
  ray.dir_x = d[0];
  ray.dir_y = d[1];
  ray.dir_z = d[2];
  ray.time = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xffffffffu;
  ray.id = 0;
  ray.flags = 0;
}

// Arg: 1 = robust scene (what RayCaster uses), 0 = Embree's default fast scene.
void BM_BareIntersect1(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const RTCScene scene = state.range(0) ? s.bareRobust->scene : s.bareFast->scene;
  size_t hits = 0;
  for (auto _ : state) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t i = 0; i < s.size(); ++i) {
      RTCRayHit rh;
      fillRay(rh.ray, &s.o[3 * i], &s.d[3 * i], static_cast<float>(kRange));
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    benchmark::DoNotOptimize(hits);
  }
  finish(state, s.size());
}

void BM_BareIntersect16(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const RTCScene scene = state.range(0) ? s.bareRobust->scene : s.bareFast->scene;
  std::vector<float> distances(s.size());
  for (auto _ : state) {
    coinspect::bench::intersectPackets16(
        scene, s.o.data(), s.d.data(), s.size(), static_cast<float>(kRange),
        [&](size_t ray, bool hit, float r) { distances[ray] = hit ? r : INFINITY; });
    benchmark::DoNotOptimize(distances.data());
  }
  finish(state, s.size());
}

void BM_BareOccluded1(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const RTCScene scene = state.range(0) ? s.bareRobust->scene : s.bareFast->scene;
  const float reach =
      static_cast<float>(kSegmentLength - coinspect::world::kLinkClearanceTolerance);
  size_t clear = 0;
  for (auto _ : state) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t i = 0; i < s.size(); ++i) {
      RTCRay ray;
      fillRay(ray, &s.o[3 * i], &s.d[3 * i], reach);
      rtcOccluded1(scene, &context, &ray);
      clear += ray.tfar >= 0.0f;
    }
    benchmark::DoNotOptimize(clear);
  }
  state.counters["clear_fraction"] =
      static_cast<double>(clear) / static_cast<double>(s.size() * state.iterations());
  finish(state, s.size());
}

// The same occlusion tests starting from the segment end points, as any caller of a segment
// query must: direction and length are computed in the loop, as RayCaster::segmentClear does.
void BM_BareOccluded1FromEndpoints(benchmark::State& state) {
  if (!ready(state)) return;
  const Setup& s = setup();
  const RTCScene scene = s.bareRobust->scene;
  const double tolerance = coinspect::world::kLinkClearanceTolerance;
  size_t clear = 0;
  for (auto _ : state) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t i = 0; i < s.size(); ++i) {
      const Vec3& a = s.origins[i];
      const Vec3 delta = s.ends[i] - a;
      const double length = delta.norm();
      const float o[3] = {static_cast<float>(a.x()), static_cast<float>(a.y()),
                          static_cast<float>(a.z())};
      const float d[3] = {static_cast<float>(delta.x() / length),
                          static_cast<float>(delta.y() / length),
                          static_cast<float>(delta.z() / length)};
      RTCRay ray;
      fillRay(ray, o, d, static_cast<float>(length - tolerance));
      rtcOccluded1(scene, &context, &ray);
      clear += ray.tfar >= 0.0f;
    }
    benchmark::DoNotOptimize(clear);
  }
  finish(state, s.size());
}

BENCHMARK(BM_WrapperClosestHit)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WrapperClosestHits)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WrapperSegmentClear)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WrapperSegmentsClear)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BareIntersect1)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BareIntersect16)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BareOccluded1)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BareOccluded1FromEndpoints)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
