// The status timeline of a feature mission (the SLEI3D paper's Fig. 12): one row per unit, the
// activity it reported over mission time as coloured segments, its meetings as markers joined
// across the two rows, and a cross where it was lost. Read from the rawlog's "activity-changed",
// "meeting" and death events (doc/features.md); `coinspect plot-timeline` draws it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/eval/image.h"
#include "coinspect/eval/run_tracks.h"

namespace coinspect::eval {

// One stretch of time (mission clock, s) in which a unit reported the same activity.
struct ActivitySpan {
  double from = 0.0, to = 0.0;
  std::string activity;  // as recorded: agent::toString(Activity), e.g. "exploring"
};

struct UnitStatus {
  std::string name;
  std::vector<ActivitySpan> spans;  // in time order, back to back; empty without activity events
  std::optional<double> lostAt;     // mission clock of its first collision, failure or death
};

// A meeting of units[a] and units[b] (a < b) at `time` on the mission clock.
struct StatusMeeting {
  double time = 0.0;
  size_t a = 0, b = 0;
};

struct StatusTimeline {
  std::vector<UnitStatus> units;  // fleet order (the run's first pose records)
  std::vector<StatusMeeting> meetings;
  double endTime = 0.0;  // mission clock at the end of the run
};

// The timeline of `tracks` on the mission clock (0 at the "start" event). Throws InputError naming
// `source` when the run has no "activity-changed" event: not a feature mission, or recorded
// before coinspect wrote them.
StatusTimeline statusTimeline(const RunTracks& tracks, const std::string& source);

// The activities a strategy can report, in legend order ("unreported" first).
const std::vector<std::string>& knownActivities();
// The colour of an activity's segments; activities this build does not know share one grey.
Rgb activityColor(const std::string& activity);
inline constexpr Rgb kMeetingMarkerColor{20, 20, 20};
inline constexpr Rgb kLostMarkerColor{215, 25, 30};

// Where the picture put things (tests locate content with it), in pixels (x right, y down).
struct StatusTimelineFrame {
  double timeLo = 0.0, timeHi = 1.0;             // the x axis (s)
  int left = 0, top = 0, right = 0, bottom = 0;  // plot area: left <= x < right, top <= y < bottom
  double rowHeight = 0.0;                        // each unit's band, from `top` in fleet order
  int legendLeft = 0, legendTop = 0, legendRight = 0, legendBottom = 0;
  double x(double time) const;
  double rowCenter(size_t unit) const;
  // Half the height of a row's bar of segments.
  double barHalfHeight() const;
};

// The picture, titled `title`: unit names left of their rows, time below, the legend (the
// activities that occur, then meeting and lost markers) right of the plot. Same input, same
// pixels.
RgbImage renderStatusTimeline(const StatusTimeline& timeline, const std::string& title, int width,
                              int height, StatusTimelineFrame* frame = nullptr);

}  // namespace coinspect::eval
