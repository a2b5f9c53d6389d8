// ROS message <-> core conversions of the localizer (library wheelchair_kld_ros).
#pragma once

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Transform.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPose2D.h>
#include <sensor_msgs/LaserScan.h>
#include <wheelchair_kld/laser_scan.h>
#include <wheelchair_kld/pose_estimate.h>

#include <vector>

namespace wheelchair_kld {

mrpt::math::TPose2D toPose2D(const geometry_msgs::Pose& pose);
mrpt::math::TPose2D toPose2D(const geometry_msgs::Transform& transform);
geometry_msgs::Pose toPoseMsg(const mrpt::math::TPose2D& pose);

/// Ranges as sent (NaN stays NaN so validateScan can reject it); `sensor_pose` is the laser
/// frame in base_link.
LaserScan fromScanMsg(const sensor_msgs::LaserScan& msg, const mrpt::math::TPose2D& sensor_pose);

/// The (x, y, yaw) block of a 6x6 ROS covariance and back.
mrpt::math::CMatrixDouble33 fromRosCovariance(const boost::array<double, 36>& cov);
geometry_msgs::PoseWithCovariance toPoseWithCovariance(const PoseEstimate& estimate);

geometry_msgs::PoseArray toPoseArray(const std::vector<Particle>& particles);

}  // namespace wheelchair_kld
