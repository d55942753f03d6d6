// LiDAR scans as MRPT observations, for rawlogs and MRPT maps. Only src/lidar_observation.cpp
// includes MRPT's observation headers: this header forward-declares the class (its ::Ptr is a
// std::shared_ptr), so users that never touch MRPT pay nothing.
#pragma once

#include <memory>
#include <string>

#include "coinspect/sensing/lidar.h"

namespace mrpt::obs {
class CObservationPointCloud;
}

namespace coinspect::sensing {

// A CObservationPointCloud (a CSimplePointsMap) with the scan's points in the SENSOR frame,
// sensorPose = the sensor pose in the BODY frame (MRPT composes it with the robot pose), timestamp
// = mrpt::Clock::fromDouble(scan.time) and sensorLabel = label (e.g. "jurong.lidar").
std::shared_ptr<mrpt::obs::CObservationPointCloud> toObservation(const LidarScan& scan,
                                                                 const std::string& label);

}  // namespace coinspect::sensing
