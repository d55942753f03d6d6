// Private to the 3D pictures: the MRPT scene of a recorded run (structure, ground, boxes,
// interest points, trajectories, units) and the state it shows, advanced through time; the
// cameras that look at it.
#pragma once

#include <mrpt/opengl/CCamera.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTriangles.h>

#include <utility>
#include <vector>

#include "coinspect/eval/image.h"
#include "coinspect/eval/run_tracks.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval::detail {

namespace gl = mrpt::opengl;
using world::Vec3;

class RunScene {
 public:
  RunScene(const world::Scenario& scenario, const RunTracks& tracks);

  gl::COpenGLScene& scene() { return *scene_; }
  double time() const { return time_; }
  const Vec3& center() const { return center_; }
  double radius() const { return radius_; }
  double unitRadius() const { return unitRadius_; }
  // Azimuth (deg) of the overview camera: the diagonal view facing the most final score.
  double overviewAzimuthDeg() const { return overviewAzimuthDeg_; }
  // Corners of everything drawn (content bounds and the ground plane).
  const std::vector<Vec3>& extremes() const { return extremes_; }

  // Shows the run at time t (not before the current time): trails grow, units move, points
  // take the tally's colours.
  void advanceTo(double t);

 private:
  void addGround(const world::Scenario& scenario, const world::Aabb& bounds);

  void addStructure(const world::Scenario& scenario);

  void addBoxes(const world::Scenario& scenario);

  void addPoints(const world::Scenario& scenario);

  void addUnits();

  // A trajectory as a ribbon of two crossed quads per segment (seen from any side), unlit:
  // MRPT 2.5.8 draws every line one pixel wide. Segments go into chunks of kChunk so that a
  // growing trail re-uploads only its last chunk.
  struct Trail {
    gl::CSetOfObjects::Ptr group;
    gl::CSetOfTriangles::Ptr chunk;
    size_t chunkSegments = 0;
  };
  static constexpr size_t kChunk = 256;

  void appendToTrail(Trail& trail, const Vec3& a, const Vec3& b, Rgb color);

  const RunTracks& tracks_;
  gl::COpenGLScene::Ptr scene_;
  std::vector<Vec3> extremes_;
  Vec3 center_ = Vec3::Zero();
  double radius_ = 1.0, unitRadius_ = 0.5, trailWidth_ = 0.2, time_ = 0.0;
  double overviewAzimuthDeg_ = -126.0;
  gl::CPointCloudColoured::Ptr points_;
  std::vector<Trail> trails_;
  std::vector<size_t> trailNext_;
  std::vector<gl::CSetOfObjects::Ptr> markers_;
  std::vector<std::pair<gl::CSetOfTriangles::Ptr, gl::CSetOfTriangles::Ptr>>
      bodies_;  // alive, lost
  size_t nextChange_ = 0;
};

// The overview: from above along a diagonal (RunScene::overviewAzimuthDeg), the whole scene
// in view.
gl::CCamera overviewCamera(const RunScene& scene);
// Behind the unit along its heading, a little above.
gl::CCamera chaseCamera(const RunScene& scene, const PoseSample& pose);
// Sets the scene's near and far planes for this camera (see run_scene.cpp for why they matter).
void setClipDistances(RunScene& scene, const gl::CCamera& camera, bool chase);

}  // namespace coinspect::eval::detail
