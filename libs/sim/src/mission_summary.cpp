#include "coinspect/sim/mission_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "mission_impl.h"

namespace coinspect::sim {

namespace {

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

MissionSummary Mission::summary() const {
  const auto& impl = *impl_;
  MissionSummary out;
  out.scenario = impl.scenario.name;
  out.strategy = impl.config.strategy;
  out.seed = impl.config.seed;
  out.scoring = sensing::toString(impl.config.scoring);
  out.score = impl.tally.totalScore();
  out.detected = impl.tally.detectedCount();
  out.totalPoints = impl.scenario.interestPoints.size();
  for (const auto& unit : impl.units) {
    UnitSummary u;
    u.name = unit.spec->name;
    u.role = agent::toString(unit.role);
    u.alive = unit.alive();
    u.deathCause = unit.deathCause;
    u.distanceFlown = unit.distanceFlown;
    u.captures = unit.captures;
    u.detected = unit.log.detectedCount();
    u.ownScore = unit.ownScore;
    if (unit.battery.limited()) u.lowestEnergy = unit.lowestEnergy;
    u.chargedFor = unit.chargedFor;
    u.rejectedCommands =
        (unit.vehicle ? unit.vehicle->rejectedCommands() : unit.ground->rejectedCommands()) +
        unit.badFeatureIds;
    out.rejectedCommands += u.rejectedCommands;
    out.deaths += u.alive ? 0 : 1;
    out.units.push_back(u);
  }
  out.collisions = static_cast<size_t>(impl.collisionDeaths);
  const auto totals = impl.network->totals();
  out.messagesSent = totals.sentMessages + impl.misaddressed;
  out.messagesDelivered = totals.deliveredMessages;
  out.messagesDropped = totals.droppedMessages + impl.misaddressed;
  out.keyFrames = impl.keyFrameCount;
  out.keyFramesDelivered = impl.exchange->deliveryCount();
  out.started = impl.started;
  out.startTime = impl.startTime;
  out.missionTime = impl.started ? impl.now() - impl.startTime : 0.0;
  out.budget = impl.budget;
  out.simTime = impl.now();
  out.wallTime = impl.wallTime;
  out.stages = impl.stages;
  out.runMode = toString(impl.config.runMode);
  out.requestedRealtimeFactor = impl.config.realtimeFactor;
  out.threads = impl.workers ? impl.workers->threads() : 1;
  out.decisionTimes = impl.decisionTimes;
  if (impl.features)
    out.features = impl.features->summary(impl.now(), impl.started ? impl.startTime : impl.now());
  return out;
}

double DecisionTimes::quantile(double q) const {
  if (samples.empty()) return 0.0;
  std::vector<float> sorted = samples;
  const size_t rank = std::min(
      sorted.size() - 1,
      static_cast<size_t>(std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(sorted.size()))) -
          (q > 0.0 ? 1 : 0));
  std::nth_element(sorted.begin(), sorted.begin() + rank, sorted.end());
  return sorted[rank];
}

std::string formatSummary(const MissionSummary& s) {
  std::string out;
  char line[512];
  const auto add = [&](const char* format, auto... args) {
    std::snprintf(line, sizeof line, format, args...);
    out += line;
  };
  add("mission     %s, strategy %s, seed %llu, scoring %s\n", s.scenario.c_str(),
      s.strategy.c_str(), static_cast<unsigned long long>(s.seed), s.scoring.c_str());
  add("score       Q = %.2f\n", s.score);
  add("detected    %zu / %zu interest points (%.1f %%)\n", s.detected, s.totalPoints,
      s.totalPoints ? 100.0 * s.detected / s.totalPoints : 0.0);
  add("collisions  %zu (deaths %zu)\n", s.collisions, s.deaths);
  if (s.features.enabled) {
    const auto& f = s.features;
    add("features    %zu: discovered %zu, assigned %zu, inspected %zu, collected %zu "
        "(finish rate %.1f %%)%s\n",
        f.total, f.discovered, f.assigned, f.inspected, f.collected, 100.0 * f.finishRate(),
        f.finishTime ? (", all collected at " + fixed(*f.finishTime, 2) + " s").c_str() : "");
    if (f.priorityTotal > 0)
      add("priority    %zu high-priority features: collected %zu%s\n", f.priorityTotal,
          f.priorityCollected,
          f.priorityFinishTime ? (", all at " + fixed(*f.priorityFinishTime, 2) + " s").c_str()
                               : "");
    add("meetings    gcs-explorer %llu, explorer-inspector %llu, other %llu\n",
        static_cast<unsigned long long>(f.meetingsGcsExplorer),
        static_cast<unsigned long long>(f.meetingsExplorerInspector),
        static_cast<unsigned long long>(f.meetingsOther));
    add("punctuality explorers' promised station meetings: on time %llu, early %llu, late %llu, "
        "missed %llu, rescheduled %llu\n",
        static_cast<unsigned long long>(f.promisesOnTime),
        static_cast<unsigned long long>(f.promisesEarly),
        static_cast<unsigned long long>(f.promisesLate),
        static_cast<unsigned long long>(f.promisesMissed),
        static_cast<unsigned long long>(f.promisesRescheduled));
  }
  double distance = 0.0;
  for (const auto& u : s.units)
    if (u.role != "gcs") distance += u.distanceFlown;  // a ground station drives
  add("distance    %.1f m flown in total\n", distance);
  for (const auto& u : s.units) {
    if (u.role == "gcs") continue;
    char battery[96] = "";
    if (u.lowestEnergy)
      std::snprintf(battery, sizeof battery, ", battery lowest %.0f %%, charged %.0f s",
                    100.0 * *u.lowestEnergy, u.chargedFor);
    add("  %-10s %-12s %8.1f m, %5zu captures, own log %5zu points %9.2f%s%s%s\n", u.name.c_str(),
        u.role.c_str(), u.distanceFlown, u.captures, u.detected, u.ownScore, battery,
        u.alive ? "" : ", dead: ", u.deathCause.c_str());
  }
  add("messages    sent %llu, delivered %llu, dropped %llu; key frames %llu, delivered %llu\n",
      static_cast<unsigned long long>(s.messagesSent),
      static_cast<unsigned long long>(s.messagesDelivered),
      static_cast<unsigned long long>(s.messagesDropped),
      static_cast<unsigned long long>(s.keyFrames),
      static_cast<unsigned long long>(s.keyFramesDelivered));
  add("commands    rejected %lld\n", s.rejectedCommands);
  if (s.started)
    add("clock       started at %.3f s, mission time %.2f s of %.0f s\n", s.startTime,
        s.missionTime, s.budget);
  else
    add("clock       never started (no take-off)\n");
  add("sim time    %.2f s\n", s.simTime);
  add("wall time   %.2f s on %zu thread%s\n", s.wallTime, s.threads, s.threads == 1 ? "" : "s");
  add("real-time factor %.1fx\n", s.realTimeFactor());
  const auto& t = s.stages;
  add("stages      physics %.2f s, lidar %.2f s, topology %.2f s, scoring %.2f s, strategies "
      "%.2f s, collisions %.2f s%s\n",
      t.physics, t.lidar, t.topology, t.scoring, t.decisions, t.collisions,
      s.runMode == "realtime" ? (", pacing " + fixed(t.pacing, 2) + " s").c_str() : "");
  const auto& d = s.decisionTimes;
  add("decisions   %llu, compute time per decision p50 %.3f ms, p95 %.3f ms, max %.3f ms\n",
      static_cast<unsigned long long>(d.count), 1e3 * d.quantile(0.5), 1e3 * d.quantile(0.95),
      1e3 * d.max);
  if (s.runMode == "latency")
    add("run mode    latency: each command delayed by its decision's compute time (mean %.3f ms, "
        "max %.3f ms over %llu decisions); not deterministic\n",
        1e3 * d.mean(), 1e3 * d.max, static_cast<unsigned long long>(d.count));
  else if (s.runMode == "realtime")
    add("run mode    realtime at %gx requested, %.2fx achieved\n", s.requestedRealtimeFactor,
        s.realTimeFactor());
  else
    add("run mode    lockstep\n");
  return out;
}

}  // namespace coinspect::sim
