// What a robot can observe about itself and its surroundings, as plain data. The agent library
// depends on core and Eigen only: strategies never see meshes, interest points or another unit's
// hidden state, and these structs carry nothing of the kind.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace coinspect::agent {

using Vec3 = Eigen::Vector3d;

enum class Role { GroundStation, Explorer, Photographer };
const char* toString(Role role);

// Ground-truth odometry of one unit (the reference publishes it without noise).
struct Odometry {
  double time = 0.0;                          // s, simulated
  Vec3 position = Vec3::Zero();               // world frame, m
  Vec3 velocity = Vec3::Zero();               // world frame, m/s
  double yaw = 0.0, pitch = 0.0, roll = 0.0;  // Z-Y-X Euler angles, rad
  Vec3 angularVelocity = Vec3::Zero();        // body frame, rad/s
};

// Gimbal angles relative to the stabilizer (yaw-only) frame; positive pitch looks down.
struct GimbalState {
  double pitch = 0.0, yaw = 0.0;                       // rad
  double pitchRate = 0.0, yawRate = 0.0;               // rad/s
  double pitchMax = 0.0, yawMax = 0.0, rateMax = 0.0;  // limits (rad, rad/s)
};

// A LiDAR key frame: points already in the world frame, shared between receivers without copies.
struct KeyFrame {
  uint64_t id = 0;  // unique per producing unit
  std::string producer;
  double time = 0.0;
  Vec3 position = Vec3::Zero();  // body position when the scan was taken
  Eigen::Quaterniond bodyOrientation = Eigen::Quaterniond::Identity();
  std::vector<Eigen::Vector3f> points;  // world frame, downsampled
};
using KeyFrameView = std::shared_ptr<const KeyFrame>;

// The latest LiDAR sweep of the unit itself (explorers only), world frame.
struct LidarView {
  double time = 0.0;
  Vec3 sensorPosition = Vec3::Zero();
  std::shared_ptr<const std::vector<Eigen::Vector3f>> points;  // null before the first sweep
};

struct ReceivedMessage {
  std::string from;
  std::string topic;
  std::vector<uint8_t> bytes;
  double time = 0.0;  // when it was sent (and delivered: links have no latency in CARIC)
};

// A unit in line of sight this decision, with its odometry (the reference shares it over ppcom).
struct NeighbourInfo {
  std::string name;
  Role role = Role::Photographer;
  Odometry odometry;
};

// One capture of the unit's own camera: how much it brought, never which points.
struct CaptureReport {
  double time = 0.0;
  size_t pointsCounted = 0;   // points of this capture with score >= 0.2
  size_t pointsImproved = 0;  // of those, how many beat the unit's previous best
  double scoreGained = 0.0;   // increase of the unit's own-log total
};

// A feature found by the unit's own detector (feature missions, doc/features.md). The index
// names the feature for every robot (as a tag would); position and normal are what the detector
// measured, exactly.
struct FeatureView {
  uint32_t id = 0;
  Vec3 position = Vec3::Zero();  // world frame, m
  Vec3 normal = Vec3::Zero();    // unit, pointing out of the surface
  double time = 0.0;             // s, simulated, when it was detected
  bool highPriority = false;     // its tag marks it urgent ([features] priority_boxes)
};

// The unit's own camera, as its owner configured it (the ppcom network file in CARIC).
struct CameraInfo {
  double horizontalFov = 0.0, verticalFov = 0.0;  // rad
  Vec3 positionInBody = Vec3::Zero();             // m
  double exposureTime = 0.0;                      // s
  double triggerInterval = 0.0;                   // s
  double focalLength = 0.0;                       // m
  double pixelSize = 0.0;                         // m
  double desiredMmPerPixel = 0.0;                 // r_des, mm/px
};

// A UAV's battery ([energy], doc/features.md, "Energy"): its spec sheet, known to the fleet.
// capacity 0: not limited.
struct BatterySpec {
  double capacity = 0.0;     // s of flight from full to empty
  double chargeTime = 0.0;   // s from empty to full at a station's charger
  double chargeRange = 0.0;  // m from a live ground station within which it charges
  bool limited() const { return capacity > 0.0; }
};

// A member of the fleet: names and roles are public (every unit reads the same network file).
struct FleetMember {
  FleetMember() = default;
  FleetMember(std::string name, Role role, double detectRange = 0.0, BatterySpec battery = {})
      : name(std::move(name)), role(role), detectRange(detectRange), battery(battery) {}

  std::string name;
  Role role = Role::Photographer;
  // m, an explorer's feature detector range in a feature mission (its spec sheet, known to the
  // fleet: [features] explorer_ranges); 0 otherwise.
  double detectRange = 0.0;
  BatterySpec battery;
};

// A bounding box of the mission (CARIC publishes them to every unit).
struct BoxView {
  Vec3 center = Vec3::Zero();
  Vec3 size = Vec3::Zero();                                // full edges along the box axes
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // columns: box axes in the world
  bool highPriority = false;  // feature missions: an urgent area ([features] priority_boxes)
};

}  // namespace coinspect::agent
