// 3D pictures of a recorded run, rendered by MRPT's offscreen CFBORender (EGL: headless, no X):
// the structure, the inspection boxes, the interest points coloured by the ground station's
// score, the trajectories and the units. The same mrpt::opengl::COpenGLScene can be saved as a
// .3Dscene file that MRPT's SceneViewer3D opens. MRPT's headers stay in the .cpp.
//
// EGL contexts belong to threads: the first render on a thread creates that thread's context
// (kept until the thread ends; every renderer of the thread shares it). When no EGL context can
// be created, rendering throws std::runtime_error saying which packages provide EGL.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "coinspect/eval/image.h"
#include "coinspect/eval/run_tracks.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval {

// Where the camera of a 3D picture is.
struct CameraView {
  enum class Mode { Overview, Chase } mode = Mode::Overview;
  std::string unit;  // Chase: the unit followed (from behind and above, along its heading)
};

// "overview" or "chase:<unit>" where <unit> has a track in `tracks`; throws InputError naming
// `source` (the option) otherwise.
CameraView parseCameraView(const std::string& text, const RunTracks& tracks,
                           const std::string& source);

// final3d.png (`png`, width x height): the state at the end of the run from the overview camera,
// with a title and a legend drawn over it; and `sceneFile` (.3Dscene), the scene without the
// overlay. Throws InputError naming a file that cannot be written.
void writeFinalScene3d(const world::Scenario& scenario, const RunTracks& tracks,
                       const std::filesystem::path& png, const std::filesystem::path& sceneFile,
                       int width, int height);

// Frames of a replay at `fps` per second of mission time cover t = 0, 1/fps, ... up to the
// run's end: floor(endTime * fps) + 1 frames (a rounding error of 1e-9 s is forgiven).
size_t replayFrameCount(double endTime, double fps);

// Frames of a replay: the scene at any time of the run (trajectories so far, units where they
// were, points coloured by the tally at that time), with the clock, the score and recent events
// drawn over it.
class ReplayRenderer {
 public:
  ReplayRenderer(const world::Scenario& scenario, const RunTracks& tracks, int width, int height,
                 const CameraView& view);
  ~ReplayRenderer();
  ReplayRenderer(const ReplayRenderer&) = delete;
  ReplayRenderer& operator=(const ReplayRenderer&) = delete;

  // The frame at time t (s). Times must not decrease from one call to the next.
  RgbImage frameAt(double t);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coinspect::eval
