// The GCS's meeting order: exact dynamic programme and insertion heuristic (see
// slei_meeting_order.h).
#include "coinspect/planning/slei_meeting_order.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::planning {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr char kSource[] = "meeting order";
constexpr int kMaxExactMeetings = 16;         // 2^16 x 16 states
constexpr double kHeuristicTolerance = 1e-9;  // s: smaller gains do not count as improvements

// Travel times looked up once: the travel function may be an expensive path search.
class TravelTable {
 public:
  explicit TravelTable(const MeetingOrderProblem& problem)
      : n_(static_cast<int>(problem.meetings.size())) {
    const GcsTravelTime travel = problem.travelTime ? problem.travelTime : groundTravelTime(1.0);
    times_.resize(static_cast<size_t>(n_ + 1) * n_);
    for (int from = -1; from < n_; ++from) {
      const Vec3& origin = from < 0 ? problem.start : problem.meetings[from].place;
      for (int to = 0; to < n_; ++to) {
        const double time = from == to ? 0.0 : travel(origin, problem.meetings[to].place);
        if (!(time >= 0.0)) {
          throw InputError(
              kSource, "travelTime",
              std::to_string(time) + " to meeting " + std::to_string(to) + " is negative or NaN");
        }
        times_[index(from, to)] = time;
      }
    }
  }
  // from = -1: from the GCS's start.
  double operator()(int from, int to) const { return times_[index(from, to)]; }

 private:
  size_t index(int from, int to) const { return static_cast<size_t>(from + 1) * n_ + to; }
  int n_;
  std::vector<double> times_;
};

struct Step {
  double arrival, start, departure, lateness;
};

Step serve(double departure, double travel, const GcsMeeting& meeting) {
  Step step;
  step.arrival = departure + travel;
  step.start = std::max(step.arrival, meeting.earliest);
  // A meeting the GCS cannot reach is infinitely late, even with an open window.
  step.lateness = !std::isfinite(step.arrival)    ? kInfinity
                  : step.arrival > meeting.latest ? step.arrival - meeting.latest
                                                  : 0.0;
  step.departure = step.start + meeting.service;
  return step;
}

struct Rank {
  double maxLateness = 0.0, totalLateness = 0.0, completion = 0.0;
};

// Written as two one-sided tests so that equal infinities compare equal.
bool rankLess(const Rank& a, const Rank& b, double tolerance) {
  if (a.maxLateness < b.maxLateness - tolerance) return true;
  if (b.maxLateness < a.maxLateness - tolerance) return false;
  if (a.totalLateness < b.totalLateness - tolerance) return true;
  if (b.totalLateness < a.totalLateness - tolerance) return false;
  return a.completion < b.completion - tolerance;
}

Rank rankOf(const MeetingOrderProblem& problem, const TravelTable& table,
            const std::vector<int>& order) {
  Rank rank;
  rank.completion = problem.startTime;
  int previous = -1;
  for (const int meeting : order) {
    const Step step = serve(rank.completion, table(previous, meeting), problem.meetings[meeting]);
    rank.maxLateness = std::max(rank.maxLateness, step.lateness);
    rank.totalLateness += step.lateness;
    rank.completion = step.departure;
    previous = meeting;
  }
  return rank;
}

MeetingSchedule scheduleOf(const MeetingOrderProblem& problem, const TravelTable& table,
                           const std::vector<int>& order, bool exact) {
  MeetingSchedule schedule;
  schedule.order = order;
  schedule.completion = problem.startTime;
  schedule.exact = exact;
  int previous = -1;
  for (const int meeting : order) {
    const GcsMeeting& m = problem.meetings[meeting];
    const Step step = serve(schedule.completion, table(previous, meeting), m);
    schedule.stops.push_back(
        {meeting, m.id, step.arrival, step.start, step.departure, step.lateness});
    schedule.maxLateness = std::max(schedule.maxLateness, step.lateness);
    schedule.totalLateness += step.lateness;
    schedule.completion = step.departure;
    previous = meeting;
  }
  schedule.allWindowsMet = schedule.maxLateness == 0.0;
  return schedule;
}

// One partial order ending in a state's last meeting; prev* lead back to its predecessor label.
struct Label {
  double departure, maxLateness, totalLateness;
  int previousLast, previousLabel;
};

bool dominates(const Label& a, const Label& b) {
  return a.departure <= b.departure && a.maxLateness <= b.maxLateness &&
         a.totalLateness <= b.totalLateness;
}

// Keeps `front` free of beaten labels; an equal label is not added (the first found stays).
void insertLabel(std::vector<Label>& front, const Label& label) {
  for (const Label& kept : front) {
    if (dominates(kept, label)) return;
  }
  front.erase(std::remove_if(front.begin(), front.end(),
                             [&](const Label& kept) { return dominates(label, kept); }),
              front.end());
  front.push_back(label);
}

// The best order whose largest lateness is at most `lateBound` (0: every window met), or an
// empty order when there is none.
std::vector<int> dynamicProgramme(const MeetingOrderProblem& problem, const TravelTable& table,
                                  double lateBound) {
  const int n = static_cast<int>(problem.meetings.size());
  const unsigned full = (1u << n) - 1u;
  std::vector<std::vector<Label>> fronts(static_cast<size_t>(full + 1) * n);
  const auto state = [n](unsigned set, int last) { return static_cast<size_t>(set) * n + last; };
  for (int first = 0; first < n; ++first) {
    const Step step = serve(problem.startTime, table(-1, first), problem.meetings[first]);
    if (step.lateness > lateBound) continue;
    fronts[state(1u << first, first)].push_back(
        {step.departure, step.lateness, step.lateness, -1, -1});
  }
  // Every set is finished before a larger one is expanded, so back references stay valid.
  for (unsigned set = 1; set < full; ++set) {
    for (int last = 0; last < n; ++last) {
      const std::vector<Label>& front = fronts[state(set, last)];
      for (int index = 0; index < static_cast<int>(front.size()); ++index) {
        const Label& label = front[index];
        for (int next = 0; next < n; ++next) {
          if (set & (1u << next)) continue;
          const Step step = serve(label.departure, table(last, next), problem.meetings[next]);
          const double maxLateness = std::max(label.maxLateness, step.lateness);
          if (maxLateness > lateBound) continue;
          insertLabel(
              fronts[state(set | (1u << next), next)],
              {step.departure, maxLateness, label.totalLateness + step.lateness, last, index});
        }
      }
    }
  }
  int bestLast = -1, bestIndex = -1;
  Rank best;
  for (int last = 0; last < n; ++last) {
    const std::vector<Label>& front = fronts[state(full, last)];
    for (int index = 0; index < static_cast<int>(front.size()); ++index) {
      const Rank rank{front[index].maxLateness, front[index].totalLateness, front[index].departure};
      if (bestLast < 0 || rankLess(rank, best, 0.0)) {
        best = rank;
        bestLast = last;
        bestIndex = index;
      }
    }
  }
  std::vector<int> order;
  unsigned set = full;
  while (bestLast >= 0) {
    order.push_back(bestLast);
    const Label& label = fronts[state(set, bestLast)][bestIndex];
    set &= ~(1u << bestLast);
    bestLast = label.previousLast;
    bestIndex = label.previousLabel;
  }
  std::reverse(order.begin(), order.end());
  return order;
}

std::vector<int> insertionOrder(const MeetingOrderProblem& problem, const TravelTable& table) {
  const std::vector<GcsMeeting>& meetings = problem.meetings;
  std::vector<int> byDeadline(meetings.size());
  std::iota(byDeadline.begin(), byDeadline.end(), 0);
  std::stable_sort(byDeadline.begin(), byDeadline.end(), [&](int a, int b) {
    if (meetings[a].latest != meetings[b].latest) return meetings[a].latest < meetings[b].latest;
    return meetings[a].earliest < meetings[b].earliest;
  });
  std::vector<int> order;
  for (const int meeting : byDeadline) {
    std::vector<int> best;
    Rank bestRank;
    for (size_t position = 0; position <= order.size(); ++position) {
      std::vector<int> candidate = order;
      candidate.insert(candidate.begin() + position, meeting);
      const Rank rank = rankOf(problem, table, candidate);
      if (best.empty() || rankLess(rank, bestRank, kHeuristicTolerance)) {
        best = std::move(candidate);
        bestRank = rank;
      }
    }
    order = std::move(best);
  }
  return order;
}

// First-improvement local search: swap two meetings, move one elsewhere, or reverse a stretch
// (the 2-opt move, which undoes a crossing of the GCS's path that swaps alone rarely can).
void improveOrder(const MeetingOrderProblem& problem, const TravelTable& table, int passes,
                  std::vector<int>& order) {
  Rank best = rankOf(problem, table, order);
  const size_t n = order.size();
  const auto tryCandidate = [&](std::vector<int>& candidate) {
    const Rank rank = rankOf(problem, table, candidate);
    if (!rankLess(rank, best, kHeuristicTolerance)) return false;
    best = rank;
    order.swap(candidate);
    return true;
  };
  for (int pass = 0; pass < passes; ++pass) {
    bool improved = false;
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = i + 1; j < n; ++j) {
        std::vector<int> candidate = order;
        std::swap(candidate[i], candidate[j]);
        improved = tryCandidate(candidate) || improved;
      }
    }
    for (size_t from = 0; from < n; ++from) {
      for (size_t to = 0; to < n; ++to) {
        if (to == from) continue;
        std::vector<int> candidate = order;
        const int meeting = candidate[from];
        candidate.erase(candidate.begin() + from);
        candidate.insert(candidate.begin() + to, meeting);
        improved = tryCandidate(candidate) || improved;
      }
    }
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = i + 2; j < n; ++j) {  // i + 1 would repeat a swap
        std::vector<int> candidate = order;
        std::reverse(candidate.begin() + i, candidate.begin() + j + 1);
        improved = tryCandidate(candidate) || improved;
      }
    }
    if (!improved) break;
  }
}

void validateInputs(const MeetingOrderProblem& problem, const MeetingOrderOptions& options) {
  if (!problem.start.allFinite() || !std::isfinite(problem.startTime)) {
    throw InputError(kSource, "start", "position and time must be finite");
  }
  for (size_t i = 0; i < problem.meetings.size(); ++i) {
    const GcsMeeting& m = problem.meetings[i];
    const std::string where = "meeting " + std::to_string(i);
    if (!m.place.allFinite() || !std::isfinite(m.earliest)) {
      throw InputError(kSource, where, "place and earliest time must be finite");
    }
    if (!(m.latest >= m.earliest)) {
      throw InputError(kSource, where, "latest time is before the earliest");
    }
    if (!(m.service >= 0.0) || !std::isfinite(m.service)) {
      throw InputError(kSource, where, "service time is not a finite value >= 0");
    }
  }
  if (options.exactLimit < 0 || options.exactLimit > kMaxExactMeetings) {
    throw InputError(kSource, "exactLimit",
                     std::to_string(options.exactLimit) + " is outside [0, " +
                         std::to_string(kMaxExactMeetings) + "]");
  }
  if (options.improvementPasses < 0) {
    throw InputError(kSource, "improvementPasses", "is negative");
  }
}

MeetingSchedule heuristic(const MeetingOrderProblem& problem, const TravelTable& table,
                          const MeetingOrderOptions& options) {
  std::vector<int> order = insertionOrder(problem, table);
  improveOrder(problem, table, options.improvementPasses, order);
  return scheduleOf(problem, table, order, false);
}

MeetingSchedule exact(const MeetingOrderProblem& problem, const TravelTable& table) {
  std::vector<int> order = dynamicProgramme(problem, table, 0.0);
  if (!order.empty() || problem.meetings.empty()) return scheduleOf(problem, table, order, true);
  // No order meets every window: the least late one, never later than the heuristic's.
  const MeetingSchedule incumbent = heuristic(problem, table, MeetingOrderOptions{});
  order = dynamicProgramme(problem, table, incumbent.maxLateness);
  if (order.empty()) return incumbent;  // only if rounding differed; the incumbent is as good
  return scheduleOf(problem, table, order, true);
}

}  // namespace

GcsTravelTime groundTravelTime(double speed) {
  if (!(speed > 0.0) || !std::isfinite(speed)) {
    throw InputError(kSource, "speed", std::to_string(speed) + " is not a finite speed > 0");
  }
  return [speed](const Vec3& from, const Vec3& to) {
    return (to.head<2>() - from.head<2>()).norm() / speed;
  };
}

void validateMeetingOrderProblem(const MeetingOrderProblem& problem,
                                 const MeetingOrderOptions& options) {
  validateInputs(problem, options);
  TravelTable table(problem);  // checks every travel time
}

MeetingSchedule planMeetingOrder(const MeetingOrderProblem& problem,
                                 const MeetingOrderOptions& options) {
  validateInputs(problem, options);
  const TravelTable table(problem);
  if (static_cast<int>(problem.meetings.size()) <= options.exactLimit) {
    return exact(problem, table);
  }
  return heuristic(problem, table, options);
}

MeetingSchedule exactMeetingOrder(const MeetingOrderProblem& problem) {
  MeetingOrderOptions options;
  options.exactLimit = kMaxExactMeetings;
  validateInputs(problem, options);
  if (static_cast<int>(problem.meetings.size()) > kMaxExactMeetings) {
    throw InputError(kSource, "meetings",
                     std::to_string(problem.meetings.size()) + " exceed the exact limit of " +
                         std::to_string(kMaxExactMeetings));
  }
  return exact(problem, TravelTable(problem));
}

MeetingSchedule heuristicMeetingOrder(const MeetingOrderProblem& problem,
                                      const MeetingOrderOptions& options) {
  validateInputs(problem, options);
  return heuristic(problem, TravelTable(problem), options);
}

MeetingSchedule evaluateMeetingOrder(const MeetingOrderProblem& problem,
                                     const std::vector<int>& order) {
  validateInputs(problem, MeetingOrderOptions{});
  std::vector<bool> seen(problem.meetings.size(), false);
  for (const int meeting : order) {
    if (meeting < 0 || meeting >= static_cast<int>(seen.size()) || seen[meeting]) {
      throw InputError(kSource, "order",
                       "meeting " + std::to_string(meeting) + " is out of range or repeated");
    }
    seen[meeting] = true;
  }
  if (order.size() != seen.size()) {
    throw InputError(kSource, "order", "does not visit every meeting");
  }
  return scheduleOf(problem, TravelTable(problem), order, false);
}

bool ranksBefore(const MeetingSchedule& a, const MeetingSchedule& b, double tolerance) {
  return rankLess({a.maxLateness, a.totalLateness, a.completion},
                  {b.maxLateness, b.totalLateness, b.completion}, tolerance);
}

}  // namespace coinspect::planning
