// Hand-written rawlogs for the evaluator's unit tests: a wall with interest points, a ground
// station and two photographers, and a writer that records captures (scored as the mission
// scores them), links, events (deaths, ...), tally updates and the end at chosen physics ticks.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "coinspect/record/observations.h"
#include "coinspect/record/rawlog_writer.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/world/ray_caster.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval::test {

inline constexpr double kStep = 0.0025;  // physics step of the synthetic runs: merges every 8 ticks

// A solid wall 10 <= x <= 11, |y| <= 5, 0 <= z <= 10; interest points every 0.5 m on its face
// x = 10 for |y| <= 2, 3 <= z <= 7 (45 points, normal -x). Units: "gcs" (ground station), "a"
// and "b" (photographers).
inline world::Scenario wallScenario() {
  world::Scenario scenario;
  scenario.name = "wall";
  world::TriangleMesh mesh;
  mesh.name = "wall";
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(i & 1 ? 11.0f : 10.0f, i & 2 ? 5.0f : -5.0f, i & 4 ? 10.0f : 0.0f);
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  scenario.meshes.push_back(mesh);
  std::vector<world::InterestPoint> points;
  for (int iy = -4; iy <= 4; iy += 2)
    for (int iz = 6; iz <= 14; ++iz) {
      world::InterestPoint p;
      p.position = world::Vec3(10.0, 0.5 * iy, 0.5 * iz);
      p.normal = world::Vec3(-1, 0, 0);
      points.push_back(p);
    }
  scenario.interestPoints = world::InterestPointSet(points);
  for (const auto& [name, role] : {std::pair{"gcs", world::UnitRole::GroundStation},
                                   std::pair{"a", world::UnitRole::Photographer},
                                   std::pair{"b", world::UnitRole::Photographer}}) {
    world::UnitSpec unit;
    unit.name = name;
    unit.role = role;
    scenario.fleet.push_back(unit);
  }
  return scenario;
}

// Writes a rawlog of the wall scenario tick by tick; captures are scored by the scorer the
// evaluator rebuilds, so the recorded points agree with the re-scored ones.
class SyntheticRun {
 public:
  SyntheticRun(const std::filesystem::path& path, const world::Scenario& scenario,
               sensing::ScoringMode mode)
      : scenario_(scenario),
        caster_(scenario.meshes, scenario.groundZ),
        scorer_(scenario.interestPoints, caster_, mode),
        writer_(path, record::RunHeader{"test", 1, "0", "[mission]\n"}) {}

  static double at(long long tick) { return static_cast<double>(tick) * kStep; }

  // A level camera at (x, 0, 5) looking at the wall (+x): at x = 5 every point scores 1.
  void capture(long long tick, const std::string& unit, double x) {
    const auto& camera = scenario_.fleet[unitIndex(unit)].camera;
    sensing::CaptureState state;
    state.position = world::Vec3(x, 0.0, 5.0) - camera.positionInBody;
    std::vector<sensing::PointScore> scores;
    scorer_.score(camera, state, {}, scores);
    writer_.writeCapture(unit, at(tick), Eigen::Isometry3d::Identity(), state, {}, scores);
    lastScores_ = scores;
  }
  void link(long long tick, const std::string& a, const std::string& b, bool linked) {
    writer_.writeLinkChanges(at(tick), {{a, b, linked}});
  }
  void event(long long tick, record::MissionEventKind kind, const std::string& unit,
             const std::string& detail) {
    writer_.writeEvent(at(tick), kind, unit, detail);
  }
  void death(long long tick, const std::string& unit) {
    writer_.writeEvent(at(tick), record::MissionEventKind::Death, unit, "test");
  }
  void tally(long long tick, const std::vector<record::TallyChangeRecord>& changes,
             uint64_t detected, double total) {
    writer_.writeTally(at(tick), changes, detected, scenario_.interestPoints.size(), total);
  }
  void pose(long long tick, const std::string& unit) {
    writer_.writeGroundTruth(unit, at(tick), Eigen::Isometry3d::Identity(), Eigen::Vector3d::Zero(),
                             Eigen::Vector3d::Zero());
  }
  void end(long long tick) {
    writer_.writeEvent(at(tick), record::MissionEventKind::End, "", "budget used");
    writer_.close();
  }
  const std::vector<sensing::PointScore>& lastScores() const { return lastScores_; }

 private:
  size_t unitIndex(const std::string& name) const {
    for (size_t i = 0; i < scenario_.fleet.size(); ++i)
      if (scenario_.fleet[i].name == name) return i;
    return 0;
  }

  const world::Scenario& scenario_;
  world::RayCaster caster_;
  sensing::InspectionScorer scorer_;
  record::RawlogWriter writer_;
  std::vector<sensing::PointScore> lastScores_;
};

}  // namespace coinspect::eval::test
