// Link models: which pairs of units can talk, computed for all pairs at once.
//
// `caric` is the reference's ppcom rule (doc/communication.md): six antennas per unit at
// +-antennaOffset along the WORLD x, y and z axes (the -z one kept at least 0.1 m above the
// ground), linked when any of the 36 antenna-to-antenna segments is clear (no hit, or the first
// hit within 0.1 m of the far end), no range limit. `range` is SLEI3D's: the centre-to-centre
// segment clear with the same tolerance and the centres at most `range` metres apart.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/comms/link_matrix.h"
#include "coinspect/world/mesh.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::comms {

// What a link model needs to know about one unit. The antennas are fixed to world axes in the
// reference, so no attitude is needed.
struct LinkEndpoint {
  world::Vec3 position = world::Vec3::Zero();  // body centre, world frame, metres
  double antennaOffset = 0.1;                  // metres (0.2 explorers, 0.1 others in CARIC)
  // false: the unit takes no part in the topology (no links at all).
  bool alive = true;
};

// The reference keeps the -z antenna this far above the ground (z >= 0.1 with ground z = 0).
inline constexpr double kAntennaGroundClearance = 0.1;

// The six antenna positions in the reference's order: +x, -x, +y, -y, +z, -z; the -z one is
// raised to groundZ + kAntennaGroundClearance when it is lower and a ground exists.
std::array<world::Vec3, 6> antennaPositions(const LinkEndpoint& unit, bool hasGround,
                                            double groundZ);

// Immutable: one model can serve several runs and threads; per-run state is the LinkMatrix.
class LinkModel {
 public:
  virtual ~LinkModel() = default;
  virtual std::string name() const = 0;
  // Recomputes `out` (resized to units.size()) for every pair of alive units.
  virtual void update(const world::RayCaster& caster, const std::vector<LinkEndpoint>& units,
                      LinkMatrix& out) const = 0;
};

class CaricLinkModel final : public LinkModel {
 public:
  std::string name() const override { return "caric"; }
  // Batched and staged: first the +z-to-+z antenna segment of every pair (it clears low walls and
  // open air), then the other like-for-like pairs, then the 30 crossed pairs, each stage one
  // batch over the pairs still unlinked. Same result as testing the 36 segments one by one.
  void update(const world::RayCaster& caster, const std::vector<LinkEndpoint>& units,
              LinkMatrix& out) const override;
};

class RangeLinkModel final : public LinkModel {
 public:
  // Throws InputError when range is not a finite positive number.
  explicit RangeLinkModel(double range);
  std::string name() const override { return "range"; }
  double range() const { return range_; }
  void update(const world::RayCaster& caster, const std::vector<LinkEndpoint>& units,
              LinkMatrix& out) const override;

 private:
  double range_;
};

// "caric" or "range" (then `range` metres is used; SLEI3D uses 5). Throws InputError naming
// `source` for an unknown name or a bad range.
std::unique_ptr<LinkModel> makeLinkModel(const std::string& name, double range,
                                         const std::string& source = "link model");

}  // namespace coinspect::comms
