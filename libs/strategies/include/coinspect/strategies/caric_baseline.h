// `caric-baseline`: the CARIC organisers' baseline (team XXH's approach). Teams of one explorer
// and its nearest photographers (from the start positions every unit sees at take-off); boxes
// assigned to teams along a best-first path in proportion to team size (split along their
// longest side where a share ends); explorers circle their boxes layer by layer at a standoff
// (LiDAR mapping for the whole fleet through key frames); photographers divide their team's
// layers and circle them at the q_res = 1 distance, gimbal on the box surface, at the speed that
// keeps q_blur = 1. At the end (or when the time left only just covers the way back) every UAV
// returns above its start, where it was in line of sight of the ground station.
//
// Config [caric-baseline] (every key optional; doc/strategies.md):
//   inspect_distance      0     m from the box face; 0: the camera's q_res = 1 distance
//   inspect_layer_height  0     m; 0: 0.8 x the camera's vertical footprint at that distance
//   explore_distance      10    m from the box face
//   explore_layer_height  10    m
//   max_speed             2.5   m/s (photographers also keep q_blur = 1)
//   max_acceleration      1.0   m/s^2
//   safety_margin         0.8   m kept between a UAV's sphere and any mapped surface
//   grid_resolution       1.0   m, planning grid
//   min_height            3.0   m above the start height for any layer
//   takeoff_height        3.0   m climbed vertically first
//   unknown_space         near-boxes   blocked | free | near-boxes (runtime/robot_map.h)
//   unknown_box_margin    2.0   m (near-boxes)
//   explorer_sweep_every  0     insert every n-th own sweep in the explorer's map (0: key frames)
//   return_home           true
//   rate                  10    decisions per second (10 to 50)
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/strategies/caric_baseline_plan.h"
#include "coinspect/strategies/runtime/flight.h"
#include "coinspect/strategies/runtime/robot_map.h"

namespace coinspect::strategies {

using agent::BoxView;
using agent::Vec3;

struct CaricBaselineOptions {
  double inspectDistance = 0.0;
  double inspectLayerHeight = 0.0;
  double exploreDistance = 10.0;
  double exploreLayerHeight = 10.0;
  double maxSpeed = 2.5;
  double maxAcceleration = 1.0;
  double safetyMargin = 0.8;
  double gridResolution = 1.0;
  double minHeight = 3.0;
  double takeoffHeight = 3.0;
  runtime::UnknownSpace unknownSpace = runtime::UnknownSpace::BlockedNearBoxes;
  double unknownBoxMargin = 2.0;
  int explorerSweepEvery = 0;
  bool returnHome = true;
  double rate = 10.0;

  // Reads [caric-baseline]; throws InputError naming the file and key for a bad value.
  static CaricBaselineOptions read(const Config& config);
};

class CaricBaseline : public agent::Strategy {
 public:
  CaricBaseline(const CaricBaselineOptions& options, const agent::StrategyContext& context);

  agent::AgentCommand decide(const agent::AgentView& view) override;
  double decisionRate() const override { return options_.rate; }

  // The layers this unit flies (after the first plan; for tests and logs).
  const std::vector<baseline::Layer>& layers() const { return layers_; }
  bool planned() const { return planned_; }

 private:
  void makePlan(const agent::AgentView& view);
  void startLayer(const agent::AgentView& view);
  double standoff() const;
  double cruiseSpeed() const;
  Vec3 aimPoint(const Vec3& position) const;

  CaricBaselineOptions options_;
  agent::Role role_;
  std::vector<agent::FleetMember> fleet_;
  agent::CameraInfo camera_;
  double radius_ = 0.0;
  size_t self_ = 0;

  bool planned_ = false;
  std::vector<baseline::Layer> layers_;
  size_t layer_ = 0;
  bool layerStarted_ = false;
  bool goingHome_ = false;
  Vec3 home_ = Vec3::Zero();
  std::unique_ptr<runtime::RobotMap> map_;
  std::unique_ptr<runtime::Flight> flight_;
};

void registerCaricBaseline(agent::StrategyRegistry& registry);

}  // namespace coinspect::strategies
