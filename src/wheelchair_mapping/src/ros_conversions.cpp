#include <wheelchair_mapping/ros_conversions.h>

#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_mapping {

nav_msgs::MapMetaData toMapMetaData(const OccupancyMap& map, const ros::Time& load_time) {
  nav_msgs::MapMetaData info;
  info.map_load_time = load_time;
  info.resolution = static_cast<float>(map.resolution);
  info.width = static_cast<uint32_t>(map.width);
  info.height = static_cast<uint32_t>(map.height);
  info.origin.position.x = map.origin_x;
  info.origin.position.y = map.origin_y;
  info.origin.orientation.z = std::sin(map.origin_yaw / 2);
  info.origin.orientation.w = std::cos(map.origin_yaw / 2);
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

OccupancyMap fromOccupancyGrid(const nav_msgs::OccupancyGrid& msg) {
  if (msg.data.size() != static_cast<size_t>(msg.info.width) * msg.info.height) {
    throw std::invalid_argument("OccupancyGrid data size differs from width x height");
  }
  if (!(msg.info.resolution > 0)) {
    throw std::invalid_argument("OccupancyGrid resolution must be positive");
  }
  OccupancyMap map;
  map.resolution = msg.info.resolution;
  map.width = static_cast<int>(msg.info.width);
  map.height = static_cast<int>(msg.info.height);
  map.origin_x = msg.info.origin.position.x;
  map.origin_y = msg.info.origin.position.y;
  const auto& q = msg.info.origin.orientation;
  map.origin_yaw = std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
  map.data = msg.data;
  return map;
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

bool laserPose2D(const geometry_msgs::Transform& transform, Pose2D& pose) {
  const auto& q = transform.rotation;
  const tf2::Matrix3x3 r(tf2::Quaternion(q.x, q.y, q.z, q.w));
  pose = {transform.translation.x, transform.translation.y, std::atan2(r[1][0], r[0][0])};
  return r[2][2] < 0;
}

void mirrorScanAngles(LaserScan2D& scan) {
  scan.angle_min = -scan.angle_min;
  scan.angle_max = -scan.angle_max;
  scan.angle_increment = -scan.angle_increment;
}

}  // namespace wheelchair_mapping
