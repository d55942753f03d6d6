// Scores the interest points one camera capture sees, as the CARIC reference does
// (gazebo_ppcom_plugin.cpp, EvaluateCam), or by the published formulas. doc/scoring.md has
// every formula and every difference between the two modes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "coinspect/sensing/camera_model.h"
#include "coinspect/sensing/capture_state.h"
#include "coinspect/sensing/sphere_occluder.h"
#include "coinspect/world/interest_points.h"
#include "coinspect/world/oriented_box.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::sensing {

enum class ScoringMode {
  Caric,   // what the reference code computes, quirks included (the leaderboard's numbers)
  Strict,  // normalised displacement directions, line of sight = nothing in between
};

const char* toString(ScoringMode mode);
// "caric" or "strict"; throws InputError naming `source` otherwise.
ScoringMode parseScoringMode(const std::string& text, const std::string& source);

// A capture counts for a point only when its score reaches this value (inclusive).
inline constexpr double kCountThreshold = 0.2;
// Displacement (m) on each side of the point used to measure mm per pixel: 0.5 mm.
inline constexpr double kResolutionProbe = 0.0005;

enum class NotSeenReason : uint8_t {
  None,                  // seen
  OutOfRange,            // farther than candidateRadius (only scorePoint reports it)
  BehindCamera,          // x <= 0 in the camera frame
  OutsideHorizontalFov,  // |atan(y/x)| > HFOV/2
  OutsideVerticalFov,    // |atan(z/x)| > VFOV/2
  Occluded,              // something solid is hit before the point
  NoSurfaceHit,          // caric: the ray hits nothing near the point (the reference's 1000 m)
  DegenerateResolution,  // a 0.5 mm probe falls behind the camera plane (reference skips it)
};

const char* toString(NotSeenReason reason);

struct PointScore {
  uint32_t index = 0;
  bool seen = false;  // q_seen
  NotSeenReason reason = NotSeenReason::None;
  double distance = 0.0;         // |p - p_C|, m
  Vec3 inCamera = Vec3::Zero();  // q = R_WC^T (p - p_C)
  // The terms below are computed whenever the point is in front of the camera (x > 0), even
  // when it is not seen, to help debugging; they enter the score only when seen.
  double blurPixels = 0.0;  // max(pix_y, pix_z)
  double mmPerPixel = 0.0;  // max(mmpp_u, mmpp_v)
  double qBlur = 0.0;
  double qRes = 0.0;
  double score = 0.0;    // qBlur * qRes when seen, else 0
  bool counted = false;  // seen and score >= kCountThreshold
};

// Other UAVs (or anything movable) that can hide points: spheres and oriented boxes.
struct Occluders {
  std::vector<SphereOccluder> spheres;
  std::vector<world::OrientedBox> boxes;
  bool empty() const { return spheres.empty() && boxes.empty(); }
  // Distance along the unit direction to the first occluder surface in (0, maxRange], or
  // +infinity. A ray starting inside an occluder hits its far side (as ODE rays do).
  double firstHit(const Vec3& origin, const Vec3& unitDirection, double maxRange) const;
};

class InspectionScorer {
 public:
  // Keeps references: the point set and the caster must outlive the scorer.
  InspectionScorer(const world::InterestPointSet& points, const world::RayCaster& caster,
                   ScoringMode mode);

  ScoringMode mode() const { return mode_; }

  // Evaluates every interest point within candidateRadius(spec) of the camera, in ascending
  // index order, into `out` (resized). Reuses internal buffers: the scorer itself does not
  // allocate once warm (InterestPointSet::withinRadius may).
  // Not thread-safe; use one scorer per thread (the caster and the points may be shared).
  void score(const CameraSpec& spec, const CaptureState& state, const Occluders& occluders,
             std::vector<PointScore>& out);

  // Every term for one point, whatever its distance (OutOfRange beyond the candidate radius,
  // with the other terms still filled in). For debugging and tests.
  PointScore scorePoint(const CameraSpec& spec, const CaptureState& state,
                        const Occluders& occluders, uint32_t index) const;

 private:
  struct Candidate {
    uint32_t slot;  // position in `out`
    Vec3 direction;
    double distance;
  };

  const world::InterestPointSet& points_;
  const world::RayCaster& caster_;
  ScoringMode mode_;
  std::vector<uint32_t> indices_;
  std::vector<Candidate> candidates_;
  std::vector<Vec3> origins_;
  std::vector<Vec3> directions_;
  std::vector<double> hits_;
};

// The pure formulas, exposed for tests and tools. `q` is the point in the camera frame.
// Blur: the point's displacement in pixels during the exposure; returns max(pix_y, pix_z).
double blurPixels(const CameraSpec& spec, const Vec3& q, const Vec3& velocityInCamera);
// 1 / max(pixels), capped at 1 (and 1 for no motion).
double blurQuality(double pixels);
// mm per pixel at q for a surface with camera-frame normal `normalInCamera` (normalised by the
// function); +infinity for an edge-on direction, NaN when a probe falls behind the camera plane.
double resolutionMmPerPixel(const CameraSpec& spec, const Vec3& q, const Vec3& normalInCamera,
                            ScoringMode mode);
// min(r_des / mm, 1); 0 for infinite mm.
double resolutionQuality(const CameraSpec& spec, double mmPerPixel);

}  // namespace coinspect::sensing
