// What a strategy may send back after a decision: a motion setpoint, a gimbal command, messages.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/observations.h"

namespace coinspect::agent {

// The reference's command interface (position, velocity, acceleration, yaw). A held setpoint
// expires after 0.1 s in the vehicle: strategies must stream it at >= 10 Hz.
struct AgentSetpoint {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  double yaw = 0.0;  // rad
};

struct GimbalCommand {
  enum class Mode { Angles, Rates };
  Mode mode = Mode::Angles;
  double pitch = 0.0;  // rad (Angles) or rad/s (Rates); positive looks down
  double yaw = 0.0;    // rad (Angles) or rad/s (Rates); positive looks left

  static GimbalCommand angles(double pitch, double yaw) { return {Mode::Angles, pitch, yaw}; }
  static GimbalCommand rates(double pitch, double yaw) { return {Mode::Rates, pitch, yaw}; }
};

// A single-hop message; `to` empty broadcasts to every neighbour in line of sight.
struct OutgoingMessage {
  std::string to;
  std::string topic;
  std::vector<uint8_t> bytes;
};

// What a unit says it is doing (feature missions): the report splits each unit's time by it, as
// SLEI3D's idle time (travel to meetings + waiting). It does not move anything.
enum class Activity { Unreported, Exploring, Inspecting, TravellingToMeeting, Waiting, Returning };
const char* toString(Activity activity);
inline constexpr int kActivityCount = 6;

struct AgentCommand {
  std::optional<AgentSetpoint> setpoint;  // none: keep the previous one (it expires after 0.1 s)
  std::optional<GimbalCommand> gimbal;
  // The camera fires by itself every TriggerInterval (as in CARIC); a strategy cannot stop it.
  std::vector<OutgoingMessage> messages;
  // Feature missions, for the report only: the activity from now on (kept until the next one)
  // and the features this unit has just assigned to an inspector (ids out of range are
  // rejected and counted like a bad setpoint).
  std::optional<Activity> activity;
  std::vector<uint32_t> assignedFeatures;
  // Feature missions, explorers, for the report only: when this explorer plans to meet a ground
  // station next (simulated time; kept until the next one). The report's punctuality compares
  // it with when the explorer and a station were actually linked (doc/features.md).
  std::optional<double> stationMeetingTime;
};

}  // namespace coinspect::agent
