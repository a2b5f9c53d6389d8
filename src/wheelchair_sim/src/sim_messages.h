// ROS layer: the simulator's outputs as messages (conversions of wheelchair_ros).
#pragma once

#include <wheelchair_core/kinematics.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_sim/obstacle_discs.h>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <sensor_msgs/LaserScan.h>

#include <string>
#include <vector>

namespace wheelchair_sim {

nav_msgs::Odometry odometryMessage(const ros::Time& stamp, const std::string& frame,
                                   const std::string& child, const wheelchair_core::Pose2D& pose,
                                   const wheelchair_core::BodyTwist& twist);

geometry_msgs::TransformStamped transformMessage(const ros::Time& stamp, const std::string& parent,
                                                 const std::string& child,
                                                 const wheelchair_core::Pose2D& pose,
                                                 double z = 0.0);

/// All beams at the scan's stamp; a scan every 1 / rate seconds.
sensor_msgs::LaserScan scanMessage(const wheelchair_core::LaserScan2D& scan,
                                   const std::string& frame, double rate);

/// The private parameter ~obstacles: [{x, y, radius, appear_time}, ...] (radius default
/// 0.15, time default 0); none if absent. Throws std::runtime_error if it is not such a list;
/// the discs' values are checked by ObstacleDiscs::add.
std::vector<Disc> obstaclesParameter(const ros::NodeHandle& private_nh);

}  // namespace wheelchair_sim
