// SLEI3D's completion prediction and GCS meeting corners (see slei_schedule.h).
#include "coinspect/planning/slei_schedule.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::planning {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// `!(value >= 0)` is also true for NaN, which must not slip through as "not negative".
void requireNonNegative(const char* source, const char* name, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InputError(source, name, std::to_string(value) + " is not a finite value >= 0");
  }
}

void validateCompletion(const CompletionInputs& inputs,
                        const CompletionPredictionOptions& options) {
  const char* const source = "completion prediction";
  requireNonNegative(source, "boxVolume", inputs.boxVolume);
  requireNonNegative(source, "exploredVolume", inputs.exploredVolume);
  requireNonNegative(source, "featuresScanned", inputs.featuresScanned);
  requireNonNegative(source, "featuresInspected", inputs.featuresInspected);
  requireNonNegative(source, "timeInBox", inputs.timeInBox);
  requireNonNegative(source, "plannedSweepTime", inputs.plannedSweepTime);
  requireNonNegative(source, "closingTourLength", inputs.closingTourLength);
  if (!std::isfinite(inputs.now) || !std::isfinite(inputs.earliestInspectorFinish)) {
    throw InputError(source, "now / earliestInspectorFinish", "must be finite");
  }
  requireNonNegative(source, "minRemaining", options.minRemaining);
  requireNonNegative(source, "maxRemaining", options.maxRemaining);
  requireNonNegative(source, "uninspectedFallback", options.uninspectedFallback);
  if (options.minRemaining > options.maxRemaining) {
    throw InputError(source, "minRemaining",
                     std::to_string(options.minRemaining) + " is above maxRemaining " +
                         std::to_string(options.maxRemaining));
  }
  if (!(options.explorerSpeed > 0.0) || !std::isfinite(options.explorerSpeed)) {
    throw InputError(source, "explorerSpeed",
                     std::to_string(options.explorerSpeed) + " is not a finite speed > 0");
  }
}

// The unclamped time of the case that applies, and which case it was.
CompletionPrediction unclampedCompletion(const CompletionInputs& in,
                                         const CompletionPredictionOptions& options) {
  CompletionPrediction prediction;
  if (in.explorationFinished) {
    const double firstFree = std::max(in.earliestInspectorFinish, in.now);
    prediction.unclamped = firstFree + in.closingTourLength / options.explorerSpeed - in.now;
    prediction.rule = CompletionRule::ClosingTour;
    return prediction;
  }
  if (in.exploredVolume == 0.0) {
    // The reference's floor (50 s) is too short to reach a far first stop and come back: an
    // explorer met its station every 35 s for 400 s of a slei-a run, sweeping nothing. The
    // planned sweep's flying time when there is one.
    prediction.unclamped = in.plannedSweepTime > 0.0 ? in.plannedSweepTime : options.minRemaining;
    prediction.rule = CompletionRule::NothingExplored;
    return prediction;
  }
  const double scanned = in.featuresScanned;
  const double predicted = std::floor(scanned * in.boxVolume / in.exploredVolume);
  const double t = in.timeInBox;
  if (in.featuresScanned == 0 || scanned >= predicted || in.inspectedAfterExploration) {
    prediction.unclamped = in.boxVolume / in.exploredVolume * t - t;
    prediction.rule = CompletionRule::VolumeExtrapolation;
  } else if (in.featuresInspected == 0) {
    prediction.unclamped = options.uninspectedFallback;
    prediction.rule = CompletionRule::UninspectedFallback;
  } else {
    prediction.unclamped = predicted / in.featuresInspected * t - t;
    prediction.rule = CompletionRule::InspectionExtrapolation;
  }
  return prediction;
}

double horizontalDistance(const Vec3& a, const Vec3& b) {
  return (a.head<2>() - b.head<2>()).norm();
}

}  // namespace

CompletionPrediction predictCompletion(const CompletionInputs& inputs,
                                       const CompletionPredictionOptions& options) {
  validateCompletion(inputs, options);
  CompletionPrediction prediction = unclampedCompletion(inputs, options);
  prediction.remaining =
      std::clamp(prediction.unclamped, options.minRemaining, options.maxRemaining);
  return prediction;
}

double straightTourLength(const Vec3& start, const std::vector<Vec3>& stops, bool horizontalOnly) {
  double length = 0.0;
  Vec3 from = start;
  for (const Vec3& stop : stops) {
    length += horizontalOnly ? horizontalDistance(from, stop) : (stop - from).norm();
    from = stop;
  }
  return length;
}

namespace {

// FF3E's time model: straight lines at `speed`, times `travelFactor` (paths are longer).
double straightFlight(const Vec3& a, const Vec3& b, double speed, double travelFactor) {
  return travelFactor * (a - b).norm() / speed;
}

}  // namespace

std::vector<size_t> deadlineBoundedTour(const Vec3& start, double now,
                                        const std::vector<Vec3>& stops, const Vec3& meeting,
                                        double deadline, double speed, double travelFactor) {
  const auto flight = [&](const Vec3& a, const Vec3& b) {
    return straightFlight(a, b, speed, travelFactor);
  };
  std::vector<uint8_t> used(stops.size(), 0);
  std::vector<size_t> tour;
  Vec3 from = start;
  double time = now;
  while (true) {
    size_t best = stops.size();
    double bestDistance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < stops.size(); ++i) {
      if (used[i]) continue;
      const double distance = (stops[i] - from).squaredNorm();
      if (distance >= bestDistance) continue;
      if (time + flight(from, stops[i]) + flight(stops[i], meeting) > deadline) continue;
      bestDistance = distance;
      best = i;
    }
    if (best == stops.size()) return tour;
    used[best] = 1;
    time += flight(from, stops[best]);
    from = stops[best];
    tour.push_back(best);
  }
}

namespace {

// The depth-first search of deadlineBoundedSearch: extends `sequence` (ending at `from` at
// `time`, having gained `gained`) and keeps the best rate seen in `best`.
struct SequenceSearch {
  const std::vector<Vec3>& stops;
  const std::vector<double>& gains;
  const Vec3& meeting;
  double now, deadline, speed;
  const FrontierSearchOptions& options;
  std::vector<uint8_t> used;
  std::vector<size_t> sequence, best;
  double bestRate = -1.0, bestTime = 0.0;

  double flight(const Vec3& a, const Vec3& b) const {
    return straightFlight(a, b, speed, options.travelFactor);
  }
  void extend(const Vec3& from, double time, double gained) {
    if (!sequence.empty()) {
      const double elapsed = std::max(time - now, 1e-9);
      const double rate = gained / elapsed;
      if (rate > bestRate + 1e-12 || (std::abs(rate - bestRate) <= 1e-12 && elapsed < bestTime))
        bestRate = rate, bestTime = elapsed, best = sequence;
    }
    if (sequence.size() >= options.depth) return;
    // The `branching` nearest stops that still fit before the deadline.
    std::vector<std::pair<double, size_t>> next;
    for (size_t i = 0; i < stops.size(); ++i) {
      if (used[i]) continue;
      const double arrive = time + flight(from, stops[i]) + options.dwell;
      if (arrive + flight(stops[i], meeting) > deadline) continue;
      next.emplace_back(arrive, i);
    }
    const size_t keep = std::min(options.branching, next.size());
    std::partial_sort(next.begin(), next.begin() + static_cast<std::ptrdiff_t>(keep), next.end());
    next.resize(keep);
    for (const auto& [arrive, i] : next) {
      used[i] = 1;
      sequence.push_back(i);
      extend(stops[i], arrive, gained + gains[i]);
      sequence.pop_back();
      used[i] = 0;
    }
  }
};

}  // namespace

std::vector<size_t> deadlineBoundedSearch(const Vec3& start, double now,
                                          const std::vector<Vec3>& stops,
                                          const std::vector<double>& gains, const Vec3& meeting,
                                          double deadline, double speed,
                                          const FrontierSearchOptions& options) {
  const char* const source = "frontier search";
  if (gains.size() != stops.size()) throw InputError(source, "gains", "one per stop");
  for (const double gain : gains)
    if (!std::isfinite(gain) || gain < 0.0) throw InputError(source, "gains", "finite, >= 0");
  if (options.depth == 0)
    return deadlineBoundedTour(start, now, stops, meeting, deadline, speed, options.travelFactor);
  SequenceSearch search{stops, gains, meeting, now, deadline, speed, options, {}, {}, {}};
  search.used.assign(stops.size(), 0);
  search.extend(start, now, 0.0);
  if (search.best.empty()) return {};
  // Then nearest first from the sequence's end, among the stops it left.
  std::vector<Vec3> rest;
  std::vector<size_t> restIndex;
  Vec3 end = start;
  double time = now;
  for (const size_t i : search.best) {
    time += search.flight(end, stops[i]) + options.dwell;
    end = stops[i];
    search.used[i] = 1;
  }
  for (size_t i = 0; i < stops.size(); ++i)
    if (!search.used[i]) rest.push_back(stops[i]), restIndex.push_back(i);
  std::vector<size_t> out = search.best;
  for (const size_t k :
       deadlineBoundedTour(end, time, rest, meeting, deadline, speed, options.travelFactor))
    out.push_back(restIndex[k]);
  return out;
}

std::array<Vec3, 4> meetingCorners(const Vec3& boxMin, const Vec3& boxMax,
                                   const MeetingCornerOptions& options) {
  const char* const source = "meeting corners";
  if (!boxMin.allFinite() || !boxMax.allFinite() || !std::isfinite(options.height)) {
    throw InputError(source, "box", "corners and height must be finite");
  }
  if (boxMin.x() > boxMax.x() || boxMin.y() > boxMax.y()) {
    throw InputError(source, "box", "the minimum corner is above the maximum in x or y");
  }
  requireNonNegative(source, "inset", options.inset);
  // Never move past the middle: a narrow box keeps both corners of that axis on its centre line.
  const double insetX = std::min(options.inset, 0.5 * (boxMax.x() - boxMin.x()));
  const double insetY = std::min(options.inset, 0.5 * (boxMax.y() - boxMin.y()));
  const double x0 = boxMin.x() + insetX, x1 = boxMax.x() - insetX;
  const double y0 = boxMin.y() + insetY, y1 = boxMax.y() - insetY;
  const double z = options.height;
  return {Vec3(x0, y0, z), Vec3(x1, y0, z), Vec3(x1, y1, z), Vec3(x0, y1, z)};
}

MeetingCornerChoice nearestMeetingCorner(const Vec3& boxMin, const Vec3& boxMax,
                                         const Vec3& reference,
                                         const MeetingCornerOptions& options) {
  const std::array<Vec3, 4> corners = meetingCorners(boxMin, boxMax, options);
  MeetingCornerChoice choice;
  double best = kInfinity;
  for (int i = 0; i < 4; ++i) {
    const double distance = horizontalDistance(corners[i], reference);
    if (distance < best) {  // strict: ties keep the first corner
      best = distance;
      choice.index = i;
    }
  }
  if (choice.index < 0) choice.index = 0;  // a NaN reference: every distance compares false
  choice.point = corners[choice.index];
  return choice;
}

MeetingCornerChoice bestTimedMeetingCorner(const Vec3& boxMin, const Vec3& boxMax,
                                           const std::function<double(const Vec3&)>& arrivalTime,
                                           double plannedTime,
                                           const MeetingCornerOptions& options) {
  if (!arrivalTime) {
    throw InputError("meeting corners", "arrivalTime", "no arrival-time function given");
  }
  if (!std::isfinite(plannedTime)) {
    throw InputError("meeting corners", "plannedTime", "must be finite");
  }
  const std::array<Vec3, 4> corners = meetingCorners(boxMin, boxMax, options);
  MeetingCornerChoice choice;
  choice.arrival = kInfinity;
  double bestMismatch = kInfinity;
  for (int i = 0; i < 4; ++i) {
    const double arrival = arrivalTime(corners[i]);
    if (!std::isfinite(arrival)) continue;  // unreachable
    const double mismatch = std::abs(arrival - plannedTime);
    const bool better =
        mismatch < bestMismatch || (mismatch == bestMismatch && arrival < choice.arrival);
    if (better) {
      bestMismatch = mismatch;
      choice.index = i;
      choice.arrival = arrival;
      choice.point = corners[i];
    }
  }
  return choice;
}

}  // namespace coinspect::planning
