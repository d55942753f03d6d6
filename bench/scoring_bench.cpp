// Camera captures scored per second on the CARIC MBS scenario (read from COINSPECT_SHARED_DIR).
//
// Poses: a level photographer camera aimed at every 3rd interest point against its normal from
// 6 m, kept when its candidate set (points within the 15.5 m candidate radius) holds 60 to 160
// points, up to 64 poses; each iteration scores all of them. Counters: captures/s, candidate
// points/s, mean candidates per capture and the fraction seen.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "caric_mbs_fixture.h"
#include "coinspect/sensing/inspection_scorer.h"

namespace {

using namespace coinspect;

struct MbsFixture {
  const world::Scenario& scenario;
  const world::RayCaster* caster;
  world::CameraSpec spec;
  std::vector<sensing::CaptureState> poses;
};

// Built once; null when the shared data is absent.
const MbsFixture* fixture() {
  static const std::unique_ptr<MbsFixture> instance = []() -> std::unique_ptr<MbsFixture> {
    const bench::CaricMbs* mbs = bench::caricMbs();
    if (mbs == nullptr) return nullptr;
    auto f = std::make_unique<MbsFixture>(MbsFixture{mbs->scenario, mbs->caster.get(), {}, {}});
    for (const world::UnitSpec& unit : f->scenario.fleet) {
      if (unit.role == world::UnitRole::Photographer) {
        f->spec = unit.camera;
        break;
      }
    }
    const world::InterestPointSet& points = f->scenario.interestPoints;
    const double radius = sensing::candidateRadius(f->spec);
    std::vector<uint32_t> near;
    for (size_t i = 0; i < points.size() && f->poses.size() < 64; i += 3) {
      const sensing::CaptureState state =
          sensing::aimCamera(f->spec, points[i].position, -points[i].normal, 6.0);
      points.withinRadius(sensing::cameraPose(f->spec, state).position, radius, near);
      if (near.size() >= 60 && near.size() <= 160) f->poses.push_back(state);
    }
    return f;
  }();
  return instance.get();
}

void scoreCaptures(benchmark::State& state, sensing::ScoringMode mode) {
  const MbsFixture* f = fixture();
  if (f == nullptr) {
    state.SkipWithError("CARIC MBS data not found under COINSPECT_SHARED_DIR");
    return;
  }
  if (f->poses.empty()) {
    state.SkipWithError("no camera pose with 60-160 candidate points");
    return;
  }
  sensing::InspectionScorer scorer(f->scenario.interestPoints, *f->caster, mode);
  std::vector<sensing::PointScore> out;
  const sensing::Occluders none;
  size_t candidates = 0, seen = 0, captures = 0;
  for (auto _ : state) {
    for (const sensing::CaptureState& pose : f->poses) {
      scorer.score(f->spec, pose, none, out);
      candidates += out.size();
      for (const sensing::PointScore& ps : out)
        seen += ps.seen ? 1 : 0;
      ++captures;
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(captures));
  state.counters["captures/s"] =
      benchmark::Counter(static_cast<double>(captures), benchmark::Counter::kIsRate);
  state.counters["points/s"] =
      benchmark::Counter(static_cast<double>(candidates), benchmark::Counter::kIsRate);
  state.counters["candidates"] =
      captures ? static_cast<double>(candidates) / static_cast<double>(captures) : 0.0;
  state.counters["seen_fraction"] =
      candidates ? static_cast<double>(seen) / static_cast<double>(candidates) : 0.0;
  state.counters["poses"] = static_cast<double>(f->poses.size());
}

void BM_ScoreCaptureCaric(benchmark::State& state) {
  scoreCaptures(state, sensing::ScoringMode::Caric);
}
void BM_ScoreCaptureStrict(benchmark::State& state) {
  scoreCaptures(state, sensing::ScoringMode::Strict);
}

BENCHMARK(BM_ScoreCaptureCaric)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScoreCaptureStrict)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
