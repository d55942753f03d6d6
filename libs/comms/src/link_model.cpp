#include "coinspect/comms/link_model.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "coinspect/core/error.h"

namespace coinspect::comms {

using world::Vec3;

namespace {

struct Pair {
  uint32_t i;
  uint32_t j;
};

// Pairs i < j of alive units, in row-major order (the order of every batch below).
std::vector<Pair> alivePairs(const std::vector<LinkEndpoint>& units) {
  std::vector<Pair> pairs;
  const auto n = static_cast<uint32_t>(units.size());
  for (uint32_t i = 0; i < n; ++i) {
    if (!units[i].alive) continue;
    for (uint32_t j = i + 1; j < n; ++j)
      if (units[j].alive) pairs.push_back({i, j});
  }
  return pairs;
}

void resetTo(LinkMatrix& out, size_t units) {
  if (out.size() == units)
    out.clear();
  else
    out = LinkMatrix(units);
}

struct AntennaPair {
  int a;  // antenna of the lower-index unit (0..5: +x, -x, +y, -y, +z, -z)
  int b;  // antenna of the other unit
};

// The 36 antenna pairs split into stages; a pair of units goes to the next stage only while
// every segment so far is blocked. First +z to +z, which passes over low obstacles and the
// ground; then the other like-for-like pairs, which look past an obstacle on one side; then the
// remaining 30 crossed pairs.
const std::vector<std::vector<AntennaPair>>& stagePlan() {
  static const std::vector<std::vector<AntennaPair>> plan = [] {
    std::vector<std::vector<AntennaPair>> stages(3);
    stages[0].push_back({4, 4});
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        if (a == 4 && b == 4) continue;
        stages[a == b ? 1 : 2].push_back({a, b});
      }
    return stages;
  }();
  return plan;
}

}  // namespace

std::array<Vec3, 6> antennaPositions(const LinkEndpoint& unit, bool hasGround, double groundZ) {
  COINSPECT_ASSERT(unit.position.allFinite() && std::isfinite(unit.antennaOffset));
  const Vec3& p = unit.position;
  const double b = unit.antennaOffset;
  std::array<Vec3, 6> antennas{p + Vec3(b, 0, 0), p - Vec3(b, 0, 0), p + Vec3(0, b, 0),
                               p - Vec3(0, b, 0), p + Vec3(0, 0, b), p - Vec3(0, 0, b)};
  // Only the -z antenna is clamped, as in the reference; the others may sit below the ground.
  if (hasGround) antennas[5].z() = std::max(groundZ + kAntennaGroundClearance, antennas[5].z());
  return antennas;
}

void CaricLinkModel::update(const world::RayCaster& caster, const std::vector<LinkEndpoint>& units,
                            LinkMatrix& out) const {
  resetTo(out, units.size());
  std::vector<std::array<Vec3, 6>> antennas;
  antennas.reserve(units.size());
  for (const LinkEndpoint& unit : units)
    antennas.push_back(antennaPositions(unit, caster.hasGround(), caster.groundZ()));
  std::vector<Pair> open = alivePairs(units);

  std::vector<Vec3> from, to;
  std::vector<uint8_t> clear;
  std::vector<Pair> stillBlocked;
  for (const std::vector<AntennaPair>& stage : stagePlan()) {
    if (open.empty()) break;
    // One batch per stage: every segment of the stage for every pair not linked yet.
    const size_t width = stage.size();
    from.clear();
    to.clear();
    for (const Pair& pair : open)
      for (const AntennaPair& segment : stage) {
        from.push_back(antennas[pair.i][segment.a]);
        to.push_back(antennas[pair.j][segment.b]);
      }
    caster.segmentsClear(from, to, world::kLinkClearanceTolerance, clear);
    stillBlocked.clear();
    for (size_t k = 0; k < open.size(); ++k) {
      const auto first = clear.begin() + static_cast<std::ptrdiff_t>(k * width);
      if (std::any_of(first, first + static_cast<std::ptrdiff_t>(width),
                      [](uint8_t c) { return c != 0; }))
        out.setLinked(open[k].i, open[k].j, true);
      else
        stillBlocked.push_back(open[k]);
    }
    open.swap(stillBlocked);
  }
}

RangeLinkModel::RangeLinkModel(double range) : range_(range) {
  if (!(std::isfinite(range) && range > 0.0))
    throw InputError("link model", "range",
                     "must be a finite positive distance in metres, got " + std::to_string(range));
}

void RangeLinkModel::update(const world::RayCaster& caster, const std::vector<LinkEndpoint>& units,
                            LinkMatrix& out) const {
  resetTo(out, units.size());
  std::vector<Pair> candidates;
  std::vector<Vec3> from, to;
  for (const Pair& pair : alivePairs(units)) {
    const Vec3& a = units[pair.i].position;
    const Vec3& b = units[pair.j].position;
    COINSPECT_ASSERT(a.allFinite() && b.allFinite());
    if ((b - a).norm() > range_) continue;
    candidates.push_back(pair);
    from.push_back(a);
    to.push_back(b);
  }
  std::vector<uint8_t> clear;
  caster.segmentsClear(from, to, world::kLinkClearanceTolerance, clear);
  for (size_t k = 0; k < candidates.size(); ++k)
    if (clear[k] != 0) out.setLinked(candidates[k].i, candidates[k].j, true);
}

std::unique_ptr<LinkModel> makeLinkModel(const std::string& name, double range,
                                         const std::string& source) {
  if (name == "caric") return std::make_unique<CaricLinkModel>();
  if (name == "range") {
    if (!(std::isfinite(range) && range > 0.0))
      throw InputError(
          source, "range",
          "must be a finite positive distance in metres, got " + std::to_string(range));
    return std::make_unique<RangeLinkModel>(range);
  }
  throw InputError(source, "link model",
                   "unknown link model '" + name + "'; expected 'caric' or 'range'");
}

}  // namespace coinspect::comms
