#include "coinspect/sensing/lidar_observation.h"

#include <mrpt/core/Clock.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/poses/CPose3D.h>

namespace coinspect::sensing {

std::shared_ptr<mrpt::obs::CObservationPointCloud> toObservation(const LidarScan& scan,
                                                                 const std::string& label) {
  auto observation = std::make_shared<mrpt::obs::CObservationPointCloud>();
  auto cloud = std::make_shared<mrpt::maps::CSimplePointsMap>();
  cloud->reserve(scan.points.size());
  for (const auto& p : scan.points)
    cloud->insertPointFast(p.x(), p.y(), p.z());
  // insertPointFast skips the map's bookkeeping; one mark after the batch keeps it consistent.
  cloud->mark_as_modified();
  observation->pointcloud = cloud;
  const Eigen::Matrix4d m = scan.sensorPoseInBody.matrix();
  observation->sensorPose = mrpt::poses::CPose3D::FromHomogeneousMatrix(m);
  observation->timestamp = mrpt::Clock::fromDouble(scan.time);
  observation->sensorLabel = label;
  return observation;
}

}  // namespace coinspect::sensing
