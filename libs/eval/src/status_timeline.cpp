// The status timeline's content: activity spans, meetings and losses on the mission clock, from
// a run's events. The picture is drawn in status_timeline_plot.cpp.
#include "coinspect/eval/status_timeline.h"

#include <algorithm>

#include "coinspect/core/error.h"
#include "coinspect/record/observations.h"

namespace coinspect::eval {

namespace {

using Kind = record::MissionEventKind;

// Rows in fleet order: the units of the pose records, then any unit only events name (a unit
// recorded without ground truth still gets its row).
class Rows {
 public:
  explicit Rows(const RunTracks& tracks) {
    for (const auto& unit : tracks.units)
      indexOf(unit.name);
  }
  size_t indexOf(const std::string& name) {
    for (size_t i = 0; i < units.size(); ++i)
      if (units[i].name == name) return i;
    units.push_back(UnitStatus{name, {}, std::nullopt});
    return units.size() - 1;
  }
  std::vector<UnitStatus> units;
};

// Ends the unit's spans at `end` (its loss or the end of the run): what it reported after that
// is dropped, and a span left without length too.
void closeSpans(UnitStatus& unit, double end) {
  auto& spans = unit.spans;
  spans.erase(std::remove_if(spans.begin(), spans.end(),
                             [end](const ActivitySpan& span) { return span.from >= end; }),
              spans.end());
  if (!spans.empty()) spans.back().to = end;
}

}  // namespace

StatusTimeline statusTimeline(const RunTracks& tracks, const std::string& source) {
  std::optional<double> start, end, firstActivity;
  for (const auto& event : tracks.events) {
    if (event.kind == Kind::Start && !start) start = event.time;
    if (event.kind == Kind::End && !end) end = event.time;
    if (event.kind == Kind::ActivityChanged && !firstActivity) firstActivity = event.time;
  }
  if (!firstActivity)
    throw InputError(source, "",
                     "no activity-changed event: not the rawlog of a feature mission (objective = "
                     "features), or recorded before coinspect recorded activities");
  // Without a start event (a damaged or hand-made rawlog) the first activity starts the clock.
  const double origin = start ? *start : *firstActivity;
  const auto clock = [origin](double time) { return std::max(0.0, time - origin); };

  StatusTimeline timeline;
  timeline.endTime = clock(end ? *end : tracks.endTime);
  Rows rows(tracks);
  for (const auto& event : tracks.events) {
    if (event.unit.empty()) continue;
    const double t = clock(event.time);
    timeline.endTime = std::max(timeline.endTime, t);
    if (event.kind == Kind::ActivityChanged) {
      auto& spans = rows.units[rows.indexOf(event.unit)].spans;
      if (!spans.empty() && spans.back().activity == event.detail) continue;
      if (!spans.empty()) spans.back().to = t;
      // Two reports at one instant: the later one is what the unit was doing.
      if (!spans.empty() && spans.back().from == t) spans.pop_back();
      if (!spans.empty() && spans.back().activity == event.detail) continue;  // goes on
      spans.push_back(ActivitySpan{t, t, event.detail});
    } else if (event.kind == Kind::Meeting) {
      const size_t a = rows.indexOf(event.unit), b = rows.indexOf(event.detail);
      if (a != b) timeline.meetings.push_back(StatusMeeting{t, std::min(a, b), std::max(a, b)});
    } else if (isDeathEvent(event.kind)) {
      auto& unit = rows.units[rows.indexOf(event.unit)];
      if (!unit.lostAt) unit.lostAt = t;
    }
  }
  for (auto& unit : rows.units)
    closeSpans(unit, unit.lostAt ? *unit.lostAt : timeline.endTime);
  timeline.units = std::move(rows.units);
  return timeline;
}

const std::vector<std::string>& knownActivities() {
  // agent::toString(Activity) of every Activity (eval does not depend on agent; a test checks
  // that the two lists agree).
  static const std::vector<std::string> names = {
      "unreported", "exploring", "inspecting", "travelling-to-meeting", "waiting", "returning"};
  return names;
}

Rgb activityColor(const std::string& activity) {
  // Light grey for "nothing said", then hues far apart; none is the meeting marker's near-black
  // or the lost marker's red.
  static const std::vector<Rgb> colors = {{200, 200, 200}, {45, 110, 200}, {40, 160, 70},
                                          {245, 150, 20},  {240, 210, 40}, {150, 80, 180}};
  const auto& names = knownActivities();
  const auto it = std::find(names.begin(), names.end(), activity);
  return it == names.end() ? Rgb{120, 120, 120} : colors[static_cast<size_t>(it - names.begin())];
}

}  // namespace coinspect::eval
