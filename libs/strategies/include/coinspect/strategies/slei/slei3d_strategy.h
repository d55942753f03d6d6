// `slei3d`: the SLEI3D method (Chen et al., IEEE T-ASE; ../shared/design/slei3d-reference.md)
// for feature missions ([mission] objective = features, doc/features.md), one class for the
// three roles (doc/strategies.md, "SLEI3D"):
// - the station makes the first plan (subgroups, first boxes, first meetings) and floods it
//   (several stations: each its own share of explorers, inspectors and boxes, stationShares);
//   it then drives from meeting to meeting; at each, the explorer reports its box and predicted
//   time to finish (eq. 9) and gets its next meeting (a corner of its box), or a new box, the
//   free one nearest its last (rolling assignment), when it reports its box finished;
// - an explorer explores its box: its LiDAR maps the structure from afar, but features are
//   detected only within 5 m of the explorer and +-45 deg of its heading, so exploring means
//   sweeping the detector over every mapped surface of the box (viewpoints covering surface
//   patches from 4 m, facing them) and flying to frontiers where the box is not mapped yet;
//   it hands the features it detects to its inspectors at meetings it flies to, and leaves for
//   the station in time for each meeting;
// - an inspector flies its list of features (each from the pose where the explorer detected
//   it, camera on the feature) until inspected, then waits where its list ends.
// Robots share key frames by store and forward (they fly on each other's maps) and the
// simulator carries inspection results to whoever they meet.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/planning/coverage.h"
#include "coinspect/planning/detection_coverage.h"
#include "coinspect/planning/ground_drive.h"
#include "coinspect/planning/meeting_allocation.h"
#include "coinspect/planning/meeting_route.h"
#include "coinspect/planning/slei_meeting_order.h"
#include "coinspect/strategies/coinspect/keyframe_relay.h"
#include "coinspect/strategies/runtime/flight.h"
#include "coinspect/strategies/runtime/robot_map.h"
#include "coinspect/strategies/runtime/unit_info.h"
#include "coinspect/strategies/slei/fleet_plan.h"
#include "coinspect/strategies/slei/protocol.h"

namespace coinspect::strategies::slei {

// The paper's baselines, flown with SLEI3D's own exploration, flight and messages so that a
// comparison measures the layer each one changes (doc/strategies.md, "Baselines"):
// - Pre: SLEI-PRE, each explorer's boxes in an order fixed at the start (no rolling choice);
// - Fix: SLEI-FIX, the station does not move; explorers come back to it at fixed intervals;
// - Team: CARIC-style teams (`caric-team`): each team a fixed region (Pre's dealt boxes), a
//   static station as the relay hub (returns every teamInterval at most, and once the region is
//   explored) where the inspectors wait between lists, and the explorer splits its features
//   among the inspectors free there, no meeting optimisation;
// - ExploreFirst: exploration, then inspection (MU-CPPI style, `explore-then-inspect`): the
//   explorers explore every box before handing out any feature; the inspectors wait meanwhile.
enum class SleiVariant { Slei3d, Pre, Fix, Team, ExploreFirst };

struct SleiOptions {
  SleiVariant variant = SleiVariant::Slei3d;
  double fixInterval = 120.0;  // s between an explorer's returns to the static station (slei-fix)
  // caric-team: s at most between an explorer's returns to its hub (it also comes back as soon
  // as its region's last box is explored). Every 120 s, as slei-fix, no box of slei-c's scene
  // seed 2 was explored within 1000 s: the trips took the time of the exploring.
  double teamInterval = 300.0;
  bool priorityFirst = true;  // high-priority features allocated first (off: like the others)
  // FF3E's bound, greedy form: explore only what still lets it reach its station meeting on
  // time, and leave at once when nothing fits (off: nearest first, leave by the clock).
  bool deadlineBound = false;
  // FF3E's recursive search over the detector's stops (planning::deadlineBoundedSearch): how
  // many stops ahead (0: nearest first).
  size_t searchDepth = 0;
  // The paper's fully unknown workspace (`[slei3d] workspace = unknown`): the robots use only the
  // bounds of all the boxes, split into one equal slab per explorer; at each meeting an explorer
  // whose box is not done and larger than a leaf reports the box's octree parts that still hold
  // work, which join the free boxes (fleet_plan.h, splitWorkspace, octreeChildren).
  bool unknownWorkspace = false;
  double leafEdge = 10.0;  // m: the octree partition stops at parts no longer than this
  // m around the boxes where unknown space blocks paths (runtime::RobotMapOptions::boxMargin).
  // The generated SLEI scenes' boxes enclose their structures with 1 m to spare; 2 m closed
  // slei-c's 6 m streets to every UAV that had not mapped them.
  double unknownBoxMargin = 1.0;
  double speed = 2.0;             // m/s, UAV cruise
  double exploreHeight = 3.0;     // m above the ground to enter a box
  double meetHeight = 3.0;        // m above the ground where an explorer meets the station
  double waitHeight = 6.0;        // m above the ground where inspectors wait for orders
  double gridResolution = 0.5;    // m, map and planning grid
  double safetyMargin = 0.4;      // m between a UAV's sphere and mapped surface
  double sweepDistance = 4.0;     // m from a surface patch to sweep the detector over it
  double handoutPeriod = 5.0;     // s between hand-out decisions (SOEI's period)
  double meetingGrace = 10.0;     // s: a meeting partner later than this is given up (delta)
  double inspectPatience = 12.0;  // s at a feature's pose without its inspection: skip it
  // An inspector whose own view has no free place on the normal's line turns it away from the
  // normal (30, then 55 deg) before falling back to the detection pose (doc/strategies.md).
  bool obliqueViews = false;
  // SOEI's view of an inspector (`[slei3d] presume_done`): a feature on its list whose predicted
  // end, counted from its last status, is past is presumed inspected, and the inspector at its
  // next one or its wait point. Off: every listed feature still ahead of it from now on.
  bool presumeDone = true;
  // At a hand-out's meeting point without the inspector in link, the explorer flies on towards
  // the inspector's predicted place (`[slei3d] approach_partner`). Off: it waits at the point.
  bool approachPartner = true;
  // `[slei3d] handout_at_box_end` (not the paper's): while its box is left to explore, an
  // explorer hands nothing out (SOEI still meets inspectors when the box is explored, when it
  // announces a new box to them, and for high-priority features): it never breaks off its
  // exploring, and the inspectors work a box behind it, away from its sweep.
  bool handoutAtBoxEnd = false;
  // s: with `handout_at_box_end`, in its last box (the station reserved none after it) an
  // explorer hands out the features it has held this long (`[slei3d] last_box_hold`; 0: held to
  // the box's end there too). No next box waits for it, and the inspectors are idle.
  double lastBoxHold = 100.0;
  // s, `[slei3d] fetch_detour` (not the paper's; 0: off): with no next box reserved, an explorer
  // on its way to the station first meets those of its inspectors whose lists should be done,
  // when that costs it at most this much more than flying straight there, so that their results
  // go with it to this meeting rather than the next one.
  double fetchDetour = 0.0;
  // `[slei3d] sweep_through`: the flight is given the sweep's next two stops, so that it passes
  // a stop at its turn's speed instead of braking to a halt there (off: one stop at a time).
  bool sweepThrough = true;
  // s, longest time to the next station meeting. The reference clamps eq. 9 at 600 s; with the
  // next box reserved an explorer done early no longer waits that long, and the lead only bounds
  // how long its results and the station's plan go unexchanged: 200 s collected 124.7 features
  // on average against 111.9 with 600 s over nine slei-a runs (doc/strategies.md).
  double maxMeetingLead = 200.0;
  // Each reply also reserves the subgroup's next box (the one the rolling assignment or its
  // fixed order would give it next), so that an explorer done before its meeting goes on to it
  // instead of waiting for the station (`[slei3d] reserve_next_box`; off: the paper's rule, a
  // new box only at a meeting). A rolling box is reserved only while one stays free for each
  // other explorer at work without a reservation (freeBoxesSpare).
  bool reserveNextBox = true;
  // `[slei3d] feasible_meetings` (not the paper's): the station promises an explorer's next
  // meeting no sooner than its route can keep it (feasibleMeetingTime). Off: eq. 9's time.
  bool feasibleMeetings = false;
  // Work sharing (`[slei3d] share_work`; not the paper's): an explorer left without a box while
  // another still explores waits for a share of it at that one's next station meeting; there
  // the other's reserved box, not yet started, goes back to the free ones, or, none being free,
  // its box is split across its footprint into the parts still holding work (octreeChildren,
  // edges above leafEdge), which join the free boxes. Off: an explorer with no free box left is
  // done (the paper's rolling assignment). Not for the fixed box orders (slei-pre, caric-team).
  bool shareWork = true;
  // `[slei3d] split_last_box` (not the paper's): the rolling assignment, about to give out (or
  // reserve) the last free box of the scene while the station has other explorers, splits it
  // first (halves across its longer side for two explorers, footprint quarters for more; edges
  // above leafEdge) and gives out the part nearest; the other parts stay free for whoever is
  // done next. Whole, the last box goes to one explorer, often reserved long before it can start
  // it, and the others, done, wait for a share of it (slei-c, scene seed 1: block 3, reserved at
  // 566 s, started at 1086 s, split at 1121 s). Off by default: measured, it moved neither
  // Table I ratio (doc/strategies.md, "Work sharing").
  bool splitLastBox = false;
  // m: frontier clusters are cut into cubes of this edge, one viewpoint each (FUEL's split of
  // large frontiers; 0: whole clusters).
  double frontierChunk = 0.0;
  // Once the box's mapped surface is swept, the explorer flies over the box, between two
  // opposite corners of its footprint above its top (`[slei3d] roof_pass`): its LiDAR sees the
  // roofs from above, which it never does from beside the structure, and the sweep goes on over
  // them. Off: the frontiers alone lead it (they never did above the roofs).
  bool roofPass = true;
  PlanOptions plan;  // the station's first plan (even split, corners, its speed)
};

class Slei3dStrategy : public agent::Strategy {
 public:
  Slei3dStrategy(const agent::StrategyContext& context, const SleiOptions& options);
  ~Slei3dStrategy() override;
  agent::AgentCommand decide(const agent::AgentView& view) override;
  double decisionRate() const override { return 10.0; }

 private:
  // ---- shared (slei3d_strategy.cpp)
  void initialise(const agent::AgentView& view);
  void readPlan(const agent::AgentView& view);
  void floodPlan(const agent::AgentView& view, agent::AgentCommand& command);
  bool neighbour(const agent::AgentView& view, uint32_t unit) const;
  void send(agent::AgentCommand& command, uint32_t to, const char* topic,
            std::vector<uint8_t> bytes) const;
  agent::AgentCommand fly(const agent::AgentView& view, std::optional<Vec3> aim);
  // The station: walls in a key frame's points onto its ground.
  void learnGround(const agent::KeyFrame& frame);
  const Subgroup* subgroupOf(uint32_t unit) const;
  // Where the k-th inspector of a subgroup waits for its first orders: off the corner of the
  // first box where the station first meets the explorer, 2.5 m apart, away from the box
  // (caric-team: around the relay).
  Vec3 firstWaitPoint(const Subgroup& subgroup, size_t k) const;
  // Where the k-th inspector of a subgroup waits in `box` when the subgroup came to it from
  // `from`: off the box's corner nearest `from`, 2.5 m apart, away from the box.
  Vec3 waitPointNear(int32_t box, const Vec3& from, size_t k) const;
  double boxExploredFraction(int32_t box) const;
  bool fixedRegions() const {
    return options_.variant == SleiVariant::Pre || options_.variant == SleiVariant::Team;
  }
  bool staticStation() const {
    return options_.variant == SleiVariant::Fix || options_.variant == SleiVariant::Team;
  }
  // s from a reply to an explorer's next meeting at the static station.
  double returnInterval() const {
    return options_.variant == SleiVariant::Team ? options_.teamInterval : options_.fixInterval;
  }

  // ---- station (slei3d_station.cpp)
  struct StationMeeting {
    uint32_t explorer = 0;
    Meeting meeting;
  };
  agent::AgentCommand decideStation(const agent::AgentView& view);
  void answerReports(const agent::AgentView& view, agent::AgentCommand& command);
  planning::MeetingOrderProblem scheduleProblem(const agent::AgentView& view,
                                                std::optional<uint32_t> without) const;
  void orderSchedule(const agent::AgentView& view);
  double feasibleMeetingTime(const agent::AgentView& view, uint32_t explorer,
                             const Meeting& wanted) const;
  // An explorer presumed lost: its box is given to the next subgroup that asks for one, and its
  // inspectors to the next explorer with a box that reports (orphans_).
  void releaseBox(uint32_t explorer);
  void returnBox(uint32_t explorer, int32_t box);  // to the free boxes or another fixed order
  int32_t takeNextBox(uint32_t explorer, int32_t after);  // the subgroup's next box, now taken
  bool freeBoxesSpare(uint32_t explorer) const;           // a box may be reserved for it now
  int32_t boxOf(uint32_t explorer) const;  // its box as last answered (the plan's first)
  size_t freeBoxCount() const;             // boxes no subgroup has taken
  bool sharingWork() const { return options_.shareWork && !fixedRegions(); }
  // Work sharing: explorers other than `explorer` waiting for a share of another's box.
  bool othersAwaitWork(uint32_t explorer) const;
  size_t explorerCount() const;  // the station's explorers, not lost
  // The earliest scheduled meeting of an explorer, not `explorer`, still at work in a box.
  const StationMeeting* nextMeetingAtWork(uint32_t explorer) const;
  // The shape to send with `box` when it is a part the explorers do not know.
  std::optional<agent::BoxView> partShape(int32_t box) const;
  void orphanInspectors(uint32_t explorer);
  size_t subgroupIndex(uint32_t explorer) const;  // of the plan's subgroups (size(): none)

  // ---- explorer (slei3d_explorer.cpp)
  enum class ExplorerPhase { ToBox, Exploring, ToStation, AtStation, ToInspector, Done };
  agent::AgentCommand decideExplorer(const agent::AgentView& view);
  void learnInspected(uint32_t id);
  void dropKnownInspected(std::vector<FeatureTask>& tasks) const;
  void collectDetections(const agent::AgentView& view);
  void readStatus(const agent::AgentView& view);
  // What an exploration plan found: something to fly to now, nothing left to explore (of what
  // has a viewpoint), or something left that it cannot fly before its station meeting.
  enum class Plan { Flying, Nothing, NotBeforeMeeting };
  Plan planExploration(const agent::AgentView& view);
  void markSwept(const agent::AgentView& view);
  void followSweep(const agent::AgentView& view);
  void flySweep();  // to the sweep's next stop (with sweep_through, on through the one after)
  void planHandout(const agent::AgentView& view);
  double predictRemaining(const agent::AgentView& view) const;
  void enterBox(const agent::AgentView& view, int32_t box);
  // Where it enters a box coming from `from`: the box's corner nearest it, at exploreHeight.
  Vec3 boxEntry(int32_t box, const Vec3& from) const;
  Vec3 atMeetHeight(const Vec3& place) const;  // `place` at the explorers' meeting height
  // When, leaving `from` at `leaving`, it would be at its own station meeting's place, with the
  // margin it keeps (kLeaveMargin): later than the meeting's time, it is late.
  double ownMeetingArrival(const Vec3& from, double leaving) const;
  // The unknown workspace (and work sharing, across the footprint only): the octree parts of
  // its box that still hold work (open surface or a frontier), for its report; none for a leaf.
  std::vector<agent::BoxView> remainderParts() const;
  // The mapped surface patches of `box` (and within 1 m of it) its detector has not swept.
  std::vector<planning::InspectionPatch> unsweptPatches(const agent::BoxView& box) const;
  // Inspectors of a lost explorer, given by the station: met where they should wait and told of
  // this subgroup's wait point.
  void adoptInspectors(const agent::AgentView& view, const std::vector<Adoption>& adopt);
  // Done with the box before the meeting: the station's stop where it can be caught soonest.
  void goToStation(const agent::AgentView& view, const Vec3& place);
  // Where it meets a station at `place`: the flyable point nearest its antenna in line of sight
  // (a static station's: nearest the explorer's own side of it).
  Vec3 stationPoint(const agent::AgentView& view, const Vec3& place) const;
  // The flyable point within kApproachReach of `partner`, in line of sight of it, nearest to
  // `toward` (default: to the partner itself).
  Vec3 meetingPointNear(const agent::AgentView& view, const Vec3& partner, const Vec3& fallback,
                        bool above, const std::optional<Vec3>& toward = std::nullopt) const;
  double lastApproach_ = -1e300;
  std::optional<Vec3> hubSlot_;  // a static station's explorer with nothing left waits there
  // `by`: when the station should be there.
  std::optional<Vec3> earlyStop(const agent::AgentView& view, double* by, size_t* stop) const;

  // ---- inspector (slei3d_inspector.cpp)
  agent::AgentCommand decideInspector(const agent::AgentView& view);

  SleiOptions options_;
  runtime::UnitInfo unit_;
  std::vector<std::string> names_;
  uint64_t seed_ = 0;  // the run's seed for this unit (SOEI's genetic algorithm)
  bool initialised_ = false;
  double groundZ_ = 0.0;
  std::unique_ptr<runtime::RobotMap> map_;
  std::unique_ptr<runtime::Flight> flight_;
  // One flood of the grid per grid version for every "can it get there" of the explorer.
  mutable planning::ReachableCellsCache reachable_;
  std::unique_ptr<coinspect_strategy::KeyFrameRelay> relay_;
  // The plan: a station's own part; a UAV's, the parts it has heard of merged (one per station).
  std::optional<FleetPlan> plan_;
  std::vector<std::vector<uint8_t>> planBytes_;  // the parts as received (flooded on)
  double lastFlood_ = -1e300;
  std::vector<agent::BoxView> boxes_;

  // Station.
  std::vector<StationMeeting> schedule_;        // upcoming meetings, in the order served
  std::map<uint32_t, Reply> answered_;          // per explorer: the last reply sent
  std::vector<uint8_t> boxTaken_;               // per box: assigned to some subgroup
  std::vector<std::vector<int32_t>> boxOrder_;  // fixed orders: per subgroup, boxes left
  std::map<uint32_t, int32_t> reserved_;        // per explorer: its next box, taken already
  Vec3 staticPlace_ = Vec3::Zero();             // where it started: a static station stays there
  // Per live explorer: its inspectors and where each should be waiting (the station's
  // prediction: off the corner of the explorer's box nearest where it came from).
  struct Member {
    uint32_t inspector = 0;
    Vec3 place = Vec3::Zero();
  };
  std::map<uint32_t, std::vector<Member>> members_;
  std::map<uint32_t, Vec3> enteredFrom_;  // per explorer: where it came to its box from
  std::vector<Adoption> orphans_;         // inspectors of lost explorers, not given yet
  std::set<uint32_t> lost_;               // explorers presumed lost, not heard since
  std::set<uint32_t> awaitingWork_;       // work sharing: explorers without a box, waiting
  size_t sceneBoxes_ = 0;                 // boxes before any split (the explorers know them)
  // The meeting it drives to or waits at, and when it got there.
  uint32_t waitingFor_ = ~uint32_t{0};
  double waitingForTime_ = 0.0;
  std::optional<double> arrivedAt_;
  double holdUntil_ = -1e300;  // [energy]: it stays where it is while an explorer charges
  // Its ground paths: around the boxes' footprints, the walls in the key frames it carries and
  // where it found its way blocked.
  std::unique_ptr<planning::GroundDrive> drive_;
  void driveStation(const agent::AgentView& view, const Vec3& goal, agent::AgentCommand& command);

  // Explorer.
  bool joined_ = false;  // took its part of the plan
  ExplorerPhase phase_ = ExplorerPhase::ToBox;
  double lastSend_ = -1e300;
  int32_t box_ = -1;
  Vec3 boxFrom_ = Vec3::Zero();  // where it came to the box from (its wait points' corner)
  double boxStart_ = 0.0;
  Meeting stationMeeting_;
  std::vector<Meeting> stationStops_;  // the station's schedule at the last reply, in order
  Meeting lastReply_;                  // where and when the last reply came
  std::optional<Vec3> earlyPlace_;     // a stop to catch the station at before the meeting
  double earlyBy_ = 0.0;               // when the station should be there
  size_t earlyStop_ = 0;               // which of stationStops_ earlyPlace_ is
  bool earlyTried_ = false;            // since the last reply
  int32_t nextBox_ = -1;               // the box the last reply reserved for it (-1: none)
  // caric-team: a reply came at the hub, and the hand-out there is still to plan (after any
  // charging).
  bool hubHandoutDue_ = false;
  // [energy]: after a reply it charges above the station before it goes on (the station waits);
  // given up when the level has not risen for a while (no charger in reach).
  bool charging_ = false;
  double chargeFrom_ = 0.0;          // the charger is free for it from then (the reply says)
  double chargeLevel_ = 0.0;         // the level when it last rose
  double chargeRoseAt_ = 0.0;        // and when
  Vec3 stationSeen_ = Vec3::Zero();  // where its station last was in sight
  agent::AgentCommand charge(const agent::AgentView& view, uint32_t station);
  uint32_t meetingNumber_ = 1;
  std::vector<agent::BoxView> remainder_;  // the unknown workspace: its box's parts with work
  uint32_t remainderMeeting_ = 0;          // the meeting they were computed for
  bool explorationFinished_ = false;
  std::optional<Vec3> exploreAim_;
  std::vector<Vec3> unreachable_;     // frontier clusters flown to or given up
  std::set<uint64_t> swept_;          // surface patches the detector has passed close to
  planning::DetectorModel detector_;  // its own detector (range scaled to its detectRange)
  double sweepDistance_ = 4.0;        // m, options_.sweepDistance scaled the same way
  // The detector's sweep: the box's open patches at the last plan and the viewpoints that pass
  // the detector over them, in flying order (each with the patches it was chosen for).
  struct SweepStop {
    Vec3 position = Vec3::Zero();
    Vec3 target = Vec3::Zero();
    std::vector<uint64_t> keys;  // none: a stop of the roof pass (passed once reached)
  };
  std::vector<Vec3> roofPass_;  // the roof pass's stops still to fly in the box
  std::vector<planning::InspectionPatch> openList_;
  std::vector<SweepStop> sweepRoute_;
  // s, since when features have been pending, as seen at the hand-out decisions (-1: none
  // pending at the last one)
  double heldSince_ = -1.0;
  double atStopSince_ = -1.0;  // reached the current stop then (-1: not yet)
  bool toFrontier_ = false;    // flying to a frontier viewpoint, not a sweep stop
  size_t openPatches_ = 0;     // in the box at the last plan
  size_t sweptInBox_ = 0;
  double lastPlan_ = -1e300;
  double lastHandout_ = -1e300;
  std::vector<FeatureTask> pending_;  // detected, not handed out yet
  size_t scannedInBox_ = 0;           // features detected in the current box (N_s)
  size_t inspectedInBox_ = 0;         // of those, known inspected (N_r)
  std::set<uint32_t> boxFeatures_;
  // Reported inspected by its inspectors, or whose results it carries (learnInspected).
  std::set<uint32_t> knownInspected_;
  // What the explorer knows of one of its inspectors: where it was last known to be and the
  // features it was given since (its plan, in order), from which its hover windows follow.
  struct InspectorModel {
    uint32_t unit = 0;
    uint32_t sequence = 0;  // last orders sent
    uint32_t acknowledged = 0;
    Vec3 position = Vec3::Zero();  // where it was (or will be) at `since`
    double since = 0.0;
    std::vector<FeatureTask> tasks;  // given, not known to be inspected
    // Given before a missed meeting, not known to be inspected: handed out again when the
    // inspector is presumed failed.
    std::vector<FeatureTask> unconfirmed;
    std::optional<Vec3> waitAt;  // to pass on with the next orders
    Vec3 home = Vec3::Zero();    // its wait point: where it goes with nothing to inspect
    int missed = 0;              // hand-outs in a row it was not found for
    double lostUntil = 0.0;      // not looked for before this time
    double heard = 0.0;          // its last status
    uint32_t listLeft = 0;       // features on its list by its last status
    // Results to collect from it: features given and not yet known inspected, and it is looked
    // for at `now`.
    bool toCollect(double now) const { return !tasks.empty() && lostUntil <= now; }
  };
  std::vector<InspectorModel> inspectors_;
  // A planned meeting with an inspector (SOEI): where, when, and its orders.
  struct Handout {
    size_t inspector = 0;  // index into inspectors_
    Vec3 place = Vec3::Zero();
    double time = 0.0;  // planned meeting time; given up meetingGrace after it
    Orders orders;
    bool collect = false;  // no features: to take its results once its list is done
    // The inspector's predicted place the meeting point was sampled around (SOEI's hand-outs);
    // flown towards once, when the inspector is not in link at the point (`approach_partner`).
    std::optional<Vec3> partnerAt;
    bool approached = false;
  };
  std::vector<Handout> handouts_;  // in the order they are flown
  // The hand-outs under way collect results on the way to the station (fetchOnTheWay), once per
  // station meeting (fetchedFor_, the meeting's number).
  bool fetching_ = false;
  uint32_t fetchedFor_ = 0;
  // caric-team's rule at its hub: the pending features split in equal runs of a nearest-neighbour
  // tour among the inspectors free within kMaxHandoutWait of the first one free, each met where
  // its plan ends; none when the explorer would wait long for the first while exploring remains.
  std::vector<Handout> splitAtHub(const agent::AgentView& view, bool explorationFinished) const;
  // SOEI's candidates of a mandatory hand-out: the point near where its plan ends for an
  // inspector with none sampled (points[i] for plans[i]).
  void addPlanEndPoints(const agent::AgentView& view,
                        const std::vector<planning::InspectorPlan>& plans,
                        std::vector<planning::InspectorMeetingPoints>* points) const;
  // SOEI found no meeting point and a hand-out is due: each of `plans` (the inspectors
  // inspectors_[modelOf[i]]) met where its plan ends, free soonest first, the features split
  // among them by SOEI's allocation.
  std::vector<Handout> handToEach(const agent::AgentView& view,
                                  const std::vector<planning::InspectorPlan>& plans,
                                  const std::vector<planning::PendingFeature>& features,
                                  const std::vector<size_t>& modelOf) const;
  // A meeting with inspector k for its results where its list ends (`plan`'s last pose).
  Handout collectionAt(const agent::AgentView& view, size_t k,
                       const planning::InspectorPlan& plan) const;
  // No box left and nothing pending: meet each inspector that still has features where its
  // list ends, to carry its results to the station.
  std::vector<Handout> planCollection(const agent::AgentView& view) const;
  // Those of its inspectors whose lists should be done by the time it gets to them, met on the
  // way to `to` (nearest first) while the detour stays within fetchDetour: each with its
  // predicted plan, and via them the arrival at `to` (`arrival`). Checked every step near the
  // time to leave: no map search here (collectionAt's, once the fetch is decided).
  using FetchStop = std::pair<size_t, planning::InspectorPlan>;
  double fetchedAt(const Vec3& at, double t, const Vec3& place, double ready) const;
  std::vector<FetchStop> fetchOnTheWay(const agent::AgentView& view, const Vec3& to,
                                       double* arrival) const;
  void startHandouts(std::vector<Handout> planned);
  // The inspector's hover windows as the explorer predicts them (SOEI's input).
  planning::InspectorPlan predictedPlan(const InspectorModel& model, double now,
                                        bool presumeDone = false) const;

  // Inspector.
  std::optional<uint32_t> myExplorer_;  // its subgroup's, or whoever adopted it since
  std::vector<FeatureTask> tasks_;
  std::set<uint32_t> inspected_;
  uint32_t lastOrders_ = 0;
  std::optional<Vec3> waitAt_;     // where it goes with nothing to inspect (its explorer knows)
  std::optional<Vec3> afterList_;  // where to go once the list is done (a new box)
  double retryWaitAt_ = 0.0;       // no way to the wait point found: try again then
  std::optional<double> atTaskSince_;
  // The pose it inspects the first feature of its list from: its own camera view in front of
  // the feature first, then the explorer's detection pose (taskPoseFor_: the feature it is for).
  std::optional<Vec3> taskPose_;
  int64_t taskPoseFor_ = -1;
  bool ownView_ = false;
  double lastStatus_ = -1e300;
  Vec3 ownViewpoint(const FeatureTask& task, bool* free) const;
};

void registerSlei3d(agent::StrategyRegistry& registry);

}  // namespace coinspect::strategies::slei
