#include "explorer_lidar.h"

#include <Eigen/Geometry>

#include "coinspect/sensing/key_frames.h"
#include "coinspect/sensing/lidar.h"

namespace coinspect::sim {

struct ExplorerLidar::Impl {
  sensing::LidarSimulator simulator;
  sensing::KeyFrameSelector selector;
  sensing::LidarScan scan;
  std::string unit;
  Impl(const sensing::LidarSpec& spec, uint64_t seed, std::string name)
      : simulator(spec, seed), unit(std::move(name)) {}
};

ExplorerLidar::ExplorerLidar(const sensing::LidarSpec& spec, uint64_t seed, std::string unitName)
    : impl_(std::make_unique<Impl>(spec, seed, std::move(unitName))) {}

ExplorerLidar::~ExplorerLidar() = default;

double ExplorerLidar::rate() const {
  return impl_->simulator.spec().rate;
}

size_t ExplorerLidar::keyFrameCount() const {
  return impl_->selector.keyFrames().size();
}

const sensing::LidarScan& ExplorerLidar::lastScan() const {
  return impl_->scan;
}

agent::KeyFrameView ExplorerLidar::sweep(const world::RayCaster& caster, double time,
                                         const vehicle::VehicleState& body,
                                         const std::vector<sensing::SphereOccluder>& spheres,
                                         agent::LidarView& view) {
  auto& impl = *impl_;
  Eigen::Isometry3d bodyPose = Eigen::Isometry3d::Identity();
  bodyPose.linear() = (Eigen::AngleAxisd(body.yaw, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(body.pitch, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(body.roll, Eigen::Vector3d::UnitX()))
                          .toRotationMatrix();
  bodyPose.translation() = body.position;
  impl.simulator.sweepFromBody(caster, time, bodyPose, impl.scan, spheres);

  auto world = std::make_shared<std::vector<Eigen::Vector3f>>();
  world->reserve(impl.scan.points.size());
  const Eigen::Isometry3f sensorPose = impl.scan.sensorPose.cast<float>();
  for (const auto& p : impl.scan.points)
    world->push_back(sensorPose * p);
  view.time = time;
  view.sensorPosition = impl.scan.sensorPose.translation();
  view.points = std::move(world);

  if (!impl.selector.offer(impl.scan, bodyPose)) return nullptr;
  const auto& selected = impl.selector.keyFrames().back();
  auto keyFrame = std::make_shared<agent::KeyFrame>();
  keyFrame->id = selected.id;
  keyFrame->producer = impl.unit;
  keyFrame->time = selected.time;
  keyFrame->position = selected.pose.translation();
  keyFrame->bodyOrientation = Eigen::Quaterniond(selected.pose.linear());
  keyFrame->points = selected.points;
  return keyFrame;
}

}  // namespace coinspect::sim
