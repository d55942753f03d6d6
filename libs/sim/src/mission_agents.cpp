// What a strategy sees (only what its robot could know) and how its commands are applied.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>

#include "mission_impl.h"

namespace coinspect::sim {

namespace {

agent::Odometry toOdometry(const vehicle::VehicleState& state) {
  agent::Odometry odometry;
  odometry.time = state.time;
  odometry.position = state.position;
  odometry.velocity = state.velocity;
  odometry.yaw = state.yaw;
  odometry.pitch = state.pitch;
  odometry.roll = state.roll;
  odometry.angularVelocity = state.angularVelocity;
  return odometry;
}

}  // namespace

agent::AgentView Mission::Impl::observe(size_t i) {
  auto& unit = units[i];
  agent::AgentView view;
  view.name = unit.spec->name;
  view.role = unit.role;
  view.index = i;
  view.alive = unit.alive();
  view.time = now();
  view.started = started;
  view.missionTime = started ? now() - startTime : 0.0;
  view.timeLeft = budget - view.missionTime;
  view.odometry = toOdometry(unit.state());
  view.energy = unit.energy;
  if (unit.gimbal) {  // a ground station has none: its gimbal state stays zero
    const auto& camera = unit.spec->camera;
    view.gimbal.pitch = unit.gimbal->pitch();
    view.gimbal.yaw = unit.gimbal->yaw();
    view.gimbal.pitchRate = unit.gimbal->pitchRate();
    view.gimbal.yawRate = unit.gimbal->yawRate();
    view.gimbal.pitchMax = camera.gimbalPitchMax;
    view.gimbal.yawMax = camera.gimbalYawMax;
    view.gimbal.rateMax = camera.gimbalRateMax;
  }
  view.lidar = unit.lidarView;
  view.ownKeyFrames = std::move(unit.pendingOwnKeyFrames);
  unit.pendingOwnKeyFrames.clear();
  for (const auto& delivery : exchange->takeDeliveries(static_cast<uint32_t>(i)))
    view.receivedKeyFrames.push_back(units[delivery.from].keyFrames.at(delivery.keyFrameId));
  for (auto& message : network->takeInbox(static_cast<uint32_t>(i)))
    view.messages.push_back({units[message.from].spec->name, std::move(message.topic),
                             std::move(message.payload), message.sentTime});
  for (const uint32_t j : links.neighbours(static_cast<uint32_t>(i))) {
    const auto& other = units[j];
    if (!other.alive()) continue;
    agent::NeighbourInfo neighbour;
    neighbour.name = other.spec->name;
    neighbour.role = other.role;
    neighbour.odometry = toOdometry(other.state());
    view.neighbours.push_back(neighbour);
  }
  view.boxes = &boxes;
  view.captures = std::move(unit.pendingCaptures);
  unit.pendingCaptures.clear();
  view.detectedCount = unit.log.detectedCount();
  view.ownScore = unit.ownScore;
  if (features) features->fill(i, view);
  return view;
}

void Mission::Impl::decideAll() {
  using Clock = std::chrono::steady_clock;
  const auto stageStart = Clock::now();
  std::vector<size_t> deciding;
  for (size_t i = 0; i < units.size(); ++i)
    if (units[i].alive() && tick % units[i].decisionPeriod == 0) deciding.push_back(i);
  const size_t n = deciding.size();
  if (n == 0) return;  // most ticks: the loop runs at 400 Hz, strategies decide far less often
  std::vector<agent::AgentView> views(n);
  std::vector<agent::AgentCommand> commands(n);
  std::vector<double> computeTimes(n);
  const auto decideOne = [&](size_t k) {
    const auto decideStart = Clock::now();
    commands[k] = units[deciding[k]].strategy->decide(views[k]);
    computeTimes[k] = std::chrono::duration<double>(Clock::now() - decideStart).count();
  };
  const auto finish = [&](size_t k) {
    const size_t i = deciding[k];
    const double computeTime = computeTimes[k];
    ++decisionTimes.count;
    decisionTimes.total += computeTime;
    decisionTimes.max = std::max(decisionTimes.max, computeTime);
    decisionTimes.samples.push_back(static_cast<float>(computeTime));
    if (config.runMode != RunMode::Latency) {
      applyCommand(i, commands[k]);
      return;
    }
    // The command applies at the first tick at or after decision time + compute time, and never
    // before an earlier decision's command of the same unit.
    auto& unit = units[i];
    long long applyTick = tick + static_cast<long long>(std::ceil(computeTime / step - 1e-9));
    if (!unit.pendingCommands.empty())
      applyTick = std::max(applyTick, unit.pendingCommands.back().applyTick);
    unit.pendingCommands.push_back({applyTick, std::move(commands[k])});
    applyDueCommands(i);  // applies now only if the clock did not move (compute time ~ 0)
  };
  if (!workers) {
    // In fleet order, each unit seeing what the units before it just sent.
    for (size_t k = 0; k < n; ++k) {
      views[k] = observe(deciding[k]);
      decideOne(k);
      finish(k);
    }
  } else {
    // The same results on several threads. A command reaches another unit's view at this tick
    // only as a message over a link, so a unit waits only for the earlier units it is linked
    // with (observed once their commands are applied); the others decide at once. Commands are
    // applied in fleet order, as above, for the message sequence, events and rawlog order.
    std::vector<size_t> waitingFor(n, 0);
    std::vector<std::vector<size_t>> unblocks(n);
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b)
        if (links.linked(static_cast<uint32_t>(deciding[a]), static_cast<uint32_t>(deciding[b]))) {
          ++waitingFor[b];
          unblocks[a].push_back(b);
        }
    std::vector<std::future<void>> decided(n);
    const auto start = [&](size_t k) {
      views[k] = observe(deciding[k]);
      decided[k] = workers->submit([&decideOne, k] { decideOne(k); });
    };
    try {
      for (size_t k = 0; k < n; ++k)
        if (waitingFor[k] == 0) start(k);
      for (size_t k = 0; k < n; ++k) {
        decided[k].get();  // started: every unit it waited for is before it
        finish(k);
        for (const size_t b : unblocks[k])
          if (--waitingFor[b] == 0) start(b);
      }
    } catch (...) {
      for (auto& future : decided)  // the jobs refer to this frame's vectors
        if (future.valid()) future.wait();
      throw;
    }
  }
  stages.decisions += std::chrono::duration<double>(Clock::now() - stageStart).count();
}

void Mission::Impl::applyDueCommands(size_t i) {
  auto& unit = units[i];
  while (!unit.pendingCommands.empty() && unit.pendingCommands.front().applyTick <= tick) {
    // A unit that died meanwhile has no computer left to send its command.
    if (unit.alive()) applyCommand(i, unit.pendingCommands.front().command);
    unit.pendingCommands.pop_front();
  }
}

bool Mission::Impl::commandDue() const {
  for (const auto& unit : units)
    if (!unit.pendingCommands.empty() && unit.pendingCommands.front().applyTick <= tick)
      return true;
  return false;
}

void Mission::Impl::applyCommand(size_t i, const agent::AgentCommand& command) {
  auto& unit = units[i];
  const double t = now();
  if (command.setpoint) {
    vehicle::Setpoint setpoint;
    setpoint.position = command.setpoint->position;
    setpoint.velocity = command.setpoint->velocity;
    setpoint.acceleration = command.setpoint->acceleration;
    setpoint.yaw = command.setpoint->yaw;
    // A non-finite setpoint is rejected and counted by the vehicle. A ground station drives
    // toward the position's x, y only, but rejects the whole command as a UAV would (a NaN
    // target makes it count the rejection).
    if (unit.vehicle)
      unit.vehicle->command(setpoint, t);
    else
      unit.ground->setTarget(vehicle::isFinite(setpoint)
                                 ? setpoint.position
                                 : world::Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  }
  if (command.gimbal && unit.gimbal) {
    if (command.gimbal->mode == agent::GimbalCommand::Mode::Angles)
      unit.gimbal->commandAngles(command.gimbal->pitch, command.gimbal->yaw, t);
    else
      unit.gimbal->commandRates(command.gimbal->pitch, command.gimbal->yaw, t);
  }
  if (features) unit.badFeatureIds += static_cast<long long>(features->command(i, t, command));
  for (const auto& message : command.messages) {
    if (message.to.empty()) {
      network->broadcast(static_cast<uint32_t>(i), message.topic, message.bytes);
      continue;
    }
    size_t to = units.size();
    for (size_t j = 0; j < units.size(); ++j)
      if (units[j].spec->name == message.to) to = j;
    if (to == units.size() || to == i) {
      ++misaddressed;  // no such unit: dropped, like a message to nobody
      if (recorder) recorder->misaddressed(i, message.to, message.topic, message.bytes.size());
      continue;
    }
    comms::Message out;
    out.from = static_cast<uint32_t>(i);
    out.to = static_cast<uint32_t>(to);
    out.topic = message.topic;
    out.payload = message.bytes;
    out.sentTime = t;
    network->send(std::move(out));
  }
}

}  // namespace coinspect::sim
