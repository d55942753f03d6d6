#include "coinspect/strategies/demo_paths.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"

namespace coinspect::strategies {

namespace {

constexpr double kDegree = M_PI / 180.0;

Vec3 parseVector(const std::string& text, const Config& config, const std::string& where) {
  const auto tokens = splitTokens(text, " \t,");
  if (tokens.size() != 3)
    throw InputError(config.source(), where, "expected 3 numbers (x y z), got '" + text + "'");
  Vec3 out;
  for (int i = 0; i < 3; ++i) {
    const auto value = parseFiniteDouble(tokens[i]);
    if (!value)
      throw InputError(config.source(), where, "not a finite number: '" + tokens[i] + "'");
    out[i] = *value;
  }
  return out;
}

std::vector<Vec3> parseWaypoints(const std::string& text, const Config& config,
                                 const std::string& where) {
  std::vector<Vec3> out;
  for (const auto& item : splitTokens(text, ";"))
    out.push_back(parseVector(item, config, where));
  if (out.empty()) throw InputError(config.source(), where, "no waypoint");
  return out;
}

// The distance the reference point may run ahead of the vehicle before it waits for it.
double maxLag(double speed) {
  return std::max(2.0, 1.5 * speed);
}

}  // namespace

std::optional<DemoPathsOptions> DemoPathsOptions::read(const Config& config,
                                                       const std::string& unit) {
  const std::string section = "demo-paths." + unit;
  if (!config.hasSection(section)) return std::nullopt;
  const auto where = [&](const std::string& key) { return "[" + section + "] " + key; };
  DemoPathsOptions options;
  options.waypoints =
      parseWaypoints(config.getString(section, "waypoints"), config, where("waypoints"));
  options.speed = config.getDouble(section, "speed", options.speed);
  if (!(options.speed > 0.0)) throw InputError(config.source(), where("speed"), "must be > 0 m/s");
  options.loop = config.getBool(section, "loop", options.loop);
  const long long loopFrom = config.getInt(section, "loop_from", 1);
  if (loopFrom < 1 || loopFrom > static_cast<long long>(options.waypoints.size()))
    throw InputError(config.source(), where("loop_from"), "must be a waypoint number, 1 to n");
  options.loopFrom = static_cast<size_t>(loopFrom - 1);
  options.takeoff = config.getBool(section, "takeoff", options.takeoff);
  if (config.has(section, "gimbal_target"))
    options.gimbalTarget = config.getVector3(section, "gimbal_target");
  options.gimbalPitch = config.getDouble(section, "gimbal_pitch", 0.0) * kDegree;
  const std::string yaw = toLower(config.getString(section, "yaw", "target"));
  if (yaw == "target") {
    options.yawPolicy = options.gimbalTarget ? YawPolicy::Target : YawPolicy::Travel;
  } else if (yaw == "travel") {
    options.yawPolicy = YawPolicy::Travel;
  } else if (const auto angle = parseFiniteDouble(yaw)) {
    options.yawPolicy = YawPolicy::Fixed;
    options.fixedYaw = *angle * kDegree;
  } else {
    throw InputError(config.source(), where("yaw"),
                     "expected target, travel or an angle in degrees, got '" + yaw + "'");
  }
  options.cameraOffset = config.getVector3(section, "camera_offset", options.cameraOffset);
  options.rate = config.getDouble(section, "rate", options.rate);
  if (!(options.rate >= 10.0 && options.rate <= 400.0))
    throw InputError(config.source(), where("rate"),
                     "must be in [10, 400] Hz (setpoints expire after 0.1 s)");
  return options;
}

DemoPaths::DemoPaths(std::optional<DemoPathsOptions> options) : options_(std::move(options)) {}

double DemoPaths::decisionRate() const {
  return options_ ? options_->rate : 10.0;
}

void DemoPaths::buildPath(const Vec3& start) {
  path_.clear();
  path_.push_back(start);
  const Vec3& first = options_->waypoints.front();
  if (options_->takeoff && first.z() > start.z())
    path_.emplace_back(start.x(), start.y(), first.z());
  for (const auto& waypoint : options_->waypoints)
    if (waypoint != path_.back()) path_.push_back(waypoint);
  segment_ = 0;
  along_ = 0.0;
  finished_ = path_.size() < 2;
}

// Moves the reference point `speed * dt` along the path, unless the vehicle lags too far behind.
void DemoPaths::advance(const Vec3& position, double dt) {
  // A finished path (or one with a single point) has no segment to move along.
  if (finished_ || path_.size() < 2) return;
  const Vec3 reference =
      path_[segment_] + along_ * (path_[segment_ + 1] - path_[segment_]).normalized();
  if ((position - reference).norm() > maxLag(options_->speed)) return;
  double step = options_->speed * dt;
  while (!finished_ && step > 0.0) {
    const double length = (path_[segment_ + 1] - path_[segment_]).norm();
    if (along_ + step < length) {
      along_ += step;
      break;
    }
    step -= length - along_;
    along_ = 0.0;
    if (segment_ + 2 < path_.size()) {
      ++segment_;
    } else if (options_->loop && options_->waypoints.size() - options_->loopFrom > 1) {
      // Close the loop: rebuild the path as last waypoint -> loop start -> ... -> last.
      const Vec3 last = path_.back();
      path_.assign(1, last);
      for (size_t w = options_->loopFrom; w < options_->waypoints.size(); ++w)
        if (options_->waypoints[w] != path_.back()) path_.push_back(options_->waypoints[w]);
      segment_ = 0;
    } else {
      segment_ = path_.size() - 2;
      along_ = (path_[segment_ + 1] - path_[segment_]).norm();
      finished_ = true;
    }
  }
}

agent::AgentCommand DemoPaths::decide(const agent::AgentView& view) {
  agent::AgentCommand command;
  if (!options_ || !view.alive) return command;
  const auto& odometry = view.odometry;
  if (path_.empty()) {
    buildPath(odometry.position);
    lastTime_ = view.time;
  }
  advance(odometry.position, std::max(0.0, view.time - lastTime_));
  lastTime_ = view.time;

  Vec3 direction = Vec3::Zero();
  if (path_.size() >= 2) {
    const Vec3 delta = path_[segment_ + 1] - path_[segment_];
    if (delta.norm() > 0.0) direction = delta.normalized();
  }
  agent::AgentSetpoint setpoint;
  setpoint.position = path_.size() >= 2 ? path_[segment_] + along_ * direction : path_.front();
  setpoint.velocity = finished_ ? Vec3::Zero() : Vec3(options_->speed * direction);

  const Eigen::Matrix3d bodyRotation = (Eigen::AngleAxisd(odometry.yaw, Vec3::UnitZ()) *
                                        Eigen::AngleAxisd(odometry.pitch, Vec3::UnitY()) *
                                        Eigen::AngleAxisd(odometry.roll, Vec3::UnitX()))
                                           .toRotationMatrix();
  const Vec3 camera = odometry.position + bodyRotation * options_->cameraOffset;
  switch (options_->yawPolicy) {
    case DemoPathsOptions::YawPolicy::Target: {
      const Vec3 toTarget = *options_->gimbalTarget - camera;
      setpoint.yaw = std::hypot(toTarget.x(), toTarget.y()) > 1e-6
                         ? std::atan2(toTarget.y(), toTarget.x())
                         : odometry.yaw;
      break;
    }
    case DemoPathsOptions::YawPolicy::Travel:
      setpoint.yaw = std::hypot(direction.x(), direction.y()) > 1e-6
                         ? std::atan2(direction.y(), direction.x())
                         : odometry.yaw;
      break;
    case DemoPathsOptions::YawPolicy::Fixed:
      setpoint.yaw = options_->fixedYaw;
      break;
  }
  command.setpoint = setpoint;

  if (options_->gimbalTarget) {
    const auto aim = aimGimbal(camera, odometry.yaw, *options_->gimbalTarget);
    const auto clampTo = [](double value, double limit) {
      return limit > 0.0 ? std::clamp(value, -limit, limit) : value;
    };
    command.gimbal = agent::GimbalCommand::angles(clampTo(aim.pitch, view.gimbal.pitchMax),
                                                  clampTo(aim.yaw, view.gimbal.yawMax));
  } else {
    command.gimbal = agent::GimbalCommand::angles(options_->gimbalPitch, 0.0);
  }
  return command;
}

void registerDemoPaths(agent::StrategyRegistry& registry) {
  registry.registerStrategy("demo-paths", [](const agent::StrategyContext& context) {
    return std::make_unique<DemoPaths>(DemoPathsOptions::read(context.config, context.unitName));
  });
}

}  // namespace coinspect::strategies
