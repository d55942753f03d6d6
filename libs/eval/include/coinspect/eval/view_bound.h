// How much of a scenario's score can be reached at all by a camera that keeps a clearance from
// the structure: every interest point is looked at, from both sides of its normal (the scoring has
// no back-face test and mesh normals may point inwards), along the normal and along directions
// turned from it by `tilts` about the vertical and about the horizontal, from each of
// `distances`; a view counts for a clearance when its body is at least that far from every mesh
// surface, `minHeight` above the ground and its camera not inside a closed structure (most axis
// rays from it hit the back of a facet); each view is scored exactly as a capture (static, level
// body). The result is an estimate of the attainable maximum, not a proof: other
// positions may see a little more, and no time budget, flight or line of sight to the ground
// station is taken into account. On the CARIC MBS scene many points lie on faces that look into
// gaps narrower than a UAV and its clearance (doc/strategies.md).
#pragma once

#include <cstddef>
#include <vector>

#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/world/ray_caster.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval {

struct ViewBoundOptions {
  std::vector<double> clearances = {0.0, 1.0, 2.0, 3.0};   // m, body to the nearest mesh surface
  std::vector<double> distances = {4.0, 7.0, 10.0, 13.0};  // m, camera to the point
  std::vector<double> tilts = {0.5, 1.0};                  // rad from the normal
  double minHeight = 1.0;                                  // m above the ground
};

struct ViewBoundRow {
  double clearance = 0.0;
  size_t views = 0;     // sampled views with at least this clearance
  size_t detected = 0;  // points with a best score >= 0.2 over those views
  double score = 0.0;   // sum over points of the best score
};

// One row per clearance, in the order given; with `bestPerPoint`, also each point's best score
// per clearance ([clearance][point]). Throws InputError for an empty list, a negative value or a
// zero distance.
std::vector<ViewBoundRow> staticViewBound(const world::Scenario& scenario,
                                          const world::RayCaster& caster,
                                          const world::CameraSpec& camera,
                                          sensing::ScoringMode mode,
                                          const ViewBoundOptions& options = {},
                                          std::vector<std::vector<double>>* bestPerPoint = nullptr);

}  // namespace coinspect::eval
