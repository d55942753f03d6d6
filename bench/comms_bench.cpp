// Link topology updates per second on the CARIC MBS scenario (read from COINSPECT_SHARED_DIR).
//
// Units are placed at seeded random positions in the structure's bounding box grown by 15 m
// (x, y) and from 1 m to 10 m above its top, at least 2 m from any surface; 16 such layouts are
// cycled, one per update, so that the numbers are not those of one lucky geometry. Each update is
// what the simulator does at 50 Hz: the full N x N matrix. Time is per update; counters:
// updates/s, simulated seconds of 50 Hz topology per wall-clock second (its real-time factor) and
// the mean share of linked pairs.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "caric_mbs_fixture.h"
#include "coinspect/comms/link_model.h"
#include "coinspect/core/random.h"

namespace {

using namespace coinspect;
using world::Vec3;

constexpr int kLayouts = 16;

std::vector<std::vector<comms::LinkEndpoint>> layouts(const bench::CaricMbs& f, int units) {
  const world::Aabb box = f.scenario.bounds();
  Rng rng(7700 + static_cast<uint64_t>(units));
  std::vector<std::vector<comms::LinkEndpoint>> result(kLayouts);
  for (auto& layout : result) {
    while (layout.size() < static_cast<size_t>(units)) {
      const Vec3 p(rng.uniform(box.min.x() - 15, box.max.x() + 15),
                   rng.uniform(box.min.y() - 15, box.max.y() + 15),
                   rng.uniform(f.scenario.groundZ + 1.0, box.max.z() + 10.0));
      if (f.caster->distanceToSurface(p, 2.0) <= 2.0) continue;
      comms::LinkEndpoint e;
      e.position = p;
      e.antennaOffset = layout.size() % 3 == 0 ? 0.2 : 0.1;
      layout.push_back(e);
    }
  }
  return result;
}

void reportRates(benchmark::State& state, size_t linked, int units) {
  const double updates = static_cast<double>(state.iterations());
  state.counters["updates/s"] = benchmark::Counter(updates, benchmark::Counter::kIsRate);
  // Topology alone at 50 Hz: simulated seconds per wall-clock second (its real-time factor).
  state.counters["sim_s/s@50Hz"] = benchmark::Counter(updates / 50.0, benchmark::Counter::kIsRate);
  const double pairs = units * (units - 1) / 2.0;
  state.counters["linked_share"] = static_cast<double>(linked) / (updates * pairs);
}

void topologyUpdate(benchmark::State& state, const comms::LinkModel& model) {
  const bench::CaricMbs* f = bench::caricMbs();
  if (f == nullptr) {
    state.SkipWithError("CARIC MBS data not found under COINSPECT_SHARED_DIR");
    return;
  }
  const int units = static_cast<int>(state.range(0));
  const auto sets = layouts(*f, units);
  comms::LinkMatrix links;
  size_t linked = 0, k = 0;
  for (auto _ : state) {
    model.update(*f->caster, sets[k++ % kLayouts], links);
    linked += links.linkCount();
  }
  reportRates(state, linked, units);
}

void BM_CaricTopology(benchmark::State& state) {
  topologyUpdate(state, comms::CaricLinkModel());
}
void BM_RangeTopology(benchmark::State& state) {
  topologyUpdate(state, comms::RangeLinkModel(5.0));
}

// The reference's loop for comparison: pair by pair, antenna pair by antenna pair, one ray each,
// stopping at the first clear segment.
void BM_CaricTopologyPerPairLoop(benchmark::State& state) {
  const bench::CaricMbs* f = bench::caricMbs();
  if (f == nullptr) {
    state.SkipWithError("CARIC MBS data not found under COINSPECT_SHARED_DIR");
    return;
  }
  const int units = static_cast<int>(state.range(0));
  const auto sets = layouts(*f, units);
  const world::RayCaster& caster = *f->caster;
  comms::LinkMatrix links(static_cast<size_t>(units));
  size_t linked = 0, k = 0;
  for (auto _ : state) {
    const auto& layout = sets[k++ % kLayouts];
    links.clear();
    for (uint32_t i = 0; i < layout.size(); ++i) {
      const auto a = comms::antennaPositions(layout[i], caster.hasGround(), caster.groundZ());
      for (uint32_t j = i + 1; j < layout.size(); ++j) {
        const auto b = comms::antennaPositions(layout[j], caster.hasGround(), caster.groundZ());
        bool clear = false;
        for (size_t x = 0; x < 6 && !clear; ++x)
          for (size_t y = 0; y < 6 && !clear; ++y)
            clear = caster.segmentClear(a[x], b[y], world::kLinkClearanceTolerance);
        links.setLinked(i, j, clear);
      }
    }
    linked += links.linkCount();
  }
  reportRates(state, linked, units);
}

BENCHMARK(BM_CaricTopology)->Arg(5)->Arg(75)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CaricTopologyPerPairLoop)->Arg(5)->Arg(75)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RangeTopology)->Arg(5)->Arg(75)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
