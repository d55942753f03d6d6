#include "run_scene.h"

#include <mrpt/opengl/CArrow.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "coinspect/eval/run_plots.h"

namespace coinspect::eval::detail {

namespace {

const mrpt::img::TColor kStructure{205, 200, 192};
const mrpt::img::TColor kGround{205, 214, 196};
const mrpt::img::TColor kGridLines{160, 170, 158};
const mrpt::img::TColor kBoxColor{40, 110, 220};

mrpt::img::TColor toColor(Rgb c) {
  return {c.r, c.g, c.b};
}
mrpt::math::TPoint3Df toPoint(const Vec3& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

// A colour lit by a sun from behind the overview camera (south-west, high) and a weaker light
// from the opposite side, so that no face is flat black; both sides of a facet are lit alike
// (meshes are not always closed or consistently wound).
mrpt::img::TColor shaded(const mrpt::img::TColor& base, const Vec3& normal) {
  static const Vec3 kSun = Vec3(-0.3, -0.7, 0.65).normalized();  // toward the sun
  static const Vec3 kFill = Vec3(0.6, 0.4, 0.3).normalized();
  const double light = 0.5 + 0.42 * std::abs(normal.dot(kSun)) + 0.12 * std::abs(normal.dot(kFill));
  const auto channel = [light](uint8_t c) {
    return static_cast<uint8_t>(std::clamp(std::lround(c * light), 0L, 255L));
  };
  return {channel(base.R), channel(base.G), channel(base.B)};
}

// A unit's body: an octahedron longer along its heading (x), its faces shaded like the structure
// (unlit, see addStructure).
gl::CSetOfTriangles::Ptr unitBody(double radius, Rgb color) {
  const Vec3 tips[6] = {{1.5 * radius, 0, 0}, {-radius, 0, 0},      {0, radius, 0},
                        {0, -radius, 0},      {0, 0, 0.7 * radius}, {0, 0, -0.7 * radius}};
  auto body = gl::CSetOfTriangles::Create();
  body->enableLight(false);
  for (const int x : {0, 1})
    for (const int y : {2, 3})
      for (const int z : {4, 5}) {
        const Vec3 normal = (tips[y] - tips[x]).cross(tips[z] - tips[x]).normalized();
        gl::TTriangle triangle(toPoint(tips[x]), toPoint(tips[y]), toPoint(tips[z]));
        triangle.setColor(shaded(toColor(color), normal));
        body->insertTriangle(triangle);
      }
  return body;
}

world::Aabb sceneBounds(const world::Scenario& scenario, const RunTracks& tracks) {
  world::Aabb bounds = scenario.bounds();
  for (const auto& box : scenario.boxes)
    for (const auto& corner : box.vertices())
      bounds.extend(corner);
  for (const auto& unit : tracks.units)
    for (const auto& sample : unit.poses)
      bounds.extend(sample.position);
  if (bounds.empty()) bounds.extend(Vec3::Zero()), bounds.extend(Vec3::Ones());
  return bounds;
}

// Of the four diagonal views from above, the one that faces the most final score (points whose
// normal points toward the camera), so that the overview shows what was inspected; south-west
// when nothing was scored. Deterministic: ties keep the earlier candidate.
double bestOverviewAzimuth(const world::Scenario& scenario, const RunTracks& tracks) {
  constexpr double kCandidates[] = {-126.0, -54.0, 54.0, 126.0};
  double best = kCandidates[0], bestScore = 0.0;
  for (const double azimuth : kCandidates) {
    const double a = azimuth * M_PI / 180.0;
    const Vec3 toEye = Vec3(std::cos(a), std::sin(a), 0.55).normalized();
    double facing = 0.0;
    for (const auto& point : scenario.interestPoints.points())
      if (point.index < tracks.finalValues.size() && point.normal.dot(toEye) > 0.2)
        facing += tracks.finalValues[point.index];
    if (facing > bestScore) best = azimuth, bestScore = facing;
  }
  return best;
}

}  // namespace

RunScene::RunScene(const world::Scenario& scenario, const RunTracks& tracks)
    : tracks_(tracks), scene_(gl::COpenGLScene::Create()) {
  const world::Aabb bounds = sceneBounds(scenario, tracks);
  center_ = 0.5 * (bounds.min + bounds.max);
  radius_ = std::max(0.5 * bounds.size().norm(), 1.0);
  unitRadius_ = std::clamp(0.025 * radius_, 0.3, 4.0);  // visible, whatever the scene's size
  trailWidth_ = 0.45 * unitRadius_;
  auto viewport = scene_->getViewport();
  viewport->setCustomBackgroundColor(mrpt::img::TColorf(0.87f, 0.91f, 0.96f));
  // Only the units' heading arrows use MRPT's lighting; see addStructure.
  auto& lights = viewport->lightParameters();
  lights.ambient = mrpt::img::TColorf(0.5f, 0.5f, 0.5f);
  lights.diffuse = mrpt::img::TColorf(0.55f, 0.55f, 0.55f);
  lights.direction = mrpt::math::TVector3Df(0.4f, 0.5f, -0.77f).unitarize();
  addGround(scenario, bounds);
  addStructure(scenario);
  addBoxes(scenario);
  addPoints(scenario);
  overviewAzimuthDeg_ = bestOverviewAzimuth(scenario, tracks);
  addUnits();
}

void RunScene::advanceTo(double t) {
  time_ = std::max(time_, t);
  for (size_t i = 0; i < tracks_.units.size(); ++i) {
    const auto& unit = tracks_.units[i];
    if (unit.poses.empty()) continue;
    auto& next = trailNext_[i];
    while (next < unit.poses.size() && unit.poses[next].time <= time_) {
      if (next > 0 && unit.poses[next].position != unit.poses[next - 1].position) {
        const Vec3& a = unit.poses[next - 1].position;
        const Vec3& b = unit.poses[next].position;
        appendToTrail(trails_[i], a, b, unitColor(i));
      }
      ++next;
    }
    const PoseSample pose = poseAt(unit, time_);
    markers_[i]->setPose(mrpt::poses::CPose3D(pose.position.x(), pose.position.y(),
                                              pose.position.z(), pose.yaw, pose.pitch, pose.roll));
    const bool lost = unit.deathTime && time_ >= *unit.deathTime;
    bodies_[i].first->setVisibility(!lost);
    bodies_[i].second->setVisibility(lost);
  }
  bool recoloured = false;
  while (nextChange_ < tracks_.tallyChanges.size() &&
         tracks_.tallyChanges[nextChange_].time <= time_) {
    const auto& change = tracks_.tallyChanges[nextChange_++];
    if (change.index >= points_->size()) continue;
    const Rgb c = change.value > 0.0 ? scoreColor(change.value) : kUnscoredColor;
    points_->setPointColor_u8_fast(change.index, c.r, c.g, c.b);
    recoloured = true;
  }
  if (recoloured) points_->markAllPointsAsNew();
}

void RunScene::addGround(const world::Scenario& scenario, const world::Aabb& bounds) {
  // A plane somewhat larger than everything, and a grid of round spacing on it.
  const double half = 0.75 * std::max(bounds.size().x(), bounds.size().y()) + 0.2 * radius_;
  const double z = scenario.groundZ;
  const double x0 = center_.x() - half, x1 = center_.x() + half;
  const double y0 = center_.y() - half, y1 = center_.y() + half;
  for (int i = 0; i < 8; ++i)
    extremes_.emplace_back(i & 1 ? bounds.max.x() : bounds.min.x(),
                           i & 2 ? bounds.max.y() : bounds.min.y(),
                           i & 4 ? bounds.max.z() : bounds.min.z());
  for (double x : {x0, x1})
    for (double y : {y0, y1})
      extremes_.emplace_back(x, y, z);
  auto ground = gl::CSetOfTriangles::Create();
  ground->setName("ground");
  ground->enableLight(false);
  const float zg = static_cast<float>(z - 0.01 * radius_);  // below the grid: no z-fighting
  for (const auto& [a, b, c] :
       {std::array<std::array<double, 2>, 3>{{{x0, y0}, {x1, y0}, {x1, y1}}},
        std::array<std::array<double, 2>, 3>{{{x0, y0}, {x1, y1}, {x0, y1}}}}) {
    gl::TTriangle triangle(mrpt::math::TPoint3Df(a[0], a[1], zg),
                           mrpt::math::TPoint3Df(b[0], b[1], zg),
                           mrpt::math::TPoint3Df(c[0], c[1], zg));
    triangle.setColor(kGround);
    ground->insertTriangle(triangle);
  }
  scene_->insert(ground);
  // About ten to twenty cells a side, 1, 2 or 5 times a power of ten metres.
  const double raw = 2.0 * half / 12.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double spacing = magnitude * (raw / magnitude < 2.0   ? 1.0
                                      : raw / magnitude < 5.0 ? 2.0
                                                              : 5.0);
  auto grid = gl::CGridPlaneXY::Create(x0, x1, y0, y1, z + 0.002 * radius_, spacing);
  grid->setName("grid");
  grid->setColor_u8(kGridLines);
  scene_->insert(grid);
}

void RunScene::addStructure(const world::Scenario& scenario) {
  // Shading is baked into the triangle colours and MRPT's lighting is off: Debian's MRPT 2.5.8
  // lit-triangle shader (mediump GLSL ES) resolves depth wrongly on Mesa's llvmpipe, showing
  // the back faces of solids; the unlit shader does not (checked on a coloured cube).
  auto structure = gl::CSetOfTriangles::Create();
  structure->setName("structure");
  structure->enableLight(false);
  for (const auto& mesh : scenario.meshes)
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
      const auto& t = mesh.triangles[i];
      gl::TTriangle triangle(toPoint(mesh.vertex(t[0])), toPoint(mesh.vertex(t[1])),
                             toPoint(mesh.vertex(t[2])));
      triangle.setColor(shaded(kStructure, mesh.facetNormal(i)));
      structure->insertTriangle(triangle);
    }
  scene_->insert(structure);
}

void RunScene::addBoxes(const world::Scenario& scenario) {
  auto boxes = gl::CSetOfObjects::Create();
  boxes->setName("boxes");
  for (const auto& box : scenario.boxes) {
    const Vec3 half = 0.5 * box.size;
    auto outline = gl::CBox::Create(mrpt::math::TPoint3D(-half.x(), -half.y(), -half.z()),
                                    mrpt::math::TPoint3D(half.x(), half.y(), half.z()), true);
    outline->setName(box.name);
    outline->setBoxBorderColor(kBoxColor);
    outline->setColor_u8(kBoxColor);
    mrpt::math::CMatrixDouble44 pose = mrpt::math::CMatrixDouble44::Identity();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        pose(r, c) = box.rotation(r, c);
      pose(r, 3) = box.center[r];
    }
    outline->setPose(mrpt::poses::CPose3D(pose));
    boxes->insert(outline);
  }
  scene_->insert(boxes);
}

void RunScene::addPoints(const world::Scenario& scenario) {
  // Lifted off their surface along the normal, so that the surface does not hide them.
  const double lift = std::max(0.05, 0.005 * radius_);
  points_ = gl::CPointCloudColoured::Create();
  points_->setName("interest_points");
  points_->setPointSize(scenario.interestPoints.size() > 5000 ? 2.0f : 7.0f);
  for (const auto& point : scenario.interestPoints.points()) {
    const Vec3 p = point.position + lift * point.normal;
    points_->push_back(p.x(), p.y(), p.z(), kUnscoredColor.r / 255.0f, kUnscoredColor.g / 255.0f,
                       kUnscoredColor.b / 255.0f);
  }
  scene_->insert(points_);
}

void RunScene::addUnits() {
  for (size_t i = 0; i < tracks_.units.size(); ++i) {
    const auto& unit = tracks_.units[i];
    Trail trail;
    trail.group = gl::CSetOfObjects::Create();
    trail.group->setName("trajectory:" + unit.name);
    scene_->insert(trail.group);
    trails_.push_back(trail);
    trailNext_.push_back(0);

    // A body (two, for alive and lost, one of them hidden), an arrow along its heading, its
    // name above.
    auto marker = gl::CSetOfObjects::Create();
    marker->setName("unit:" + unit.name);
    auto body = unitBody(unitRadius_, unitColor(i));
    auto lostBody = unitBody(unitRadius_, kLostUnitColor);
    lostBody->setVisibility(false);
    marker->insert(body);
    marker->insert(lostBody);
    auto nose = gl::CArrow::Create(0, 0, 0, static_cast<float>(3 * unitRadius_), 0, 0, 0.35f,
                                   static_cast<float>(0.25 * unitRadius_),
                                   static_cast<float>(0.6 * unitRadius_));
    nose->setColor_u8(mrpt::img::TColor(40, 40, 40));
    marker->insert(nose);
    auto label = gl::CText::Create(unit.name);
    label->setLocation(0, 0, 2.0 * unitRadius_);
    label->setColor_u8(mrpt::img::TColor(20, 20, 20));
    marker->insert(label);
    scene_->insert(marker);
    markers_.push_back(marker);
    bodies_.push_back({body, lostBody});
  }
}

void RunScene::appendToTrail(Trail& trail, const Vec3& a, const Vec3& b, Rgb color) {
  const Vec3 d = b - a;
  if (d.norm() < 1e-9) return;
  if (!trail.chunk || trail.chunkSegments >= kChunk) {
    trail.chunk = gl::CSetOfTriangles::Create();
    trail.chunk->enableLight(false);
    trail.group->insert(trail.chunk);
    trail.chunkSegments = 0;
  }
  const Vec3 along = d.normalized();
  Vec3 side = along.cross(Vec3::UnitZ());
  if (side.norm() < 1e-6) side = Vec3::UnitX();
  side.normalize();
  const Vec3 up = side.cross(along).normalized();
  const double half = 0.5 * trailWidth_;
  for (const Vec3& offset : {Vec3(half * side), Vec3(half * up)}) {
    const Vec3 corners[4] = {a - offset, b - offset, b + offset, a + offset};
    for (const auto& [i, j, k] : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
      gl::TTriangle triangle(toPoint(corners[i]), toPoint(corners[j]), toPoint(corners[k]));
      triangle.setColor(toColor(color));
      trail.chunk->insertTriangle(triangle);
    }
  }
  ++trail.chunkSegments;
}

gl::CCamera overviewCamera(const RunScene& scene) {
  gl::CCamera camera;
  constexpr double kFovDeg = 40.0;
  camera.setProjectiveFOVdeg(kFovDeg);
  const Vec3 target = scene.center() - Vec3(0, 0, 0.1 * scene.radius());
  camera.setPointingAt(static_cast<float>(target.x()), static_cast<float>(target.y()),
                       static_cast<float>(target.z()));
  camera.setAzimuthDegrees(static_cast<float>(scene.overviewAzimuthDeg()));
  camera.setElevationDegrees(28.0f);
  camera.setZoomDistance(
      static_cast<float>(scene.radius() / std::sin(0.5 * kFovDeg * M_PI / 180.0)));
  return camera;
}

gl::CCamera chaseCamera(const RunScene& scene, const PoseSample& pose) {
  gl::CCamera camera;
  camera.setProjectiveFOVdeg(55.0f);
  camera.setPointingAt(static_cast<float>(pose.position.x()), static_cast<float>(pose.position.y()),
                       static_cast<float>(pose.position.z()));
  camera.setAzimuthDegrees(static_cast<float>(pose.yaw * 180.0 / M_PI + 180.0));
  camera.setElevationDegrees(20.0f);
  camera.setZoomDistance(static_cast<float>(std::max(8.0, 14.0 * scene.unitRadius())));
  return camera;
}

// Near and far planes hugging the scene's content along the view. Debian's MRPT 2.5.8 shaders
// declare their matrices `mediump`, which Mesa's llvmpipe evaluates in 16-bit floats: with a
// near plane at a few centimetres every depth rounds to the same value and whatever is drawn
// last wins (the grid showed through solids). A tight [near, far] keeps depths apart.
void setClipDistances(RunScene& scene, const gl::CCamera& camera, bool chase) {
  const double azimuth = camera.getAzimuthDegrees() * M_PI / 180.0;
  const double elevation = camera.getElevationDegrees() * M_PI / 180.0;
  const Vec3 toEye(std::cos(azimuth) * std::cos(elevation), std::sin(azimuth) * std::cos(elevation),
                   std::sin(elevation));
  const auto pointing = camera.getPointingAt();
  const Vec3 eye = Vec3(pointing.x, pointing.y, pointing.z) + camera.getZoomDistance() * toEye;
  double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
  for (const Vec3& corner : scene.extremes()) {
    const double depth = (corner - eye).dot(-toEye);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  // A chase camera is inside the scene: keep what lies between it and the unit it follows.
  const double near = chase ? 0.5 * camera.getZoomDistance() : std::max(0.05, 0.9 * nearest);
  const double far = std::max(near + 1.0, 1.1 * farthest);
  scene.scene().getViewport()->setViewportClipDistances(static_cast<float>(near),
                                                        static_cast<float>(far));
}

}  // namespace coinspect::eval::detail
