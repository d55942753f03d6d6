// The feature side of a mission with objective = features (doc/features.md): explorers' detections,
// inspectors' inspection timers, the results the robots carry and hand over at meetings, what the
// ground stations have collected, meetings, and the activity each unit reports.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/agent_view.h"
#include "coinspect/agent/commands.h"
#include "coinspect/comms/carried_data.h"
#include "coinspect/sensing/feature_detection.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sim/mission_config.h"
#include "coinspect/sim/mission_summary.h"
#include "coinspect/vehicle/vehicle_state.h"
#include "coinspect/world/scenario.h"

namespace coinspect::sim {

// Per box of the scenario, 1 when [features] priority_boxes names it. Throws InputError naming
// the key for a name that is not a box of the scenario.
std::vector<uint8_t> priorityBoxFlags(const std::vector<std::string>& names,
                                      const world::Scenario& scenario, const std::string& source);

// Per feature of the scenario, 1 when it lies in a box flagged urgent (priorityBoxFlags; empty
// when none is). Throws InputError naming the key for an urgent box that holds no feature.
std::vector<uint8_t> highPriorityFeatures(const std::vector<uint8_t>& urgentBoxes,
                                          const world::Scenario& scenario,
                                          const std::string& source);

// Per unit of the scenario's fleet, its feature detector range: explorers in fleet order from
// `ranges` (empty: `fallback` for all), 0 for the other units. Throws InputError naming the key
// when `ranges` does not hold one range per explorer.
std::vector<double> explorerDetectRanges(const std::vector<double>& ranges, double fallback,
                                         const world::Scenario& scenario,
                                         const std::string& source);

class FeatureTracker {
 public:
  // kind, unit, detail (a mission event).
  using EventSink = std::function<void(const std::string&, const std::string&, const std::string&)>;

  // highPriority: per feature, 1 when its detection reports it urgent (empty: none is). The
  // units of role GroundStation are the stations: a feature is collected when any of them
  // receives its result (the paper's several GCS), the first time only. ranges: per unit, its
  // detector range (explorerDetectRanges).
  FeatureTracker(const FeatureConfig& config, const world::InterestPointSet& features,
                 std::vector<uint8_t> highPriority, std::vector<std::string> names,
                 std::vector<agent::Role> roles, std::vector<double> ranges, EventSink sink);

  // The mission clock starts: activity time counts from here.
  void start(double time);
  // An explorer's detector at its current pose.
  void detect(size_t unit, double time, const vehicle::VehicleState& state,
              const world::RayCaster& caster);
  // An inspector's capture (scores of the points in its candidate radius).
  void capture(size_t unit, double time, const std::vector<sensing::PointScore>& scores);
  // A topology update: meetings, then one store-and-forward hop. True when the stations now hold
  // every feature between them (the first time only).
  bool exchange(double time, const comms::LinkMatrix& links, const std::vector<bool>& alive);
  // A dead unit's results are lost and its activity stops counting.
  void unitDied(size_t unit, double time);
  // The unit's command: activity and assignments. Returns the number of bad feature ids.
  size_t command(size_t unit, double time, const agent::AgentCommand& command);
  // Moves what is new for `unit` into its view.
  void fill(size_t unit, agent::AgentView& view);

  FeatureSummary summary(double now, double startTime) const;

 private:
  void addActivityTime(size_t unit, double time);
  // An explorer's promised station meeting and what became of it.
  struct Promise {
    double time = 0.0;
    bool kept = false, late = false;
    bool unlinked = false;  // not linked with a station at some update since it was made
    bool early = false;     // linked again after that, before its window
  };
  struct PromiseCounts {
    uint64_t onTime = 0, early = 0, late = 0, missed = 0, rescheduled = 0;
  };
  // Counts the promise as it stands at `now`: `replaced` by another one, or at the end of the
  // mission (a promise whose window has not closed yet is not counted).
  void settle(const Promise& promise, double now, bool replaced, PromiseCounts& counts) const;

  FeatureConfig config_;
  const world::InterestPointSet& features_;
  std::vector<uint8_t> highPriority_;  // per feature, or empty
  bool isHighPriority(size_t feature) const {
    return !highPriority_.empty() && highPriority_[feature];
  }
  std::vector<std::string> names_;
  std::vector<agent::Role> roles_;
  std::vector<double> ranges_;     // per unit: its detector range (explorers)
  sensing::FeatureSensor sensor_;  // buffer: config_.sensor with a unit's range
  size_t stations_ = 0;            // units of role GroundStation
  size_t collected_ = 0;           // features some station holds
  EventSink sink_;
  comms::CarriedData carried_;
  comms::MeetingCounter meetings_;
  std::vector<sensing::InspectionTimer> timers_;   // per unit (used for inspectors only)
  std::vector<std::vector<uint8_t>> knownByUnit_;  // per explorer: features it has detected
  std::vector<double> discoveredAt_, assignedAt_, inspectedAt_, collectedAt_;  // sim time
  std::optional<double> finishedAt_;
  uint64_t meetingsGcsExplorer_ = 0, meetingsExplorerInspector_ = 0, meetingsOther_ = 0;
  std::vector<std::optional<Promise>> promises_;  // per unit: the current one
  PromiseCounts settled_;                         // promises replaced so far
  // Per unit.
  std::vector<std::vector<agent::FeatureView>> pendingDetections_;
  std::vector<std::vector<uint32_t>> pendingInspected_, pendingReceived_;
  std::vector<size_t> detectedCount_, inspectedCount_;
  std::vector<agent::Activity> activity_;
  std::vector<double> activitySince_;
  std::vector<uint8_t> counting_;  // alive and the mission clock runs
  std::vector<std::array<double, agent::kActivityCount>> activitySeconds_;
  // Buffers.
  std::vector<uint32_t> found_, counted_, completed_;
};

}  // namespace coinspect::sim
