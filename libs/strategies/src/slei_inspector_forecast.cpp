// An explorer's forecast of an inspector's hover windows, and its approach to a missing one.
#include "coinspect/strategies/slei/inspector_forecast.h"

#include <algorithm>

namespace coinspect::strategies::slei {

planning::InspectorPlan forecastInspector(const InspectorForecast& inspector, double now,
                                          const ForecastModel& model) {
  const auto travel = [&](const Vec3& a, const Vec3& b) {
    return model.travelFactor * (a - b).norm() / model.speed;
  };
  const auto hoverEnd = [&](double start) { return start + model.inspectionTime + model.settle; };
  planning::InspectorPlan plan;
  plan.id = inspector.id;
  double t = model.presumeDone ? inspector.since : std::max(now, inspector.since);
  Vec3 at = inspector.position;
  for (const Vec3& pose : inspector.poses) {
    const double arrival = t + travel(at, pose);
    if (model.presumeDone && hoverEnd(arrival) < now) {
      t = hoverEnd(arrival);  // presumed done
    } else {
      const double start = std::max(now, arrival);
      plan.poses.push_back({pose, start, hoverEnd(start)});
      t = hoverEnd(start);
    }
    at = pose;
  }
  plan.poses.push_back(
      {inspector.home, std::max(now, t + travel(at, inspector.home)), planning::kOpenWindowEnd});
  return plan;
}

Vec3 approachPoint(const Vec3& here, const Vec3& expected, double stop) {
  const Vec3 towards = expected - here;
  const double distance = towards.norm();
  if (distance <= stop) return here;
  return here + towards * ((distance - stop) / distance);
}

}  // namespace coinspect::strategies::slei
