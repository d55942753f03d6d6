// SLEI3D-like scenarios (slei3d-reference.md): the paper's four scenes rebuilt from primitives
// at their published extents, each with exactly 150 features (interest points) spread over the
// boxes, and the paper's fleet of the scene: 1 ground GCS, 2 explorers and 4 inspectors (A, and
// B, where the paper flies 1 + 3), 4 + 8 (C), 8 + 40 (D).
#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"
#include "generator_detail.h"

namespace coinspect::world::detail {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr size_t kFeatures = 150;

double jitter(Rng& rng, double value, double fraction) {
  return value * (1.0 + rng.uniform(-fraction, fraction));
}

// A structure's local frame on the ground: x_world = center + Rz(yaw) x_local.
struct Placement {
  Vec2 center = Vec2::Zero();
  double yaw = 0.0;
  Vec3 at(double x, double y, double z) const {
    const Vec2 p = center + rotate2({x, y}, yaw);
    return {p.x(), p.y(), z};
  }
  // Axis-aligned box in local coordinates given by its centre and size.
  TriangleMesh box(double x, double y, double z, double sx, double sy, double sz) const {
    return makeBox(at(x, y, z), Vec3(sx, sy, sz), yaw);
  }
};

// Gable roof: triangle (across the local y axis) of `width` and `rise` on z0, along local x.
TriangleMesh gableRoof(const Placement& place, double cx, double length, double width, double z0,
                       double rise) {
  const std::vector<Vec2> profile{{-0.5 * width, 0.0}, {0.5 * width, 0.0}, {0.0, rise}};
  const Eigen::Matrix3d r = yawRotation(place.yaw);
  return makeExtrusion(profile, place.at(cx - 0.5 * length, 0.0, z0), r.col(1), Vec3::UnitZ(),
                       length * r.col(0));
}

// ---- Ancient structures (slei-a, slei-d) -----------------------------------------------------

void addHall(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  const double length = jitter(rng, 11.0, 0.05), depth = jitter(rng, 6.5, 0.05);
  scene.add(name, p.box(0, 0, 0.4, length + 2.0, depth + 2.5, 0.8));
  const double wallTop = 0.8 + jitter(rng, 4.0, 0.05);
  scene.add(name, p.box(0, 0, 0.5 * (0.8 + wallTop), length, depth, wallTop - 0.8));
  scene.add(name, gableRoof(p, 0.0, length + 1.4, depth + 1.6, wallTop, jitter(rng, 2.6, 0.05)));
  // Porch columns along the front.
  for (int i = 0; i < 4; ++i) {
    const double x = -0.5 * length + length * (i + 0.5) / 4.0;
    scene.add(name, makeFrustum(p.at(x, -0.5 * depth - 0.9, 0.8), 0.3, 0.26, wallTop - 0.8, 10));
  }
}

void addStupa(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  const double r = jitter(rng, 2.8, 0.05);
  scene.add(name, p.box(0, 0, 0.6, 2.5 * r, 2.5 * r, 1.2));
  scene.add(name, makeFrustum(p.at(0, 0, 1.2), r, r, 1.6, 20));
  scene.add(name, makeEllipsoid(p.at(0, 0, 2.8), Vec3(r, r, 0.93 * r), Eigen::Matrix3d::Identity(),
                                20, 12));
  const double domeTop = 2.8 + 0.93 * r;
  scene.add(name, p.box(0, 0, domeTop + 0.3, 1.2, 1.2, 1.0));
  scene.add(name, makeFrustum(p.at(0, 0, domeTop + 0.8), 0.5, 0.0, 8.8 - domeTop - 0.8, 10));
}

void addPagoda(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  const double base = jitter(rng, 5.0, 0.05);
  double z = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double size = base - 0.7 * k;
    scene.add(name, p.box(0, 0, z + 0.85, size, size, 1.7));
    scene.add(name, p.box(0, 0, z + 1.85, size + 1.6, size + 1.6, 0.3));
    z += 2.0;
  }
  scene.add(name, makeFrustum(p.at(0, 0, z), 0.6, 0.0, 1.0, 8));
}

void addGate(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  const double half = jitter(rng, 3.5, 0.05);
  for (const double side : {-1.0, 1.0})
    scene.add(name, p.box(side * half, 0, 3.0, 0.9, 0.9, 6.0));
  scene.add(name, p.box(0, 0, 5.35, 2 * half + 2.5, 0.9, 0.7));
  scene.add(name, p.box(0, 0, 5.8, 0.6, 0.6, 0.5));
  scene.add(name, p.box(0, 0, 6.3, 2 * half + 3.5, 1.1, 0.6));
  // Guardian blocks before the pillars.
  for (const double side : {-1.0, 1.0})
    scene.add(name, p.box(side * (half + 1.2), -2.0, 0.6, 1.0, 1.6, 1.2));
}

void addColonnade(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  const double spacing = jitter(rng, 3.0, 0.05), height = jitter(rng, 5.0, 0.05);
  const int columns = 5;
  const double length = spacing * (columns - 1);
  scene.add(name, p.box(0, 0, 0.25, length + 3.0, 7.0, 0.5));
  for (const double y : {-2.2, 2.2}) {
    for (int i = 0; i < columns; ++i) {
      // Ruined: one column of each row may be broken off.
      const double h = (i == static_cast<int>(rng.below(columns))) ? 0.4 * height : height;
      const double x = -0.5 * length + i * spacing;
      scene.add(name, makeFrustum(p.at(x, y, 0.5), 0.45, 0.38, h, 12));
    }
    scene.add(name, p.box(0, y, 0.5 + height + 0.35, length + 1.2, 1.0, 0.8));
  }
}

void addRuins(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  const double w = jitter(rng, 10.0, 0.05), d = jitter(rng, 7.0, 0.05);
  const double h0 = rng.uniform(2.5, 3.5), h1 = rng.uniform(1.5, 3.0), h2 = rng.uniform(1.5, 3.0);
  scene.add(name, p.box(0, 0.5 * d - 0.4, 0.5 * h0, w, 0.8, h0));
  scene.add(name, p.box(-0.5 * w + 0.4, 0, 0.5 * h1, 0.8, d, h1));
  scene.add(name, p.box(0.5 * w - 0.4, 0.15 * d, 0.5 * h2, 0.8, 0.7 * d, h2));
  scene.add(name, p.box(-1.0, 0.5, 0.6, 0.8, 3.0, 1.2));
  for (int i = 0; i < 4; ++i)
    scene.add(name, p.box(rng.uniform(-0.3 * w, 0.3 * w), rng.uniform(-0.5 * d, -0.1 * d), 0.4, 1.0,
                          0.8, 0.8));
}

void addShrine(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  const double size = jitter(rng, 4.0, 0.05);
  scene.add(name, p.box(0, 0, 0.3, size + 1.2, size + 1.2, 0.6));
  scene.add(name, p.box(0, 0, 2.1, size, size, 3.0));
  // Pyramid roof: a four-sided cone, corners on the diagonals of the cella.
  const double roofR = 0.75 * size * std::sqrt(2.0);
  TriangleMesh roof = makeFrustum(Vec3::Zero(), roofR, 0.0, 2.2, 4);
  MeshTransform placeRoof;
  placeRoof.yaw = p.yaw + M_PI / 4;
  placeRoof.translation = p.at(0, 0, 3.6);
  roof.transform(placeRoof);
  scene.add(name, std::move(roof));
}

void addObelisks(SceneBuilder& scene, const std::string& name, const Placement& p, Rng& rng) {
  for (int i = -1; i <= 1; ++i) {
    const double h = jitter(rng, 6.4, 0.06);
    const double x = 3.5 * i;
    scene.add(name, p.box(x, 0, 0.3, 1.6, 1.6, 0.6));
    std::vector<std::vector<Vec3>> rings(2);
    for (const auto& [sx, sy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      rings[0].push_back(p.at(x + 0.5 * sx, 0.5 * sy, 0.6));
      rings[1].push_back(p.at(x + 0.3 * sx, 0.3 * sy, 0.6 + h));
    }
    scene.add(name, makeLoft(rings, std::nullopt, p.at(x, 0, 0.6 + h + 0.8)));
  }
}

using StructureBuilder = void (*)(SceneBuilder&, const std::string&, const Placement&, Rng&);

// Ground-level enclosure wall around [-hx, hx] x [-hy, hy] with a gate in the south side;
// `broken` leaves random gaps and heights (ruins).
void addEnclosure(SceneBuilder& scene, double hx, double hy, double height, bool broken, Rng& rng) {
  const double t = 0.8, gate = 4.0;
  struct Run {
    Vec2 a, b;
  };
  const Run runs[] = {{{-hx, -hy + 0.5 * t}, {-gate, -hy + 0.5 * t}},
                      {{gate, -hy + 0.5 * t}, {hx, -hy + 0.5 * t}},
                      {{hx - 0.5 * t, -hy + t}, {hx - 0.5 * t, hy - t}},
                      {{hx, hy - 0.5 * t}, {-hx, hy - 0.5 * t}},
                      {{-hx + 0.5 * t, hy - t}, {-hx + 0.5 * t, -hy + t}}};
  for (const Run& run : runs) {
    const Vec2 dir = (run.b - run.a).normalized();
    const double length = (run.b - run.a).norm();
    const double yaw = std::atan2(dir.y(), dir.x());
    double s = 0.0;
    while (s < length - 0.5) {
      double piece = broken ? std::min(rng.uniform(6.0, 14.0), length - s) : length;
      // Keep the corners: the enclosure defines the site's extent.
      if (length - s - piece < 2.0) piece = length - s;
      const double h = broken ? rng.uniform(0.6, 1.0) * height : height;
      const Vec2 c = run.a + (s + 0.5 * piece) * dir;
      scene.add("walls", makeBox(Vec3(c.x(), c.y(), 0.5 * h), Vec3(piece, t, h), yaw));
      s += piece + (broken ? rng.uniform(1.5, 3.0) : 0.0);
    }
  }
}

// The paper's fleet of a scene (its Table I and section VI), or another size (`[mission] fleet`):
// the ground stations in a row 3 m behind the gate, the explorers in a row at the gate and the
// inspectors in rows of up to 10 behind the stations, 3-4 m apart so that no two start within
// each other's collision radius. A single station is "gcs", several are "gcs1", "gcs2", ...
std::vector<UnitSpec> sleiFleet(const Vec2& gate, const SleiFleet& size) {
  std::vector<UnitSpec> fleet;
  for (int i = 0; i < size.stations; ++i)
    // A GCS is a ground vehicle: it starts on the ground like the others.
    fleet.push_back(makeUnit(
        size.stations == 1 ? "gcs" : "gcs" + std::to_string(i + 1), UnitRole::GroundStation,
        Vec3(gate.x() - 2.0 * (size.stations - 1) + 4.0 * i, gate.y() - 3.0, 0.1), 2.0));
  for (int i = 0; i < size.explorers; ++i)
    fleet.push_back(makeUnit("explorer" + std::to_string(i + 1), UnitRole::Explorer,
                             Vec3(gate.x() - 2.0 * (size.explorers - 1) + 4.0 * i, gate.y(), 0.1),
                             2.0));
  const int perRow = std::max(1, std::min(size.inspectors, 10));
  for (int i = 0; i < size.inspectors; ++i) {
    const int row = i / perRow, column = i % perRow;
    fleet.push_back(makeUnit(
        "inspector" + std::to_string(i + 1), UnitRole::Photographer,
        Vec3(gate.x() - 1.5 * (perRow - 1) + 3.0 * column, gate.y() - 6.0 - 3.0 * row, 0.1), 2.0));
  }
  return fleet;
}

// Features lie more than this above the ground, as in the reference's feature server, which
// keeps only the map's points above 1 m (TRIO-PKU/SLEI3D, env_server/feature_server.py).
constexpr double kFeatureMinHeight = 1.0;

std::vector<InterestPoint> features(const SceneBuilder& scene,
                                    const std::vector<OrientedBox>& boxes, Rng& rng) {
  SurfaceSampling sampling;
  sampling.minSpacing = 0.8;  // only a pool for the farthest-point choice below
  auto pool = sampleSurfacePoints(scene, boxes, sampling, rng);
  pool.erase(std::remove_if(pool.begin(), pool.end(),
                            [&](const InterestPoint& p) {
                              return p.position.z() <= sampling.groundZ + kFeatureMinHeight;
                            }),
             pool.end());
  return farthestPointSubset(pool, kFeatures, rng);
}

Scenario finishSlei(const std::string& name, const std::string& description, SceneBuilder& scene,
                    std::vector<OrientedBox> boxes, const Vec2& gate, double budget, Rng& rng,
                    const SleiFleet& fleetSize) {
  auto points = features(scene, boxes, rng);
  return assembleScenario(name, description, scene, std::move(boxes), std::move(points),
                          sleiFleet(gate, fleetSize), budget);
}

}  // namespace

Scenario generateSleiA(uint64_t seed, const std::optional<SleiFleet>& fleet) {
  Rng rng(seed);
  Rng layoutRng = rng.fork(1), pointRng = rng.fork(2);
  SceneBuilder scene;
  addEnclosure(scene, 30.0, 25.0, 2.2, false, layoutRng);
  // Eight structures in a 4 x 2 grid, in a seed-dependent order, long axes along y.
  std::vector<std::pair<const char*, StructureBuilder>> kinds{
      {"hall", addHall},     {"stupa", addStupa},         {"pagoda", addPagoda},
      {"gate", addGate},     {"colonnade", addColonnade}, {"ruins", addRuins},
      {"shrine", addShrine}, {"obelisks", addObelisks}};
  for (size_t i = kinds.size(); i > 1; --i)
    std::swap(kinds[i - 1], kinds[layoutRng.below(i)]);
  std::vector<OrientedBox> boxes;
  for (size_t i = 0; i < kinds.size(); ++i) {
    Placement place;
    place.center = Vec2(-22.5 + 15.0 * static_cast<double>(i % 4) + layoutRng.uniform(-0.8, 0.8),
                        (i < 4 ? -12.0 : 12.0) + layoutRng.uniform(-2.0, 2.0));
    place.yaw = M_PI / 2 + layoutRng.uniform(-6.0, 6.0) * kDeg;
    const std::string name = kinds[i].first;
    kinds[i].second(scene, name, place, layoutRng);
    boxes.push_back(boxAround(name, scene.bounds(name), 1.0));
  }
  return finishSlei("slei-a",
                    "SLEI3D scene A: walled cluster of 8 ancient structures, 60 x 50 x 9 m; "
                    "8 boxes, 150 features",
                    scene, std::move(boxes), Vec2(0.0, -29.0), 1200.0, pointRng,
                    fleet.value_or(SleiFleet{}));
}

Scenario generateSleiB(uint64_t seed, const std::optional<SleiFleet>& fleet) {
  Rng rng(seed);
  Rng pointRng = rng.fork(2);
  SceneBuilder scene;
  const std::string name = "building";
  const Placement p;
  // Body 16 x 17 x 10 m, gable roof to 14.2 m with 1 m eaves, porch at the front (-y), chimney.
  const double wallTop = jitter(rng, 10.0, 0.03);
  scene.add(name, p.box(0, 0.5, 0.5 * wallTop, 16.0, 17.0, wallTop));
  {
    const std::vector<Vec2> profile{{-9.0, 0.0}, {9.0, 0.0}, {0.0, 4.2}};
    scene.add(name, makeExtrusion(profile, Vec3(0, -8.5, wallTop), Vec3::UnitX(), Vec3::UnitZ(),
                                  Vec3(0, 19.0, 0)));
  }
  scene.add(name, p.box(0, -9.25, 3.4, 8.0, 2.5, 0.4));
  for (const double x : {-3.6, 3.6})
    scene.add(name, makeFrustum(p.at(x, -10.2, 0), 0.2, 0.2, 3.3, 16));
  const double chimneyX = rng.uniform(3.5, 5.5), chimneyY = rng.uniform(-4.0, 6.0);
  scene.add(name, p.box(chimneyX, chimneyY, 0.5 * (wallTop - 1.0 + 14.6), 1.2, 1.2,
                        14.6 - (wallTop - 1.0)));
  for (const double dy : {-0.3, 0.3})
    scene.add(name, makeFrustum(p.at(chimneyX, chimneyY + dy, 14.6), 0.2, 0.16, 0.45, 12));
  // Dormers on both roof slopes: a box half sunk into the roof under a small gable.
  for (const double side : {-1.0, 1.0})
    for (const double y : {-3.0, 4.0}) {
      const double x = side * 4.5;
      scene.add(name, p.box(x, y, wallTop + 1.6, 2.5, 2.0, 2.2));
      const std::vector<Vec2> gable{{-1.2, 0.0}, {1.2, 0.0}, {0.0, 0.9}};
      scene.add(name, makeExtrusion(gable, Vec3(x - 1.35, y, wallTop + 2.7), Vec3::UnitY(),
                                    Vec3::UnitZ(), Vec3(2.7, 0, 0)));
    }
  // Round bay window on the back and downpipes at the corners.
  scene.add(name, makeFrustum(p.at(0, 9.0, 0), 1.6, 1.6, 7.5, 24));
  for (const double x : {-8.1, 8.1})
    for (const double y : {-7.9, 8.9})
      scene.add(name, makeFrustum(p.at(x, y, 0), 0.1, 0.1, wallTop - 0.2, 8));
  // Window frames standing out of the facades, on two floors.
  for (const double z : {2.6, 6.6}) {
    for (int i = 0; i < 4; ++i) {
      const double y = -6.0 + 4.0 * i + 0.5;
      for (const double side : {-1.0, 1.0})
        scene.add(name, p.box(side * 8.05, y, z, 0.3, 1.4, 1.8));
    }
    for (const double x : {-5.0, 0.0, 5.0}) {
      if (z < 5.0 && x == 0.0) continue;  // the door behind the porch
      scene.add(name, p.box(x, -8.05, z, 1.4, 0.3, 1.8));
      scene.add(name, p.box(x, 9.05, z, 1.4, 0.3, 1.8));
    }
  }
  // Balcony on the +x side.
  scene.add(name, p.box(8.7, 3.0, 6.0, 1.6, 4.0, 0.3));
  scene.add(name, p.box(9.35, 3.0, 6.6, 0.1, 4.0, 0.9));

  std::vector<OrientedBox> boxes;
  const Aabb all = scene.bounds();
  const Vec3 mid = 0.5 * (all.min + all.max);
  const char* names[] = {"southwest", "southeast", "northwest", "northeast"};
  for (int i = 0; i < 4; ++i) {
    const double x0 = i % 2 == 0 ? all.min.x() - 1.0 : mid.x();
    const double x1 = i % 2 == 0 ? mid.x() : all.max.x() + 1.0;
    const double y0 = i < 2 ? all.min.y() - 1.0 : mid.y();
    const double y1 = i < 2 ? mid.y() : all.max.y() + 1.0;
    boxes.push_back(makeInspectionBox(names[i], Vec3(0.5 * (x0 + x1), 0.5 * (y0 + y1), 8.0),
                                      Vec3(x1 - x0, y1 - y0, 16.0)));
  }
  return finishSlei("slei-b",
                    "SLEI3D scene B: one large gabled building with porch, chimney and window "
                    "frames, 18 x 20 x 15 m; 4 boxes, 150 features",
                    scene, std::move(boxes), Vec2(0.0, -16.0), 1200.0, pointRng,
                    fleet.value_or(SleiFleet{}));
}

Scenario generateSleiC(uint64_t seed, const std::optional<SleiFleet>& fleet) {
  Rng rng(seed);
  Rng layoutRng = rng.fork(1), pointRng = rng.fork(2);
  SceneBuilder scene;
  std::vector<OrientedBox> boxes;
  // 3 x 3 blocks of 18 x 15 m between 8 m and 7.5 m streets: 70 x 60 m. The centre block holds
  // the 30 m landmark; the others draw one of five block types.
  for (int by = 0; by < 3; ++by)
    for (int bx = 0; bx < 3; ++bx) {
      const std::string name = "block" + std::to_string(by * 3 + bx + 1);
      const Vec2 c(-26.0 + 26.0 * bx, -22.5 + 22.5 * by);
      // A kerb slab over the whole plot keeps every block's footprint (and the city's extent).
      scene.add(name, makeBox(Vec3(c.x(), c.y(), 0.15), Vec3(18.0, 15.0, 0.3)));
      const int kind = (bx == 1 && by == 1) ? 5 : static_cast<int>(layoutRng.below(5));
      const auto box = [&](double x, double y, double z0, double sx, double sy, double h) {
        scene.add(name, makeBox(Vec3(c.x() + x, c.y() + y, z0 + 0.5 * h), Vec3(sx, sy, h)));
      };
      switch (kind) {
        case 0: {  // slab tower with a rooftop plant room
          const double h = layoutRng.uniform(16.0, 24.0);
          box(0, 0, 0.3, 14.0, 11.0, h);
          box(layoutRng.uniform(-3, 3), layoutRng.uniform(-2, 2), 0.3 + h, 4.0, 3.0, 2.0);
          break;
        }
        case 1: {  // two buildings side by side
          box(-4.5, 0, 0.3, 8.0, 13.0, layoutRng.uniform(8.0, 20.0));
          box(4.5, 0, 0.3, 8.0, 13.0, layoutRng.uniform(8.0, 20.0));
          break;
        }
        case 2: {  // L-shaped block (fan from inside the corner square)
          const double h = layoutRng.uniform(10.0, 18.0);
          const std::vector<Vec2> plan{{-8, -6.5}, {8, -6.5}, {8, -1.5},
                                       {-3, -1.5}, {-3, 6.5}, {-8, 6.5}};
          std::vector<Vec2> shifted;
          for (const Vec2& q : plan)
            shifted.push_back(c + q);
          scene.add(name, makePrism(shifted, 0.3, 0.3 + h, Vec2(c + Vec2(-5.5, -4.0))));
          box(3.0, 3.0, 0.3, 4.0, 4.0, 4.0);  // a pavilion in the open corner
          break;
        }
        case 3: {  // courtyard block: four wings around a court
          const double h = layoutRng.uniform(10.0, 14.0);
          box(0, -5.5, 0.3, 16.0, 3.0, h);
          box(0, 5.5, 0.3, 16.0, 3.0, h);
          box(-6.5, 0, 0.3, 3.0, 8.0, h);
          box(6.5, 0, 0.3, 3.0, 8.0, h);
          break;
        }
        case 4: {  // round tower on a podium
          box(0, 0, 0.3, 16.0, 13.0, 5.0);
          scene.add(name, makeFrustum(Vec3(c.x(), c.y(), 5.3), 5.5, 4.5,
                                      layoutRng.uniform(12.0, 20.0), 24));
          break;
        }
        default: {  // the landmark: podium, stepped tower, crown to 30 m
          box(0, 0, 0.3, 17.0, 14.0, 6.0);
          box(0, 0, 6.3, 11.0, 9.0, 14.0);
          box(0, 0, 20.3, 8.0, 6.5, 6.0);
          scene.add(name, makeFrustum(Vec3(c.x(), c.y(), 26.3), 2.5, 0.6, 3.7, 8));
          break;
        }
      }
      if (kind != 5) {
        // A water tank on the highest roof of the block.
        const SceneBuilder::Part* roof = nullptr;
        for (const auto& part : scene.parts())
          if (part.structure == name && (!roof || part.bounds.max.z() > roof->bounds.max.z()))
            roof = &part;
        const Vec3 top = 0.5 * (roof->bounds.min + roof->bounds.max);
        scene.add(name,
                  makeFrustum(Vec3(top.x(), top.y(), roof->bounds.max.z()), 1.2, 1.2, 2.0, 20));
      }
      boxes.push_back(boxAround(name, scene.bounds(name), 1.0));
    }
  return finishSlei("slei-c",
                    "SLEI3D scene C: 3 x 3 city blocks of varied buildings up to 30 m, "
                    "70 x 60 x 30 m; 9 boxes, 150 features; 4 explorers, 8 inspectors",
                    scene, std::move(boxes), Vec2(0.0, -36.0), 3000.0, pointRng,
                    fleet.value_or(SleiFleet{1, 4, 8}));
}

Scenario generateSleiD(uint64_t seed, const std::optional<SleiFleet>& fleet) {
  Rng rng(seed);
  Rng layoutRng = rng.fork(1), pointRng = rng.fork(2);
  SceneBuilder scene;
  addEnclosure(scene, 60.0, 80.0, 3.0, true, layoutRng);
  std::vector<OrientedBox> boxes;

  // Central stepped pyramid, 36 m base, five 4 m tiers to 20 m, with a ramp up its south face.
  {
    const std::string name = "ziggurat";
    const Vec2 c(0.0, 10.0);
    const double base = jitter(layoutRng, 36.0, 0.03);
    const double tier = 4.0;
    double size = base;
    for (int k = 0; k < 5; ++k) {
      scene.add(name, makeBox(Vec3(c.x(), c.y(), tier * (k + 0.5)), Vec3(size, size, tier)));
      size -= 0.19 * base;
    }
    const double topHalf = 0.5 * (size + 0.19 * base);
    const std::vector<Vec2> ramp{
        {-(topHalf - 1.0), 0.0}, {-(0.5 * base + 18.0), 0.0}, {-(topHalf - 1.0), 5.0 * tier}};
    scene.add(name, makeExtrusion(ramp, Vec3(c.x() - 2.5, c.y(), 0.0), Vec3::UnitY(), Vec3::UnitZ(),
                                  Vec3(5.0, 0.0, 0.0)));
    boxes.push_back(boxAround(name, scene.bounds(name), 1.5));
  }
  // Avenue of obelisks leading to the ramp.
  {
    const std::string name = "avenue";
    for (int i = 0; i < 4; ++i)
      for (const double x : {-7.0, 7.0}) {
        Placement p;
        p.center = Vec2(x, -66.0 + 9.0 * i);
        p.yaw = M_PI / 2;
        addObelisks(scene, name, p, layoutRng);
      }
    boxes.push_back(boxAround(name, scene.bounds(name), 1.0));
  }
  struct Site {
    const char* name;
    StructureBuilder build;
    Vec2 center;
    double yaw;
  };
  const Site sites[] = {{"hall-nw", addHall, {-36.0, 45.0}, 0.0},
                        {"hall-ne", addHall, {36.0, 45.0}, 0.0},
                        {"hall-sw", addHall, {-36.0, -25.0}, 0.0},
                        {"hall-se", addHall, {36.0, -25.0}, 0.0},
                        {"stupa-w", addStupa, {-38.0, -58.0}, 0.0},
                        {"stupa-e", addStupa, {38.0, -58.0}, 0.0},
                        {"stupa-n", addStupa, {0.0, 64.0}, 0.0},
                        {"colonnade-w", addColonnade, {-36.0, 10.0}, M_PI / 2},
                        {"colonnade-e", addColonnade, {36.0, 10.0}, M_PI / 2},
                        {"pagoda-nw", addPagoda, {-40.0, 66.0}, 0.0},
                        {"pagoda-ne", addPagoda, {40.0, 66.0}, 0.0},
                        {"ruins", addRuins, {-20.0, -50.0}, 0.0},
                        {"shrine", addShrine, {20.0, -50.0}, 0.0}};
  for (const Site& site : sites) {
    Placement p;
    p.center = site.center + Vec2(layoutRng.uniform(-1.5, 1.5), layoutRng.uniform(-1.5, 1.5));
    p.yaw = site.yaw + layoutRng.uniform(-8.0, 8.0) * kDeg;
    site.build(scene, site.name, p, layoutRng);
    boxes.push_back(boxAround(site.name, scene.bounds(site.name), 1.0));
  }
  return finishSlei("slei-d",
                    "SLEI3D scene D: large walled ancient site with a 20 m stepped pyramid, "
                    "temples, stupas and an obelisk avenue, 120 x 160 x 20 m; 15 boxes, 150 "
                    "features; 8 explorers, 40 inspectors",
                    scene, std::move(boxes), Vec2(0.0, -86.0), 3600.0, pointRng,
                    fleet.value_or(SleiFleet{1, 8, 40}));
}

}  // namespace coinspect::world::detail
