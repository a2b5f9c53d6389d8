#include <tf2/utils.h>
#include <wheelchair_kld/ros/conversions.h>

#include <cmath>

namespace wheelchair_kld {

mrpt::math::TPose2D toPose2D(const geometry_msgs::Pose& pose) {
  return mrpt::math::TPose2D(pose.position.x, pose.position.y, tf2::getYaw(pose.orientation));
}

mrpt::math::TPose2D toPose2D(const geometry_msgs::Transform& t) {
  return mrpt::math::TPose2D(t.translation.x, t.translation.y, tf2::getYaw(t.rotation));
}

geometry_msgs::Pose toPoseMsg(const mrpt::math::TPose2D& pose) {
  geometry_msgs::Pose p;
  p.position.x = pose.x;
  p.position.y = pose.y;
  p.orientation.z = std::sin(pose.phi / 2);
  p.orientation.w = std::cos(pose.phi / 2);
  return p;
}

LaserScan fromScanMsg(const sensor_msgs::LaserScan& msg, const mrpt::math::TPose2D& sensor_pose) {
  LaserScan s;
  s.ranges = msg.ranges;
  s.angle_min = msg.angle_min;
  s.angle_increment = msg.angle_increment;
  s.range_min = msg.range_min;
  s.range_max = msg.range_max;
  s.sensor_pose = sensor_pose;
  return s;
}

mrpt::math::CMatrixDouble33 fromRosCovariance(const boost::array<double, 36>& cov) {
  const int idx[3] = {0, 1, 5};
  mrpt::math::CMatrixDouble33 c;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) c(r, k) = cov[idx[r] * 6 + idx[k]];
  return c;
}

geometry_msgs::PoseWithCovariance toPoseWithCovariance(const PoseEstimate& estimate) {
  geometry_msgs::PoseWithCovariance p;
  p.pose = toPoseMsg(estimate.mean);
  const int idx[3] = {0, 1, 5};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) p.covariance[idx[r] * 6 + idx[k]] = estimate.cov(r, k);
  return p;
}

geometry_msgs::PoseArray toPoseArray(const std::vector<Particle>& particles) {
  geometry_msgs::PoseArray a;
  a.poses.reserve(particles.size());
  for (const auto& p : particles) a.poses.push_back(toPoseMsg(p.d));
  return a;
}

}  // namespace wheelchair_kld
