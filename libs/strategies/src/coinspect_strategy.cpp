#include "coinspect/strategies/coinspect/coinspect_strategy.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"
#include "coinspect/planning/routing_tsp.h"
#include "coinspect/planning/viewpoint.h"
#include "coinspect/strategies/coinspect/exploration_layers.h"
#include "coinspect/strategies/coinspect/patch_choice.h"
#include "coinspect/strategies/runtime/box_geometry.h"
#include "coinspect/strategies/runtime/camera_aim.h"

namespace coinspect::strategies::coinspect_strategy {

namespace {

constexpr double kNever = -1e300;
constexpr double kFaceSpacing = 4.0;     // m between work-partition samples of the box faces
constexpr double kPatchSize = 2.0;       // m, surface patches the coverage plans over
constexpr double kSurfaceNearBox = 1.0;  // m: mapped surface farther from every box is not a target
constexpr double kReached = 1.2;         // m from a stop's body position that counts as there
constexpr size_t kStopsPerPlan = 8;      // viewpoints flown per plan (each leg may need a search)
constexpr size_t kPatchesPerPlan = 120;  // nearest uninspected patches a plan covers
constexpr int kAttemptsPerPatch = 2;     // plans that may pick a patch before it is given up
constexpr size_t kFramesPerDecision = 4;  // key frames inserted per decision (~2 ms each at 1 m)
constexpr double kRoofHeight = 3.0;       // m above a free roof where explorers orbit

std::vector<std::string> fleetNames(const std::vector<agent::FleetMember>& fleet) {
  std::vector<std::string> names;
  for (const auto& member : fleet)
    names.push_back(member.name);
  return names;
}

double readPositive(const Config& config, const std::string& key, double fallback) {
  const double value = config.getDouble("coinspect", key, fallback);
  if (!(value > 0.0) || !std::isfinite(value))
    throw InputError(config.source(), "[coinspect] " + key, "must be a finite number > 0");
  return value;
}

}  // namespace

CoinspectOptions CoinspectOptions::read(const Config& config) {
  CoinspectOptions o;
  o.exploreTime = config.getDouble("coinspect", "explore_time", o.exploreTime);
  if (!(o.exploreTime >= 0.0) || !std::isfinite(o.exploreTime))
    throw InputError(config.source(), "[coinspect] explore_time", "must be a finite number >= 0");
  o.exploreStandoff = readPositive(config, "explore_standoff", o.exploreStandoff);
  o.viewDistance = readPositive(config, "view_distance", o.viewDistance);
  if (o.viewDistance > 2.0)
    throw InputError(config.source(), "[coinspect] view_distance",
                     "is a fraction of the full-resolution distance: at most 2");
  o.replanPeriod = readPositive(config, "replan_period", o.replanPeriod);
  o.transitSpeed = readPositive(config, "transit_speed", o.transitSpeed);
  o.explorerCapacity = readPositive(config, "explorer_capacity", o.explorerCapacity);
  o.delivery.period = readPositive(config, "deliver_period", o.delivery.period);
  return o;
}

CoinspectStrategy::CoinspectStrategy(const agent::StrategyContext& context,
                                     const CoinspectOptions& options)
    : options_(options),
      unit_(context),
      contact_(options.delivery),
      relay_(RelayOptions{}, fleetNames(context.fleet)),
      tour_(kReached, kAttemptsPerPatch) {}

CoinspectStrategy::~CoinspectStrategy() = default;

void CoinspectStrategy::initialise(const agent::AgentView& view) {
  initialised_ = true;
  const double groundZ = view.odometry.position.z() - 0.1;
  runtime::RobotMapOptions mapOptions;
  mapOptions.mapResolution = 1.0;        // key frames only: ~2 ms each at 1 m (doc/mapping.md)
  mapOptions.keyFramesFromView = false;  // they come through the relay
  map_ = std::make_unique<runtime::RobotMap>(mapOptions, *view.boxes, groundZ);

  runtime::FlightOptions flightOptions;
  flightOptions.radius = unit_.radius;
  flightOptions.limits.speed = options_.transitSpeed;
  flightOptions.takeoffHeight = 6.0;
  flight_ = std::make_unique<runtime::Flight>(flightOptions, fleetNames(unit_.fleet), unit_.self);

  // The same partition in every robot: UAVs in fleet order, explorers with less capacity.
  std::vector<double> capacities;
  for (size_t i = 0; i < unit_.fleet.size(); ++i) {
    if (unit_.fleet[i].role == agent::Role::GroundStation) continue;
    if (i == unit_.self) region_ = static_cast<uint32_t>(capacities.size());
    capacities.push_back(unit_.fleet[i].role == agent::Role::Explorer ? options_.explorerCapacity
                                                                      : 1.0);
  }
  work_ = sampleBoxFaces(*view.boxes, kFaceSpacing, groundZ, 1.0);
  workRegion_ = partitionWork(work_, capacities);
  task_ = unit_.role == agent::Role::Explorer && options_.exploreTime > 0.0 ? Task::Explore
                                                                            : Task::Inspect;
  if (task_ == Task::Explore) flight_->follow(explorationRoute(view), options_.transitSpeed);
}

// Orbits around each box at the standoff, so the LiDAR sees faces that look into the gaps
// between structures (an orbit around all boxes at once never does): the boxes, sorted along x,
// are dealt to the explorers in contiguous runs (explorer k of n takes the k-th run); a box gets
// the layers of explorationLayers; the boxes are flown nearest first.
std::vector<Vec3> CoinspectStrategy::explorationRoute(const agent::AgentView& view) const {
  size_t explorers = 0, rank = 0;
  for (size_t i = 0; i < unit_.fleet.size(); ++i)
    if (unit_.fleet[i].role == agent::Role::Explorer) {
      if (i == unit_.self) rank = explorers;
      ++explorers;
    }
  std::vector<agent::BoxView> boxes = *view.boxes;
  std::stable_sort(boxes.begin(), boxes.end(),
                   [](const auto& a, const auto& b) { return a.center.x() < b.center.x(); });
  const size_t n = boxes.size(), share = std::max<size_t>(1, explorers);
  std::vector<agent::BoxView> mine(boxes.begin() + static_cast<long>(rank * n / share),
                                   boxes.begin() + static_cast<long>((rank + 1) * n / share));
  const double lowest = view.odometry.position.z() + 3.0;
  std::vector<Vec3> route;
  Vec3 from = view.odometry.position;
  while (!mine.empty()) {
    const auto nearest =
        std::min_element(mine.begin(), mine.end(), [&](const auto& a, const auto& b) {
          return runtime::distanceToBox(a, from) < runtime::distanceToBox(b, from);
        });
    const auto layers = explorationLayers(*nearest, boxes, lowest, kRoofHeight);
    for (const double z : layers) {
      auto orbit = runtime::standoffOrbit(*nearest, z, options_.exploreStandoff, 6.0, from);
      orbit.push_back(orbit.front());
      route.insert(route.end(), orbit.begin(), orbit.end());
      from = route.back();
    }
    mine.erase(nearest);
  }
  return route;
}

void CoinspectStrategy::planInspection(const agent::AgentView& view) {
  lastPlan_ = view.missionTime;
  const auto& grid = map_->grid();
  const auto grouped =
      planning::groupSurface(map_->surfaceNearBoxes(*view.boxes, kSurfaceNearBox), kPatchSize);
  std::vector<uint32_t> owners;
  for (const auto& patch : grouped) {
    auto owner = owner_.find(patch.key);
    if (owner == owner_.end()) {
      size_t best = 0;
      double bestDistance = std::numeric_limits<double>::infinity();
      for (size_t w = 0; w < work_.size(); ++w) {
        const double d = (work_[w].position - patch.centre).squaredNorm();
        if (d < bestDistance) bestDistance = d, best = w;
      }
      owner = owner_.emplace(patch.key, work_.empty() ? 0u : workRegion_[best]).first;
    }
    owners.push_back(owner->second);
  }
  const Vec3 here = view.odometry.position;
  const auto patches = choosePatches(
      grouped, owners, region_,
      [&](uint64_t key) { return inspected_.count(key) != 0 || progress_.done(key); }, here,
      kPatchesPerPlan);

  tour_.stops().clear();
  planning::CoverageOptions coverage;
  const double fullResolution = planning::fullResolutionDistance(unit_.optics);
  coverage.distance = options_.viewDistance * fullResolution;
  coverage.maxDistance = std::max(1.1, options_.viewDistance + 0.2) * fullResolution;
  coverage.clearance = flight_->requiredClearance(grid);
  coverage.groundZ = map_->region().min.z();
  // Photographers map from explorers' key frames only: much of the space in front of a mapped
  // wall stays unknown, and requiring it free left more patches without a viewpoint than were
  // viewed (CARIC MBS, 5 seeds: median 1181.51 -> 1231.19 when unknown space does not hide
  // patches).
  coverage.unknownHides = false;
  // Patches without any safe viewpoint (under overhangs, in unmapped gaps) would stay the nearest
  // open ones and fill every plan: on MBS a photographer hovered for 240 s with 418 open patches
  // in its region and no viewpoint for the 120 nearest. They fail like unreached stops.
  std::vector<uint32_t> uncoverable;
  const auto views = planning::coverPatches(patches, grid, coverage, &uncoverable);
  std::vector<uint64_t> uncovered;
  for (const uint32_t j : uncoverable)
    uncovered.push_back(patches[j].key);
  for (const uint64_t key : tour_.fail(uncovered))
    inspected_.insert(key);
  if (views.empty()) return;

  // The nearest views first (by straight distance), ordered by an open tour from here.
  std::vector<size_t> chosen(views.size());
  for (size_t i = 0; i < views.size(); ++i)
    chosen[i] = i;
  std::stable_sort(chosen.begin(), chosen.end(), [&](size_t a, size_t b) {
    return (views[a].camera - here).squaredNorm() < (views[b].camera - here).squaredNorm();
  });
  if (chosen.size() > kStopsPerPlan) chosen.resize(kStopsPerPlan);
  std::vector<Eigen::Vector3d> points = {here};
  for (const size_t i : chosen)
    points.push_back(views[i].camera);
  const auto tour =
      planning::solveTsp(planning::euclideanCostMatrix(points), {planning::TourKind::Open, 0, -1});
  std::vector<Vec3> route;
  for (size_t k = 1; k < tour.order.size(); ++k) {
    const auto& v = views[chosen[tour.order[k] - 1]];
    runtime::PatchStop stop;
    stop.target = v.target;
    stop.yaw = runtime::headingTowards(v.camera, v.target, view.odometry.yaw);
    stop.body = v.camera - Eigen::AngleAxisd(stop.yaw, Vec3::UnitZ()) * unit_.camera.positionInBody;
    for (const uint32_t j : v.covered)
      stop.patches.push_back(patches[j].key);
    route.push_back(stop.body);
    tour_.stops().push_back(std::move(stop));
  }
  const double speed =
      planning::inspectionSpeed(unit_.optics, coverage.distance, options_.transitSpeed);
  flight_->follow(route, speed);
}

agent::AgentCommand CoinspectStrategy::decide(const agent::AgentView& view) {
  if (!view.alive || !view.boxes) return {};
  auto messages = relay_.exchange(view);
  if (auto report = progress_.exchange(view)) messages.push_back(std::move(*report));
  if (unit_.role ==
      agent::Role::GroundStation) {  // a relay only: it sees every robot that delivers
    relay_.takeNew(std::numeric_limits<size_t>::max());  // it keeps no map
    agent::AgentCommand out;
    out.messages = std::move(messages);
    return out;
  }
  if (!initialised_) initialise(view);
  for (const auto& frame : relay_.takeNew(kFramesPerDecision))
    map_->insertFrame(frame);
  map_->update(view);
  map_->refresh(view.time);
  contact_.observe(view);
  const Vec3 here = view.odometry.position;

  if (task_ != Task::Deliver && contact_.shouldDeliver(view)) {
    resume_ = task_;
    task_ = Task::Deliver;
    flight_->goTo(*contact_.nearestContactPoint(here), options_.transitSpeed);
  } else if (task_ == Task::Deliver && contact_.inContact()) {
    // Near the end, stay in sight of the station: the last captures are merged while here.
    if (view.timeLeft > options_.delivery.endMargin + 10.0) {
      task_ = resume_;
      lastPlan_ = kNever;
      if (task_ == Task::Explore) flight_->follow(explorationRoute(view), options_.transitSpeed);
    } else {
      flight_->hover();
    }
  }
  if (task_ == Task::Explore && !flight_->takingOff() &&
      (flight_->done() || flight_->failed() || view.missionTime > options_.exploreTime)) {
    task_ = Task::Inspect;
    lastPlan_ = kNever;
  }
  if (task_ == Task::Inspect && !flight_->takingOff()) {
    for (const auto& stop : tour_.takeReached(here))
      for (const uint64_t key : stop.patches) {
        inspected_.insert(key);
        progress_.markViewed(key);
      }
    if ((flight_->done() || flight_->failed()) && !tour_.stops().empty()) {
      // The flight ended short of these stops: their patches get another chance in a later plan.
      for (const uint64_t key : tour_.abandon(runtime::patchKeys))
        inspected_.insert(key);
      flight_->hover();
    }
    const bool stale = view.missionTime - lastPlan_ >= options_.replanPeriod;
    const bool idle =
        (tour_.stops().empty() || flight_->done()) && view.missionTime - lastPlan_ >= 2.0;
    if (stale || idle) planInspection(view);
    if (tour_.stops().empty() && flight_->done()) {
      // Nothing mapped to inspect yet: wait by the own region, where key frames may arrive.
      double best = std::numeric_limits<double>::infinity();
      Vec3 staging = here;
      for (size_t w = 0; w < work_.size(); ++w) {
        if (workRegion_[w] != region_) continue;
        const Vec3 candidate = work_[w].position + options_.exploreStandoff * work_[w].normal;
        const double d = (candidate - here).norm();
        if (d < best) best = d, staging = candidate;
      }
      if (best > 2.0) flight_->goTo(staging, options_.transitSpeed);
    }
  }
  auto out = command(view, flight_->step(view, *map_));
  out.messages = std::move(messages);
  return out;
}

agent::AgentCommand CoinspectStrategy::command(const agent::AgentView& view,
                                               agent::AgentSetpoint setpoint) {
  agent::AgentCommand out;
  const auto& odometry = view.odometry;
  // Look at the next viewpoint's patch when inspecting, else at the nearest box.
  Vec3 target;
  if (task_ == Task::Inspect && !tour_.stops().empty()) {
    target = tour_.stops().front().target;
  } else {
    double best = std::numeric_limits<double>::infinity();
    target = odometry.position + Vec3(std::cos(odometry.yaw), std::sin(odometry.yaw), 0.0);
    for (const auto& box : *view.boxes) {
      const Vec3 p = runtime::closestPointOnBox(box, odometry.position);
      const double d = (p - odometry.position).norm();
      if (d < best) best = d, target = p;
    }
  }
  setpoint.yaw = runtime::headingTowards(odometry.position, target, odometry.yaw);
  const Vec3 cameraPosition = odometry.position + Eigen::AngleAxisd(odometry.yaw, Vec3::UnitZ()) *
                                                      unit_.camera.positionInBody;
  const auto aim = planning::aimGimbal(cameraPosition, odometry.yaw, target);
  out.gimbal = agent::GimbalCommand::angles(
      std::clamp(aim.pitch, -view.gimbal.pitchMax, view.gimbal.pitchMax),
      std::clamp(aim.yaw, -view.gimbal.yawMax, view.gimbal.yawMax));
  out.setpoint = setpoint;
  return out;
}

void registerCoinspect(agent::StrategyRegistry& registry) {
  registry.registerStrategy("coinspect", [](const agent::StrategyContext& context) {
    return std::make_unique<CoinspectStrategy>(context, CoinspectOptions::read(context.config));
  });
}

}  // namespace coinspect::strategies::coinspect_strategy
