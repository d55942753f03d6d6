// The registry of scenario generators (generators.h).
#include "coinspect/world/generators.h"

#include "coinspect/core/error.h"
#include "generator_detail.h"

namespace coinspect::world {

namespace {

struct Entry {
  GeneratorInfo info;
  Scenario (*generate)(uint64_t seed) = nullptr;  // caric
  Scenario (*generateSlei)(uint64_t seed, const std::optional<SleiFleet>& fleet) = nullptr;
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> table{
      {{"mbs", "caric",
        "Marina Bay Sands: three towers under a sky deck, lotus museum (~140 x 62 x 60 m)"},
       detail::generateMbs},
      {{"hangar", "caric",
        "Aircraft hangar with an open door and an airliner inside (~78 x 62 x 22 m)"},
       detail::generateHangar},
      {{"crane", "caric", "Construction site with three lattice tower cranes (~122 x 80 x 56 m)"},
       detail::generateCrane},
      {{"burj-khalifa", "caric",
        "Y-plan tower with spiralling setbacks and spire, scale 0.22 (~185 m high)"},
       detail::generateBurjKhalifa},
      {{"burj-al-arab", "caric",
        "Sail-shaped tower on an island with helipad and mast, scale 0.4 (~128 m high)"},
       detail::generateBurjAlArab},
      {{"slei-a", "slei", "SLEI3D scene A: 8 ancient structures, 60 x 50 x 9 m, 150 features"},
       nullptr,
       detail::generateSleiA},
      {{"slei-b", "slei", "SLEI3D scene B: one building, 18 x 20 x 15 m, 150 features"},
       nullptr,
       detail::generateSleiB},
      {{"slei-c", "slei", "SLEI3D scene C: city blocks, 70 x 60 x 30 m, 150 features"},
       nullptr,
       detail::generateSleiC},
      {{"slei-d", "slei", "SLEI3D scene D: large ancient site, 120 x 160 x 20 m, 150 features"},
       nullptr,
       detail::generateSleiD},
  };
  return table;
}

}  // namespace

const std::vector<GeneratorInfo>& scenarioGenerators() {
  static const std::vector<GeneratorInfo> infos = [] {
    std::vector<GeneratorInfo> list;
    for (const Entry& entry : entries())
      list.push_back(entry.info);
    return list;
  }();
  return infos;
}

std::string sleiFleetProblem(const SleiFleet& fleet) {
  const struct {
    int value, low, high;
    const char* what;
  } counts[] = {{fleet.stations, 1, 20, "stations"},
                {fleet.explorers, 1, 100, "explorers"},
                {fleet.inspectors, 0, 400, "inspectors"}};
  for (const auto& c : counts)
    if (c.value < c.low || c.value > c.high)
      return std::to_string(c.value) + " " + c.what + ": must be from " + std::to_string(c.low) +
             " to " + std::to_string(c.high);
  return "";
}

std::string generatorNames() {
  std::string names;
  for (const auto& generator : scenarioGenerators())
    names += (names.empty() ? "" : ", ") + generator.name;
  return names;
}

Scenario generateScenario(const std::string& name, uint64_t seed,
                          const std::optional<SleiFleet>& fleet) {
  for (const Entry& entry : entries()) {
    if (entry.info.name != name) continue;
    if (!entry.generateSlei) {
      if (fleet) throw InputError("scenario", name, "a fleet size is for the slei-* scenes only");
      return entry.generate(seed);
    }
    if (fleet) {
      const std::string problem = sleiFleetProblem(*fleet);
      if (!problem.empty()) throw InputError("scenario", name, "fleet: " + problem);
    }
    return entry.generateSlei(seed, fleet);
  }
  throw InputError("scenario", name,
                   "unknown scenario generator (known: " + generatorNames() + ")");
}

}  // namespace coinspect::world
