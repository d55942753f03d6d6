// Collision-free flight to a goal or along a route, as one setpoint per decision.
//
// A unit first climbs vertically to `takeoffHeight` above where it stands. Then a goal (or each
// leg of a route whose straight segment is not clear) is planned with the planning library's
// path search on the RobotMap's grid, at the clearance of the robot's radius plus a margin plus
// the grid's own uncertainty; the polyline is flown by a PathProfile. The remaining path is
// checked again whenever the grid is rebuilt, and planned again from where the robot is when new
// map information blocks it. Without anything to do the unit hovers where it stopped. A unit
// whose own free space at that clearance is a pocket (no path out of a few tens of cubic metres,
// or no clear cell near it at all: a narrow place that closed around it as it was mapped) for
// 10 s plans its way out at the clearance of its own sphere instead.
//
// Neighbours in line of sight (their odometry is in the view) are deconflicted by priority (fleet
// order: the lower index goes first): a unit holds while a higher-priority neighbour is within
// `separation` of its next few metres of path and backs off to `separation` from it (after
// `yieldPatience` it plans around one that stays where it is: a unit waiting at its post held
// another for good), and every unit closer than `minSeparation` to a neighbour backs away from
// it (the lower-priority one also climbs); a unit stays where it backed off to (flying back to
// its reference point brought two units together again). A step back ends, by preference, where
// the unit has the clearance paths keep, else no closer to mapped surfaces than it is, and only
// with a neighbour within minSeparation anywhere its own sphere fits; never against the way away
// from its neighbours. Having the right of way does not mean flying into a unit that holds on
// the path: a unit does not advance while its next `lookahead` metres would bring it closer than
// minSeparation + radius to a lower-priority neighbour within `separation` (nor closer than it
// already is), and after `yieldPatience` it plans around the neighbours still in its way.
//
// The vehicle's tracking controller flies straight at its setpoint as fast as its limits allow,
// so a setpoint far from the vehicle would be reached along a line nobody checked. Every setpoint
// after take-off is therefore kept within `maxSetpointOffset` of the vehicle, and one whose
// straight line from the vehicle is not clear becomes a hold where the vehicle is (a flight then
// plans again from there). A hover point that a new grid blocks (or the straight way to it)
// becomes where the vehicle is.
#pragma once

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/agent_view.h"
#include "coinspect/planning/path_search.h"
#include "coinspect/strategies/runtime/path_profile.h"
#include "coinspect/strategies/runtime/robot_map.h"

namespace coinspect::strategies::runtime {

struct FlightOptions {
  double radius = 0.5;        // m, the robot's collision radius
  double safetyMargin = 0.8;  // m, kept between the robot's sphere and any mapped surface
  planning::UnknownPolicy unknown = planning::UnknownPolicy::Blocked;
  ProfileLimits limits;
  double takeoffHeight = 3.0;      // m above the start, climbed vertically first
  double retryPeriod = 1.0;        // s between planning attempts after a failure
  int maxFailures = 3;             // consecutive failures before failed() says so
  int snapRadius = 4;              // cells: blocked start/goal/waypoints move this far at most
  double separation = 4.0;         // m, hold distance to higher-priority neighbours' positions
  double minSeparation = 2.0;      // m, back away from any neighbour closer than this
  double lookahead = 4.0;          // m of own path checked against neighbours
  double yieldPatience = 3.0;      // s held by lower-priority units before planning around them
  double recheckDistance = 20.0;   // m of remaining path checked again after each map rebuild
  size_t maxExpansions = 200000;   // search budget to the first waypoint (a tenth per later leg)
  double maxSetpointOffset = 2.5;  // m between the vehicle and any setpoint after take-off
};

class Flight {
 public:
  // `fleet`: every unit's name in fleet order (priorities); `self`: own fleet index.
  Flight(const FlightOptions& options, std::vector<std::string> fleet, size_t self);

  // New goal (ignored when equal to the current one within 0.3 m and `speed` unchanged, or to
  // the goal reached last while the unit still holds there).
  void goTo(const Vec3& goal, double speed);
  // Visit every waypoint in order (a blocked one is moved to the nearest clear cell or skipped).
  void follow(const std::vector<Vec3>& route, double speed);
  void hover();
  // Keep its place against higher-priority neighbours too (it neither holds for them nor backs
  // off to `separation`; closer than minSeparation both still back away): a unit that must stay
  // where it is, such as an explorer at its charger, which a passing explorer pushed out of the
  // charger's range.
  void standGround(bool on) { standGround_ = on; }

  bool takingOff() const { return phase_ == Phase::Takeoff; }
  // The goal or route is done (also after hover()).
  bool done() const { return phase_ == Phase::Idle; }
  bool failed() const { return failures_ >= options_.maxFailures; }
  double requiredClearance(const mapping::VoxelGrid& grid) const;
  // Opens the unknown space of the take-off column at `start` in `map` (where a unit stands and
  // climbs is free): radius, and height above the climb, = the clearance the path search
  // requires. Rebuilds the grid. The space around the column may stay unknown (blocked near a
  // box) until mapped: plans out of it can fail meanwhile.
  void openTakeoffColumn(RobotMap& map, const Vec3& start, double time) const;

  // One decision: replans when needed, deconflicts, returns the setpoint (yaw: keeps the current
  // heading; callers overwrite it).
  agent::AgentSetpoint step(const agent::AgentView& view, const RobotMap& map);

  // The path search's options on `grid` (what a goal must satisfy to be reached).
  planning::PathSearchOptions searchOptions(const mapping::VoxelGrid& grid) const;
  const PathProfile& profile() const { return profile_; }
  // Setpoints the offset guard had to shorten or turn into a hold (0 in a healthy flight).
  size_t guardedSetpoints() const { return guardedSetpoints_; }
  // Unit direction of travel at the carrot (zero when hovering).
  Vec3 travelDirection() const;

 private:
  enum class Phase { Takeoff, Planning, Flying, Idle };
  bool plan(const Vec3& from, double speed, const RobotMap& map,
            const std::vector<planning::AvoidSphere>& avoid = {});
  // Plans the rest of the route around `blockers` (lower-priority units holding in the way);
  // keeps the current profile when that fails.
  void planAround(const Vec3& from, double speed, const RobotMap& map,
                  const std::vector<planning::AvoidSphere>& blockers);
  bool remainingPathClear(const RobotMap& map) const;
  // The search from the unit's own position found no way out of where it is.
  bool trapped(const planning::PathResult& result, const mapping::VoxelGrid& grid) const;
  void dropReachedWaypoints();  // the route keeps only waypoints the profile has not reached
  // `blockers` (optional): lower-priority units this unit holds for, as spheres to plan around.
  agent::AgentSetpoint deconflict(const agent::AgentView& view, const RobotMap& map,
                                  agent::AgentSetpoint setpoint, bool* holding,
                                  std::vector<planning::AvoidSphere>* blockers = nullptr);
  size_t priorityOf(const std::string& name) const;
  // searchOptions, clear of the vehicle's own sphere only: for short straight moves (a guarded
  // setpoint, a step away from a neighbour), not for planned paths.
  planning::PathSearchOptions ownSphereOptions(const mapping::VoxelGrid& grid) const;
  // At each new grid: a hover point (or the straight way to it) that new map information
  // blocks at the vehicle's own sphere moves to where the vehicle is, when that is clear.
  void keepHoverPointClear(const Vec3& position, const RobotMap& map);
  agent::AgentSetpoint bounded(const Vec3& position, const RobotMap& map,
                               agent::AgentSetpoint setpoint);

  FlightOptions options_;
  std::vector<std::string> fleet_;
  size_t self_;

  Phase phase_ = Phase::Takeoff;
  bool started_ = false;
  Vec3 hoverPoint_ = Vec3::Zero();
  std::vector<Vec3> route_;             // what is left to visit (the goal is a route of one)
  std::optional<Vec3> reachedGoal_;     // the route's last waypoint, while holding where it ended
  std::vector<size_t> routeMark_;       // per profile vertex: route waypoints reached there
  bool escaping_ = false;               // the profile leaves a trap at the own-sphere clearance
  std::optional<double> trappedSince_;  // plans from where it was found no way out since then
  double speed_ = 1.0;
  PathProfile profile_;
  uint64_t checkedGridVersion_ = 0;
  uint64_t hoverCheckedVersion_ = 0;  // the grid keepHoverPointClear last checked against
  double lastAttempt_ = -1e300;
  int failures_ = 0;
  // Since when lower-priority units hold this unit up (-inf: they do not).
  double yieldingSince_ = -std::numeric_limits<double>::infinity();
  bool standGround_ = false;
  double lastTime_ = 0.0;
  Vec3 takeoffTarget_ = Vec3::Zero();
  size_t guardedSetpoints_ = 0;
};

}  // namespace coinspect::strategies::runtime
