// slei3d: what the three roles share (map, flight, the plan and its flooding, messages).
#include "coinspect/strategies/slei/slei3d_strategy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "coinspect/core/error.h"
#include "coinspect/strategies/runtime/box_geometry.h"
#include "coinspect/strategies/runtime/camera_aim.h"
#include "coinspect/strategies/runtime/option_reader.h"

namespace coinspect::strategies::slei {

namespace {

constexpr double kFloodPeriod = 1.0;   // s between broadcasts of the plan
constexpr double kFloodUntil = 120.0;  // s: by then every robot holds the plan
constexpr size_t kFramesPerDecision = 8;
constexpr double kRelayCircle = 3.0;  // m from caric-team's relay where its inspectors wait
// m beyond the flight's hold distance between two inspectors' wait points (2.5 m apart, a
// waiting inspector held the next one 3 m off its point for a whole slei-a run, where its
// explorer, looking for it at its point, missed it at every hand-out)
constexpr double kWaitSpacing = 1.0;
constexpr double kReferenceDetectRange = 5.0;  // m, the detector the explorer's model assumes

}  // namespace

Slei3dStrategy::Slei3dStrategy(const agent::StrategyContext& context, const SleiOptions& options)
    : options_(options), unit_(context), seed_(context.seed) {
  for (const auto& member : unit_.fleet)
    names_.push_back(member.name);
}

Slei3dStrategy::~Slei3dStrategy() = default;

void Slei3dStrategy::initialise(const agent::AgentView& view) {
  initialised_ = true;
  groundZ_ = view.odometry.position.z() - 0.1;  // every unit starts 0.1 m above the ground
  boxes_ = *view.boxes;
  if (options_.unknownWorkspace && !boxes_.empty()) {
    // Only the area's bounds are known: one slab per explorer of the whole fleet (every robot
    // computes the same ones; the stations share them out like boxes). No box: no area.
    const auto explorers = static_cast<size_t>(
        std::count_if(unit_.fleet.begin(), unit_.fleet.end(),
                      [](const agent::FleetMember& m) { return m.role == agent::Role::Explorer; }));
    boxes_ = splitWorkspace(workspaceBox(*view.boxes), explorers);
  }
  // priority_first off: urgent areas are dealt like the others.
  if (!options_.priorityFirst)
    for (auto& box : boxes_)
      box.highPriority = false;
  boxTaken_.assign(boxes_.size(), 0);
  sceneBoxes_ = boxes_.size();
  // Frames travel between robots (meetings are short, so a reply carries many).
  coinspect_strategy::RelayOptions relay;
  relay.digestPeriod = 1.0;
  relay.framesPerReply = 200;
  relay_ = std::make_unique<coinspect_strategy::KeyFrameRelay>(relay, names_);
  if (unit_.role == agent::Role::GroundStation) {
    // The ground it drives on; it learns walls from the key frames it carries.
    drive_ = std::make_unique<planning::GroundDrive>(stationGroundGrid(
        boxes_, view.odometry.position.head<2>(), unit_.radius, !options_.unknownWorkspace));
    return;
  }
  runtime::RobotMapOptions mapOptions;
  // A finer grid than the CARIC strategies': the scenes are small, and the clearance a path
  // needs (radius + margin + a cell's diagonal) sets how low a UAV can fly, while the detector
  // must look at features down to the ground from within 5 m and 30 deg of elevation.
  mapOptions.mapResolution = options_.gridResolution;
  mapOptions.gridResolution = options_.gridResolution;
  mapOptions.keyFramesFromView = false;  // through the relay
  mapOptions.include = {view.odometry.position};
  if (unit_.role == agent::Role::Explorer) {
    mapOptions.ownSweepEvery = 2;
    // Its own detector (heterogeneous explorers): the model and the sweep distance were tuned
    // for the reference's 5 m and scale with the range.
    const double range = unit_.fleet[unit_.self].detectRange;
    const double scale = range > 0.0 ? range / kReferenceDetectRange : 1.0;
    detector_.range *= scale;
    sweepDistance_ = options_.sweepDistance * scale;
  }
  mapOptions.boxMargin = options_.unknownBoxMargin;
  // Teammates seen from beyond the 5 m link are not filtered from scans: without this they
  // stayed in the maps as obstacles (one closed the way in front of slei-b's building).
  mapOptions.raysClearAwayFromBoxes = true;
  map_ = std::make_unique<runtime::RobotMap>(mapOptions, boxes_, groundZ_);
  runtime::FlightOptions flight;
  flight.radius = unit_.radius;
  flight.safetyMargin = options_.safetyMargin;
  flight.limits.speed = options_.speed;
  flight.takeoffHeight = options_.exploreHeight;
  flight.maxExpansions = 150000;  // a 0.5 m grid has 8 times the cells of 1 m
  flight_ = std::make_unique<runtime::Flight>(flight, names_, unit_.self);
  flight_->openTakeoffColumn(*map_, view.odometry.position, view.time);
}

const Subgroup* Slei3dStrategy::subgroupOf(uint32_t unit) const {
  if (!plan_) return nullptr;
  for (const auto& s : plan_->subgroups) {
    if (s.explorer == unit) return &s;
    if (std::find(s.inspectors.begin(), s.inspectors.end(), unit) != s.inspectors.end()) return &s;
  }
  return nullptr;
}

Vec3 Slei3dStrategy::firstWaitPoint(const Subgroup& subgroup, size_t k) const {
  if (options_.variant == SleiVariant::Team) {
    // caric-team: every inspector waits around the relay (the first meeting place of every
    // subgroup), in link with the station, on a circle in the order of the fleet.
    size_t index = 0, count = 0;
    for (const auto& s : plan_->subgroups) {
      if (s.station != subgroup.station) continue;  // another station's relay
      for (const uint32_t unit : s.inspectors) {
        if (unit == subgroup.inspectors[k]) index = count;
        ++count;
      }
    }
    const Vec3& relay = subgroup.firstMeeting.place;
    const double hold = runtime::FlightOptions{}.separation;
    return relayWaitPoint(Vec3(relay.x(), relay.y(), groundZ_ + options_.meetHeight), index, count,
                          kRelayCircle, hold, hold + kWaitSpacing);
  }
  return waitPointNear(subgroup.box, subgroup.firstMeeting.place, k);
}

Vec3 Slei3dStrategy::waitPointNear(int32_t box, const Vec3& from, size_t k) const {
  const auto index = static_cast<size_t>(box);
  // The unknown workspace: a part's corner may stand inside a structure; `from`, where the
  // station met the explorer, is open ground.
  const Vec3 corner = options_.unknownWorkspace
                          ? from
                          : boxCorner(boxes_, index, options_.plan.cornerOffset, 0.0, from);
  return waitPointOffCorner(boxes_, index, corner, k,
                            runtime::FlightOptions{}.separation + kWaitSpacing,
                            groundZ_ + options_.waitHeight);
}

void Slei3dStrategy::readPlan(const agent::AgentView& view) {
  // A station makes its own part (decideStation); a UAV merges the parts of every station it
  // hears of, each subgroup once, and floods each part on.
  if (unit_.role == agent::Role::GroundStation) return;
  for (const auto& message : view.messages) {
    if (message.topic != kPlanTopic) continue;
    if (std::find(planBytes_.begin(), planBytes_.end(), message.bytes) != planBytes_.end())
      continue;
    const auto part = decodePlan(message.bytes);
    if (!part) continue;
    if (!plan_) plan_ = FleetPlan{};
    bool fresh = false;
    for (const auto& s : part->subgroups)
      if (!subgroupOf(s.explorer)) {
        plan_->subgroups.push_back(s);
        fresh = true;
      }
    if (fresh) planBytes_.push_back(message.bytes);
  }
}

void Slei3dStrategy::floodPlan(const agent::AgentView& view, agent::AgentCommand& command) {
  if (planBytes_.empty() || view.time > kFloodUntil || view.time - lastFlood_ < kFloodPeriod)
    return;
  if (view.neighbours.empty()) return;
  lastFlood_ = view.time;
  for (const auto& part : planBytes_)
    command.messages.push_back({"", kPlanTopic, part});
}

bool Slei3dStrategy::neighbour(const agent::AgentView& view, uint32_t unit) const {
  return std::any_of(view.neighbours.begin(), view.neighbours.end(),
                     [&](const agent::NeighbourInfo& n) { return n.name == names_[unit]; });
}

void Slei3dStrategy::send(agent::AgentCommand& command, uint32_t to, const char* topic,
                          std::vector<uint8_t> bytes) const {
  command.messages.push_back({names_[to], topic, std::move(bytes)});
}

double Slei3dStrategy::boxExploredFraction(int32_t box) const {
  if (box < 0 || !map_) return 0.0;
  const auto bounds = runtime::boxBounds(boxes_[static_cast<size_t>(box)]);
  const double step = map_->options().mapResolution;
  size_t known = 0, total = 0;
  for (double x = bounds.min.x() + step / 2; x < bounds.max.x(); x += step)
    for (double y = bounds.min.y() + step / 2; y < bounds.max.y(); y += step)
      for (double z = std::max(bounds.min.z(), groundZ_) + step / 2; z < bounds.max.z();
           z += step) {
        ++total;
        if (map_->map().state(Vec3(x, y, z)) != mapping::CellState::Unknown) ++known;
      }
  return total ? static_cast<double>(known) / static_cast<double>(total) : 1.0;
}

void Slei3dStrategy::learnGround(const agent::KeyFrame& frame) {
  if (staticStation()) return;  // it never drives
  // A station that learns a wall plans its way again.
  drive_->learn([&](planning::GroundGrid& ground) {
    return blockGroundObstacles(ground, frame.points, groundZ_, unit_.radius + kGroundClearance);
  });
}

agent::AgentCommand Slei3dStrategy::fly(const agent::AgentView& view, std::optional<Vec3> aim) {
  agent::AgentCommand command;
  command.setpoint = flight_->step(view, *map_);
  const Vec3 here = view.odometry.position;
  if (aim && !flight_->takingOff()) {
    command.setpoint->yaw = runtime::headingTowards(here, *aim, view.odometry.yaw);
    command.gimbal = runtime::aimCamera(view.odometry, unit_.camera, view.gimbal, *aim);
  } else {
    command.gimbal = agent::GimbalCommand::angles(0.0, 0.0);
  }
  return command;
}

agent::AgentCommand Slei3dStrategy::decide(const agent::AgentView& view) {
  if (!view.alive || !view.boxes) return {};
  if (!initialised_) initialise(view);
  auto relayed = relay_->exchange(view);
  if (map_) {
    for (const auto& frame : relay_->takeNew(kFramesPerDecision))
      map_->insertFrame(frame);
    map_->update(view);
    map_->refresh(view.time);
  } else {
    // The station keeps no map, only its ground.
    for (const auto& frame : relay_->takeNew(std::numeric_limits<size_t>::max()))
      learnGround(*frame);
  }
  readPlan(view);
  agent::AgentCommand command;
  if (unit_.role != agent::Role::GroundStation && !subgroupOf(static_cast<uint32_t>(unit_.self))) {
    command.activity = agent::Activity::Waiting;  // no plan yet (or no part in it): on the ground
  } else {
    switch (unit_.role) {
      case agent::Role::GroundStation:
        command = decideStation(view);
        break;
      case agent::Role::Explorer:
        command = decideExplorer(view);
        break;
      case agent::Role::Photographer:
        command = decideInspector(view);
        break;
    }
  }
  floodPlan(view, command);
  for (auto& message : relayed)
    command.messages.push_back(std::move(message));
  return command;
}

namespace {

SleiOptions readOptions(const Config& config, SleiVariant variant) {
  const auto number = [&](const char* key, double fallback, double low, double high) {
    return runtime::readNumber(config, "slei3d", key, fallback, low, high);
  };
  SleiOptions o;
  o.variant = variant;
  o.speed = number("speed", o.speed, 0.1, 20.0);
  o.exploreHeight = number("explore_height", o.exploreHeight, 1.0, 100.0);
  o.meetHeight = number("meet_height", o.meetHeight, 1.0, 100.0);
  o.waitHeight = number("wait_height", o.waitHeight, 1.0, 100.0);
  o.gridResolution = number("grid_resolution", o.gridResolution, 0.2, 2.0);
  o.safetyMargin = number("safety_margin", o.safetyMargin, 0.0, 10.0);
  o.sweepDistance = number("sweep_distance", o.sweepDistance, 1.0, 100.0);
  o.handoutPeriod = number("handout_period", o.handoutPeriod, 0.1, 600.0);
  o.meetingGrace = number("meeting_grace", o.meetingGrace, 0.0, 600.0);
  o.inspectPatience = number("inspect_patience", o.inspectPatience, 0.0, 600.0);
  o.maxMeetingLead = number("max_meeting_lead", o.maxMeetingLead, 50.0, 3600.0);
  o.fixInterval = number("fix_interval", o.fixInterval, 10.0, 3600.0);
  o.teamInterval = number("team_interval", o.teamInterval, 10.0, 3600.0);
  o.plan.evenSplit = config.getBool("slei3d", "even_split", o.plan.evenSplit);
  o.reserveNextBox = config.getBool("slei3d", "reserve_next_box", o.reserveNextBox);
  o.feasibleMeetings = config.getBool("slei3d", "feasible_meetings", o.feasibleMeetings);
  // explore-then-inspect hands out only once no box is left for an explorer: one that waited
  // for a share of another's box never got to hand out (slei-c scene seed 2, 3000 s: two
  // explorers waited for shares from 752 and 787 s to the end, a third from 1798 s, while the
  // fourth still explored; nothing was handed out).
  o.shareWork = config.getBool("slei3d", "share_work", variant != SleiVariant::ExploreFirst);
  o.splitLastBox = config.getBool("slei3d", "split_last_box", o.splitLastBox);
  o.frontierChunk = number("frontier_chunk", o.frontierChunk, 0.0, 100.0);
  if (o.frontierChunk > 0.0 && o.frontierChunk < 1.0)
    throw InputError(config.source(), "[slei3d] frontier_chunk",
                     std::to_string(o.frontierChunk) + " is neither 0 (off) nor at least 1 m");
  o.roofPass = config.getBool("slei3d", "roof_pass", o.roofPass);
  o.obliqueViews = config.getBool("slei3d", "oblique_views", o.obliqueViews);
  o.presumeDone = config.getBool("slei3d", "presume_done", o.presumeDone);
  o.approachPartner = config.getBool("slei3d", "approach_partner", o.approachPartner);
  o.handoutAtBoxEnd = config.getBool("slei3d", "handout_at_box_end", o.handoutAtBoxEnd);
  o.sweepThrough = config.getBool("slei3d", "sweep_through", o.sweepThrough);
  o.lastBoxHold = number("last_box_hold", o.lastBoxHold, 0.0, 3600.0);
  o.fetchDetour = number("fetch_detour", o.fetchDetour, 0.0, 600.0);
  o.priorityFirst = config.getBool("slei3d", "priority_first", o.priorityFirst);
  o.deadlineBound = config.getBool("slei3d", "deadline_bound", o.deadlineBound);
  o.searchDepth =
      static_cast<size_t>(runtime::readInteger(config, "slei3d", "search_depth", 0, 0, 6));
  const std::string workspace = config.getString("slei3d", "workspace", "boxes");
  if (workspace != "boxes" && workspace != "unknown")
    throw InputError(config.source(), "[slei3d] workspace",
                     "expected boxes or unknown, got '" + workspace + "'");
  o.unknownWorkspace = workspace == "unknown";
  o.leafEdge = number("leaf_edge", o.leafEdge, 1.0, 1000.0);
  o.unknownBoxMargin = number("unknown_box_margin", o.unknownBoxMargin, 0.0, 10.0);
  o.plan.stationSpeed = number("station_speed", o.plan.stationSpeed, 0.1, 20.0);
  return o;
}

}  // namespace

void registerSlei3d(agent::StrategyRegistry& registry) {
  const std::pair<const char*, SleiVariant> variants[] = {
      {"slei3d", SleiVariant::Slei3d},
      {"slei-pre", SleiVariant::Pre},
      {"slei-fix", SleiVariant::Fix},
      {"caric-team", SleiVariant::Team},
      {"explore-then-inspect", SleiVariant::ExploreFirst}};
  for (const auto& [name, variant] : variants)
    registry.registerStrategy(name, [variant = variant](const agent::StrategyContext& context) {
      return std::make_unique<Slei3dStrategy>(context, readOptions(context.config, variant));
    });
}

}  // namespace coinspect::strategies::slei
