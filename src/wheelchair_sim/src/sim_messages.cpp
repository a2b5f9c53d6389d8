#include "sim_messages.h"

#include <wheelchair_ros/conversions.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_sim {

nav_msgs::Odometry odometryMessage(const ros::Time& stamp, const std::string& frame,
                                   const std::string& child, const wheelchair_core::Pose2D& pose,
                                   const wheelchair_core::BodyTwist& twist) {
  nav_msgs::Odometry m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.child_frame_id = child;
  m.pose.pose = wheelchair_ros::toPoseMsg(pose);
  m.twist.twist.linear.x = twist.v;
  m.twist.twist.angular.z = twist.omega;
  return m;
}

geometry_msgs::TransformStamped transformMessage(const ros::Time& stamp, const std::string& parent,
                                                 const std::string& child,
                                                 const wheelchair_core::Pose2D& pose, double z) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform = wheelchair_ros::toTransformMsg(pose);
  t.transform.translation.z = z;
  return t;
}

sensor_msgs::LaserScan scanMessage(const wheelchair_core::LaserScan2D& scan,
                                   const std::string& frame, double rate) {
  sensor_msgs::LaserScan m = wheelchair_ros::toLaserScanMsg(scan, frame);
  m.time_increment = 0.0;  // all beams at the stamp
  m.scan_time = 1.0 / rate;
  return m;
}

std::vector<Disc> obstaclesParameter(const ros::NodeHandle& private_nh) {
  XmlRpc::XmlRpcValue list;
  if (!private_nh.getParam("obstacles", list)) return {};
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray)
    throw std::runtime_error("~obstacles must be a list of {x, y, radius, appear_time}");
  std::vector<Disc> discs;
  for (int i = 0; i < list.size(); ++i) {
    auto number = [&](const char* key, double fallback) {
      if (!list[i].hasMember(key)) return fallback;
      XmlRpc::XmlRpcValue& v = list[i][key];
      return v.getType() == XmlRpc::XmlRpcValue::TypeInt ? double(int(v)) : double(v);
    };
    Disc disc;
    disc.centre = {number("x", NAN), number("y", NAN)};
    disc.radius = number("radius", disc.radius);
    disc.appear_time = number("appear_time", 0.0);
    discs.push_back(disc);
  }
  return discs;
}

}  // namespace wheelchair_sim
