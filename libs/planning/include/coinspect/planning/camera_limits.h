// The two camera facts every inspection planner needs, from the CARIC scoring formulas
// (doc/scoring.md): how far to stand for full resolution, how fast to move for no blur.
#pragma once

namespace coinspect::planning {

struct CameraOptics {
  double focalLength = 0.016;      // m
  double pixelSize = 4.35e-6;      // m
  double exposure = 0.001;         // s
  double desiredMmPerPixel = 2.0;  // mm/px (r_des)
};

// Distance (m) at which a frontal surface is seen at exactly r_des mm/px, so q_res = 1 at or
// inside it: mm/px = 1000 c d / f  =>  d = r_des f / (1000 c). 7.356 m for MBS (r_des = 2).
double fullResolutionDistance(const CameraOptics& optics);

// Largest speed (m/s) across the line of sight that keeps the blur at or under one pixel
// (q_blur = 1) for a surface `distance` m away: f tau v / (c d) <= 1.
double blurFreeSpeed(const CameraOptics& optics, double distance);

}  // namespace coinspect::planning
