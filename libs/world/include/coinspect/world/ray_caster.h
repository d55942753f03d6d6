// Ray casting against all solid geometry of a scenario, through Embree 3.
//
// The caster is built once per scenario and is immutable afterwards, so queries are const and
// may run from several threads at once.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "coinspect/world/mesh.h"

namespace coinspect::world {

struct RayHit {
  double distance = 0.0;  // along the unit direction, metres
  uint32_t geometry = 0;  // index into the meshes given at construction; ground = meshes.size()
  uint32_t triangle = 0;
  Vec3 normal = Vec3::Zero();  // unit geometric normal of the hit facet
};

// The reference's tolerances (caric-reference.md).
inline constexpr double kPointVisibilityTolerance = 0.025;  // q_seen: first hit near the point
inline constexpr double kLinkClearanceTolerance = 0.1;      // ppcom antenna segments

class RayCaster {
 public:
  // Builds the scene from the meshes, plus the ground plane z = groundZ (a square of
  // `groundHalfExtent` around the meshes' centre) when groundZ is given.
  explicit RayCaster(const std::vector<TriangleMesh>& meshes,
                     std::optional<double> groundZ = 0.0, double groundHalfExtent = 5000.0);
  ~RayCaster();
  RayCaster(RayCaster&&) noexcept;
  RayCaster& operator=(RayCaster&&) noexcept;
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Closest hit along origin + t * direction, t in (0, maxRange]; direction need not be unit
  // (distances are always in metres).
  std::optional<RayHit> closestHit(const Vec3& origin, const Vec3& direction,
                                   double maxRange = std::numeric_limits<double>::infinity()) const;

  // True when the segment a->b has no hit closer than |b - a| - tolerance (the reference's rule:
  // "no hit, or first hit >= length - tolerance").
  bool segmentClear(const Vec3& a, const Vec3& b, double tolerance) const;

  // Batched closest hits (16-ray packets where possible): distances[i] = hit distance along the
  // unit direction of directions[i], or +infinity when nothing is hit within maxRange.
  void closestHits(const std::vector<Vec3>& origins, const std::vector<Vec3>& directions,
                   double maxRange, std::vector<double>& distances) const;
  // Batched segmentClear.
  void segmentsClear(const std::vector<Vec3>& from, const std::vector<Vec3>& to, double tolerance,
                     std::vector<uint8_t>& clear) const;

  // Distance from p to the nearest mesh surface (not the ground plane), or +infinity when none
  // is within maxDistance. Used for collisions.
  double distanceToSurface(const Vec3& p,
                           double maxDistance = std::numeric_limits<double>::infinity()) const;

  size_t meshTriangleCount() const;
  bool hasGround() const;
  double groundZ() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coinspect::world
