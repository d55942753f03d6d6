// The status timeline (the SLEI3D paper's Fig. 12) of a hand-written feature-mission rawlog: its
// spans, meetings and losses on the mission clock, and where the picture puts them.
#include "coinspect/eval/status_timeline.h"

#include <gtest/gtest.h>

#include "coinspect/agent/commands.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "pixel_count.h"
#include "synthetic_run.h"

namespace coinspect::eval {
namespace {

using record::MissionEventKind;
using test::countIn;
using test::countNear;

constexpr long long kTicksPerSecond = 400;  // test::kStep = 2.5 ms
constexpr double kStart = 2.0;              // simulated time of the mission clock's 0 (s)

long long tickAt(double missionTime) {
  return static_cast<long long>((missionTime + kStart) * kTicksPerSecond);
}

// Units gcs, a, b (fleet order). On the mission clock: gcs waits throughout; a explores, travels
// to a meeting from 10 s, returns from 18 s; b inspects until it dies at 40 s; gcs meets b at
// 30 s (across a's row); the run ends at 50 s.
RunTracks writeFeatureRun(const std::string& name) {
  const auto path = testing::scratchDir("status_timeline_" + name) / "run.rawlog";
  const auto scenario = test::wallScenario();
  test::SyntheticRun run(path, scenario, sensing::ScoringMode::Caric);
  for (const char* unit : {"gcs", "a", "b"})
    run.pose(0, unit);
  // Reported before the clock starts: not part of the timeline (the mission writes none).
  run.event(tickAt(0.0), MissionEventKind::Start, "a", "take-off");
  run.event(tickAt(0.0), MissionEventKind::ActivityChanged, "gcs", "waiting");
  run.event(tickAt(0.0), MissionEventKind::ActivityChanged, "a", "exploring");
  run.event(tickAt(0.0), MissionEventKind::ActivityChanged, "b", "inspecting");
  run.event(tickAt(10.0), MissionEventKind::ActivityChanged, "a", "travelling-to-meeting");
  run.event(tickAt(18.0), MissionEventKind::ActivityChanged, "a", "returning");
  run.event(tickAt(30.0), MissionEventKind::Meeting, "gcs", "b");
  run.death(tickAt(40.0), "b");
  run.end(tickAt(50.0));
  return readRunTracks(path);
}

TEST(StatusTimeline, SpansMeetingsAndLossesOnTheMissionClock) {
  const StatusTimeline timeline = statusTimeline(writeFeatureRun("spans"), "run.rawlog");
  EXPECT_NEAR(timeline.endTime, 50.0, 1e-9);
  ASSERT_EQ(timeline.units.size(), 3u);
  EXPECT_EQ(timeline.units[0].name, "gcs");
  EXPECT_EQ(timeline.units[1].name, "a");
  EXPECT_EQ(timeline.units[2].name, "b");
  const auto& a = timeline.units[1].spans;
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].activity, "exploring");
  EXPECT_NEAR(a[0].from, 0.0, 1e-9);
  EXPECT_NEAR(a[0].to, 10.0, 1e-9);
  EXPECT_EQ(a[1].activity, "travelling-to-meeting");
  EXPECT_NEAR(a[1].to, 18.0, 1e-9);
  EXPECT_EQ(a[2].activity, "returning");
  EXPECT_NEAR(a[2].to, 50.0, 1e-9);
  const auto& b = timeline.units[2];
  ASSERT_EQ(b.spans.size(), 1u);
  EXPECT_NEAR(b.spans[0].to, 40.0, 1e-9);  // cut at its death
  ASSERT_TRUE(b.lostAt);
  EXPECT_NEAR(*b.lostAt, 40.0, 1e-9);
  EXPECT_FALSE(timeline.units[1].lostAt);
  ASSERT_EQ(timeline.meetings.size(), 1u);
  EXPECT_NEAR(timeline.meetings[0].time, 30.0, 1e-9);
  EXPECT_EQ(timeline.meetings[0].a, 0u);
  EXPECT_EQ(timeline.meetings[0].b, 2u);
}

TEST(StatusTimeline, EachActivityIsDrawnInItsRowOverItsTimeSpan) {
  const StatusTimeline timeline = statusTimeline(writeFeatureRun("picture"), "run.rawlog");
  StatusTimelineFrame frame;
  const RgbImage image = renderStatusTimeline(timeline, "status", 600, 400, &frame);
  ASSERT_EQ(image.width(), 600);
  ASSERT_EQ(image.height(), 400);
  EXPECT_NEAR(frame.timeLo, 0.0, 1e-9);
  EXPECT_NEAR(frame.timeHi, 50.0, 1e-9);
  const int half = static_cast<int>(frame.barHalfHeight()) - 1;
  ASSERT_GE(half, 2);
  // Pixels of `activity` in row `unit` between two mission times, and the most there can be.
  const auto inRow = [&](size_t unit, double from, double to, const std::string& activity) {
    const int y = static_cast<int>(frame.rowCenter(unit));
    return countIn(image, static_cast<int>(frame.x(from)), y - half, static_cast<int>(frame.x(to)),
                   y + half, activityColor(activity));
  };
  const auto area = [&](double from, double to) {
    return (static_cast<int>(frame.x(to)) - static_cast<int>(frame.x(from))) * 2 * half;
  };
  // a: exploring, travelling, returning, each over its own span only.
  EXPECT_EQ(inRow(1, 1.0, 9.0, "exploring"), area(1.0, 9.0));
  EXPECT_EQ(inRow(1, 11.0, 17.0, "travelling-to-meeting"), area(11.0, 17.0));
  EXPECT_EQ(inRow(1, 19.0, 28.0, "returning"), area(19.0, 28.0));
  EXPECT_EQ(inRow(1, 11.0, 50.0, "exploring"), 0);
  EXPECT_EQ(inRow(1, 0.0, 17.0, "returning"), 0);
  // The colours differ, and no other row has a's activities.
  EXPECT_FALSE(activityColor("exploring") == activityColor("returning"));
  EXPECT_EQ(inRow(0, 0.0, 50.0, "exploring") + inRow(2, 0.0, 50.0, "exploring"), 0);
  // (Away from the meeting's markers, drawn over the bars at 30 s.)
  EXPECT_EQ(inRow(0, 1.0, 26.0, "waiting"), area(1.0, 26.0));
  EXPECT_GT(inRow(0, 34.0, 49.0, "waiting"), 0);
  // b inspects up to its death, then nothing; a cross marks the death.
  EXPECT_EQ(inRow(2, 1.0, 26.0, "inspecting"), area(1.0, 26.0));
  EXPECT_EQ(inRow(2, 43.0, 50.0, "inspecting"), 0);
  EXPECT_GT(countNear(image, frame.x(40.0), frame.rowCenter(2), 3, kLostMarkerColor), 4);
  EXPECT_EQ(countIn(image, 0, 0, frame.right, static_cast<int>(frame.top + 2 * frame.rowHeight),
                    kLostMarkerColor),
            0);
  // The meeting: a marker on gcs's and b's rows at 30 s, joined across a's row; nothing else.
  const Rgb meeting = kMeetingMarkerColor;
  EXPECT_GT(countNear(image, frame.x(30.0), frame.rowCenter(0), 2, meeting), 8);
  EXPECT_GT(countNear(image, frame.x(30.0), frame.rowCenter(2), 2, meeting), 8);
  EXPECT_GT(countNear(image, frame.x(30.0), frame.rowCenter(1), 1, meeting), 0);
  EXPECT_LE(countNear(image, frame.x(30.0), frame.rowCenter(1), 3, meeting), 7);  // a thin line
  EXPECT_EQ(
      countIn(image, frame.left, frame.top, static_cast<int>(frame.x(27.0)), frame.bottom, meeting),
      0);
  EXPECT_EQ(countIn(image, static_cast<int>(frame.x(33.0)), frame.top, frame.right, frame.bottom,
                    meeting),
            0);
}

TEST(StatusTimeline, LegendShowsTheRunsActivitiesAndMarkers) {
  const StatusTimeline timeline = statusTimeline(writeFeatureRun("legend"), "run.rawlog");
  StatusTimelineFrame frame;
  const RgbImage image = renderStatusTimeline(timeline, "status", 600, 400, &frame);
  EXPECT_GE(frame.legendLeft, frame.right);
  EXPECT_LE(frame.legendRight, image.width());
  const auto inLegend = [&](Rgb color) {
    return countIn(image, frame.legendLeft, frame.legendTop, frame.legendRight, frame.legendBottom,
                   color);
  };
  for (const char* activity :
       {"exploring", "inspecting", "travelling-to-meeting", "waiting", "returning"})
    EXPECT_GT(inLegend(activityColor(activity)), 20) << activity;
  EXPECT_EQ(inLegend(activityColor("unreported")), 0);  // not in this run
  EXPECT_GT(inLegend(kMeetingMarkerColor), 5);
  EXPECT_GT(inLegend(kLostMarkerColor), 5);
  // The unit names, left of their rows.
  const Rgb text{35, 35, 35};
  for (size_t unit = 0; unit < 3; ++unit) {
    const int y = static_cast<int>(frame.rowCenter(unit));
    EXPECT_GT(countIn(image, 0, y - 6, frame.left, y + 6, text), 5) << unit;
  }
}

TEST(StatusTimeline, ARunWithoutActivityEventsIsAnErrorNamingTheSource) {
  const auto path = testing::scratchDir("status_timeline_none") / "run.rawlog";
  const auto scenario = test::wallScenario();
  {
    test::SyntheticRun run(path, scenario, sensing::ScoringMode::Caric);
    run.pose(0, "a");
    run.event(0, MissionEventKind::Start, "a", "take-off");
    run.end(100);
  }
  const RunTracks tracks = readRunTracks(path);
  const std::string message =
      testing::messageOf([&] { statusTimeline(tracks, "somewhere/run.rawlog"); });
  EXPECT_MENTIONS(message, "somewhere/run.rawlog");
  EXPECT_MENTIONS(message, "no activity-changed event");
}

// eval keeps its own list of the activity names (it does not depend on agent): the same as
// agent::toString, in the enum's order.
TEST(StatusTimeline, KnownActivitiesAreTheAgentsActivityNames) {
  const std::vector<agent::Activity> all = {
      agent::Activity::Unreported,          agent::Activity::Exploring, agent::Activity::Inspecting,
      agent::Activity::TravellingToMeeting, agent::Activity::Waiting,   agent::Activity::Returning};
  ASSERT_EQ(static_cast<int>(all.size()), agent::kActivityCount);
  ASSERT_EQ(knownActivities().size(), all.size());
  for (size_t i = 0; i < all.size(); ++i)
    EXPECT_EQ(knownActivities()[i], agent::toString(all[i]));
}

}  // namespace
}  // namespace coinspect::eval
