// Construction of a mission and its loop (doc/architecture.md, "The tick").
#include "coinspect/sim/mission.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "coinspect/core/error.h"
#include "coinspect/core/random.h"
#include "coinspect/sensing/lidar_model.h"
#include "coinspect/vehicle/airframe.h"
#include "mission_impl.h"

namespace coinspect::sim {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

long long ticksFor(double period, double step) {
  return std::max(1LL, std::llround(period / step));
}

agent::Role toAgentRole(world::UnitRole role) {
  switch (role) {
    case world::UnitRole::GroundStation:
      return agent::Role::GroundStation;
    case world::UnitRole::Explorer:
      return agent::Role::Explorer;
    case world::UnitRole::Photographer:
      return agent::Role::Photographer;
  }
  return agent::Role::Photographer;
}

agent::CameraInfo toCameraInfo(const world::CameraSpec& camera) {
  agent::CameraInfo out;
  out.horizontalFov = camera.horizontalFov;
  out.verticalFov = camera.verticalFov;
  out.positionInBody = camera.positionInBody;
  out.exposureTime = camera.exposureTime;
  out.triggerInterval = camera.triggerInterval;
  out.focalLength = camera.focalLength;
  out.pixelSize = camera.pixelSize;
  out.desiredMmPerPixel = camera.desiredMmPerPixel;
  return out;
}

template <class Map>
const typename Map::mapped_type& lookup(const Map& map, const std::string& name,
                                        const std::string& source, const std::string& key) {
  const auto found = map.find(name);
  if (found == map.end()) {
    std::string known;
    for (const auto& entry : map)
      known += (known.empty() ? "" : ", ") + entry.first;
    throw InputError(source, key, "unknown model '" + name + "' (known: " + known + ")");
  }
  return found->second;
}

}  // namespace

Mission::Impl::Impl(world::Scenario scenarioIn, MissionConfig configIn, const Config& ini,
                    const agent::StrategyRegistry& registry)
    : config(std::move(configIn)), scenario(std::move(scenarioIn)) {
  step = config.physicsStep;
  budget = config.budget.value_or(scenario.missionBudget);
  controlPeriod = ticksFor(vehicle::kControlPeriod, step);
  gimbalPeriod = ticksFor(1.0 / sensing::Gimbal::kUpdateRate, step);
  monitorPeriod = ticksFor(0.01, step);
  topologyPeriod = sensing::tallyMergeTicks(step);
  caster = std::make_unique<world::RayCaster>(scenario.meshes, scenario.groundZ);
  linkModel =
      comms::makeLinkModel(config.links, config.linkRange, config.source + ": [mission] links");
  const auto urgent = priorityBoxFlags(config.features.priorityBoxes, scenario, config.source);
  for (size_t b = 0; b < scenario.boxes.size(); ++b) {
    const auto& box = scenario.boxes[b];
    boxes.push_back({box.center, box.size, box.rotation, urgent[b] != 0});
  }

  // A feature mission's data reaches a station only from explorers (detections) and inspectors
  // (results): without a station or an explorer nothing could ever be collected. Generated
  // fleets are checked when given ([mission] fleet); a scenario file's fleet is checked here.
  const auto countOf = [&](world::UnitRole role) {
    return std::count_if(scenario.fleet.begin(), scenario.fleet.end(),
                         [role](const world::UnitSpec& s) { return s.role == role; });
  };
  if (config.objective == Objective::Features &&
      (countOf(world::UnitRole::GroundStation) == 0 || countOf(world::UnitRole::Explorer) == 0))
    throw InputError(
        config.source, "[mission] objective",
        "a feature mission needs at least one ground station and one explorer; "
        "the fleet of scenario '" +
            scenario.name + "' has " + std::to_string(countOf(world::UnitRole::GroundStation)) +
            " stations and " + std::to_string(countOf(world::UnitRole::Explorer)) + " explorers");

  // Explorers' detector ranges, known to the fleet (0 when features are not the objective).
  const auto detectRanges =
      config.objective == Objective::Features
          ? explorerDetectRanges(config.features.explorerRanges, config.features.sensor.range,
                                 scenario, config.source)
          : std::vector<double>(scenario.fleet.size(), 0.0);
  const auto airframes = vehicle::loadAirframes(config.airframes);
  const auto& explorerFrame =
      lookup(airframes, config.explorerAirframe, config.source, "[mission] explorer_airframe");
  const auto& photographerFrame = lookup(airframes, config.photographerAirframe, config.source,
                                         "[mission] photographer_airframe");
  std::map<std::string, sensing::LidarSpec> lidars;
  if (config.explorerLidar != "none") lidars = sensing::loadLidarModels(config.lidars);

  // Batteries: explorers only (they are the units that meet the stations in SLEI3D), charged
  // by a station: a fleet without one could never charge.
  const auto batteryOf = [&](const world::UnitSpec& spec) {
    agent::BatterySpec battery;
    if (!config.energy || spec.role != world::UnitRole::Explorer) return battery;
    battery.capacity = config.energy->capacity;
    battery.chargeTime = config.energy->chargeTime;
    battery.chargeRange = config.energy->chargeRange;
    return battery;
  };
  if (config.energy && countOf(world::UnitRole::GroundStation) == 0)
    throw InputError(
        config.source, "[energy]",
        "the fleet has no ground station to charge at (scenario '" + scenario.name + "')");

  const size_t pointCount = scenario.interestPoints.size();
  const Rng seeds(config.seed);
  units.resize(scenario.fleet.size());
  for (size_t i = 0; i < units.size(); ++i) {
    auto& unit = units[i];
    unit.spec = &scenario.fleet[i];
    unit.role = toAgentRole(unit.spec->role);
    unit.log = sensing::ScoreLog(pointCount);
    unit.lastPosition = unit.spec->startPosition;
    if (unit.role == agent::Role::GroundStation) {
      stations.push_back(i);
      unit.ground = std::make_unique<vehicle::GroundVehicle>(unit.spec->startPosition,
                                                             unit.spec->startYaw, config.gcsSpeed);
    } else {
      const auto& frame = unit.role == agent::Role::Explorer ? explorerFrame : photographerFrame;
      unit.collisionRadius = frame.collisionRadius;
      unit.vehicle = std::make_unique<vehicle::Multirotor>(frame, unit.spec->startPosition,
                                                           unit.spec->startYaw, scenario.groundZ);
      unit.gimbal = std::make_unique<sensing::Gimbal>(unit.spec->camera);
      if (unit.role == agent::Role::Explorer && config.explorerLidar != "none") {
        const auto& spec =
            lookup(lidars, config.explorerLidar, config.source, "[mission] explorer_lidar");
        unit.lidar =
            std::make_unique<ExplorerLidar>(spec, seeds.fork(2000 + i).next(), unit.spec->name);
        unit.lidarPeriod = ticksFor(1.0 / unit.lidar->rate(), step);
      }
      unit.capturePeriod = ticksFor(
          sensing::capturePeriod(unit.spec->camera.triggerInterval, step, config.scoring), step);
      unit.nextCapture = unit.capturePeriod;
      unit.battery = batteryOf(*unit.spec);
      if (unit.battery.limited()) unit.energy = unit.lowestEnergy = config.energy->startLevel;
    }
    // Ground stations get a strategy too: it drives a mobile one (gcs_speed > 0).
    agent::StrategyContext context{
        ini, config.strategy, unit.spec->name, unit.role, i, seeds.fork(1000 + i).next(), {}, {},
        0.0};
    for (size_t j = 0; j < scenario.fleet.size(); ++j)
      context.fleet.push_back({scenario.fleet[j].name, toAgentRole(scenario.fleet[j].role),
                               detectRanges[j], batteryOf(scenario.fleet[j])});
    context.camera = toCameraInfo(unit.spec->camera);
    context.collisionRadius = unit.collisionRadius;
    unit.strategy = registry.create(config.strategy, context);
    const double rate = unit.strategy->decisionRate();
    if (!(rate > 0.0) || !std::isfinite(rate))
      throw InputError(config.source, "[strategy] name", "strategy gives a non-positive rate");
    unit.decisionPeriod = ticksFor(1.0 / rate, step);
  }
  // Faults and blackouts name units: check them now.
  for (const auto& fault : config.faults)
    faultUnits.push_back(unitIndexOf(fault.unit, "[fault] unit"));
  for (const auto& blackout : config.blackouts) {
    std::vector<size_t> indices;
    for (const auto& name : blackout.units)
      indices.push_back(unitIndexOf(name, "[blackout] units"));
    blackoutUnits.push_back(indices);
  }
  faultsApplied.assign(config.faults.size(), 0);
  blackoutActive.assign(config.blackouts.size(), 0);

  scorer =
      std::make_unique<sensing::InspectionScorer>(scenario.interestPoints, *caster, config.scoring);
  tally = sensing::GroundStationTally(pointCount, config.scoring);
  links = comms::LinkMatrix(units.size());
  network = std::make_unique<comms::Network>(units.size());
  exchange = std::make_unique<comms::KeyFrameExchange>(units.size());
  if (config.objective == Objective::Features) {
    featurePeriod = ticksFor(0.1, step);
    std::vector<std::string> names;
    std::vector<agent::Role> roles;
    for (const auto& unit : units) {
      names.push_back(unit.spec->name);
      roles.push_back(unit.role);
    }
    features = std::make_unique<FeatureTracker>(
        config.features, scenario.interestPoints,
        highPriorityFeatures(urgent, scenario, config.source), std::move(names), std::move(roles),
        detectRanges,
        [this](const std::string& kind, const std::string& unit, const std::string& detail) {
          event(kind, unit, detail);
        });
  }
}

size_t Mission::Impl::unitIndexOf(const std::string& name, const std::string& where) const {
  for (size_t i = 0; i < units.size(); ++i)
    if (units[i].spec->name == name) return i;
  throw InputError(config.source, where, "no unit named '" + name + "' in the fleet");
}

void Mission::Impl::event(const std::string& kind, const std::string& unit,
                          const std::string& detail) {
  events.push_back({now(), kind, unit, detail});
  if (recorder) recorder->event(events.back());
}

void Mission::Impl::kill(size_t i, const std::string& cause) {
  auto& unit = units[i];
  if (!unit.alive()) return;
  if (unit.vehicle) {
    unit.vehicle->kill();
    updateFallFloor(unit);
  } else {
    unit.stationAlive = false;
    unit.ground->setTarget(unit.ground->state().position);  // a dead station stops where it is
  }
  unit.deathCause = cause;
  if (features) features->unitDied(i, now());
  event("death", unit.spec->name, cause);
}

// The vehicle only knows a flat ground at scenario.groundZ, so a dead UAV above a roof or beside
// a wall would fall through the mesh. Its floor is the first surface straight below it; it is
// looked for again at every monitor tick because the UAV drifts sideways while it falls (off a
// roof's edge, say). Between two looks the vehicle lands exactly on the floor it was given.
void Mission::Impl::updateFallFloor(UnitRuntime& unit) {
  auto& uav = *unit.vehicle;
  if (uav.alive() || !uav.airborne()) return;
  const world::Vec3& p = uav.state().position;
  double floor = scenario.groundZ;
  if (const auto hit = caster->closestHit(p, -world::Vec3::UnitZ()))
    floor = std::max(floor, p.z() - hit->distance);
  uav.setGroundZ(floor);
}

std::vector<bool> Mission::Impl::aliveFlags() const {
  std::vector<bool> alive(units.size());
  for (size_t i = 0; i < units.size(); ++i)
    alive[i] = units[i].alive();
  return alive;
}

void Mission::Impl::syncVehicles() {
  const double t = now();
  const double dt = t - syncedTo;
  if (dt <= 0.0) return;
  const auto stageStart = Clock::now();
  for (auto& unit : units) {
    const bool wasAlive = unit.alive();
    if (unit.vehicle)
      unit.vehicle->advance(dt);
    else
      advanceStation(unit, dt);
    const auto& p = unit.state().position;
    if (wasAlive) unit.distanceFlown += (p - unit.lastPosition).norm();
    unit.lastPosition = p;
  }
  syncedTo = t;
  stages.physics += secondsSince(stageStart);
}

// A ground station drives straight and cannot pass through structures: a move whose segment
// crosses a mesh surface (walls, not the ground) leaves it where it was, at rest.
void Mission::Impl::advanceStation(UnitRuntime& unit, double dt) {
  const world::Vec3 before = unit.ground->state().position;
  unit.ground->advance(dt);
  const world::Vec3& after = unit.ground->state().position;
  if (after != before && !caster->segmentClear(before, after, 0.0)) unit.ground->stopAt(before);
}

void Mission::Impl::applyFaultsAndBlackouts() {
  const double t = now();
  for (size_t f = 0; f < config.faults.size(); ++f) {
    if (faultsApplied[f] || config.faults[f].at > t) continue;
    faultsApplied[f] = 1;
    event("fault", config.faults[f].unit, "unit fails");
    kill(faultUnits[f], "fault injected at " + std::to_string(config.faults[f].at) + " s");
  }
  for (size_t b = 0; b < config.blackouts.size(); ++b) {
    const auto& blackout = config.blackouts[b];
    const bool active = t >= blackout.from && t < blackout.to;
    if (active == static_cast<bool>(blackoutActive[b])) continue;
    blackoutActive[b] = active;
    const std::string scope = blackout.units.empty() ? "all links" : "links of listed units";
    event(active ? "blackout-start" : "blackout-end", "", scope);
  }
}

void Mission::Impl::monitor() {
  const auto stageStart = Clock::now();
  for (auto& unit : units)
    if (unit.vehicle) updateFallFloor(unit);
  // Collisions with surfaces (the ground is not one), then between UAVs.
  for (size_t i = 0; i < units.size(); ++i) {
    auto& unit = units[i];
    if (!unit.vehicle || !unit.vehicle->alive() || !unit.vehicle->airborne()) continue;
    // Mesh surfaces at ground level are ground (CARIC meshes have floor plates): close to the
    // ground a UAV is checked as if it were its collision radius (+ 5 cm) above it, which still
    // catches walls beside it.
    world::Vec3 p = unit.vehicle->state().position;
    p.z() = std::max(p.z(), scenario.groundZ + unit.collisionRadius + 0.05);
    const double distance = caster->distanceToSurface(p, unit.collisionRadius);
    if (distance < unit.collisionRadius) {
      event("collision", unit.spec->name, "surface");
      ++collisionDeaths;
      kill(i, "collision with a surface");
    }
  }
  for (size_t i = 0; i < units.size(); ++i) {
    for (size_t j = i + 1; j < units.size(); ++j) {
      auto& a = units[i];
      auto& b = units[j];
      if (!a.vehicle || !b.vehicle || !a.vehicle->alive() || !b.vehicle->alive()) continue;
      if (!a.vehicle->airborne() && !b.vehicle->airborne()) continue;
      const double gap = (a.vehicle->state().position - b.vehicle->state().position).norm();
      if (gap >= a.collisionRadius + b.collisionRadius) continue;
      event("collision", a.spec->name, b.spec->name);
      event("collision", b.spec->name, a.spec->name);
      collisionDeaths += 2;
      kill(i, "collision with " + b.spec->name);
      kill(j, "collision with " + a.spec->name);
    }
  }
  // The mission clock: any UAV above start_height and faster than start_speed.
  if (!started) {
    for (const auto& unit : units) {
      if (!unit.vehicle) continue;
      const auto& state = unit.vehicle->state();
      if (state.position.z() - scenario.groundZ > config.startHeight &&
          state.velocity.norm() > config.startSpeed) {
        started = true;
        startTime = now();
        event("mission-start", unit.spec->name, "take-off");
        if (features) features->start(startTime);  // after the start: its activity events
        break;
      }
    }
  }
  if (started && config.energy) updateEnergy(static_cast<double>(monitorPeriod) * step);
  stages.collisions += secondsSince(stageStart);
}

void Mission::Impl::updateTopology() {
  const auto stageStart = Clock::now();
  std::vector<comms::LinkEndpoint> endpoints(units.size());
  // In caric mode a crashed UAV's antennas still reach the ground station (the reference merges
  // its log); messages still need both ends alive (the network checks).
  const bool deadStillLinked = sensing::capturesWhenCrashed(config.scoring);
  for (size_t i = 0; i < units.size(); ++i) {
    const auto& unit = units[i];
    endpoints[i].position = unit.lastPosition;
    endpoints[i].antennaOffset = unit.spec->antennaOffset;
    endpoints[i].alive = unit.alive() || (unit.vehicle && deadStillLinked);
  }
  linkModel->update(*caster, endpoints, links);
  for (size_t b = 0; b < config.blackouts.size(); ++b) {
    if (!blackoutActive[b]) continue;
    if (blackoutUnits[b].empty()) {
      links.clear();
      continue;
    }
    for (const size_t u : blackoutUnits[b])
      for (size_t j = 0; j < units.size(); ++j)
        if (j != u) links.setLinked(static_cast<uint32_t>(u), static_cast<uint32_t>(j), false);
  }
  const auto alive = aliveFlags();
  network->setTopology(links, alive, now());
  if (features && features->exchange(now(), links, alive)) allCollected = true;
  // A UAV's captures count once some live station hears it (several stations pool what they
  // hear, as the features' collection does).
  size_t improved = 0;
  for (size_t i = 0; i < units.size(); ++i) {
    if (!units[i].vehicle) continue;
    const bool heard = std::any_of(stations.begin(), stations.end(), [&](size_t g) {
      return units[g].alive() && links.linked(static_cast<uint32_t>(g), static_cast<uint32_t>(i));
    });
    if (heard) improved += tally.merge(units[i].log, units[i].alive());
  }
  if (recorder) recorder->topology(now(), links, tally, improved > 0);
  stages.topology += secondsSince(stageStart);
}

void Mission::Impl::sweepLidars() {
  std::vector<size_t> sweeping;
  for (size_t i = 0; i < units.size(); ++i)
    if (units[i].lidar && units[i].alive() && tick % units[i].lidarPeriod == 0)
      sweeping.push_back(i);
  if (sweeping.empty()) return;
  const auto stageStart = Clock::now();
  // Each sweep reads the shared world and writes only its own unit's LiDAR (its own noise), so
  // the sweeps may run at once; what they publish is then handled in fleet order.
  std::vector<std::shared_ptr<const agent::KeyFrame>> keyFrames(sweeping.size());
  const auto sweep = [&](size_t k) {
    const size_t i = sweeping[k];
    auto& unit = units[i];
    std::vector<sensing::SphereOccluder> spheres;
    for (size_t j = 0; j < units.size(); ++j)
      if (j != i && units[j].vehicle)
        spheres.push_back({units[j].vehicle->state().position, units[j].collisionRadius});
    keyFrames[k] =
        unit.lidar->sweep(*caster, now(), unit.vehicle->state(), spheres, unit.lidarView);
  };
  if (workers && sweeping.size() > 1)
    workers->run(sweeping.size(), sweep);
  else
    for (size_t k = 0; k < sweeping.size(); ++k)
      sweep(k);
  for (size_t k = 0; k < sweeping.size(); ++k) {
    const size_t i = sweeping[k];
    auto& unit = units[i];
    const auto& keyFrame = keyFrames[k];
    if (recorder) recorder->lidar(unit.spec->name, unit.lidar->lastScan(), keyFrame != nullptr);
    if (keyFrame) {
      COINSPECT_ASSERT(keyFrame->id == unit.keyFrames.size());
      unit.keyFrames.push_back(keyFrame);
      unit.pendingOwnKeyFrames.push_back(keyFrame);
      exchange->publish(static_cast<uint32_t>(i), keyFrame->id, links, aliveFlags(), now());
      ++keyFrameCount;
    }
  }
  stages.lidar += secondsSince(stageStart);
}

void Mission::Impl::capture(size_t i) {
  auto& unit = units[i];
  if (!unit.alive() && !sensing::capturesWhenCrashed(config.scoring)) return;
  const auto stageStart = Clock::now();
  const auto& state = unit.vehicle->state();
  sensing::CaptureState capture;
  capture.position = state.position;
  capture.yaw = state.yaw;
  capture.pitch = state.pitch;
  capture.roll = state.roll;
  capture.linearVelocity = state.velocity;
  capture.angularVelocity = state.angularVelocity;
  unit.gimbal->applyTo(capture);
  occluders.spheres.clear();
  for (size_t j = 0; j < units.size(); ++j)
    if (j != i && units[j].vehicle)
      occluders.spheres.push_back({units[j].vehicle->state().position, units[j].collisionRadius});
  scorer->score(unit.spec->camera, capture, occluders, scores);
  if (recorder)
    recorder->capture(unit.spec->name, now(), unit.spec->camera, capture, occluders.spheres,
                      scores);
  agent::CaptureReport report;
  report.time = now();
  for (const auto& s : scores)
    report.pointsCounted += s.counted ? 1 : 0;
  report.pointsImproved = unit.log.record(scores);
  if (report.pointsImproved > 0) {
    const double total = unit.log.totalScore();
    report.scoreGained = total - unit.ownScore;
    unit.ownScore = total;
  }
  ++unit.captures;
  unit.pendingCaptures.push_back(report);
  if (features && unit.alive()) features->capture(i, now(), scores);
  stages.scoring += secondsSince(stageStart);
}

void Mission::Impl::hashStates() {
  const auto mix = [this](double value) { digest = core::fnv1a(&value, sizeof value, digest); };
  for (const auto& unit : units) {
    const auto& s = unit.state();
    for (int k = 0; k < 3; ++k) {
      mix(s.position[k]);
      mix(s.velocity[k]);
      mix(s.angularVelocity[k]);
    }
    mix(s.yaw);
    mix(s.pitch);
    mix(s.roll);
    if (!unit.gimbal) continue;
    mix(unit.gimbal->pitch());
    mix(unit.gimbal->yaw());
  }
}

// Realtime mode, at controller ticks: sleeps until the wall clock has caught up with simulated
// time (scaled by the factor) since the first step. Behind, it does not sleep: the run goes as
// fast as it can and the summary's real-time factor shows what was achieved.
void Mission::Impl::paceToWallClock() {
  const auto wallNow = Clock::now();
  if (!paceWallStart) {
    paceWallStart = wallNow;
    paceSimStart = now();
    return;
  }
  const double due = (now() - paceSimStart) / config.realtimeFactor;
  const double ahead = due - std::chrono::duration<double>(wallNow - *paceWallStart).count();
  if (ahead <= 0.0) return;
  std::this_thread::sleep_for(std::chrono::duration<double>(ahead));
  stages.pacing += secondsSince(wallNow);
}

bool Mission::Impl::stepOnce() {
  if (ended) return false;
  const auto stageStart = Clock::now();
  if (config.runMode == RunMode::Realtime && tick % controlPeriod == 0) paceToWallClock();
  const bool monitorTick = tick % monitorPeriod == 0;
  const bool topologyTick = tick % topologyPeriod == 0;
  bool needState = monitorTick || topologyTick || tick % controlPeriod == 0 || commandDue() ||
                   (features && tick % featurePeriod == 0);
  if (recorder) needState = needState || recorder->groundTruthDue(tick);
  for (const auto& unit : units) {
    needState = needState || tick % unit.decisionPeriod == 0;
    if (unit.vehicle)
      needState =
          needState || tick >= unit.nextCapture || (unit.lidar && tick % unit.lidarPeriod == 0);
  }

  applyFaultsAndBlackouts();
  if (needState) syncVehicles();
  if (recorder && recorder->groundTruthDue(tick)) recorder->groundTruth(now(), units);
  if (tick % controlPeriod == 0) {
    hashStates();
    if (controlTickObserver) controlTickObserver();
  }
  if (monitorTick) monitor();
  if (topologyTick) updateTopology();
  sweepLidars();
  if (features && tick % featurePeriod == 0)
    for (size_t i = 0; i < units.size(); ++i)
      if (units[i].role == agent::Role::Explorer && units[i].alive())
        features->detect(i, now(), units[i].state(), *caster);
  for (size_t i = 0; i < units.size(); ++i) {
    auto& unit = units[i];
    if (!unit.vehicle || tick < unit.nextCapture) continue;
    unit.nextCapture += unit.capturePeriod;
    capture(i);
  }
  if (tick % gimbalPeriod == 0)
    for (auto& unit : units)
      if (unit.gimbal) unit.gimbal->update(now());
  if (recorder && tick % gimbalPeriod == 0) recorder->gimbals(now(), units);
  for (size_t i = 0; i < units.size(); ++i)
    applyDueCommands(i);  // latency mode: earlier decisions whose compute time has passed
  decideAll();
  if (recorder) recorder->flushMessages(now());  // what the decisions sent, one record

  // The end: the budget on the mission clock is used up (motors stop), or nobody took off.
  const double t = now();
  if (allCollected && config.features.endWhenCollected) {
    ended = true;
    event("mission-end", "", "all features collected");
  } else if (started && t - startTime >= budget - 1e-9) {
    ended = true;
    event("mission-end", "", "budget used");
  } else if (!started && t >= config.startTimeout) {
    ended = true;
    event("no-takeoff", "", "no UAV took off within start_timeout");
  }
  endRecordingTick();
  ++tick;
  wallTime += secondsSince(stageStart);
  return !ended;
}

// ---------------------------------------------------------------------------------------------

Mission::Mission(const Config& ini, const agent::StrategyRegistry& registry,
                 std::optional<uint64_t> seedOverride) {
  auto config = MissionConfig::read(ini, seedOverride);
  auto scenario = loadMissionScenario(config);
  world::validateScenario(scenario, config.scenario);
  impl_ = std::make_unique<Impl>(std::move(scenario), std::move(config), ini, registry);
}

Mission::Mission(world::Scenario scenario, const Config& ini,
                 const agent::StrategyRegistry& registry, std::optional<uint64_t> seedOverride) {
  auto config = MissionConfig::read(ini, seedOverride);
  impl_ = std::make_unique<Impl>(std::move(scenario), std::move(config), ini, registry);
}

Mission::~Mission() = default;

void Mission::run() {
  while (impl_->stepOnce()) {
  }
}

bool Mission::step() {
  return impl_->stepOnce();
}

void Mission::runUntil(double time) {
  while (impl_->now() < time - 1e-12 && impl_->stepOnce()) {
  }
}

bool Mission::finished() const {
  return impl_->ended;
}
double Mission::time() const {
  return impl_->now();
}
const world::Scenario& Mission::scenario() const {
  return impl_->scenario;
}
const MissionConfig& Mission::config() const {
  return impl_->config;
}
const std::vector<MissionEvent>& Mission::events() const {
  return impl_->events;
}
uint64_t Mission::stateDigest() const {
  return impl_->digest;
}

size_t Mission::unitIndex(const std::string& name) const {
  return impl_->unitIndexOf(name, "unit");
}

vehicle::VehicleState Mission::unitState(size_t unit) const {
  return impl_->units.at(unit).state();
}

bool Mission::unitAlive(size_t unit) const {
  return impl_->units.at(unit).alive();
}

double Mission::unitOwnScore(size_t unit) const {
  return impl_->units.at(unit).ownScore;
}

const std::vector<float>& Mission::gcsValues() const {
  return impl_->tally.values();
}

void Mission::setThreads(size_t threads) {
  COINSPECT_ASSERT(impl_->tick == 0);
  const size_t resolved = core::WorkerPool::resolve(threads);
  impl_->workers = resolved > 1 ? std::make_unique<core::WorkerPool>(resolved) : nullptr;
}

size_t Mission::threads() const {
  return impl_->workers ? impl_->workers->threads() : 1;
}

void Mission::setControlTickObserver(ControlTickObserver observer) {
  if (!observer) {
    impl_->controlTickObserver = nullptr;
    return;
  }
  impl_->controlTickObserver = [this, observer = std::move(observer)] { observer(*this); };
}

double Mission::gcsScore() const {
  return impl_->tally.totalScore();
}

}  // namespace coinspect::sim
