// What an explorer expects of one of its inspectors between their meetings (SOEI's hover windows,
// doc/strategies.md "Hand-outs (SOEI)"), and where it looks for an inspector that is not at a
// hand-out's meeting point: pure functions of what the explorer knows.
#pragma once

#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/planning/meeting_route.h"

namespace coinspect::strategies::slei {

using agent::Vec3;

// The inspector as its explorer last heard of it.
struct InspectorForecast {
  int id = 0;                    // copied into the plan
  Vec3 position = Vec3::Zero();  // where it was (or was to be) at `since`
  double since = 0.0;            // s
  std::vector<Vec3> poses;       // the features it was given and has not reported, in order
  Vec3 home = Vec3::Zero();      // its wait point, where it goes once its list is done
};

struct ForecastModel {
  double speed = 2.0;           // m/s
  double travelFactor = 1.5;    // paths are this much longer than straight lines
  double inspectionTime = 3.0;  // s at a pose (t_q) ...
  double settle = 2.0;          // s ... and the time it needs beyond that
  // A listed pose whose predicted end is already past is presumed done (its status is still to
  // come), and the list timed from `since`. Off: every listed pose lies ahead, from now on.
  bool presumeDone = false;
};

// Its hover windows from `now`: one per listed pose still ahead, then its wait point for good.
planning::InspectorPlan forecastInspector(const InspectorForecast& inspector, double now,
                                          const ForecastModel& model);

// Where an explorer at `here` flies on to when the inspector it came to meet is not in link:
// `stop` metres short of where the inspector was expected; `here` when it is that close already.
Vec3 approachPoint(const Vec3& here, const Vec3& expected, double stop);

}  // namespace coinspect::strategies::slei
