#include "coinspect/eval/run_tracks.h"

#include <mrpt/obs/CObservationRobotPose.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "coinspect/core/error.h"
#include "coinspect/record/observations.h"

namespace coinspect::eval {

namespace {

const std::string kPoseSuffix = ".pose";

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

double wrapAngle(double angle) {
  return std::remainder(angle, 2.0 * M_PI);
}

}  // namespace

int RunTracks::unitIndex(const std::string& name) const {
  for (size_t i = 0; i < units.size(); ++i)
    if (units[i].name == name) return static_cast<int>(i);
  return -1;
}

RunTracks readRunTracks(const std::filesystem::path& rawlog, double latestTime) {
  record::RawlogReader reader(rawlog);
  reader.setLatestTime(latestTime);
  RunTracks tracks;
  tracks.header = reader.header();
  std::map<std::string, size_t> unitByName;
  std::shared_ptr<mrpt::obs::CObservation> observation;
  while (reader.next(observation)) {
    const double time = mrpt::Clock::toDouble(observation->timestamp);
    tracks.endTime = std::max(tracks.endTime, time);
    if (const auto* pose = dynamic_cast<const mrpt::obs::CObservationRobotPose*>(observation.get());
        pose && endsWith(pose->sensorLabel, kPoseSuffix)) {
      const std::string name =
          pose->sensorLabel.substr(0, pose->sensorLabel.size() - kPoseSuffix.size());
      auto [it, added] = unitByName.emplace(name, tracks.units.size());
      if (added) tracks.units.push_back(UnitTrack{name, {}, std::nullopt, {}});
      const auto& mean = pose->pose.mean;
      // The pictures fit their view to the poses: an infinite one broke MRPT's projection.
      for (const double value :
           {mean.x(), mean.y(), mean.z(), mean.yaw(), mean.pitch(), mean.roll()})
        if (!std::isfinite(value))
          throw InputError(rawlog.string(), pose->sensorLabel + " at t = " + std::to_string(time),
                           "the pose is not finite");
      tracks.units[it->second].poses.push_back(PoseSample{
          time, world::Vec3(mean.x(), mean.y(), mean.z()), mean.yaw(), mean.pitch(), mean.roll()});
    } else if (const auto* tally =
                   dynamic_cast<const record::CObservationCoinspectTally*>(observation.get())) {
      tracks.pointCount = std::max<uint64_t>(tracks.pointCount, tally->pointCount);
      for (const auto& change : tally->changes) {
        if (change.index >= tracks.pointCount)
          throw InputError(rawlog.string(), "gcs.tally at t = " + std::to_string(time),
                           "point index " + std::to_string(change.index) +
                               " beyond the point count " + std::to_string(tally->pointCount));
        // Grown to the indices met, not to the recorded count: a damaged count asked for 10^12.
        if (tracks.finalValues.size() <= change.index)
          tracks.finalValues.resize(change.index + 1, 0.0);
        tracks.finalValues[change.index] = change.value;
        tracks.tallyChanges.push_back(TallyChange{time, change.index, change.value});
      }
      tracks.tally.push_back(TallySample{time, tally->totalScore, tally->detected});
    } else if (const auto* event =
                   dynamic_cast<const record::CObservationCoinspectEvent*>(observation.get())) {
      tracks.events.push_back(RunEvent{time, event->kind, event->unit, event->detail});
    }
  }
  tracks.status = reader.status();
  tracks.objects = reader.status().objects;

  // Death times: events may name units before (or without) any pose record.
  for (const auto& event : tracks.events) {
    if (!isDeathEvent(event.kind) || event.unit.empty()) continue;
    const int index = tracks.unitIndex(event.unit);
    if (index < 0 || tracks.units[index].deathTime) continue;
    auto& unit = tracks.units[index];
    unit.deathTime = event.time;
    unit.deathCause = eventKindName(event.kind) + (event.detail.empty() ? "" : ": " + event.detail);
  }
  return tracks;
}

PoseSample poseAt(const UnitTrack& track, double t) {
  COINSPECT_ASSERT(!track.poses.empty());
  const auto& poses = track.poses;
  if (t <= poses.front().time) return poses.front();
  if (t >= poses.back().time) return poses.back();
  const auto after =
      std::upper_bound(poses.begin(), poses.end(), t,
                       [](double time, const PoseSample& s) { return time < s.time; });
  const PoseSample& b = *after;
  const PoseSample& a = *(after - 1);
  const double span = b.time - a.time;
  const double f = span > 0.0 ? (t - a.time) / span : 0.0;
  PoseSample out;
  out.time = t;
  out.position = a.position + f * (b.position - a.position);
  out.yaw = wrapAngle(a.yaw + f * wrapAngle(b.yaw - a.yaw));
  out.pitch = a.pitch + f * (b.pitch - a.pitch);
  out.roll = a.roll + f * wrapAngle(b.roll - a.roll);
  return out;
}

std::string eventKindName(record::MissionEventKind kind) {
  return record::toString(kind);
}

bool isDeathEvent(record::MissionEventKind kind) {
  using K = record::MissionEventKind;
  return kind == K::Collision || kind == K::Failure || kind == K::Death;
}

}  // namespace coinspect::eval
