// The LiDAR of one explorer inside the mission: sweep, key frame selection, and the views a
// strategy receives. Kept in its own translation unit so the mission does not include the LiDAR
// headers (and their MRPT-free but large dependencies) everywhere.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/sensing/lidar_model.h"
#include "coinspect/sensing/sphere_occluder.h"
#include "coinspect/vehicle/vehicle_state.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::sensing {
struct LidarScan;
}

namespace coinspect::sim {

class ExplorerLidar {
 public:
  ExplorerLidar(const sensing::LidarSpec& spec, uint64_t seed, std::string unitName);
  ~ExplorerLidar();
  ExplorerLidar(const ExplorerLidar&) = delete;
  ExplorerLidar& operator=(const ExplorerLidar&) = delete;

  double rate() const;
  // Sweeps from the body state at `time`; other UAVs block rays as spheres.
  // Fills `view` with the world-frame points; returns a new key frame when the scan became one.
  agent::KeyFrameView sweep(const world::RayCaster& caster, double time,
                            const vehicle::VehicleState& body,
                            const std::vector<sensing::SphereOccluder>& spheres,
                            agent::LidarView& view);
  size_t keyFrameCount() const;
  // The latest sweep, points in the sensor frame (what the recorder writes).
  const sensing::LidarScan& lastScan() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coinspect::sim
