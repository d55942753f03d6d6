// MVRP: round-robin nearest-neighbour allocation of pending features (see meeting_allocation.h).
#include "coinspect/planning/meeting_allocation.h"

#include <algorithm>
#include <limits>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::planning {

namespace {

void validateAllocation(const std::vector<InspectorPlan>& inspectors, const std::vector<int>& met,
                        const std::vector<double>& meetingTimes, const AllocationModel& model) {
  const char* const source = "feature allocation";
  if (met.empty()) throw InputError(source, "met", "no inspector is met");
  if (meetingTimes.size() != met.size()) {
    throw InputError(source, "meetingTimes",
                     std::to_string(meetingTimes.size()) + " times for " +
                         std::to_string(met.size()) + " inspectors");
  }
  std::vector<bool> seen(inspectors.size(), false);
  for (const int index : met) {
    if (index < 0 || index >= static_cast<int>(inspectors.size()) || seen[index]) {
      throw InputError(source, "met",
                       "inspector " + std::to_string(index) + " is out of range or repeated");
    }
    seen[index] = true;
  }
  for (size_t i = 0; i < inspectors.size(); ++i) {
    if (inspectors[i].poses.empty())
      throw InputError(source, "inspector " + std::to_string(i), "has no planned pose");
  }
  if (!(model.inspectionTime >= 0.0)) {
    throw InputError(source, "inspectionTime",
                     std::to_string(model.inspectionTime) + " is negative");
  }
  if (!(model.inspector.speed > 0.0 && model.inspector.acceleration > 0.0))
    throw InputError(source, "inspector", "speed and acceleration must be positive");
}

}  // namespace

double idleFrom(const InspectorPlan& inspector, double now, double inspectionTime) {
  return std::max(now, inspector.poses.back().start + inspectionTime);
}

FeatureAllocation allocateFeatures(const std::vector<InspectorPlan>& inspectors,
                                   const std::vector<int>& met,
                                   const std::vector<double>& meetingTimes,
                                   const std::vector<PendingFeature>& features, double now,
                                   const AllocationModel& model) {
  validateAllocation(inspectors, met, meetingTimes, model);
  for (size_t f = 0; f < features.size(); ++f) {
    if (!features[f].inspectFrom.allFinite()) {
      throw InputError("feature allocation", "feature " + std::to_string(f),
                       "its inspection pose is not finite");
    }
  }
  FeatureAllocation allocation;
  std::vector<Vec3> at;  // where each agent is
  for (size_t a = 0; a < met.size(); ++a) {
    const InspectorPlan& inspector = inspectors[met[a]];
    InspectorAssignment agent;
    agent.inspector = met[a];
    agent.startTime =
        std::max(meetingTimes[a], inspector.poses.back().start + model.inspectionTime);
    agent.finishTime = agent.startTime;
    allocation.agents.push_back(agent);
    at.push_back(inspector.poses.back().position);
  }

  std::vector<bool> taken(features.size(), false);
  size_t left = features.size();
  size_t urgentLeft = static_cast<size_t>(std::count_if(
      features.begin(), features.end(), [](const auto& f) { return f.highPriority; }));
  for (size_t turn = 0; left > 0; turn = (turn + 1) % met.size()) {
    InspectorAssignment& agent = allocation.agents[turn];
    size_t nearest = features.size();
    double nearestDistance = std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < features.size(); ++f) {
      if (taken[f] || (urgentLeft > 0 && !features[f].highPriority)) continue;
      const double distance = (features[f].inspectFrom - at[turn]).norm();
      if (distance < nearestDistance) {
        nearestDistance = distance;
        nearest = f;
      }
    }
    const double travel = travelTime(nearestDistance, model.inspector);
    agent.travelTime += travel;
    agent.finishTime += travel + model.inspectionTime;
    agent.features.push_back(static_cast<int>(nearest));
    at[turn] = features[nearest].inspectFrom;
    taken[nearest] = true;
    --left;
    if (features[nearest].highPriority) --urgentLeft;
  }

  allocation.rightAxis = allocation.agents.front().finishTime;
  for (const InspectorAssignment& agent : allocation.agents)
    allocation.rightAxis = std::max(allocation.rightAxis, agent.finishTime);
  for (const InspectorAssignment& agent : allocation.agents)
    allocation.agentCost += agent.travelTime + (allocation.rightAxis - agent.finishTime);
  std::vector<bool> isMet(inspectors.size(), false);
  for (const int index : met)
    isMet[index] = true;
  for (size_t i = 0; i < inspectors.size(); ++i) {
    if (isMet[i]) continue;
    const double idle = idleFrom(inspectors[i], now, model.inspectionTime);
    allocation.othersCost += std::max(0.0, allocation.rightAxis - idle);
  }
  return allocation;
}

}  // namespace coinspect::planning
