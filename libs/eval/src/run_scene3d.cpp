#include "coinspect/eval/run_scene3d.h"

#include <mrpt/img/CImage.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include "coinspect/core/error.h"
#include "coinspect/eval/bitmap_font.h"
#include "coinspect/eval/canvas.h"
#include "coinspect/eval/run_plots.h"
#include "legend.h"
#include "offscreen.h"
#include "run_scene.h"

namespace coinspect::eval {

namespace {

using detail::chaseCamera;
using detail::overviewCamera;
using detail::RunScene;
using detail::setClipDistances;

constexpr Rgb kText{35, 35, 35};
constexpr Rgb kWhite{255, 255, 255};

// The title band at the top and the legend at the bottom left.
void drawOverlay(RgbImage& image, const std::vector<std::string>& lines,
                 const std::vector<detail::LegendEntry>& legend) {
  const int s = labelScale(image.width(), image.height());
  const int pad = 6 * s, row = textHeight(s) + 4 * s;
  veilRect(image, 0, 0, image.width(), pad + static_cast<int>(lines.size()) * row + pad / 2, kWhite,
           0.7);
  for (size_t i = 0; i < lines.size(); ++i)
    drawText(image, pad, pad + static_cast<int>(i) * row, lines[i], kText, s);
  if (!legend.empty())
    detail::drawLegend(image, pad, image.height() - pad - detail::legendHeight(legend, s), legend,
                       s);
}

std::vector<detail::LegendEntry> legendOf(const world::Scenario& scenario,
                                          const RunTracks& tracks) {
  auto legend = detail::unitEntries(scenario, tracks);
  for (const auto& unit : tracks.units)
    if (unit.deathTime) {
      legend.push_back({detail::LegendEntry::Kind::Unscored, "lost unit", kLostUnitColor});
      break;
    }
  legend.push_back({detail::LegendEntry::Kind::ScoreBar, "point score 0..1", kText});
  legend.push_back({detail::LegendEntry::Kind::Unscored, "not scored", kUnscoredColor});
  return legend;
}

// Q and detected at time t, from the tally records so far.
std::string scoreText(const RunTracks& tracks, double t) {
  double score = 0.0;
  uint64_t detected = 0;
  for (const auto& sample : tracks.tally) {
    if (sample.time > t) break;
    score = sample.totalScore;
    detected = sample.detected;
  }
  char text[128];
  std::snprintf(text, sizeof(text), "Q = %.2f, detected %" PRIu64 " / %" PRIu64, score, detected,
                tracks.pointCount);
  return text;
}

}  // namespace

CameraView parseCameraView(const std::string& text, const RunTracks& tracks,
                           const std::string& source) {
  if (text == "overview") return CameraView{};
  const std::string prefix = "chase:";
  if (text.compare(0, prefix.size(), prefix) == 0) {
    const std::string unit = text.substr(prefix.size());
    if (tracks.unitIndex(unit) < 0) {
      std::string known;
      for (const auto& track : tracks.units)
        known += (known.empty() ? "" : ", ") + track.name;
      throw InputError(source, "", "no unit '" + unit + "' in the rawlog (units: " + known + ")");
    }
    return CameraView{CameraView::Mode::Chase, unit};
  }
  throw InputError(source, "", "'" + text + "' is not 'overview' or 'chase:<unit>'");
}

void writeFinalScene3d(const world::Scenario& scenario, const RunTracks& tracks,
                       const std::filesystem::path& png, const std::filesystem::path& sceneFile,
                       int width, int height) {
  auto renderer = detail::makeOffscreenRenderer(width, height);
  RunScene scene(scenario, tracks);
  scene.advanceTo(tracks.endTime);
  const auto camera = overviewCamera(scene);
  setClipDistances(scene, camera, false);
  scene.scene().getViewport()->getCamera() = camera;  // what SceneViewer3D starts from
  renderer->setCamera(scene.scene(), camera);
  mrpt::img::CImage picture;
  renderer->render_RGB(scene.scene(), picture);
  RgbImage image = detail::toRgbImage(picture);
  char title[256];
  std::snprintf(title, sizeof(title), "%s: final state at t = %.1f s", scenario.name.c_str(),
                tracks.endTime);
  drawOverlay(image, {title, scoreText(tracks, tracks.endTime)}, legendOf(scenario, tracks));
  writePng(image, png);
  if (!scene.scene().saveToFile(sceneFile.string()))
    throw InputError(sceneFile.string(), "", "cannot write the 3D scene");
}

size_t replayFrameCount(double endTime, double fps) {
  COINSPECT_ASSERT(fps > 0.0 && endTime >= 0.0);
  return static_cast<size_t>(std::floor(endTime * fps + 1e-9)) + 1;
}

struct ReplayRenderer::Impl {
  Impl(const world::Scenario& scenario_, const RunTracks& tracks_, int width, int height,
       CameraView view_)
      : scenario(scenario_),
        tracks(tracks_),
        renderer(detail::makeOffscreenRenderer(width, height)),
        scene(scenario_, tracks_),
        view(std::move(view_)),
        legend(legendOf(scenario_, tracks_)) {}

  const world::Scenario& scenario;
  const RunTracks& tracks;
  std::unique_ptr<mrpt::opengl::CFBORender> renderer;
  RunScene scene;
  CameraView view;
  std::vector<detail::LegendEntry> legend;
};

ReplayRenderer::ReplayRenderer(const world::Scenario& scenario, const RunTracks& tracks, int width,
                               int height, const CameraView& view)
    : impl_(std::make_unique<Impl>(scenario, tracks, width, height, view)) {
  if (view.mode == CameraView::Mode::Chase && tracks.unitIndex(view.unit) < 0)
    throw InputError("camera view", "chase", "no unit '" + view.unit + "' in the rawlog");
}

ReplayRenderer::~ReplayRenderer() = default;

RgbImage ReplayRenderer::frameAt(double t) {
  COINSPECT_ASSERT(t >= impl_->scene.time());
  auto& scene = impl_->scene;
  scene.advanceTo(t);
  const bool chase = impl_->view.mode == CameraView::Mode::Chase;
  const auto camera =
      chase ? chaseCamera(scene,
                          poseAt(impl_->tracks.units[impl_->tracks.unitIndex(impl_->view.unit)], t))
            : overviewCamera(scene);
  setClipDistances(scene, camera, chase);
  impl_->renderer->setCamera(scene.scene(), camera);
  mrpt::img::CImage picture;
  impl_->renderer->render_RGB(scene.scene(), picture);
  RgbImage image = detail::toRgbImage(picture);

  char clock[160];
  std::snprintf(clock, sizeof(clock), "%s   t = %.2f s   %s   [%s]", impl_->scenario.name.c_str(),
                t, scoreText(impl_->tracks, t).c_str(),
                chase ? ("chase " + impl_->view.unit).c_str() : "overview");
  std::vector<std::string> lines = {clock};
  // The events of the last 10 s, newest last, at most four.
  constexpr double kEventWindow = 10.0;
  std::vector<std::string> recent;
  for (const auto& event : impl_->tracks.events) {
    if (event.time > t) break;
    if (event.time < t - kEventWindow) continue;
    char text[256];
    std::snprintf(text, sizeof(text), "%7.2f s  %s%s%s", event.time,
                  eventKindName(event.kind).c_str(), event.unit.empty() ? "" : " ",
                  event.unit.c_str());
    recent.push_back(text);
  }
  const size_t shown = std::min<size_t>(recent.size(), 4);
  lines.insert(lines.end(), recent.end() - shown, recent.end());
  drawOverlay(image, lines, impl_->legend);
  return image;
}

}  // namespace coinspect::eval
