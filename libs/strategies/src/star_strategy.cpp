#include "coinspect/strategies/star/star_strategy.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/planning/coverage.h"
#include "coinspect/planning/viewpoint.h"
#include "coinspect/strategies/runtime/box_geometry.h"
#include "coinspect/strategies/runtime/camera_aim.h"

namespace coinspect::strategies::star {

namespace {

constexpr double kNever = -1e300;
constexpr double kTakeoffHeight = 3.0;   // m climbed vertically first
constexpr double kPatchSize = 2.0;       // m, surface patches the coverage plans over
constexpr double kSurfaceNearBox = 1.0;  // m: mapped surface farther from every box is not a target
constexpr double kReached = 1.2;         // m from a stop's body position that counts as there
constexpr size_t kStopsPerPlan = 8;      // viewpoints flown per inspection plan
constexpr int kAttemptsPerPatch = 2;     // plans that may pick a patch before it is given up
constexpr size_t kSearchBudget = 50000;  // cells a flight's path search may expand
constexpr size_t kPatchesPerPlan = 400;  // nearest open patches an inspection plan covers
constexpr size_t kClustersPerPlan = 25;  // nearest clusters (frontier or viewpoint) a plan orders
constexpr double kExploreStandoff = 8.0;    // m from a face: where to go while nothing is mapped
constexpr double kHomeReserve = 20.0;       // s added to the estimated way home
constexpr double kNeighbourKeepOut = 8.0;   // m: goals this close to another UAV are left to it
constexpr double kUnreachableRadius = 3.0;  // m around a given-up goal that is skipped

double nearestBoxDistance(const std::vector<agent::BoxView>& boxes, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& box : boxes)
    best = std::min(best, runtime::distanceToBox(box, p));
  return best;
}

// True when a UAV in sight is within `radius` of `p`: a goal there is (about to be) someone
// else's, and two units converging on one point rely on deconfliction alone.
bool nearNeighbour(const agent::AgentView& view, const Vec3& p, double radius) {
  return std::any_of(view.neighbours.begin(), view.neighbours.end(), [&](const auto& n) {
    return n.role != agent::Role::GroundStation && (n.odometry.position - p).norm() < radius;
  });
}

}  // namespace

StarStrategy::StarStrategy(const agent::StrategyContext& context, const StarOptions& options)
    : options_(options), unit_(context), tour_(kReached, kAttemptsPerPatch) {}

StarStrategy::~StarStrategy() = default;

void StarStrategy::initialise(const agent::AgentView& view) {
  initialised_ = true;
  groundZ_ = view.odometry.position.z() - 0.1;  // UAVs spawn 0.1 m above the ground (CARIC)
  home_ = view.odometry.position + Vec3(0, 0, kTakeoffHeight);
  runtime::RobotMapOptions mapOptions;
  mapOptions.mapResolution = 1.0;  // key frames at ~2 ms each, frontiers in ~15 ms (mapping.md)
  mapOptions.regionMargin = 12.0;
  // Explorers map with every second own sweep as well: their frontiers and their own flight
  // need fresher data than the key frames (about one per 2 s) bring.
  if (unit_.role == agent::Role::Explorer) mapOptions.ownSweepEvery = 2;
  map_ = std::make_unique<runtime::RobotMap>(mapOptions, *view.boxes, groundZ_);

  runtime::FlightOptions flight;
  flight.radius = unit_.radius;
  flight.limits.speed = options_.maxSpeed;
  flight.takeoffHeight = kTakeoffHeight;
  // A smaller search budget than the runtime's: the Flight pays the full budget again for each
  // unreachable first stop of a route, which made single decisions take seconds on MBS.
  flight.maxExpansions = kSearchBudget;
  std::vector<std::string> names;
  for (const auto& member : unit_.fleet)
    names.push_back(member.name);
  flight_ = std::make_unique<runtime::Flight>(flight, names, unit_.self);
  flight_->openTakeoffColumn(*map_, view.odometry.position, view.time);

  // Units of the same role share the surface in fleet order: every unit computes the same split.
  size_t count = 0;
  for (size_t i = 0; i < unit_.fleet.size(); ++i) {
    if (unit_.fleet[i].role != unit_.role) continue;
    if (i == unit_.self) part_ = static_cast<uint32_t>(count);
    ++count;
  }
  split_ = std::make_unique<SurfaceSplit>(*view.boxes, groundZ_, std::max<size_t>(1, count));
  task_ = unit_.role == agent::Role::Explorer ? Task::Explore : Task::Inspect;
}

void StarStrategy::receive(const agent::AgentView& view) {
  for (const auto& message : view.messages) {
    if (message.topic != kInspectedTopic) continue;
    std::vector<uint64_t> keys;
    if (!decodeKeys(message.bytes, &keys)) continue;
    for (const uint64_t key : keys)
      if (inspected_.insert(key).second) inspectedChanged_ = true;
  }
}

bool StarStrategy::planExploration(const agent::AgentView& view, bool periodic) {
  lastPlan_ = view.missionTime;
  const auto& boxes = *view.boxes;
  const auto& grid = map_->grid();
  const auto bounds = runtime::missionRegion(boxes, options_.frontierMargin, groundZ_);
  const Vec3 here = view.odometry.position;
  struct Candidate {
    const mapping::FrontierCluster* cluster;
    double distance;
  };
  const auto clusters = map_->map().frontierClusters(bounds.min, bounds.max, 3);
  std::vector<Candidate> mine, others;
  for (const auto& cluster : clusters) {
    if (cluster.centroid.z() < groundZ_ + 1.5) continue;
    if (nearestBoxDistance(boxes, cluster.centroid) > options_.frontierMargin) continue;
    const bool given_up = givenUp(cluster.centroid);
    if (given_up || nearNeighbour(view, cluster.centroid, kNeighbourKeepOut)) continue;
    const Candidate candidate{&cluster, (cluster.centroid - here).norm()};
    (split_->ownerOf(cluster.centroid) == part_ ? mine : others).push_back(candidate);
  }
  // A periodic plan keeps the current goal while its frontier is still there: a new goal costs
  // a path search, and FUEL's tours mostly keep their first viewpoint anyway.
  if (periodic && exploreAim_) {
    const auto alive = [&](const Candidate& c) {
      return (c.cluster->centroid - *exploreAim_).norm() < kUnreachableRadius;
    };
    if (std::any_of(mine.begin(), mine.end(), alive) ||
        std::any_of(others.begin(), others.end(), alive))
      return true;
  }
  // The own share first; the others' once it is done (they may be busy or far).
  auto& pool = mine.empty() ? others : mine;
  std::stable_sort(pool.begin(), pool.end(),
                   [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  if (pool.size() > kClustersPerPlan) pool.resize(kClustersPerPlan);

  RingOptions ring;
  ring.clearance = flight_->requiredClearance(grid);
  ring.minZ = groundZ_ + 2.0;
  std::vector<Pose> poses;
  std::vector<Vec3> aims;
  for (const auto& candidate : pool)
    if (const auto viewpoint = bestRingViewpoint(*candidate.cluster, grid, ring);
        viewpoint && !nearNeighbour(view, viewpoint->pose.position, kNeighbourKeepOut)) {
      poses.push_back(viewpoint->pose);
      aims.push_back(candidate.cluster->centroid);
    }
  if (poses.empty()) {
    // Nothing to see near the mapped boxes (yet): fly to the nearest point off the own share of
    // the surface that is still unknown, where LiDAR will find structure.
    std::optional<Vec3> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (uint32_t part = 0; part < split_->parts(); ++part) {
      auto p = split_->standoffPoint(part, here, kExploreStandoff);
      // Not below the flying floor, and not where the flight gave up already (an explorer
      // asked for a point 1.2 m under the ground for the whole of one MBS run).
      if (p) p->z() = std::max(p->z(), ring.minZ);
      if (!p || map_->map().state(*p) != mapping::CellState::Unknown || givenUp(*p)) continue;
      const double d = (*p - here).norm() + (part == part_ ? 0.0 : 1000.0);
      if (d < bestDistance) bestDistance = d, best = p;
    }
    if (!best) return false;
    exploreGoal_ = *best;
    exploreAim_.reset();
    flight_->goTo(*best, options_.maxSpeed);
    return true;
  }
  const auto order = atspOrder(Pose{here, view.odometry.yaw}, poses, options_.yawWeight);
  exploreGoal_ = poses[order.front()].position;
  exploreAim_ = aims[order.front()];
  flight_->goTo(*exploreGoal_, options_.maxSpeed);
  return true;
}

bool StarStrategy::givenUp(const Vec3& goal) const {
  return std::any_of(unreachable_.begin(), unreachable_.end(),
                     [&](const Vec3& p) { return (p - goal).norm() < kUnreachableRadius; });
}

void StarStrategy::explore(const agent::AgentView& view) {
  if (flight_->failed() && exploreGoal_) {
    unreachable_.push_back(exploreAim_ ? *exploreAim_ : *exploreGoal_);
    exploreGoal_.reset();
    flight_->hover();
  }
  const double sincePlan = view.missionTime - lastPlan_;
  const bool due = flight_->done() ? sincePlan >= 1.0 : sincePlan >= options_.replanPeriod;
  if (!due) return;
  if (planExploration(view, !flight_->done())) return;
  // No frontier left near the boxes: the map is complete enough.
  exploreGoal_.reset();
  exploreAim_.reset();
  if (options_.explorersInspect) {
    task_ = Task::Inspect;
    lastPlan_ = kNever;
  } else {
    task_ = Task::Home;
    flight_->goTo(home_, options_.maxSpeed);
  }
}

void StarStrategy::planInspection(const agent::AgentView& view) {
  lastPlan_ = view.missionTime;
  const auto& grid = map_->grid();
  const auto surface = map_->surfaceNearBoxes(*view.boxes, kSurfaceNearBox);
  const auto open = dropInspected(planning::groupSurface(surface, kPatchSize), inspected_);
  // Photographers take their own share; once it is done (or not mapped yet) they help with the
  // rest. Explorers that finished mapping only help.
  std::vector<planning::InspectionPatch> patches;
  if (unit_.role == agent::Role::Photographer)
    for (const auto& patch : open) {
      auto owner = owner_.find(patch.key);
      if (owner == owner_.end())
        owner = owner_.emplace(patch.key, split_->ownerOf(patch.centre)).first;
      if (owner->second == part_) patches.push_back(patch);
    }
  if (patches.empty()) patches = open;
  // The nearest patches only: the set cover costs about patches x neighbours, and a plan flies
  // a few viewpoints anyway.
  const Vec3 here = view.odometry.position;
  if (patches.size() > kPatchesPerPlan) {
    std::stable_sort(patches.begin(), patches.end(),
                     [&](const planning::InspectionPatch& a, const planning::InspectionPatch& b) {
                       return (a.centre - here).squaredNorm() < (b.centre - here).squaredNorm();
                     });
    patches.resize(kPatchesPerPlan);
  }

  tour_.stops().clear();
  planning::CoverageOptions coverage;
  const double fullResolution = planning::fullResolutionDistance(unit_.optics);
  coverage.distance = options_.viewDistance * fullResolution;
  coverage.maxDistance = 1.1 * fullResolution;
  coverage.clearance = flight_->requiredClearance(grid);
  coverage.groundZ = groundZ_;
  auto views = planning::coverPatches(patches, grid, coverage);
  views.erase(std::remove_if(views.begin(), views.end(),
                             [&](const planning::CoverageView& v) {
                               return nearNeighbour(view, v.camera, kNeighbourKeepOut / 2.0);
                             }),
              views.end());
  if (views.empty()) return;

  std::vector<Vec3> cameras;
  for (const auto& v : views)
    cameras.push_back(v.camera);
  auto clusters = clusterViews(cameras, options_.clusterRadius, &grid);
  std::vector<Pose> poses;
  for (const auto& cluster : clusters) {
    Vec3 camera = Vec3::Zero(), target = Vec3::Zero();
    for (const size_t i : cluster) {
      camera += views[i].camera;
      target += views[i].target;
    }
    camera /= static_cast<double>(cluster.size());
    target /= static_cast<double>(cluster.size());
    poses.push_back(Pose{camera, runtime::headingTowards(camera, target, 0.0)});
  }
  // The tour only needs to be good near the robot (a plan flies a few stops): the nearest
  // clusters keep the ATSP small.
  if (clusters.size() > kClustersPerPlan) {
    std::vector<size_t> nearest(clusters.size());
    for (size_t c = 0; c < nearest.size(); ++c)
      nearest[c] = c;
    std::stable_sort(nearest.begin(), nearest.end(), [&](size_t a, size_t b) {
      return (poses[a].position - here).squaredNorm() < (poses[b].position - here).squaredNorm();
    });
    nearest.resize(kClustersPerPlan);
    std::vector<std::vector<size_t>> keptClusters;
    std::vector<Pose> keptPoses;
    for (const size_t c : nearest) {
      keptClusters.push_back(clusters[c]);
      keptPoses.push_back(poses[c]);
    }
    clusters = std::move(keptClusters);
    poses = std::move(keptPoses);
  }
  const auto order = atspOrder(Pose{here, view.odometry.yaw}, poses, options_.yawWeight);

  // Clusters in tour order; inside one, nearest viewpoint next, until the plan is full.
  std::vector<Vec3> route;
  Vec3 at = here;
  for (const size_t c : order) {
    std::vector<size_t> left = clusters[c];
    while (!left.empty() && tour_.stops().size() < kStopsPerPlan) {
      size_t pick = 0;
      for (size_t k = 1; k < left.size(); ++k)
        if ((views[left[k]].camera - at).norm() < (views[left[pick]].camera - at).norm()) pick = k;
      const auto& v = views[left[pick]];
      left.erase(left.begin() + static_cast<long>(pick));
      runtime::PatchStop stop;
      stop.target = v.target;
      const double yaw = runtime::headingTowards(v.camera, v.target, view.odometry.yaw);
      stop.body = v.camera - Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * unit_.camera.positionInBody;
      for (const uint32_t j : v.covered)
        stop.patches.push_back(patches[j].key);
      route.push_back(stop.body);
      at = v.camera;
      tour_.stops().push_back(std::move(stop));
    }
    if (tour_.stops().size() >= kStopsPerPlan) break;
  }
  const double speed =
      planning::inspectionSpeed(unit_.optics, coverage.distance, options_.maxSpeed);
  flight_->follow(route, speed);
}

void StarStrategy::inspect(const agent::AgentView& view) {
  const Vec3 here = view.odometry.position;
  for (const auto& stop : tour_.takeReached(here))
    for (const uint64_t key : stop.patches)
      if (inspected_.insert(key).second) inspectedChanged_ = true;
  if ((flight_->done() || flight_->failed()) && !tour_.stops().empty()) {
    // The flight ended short of these stops: their patches get another chance in a later plan.
    for (const uint64_t key : tour_.abandon(runtime::patchKeys))
      inspected_.insert(key);
    flight_->hover();
  }
  const double sincePlan = view.missionTime - lastPlan_;
  // Receding horizon: plan again when the plan is flown, and every `replan_period` s (received
  // keys and newly mapped surface change the plan meanwhile; on MBS this scored 754 against 622
  // for planning again only when at most two stops were left).
  const bool idle = (tour_.stops().empty() || flight_->done()) && sincePlan >= 2.0;
  if (idle || sincePlan >= options_.replanPeriod) planInspection(view);
  if (tour_.stops().empty() && flight_->done()) {
    // Nothing mapped to inspect yet: wait off the own share, where key frames may arrive.
    const double standoff = planning::fullResolutionDistance(unit_.optics) + 3.0;
    const auto staging = split_->standoffPoint(part_, here, standoff);
    if (staging && (*staging - here).norm() > 2.0) flight_->goTo(*staging, options_.maxSpeed);
  }
}

Vec3 StarStrategy::aimTarget(const agent::AgentView& view) const {
  const auto& odometry = view.odometry;
  if (task_ == Task::Inspect && !tour_.stops().empty()) return tour_.stops().front().target;
  if (task_ == Task::Explore && exploreAim_) return *exploreAim_;
  double best = std::numeric_limits<double>::infinity();
  Vec3 target = odometry.position + Vec3(std::cos(odometry.yaw), std::sin(odometry.yaw), 0.0);
  for (const auto& box : *view.boxes) {
    const Vec3 p = runtime::closestPointOnBox(box, odometry.position);
    const double d = (p - odometry.position).norm();
    if (d < best) best = d, target = p;
  }
  return target;
}

agent::AgentCommand StarStrategy::decide(const agent::AgentView& view) {
  agent::AgentCommand out;
  if (unit_.role == agent::Role::GroundStation || !view.alive || !view.boxes) return out;
  if (!initialised_) initialise(view);
  map_->update(view);
  map_->refresh(view.time);
  receive(view);
  const Vec3 here = view.odometry.position;

  if (options_.returnHome && task_ != Task::Home && view.started) {
    const double reserve = (here - home_).norm() / options_.maxSpeed * 1.5 + kHomeReserve;
    if (view.timeLeft < reserve) {
      task_ = Task::Home;
      tour_.stops().clear();
      flight_->goTo(home_, options_.maxSpeed);
    }
  }
  if (!flight_->takingOff()) {
    if (task_ == Task::Explore) explore(view);
    if (task_ == Task::Inspect) inspect(view);
  }
  out.setpoint = flight_->step(view, *map_);
  const Vec3 target = aimTarget(view);
  if (!flight_->takingOff())
    out.setpoint->yaw = runtime::headingTowards(here, target, view.odometry.yaw);
  out.gimbal = runtime::aimCamera(view.odometry, unit_.camera, view.gimbal, target);

  // Share what is covered with whoever is in sight (all of it: a receiver may have missed
  // earlier broadcasts, and it relays the keys further).
  if (!view.neighbours.empty() && !inspected_.empty() &&
      view.time - lastBroadcast_ >= options_.broadcastPeriod &&
      (inspectedChanged_ || view.time - lastBroadcast_ >= 5.0 * options_.broadcastPeriod)) {
    lastBroadcast_ = view.time;
    inspectedChanged_ = false;
    agent::OutgoingMessage message;
    message.topic = kInspectedTopic;
    message.bytes = encodeKeys(std::vector<uint64_t>(inspected_.begin(), inspected_.end()));
    out.messages.push_back(std::move(message));
  }
  return out;
}

void registerStar(agent::StrategyRegistry& registry) {
  registry.registerStrategy("star", [](const agent::StrategyContext& context) {
    return std::make_unique<StarStrategy>(context, StarOptions::read(context.config));
  });
}

}  // namespace coinspect::strategies::star
