// CARIC-like scenarios: Marina Bay Sands, an aircraft hangar and a construction site with
// tower cranes, built from closed primitives. Dimensions follow the released CARIC scenarios
// (caric-reference.md); the seed jitters sizes and placements by a few percent.
#include <cmath>

#include "coinspect/core/error.h"
#include "generator_detail.h"

namespace coinspect::world::detail {

namespace {

constexpr double kDeg = M_PI / 180.0;

double jitter(Rng& rng, double value, double fraction) {
  return value * (1.0 + rng.uniform(-fraction, fraction));
}

// Units named as in the reference: jurong and raffles explore, the others photograph.
std::vector<UnitSpec> caricFleet(const std::vector<std::pair<std::string, Vec3>>& starts,
                                 double desiredMmPerPx) {
  std::vector<UnitSpec> fleet;
  for (const auto& [name, start] : starts) {
    const UnitRole role = name == "gcs"                             ? UnitRole::GroundStation
                          : (name == "jurong" || name == "raffles") ? UnitRole::Explorer
                                                                    : UnitRole::Photographer;
    fleet.push_back(makeUnit(name, role, start, desiredMmPerPx));
  }
  return fleet;
}

// ---- Marina Bay Sands ------------------------------------------------------------------------

// A tower of two slabs: one vertical, one leaning in from a wider base until both meet under the
// sky deck, like the real hotel towers.
void addMbsTower(SceneBuilder& scene, const std::string& name, const Vec2& center, double yaw,
                 double length, double depth, double height, Rng& rng) {
  const double slabA = jitter(rng, 5.5, 0.05), slabB = jitter(rng, 5.5, 0.05);
  const Vec2 offsetA = rotate2({0.0, -0.5 * depth + 0.5 * slabA}, yaw);
  scene.add(name, makeBox(Vec3(center.x() + offsetA.x(), center.y() + offsetA.y(), 0.5 * height),
                          Vec3(length, slabA, height), yaw));
  std::vector<std::vector<Vec3>> rings;
  const int levels = 10;
  for (int k = 0; k <= levels; ++k) {
    const double t = static_cast<double>(k) / levels;
    const double f = std::pow(t, 1.6);
    // Slightly overlapping slab A at the top so the two legs join into one crown.
    const double inner = (1.0 - f) * (0.5 * depth - slabB) + f * (-0.5 * depth + slabA - 0.3);
    const double outer = inner + slabB;
    const double half = 0.48 * length;
    std::vector<Vec3> ring;
    for (const Vec2& local :
         {Vec2(-half, inner), Vec2(half, inner), Vec2(half, outer), Vec2(-half, outer)}) {
      const Vec2 p = center + rotate2(local, yaw);
      ring.emplace_back(p.x(), p.y(), t * height);
    }
    rings.push_back(std::move(ring));
  }
  scene.add(name, makeLoft(rings));
}

// ArtScience-museum-like lotus: a bowl with ten petals of varied length opening upwards.
void addLotus(SceneBuilder& scene, const Vec2& center, Rng& rng) {
  const std::string name = "lotus";
  scene.add(name, makeFrustum(Vec3(center.x(), center.y(), 0.0), 5.0, 7.5, 7.0, 24));
  const double phase = rng.uniform(0.0, 2.0 * M_PI);
  for (int i = 0; i < 10; ++i) {
    const double azimuth = phase + 2.0 * M_PI * i / 10.0;
    const double elevation = jitter(rng, 34.0 * kDeg, 0.1);
    const double length = jitter(rng, 8.5, 0.08);
    const Vec3 radial(std::cos(azimuth), std::sin(azimuth), 0.0);
    const Vec3 axis = std::cos(elevation) * radial + std::sin(elevation) * Vec3::UnitZ();
    const Vec3 tangent(-std::sin(azimuth), std::cos(azimuth), 0.0);
    Eigen::Matrix3d rotation;
    rotation << axis, tangent, axis.cross(tangent);
    const Vec3 petalCenter = Vec3(center.x(), center.y(), 7.5) + 5.2 * radial;
    scene.add(name, makeEllipsoid(petalCenter, Vec3(length, 3.4, 1.5), rotation, 18, 10));
  }
}

}  // namespace

Scenario generateMbs(uint64_t seed) {
  Rng rng(seed);
  Rng towerRng = rng.fork(1), deckRng = rng.fork(2), lotusRng = rng.fork(3), pointRng = rng.fork(4);
  SceneBuilder scene;

  // The sky deck's axis carries the layout (s along it, w across), as in the real resort.
  const Vec2 deckCenter(38.9 + rng.uniform(-1.0, 1.0), -0.3 + rng.uniform(-1.0, 1.0));
  const double deckYaw = -24.5 * kDeg + rng.uniform(-1.0, 1.0) * kDeg;
  const Vec2 d(std::cos(deckYaw), std::sin(deckYaw)), n(-d.y(), d.x());
  const auto at = [&](double s, double w) -> Vec2 { return deckCenter + s * d + w * n; };
  const double height = jitter(rng, 55.0, 0.02);

  std::vector<OrientedBox> boxes;
  const double boxBottom = 5.5;  // the podium level is not inspected, as in the reference
  struct Tower {
    double s, w, yawDeg;
  };
  const Tower towers[] = {{-30.0, 1.0, -14.8}, {2.0, 3.0, -26.1}, {34.0, 1.0, -34.0}};
  for (int i = 0; i < 3; ++i) {
    const std::string name = "tower" + std::to_string(i + 1);
    const Vec2 center = at(towers[i].s + towerRng.uniform(-1.0, 1.0), towers[i].w);
    const double yaw = (towers[i].yawDeg + towerRng.uniform(-1.5, 1.5)) * kDeg;
    const double length = jitter(towerRng, 24.0, 0.04), depth = jitter(towerRng, 15.0, 0.04);
    addMbsTower(scene, name, center, yaw, length, depth, height, towerRng);
    const double top = height + 0.7;
    boxes.push_back(makeInspectionBox(name, Vec3(center.x(), center.y(), 0.5 * (boxBottom + top)),
                                      Vec3(length + 3.0, depth + 3.0, top - boxBottom), yaw));
  }

  // Sky deck: a hull from behind tower 1 to a cantilever well past tower 3, on the tower tops.
  const double halfWidth = jitter(deckRng, 6.5, 0.04), w0 = 2.0;
  const double rear = -jitter(deckRng, 52.0, 0.02), tip = jitter(deckRng, 64.0, 0.02);
  const double thickness = 3.2;
  std::vector<Vec2> hull;
  for (const Vec2& sw :
       {Vec2(rear + halfWidth, -halfWidth), Vec2(40.0, -halfWidth),
        Vec2(0.5 * (40.0 + tip) + 2.0, -0.75 * halfWidth), Vec2(tip - 2.0, -2.0), Vec2(tip, 0.0),
        Vec2(tip - 2.0, 2.0), Vec2(0.5 * (40.0 + tip) + 2.0, 0.75 * halfWidth),
        Vec2(40.0, halfWidth), Vec2(rear + halfWidth, halfWidth)})
    hull.push_back(at(sw.x(), w0 + sw.y()));
  for (int k = 1; k < 6; ++k) {
    const double a = M_PI / 2 + M_PI * k / 6.0;
    hull.push_back(at(rear + halfWidth + halfWidth * std::cos(a), w0 + halfWidth * std::sin(a)));
  }
  const std::string deck = "skypark";
  scene.add(deck, makePrism(hull, height, height + thickness));
  // Pool and garden pavilions on top of the deck.
  const double deckTop = height + thickness;
  const Vec2 pool = at(10.0, w0 - 2.6);
  scene.add(deck, makeBox(Vec3(pool.x(), pool.y(), deckTop + 0.5), Vec3(40.0, 3.0, 1.0), deckYaw));
  for (const double s : {-40.0, -25.0, 35.0, 47.0}) {
    const Vec2 p = at(s + deckRng.uniform(-2.0, 2.0), w0 + 2.6);
    const double h = jitter(deckRng, 2.2, 0.1);
    scene.add(deck, makeBox(Vec3(p.x(), p.y(), deckTop + 0.5 * h), Vec3(6.0, 4.0, h), deckYaw));
  }
  const Vec2 deckBoxCenter = at(0.5 * (rear + tip), w0);
  boxes.insert(boxes.begin(),
               makeInspectionBox(deck, Vec3(deckBoxCenter.x(), deckBoxCenter.y(), height + 0.75),
                                 Vec3(tip - rear + 4.0, 2.0 * halfWidth + 4.0, 12.5), deckYaw));

  // Podium (shops) along the south side of the towers, below the inspected levels.
  const Vec2 podium = at(2.0, -10.5);
  scene.add("podium", makeBox(Vec3(podium.x(), podium.y(), 2.25), Vec3(84.0, 9.0, 4.5), deckYaw));
  addLotus(scene, Vec2(-31.0 + lotusRng.uniform(-1.0, 1.0), -23.0 + lotusRng.uniform(-1.0, 1.0)),
           lotusRng);

  SurfaceSampling sampling;
  auto points = sampleSurfacePoints(scene, boxes, sampling, pointRng);

  // Fleet on the open ground north of the towers; the GCS on a 20 m mast as in the reference.
  const auto ground = [&](double s, double w, double z) {
    const Vec2 p = at(s, w);
    return Vec3(p.x(), p.y(), z);
  };
  auto fleet = caricFleet({{"gcs", ground(-12.0, 19.0, 20.0)},
                           {"jurong", ground(-22.0, 17.0, 0.1)},
                           {"raffles", ground(-6.0, 17.0, 0.1)},
                           {"sentosa", ground(22.0, 17.0, 0.1)},
                           {"changi", ground(-19.0, 17.0, 0.1)},
                           {"nanyang", ground(8.0, 17.0, 0.1)}},
                          2.0);
  return assembleScenario("mbs",
                          "Marina Bay Sands: three 55 m hotel towers under a 116 m sky deck, "
                          "lotus museum; 4 boxes (deck + towers)",
                          scene, std::move(boxes), std::move(points), std::move(fleet), 600.0);
}

// ---- Hangar ----------------------------------------------------------------------------------

namespace {

// Closed airfoil section: chord along `chordDir` from `leadingEdge`, thickness along `up`
// (cambered: more above than below).
std::vector<Vec3> airfoil(const Vec3& leadingEdge, const Vec3& chordDir, const Vec3& up,
                          double chord, double thickness, bool symmetric) {
  const double stations[] = {0.1, 0.3, 0.6};
  const double shape[] = {0.7, 1.0, 0.75};
  const double above = symmetric ? 0.5 : 0.6, below = symmetric ? 0.5 : 0.4;
  std::vector<Vec3> ring{leadingEdge};
  for (int i = 0; i < 3; ++i)
    ring.push_back(leadingEdge + stations[i] * chord * chordDir +
                   above * thickness * shape[i] * up);
  ring.push_back(leadingEdge + chord * chordDir);
  for (int i = 2; i >= 0; --i)
    ring.push_back(leadingEdge + stations[i] * chord * chordDir -
                   below * thickness * shape[i] * up);
  return ring;
}

std::vector<Vec3> circleXZ(double y, double cx, double cz, double r, int segments) {
  std::vector<Vec3> ring;
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * M_PI * i / segments;
    ring.emplace_back(cx + r * std::cos(a), y, cz + r * std::sin(a));
  }
  return ring;
}

Aabb boundsOf(std::initializer_list<const TriangleMesh*> meshes) {
  Aabb box;
  for (const TriangleMesh* mesh : meshes) {
    const Aabb b = mesh->bounds();
    box.extend(b.min);
    box.extend(b.max);
  }
  return box;
}

}  // namespace

Scenario generateHangar(uint64_t seed) {
  Rng rng(seed);
  Rng shellRng = rng.fork(1), planeRng = rng.fork(2), pointRng = rng.fork(3);
  SceneBuilder scene;

  // Shell: 73 m wide, 60 m deep, walls 16 m under a barrel roof; the door side faces -y.
  const std::string shell = "hangar";
  const double halfW = jitter(shellRng, 36.0, 0.02), front = -26.0, back = 34.0;
  const double wallH = 16.0, rise = jitter(shellRng, 6.0, 0.1), t = 0.6, doorHalf = 27.0;
  const double outerHalf = halfW + t;
  for (const double side : {-1.0, 1.0}) {
    scene.add(shell, makeBox(Vec3(side * (halfW + 0.5 * t), 0.5 * (front + back), 0.5 * wallH),
                             Vec3(t, back - front, wallH)));
    scene.add(shell,
              makeBox(Vec3(side * 0.5 * (outerHalf + doorHalf), front - 0.5 * t, 0.5 * wallH),
                      Vec3(outerHalf - doorHalf, t, wallH)));
    // Door leaves slid aside in front of the wall, one partly across the opening.
    const double leafWidth = 13.5, overlap = side < 0 ? shellRng.uniform(0.0, 4.0) : 0.0;
    const double leafCenter = side * (doorHalf - overlap + 0.5 * leafWidth);
    scene.add(shell, makeBox(Vec3(leafCenter, front - t - 0.7, 7.75), Vec3(leafWidth, 0.4, 15.5)));
  }
  scene.add(shell,
            makeBox(Vec3(0.0, back + 0.5 * t, 0.5 * wallH), Vec3(2.0 * outerHalf, t, wallH)));
  const double radius = (outerHalf * outerHalf + rise * rise) / (2.0 * rise);
  const double centerZ = wallH + rise - radius;
  const double halfAngle = std::asin(outerHalf / radius);
  const int roofSegments = 14;
  std::vector<Vec2> gable;  // (x, z) circular segment above the walls
  for (int k = 0; k <= roofSegments; ++k) {
    const double a = -halfAngle + 2.0 * halfAngle * k / roofSegments;
    gable.emplace_back(radius * std::sin(a), centerZ + radius * std::cos(a));
  }
  for (int k = 0; k < roofSegments; ++k) {
    const Vec2 a = gable[static_cast<size_t>(k)], b = gable[static_cast<size_t>(k) + 1];
    const Vec2 na = (a - Vec2(0.0, centerZ)).normalized(),
               nb = (b - Vec2(0.0, centerZ)).normalized();
    const std::vector<Vec2> panel{a, b, b + 0.5 * nb, a + 0.5 * na};
    scene.add(shell, makeExtrusion(panel, Vec3(0, front - t, 0), Vec3::UnitX(), Vec3::UnitZ(),
                                   Vec3(0, back - front + 2.0 * t, 0)));
  }
  for (const double y : {front - t, back})
    scene.add(shell,
              makeExtrusion(gable, Vec3(0, y, 0), Vec3::UnitX(), Vec3::UnitZ(), Vec3(0, t, 0)));

  // Airliner: 40 m fuselage along y (nose to the door), 35 m swept wings, tail fin.
  const std::string plane = "aircraft";
  const double length = jitter(planeRng, 40.0, 0.03), span = jitter(planeRng, 35.0, 0.03);
  const double fuselageR = jitter(planeRng, 2.0, 0.05), zc = 4.2;
  const double nose = -0.5 * length;
  const auto stationY = [&](double s) { return nose + s * length; };
  std::vector<std::vector<Vec3>> fuselageRings;
  for (const double s :
       {0.005, 0.02, 0.04, 0.07, 0.1, 0.12, 0.3, 0.5, 0.75, 0.82, 0.88, 0.94, 1.0}) {
    double r = fuselageR, dz = 0.0;
    if (s < 0.12) {
      const double u = (0.12 - s) / 0.12;
      r = fuselageR * std::sqrt(1.0 - u * u);
      dz = -0.3 * u * u;
    } else if (s > 0.75) {
      const double u = (s - 0.75) / 0.25;
      r = fuselageR * (1.0 - 0.85 * std::pow(u, 1.3));
      dz = 1.2 * std::pow(u, 1.5);
    }
    fuselageRings.push_back(circleXZ(stationY(s), 0.0, zc + dz, r, 20));
  }
  const TriangleMesh fuselage = makeLoft(fuselageRings, Vec3(0.0, nose, zc - 0.3));

  const double sweep = std::tan(27.0 * kDeg), dihedral = std::tan(5.0 * kDeg);
  const double rootLe = stationY(0.45), wingZ = zc - 1.3, halfSpan = 0.5 * span;
  const auto wingLe = [&](double x) { return rootLe + std::abs(x) * sweep; };
  const auto wingZAt = [&](double x) { return wingZ + std::abs(x) * dihedral; };
  std::vector<std::vector<Vec3>> wingRings;
  for (const double x : {-halfSpan, 0.0, halfSpan}) {
    const bool root = x == 0.0;
    wingRings.push_back(airfoil(Vec3(x, wingLe(x), wingZAt(x)), Vec3::UnitY(), Vec3::UnitZ(),
                                root ? 7.0 : 2.0, root ? 0.8 : 0.25, false));
  }
  const TriangleMesh wings = makeLoft(wingRings);
  std::vector<TriangleMesh> engines;
  for (const double side : {-1.0, 1.0}) {
    const double x = side * 0.37 * halfSpan;
    const double y0 = wingLe(x) - 3.8, cz = wingZAt(x) - 1.5;
    engines.push_back(makeLoft({circleXZ(y0, x, cz, 1.1, 16), circleXZ(y0 + 4.0, x, cz, 1.1, 16),
                                circleXZ(y0 + 5.0, x, cz, 0.7, 16)}));
    engines.push_back(makeBox(Vec3(x, y0 + 3.0, cz + 1.2), Vec3(0.4, 3.0, 1.6)));
    // Main gear: strut into the wing root area and a wheel pair on the ground.
    const double gx = side * 3.0, gy = wingLe(gx) + 3.5;
    engines.push_back(makeBeam(Vec3(gx, gy, 0.6), Vec3(gx, gy, wingZAt(gx) + 0.2), 0.35));
    engines.push_back(makeBox(Vec3(gx, gy, 0.6), Vec3(0.9, 1.3, 1.2)));
  }
  const double noseGearY = nose + 5.0;
  const TriangleMesh noseStrut =
      makeBeam(Vec3(0, noseGearY, 0.5), Vec3(0, noseGearY, zc - 1.0), 0.3);
  const TriangleMesh noseWheel = makeBox(Vec3(0, noseGearY, 0.5), Vec3(0.5, 1.0, 1.0));

  const double tailSweep = std::tan(30.0 * kDeg), stabRootLe = stationY(0.885);
  std::vector<std::vector<Vec3>> stabRings;
  for (const double x : {-6.0, 0.0, 6.0}) {
    const bool root = x == 0.0;
    stabRings.push_back(airfoil(Vec3(x, stabRootLe + std::abs(x) * tailSweep, zc + 0.9),
                                Vec3::UnitY(), Vec3::UnitZ(), root ? 4.0 : 1.5, root ? 0.35 : 0.15,
                                true));
  }
  const TriangleMesh stabiliser = makeLoft(stabRings);
  const double finRootLe = stationY(0.84), finHeight = jitter(planeRng, 8.0, 0.05);
  const TriangleMesh fin = makeLoft(
      {airfoil(Vec3(0, finRootLe, zc + 0.5), Vec3::UnitY(), Vec3::UnitX(), 5.5, 0.5, true),
       airfoil(Vec3(0, finRootLe + finHeight * std::tan(35.0 * kDeg), zc + 0.5 + finHeight),
               Vec3::UnitY(), Vec3::UnitX(), 2.2, 0.2, true)});

  std::vector<OrientedBox> boxes{boxAround("fuselage", boundsOf({&fuselage, &noseWheel}), 1.0)};
  {
    Aabb wingBounds = wings.bounds();
    for (const auto& part : engines) {
      wingBounds.extend(part.bounds().min);
      wingBounds.extend(part.bounds().max);
    }
    boxes.push_back(boxAround("wings", wingBounds, 1.0));
  }
  boxes.push_back(boxAround("tail", boundsOf({&stabiliser, &fin}), 1.0));
  for (const TriangleMesh* part : {&fuselage, &wings, &stabiliser, &fin, &noseStrut, &noseWheel})
    scene.add(plane, *part);
  for (auto& part : engines)
    scene.add(plane, std::move(part));

  SurfaceSampling sampling;
  auto points = sampleSurfacePoints(scene, boxes, sampling, pointRng);
  // The released hangar scenario's start positions; its GCS stands on a 5 m mast.
  auto fleet = caricFleet({{"gcs", Vec3(16.0, -28.0, 5.0)},
                           {"jurong", Vec3(-11.0, 11.0, 0.1)},
                           {"sentosa", Vec3(-17.0, -33.0, 0.1)},
                           {"changi", Vec3(9.0, -35.0, 0.1)}},
                          1.0);
  return assembleScenario("hangar",
                          "Aircraft hangar with an open door and an airliner inside (40 m "
                          "fuselage, 35 m span); 3 boxes around the aircraft",
                          scene, std::move(boxes), std::move(points), std::move(fleet), 420.0);
}

// ---- Crane -----------------------------------------------------------------------------------

namespace {

struct CraneSpec {
  Vec2 base;
  double mastHeight;
  double jibLength;
  double counterJibLength;
  double slew;  // jib direction, rad
};

// A tower crane of lattice members: square mast, triangular jib, flat counter-jib with
// counterweights, cat head with tie rods, cab, trolley and hook. Returns its two boxes.
void addCrane(SceneBuilder& scene, const std::string& name, const CraneSpec& spec, Rng& rng,
              std::vector<OrientedBox>& boxes) {
  const Eigen::Matrix3d slew = yawRotation(spec.slew);
  const Vec3 base(spec.base.x(), spec.base.y(), 0.0);
  const auto world = [&](double x, double y, double z) {
    return Vec3(base + slew * Vec3(x, y, z));
  };
  const double h = spec.mastHeight, chord = 0.22, brace = 0.12, half = 1.0;

  scene.add(name, makeBox(Vec3(base.x(), base.y(), 0.6), Vec3(6.0, 6.0, 1.2)));
  const Vec3 corners[4] = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
  const double mastBottom = 0.6;
  const int bays = static_cast<int>(std::lround((h - mastBottom) / 2.5));
  const double bay = (h - mastBottom) / bays;
  for (const Vec3& c : corners)
    scene.add(name, makeBeam(base + c + Vec3(0, 0, mastBottom), base + c + Vec3(0, 0, h), chord));
  for (int k = 1; k <= bays; ++k) {
    const double z0 = mastBottom + (k - 1) * bay, z1 = mastBottom + k * bay;
    for (int i = 0; i < 4; ++i) {
      const Vec3 a = base + corners[i], b = base + corners[(i + 1) % 4];
      if (k < bays) scene.add(name, makeBeam(a + Vec3(0, 0, z1), b + Vec3(0, 0, z1), brace));
      // Zig-zag diagonals, alternating per bay.
      if (k % 2 == 0)
        scene.add(name, makeBeam(a + Vec3(0, 0, z0), b + Vec3(0, 0, z1), brace));
      else
        scene.add(name, makeBeam(b + Vec3(0, 0, z0), a + Vec3(0, 0, z1), brace));
    }
  }

  // Slewing table, cat head, cab.
  const double table = h + 1.2;
  scene.add(name, makeBox(world(0, 0, h + 0.6), Vec3(3.2, 3.2, 1.2), spec.slew));
  const double apexHeight = jitter(rng, 7.0, 0.05);
  const Vec3 apex = world(0, 0, table + apexHeight);
  for (const Vec3& c : corners)
    scene.add(name, makeBeam(world(c.x(), c.y(), table - 0.2), apex, 0.18));
  scene.add(name, makeBox(world(0.6, -2.6, h + 0.2), Vec3(2.2, 2.0, 2.4), spec.slew));

  // Jib: two bottom chords and a top chord, braced every 2.5 m.
  const double jibStart = 1.5, jibEnd = spec.jibLength, jibHeight = 1.5, jibHalf = 0.8;
  const int jibBays = static_cast<int>(std::lround((jibEnd - jibStart) / 2.5));
  const double jibBay = (jibEnd - jibStart) / jibBays;
  const double jz = table + 0.1;
  scene.add(name,
            makeBeam(world(jibStart - 0.1, -jibHalf, jz), world(jibEnd, -jibHalf, jz), chord));
  scene.add(name, makeBeam(world(jibStart - 0.1, jibHalf, jz), world(jibEnd, jibHalf, jz), chord));
  scene.add(name, makeBeam(world(jibStart - 0.1, 0, jz + jibHeight),
                           world(jibEnd, 0, jz + jibHeight), chord));
  for (int k = 0; k <= jibBays; ++k) {
    const double x0 = jibStart + k * jibBay, x1 = x0 + jibBay;
    scene.add(name, makeBeam(world(x0, -jibHalf, jz), world(x0, jibHalf, jz), brace));
    if (k == jibBays) {
      for (const double y : {-jibHalf, jibHalf})
        scene.add(name, makeBeam(world(x0, y, jz), world(x0, 0, jz + jibHeight), brace));
      break;
    }
    const double xa = k % 2 == 0 ? x0 : x1, xb = k % 2 == 0 ? x1 : x0;
    for (const double y : {-jibHalf, jibHalf})
      scene.add(name, makeBeam(world(xa, y, jz), world(xb, 0, jz + jibHeight), brace));
  }

  // Counter-jib with counterweights.
  const double cjEnd = -spec.counterJibLength, cjHalf = 0.9;
  for (const double y : {-cjHalf, cjHalf})
    scene.add(name, makeBeam(world(-jibStart + 0.1, y, jz), world(cjEnd, y, jz), chord));
  const int cjBays = static_cast<int>(std::lround((spec.counterJibLength - jibStart) / 2.5));
  for (int k = 0; k <= cjBays; ++k) {
    const double x = -jibStart - k * (spec.counterJibLength - jibStart) / cjBays;
    scene.add(name, makeBeam(world(x, -cjHalf, jz), world(x, cjHalf, jz), brace));
    if (k < cjBays) {
      const double xn = -jibStart - (k + 1) * (spec.counterJibLength - jibStart) / cjBays;
      scene.add(name, makeBeam(world(x, k % 2 ? -cjHalf : cjHalf, jz),
                               world(xn, k % 2 ? cjHalf : -cjHalf, jz), brace));
    }
  }
  for (int i = 0; i < 3; ++i)
    scene.add(name,
              makeBox(world(cjEnd + 1.0 + 1.15 * i, 0, jz - 0.6), Vec3(1.0, 2.4, 2.6), spec.slew));

  // Tie rods from the cat head, trolley and hook.
  scene.add(name, makeBeam(apex, world(0.55 * jibEnd, 0, jz + jibHeight), 0.08));
  for (const double y : {-cjHalf, cjHalf})
    scene.add(name, makeBeam(apex, world(cjEnd + 0.3, y, jz), 0.08));
  const double trolley = rng.uniform(0.35, 0.85) * jibEnd;
  scene.add(name, makeBox(world(trolley, 0, jz - 0.35), Vec3(1.2, 1.4, 0.5), spec.slew));
  const double hookDrop = rng.uniform(2.0, 4.0);
  scene.add(name,
            makeBeam(world(trolley, 0, jz - 0.5), world(trolley, 0, jz - 0.6 - hookDrop), 0.06));
  scene.add(name, makeBox(world(trolley, 0, jz - 1.0 - hookDrop), Vec3(0.6, 0.6, 0.9), spec.slew));

  const double top = table + apexHeight + 0.5;
  boxes.push_back(makeInspectionBox(name + "-mast", Vec3(base.x(), base.y(), 0.5 * top),
                                    Vec3(2 * half + 3.0, 2 * half + 3.0, top)));
  const double boxBack = cjEnd - 1.0, boxFront = jibEnd + 1.0;
  const Vec3 jibCenter =
      world(0.5 * (boxBack + boxFront), -0.5, 0.5 * ((h - 2.0) + (jz + jibHeight + 1.0)));
  boxes.push_back(makeInspectionBox(
      name + "-jib", jibCenter, Vec3(boxFront - boxBack, 7.4, (jz + jibHeight + 1.0) - (h - 2.0)),
      spec.slew));
}

}  // namespace

Scenario generateCrane(uint64_t seed) {
  Rng rng(seed);
  SceneBuilder scene;
  std::vector<OrientedBox> boxes;
  // Jibs point away from the neighbouring cranes (and are shorter than the distance between
  // masts), so no member of one crane can cut another.
  const CraneSpec specs[] = {
      {{15.0, 20.0}, 40.0, 34.0, 12.0, M_PI + rng.uniform(-50.0, 50.0) * kDeg},
      {{45.0, -6.0}, 48.0, 36.0, 13.0, -M_PI / 2 + rng.uniform(-30.0, 30.0) * kDeg},
      {{76.0, 19.0}, 44.0, 34.0, 12.0, rng.uniform(-50.0, 50.0) * kDeg}};
  for (int i = 0; i < 3; ++i) {
    Rng craneRng = rng.fork(static_cast<uint64_t>(10 + i));
    CraneSpec spec = specs[i];
    spec.mastHeight += craneRng.uniform(-1.0, 1.0);
    spec.jibLength += craneRng.uniform(-1.5, 1.5);
    addCrane(scene, "crane" + std::to_string(i + 1), spec, craneRng, boxes);
  }
  Rng pointRng = rng.fork(4);
  SurfaceSampling sampling;
  auto points = sampleSurfacePoints(scene, boxes, sampling, pointRng);
  // The released crane scenario's start positions.
  auto fleet = caricFleet({{"gcs", Vec3(-2.0, 8.0, 20.0)},
                           {"jurong", Vec3(0.0, 8.0, 0.1)},
                           {"raffles", Vec3(31.0, 0.0, 0.1)},
                           {"sentosa", Vec3(58.0, -13.0, 0.1)},
                           {"changi", Vec3(4.0, 8.0, 0.1)},
                           {"nanyang", Vec3(-2.0, 25.0, 0.1)}},
                          1.5);
  return assembleScenario("crane",
                          "Construction site with three lattice tower cranes (40-48 m masts, "
                          "34-36 m jibs); 6 boxes (mast + jib per crane)",
                          scene, std::move(boxes), std::move(points), std::move(fleet), 600.0);
}

}  // namespace coinspect::world::detail
