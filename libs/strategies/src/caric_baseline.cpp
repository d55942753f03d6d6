#include "coinspect/strategies/caric_baseline.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"
#include "coinspect/planning/camera_limits.h"
#include "coinspect/strategies/runtime/camera_aim.h"
#include "coinspect/strategies/runtime/option_reader.h"

namespace coinspect::strategies {

namespace {

const char* const kSection = "caric-baseline";
constexpr double kOrbitSpacing = 2.0;  // m between orbit waypoints
constexpr double kHomeReserve = 20.0;  // s added to the estimated way home

double readDouble(const Config& config, const std::string& key, double fallback, double low,
                  double high, const std::string& range) {
  return runtime::readNumber(config, kSection, key, fallback, low, high, range);
}

}  // namespace

CaricBaselineOptions CaricBaselineOptions::read(const Config& config) {
  constexpr double kHuge = 1e6;
  CaricBaselineOptions o;
  o.inspectDistance =
      readDouble(config, "inspect_distance", o.inspectDistance, 0.0, 100.0, "in [0, 100] m");
  o.inspectLayerHeight =
      readDouble(config, "inspect_layer_height", o.inspectLayerHeight, 0.0, 100.0, "in [0, 100] m");
  o.exploreDistance =
      readDouble(config, "explore_distance", o.exploreDistance, 1.0, 100.0, "in [1, 100] m");
  o.exploreLayerHeight = readDouble(config, "explore_layer_height", o.exploreLayerHeight, 0.5,
                                    100.0, "in [0.5, 100] m");
  o.maxSpeed = readDouble(config, "max_speed", o.maxSpeed, 0.1, 20.0, "in [0.1, 20] m/s");
  o.maxAcceleration =
      readDouble(config, "max_acceleration", o.maxAcceleration, 0.1, 10.0, "in [0.1, 10] m/s^2");
  o.safetyMargin = readDouble(config, "safety_margin", o.safetyMargin, 0.0, 10.0, "in [0, 10] m");
  o.gridResolution =
      readDouble(config, "grid_resolution", o.gridResolution, 0.25, 4.0, "in [0.25, 4] m");
  o.minHeight = readDouble(config, "min_height", o.minHeight, 0.0, kHuge, ">= 0 m");
  o.takeoffHeight =
      readDouble(config, "takeoff_height", o.takeoffHeight, 0.5, 50.0, "in [0.5, 50] m");
  const std::string unknown =
      config.getString(kSection, "unknown_space", runtime::toString(o.unknownSpace));
  if (!runtime::parseUnknownSpace(unknown, &o.unknownSpace))
    throw InputError(config.source(), std::string("[") + kSection + "] unknown_space",
                     "expected blocked, free or near-boxes, got '" + unknown + "'");
  o.unknownBoxMargin =
      readDouble(config, "unknown_box_margin", o.unknownBoxMargin, 0.0, 50.0, "in [0, 50] m");
  const long long every = config.getInt(kSection, "explorer_sweep_every", o.explorerSweepEvery);
  if (every < 0 || every > 1000)
    throw InputError(config.source(), std::string("[") + kSection + "] explorer_sweep_every",
                     "must be in [0, 1000] (0: key frames only)");
  o.explorerSweepEvery = static_cast<int>(every);
  o.returnHome = config.getBool(kSection, "return_home", o.returnHome);
  o.rate = readDouble(config, "rate", o.rate, 10.0, 50.0,
                      "in [10, 50] Hz (setpoints expire after 0.1 s)");
  return o;
}

CaricBaseline::CaricBaseline(const CaricBaselineOptions& options,
                             const agent::StrategyContext& context)
    : options_(options),
      role_(context.role),
      fleet_(context.fleet),
      camera_(context.camera),
      radius_(context.collisionRadius),
      self_(context.unitIndex) {
  runtime::FlightOptions flight;
  flight.radius = radius_;
  flight.safetyMargin = options.safetyMargin;
  flight.unknown = planning::UnknownPolicy::Blocked;  // the RobotMap grid applies the policy
  flight.limits.speed = options.maxSpeed;
  flight.limits.acceleration = options.maxAcceleration;
  flight.takeoffHeight = options.takeoffHeight;
  std::vector<std::string> names;
  for (const auto& member : fleet_)
    names.push_back(member.name);
  flight_ = std::make_unique<runtime::Flight>(flight, names, self_);
}

double CaricBaseline::standoff() const {
  if (role_ == agent::Role::Explorer) return options_.exploreDistance;
  return options_.inspectDistance > 0.0
             ? options_.inspectDistance
             : planning::fullResolutionDistance(runtime::cameraOptics(camera_));
}

double CaricBaseline::cruiseSpeed() const {
  if (role_ == agent::Role::Explorer) return options_.maxSpeed;
  return std::min(options_.maxSpeed,
                  planning::blurFreeSpeed(runtime::cameraOptics(camera_), standoff()));
}

void CaricBaseline::makePlan(const agent::AgentView& view) {
  planned_ = true;
  // Start positions: own odometry and the neighbours in line of sight now (before take-off every
  // unit sees the others; a unit out of sight is left out of the plan).
  std::vector<baseline::UnitStart> starts;
  int me = -1;
  double groundZ = view.odometry.position.z();
  for (const auto& member : fleet_) {
    baseline::UnitStart start{member.name, member.role, Vec3::Zero()};
    bool known = false;
    if (member.name == view.name) {
      start.position = view.odometry.position;
      known = true;
      me = static_cast<int>(starts.size());
    }
    for (const auto& neighbour : view.neighbours)
      if (neighbour.name == member.name) {
        start.position = neighbour.odometry.position;
        known = true;
      }
    if (!known) continue;
    if (member.role != agent::Role::GroundStation) groundZ = std::min(groundZ, start.position.z());
    starts.push_back(start);
  }
  groundZ -= 0.1;  // UAVs spawn 0.1 m above the ground (CARIC)
  home_ = view.odometry.position + Vec3(0, 0, options_.takeoffHeight);

  const std::vector<BoxView> boxes = view.boxes ? *view.boxes : std::vector<BoxView>{};
  runtime::RobotMapOptions mapOptions;
  mapOptions.gridResolution = options_.gridResolution;
  mapOptions.regionMargin = std::max(options_.exploreDistance, standoff()) + 5.0;
  mapOptions.unknown = options_.unknownSpace;
  mapOptions.boxMargin = options_.unknownBoxMargin;
  mapOptions.ownSweepEvery = role_ == agent::Role::Explorer ? options_.explorerSweepEvery : 0;
  if (boxes.empty()) return;  // nothing to inspect: hover after take-off
  map_ = std::make_unique<runtime::RobotMap>(mapOptions, boxes, groundZ);
  // Where the unit stands and climbs is free, even under a box.
  flight_->openTakeoffColumn(*map_, view.odometry.position, view.time);

  const auto teams = baseline::formTeams(starts);
  const auto teamBoxes = baseline::assignBoxes(boxes, teams, starts);
  const double minZ = groundZ + options_.minHeight;
  for (size_t t = 0; t < teams.size(); ++t) {
    const auto& team = teams[t];
    if (team.explorer == me) {
      layers_ = baseline::layersOf(teamBoxes[t], options_.exploreLayerHeight, minZ, standoff());
      return;
    }
    const auto it = std::find(team.photographers.begin(), team.photographers.end(), me);
    if (it == team.photographers.end()) continue;
    double layerHeight = options_.inspectLayerHeight;
    if (layerHeight <= 0.0) {
      const double vfov = camera_.verticalFov > 0.0 ? camera_.verticalFov : M_PI / 3.0;
      layerHeight = 0.8 * 2.0 * standoff() * std::tan(0.5 * vfov);
    }
    const auto all = baseline::layersOf(teamBoxes[t], layerHeight, minZ, standoff());
    const auto parts = baseline::divideLayers(all, team.photographers.size());
    layers_ = parts[static_cast<size_t>(it - team.photographers.begin())];
    return;
  }
}

Vec3 CaricBaseline::aimPoint(const Vec3& position) const {
  if (layer_ < layers_.size() && !goingHome_) {
    const auto& layer = layers_[layer_];
    return runtime::closestPointOnBox(layer.box, Vec3(position.x(), position.y(), layer.z));
  }
  // Otherwise the nearest point of any box (captures on the way still count).
  Vec3 best = position + Vec3(1, 0, 0);
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const auto& layer : layers_) {
    const Vec3 p = runtime::closestPointOnBox(layer.box, position);
    if ((p - position).norm() < bestDistance) {
      bestDistance = (p - position).norm();
      best = p;
    }
  }
  return best;
}

void CaricBaseline::startLayer(const agent::AgentView& view) {
  const auto& layer = layers_[layer_];
  auto route =
      runtime::standoffOrbit(layer.box, layer.z, standoff(), kOrbitSpacing, view.odometry.position);
  route.push_back(route.front());  // close the loop
  flight_->follow(route, cruiseSpeed());
  layerStarted_ = true;
}

agent::AgentCommand CaricBaseline::decide(const agent::AgentView& view) {
  agent::AgentCommand command;
  if (role_ == agent::Role::GroundStation || !view.alive) return command;
  if (!planned_) {
    // Links come up within the first 20 ms: wait for the neighbours before planning.
    if (view.neighbours.empty() && view.time < 0.5) return command;
    makePlan(view);
  }
  if (map_) {
    map_->update(view);
    map_->refresh(view.time);
  }
  const Vec3 position = view.odometry.position;

  if (options_.returnHome && !goingHome_ && view.started && map_) {
    const double reserve = (position - home_).norm() / options_.maxSpeed * 1.5 + kHomeReserve;
    if (view.timeLeft < reserve) {
      goingHome_ = true;
      flight_->goTo(home_, options_.maxSpeed);
    }
  }
  if (!goingHome_ && map_) {
    if (layerStarted_ && !flight_->takingOff() && (flight_->done() || flight_->failed())) {
      if (flight_->failed()) baseline::requeueFailedLayer(layers_, layer_);
      ++layer_;
      layerStarted_ = false;
    }
    if (!layerStarted_) {
      if (layer_ < layers_.size()) {
        startLayer(view);
      } else if (options_.returnHome) {
        goingHome_ = true;
        flight_->goTo(home_, options_.maxSpeed);
      } else {
        flight_->hover();
      }
    }
  }
  const Vec3 target = aimPoint(position);
  if (map_) {
    command.setpoint = flight_->step(view, *map_);
    if (!flight_->takingOff())
      command.setpoint->yaw = runtime::headingTowards(position, target, view.odometry.yaw);
  }
  command.gimbal = runtime::aimCamera(view.odometry, camera_, view.gimbal, target);
  return command;
}

void registerCaricBaseline(agent::StrategyRegistry& registry) {
  registry.registerStrategy("caric-baseline", [](const agent::StrategyContext& context) {
    return std::make_unique<CaricBaseline>(CaricBaselineOptions::read(context.config), context);
  });
}

}  // namespace coinspect::strategies
