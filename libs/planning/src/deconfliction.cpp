#include "coinspect/planning/deconfliction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::planning {

const char* toString(YieldAction action) {
  switch (action) {
    case YieldAction::Proceed:
      return "proceed";
    case YieldAction::Wait:
      return "wait";
    case YieldAction::Sidestep:
      return "sidestep";
    case YieldAction::Hold:
      return "hold";
  }
  return "?";
}

Vec3 TimedPath::at(double t) const {
  COINSPECT_ASSERT(!positions.empty() && step > 0.0);
  const double k = (t - startTime) / step;
  if (k <= 0.0) return positions.front();
  const size_t last = positions.size() - 1;
  if (k >= static_cast<double>(last)) return positions.back();
  const size_t i = static_cast<size_t>(k);
  const double f = k - static_cast<double>(i);
  return positions[i] + f * (positions[i + 1] - positions[i]);
}

TimedPath TimedPath::hold(double time, const Vec3& position) {
  return {time, 1.0, {position}};
}

TimedPath TimedPath::constantVelocity(double time, const Vec3& position, const Vec3& velocity,
                                      double horizon, double step) {
  TimedPath path{time, step, {}};
  const int count = static_cast<int>(std::ceil(horizon / step));
  for (int k = 0; k <= count; ++k)
    path.positions.push_back(position + (k * step) * velocity);
  return path;
}

TimedPath TimedPath::fromTrajectory(const Trajectory& trajectory, double trajectoryStart,
                                    double from, double horizon, double step) {
  TimedPath path{from, step, {}};
  const int count = static_cast<int>(std::ceil(horizon / step));
  for (int k = 0; k <= count; ++k)
    path.positions.push_back(trajectory.sample(from + k * step - trajectoryStart).position);
  return path;
}

namespace {

// Least |a + s (b - a)| for s in [0, 1].
double segmentDistanceToOrigin(const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  const double s = dd > 0.0 ? std::clamp(-a.dot(d) / dd, 0.0, 1.0) : 0.0;
  return (a + s * d).norm();
}

bool keepsSeparation(const TimedPath& plan, const std::vector<const Neighbour*>& higher,
                     const DeconflictionOptions& options) {
  for (const Neighbour* neighbour : higher) {
    const auto relative = [&](size_t k) {
      const double t = plan.startTime + k * plan.step;
      return Vec3(plan.positions[k] - neighbour->path.at(t));
    };
    const double floor =
        std::min(options.separation, relative(0).norm()) - 1e-9;  // never close in further
    Vec3 previous = relative(0);
    for (size_t k = 1; k < plan.positions.size(); ++k) {
      const Vec3 current = relative(k);
      if (segmentDistanceToOrigin(previous, current) < floor) return false;
      previous = current;
    }
  }
  return true;
}

}  // namespace

DeconflictionResult deconflict(size_t ownPriority, double now, const Vec3& position,
                               const TimedPath& desired, const std::vector<Neighbour>& neighbours,
                               const DeconflictionOptions& options,
                               const std::function<bool(const Vec3&, const Vec3&)>& segmentFree) {
  COINSPECT_ASSERT(options.step > 0.0 && options.horizon > 0.0 && options.sidestepSpeed > 0.0);
  std::vector<const Neighbour*> higher;
  for (const auto& neighbour : neighbours) {
    COINSPECT_ASSERT(neighbour.priority != ownPriority);
    if (neighbour.priority < ownPriority) higher.push_back(&neighbour);
  }
  const int count = static_cast<int>(std::ceil(options.horizon / options.step));
  const auto planOf = [&](auto positionAt) {
    TimedPath plan{now, options.step, {}};
    plan.positions.reserve(count + 1);
    for (int k = 0; k <= count; ++k)
      plan.positions.push_back(positionAt(k * options.step));
    return plan;
  };

  DeconflictionResult result;
  result.plan = planOf([&](double dt) { return desired.at(now + dt); });
  if (keepsSeparation(result.plan, higher, options)) {
    result.action = YieldAction::Proceed;
    return result;
  }
  const int waits = static_cast<int>(std::floor(options.maxWait / options.step + 1e-9));
  for (int w = 1; w <= waits; ++w) {
    const double wait = w * options.step;
    TimedPath plan =
        planOf([&](double dt) { return dt < wait ? position : desired.at(now + dt - wait); });
    if (keepsSeparation(plan, higher, options)) {
      result.action = YieldAction::Wait;
      result.wait = wait;
      result.plan = std::move(plan);
      return result;
    }
  }
  // Sidesteps, in a fixed order; the best is the one nearest where the desired plan ends.
  const Vec3 aim = desired.positions.back();
  double best = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 10; ++d) {
    Vec3 direction;
    if (d < 8) {
      const double angle = d * 0.25 * 3.14159265358979323846;
      direction = Vec3(std::cos(angle), std::sin(angle), 0.0);
    } else {
      direction = d == 8 ? Vec3::UnitZ() : Vec3(-Vec3::UnitZ());
    }
    const Vec3 target = position + options.sidestep * direction;
    if (segmentFree && !segmentFree(position, target)) continue;
    const double duration = options.sidestep / options.sidestepSpeed;
    TimedPath plan = planOf([&](double dt) {
      return Vec3(position + std::min(1.0, dt / duration) * (target - position));
    });
    const double score = (target - aim).norm();
    if (score < best && keepsSeparation(plan, higher, options)) {
      best = score;
      result.action = YieldAction::Sidestep;
      result.sidestepTarget = target;
      result.plan = std::move(plan);
    }
  }
  if (result.action == YieldAction::Sidestep) return result;
  result.action = YieldAction::Hold;
  result.plan = planOf([&](double) { return position; });
  return result;
}

}  // namespace coinspect::planning
