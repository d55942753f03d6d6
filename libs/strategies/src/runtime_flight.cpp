#include "coinspect/strategies/runtime/flight.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::strategies::runtime {

namespace {

constexpr double kNever = -std::numeric_limits<double>::infinity();
// m^3: free space at the full clearance smaller than this around a unit is a pocket it is
// trapped in (a 5 m alley's centre line, a few cells wide).
constexpr double kPocketVolume = 100.0;
// s a unit must have been trapped before it flies out at its own sphere's clearance: a pocket
// often opens again as the map fills in (then the unit goes on at the full clearance), and
// flying closer to surfaces is for a unit that is stuck.
constexpr double kTrappedPatience = 10.0;
// m/s: a neighbour slower than this stays where it is (it waits or holds).
constexpr double kStill = 0.3;

}  // namespace

Flight::Flight(const FlightOptions& options, std::vector<std::string> fleet, size_t self)
    : options_(options), fleet_(std::move(fleet)), self_(self) {}

double Flight::requiredClearance(const mapping::VoxelGrid& grid) const {
  // A path point may lie anywhere in its cell and the surface anywhere in the blocking cell:
  // each end loses up to half a cell diagonal against the centre-to-centre distance field.
  return options_.radius + options_.safetyMargin + grid.resolution() * std::sqrt(3.0);
}

void Flight::openTakeoffColumn(RobotMap& map, const Vec3& start, double time) const {
  const double clearance = requiredClearance(map.grid());
  map.openColumn(start, options_.takeoffHeight + clearance, clearance);
  map.refresh(time, true);
}

planning::PathSearchOptions Flight::searchOptions(const mapping::VoxelGrid& grid) const {
  planning::PathSearchOptions out;
  out.clearance = requiredClearance(grid);
  out.unknown = options_.unknown;
  out.snapRadius = options_.snapRadius;
  // Prefer the middle of free space a little: paths keep away from surfaces when they can.
  out.softClearance = out.clearance + 2.0;
  out.softWeight = 0.5;
  // Weighted Theta*: paths at most 1.5x the least cost, found in ~1 ms instead of up to
  // hundreds (doc/benchmarks.md, "Path search"); a bounded search keeps a decision short when
  // the goal is walled off.
  out.heuristicWeight = 1.5;
  out.maxExpansions = 60000;
  // plan() needs a failed search's status and expansions only: a goal in a pocket of its own
  // is then proved unreachable by a small flood, not by spending the whole budget.
  out.partialPath = false;
  return out;
}

planning::PathSearchOptions Flight::ownSphereOptions(const mapping::VoxelGrid& grid) const {
  auto out = searchOptions(grid);
  out.clearance = options_.radius + 0.5 * grid.resolution() * std::sqrt(3.0);
  return out;
}

bool Flight::trapped(const planning::PathResult& result, const mapping::VoxelGrid& grid) const {
  if (result.status == planning::PathStatus::StartBlocked) return true;
  // NoPath after a small flood: the unit's own free space at the full clearance is a pocket
  // (from open space the search floods far more before giving up, or runs out of budget).
  const double cell = std::pow(grid.resolution(), 3);
  return result.status == planning::PathStatus::NoPath &&
         static_cast<double>(result.expansions) * cell < kPocketVolume;
}

size_t Flight::priorityOf(const std::string& name) const {
  const auto it = std::find(fleet_.begin(), fleet_.end(), name);
  return static_cast<size_t>(it - fleet_.begin());  // unknown names rank last
}

void Flight::goTo(const Vec3& goal, double speed) {
  if (route_.size() == 1 && (route_.front() - goal).norm() < 0.3 && speed == speed_ &&
      phase_ != Phase::Idle)
    return;
  // Reached and still holding there: planning again would fly a path from the goal to itself
  // (or fail to: a point is no path) at every decision of a caller that keeps asking.
  if (phase_ == Phase::Idle && reachedGoal_ && (*reachedGoal_ - goal).norm() < 0.3) return;
  follow({goal}, speed);
}

void Flight::follow(const std::vector<Vec3>& route, double speed) {
  // Until the new route is planned the unit holds at the reference point it had reached, not at
  // where it last stopped (which may be far behind: the controller would fly straight there).
  if (phase_ == Phase::Flying) hoverPoint_ = profile_.setpoint().position;
  route_ = route;
  reachedGoal_.reset();
  speed_ = speed;
  failures_ = 0;
  lastAttempt_ = kNever;
  if (phase_ != Phase::Takeoff) phase_ = route_.empty() ? Phase::Idle : Phase::Planning;
}

void Flight::hover() {
  route_.clear();
  reachedGoal_.reset();
  if (phase_ == Phase::Takeoff) return;
  if (phase_ == Phase::Flying) hoverPoint_ = profile_.setpoint().position;
  phase_ = Phase::Idle;
}

Vec3 Flight::travelDirection() const {
  if (phase_ != Phase::Flying && phase_ != Phase::Takeoff) return Vec3::Zero();
  const Vec3 v = profile_.setpoint().velocity;
  return v.norm() > 1e-6 ? Vec3(v.normalized()) : Vec3::Zero();
}

bool Flight::plan(const Vec3& from, double speed, const RobotMap& map,
                  const std::vector<planning::AvoidSphere>& avoid) {
  const auto& grid = map.grid();
  auto options = searchOptions(grid);
  options.avoid = avoid;
  std::vector<Vec3> points{from};
  std::vector<size_t> marks{0};
  Vec3 current = from;
  bool escaping = false;
  for (size_t k = 0; k < route_.size(); ++k) {
    Vec3 target = route_[k];
    if (!planning::cellTraversable(grid, grid.cellOf(target), options)) {
      mapping::Index3 cell;
      if (!planning::nearestTraversableCell(grid, target, options_.snapRadius, options, &cell))
        continue;  // no clear cell near this waypoint: skip it
      target = grid.centre(cell);
    }
    std::vector<Vec3> leg;
    if (planning::segmentTraversable(grid, current, target, options)) {
      leg.push_back(target);
      if (points.size() == 1) trappedSince_.reset();  // a straight way on from where it is
    } else {
      // Legs between nearby waypoints get a small search budget: a waypoint walled off from
      // the last one is skipped rather than paid for with a flood of the whole grid.
      auto legOptions = options;
      legOptions.maxExpansions =
          points.size() == 1 ? options_.maxExpansions : options_.maxExpansions / 10;
      auto result = planning::threadPathSearcher().thetaStar(grid, current, target, legOptions);
      if (points.size() == 1) {
        if (!trapped(result, grid)) {
          trappedSince_.reset();
        } else if (!trappedSince_) {
          trappedSince_ = lastTime_;
        } else if (lastTime_ - *trappedSince_ >= kTrappedPatience) {
          // No way out of where the unit is at the full clearance for a while: a narrow place
          // it flew into closed around it as it was mapped (an explorer spent the last 860 s of
          // a mission in a 5 m alley under unseen space that way). It is there, so its own
          // sphere fits: out at that clearance, still preferring the middle of free space
          // (softClearance).
          legOptions.clearance = ownSphereOptions(grid).clearance;
          result = planning::threadPathSearcher().thetaStar(grid, current, target, legOptions);
          escaping = result.status == planning::PathStatus::Found;
        }
      }
      if (result.status != planning::PathStatus::Found) continue;  // unreachable: skip it
      for (const auto& p : result.points)
        if ((p - current).norm() > 1e-6) leg.push_back(p);
    }
    for (const auto& p : leg) {
      if ((p - points.back()).norm() <= 1e-6) continue;  // PathProfile would drop it
      points.push_back(p);
      marks.push_back(k);
    }
    marks.back() = k + 1;
    current = points.back();
  }
  if (points.size() < 2) return false;
  ProfileLimits limits = options_.limits;
  limits.speed = std::min(limits.speed, speed_);
  limits.startSpeed = speed;
  profile_ = PathProfile(points, limits);
  routeMark_ = marks;
  escaping_ = escaping;
  COINSPECT_ASSERT(profile_.points().size() == routeMark_.size());
  checkedGridVersion_ = map.gridVersion();
  return true;
}

void Flight::planAround(const Vec3& from, double speed, const RobotMap& map,
                        const std::vector<planning::AvoidSphere>& blockers) {
  const auto route = route_;  // the current profile's marks index this route
  dropReachedWaypoints();
  if (!route_.empty() && plan(from, speed, map, blockers)) return;
  route_ = route;
}

bool Flight::remainingPathClear(const RobotMap& map) const {
  const auto& grid = map.grid();
  // A way out of a trapped place is checked at the clearance it was planned with (at the full
  // one it would be planned again at every rebuild, the same way).
  const auto options = escaping_ ? ownSphereOptions(grid) : searchOptions(grid);
  const auto& points = profile_.points();
  const size_t next = profile_.nextVertex();
  if (next >= points.size()) return true;
  const Vec3 carrot = profile_.pointAt(profile_.travelled());
  // Where the robot already is cannot be avoided: a start cell that became blocked is checked
  // from the next vertex on.
  if (planning::cellTraversable(grid, grid.cellOf(carrot), options) &&
      !planning::segmentTraversable(grid, carrot, points[next], options))
    return false;
  // Only the next stretch: farther legs are checked when they come near (new map information
  // there would otherwise make the robot plan the whole route again at every rebuild).
  double checked = (points[next] - carrot).norm();
  for (size_t i = next; i + 1 < points.size() && checked < options_.recheckDistance; ++i) {
    if (!planning::segmentTraversable(grid, points[i], points[i + 1], options)) return false;
    checked += (points[i + 1] - points[i]).norm();
  }
  return true;
}

agent::AgentSetpoint Flight::deconflict(const agent::AgentView& view, const RobotMap& map,
                                        agent::AgentSetpoint setpoint, bool* holding,
                                        std::vector<planning::AvoidSphere>* blockers) {
  *holding = false;
  const Vec3 me = view.odometry.position;
  const size_t myPriority = self_;
  Vec3 escape = Vec3::Zero();
  bool tooClose = false;  // a neighbour within minSeparation
  for (const auto& neighbour : view.neighbours) {
    if (neighbour.role == agent::Role::GroundStation) continue;
    const Vec3 other = neighbour.odometry.position;
    const Vec3 offset = me - other;
    const double distance = offset.norm();
    const bool ranked = priorityOf(neighbour.name) < myPriority;
    const bool higher = ranked && !standGround_;
    if (distance < options_.minSeparation) {
      tooClose = true;
      Vec3 away = distance > 1e-6 ? Vec3(offset / distance) : Vec3::UnitZ();
      if (!ranked)
        away.z() -= 0.5;  // the higher-priority unit dips, the other climbs
      else
        away.z() += 0.5;
      escape += away;
    }
    if (!higher) {
      if (distance >= options_.separation || profile_.empty()) continue;
      // Do not fly into it (it may be holding for us): stop short of minSeparation + radius, or
      // of the current distance when already closer.
      const double keep = std::min(options_.minSeparation + options_.radius, distance);
      bool inTheWay = false;
      for (double ahead = 0.5; !inTheWay && ahead <= options_.lookahead; ahead += 0.5)
        inTheWay = (profile_.pointAt(profile_.travelled() + ahead) - other).norm() < keep;
      if (!inTheWay) continue;
      *holding = true;
      if (blockers)  // cells whose centre is outside keep every path point this far from it
        blockers->push_back({other, options_.minSeparation + options_.radius +
                                        0.5 * map.grid().resolution() * std::sqrt(3.0)});
      continue;
    }
    // Hold while the higher-priority unit is near our next few metres of path.
    bool near = distance < options_.separation;
    for (double ahead = 0.0; !near && ahead <= options_.lookahead && !profile_.empty();
         ahead += 1.0)
      near = (profile_.pointAt(profile_.travelled() + ahead) - other).norm() < options_.separation;
    if (!near) continue;
    *holding = true;
    // One that stays where it is (waiting, or holding itself) would hold this one for good: it
    // is planned around after the same patience, kept `separation` away (two inspectors of
    // slei-b: the second held 3 m from its wait point behind the first, waiting at its own,
    // for the rest of a run).
    const Vec3 velocity = neighbour.odometry.velocity;
    if (blockers && velocity.norm() < kStill)
      blockers->push_back(
          {other, options_.separation + 0.5 * map.grid().resolution() * std::sqrt(3.0)});
    // Step aside when it closes in: across its motion, and up.
    if (distance > 1e-6 && velocity.dot(offset / distance) > 0.2) {
      Vec3 across = offset - velocity.normalized() * velocity.normalized().dot(offset);
      across = across.norm() > 1e-3 ? Vec3(across.normalized()) : Vec3::Zero();
      escape += across + Vec3(0, 0, 0.5);
    }
    // Make room: it stops short of us when we are in its way (and would wait for ever), so back
    // off to `separation` (closer than minSeparation the backing away above does it).
    if (distance >= options_.minSeparation && distance < options_.separation)
      escape += offset / distance;
  }
  if (escape.norm() < 1e-6) {
    if (*holding) setpoint.velocity = Vec3::Zero();  // wait where the reference point is
    return setpoint;
  }
  *holding = true;
  const auto& grid = map.grid();
  // The step away only has to clear the vehicle's own sphere, as a guarded setpoint: with the
  // path search's margins a unit that hovered within them of a surface could never back off
  // (slei-a, scene seed 2: two waiting inspectors held an explorer between them from 320 s on).
  const auto options = ownSphereOptions(grid);
  // The step must not take it closer than minSeparation to any other unit it is not already
  // that close to: in a crowd the way away from one neighbour led into another (75 robots on
  // slei-a: two inspectors collided 9 s after take-off). Failing the step away, up, across it
  // either way, or down.
  const auto clearOfNeighbours = [&](const Vec3& target) {
    const Vec3 step = target - me;
    for (const auto& neighbour : view.neighbours) {
      if (neighbour.role == agent::Role::GroundStation) continue;
      const Vec3 other = neighbour.odometry.position;
      const double t =
          std::clamp((other - me).dot(step) / std::max(step.squaredNorm(), 1e-12), 0.0, 1.0);
      const double nearest = (me + t * step - other).norm();
      if (nearest < std::min((me - other).norm(), options_.minSeparation) - 1e-9) return false;
    }
    return true;
  };
  const Vec3 away = escape.normalized();
  const Vec3 across = Vec3(-away.y(), away.x(), 0.0);
  std::vector<Vec3> directions{away, (away + Vec3::UnitZ()).normalized(), Vec3::UnitZ()};
  if (across.norm() > 1e-3) {
    directions.push_back(across.normalized());
    directions.push_back(-across.normalized());
  }
  directions.push_back(-Vec3::UnitZ());
  agent::AgentSetpoint out = setpoint;
  out.velocity = Vec3::Zero();
  out.acceleration = Vec3::Zero();
  // No clear way to back off: hold. In flight that is where the vehicle is; a unit already
  // holding keeps its hold point. Holding "where the vehicle is" at every decision let a unit
  // near a wall creep with its own drift for good: slei-c, scene seed 1, an inspector backing
  // off from a teammate slid 3 m in 290 s into a structure.
  out.position = phase_ == Phase::Flying ? me : setpoint.position;
  // Where a step may end, in order of preference: at the clearance paths keep; no closer to
  // mapped surfaces than the unit already is; and, only with a neighbour within minSeparation,
  // anywhere its own sphere fits. Backing off 1.5 m at a time toward a roof it was under took
  // a unit to 0.2 m below an eave not mapped yet (slei-a, scene seed 4: it hit the eave as it
  // was seen).
  const auto full = searchOptions(grid);
  const float clearanceHere = grid.clearance(grid.cellOf(me));
  const auto acceptable = [&](const Vec3& target, int pass) {
    const auto cell = grid.cellOf(target);
    if (pass == 0) return planning::cellTraversable(grid, cell, full);
    if (pass == 1) return grid.clearance(cell) >= clearanceHere;
    return true;
  };
  bool stepped = false;
  for (int pass = 0; pass < (tooClose ? 3 : 2) && !stepped; ++pass)
    for (const Vec3& direction : directions) {
      // Never against the escape: stepping up, then down when up was blocked, then up again
      // kept a unit bobbing beside a neighbour it could not get away from.
      if (direction.dot(escape) < -1e-9) continue;
      const Vec3 target = me + 1.5 * direction;
      if (acceptable(target, pass) && clearOfNeighbours(target) &&
          planning::segmentTraversable(grid, me, target, options)) {
        out.position = target;
        stepped = true;
        break;
      }
    }
  // The unit stays where it backed off to: flying back to the reference point it had brought the
  // two units together again (caric-baseline, generated mbs, seed 2). A flight plans again from
  // there.
  hoverPoint_ = out.position;
  reachedGoal_.reset();
  if (phase_ == Phase::Flying) {
    dropReachedWaypoints();
    phase_ = route_.empty() ? Phase::Idle : Phase::Planning;
    lastAttempt_ = view.time;
  }
  return out;
}

agent::AgentSetpoint Flight::bounded(const Vec3& position, const RobotMap& map,
                                     agent::AgentSetpoint setpoint) {
  const Vec3 offset = setpoint.position - position;
  if (offset.norm() <= options_.maxSetpointOffset) return setpoint;
  ++guardedSetpoints_;
  // The line only has to clear the vehicle's own sphere: the margins are for planned paths.
  const auto& grid = map.grid();
  const auto options = ownSphereOptions(grid);
  const Vec3 target = position + offset.normalized() * options_.maxSetpointOffset;
  setpoint.velocity = Vec3::Zero();
  setpoint.acceleration = Vec3::Zero();
  if (planning::segmentTraversable(grid, position, target, options)) {
    setpoint.position = target;
    return setpoint;
  }
  // Stay here; a flight plans again from here at once (its reference point cannot be reached,
  // and it would otherwise wait for the vehicle forever).
  setpoint.position = position;
  hoverPoint_ = position;
  reachedGoal_.reset();
  if (phase_ == Phase::Flying) {
    dropReachedWaypoints();
    phase_ = route_.empty() ? Phase::Idle : Phase::Planning;
    lastAttempt_ = kNever;
  }
  return setpoint;
}

void Flight::keepHoverPointClear(const Vec3& position, const RobotMap& map) {
  if (map.gridVersion() == hoverCheckedVersion_) return;
  hoverCheckedVersion_ = map.gridVersion();
  const auto& grid = map.grid();
  const auto options = ownSphereOptions(grid);
  // A vehicle in a cell that is itself blocked (unknown space near a box it waits by) keeps its
  // point: holding "where it is" would follow its drift.
  if (!planning::cellTraversable(grid, grid.cellOf(position), options) ||
      planning::segmentTraversable(grid, position, hoverPoint_, options))
    return;
  // New map information blocks the point or the way to it: hover where the vehicle is.
  hoverPoint_ = position;
  reachedGoal_.reset();
}

void Flight::dropReachedWaypoints() {
  const size_t reached = routeMark_[std::min(profile_.nextVertex() - 1, routeMark_.size() - 1)];
  route_.erase(route_.begin(),
               route_.begin() + static_cast<long>(std::min(reached, route_.size())));
}

agent::AgentSetpoint Flight::step(const agent::AgentView& view, const RobotMap& map) {
  const Vec3 position = view.odometry.position;
  const double dt = started_ ? std::max(0.0, view.time - lastTime_) : 0.0;
  lastTime_ = view.time;
  if (!started_) {
    started_ = true;
    takeoffTarget_ = position + Vec3(0, 0, options_.takeoffHeight);
    ProfileLimits climb = options_.limits;
    climb.speed = std::min(climb.speed, 1.0);
    profile_ = PathProfile({position, takeoffTarget_}, climb);
    hoverPoint_ = takeoffTarget_;
  }

  bool holding = false;
  agent::AgentSetpoint setpoint;
  setpoint.yaw = view.odometry.yaw;
  switch (phase_) {
    case Phase::Takeoff:
      profile_.advance(position, dt);
      if (profile_.finished() && (position - takeoffTarget_).norm() < 0.5)
        phase_ = route_.empty() ? Phase::Idle : Phase::Planning;
      setpoint.position = profile_.setpoint().position;
      setpoint.velocity = profile_.setpoint().velocity;
      return setpoint;  // straight up from the ground: nothing to deconflict yet
    case Phase::Planning:
      if (view.time - lastAttempt_ >= options_.retryPeriod) {
        lastAttempt_ = view.time;
        if (plan(position, view.odometry.velocity.norm(), map)) {
          phase_ = Phase::Flying;
          failures_ = 0;
        } else {
          ++failures_;
        }
      }
      if (phase_ != Phase::Flying) {
        keepHoverPointClear(position, map);
        setpoint.position = hoverPoint_;
        break;
      }
      [[fallthrough]];
    case Phase::Flying: {
      if (map.gridVersion() != checkedGridVersion_) {
        checkedGridVersion_ = map.gridVersion();
        if (!remainingPathClear(map)) {
          // Keep only the route waypoints not reached yet, and plan again from here.
          dropReachedWaypoints();
          hoverPoint_ = profile_.setpoint().position;
          if (route_.empty() || !plan(position, view.odometry.velocity.norm(), map)) {
            phase_ = route_.empty() ? Phase::Idle : Phase::Planning;
            lastAttempt_ = view.time;
            if (!route_.empty()) ++failures_;
            setpoint.position = hoverPoint_;
            break;
          }
        }
      }
      std::vector<planning::AvoidSphere> blockers;
      auto preview = deconflict(view, map, profile_.setpoint(), &holding, &blockers);
      if (blockers.empty()) {
        yieldingSince_ = kNever;
      } else if (yieldingSince_ == kNever) {
        yieldingSince_ = view.time;
      } else if (view.time - yieldingSince_ >= options_.yieldPatience) {
        yieldingSince_ = view.time;  // when this fails, the next try is a period later
        planAround(position, view.odometry.velocity.norm(), map, blockers);
        preview = deconflict(view, map, profile_.setpoint(), &holding);
      }
      if (!holding) profile_.advance(position, dt);
      setpoint = holding ? preview : profile_.setpoint();
      setpoint.yaw = view.odometry.yaw;
      if (profile_.finished() && !holding) {
        phase_ = Phase::Idle;
        hoverPoint_ = profile_.points().back();
        if (!route_.empty()) reachedGoal_ = route_.back();
        route_.clear();
      }
      return bounded(position, map, setpoint);
    }
    case Phase::Idle:
      keepHoverPointClear(position, map);
      setpoint.position = hoverPoint_;
      break;
  }
  return bounded(position, map, deconflict(view, map, setpoint, &holding));
}

}  // namespace coinspect::strategies::runtime
