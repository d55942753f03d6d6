// The evaluation loop: one pass over the rawlog in its recorded order (the mission's tick order,
// doc/evaluation.md), constant memory apart from the per-unit logs.
#include "coinspect/eval/evaluate_run.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "coinspect/core/error.h"
#include "coinspect/record/observations.h"
#include "tally_replay.h"

namespace coinspect::eval {

namespace {

sensing::CaptureState captureState(const record::CObservationCoinspectCapture& c) {
  sensing::CaptureState state;
  state.position = {c.bodyPosition[0], c.bodyPosition[1], c.bodyPosition[2]};
  state.yaw = c.bodyYaw;
  state.pitch = c.bodyPitch;
  state.roll = c.bodyRoll;
  state.linearVelocity = {c.linearVelocity[0], c.linearVelocity[1], c.linearVelocity[2]};
  state.angularVelocity = {c.angularVelocity[0], c.angularVelocity[1], c.angularVelocity[2]};
  state.gimbalYaw = c.gimbalYaw;
  state.gimbalPitch = c.gimbalPitch;
  state.gimbalYawRate = c.gimbalYawRate;
  state.gimbalPitchRate = c.gimbalPitchRate;
  return state;
}

// A version 0 capture cannot be scored again: its recorded points stand for the scores.
std::vector<sensing::PointScore> recordedScores(const record::CObservationCoinspectCapture& c) {
  std::vector<sensing::PointScore> scores;
  for (const auto& p : c.points) {
    sensing::PointScore s;
    s.index = p.index;
    s.seen = p.seen;
    s.reason = static_cast<sensing::NotSeenReason>(p.notSeenReason);
    s.qBlur = p.qBlur;
    s.qRes = p.qRes;
    s.score = p.score;
    s.counted = p.counted;
    scores.push_back(s);
  }
  return scores;
}

bool sameScore(const record::ScoredPointRecord& r, const sensing::PointScore& s) {
  return r.index == s.index && r.seen == s.seen &&
         r.notSeenReason == static_cast<uint8_t>(s.reason) && r.qBlur == s.qBlur &&
         r.qRes == s.qRes && r.score == s.score && r.counted == s.counted;
}

// Points that differ between the recorded seen points and the re-scored seen points (both in
// ascending index order): differing fields, or present on one side only.
uint64_t countMismatches(const std::vector<record::ScoredPointRecord>& recorded,
                         const std::vector<sensing::PointScore>& scores) {
  uint64_t mismatches = 0;
  auto r = recorded.begin();
  auto s = scores.begin();
  const auto skipUnseen = [&] {
    while (r != recorded.end() && !r->seen)
      ++r;  // version 0 captures recorded the unseen points too
    while (s != scores.end() && !s->seen)
      ++s;
  };
  for (skipUnseen(); r != recorded.end() || s != scores.end(); skipUnseen()) {
    if (s == scores.end() || (r != recorded.end() && r->index < s->index)) {
      ++mismatches;
      ++r;
    } else if (r == recorded.end() || s->index < r->index) {
      ++mismatches;
      ++s;
    } else {
      mismatches += sameScore(*r, *s) ? 0 : 1;
      ++r;
      ++s;
    }
  }
  return mismatches;
}

// "<unit>.<sensor>" -> "<unit>".
std::string unitOfLabel(const std::string& label) {
  const auto dot = label.rfind('.');
  return dot == std::string::npos ? label : label.substr(0, dot);
}

class Evaluator {
 public:
  Evaluator(const world::Scenario& scenario, const EvaluationParams& params,
            const ProgressCallback& progress)
      : scenario_(scenario),
        params_(params),
        progress_(progress),
        caster_(scenario.meshes, scenario.groundZ),
        scorer_(scenario.interestPoints, caster_, params.scoring),
        replay_(scenario, params.scoring, params.physicsStep) {
    if (!(params.physicsStep > 0.0) || !std::isfinite(params.physicsStep))
      throw InputError(params.source, "[mission] physics_step", "must be a positive number");
    COINSPECT_ASSERT(params.progressPeriod > 0.0);
    result_.pointCount = scenario.interestPoints.size();
    result_.scoring = sensing::toString(params.scoring);
    result_.recordedValues.assign(result_.pointCount, 0.0f);
    result_.units.resize(scenario.fleet.size());
    for (size_t i = 0; i < scenario.fleet.size(); ++i) {
      result_.units[i].name = scenario.fleet[i].name;
      result_.units[i].role = scenario.fleet[i].role;
    }
  }

  RunEvaluation run(record::RawlogReader& reader) {
    std::shared_ptr<mrpt::obs::CObservation> object;
    while (reader.next(object)) {
      ++objectNumber_;
      const double time = mrpt::Clock::toDouble(object->timestamp);
      const long long tick = std::llround(time / params_.physicsStep);
      result_.endTime = time;
      handle(*object, time, tick);
      if (progress_ && time >= nextProgress_) {
        reportProgress(time);
        nextProgress_ = (std::floor(time / params_.progressPeriod) + 1.0) * params_.progressPeriod;
      }
    }
    result_.read = reader.status();
    finish();
    if (progress_) reportProgress(result_.endTime);
    return std::move(result_);
  }

 private:
  size_t unitOf(const std::string& name, const std::string& label) const {
    const size_t unit = replay_.unitIndex(name);
    if (unit == detail::TallyReplay::npos)
      throw InputError(params_.source,
                       "object " + std::to_string(objectNumber_) + " (" + label + ")",
                       "unit '" + name + "' is not in the scenario's fleet");
    return unit;
  }

  void handle(const mrpt::obs::CObservation& object, double time, long long tick) {
    using namespace record;
    if (const auto* capture = dynamic_cast<const CObservationCoinspectCapture*>(&object)) {
      replay_.advanceTo(tick, true);  // the merge of a tick comes before its captures
      onCapture(*capture);
    } else if (const auto* links = dynamic_cast<const CObservationCoinspectLinks*>(&object)) {
      replay_.advanceTo(tick, false);  // links of a tick are set before its merge
      for (const auto& change : links->changes)
        replay_.setLinked(unitOf(change.unitA, links->sensorLabel),
                          unitOf(change.unitB, links->sensorLabel), change.linked, time);
    } else if (const auto* event = dynamic_cast<const CObservationCoinspectEvent*>(&object)) {
      using Kind = MissionEventKind;
      const Kind kind = event->kind;
      const bool closing = kind == Kind::End || kind == Kind::NoTakeoff;
      replay_.advanceTo(tick, closing);  // deaths come before the merge, the end after it
      if (kind == Kind::Death) replay_.kill(unitOf(event->unit, event->sensorLabel), time);
      if (closing) result_.missionEnded = true;
      if (kind == Kind::Start && missionStart_ < 0.0) missionStart_ = time;
    } else if (const auto* tally = dynamic_cast<const CObservationCoinspectTally*>(&object)) {
      replay_.advanceTo(tick, true);  // written just after the merge that improved the tally
      onTally(*tally);
    } else if (dynamic_cast<const CObservationCoinspectGimbal*>(&object) ||
               dynamic_cast<const CObservationCoinspectMessages*>(&object)) {
      replay_.advanceTo(tick, true);  // gimbal updates and decisions follow the merge
    } else {
      replay_.advanceTo(tick, false);  // ground truth (before the merge), LiDAR: no effect
    }
  }

  void onCapture(const record::CObservationCoinspectCapture& capture) {
    const std::string name = unitOfLabel(capture.sensorLabel);
    const size_t unit = unitOf(name, capture.sensorLabel);
    UnitEvaluation& out = result_.units[unit];
    if (!replay_.alive(unit) && !sensing::capturesWhenCrashed(params_.scoring)) {
      ++out.capturesIgnored;  // strict mode: a dead unit's camera is off
      return;
    }
    if (capture.hasBodyState) {
      sensing::Occluders occluders;
      for (const auto& o : capture.occluders)
        occluders.spheres.push_back({{o.center[0], o.center[1], o.center[2]}, o.radius});
      scorer_.score(scenario_.fleet[unit].camera, captureState(capture), occluders, scores_);
      const uint64_t mismatches = countMismatches(capture.points, scores_);
      ++result_.capturesCompared;
      result_.pointMismatches += mismatches;
      result_.capturesMismatched += mismatches > 0 ? 1 : 0;
    } else {
      scores_ = recordedScores(capture);
      ++result_.capturesNotRescored;
    }
    for (const auto& s : scores_)
      if (s.seen) out.quality.add(s.qBlur, s.qRes);
    ++out.captures;
    replay_.recordCapture(unit, scores_);
  }

  void onTally(const record::CObservationCoinspectTally& tally) {
    for (const auto& change : tally.changes) {
      if (change.index >= result_.recordedValues.size())
        throw InputError(params_.source, "object " + std::to_string(objectNumber_) + " (gcs.tally)",
                         "point index " + std::to_string(change.index) + " beyond the scenario's " +
                             std::to_string(result_.recordedValues.size()) + " points");
      result_.recordedValues[change.index] = static_cast<float>(change.value);
    }
    ++result_.tallyRecords;
    result_.recordedScore = tally.totalScore;
    result_.recordedDetected = tally.detected;
    if (tally.totalScore != replay_.score() || tally.detected != replay_.tally().detectedCount())
      ++result_.tallyRecordMismatches;
  }

  void reportProgress(double time) const {
    const auto& coverage = replay_.coverage();
    EvaluationProgress p;
    p.time = time;
    p.pointCount = result_.pointCount;
    p.missionStart = missionStart_;
    if (!coverage.empty()) {
      p.score = coverage.back().score;
      p.detected = coverage.back().detected;
    }
    progress_(p);
  }

  void finish() {
    const auto& tally = replay_.tally();
    result_.values = tally.values();
    result_.score = tally.totalScore();
    result_.detected = tally.detectedCount();
    result_.coverage = replay_.coverage();
    for (size_t p = 0; p < result_.pointCount; ++p)
      if (result_.values[p] != result_.recordedValues[p]) ++result_.valueMismatches;

    // Who detected each point, and who holds the ground station's value.
    const size_t unitCount = replay_.unitCount();
    const auto idx = [](size_t p) { return static_cast<uint32_t>(p); };
    for (size_t p = 0; p < result_.pointCount; ++p) {
      size_t detectors = 0;
      size_t detector = 0;
      for (size_t u = 0; u < unitCount; ++u) {
        const float best = replay_.log(u).best(idx(p));
        if (best <= 0.0f) continue;
        ++detectors;
        detector = u;
        if (best == tally.value(idx(p))) ++result_.units[u].holdsGcsValue;
      }
      if (detectors == 1) ++result_.units[detector].onlyDetector;
    }
    for (size_t u = 0; u < unitCount; ++u) {
      UnitEvaluation& out = result_.units[u];
      out.detected = replay_.log(u).detectedCount();
      out.ownScore = replay_.log(u).totalScore();
      out.alive = replay_.alive(u);
      out.deathTime = out.alive ? 0.0 : replay_.deathTime(u);
      out.lineOfSightTime = replay_.lineOfSightTime(u, result_.endTime);
      result_.quality.add(out.quality);
    }
  }

  const world::Scenario& scenario_;
  const EvaluationParams& params_;
  const ProgressCallback& progress_;
  world::RayCaster caster_;  // built exactly as the mission builds it
  sensing::InspectionScorer scorer_;
  detail::TallyReplay replay_;
  RunEvaluation result_;
  std::vector<sensing::PointScore> scores_;
  uint64_t objectNumber_ = 1;  // the header comment is object 1
  double nextProgress_ = 0.0;
  double missionStart_ = -1.0;
};

}  // namespace

uint64_t QualityHistogram::samples() const {
  uint64_t total = 0;
  for (const uint64_t count : qBlur)
    total += count;
  return total;
}

void QualityHistogram::add(double qBlurValue, double qResValue) {
  const auto bin = [](double q) {
    const double scaled = std::floor(q * static_cast<double>(kQualityBins));
    if (!(scaled > 0.0)) return size_t{0};
    return std::min(kQualityBins - 1, static_cast<size_t>(scaled));
  };
  ++qBlur[bin(qBlurValue)];
  ++qRes[bin(qResValue)];
}

void QualityHistogram::add(const QualityHistogram& other) {
  for (size_t b = 0; b < kQualityBins; ++b) {
    qBlur[b] += other.qBlur[b];
    qRes[b] += other.qRes[b];
  }
}

RunEvaluation evaluateRun(record::RawlogReader& reader, const world::Scenario& scenario,
                          const EvaluationParams& params, const ProgressCallback& progress) {
  return Evaluator(scenario, params, progress).run(reader);
}

}  // namespace coinspect::eval
