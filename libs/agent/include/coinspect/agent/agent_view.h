// Everything a strategy sees at one decision: what its robot could know, nothing more.
#pragma once

#include <string>
#include <vector>

#include "coinspect/agent/observations.h"

namespace coinspect::agent {

struct AgentView {
  // Who am I.
  std::string name;
  Role role = Role::Photographer;
  size_t index = 0;  // position in the fleet (fixed for the mission)
  bool alive = true;

  // Time: `time` is simulated time since the simulation began; the mission clock starts at
  // take-off (`started`), and `timeLeft` counts down from the budget once it has.
  double time = 0.0;
  bool started = false;
  double missionTime = 0.0;  // since the mission clock started (0 before)
  double timeLeft = 0.0;     // budget - missionTime

  Odometry odometry;
  // Own battery level, a fraction of its capacity (FleetMember::battery); 1 when not limited.
  double energy = 1.0;
  GimbalState gimbal;
  LidarView lidar;                              // explorers; empty otherwise
  std::vector<KeyFrameView> ownKeyFrames;       // new own key frames since the last decision
  std::vector<KeyFrameView> receivedKeyFrames;  // new neighbour key frames since the last decision
  std::vector<ReceivedMessage> messages;        // arrived since the last decision
  std::vector<NeighbourInfo> neighbours;        // in line of sight now, fleet order
  const std::vector<BoxView>* boxes = nullptr;  // the mission's boxes (constant)
  std::vector<CaptureReport> captures;          // own captures since the last decision
  size_t detectedCount = 0;                     // points in the unit's own log
  double ownScore = 0.0;                        // total of the unit's own log

  // Feature missions ([mission] objective = features, doc/features.md); empty otherwise. Each
  // list holds what is new since the last decision.
  std::vector<FeatureView> detectedFeatures;  // explorers: first detections by its own detector
  std::vector<uint32_t> inspectedFeatures;    // inspections the unit itself completed
  std::vector<uint32_t> receivedResults;      // inspection results handed over at meetings
};

}  // namespace coinspect::agent
