#include "coinspect/eval/view_bound.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"
#include "coinspect/sensing/camera_model.h"

namespace coinspect::eval {

namespace {

using world::Vec3;

void checkList(const std::vector<double>& values, const char* key, bool allowZero) {
  if (values.empty()) throw InputError("view bound", key, "needs at least one value");
  for (const double v : values)
    if (!std::isfinite(v) || v < 0.0 || (!allowZero && v == 0.0))
      throw InputError("view bound", key, allowZero ? "values must be >= 0" : "values must be > 0");
}

// The directions a point is looked at along (from the camera's side: camera = point + d * dir).
std::vector<Vec3> viewDirections(const Vec3& normal, const std::vector<double>& tilts) {
  const Vec3 horizontal(-normal.y(), normal.x(), 0.0);
  const Vec3 side = horizontal.norm() > 1e-3 ? Vec3(horizontal.normalized()) : Vec3(Vec3::UnitX());
  std::vector<Vec3> out = {normal};
  for (const double tilt : tilts)
    for (const double sign : {1.0, -1.0}) {
      out.push_back(Eigen::AngleAxisd(sign * tilt, Vec3::UnitZ()) * normal);
      out.push_back(Eigen::AngleAxisd(sign * tilt, side) * normal);
    }
  return out;
}

// True when `p` is inside a closed structure: most axis rays from it first hit the back of a facet
// (right-hand normals point out of the structure). The distance to the surface cannot tell: a
// camera inside a block is as far from its faces as one outside, and sees their insides.
bool insideStructure(const world::RayCaster& caster, const Vec3& p) {
  int backHits = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0}) {
      const Vec3 direction = sign * Vec3::Unit(axis);
      const auto hit = caster.closestHit(p, direction);
      if (hit && hit->normal.dot(direction) > 0.0) ++backHits;
    }
  return backHits >= 4;
}

}  // namespace

std::vector<ViewBoundRow> staticViewBound(const world::Scenario& scenario,
                                          const world::RayCaster& caster,
                                          const world::CameraSpec& camera,
                                          sensing::ScoringMode mode,
                                          const ViewBoundOptions& options,
                                          std::vector<std::vector<double>>* bestPerPoint) {
  checkList(options.clearances, "clearance", true);
  checkList(options.distances, "distance", false);
  checkList(options.tilts, "tilt", true);
  const auto& points = scenario.interestPoints;
  const size_t levels = options.clearances.size();
  const auto [narrowest, widest] =
      std::minmax_element(options.clearances.begin(), options.clearances.end());
  std::vector<std::vector<double>> best(levels, std::vector<double>(points.size(), 0.0));
  std::vector<ViewBoundRow> rows(levels);
  for (size_t k = 0; k < levels; ++k)
    rows[k].clearance = options.clearances[k];

  sensing::InspectionScorer scorer(points, caster, mode);
  const sensing::Occluders none;
  std::vector<sensing::PointScore> scores;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 target = points[i].position;
    for (const double side : {1.0, -1.0})
      for (const Vec3& direction : viewDirections(side * points[i].normal, options.tilts))
        for (const double distance : options.distances) {
          const sensing::CaptureState state =
              sensing::aimCamera(camera, target, -direction, distance);
          if (state.position.z() < scenario.groundZ + options.minHeight) continue;
          const double clearance = caster.distanceToSurface(state.position, *widest + 1e-6);
          if (clearance < *narrowest ||
              insideStructure(caster, sensing::cameraPose(camera, state).position))
            continue;
          scorer.score(camera, state, none, scores);
          for (size_t k = 0; k < levels; ++k) {
            if (clearance < options.clearances[k]) continue;
            ++rows[k].views;
            for (const auto& s : scores)
              if (s.counted) best[k][s.index] = std::max(best[k][s.index], s.score);
          }
        }
  }
  for (size_t k = 0; k < levels; ++k)
    for (const double b : best[k]) {
      rows[k].detected += b > 0.0 ? 1 : 0;
      rows[k].score += b;
    }
  if (bestPerPoint) *bestPerPoint = std::move(best);
  return rows;
}

}  // namespace coinspect::eval
