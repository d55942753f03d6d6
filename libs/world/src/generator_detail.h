// Private helpers shared by the scenario generators: mesh primitives, the scene of closed parts,
// interest point sampling and fleet construction.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/world/generators.h"
#include "coinspect/world/scenario.h"

namespace coinspect::world::detail {

using Vec2 = Eigen::Vector2d;

Eigen::Matrix3d yawRotation(double yaw);
Vec2 rotate2(const Vec2& p, double angle);

// ---- Primitives (generator_shapes.cpp) -------------------------------------------------------
// Every primitive returns one closed mesh whose facet normals point outwards (orientOutward is
// applied last, so the vertex order a primitive builds with does not matter).

// Signed volume by the divergence theorem; positive when the facets face outwards.
double signedVolume(const TriangleMesh& mesh);
void orientOutward(TriangleMesh& mesh);

// Axis-aligned box turned by `yaw` about its centre's vertical axis.
TriangleMesh makeBox(const Vec3& center, const Vec3& size, double yaw = 0.0);
TriangleMesh makeBox(const Vec3& center, const Vec3& size, const Eigen::Matrix3d& rotation);
// Square beam of edge `width` whose axis runs from a to b (lattice members, posts, cables).
TriangleMesh makeBeam(const Vec3& a, const Vec3& b, double width);
// The 2D polygon (in the plane origin + x u + y v) swept along `along`. The polygon must be
// star-shaped around `fanCenter` (default: its area centroid) because caps are fans from it.
TriangleMesh makeExtrusion(const std::vector<Vec2>& polygon, const Vec3& origin, const Vec3& u,
                           const Vec3& v, const Vec3& along,
                           const std::optional<Vec2>& fanCenter = std::nullopt);
// Vertical prism of a plan polygon between z0 and z1.
TriangleMesh makePrism(const std::vector<Vec2>& polygon, double z0, double z1,
                       const std::optional<Vec2>& fanCenter = std::nullopt);
// Skin through rings of equal vertex count (ring i vertex j next to ring i+1 vertex j). Each end
// is closed by a fan to the given apex, or else to the ring's centroid (a flat-ish cap).
TriangleMesh makeLoft(const std::vector<std::vector<Vec3>>& rings,
                      const std::optional<Vec3>& bottomApex = std::nullopt,
                      const std::optional<Vec3>& topApex = std::nullopt);
// Vertical truncated cone (r1 may be 0 for a cone) approximated by `segments` sides.
TriangleMesh makeFrustum(const Vec3& baseCenter, double r0, double r1, double height, int segments);
// Ellipsoid with semi-axes `radii` along the columns of `rotation`.
TriangleMesh makeEllipsoid(const Vec3& center, const Vec3& radii, const Eigen::Matrix3d& rotation,
                           int slices, int stacks);

// Plan polygons (counter-clockwise).
std::vector<Vec2> regularPolygon(const Vec2& center, double radius, int sides, double phase = 0.0);
std::vector<Vec2> rectangle(const Vec2& center, double sizeX, double sizeY, double yaw = 0.0);
// Y-shaped plan: three wings of half-width `halfWidth` at 90, 210 and 330 deg (+ `phase`) from
// the origin, wing i reaching lengths[i]; rounded tips with `tipSegments` facets.
std::vector<Vec2> yPlan(const std::vector<double>& lengths, double halfWidth, double phase,
                        int tipSegments);

// ---- Scene of closed parts (generator_scene.cpp) ---------------------------------------------

// Closed solid parts grouped by structure; the scenario gets one mesh per structure. Parts may
// overlap (a beam ending inside a chord): sampling discards surface points buried in another part.
class SceneBuilder {
 public:
  struct Part {
    std::string structure;
    TriangleMesh mesh;
    Aabb bounds;
  };

  void add(const std::string& structure, TriangleMesh part);
  const std::vector<Part>& parts() const { return parts_; }
  // One mesh per structure, in order of first appearance.
  std::vector<TriangleMesh> meshes() const;
  Aabb bounds() const;
  Aabb bounds(const std::string& structure) const;

 private:
  std::vector<Part> parts_;
};

// Point-in-solid queries over the parts of a scene (parity of ray crossings per part), with a
// uniform grid over the parts' bounds so that a query touches only the parts near it.
class SolidIndex {
 public:
  explicit SolidIndex(const SceneBuilder& scene, double cellSize = 4.0);
  // True when p lies inside any part.
  bool inside(const Vec3& p) const;
  // True when p and the six points at +-radius along the axes are outside every part and above
  // `groundZ`: room for a vehicle of that radius (used for start positions).
  bool clear(const Vec3& p, double radius, double groundZ = 0.0) const;

 private:
  // A part's triangles bucketed by their shadow on the plane across the parity ray direction:
  // a ray can only cross the triangles whose shadow covers the query point's.
  struct PartRays {
    Aabb bounds;
    std::vector<std::array<Vec3, 3>> triangles;
    Vec2 origin = Vec2::Zero();
    double cell = 1.0;
    int nx = 1, ny = 1;
    std::vector<std::vector<uint32_t>> buckets;
  };
  static PartRays prepare(const TriangleMesh& mesh, const Aabb& bounds);
  bool insidePart(const PartRays& part, const Vec3& p) const;
  int64_t key(int x, int y, int z) const;
  double cell_;
  std::vector<PartRays> parts_;
  std::unordered_map<int64_t, std::vector<uint32_t>> cells_;
};

// ---- Interest points (generator_scene.cpp) ---------------------------------------------------

struct SurfaceSampling {
  // Poisson-disk radius: no two points closer. Random sequential addition from dense candidates
  // leaves a nearest-neighbour median about 1.15 times this.
  double minSpacing = 0.68;
  // Candidates per square metre, relative to 1 / minSpacing^2: enough to saturate the disks.
  double candidateFactor = 6.0;
  // A point is kept only when the points moved these distances out along its normal are free
  // air: not inside another part and above the ground. This drops faces touching the ground or
  // other parts and points in crevices where two parts meet, which no camera could see.
  std::vector<double> probeOffsets{0.02, 0.1, 0.3};
  double groundZ = 0.0;
};

// Area-weighted candidates on every part's surface inside some box, in random order, thinned
// to a Poisson-disk set. Positions lie exactly on their facet; normals are the facet normals.
std::vector<InterestPoint> sampleSurfacePoints(const SceneBuilder& scene,
                                               const std::vector<OrientedBox>& boxes,
                                               const SurfaceSampling& sampling, Rng& rng);
// Greedy farthest-point subset of `count` points (the first one chosen by rng): spread features.
std::vector<InterestPoint> farthestPointSubset(const std::vector<InterestPoint>& points,
                                               size_t count, Rng& rng);
bool insideAnyBox(const std::vector<OrientedBox>& boxes, const Vec3& p, double margin = 0.0);

// ---- Boxes, fleet, assembly (generator_scene.cpp) --------------------------------------------

OrientedBox makeInspectionBox(const std::string& name, const Vec3& center, const Vec3& size,
                              double yaw = 0.0);
// Axis-aligned box around a structure's bounds grown by `margin` (ground clipped at z = 0).
OrientedBox boxAround(const std::string& name, const Aabb& bounds, double margin);

// A unit with the CARIC camera and the reference antenna offsets (0.2 m explorers, 0.1 m others).
UnitSpec makeUnit(const std::string& name, UnitRole role, const Vec3& start, double desiredMmPerPx);

// Fills the scenario and checks what the generators promise: every start position is clear of
// the parts (COINSPECT_ASSERT: a failure is a generator bug, not bad input).
Scenario assembleScenario(const std::string& name, const std::string& description,
                          const SceneBuilder& scene, std::vector<OrientedBox> boxes,
                          std::vector<InterestPoint> points, std::vector<UnitSpec> fleet,
                          double missionBudget);

// ---- The generators (generator_caric.cpp, generator_towers.cpp, generator_slei.cpp) ----------

Scenario generateMbs(uint64_t seed);
Scenario generateHangar(uint64_t seed);
Scenario generateCrane(uint64_t seed);
Scenario generateBurjKhalifa(uint64_t seed);
Scenario generateBurjAlArab(uint64_t seed);
// `fleet`: the scene's own fleet when absent (generators.h).
Scenario generateSleiA(uint64_t seed, const std::optional<SleiFleet>& fleet);
Scenario generateSleiB(uint64_t seed, const std::optional<SleiFleet>& fleet);
Scenario generateSleiC(uint64_t seed, const std::optional<SleiFleet>& fleet);
Scenario generateSleiD(uint64_t seed, const std::optional<SleiFleet>& fleet);

}  // namespace coinspect::world::detail
