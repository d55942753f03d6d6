// Tall landmark towers with the CARIC fleet: a Burj-Khalifa-like stepped Y-plan tower and a
// Burj-Al-Arab-like sail. Both are scaled down so a mission stays within a CARIC-sized budget:
// Burj Khalifa at 0.22 of its 828 m, Burj Al Arab at 0.4 of its 321 m.
#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"
#include "generator_detail.h"

namespace coinspect::world::detail {

namespace {

constexpr double kDeg = M_PI / 180.0;

double jitter(Rng& rng, double value, double fraction) {
  return value * (1.0 + rng.uniform(-fraction, fraction));
}

std::vector<UnitSpec> fullCaricFleet(const Vec2& center, double radius, double desiredMmPerPx) {
  // The five UAVs on the ground in an arc on one side, the GCS on a 20 m mast behind them.
  const std::pair<const char*, UnitRole> units[] = {{"jurong", UnitRole::Explorer},
                                                    {"raffles", UnitRole::Explorer},
                                                    {"sentosa", UnitRole::Photographer},
                                                    {"changi", UnitRole::Photographer},
                                                    {"nanyang", UnitRole::Photographer}};
  std::vector<UnitSpec> fleet{makeUnit("gcs", UnitRole::GroundStation,
                                       Vec3(center.x() - radius - 8.0, center.y(), 20.0),
                                       desiredMmPerPx)};
  for (int i = 0; i < 5; ++i) {
    const double a = M_PI + (i - 2) * 12.0 * kDeg;
    fleet.push_back(
        makeUnit(units[i].first, units[i].second,
                 Vec3(center.x() + radius * std::cos(a), center.y() + radius * std::sin(a), 0.1),
                 desiredMmPerPx));
  }
  return fleet;
}

// Boxes stacked along z, each covering (with `margin`) the parts that reach into its slice.
std::vector<OrientedBox> stackedBoxes(const SceneBuilder& scene, const std::string& structure,
                                      const std::string& prefix, const std::vector<double>& levels,
                                      double margin) {
  std::vector<OrientedBox> boxes;
  for (size_t i = 0; i + 1 < levels.size(); ++i) {
    Aabb slice;
    for (const auto& part : scene.parts()) {
      if (part.structure != structure) continue;
      if (part.bounds.max.z() < levels[i] || part.bounds.min.z() > levels[i + 1]) continue;
      slice.extend(part.bounds.min);
      slice.extend(part.bounds.max);
    }
    COINSPECT_ASSERT(!slice.empty());
    const Vec3 low(slice.min.x() - margin, slice.min.y() - margin, levels[i]);
    const Vec3 high(slice.max.x() + margin, slice.max.y() + margin, levels[i + 1]);
    boxes.push_back(
        makeInspectionBox(prefix + std::to_string(i + 1), 0.5 * (low + high), high - low));
  }
  return boxes;
}

}  // namespace

Scenario generateBurjKhalifa(uint64_t seed) {
  Rng rng(seed);
  Rng pointRng = rng.fork(1);
  SceneBuilder scene;
  const std::string name = "tower";
  // Y plan: three wings around a hexagonal core; each tier pulls one wing in, turning around the
  // tower (the real building's spiral of setbacks), while the wings slim down.
  const double phase = rng.uniform(0.0, 2.0 * M_PI);
  const double wing = jitter(rng, 20.0, 0.03), halfWidth0 = jitter(rng, 5.2, 0.03);
  const double shortestWing = 12.0, step = (wing - shortestWing) / 3.0;
  const int direction = rng.uniform() < 0.5 ? 1 : 2;  // which way the setbacks turn
  std::vector<double> lengths(3, wing);
  const double tierHeights[] = {18.0, 17.0, 16.0, 15.0, 14.5, 14.0, 13.5, 12.5, 11.5};
  double z = 0.0;
  for (int k = 0; k < 9; ++k) {
    if (k > 0) lengths[static_cast<size_t>(((k - 1) * direction) % 3)] -= step;
    const double halfWidth = halfWidth0 - 0.2 * k;
    const double top = z + jitter(rng, tierHeights[k], 0.03);
    scene.add(name, makePrism(yPlan(lengths, halfWidth, phase, 10), z, top, Vec2::Zero()));
    z = top;
  }
  // Crown: hexagonal core, a tapering drum, then the spire.
  const double coreTop = z + 14.0;
  scene.add(name, makePrism(regularPolygon(Vec2::Zero(), 5.0, 6, phase), z, coreTop));
  scene.add(name, makeFrustum(Vec3(0, 0, coreTop), 3.6, 2.2, 14.0, 12));
  const double spire = jitter(rng, 26.0, 0.05);
  scene.add(name, makeFrustum(Vec3(0, 0, coreTop + 14.0), 1.6, 0.0, spire, 8));
  const double height = coreTop + 14.0 + spire;

  auto boxes = stackedBoxes(scene, name, "tier", {0.0, 45.0, 90.0, 135.0, height + 1.0}, 2.0);
  SurfaceSampling sampling;
  auto points = sampleSurfacePoints(scene, boxes, sampling, pointRng);
  return assembleScenario(
      "burj-khalifa",
      "Burj-Khalifa-like Y-plan tower in 9 spiralling setback tiers with spire, scale 0.22 "
      "(~185 m); 4 boxes stacked by height",
      scene, std::move(boxes), std::move(points), fullCaricFleet(Vec2::Zero(), 32.0, 2.0), 900.0);
}

Scenario generateBurjAlArab(uint64_t seed) {
  Rng rng(seed);
  Rng pointRng = rng.fork(1);
  SceneBuilder scene;

  // Island plinth (not inspected): the building stands on it with its back (spine) at x = 0 and
  // the sail bulging towards +x.
  scene.add("island", makePrism(regularPolygon(Vec2(12.0, 0.0), 32.0, 8, M_PI / 8), 0.0, 3.0));

  const std::string name = "sail";
  const double base = 3.0, bodyTop = jitter(rng, 108.0, 0.03);
  const double depth0 = jitter(rng, 42.0, 0.04), width0 = jitter(rng, 40.0, 0.04);
  const double cornerFraction = 0.62;
  const auto depthAt = [&](double f) { return depth0 * std::pow(1.0 - std::pow(f, 2.2), 0.5); };
  const auto widthAt = [&](double f) { return width0 * (1.0 - 0.75 * std::pow(f, 1.3)); };
  const auto ring = [&](double f) {
    const double d = depthAt(f), w = widthAt(f), zf = base + f * (bodyTop - base);
    const Vec2 corner(cornerFraction * d, 0.5 * w);
    std::vector<Vec3> points{Vec3(0.0, 0.0, zf)};
    for (const double t : {1.0 / 3.0, 2.0 / 3.0})
      points.emplace_back(t * corner.x(), -t * corner.y(), zf);
    // The sail: a bulge from one wing tip to the other through the front.
    const int arc = 24;
    for (int i = 0; i <= arc; ++i) {
      const double t = -1.0 + 2.0 * i / arc;
      const double bulge = std::pow(std::max(0.0, 1.0 - t * t), 0.6);
      points.emplace_back(corner.x() + (1.0 - cornerFraction) * d * bulge, t * corner.y(), zf);
    }
    for (const double t : {2.0 / 3.0, 1.0 / 3.0})
      points.emplace_back(t * corner.x(), t * corner.y(), zf);
    return points;
  };
  std::vector<std::vector<Vec3>> rings;
  const int levels = 24;
  for (int k = 0; k <= levels; ++k)
    rings.push_back(ring(0.96 * k / levels));
  scene.add(name, makeLoft(rings, std::nullopt, Vec3(2.0, 0.0, bodyTop)));

  // Helipad cantilevered from the side near the top.
  const double padF = rng.uniform(0.76, 0.82), padZ = base + padF * (bodyTop - base);
  const double padX = 0.5 * cornerFraction * depthAt(padF);
  const double edgeY = 0.5 * 0.5 * widthAt(padF);
  const Vec3 padCenter(padX, -(edgeY + 5.5), padZ);
  scene.add(name, makeFrustum(padCenter, 6.0, 6.0, 0.8, 20));
  scene.add(name, makeBeam(Vec3(padX, -edgeY + 2.0, padZ - 2.0),
                           Vec3(padX, padCenter.y(), padZ + 0.2), 1.0));

  // Exoskeleton legs behind the spine, braced, and the mast above the top.
  const double legSpread = 0.3 * width0;
  for (const double side : {-1.0, 1.0})
    scene.add(name, makeBeam(Vec3(-2.5, side * legSpread, base - 0.5),
                             Vec3(-0.6, side * 1.5, bodyTop - 6.0), 1.4));
  for (const double f : {0.25, 0.5, 0.75}) {
    const double y = legSpread + f * (1.5 - legSpread);
    const double zf = base - 0.5 + f * (bodyTop - 6.0 - base + 0.5);
    const double x = -2.5 + f * 1.9;
    scene.add(name, makeBeam(Vec3(x, -y, zf), Vec3(x, y, zf), 0.8));
  }
  const double mastTop = bodyTop + jitter(rng, 20.0, 0.05);
  scene.add(name, makeBeam(Vec3(0.5, 0.0, bodyTop - 10.0), Vec3(1.0, 0.0, mastTop), 1.0));

  auto boxes = stackedBoxes(scene, name, "sail", {base + 0.5, 40.0, 75.0, bodyTop + 2.0}, 2.0);
  SurfaceSampling sampling;
  auto points = sampleSurfacePoints(scene, boxes, sampling, pointRng);
  return assembleScenario(
      "burj-al-arab",
      "Burj-Al-Arab-like sail-shaped tower on an island plinth with helipad and mast, scale 0.4 "
      "(~128 m); 3 boxes stacked by height",
      scene, std::move(boxes), std::move(points), fullCaricFleet(Vec2(12.0, 0.0), 38.0, 2.0),
      600.0);
}

}  // namespace coinspect::world::detail
