#include "coinspect/sensing/inspection_scorer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::sensing {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The reference compares angles in degrees computed from atan; a point built to lie exactly on
// the FOV edge lands within a few ulps either side of it. This slack (far below any physical
// meaning) makes the inclusive edge hold for such points.
constexpr double kFovSlack = 1e-9;

// Everything about the camera that is the same for all points of one capture.
struct CaptureFrame {
  CameraPose pose;
  Eigen::Matrix3d worldToCamera;  // R_WC^T
  CameraTwist twist;
};

CaptureFrame makeFrame(const CameraSpec& spec, const CaptureState& state) {
  CaptureFrame frame;
  frame.pose = cameraPose(spec, state);
  frame.worldToCamera = frame.pose.rotation.transpose();
  frame.twist = cameraTwist(spec, state);
  return frame;
}

// Fills distance, q, the FOV reason and the blur/resolution terms. Returns true when the point is
// inside the field of view (the ray test is then still to be done).
bool evaluateGeometry(const CameraSpec& spec, const CaptureFrame& frame,
                      const world::InterestPoint& point, ScoringMode mode, PointScore& ps) {
  const Vec3 offset = point.position - frame.pose.position;
  ps.distance = offset.norm();
  const Vec3 q = frame.worldToCamera * offset;
  ps.inCamera = q;
  if (q.x() <= 0.0) {
    ps.reason = NotSeenReason::BehindCamera;
    return false;
  }
  // Velocity of the point relative to the camera, in the camera frame:
  // R_WC^T (w_WC x (p_C - p)) - R_WC^T v_WC.
  const Vec3 velocity =
      frame.worldToCamera * (frame.twist.angular.cross(-offset) - frame.twist.linear);
  ps.blurPixels = blurPixels(spec, q, velocity);
  ps.qBlur = blurQuality(ps.blurPixels);
  ps.mmPerPixel = resolutionMmPerPixel(spec, q, frame.worldToCamera * point.normal, mode);
  ps.qRes = std::isnan(ps.mmPerPixel) ? 0.0 : resolutionQuality(spec, ps.mmPerPixel);

  if (std::abs(std::atan(q.y() / q.x())) > spec.horizontalFov / 2.0 + kFovSlack) {
    ps.reason = NotSeenReason::OutsideHorizontalFov;
    return false;
  }
  if (std::abs(std::atan(q.z() / q.x())) > spec.verticalFov / 2.0 + kFovSlack) {
    ps.reason = NotSeenReason::OutsideVerticalFov;
    return false;
  }
  return true;
}

// Applies the line-of-sight rule given the first hit distance along the ray, then the score.
void finish(ScoringMode mode, double hit, PointScore& ps) {
  const double tolerance = world::kPointVisibilityTolerance;
  if (mode == ScoringMode::Caric) {
    // The reference accepts only a first hit within the tolerance of the point; a ray that hits
    // nothing reports 1000 m and so fails too.
    if (std::abs(hit - ps.distance) > tolerance) {
      ps.reason = hit < ps.distance ? NotSeenReason::Occluded : NotSeenReason::NoSurfaceHit;
      return;
    }
  } else if (hit < ps.distance - tolerance) {
    ps.reason = NotSeenReason::Occluded;
    return;
  }
  if (std::isnan(ps.mmPerPixel)) {
    ps.reason = NotSeenReason::DegenerateResolution;
    return;
  }
  ps.seen = true;
  ps.reason = NotSeenReason::None;
  ps.score = ps.qBlur * ps.qRes;
  ps.counted = ps.score >= kCountThreshold;
}

double rayRange(double distance) {
  return distance + 2.0 * world::kPointVisibilityTolerance;
}

}  // namespace

const char* toString(ScoringMode mode) {
  switch (mode) {
    case ScoringMode::Caric:
      return "caric";
    case ScoringMode::Strict:
      return "strict";
  }
  return "?";
}

ScoringMode parseScoringMode(const std::string& text, const std::string& source) {
  if (text == "caric") return ScoringMode::Caric;
  if (text == "strict") return ScoringMode::Strict;
  throw InputError(source, "mode", "unknown scoring mode '" + text + "' (caric or strict)");
}

const char* toString(NotSeenReason reason) {
  switch (reason) {
    case NotSeenReason::None:
      return "seen";
    case NotSeenReason::OutOfRange:
      return "out-of-range";
    case NotSeenReason::BehindCamera:
      return "behind-camera";
    case NotSeenReason::OutsideHorizontalFov:
      return "outside-hfov";
    case NotSeenReason::OutsideVerticalFov:
      return "outside-vfov";
    case NotSeenReason::Occluded:
      return "occluded";
    case NotSeenReason::NoSurfaceHit:
      return "no-surface-hit";
    case NotSeenReason::DegenerateResolution:
      return "degenerate-resolution";
  }
  return "?";
}

double blurPixels(const CameraSpec& spec, const Vec3& q, const Vec3& velocityInCamera) {
  const Vec3 moved = q + velocityInCamera * spec.exposureTime;
  const double pixY =
      spec.focalLength * std::abs(q.y() / q.x() - moved.y() / moved.x()) / spec.pixelSize;
  const double pixZ =
      spec.focalLength * std::abs(q.z() / q.x() - moved.z() / moved.x()) / spec.pixelSize;
  return std::max(pixY, pixZ);
}

double blurQuality(double pixels) {
  if (!(pixels > 0.0)) return 1.0;  // no motion at all: 1 / 0 capped at 1
  return std::min(1.0 / pixels, 1.0);
}

double resolutionMmPerPixel(const CameraSpec& spec, const Vec3& q, const Vec3& normalInCamera,
                            ScoringMode mode) {
  const Vec3 n = normalInCamera.normalized();
  // Directions in the surface's tangent plane, one in the camera x-z plane (vertical image
  // axis) and one in the x-y plane (horizontal image axis). The reference leaves them
  // unnormalised: their length shrinks as the normal leaves the optical axis.
  Vec3 dv(-n.z(), 0.0, n.x());
  Vec3 du(-n.y(), n.x(), 0.0);
  if (mode == ScoringMode::Strict) {
    if (dv.norm() > 0.0) dv.normalize();
    if (du.norm() > 0.0) du.normalize();
  }
  const Vec3 vPlus = q + kResolutionProbe * dv, vMinus = q - kResolutionProbe * dv;
  const Vec3 uPlus = q + kResolutionProbe * du, uMinus = q - kResolutionProbe * du;
  // The reference skips the point when a probe has x < 0; x == 0 would divide by zero there,
  // so it is treated the same way here.
  if (vPlus.x() <= 0.0 || vMinus.x() <= 0.0 || uPlus.x() <= 0.0 || uMinus.x() <= 0.0) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double f = spec.focalLength;
  // The probes span 2 * 0.5 mm = 1 mm, so pixel size / image displacement is mm per pixel.
  const double dV = std::abs(f * vPlus.z() / vPlus.x() - f * vMinus.z() / vMinus.x());
  const double dU = std::abs(f * uPlus.y() / uPlus.x() - f * uMinus.y() / uMinus.x());
  const double mmV = dV > 0.0 ? spec.pixelSize / dV : kInfinity;
  const double mmU = dU > 0.0 ? spec.pixelSize / dU : kInfinity;
  return std::max(mmV, mmU);
}

double resolutionQuality(const CameraSpec& spec, double mmPerPixel) {
  if (std::isinf(mmPerPixel)) return 0.0;
  if (!(mmPerPixel > 0.0)) return 1.0;
  return std::min(spec.desiredMmPerPixel / mmPerPixel, 1.0);
}

double Occluders::firstHit(const Vec3& origin, const Vec3& unitDirection, double maxRange) const {
  double best = kInfinity;
  for (const SphereOccluder& sphere : spheres) {
    const Vec3 rel = origin - sphere.center;
    const double b = unitDirection.dot(rel);
    const double c = rel.squaredNorm() - sphere.radius * sphere.radius;
    const double disc = b * b - c;
    if (disc < 0.0) continue;
    const double root = std::sqrt(disc);
    const double near = -b - root, far = -b + root;
    const double t = near > 0.0 ? near : far;
    if (t > 0.0 && t <= maxRange) best = std::min(best, t);
  }
  for (const world::OrientedBox& box : boxes) {
    const Vec3 o = box.toBox(origin);
    const Vec3 d = box.rotation.transpose() * unitDirection;
    const Vec3 half = box.size / 2.0;
    double tMin = -kInfinity, tMax = kInfinity;
    bool miss = false;
    for (int axis = 0; axis < 3 && !miss; ++axis) {
      if (d[axis] == 0.0) {
        miss = std::abs(o[axis]) > half[axis];
        continue;
      }
      double t1 = (-half[axis] - o[axis]) / d[axis];
      double t2 = (half[axis] - o[axis]) / d[axis];
      if (t1 > t2) std::swap(t1, t2);
      tMin = std::max(tMin, t1);
      tMax = std::min(tMax, t2);
      miss = tMax < tMin;
    }
    if (miss) continue;
    const double t = tMin > 0.0 ? tMin : tMax;
    if (t > 0.0 && t <= maxRange) best = std::min(best, t);
  }
  return best;
}

InspectionScorer::InspectionScorer(const world::InterestPointSet& points,
                                   const world::RayCaster& caster, ScoringMode mode)
    : points_(points), caster_(caster), mode_(mode) {}

void InspectionScorer::score(const CameraSpec& spec, const CaptureState& state,
                             const Occluders& occluders, std::vector<PointScore>& out) {
  const CaptureFrame frame = makeFrame(spec, state);
  points_.withinRadius(frame.pose.position, candidateRadius(spec), indices_);
  out.resize(indices_.size());
  candidates_.clear();
  origins_.clear();
  directions_.clear();
  double farthest = 0.0;
  for (size_t k = 0; k < indices_.size(); ++k) {
    const world::InterestPoint& point = points_[indices_[k]];
    PointScore& ps = out[k];
    ps = PointScore{};
    ps.index = indices_[k];
    if (!evaluateGeometry(spec, frame, point, mode_, ps)) continue;
    const Vec3 direction = (point.position - frame.pose.position) / ps.distance;
    candidates_.push_back({static_cast<uint32_t>(k), direction, ps.distance});
    origins_.push_back(frame.pose.position);
    directions_.push_back(direction);
    farthest = std::max(farthest, ps.distance);
  }
  if (candidates_.empty()) return;
  const double range = rayRange(farthest);
  caster_.closestHits(origins_, directions_, range, hits_);
  COINSPECT_ASSERT(hits_.size() == candidates_.size());
  for (size_t i = 0; i < candidates_.size(); ++i) {
    const Candidate& candidate = candidates_[i];
    double hit = hits_[i];
    if (!occluders.empty()) {
      hit = std::min(hit, occluders.firstHit(frame.pose.position, candidate.direction, range));
    }
    finish(mode_, hit, out[candidate.slot]);
  }
}

PointScore InspectionScorer::scorePoint(const CameraSpec& spec, const CaptureState& state,
                                        const Occluders& occluders, uint32_t index) const {
  COINSPECT_ASSERT(index < points_.size());
  const CaptureFrame frame = makeFrame(spec, state);
  const world::InterestPoint& point = points_[index];
  PointScore ps;
  ps.index = index;
  const bool inView = evaluateGeometry(spec, frame, point, mode_, ps);
  if (ps.distance > candidateRadius(spec)) {
    ps.reason = NotSeenReason::OutOfRange;
    return ps;
  }
  if (!inView) return ps;
  const Vec3 direction = (point.position - frame.pose.position) / ps.distance;
  const double range = rayRange(ps.distance);
  double hit = kInfinity;
  if (auto meshHit = caster_.closestHit(frame.pose.position, direction, range)) {
    hit = meshHit->distance;
  }
  hit = std::min(hit, occluders.firstHit(frame.pose.position, direction, range));
  finish(mode_, hit, ps);
  return ps;
}

}  // namespace coinspect::sensing
