#include <wheelchair_ros/conversions.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_ros {

using wheelchair_core::LaserScan2D;
using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;

geometry_msgs::Quaternion yawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2);
  q.w = std::cos(yaw / 2);
  return q;
}

double yawOf(const geometry_msgs::Quaternion& q) {
  // The x axis of the rotated frame projected on the ground: atan2(R10, R00).
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

bool isNormalized(const geometry_msgs::Quaternion& q, double tolerance) {
  const double n2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  return std::isfinite(n2) && std::abs(n2 - 1.0) <= tolerance;
}

Pose2D toPose2D(const geometry_msgs::Pose& pose) {
  return {pose.position.x, pose.position.y, yawOf(pose.orientation)};
}

Pose2D toPose2D(const geometry_msgs::Transform& t) {
  return {t.translation.x, t.translation.y, yawOf(t.rotation)};
}

geometry_msgs::Pose toPoseMsg(const Pose2D& pose) {
  geometry_msgs::Pose p;
  p.position.x = pose.x;
  p.position.y = pose.y;
  p.orientation = yawToQuaternion(pose.yaw);
  return p;
}

geometry_msgs::Transform toTransformMsg(const Pose2D& pose) {
  geometry_msgs::Transform t;
  t.translation.x = pose.x;
  t.translation.y = pose.y;
  t.rotation = yawToQuaternion(pose.yaw);
  return t;
}

namespace {
constexpr int kPlanar[3] = {0, 1, 5};  // x, y, yaw in the 6x6 order x y z roll pitch yaw
}

Eigen::Matrix3d planarCovariance(const boost::array<double, 36>& cov) {
  Eigen::Matrix3d c;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) c(r, k) = cov[kPlanar[r] * 6 + kPlanar[k]];
  return c;
}

boost::array<double, 36> toRosCovariance(const Eigen::Matrix3d& planar) {
  boost::array<double, 36> cov{};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) cov[kPlanar[r] * 6 + kPlanar[k]] = planar(r, k);
  return cov;
}

geometry_msgs::PoseWithCovariance toPoseWithCovarianceMsg(const Pose2D& pose,
                                                          const Eigen::Matrix3d& covariance) {
  geometry_msgs::PoseWithCovariance p;
  p.pose = toPoseMsg(pose);
  p.covariance = toRosCovariance(covariance);
  return p;
}

geometry_msgs::PoseArray toPoseArrayMsg(const std::vector<Pose2D>& poses,
                                        const std::string& frame_id, const ros::Time& stamp) {
  geometry_msgs::PoseArray a;
  a.header.frame_id = frame_id;
  a.header.stamp = stamp;
  a.poses.reserve(poses.size());
  for (const Pose2D& p : poses) a.poses.push_back(toPoseMsg(p));
  return a;
}

LaserScan2D fromLaserScanMsg(const sensor_msgs::LaserScan& msg) {
  LaserScan2D scan;
  scan.stamp = msg.header.stamp.toSec();
  scan.angle_min = msg.angle_min;
  scan.angle_max = msg.angle_max;
  scan.angle_increment = msg.angle_increment;
  scan.range_min = msg.range_min;
  scan.range_max = msg.range_max;
  scan.ranges = msg.ranges;
  return scan;
}

sensor_msgs::LaserScan toLaserScanMsg(const LaserScan2D& scan, const std::string& frame_id) {
  sensor_msgs::LaserScan msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp.fromSec(scan.stamp);
  msg.angle_min = static_cast<float>(scan.angle_min);
  msg.angle_max = static_cast<float>(scan.angle_max);
  msg.angle_increment = static_cast<float>(scan.angle_increment);
  msg.range_min = static_cast<float>(scan.range_min);
  msg.range_max = static_cast<float>(scan.range_max);
  msg.ranges = scan.ranges;
  return msg;
}

bool laserPose2D(const geometry_msgs::Transform& transform, Pose2D& pose) {
  const auto& q = transform.rotation;
  // Rotation matrix entries R00, R10, R22 of the unit quaternion.
  const double r00 = 1.0 - 2.0 * (q.y * q.y + q.z * q.z);
  const double r10 = 2.0 * (q.x * q.y + q.w * q.z);
  const double r22 = 1.0 - 2.0 * (q.x * q.x + q.y * q.y);
  pose = {transform.translation.x, transform.translation.y, std::atan2(r10, r00)};
  return r22 < 0;
}

nav_msgs::MapMetaData toMapMetaData(const OccupancyMap& map, const ros::Time& load_time) {
  nav_msgs::MapMetaData info;
  info.map_load_time = load_time;
  info.resolution = static_cast<float>(map.resolution);
  info.width = static_cast<uint32_t>(map.width);
  info.height = static_cast<uint32_t>(map.height);
  info.origin.position.x = map.origin_x;
  info.origin.position.y = map.origin_y;
  info.origin.orientation = yawToQuaternion(map.origin_yaw);
  return info;
}

nav_msgs::OccupancyGrid toOccupancyGrid(const OccupancyMap& map, const std::string& frame_id,
                                        const ros::Time& stamp) {
  nav_msgs::OccupancyGrid msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.info = toMapMetaData(map, stamp);
  msg.data = map.data;
  return msg;
}

std::string occupancyGridProblem(const nav_msgs::OccupancyGrid& msg,
                                 const wheelchair_core::MapLimits& limits) {
  const auto& o = msg.info.origin;
  const auto& q = o.orientation;
  // An all-zero quaternion (a default-constructed message) reads as no rotation.
  if (!std::isfinite(q.x + q.y + q.z + q.w)) return "map origin is not finite";
  return wheelchair_core::mapProblem(msg.info.width, msg.info.height, msg.info.resolution,
                                     o.position.x, o.position.y, msg.data, limits);
}

OccupancyMap fromOccupancyGrid(const nav_msgs::OccupancyGrid& msg,
                               const wheelchair_core::MapLimits& limits) {
  const std::string problem = occupancyGridProblem(msg, limits);
  if (!problem.empty()) throw std::invalid_argument(problem);
  const auto& o = msg.info.origin;
  OccupancyMap map;
  map.resolution = msg.info.resolution;
  map.width = static_cast<int>(msg.info.width);
  map.height = static_cast<int>(msg.info.height);
  map.origin_x = o.position.x;
  map.origin_y = o.position.y;
  map.origin_yaw = yawOf(o.orientation);
  map.data = msg.data;
  return map;
}

wheelchair_msgs::LocalizationStatus toLocalizationStatusMsg(
    const wheelchair_core::LocalizationStatus& status, const ros::Time& stamp) {
  using State = wheelchair_core::LocalizationState;
  using Msg = wheelchair_msgs::LocalizationStatus;
  Msg m;
  m.header.stamp = stamp;
  switch (status.state) {
    case State::kUninitialized:
      m.state = Msg::UNINITIALIZED;
      break;
    case State::kLocalizing:
      m.state = Msg::LOCALIZING;
      break;
    case State::kLocalized:
      m.state = Msg::LOCALIZED;
      break;
    case State::kAmbiguous:
      m.state = Msg::AMBIGUOUS;
      break;
    case State::kUncertain:
      m.state = Msg::UNCERTAIN;
      break;
    case State::kMisfit:
      m.state = Msg::MISFIT;
      break;
    case State::kNoData:
      m.state = Msg::NO_DATA;
      break;
  }
  m.localized = status.localized();
  m.sentence = wheelchair_core::riderSentence(status.state);
  m.detail = status.detail;
  m.position_std = status.position_std;
  m.heading_std = status.heading_std;
  m.inlier_fraction = status.inlier_fraction;
  m.mean_fit = status.mean_fit;
  m.hypotheses = status.hypotheses;
  m.best_weight = status.best_weight;
  m.particles = status.particles;
  return m;
}

nav_msgs::Path toPathMsg(const std::vector<Pose2D>& poses, const std::string& frame_id,
                         const ros::Time& stamp) {
  nav_msgs::Path path;
  path.header.frame_id = frame_id;
  path.header.stamp = stamp;
  path.poses.resize(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    path.poses[i].header = path.header;
    path.poses[i].pose = toPoseMsg(poses[i]);
  }
  return path;
}

std::vector<Pose2D> fromPathMsg(const nav_msgs::Path& path) {
  std::vector<Pose2D> poses;
  poses.reserve(path.poses.size());
  for (const auto& p : path.poses) poses.push_back(toPose2D(p.pose));
  return poses;
}

}  // namespace wheelchair_ros
