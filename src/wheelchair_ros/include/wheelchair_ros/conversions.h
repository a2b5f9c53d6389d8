// Every ROS message <-> core type conversion of the project, in one place (cartographer_ros's
// msg_conversion): nodelets convert here and hand core types to their ROS-free cores.
#pragma once

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovariance.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Transform.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/localization_status.h>
#include <wheelchair_core/map_limits.h>
#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_msgs/LocalizationStatus.h>

#include <Eigen/Core>

#include <boost/array.hpp>

#include <string>
#include <vector>

namespace wheelchair_ros {

/// A rotation about z by `yaw` [rad].
geometry_msgs::Quaternion yawToQuaternion(double yaw);
/// The heading of `q` (its rotation about z; for a tilted q, the heading of its x axis). NaN
/// if q is not finite.
double yawOf(const geometry_msgs::Quaternion& q);
/// True if `q` is finite and of unit length within `tolerance`.
bool isNormalized(const geometry_msgs::Quaternion& q, double tolerance = 1e-3);

wheelchair_core::Pose2D toPose2D(const geometry_msgs::Pose& pose);
wheelchair_core::Pose2D toPose2D(const geometry_msgs::Transform& transform);
geometry_msgs::Pose toPoseMsg(const wheelchair_core::Pose2D& pose);
geometry_msgs::Transform toTransformMsg(const wheelchair_core::Pose2D& pose);

/// The (x, y, yaw) block of a row-major 6x6 ROS covariance (x y z roll pitch yaw) and back
/// (the other entries zero).
Eigen::Matrix3d planarCovariance(const boost::array<double, 36>& covariance);
boost::array<double, 36> toRosCovariance(const Eigen::Matrix3d& planar);
/// A planar pose with its (x, y, yaw) covariance, e.g. a localizer's estimate.
geometry_msgs::PoseWithCovariance toPoseWithCovarianceMsg(const wheelchair_core::Pose2D& pose,
                                                          const Eigen::Matrix3d& covariance);
/// Many poses in one frame, e.g. a particle filter's cloud.
geometry_msgs::PoseArray toPoseArrayMsg(const std::vector<wheelchair_core::Pose2D>& poses,
                                        const std::string& frame_id, const ros::Time& stamp);

/// The scan's fields as they are (REP-117 meanings are the core's classifyBeam).
wheelchair_core::LaserScan2D fromLaserScanMsg(const sensor_msgs::LaserScan& msg);
sensor_msgs::LaserScan toLaserScanMsg(const wheelchair_core::LaserScan2D& scan,
                                      const std::string& frame_id);

/// The 2D pose (x, y, yaw) of a laser from its 3D transform. Returns true if the laser is
/// upside down (its z axis points down): its scan angles then turn the other way
/// (wheelchair_core::mirrorScanAngles).
bool laserPose2D(const geometry_msgs::Transform& transform, wheelchair_core::Pose2D& pose);

nav_msgs::MapMetaData toMapMetaData(const wheelchair_core::OccupancyMap& map,
                                    const ros::Time& load_time);
nav_msgs::OccupancyGrid toOccupancyGrid(const wheelchair_core::OccupancyMap& map,
                                        const std::string& frame_id, const ros::Time& stamp);
/// "" if the grid is usable, else why not (wheelchair_core::mapProblem: no cells, more than
/// limits.max_cells, data size differing from width x height, resolution not finite and
/// positive, origin not finite, a cell value outside -1..100). Every consumer of /map checks
/// here before it copies or prepares anything: any node can publish a map.
std::string occupancyGridProblem(const nav_msgs::OccupancyGrid& msg,
                                 const wheelchair_core::MapLimits& limits = {});
/// Throws std::invalid_argument with occupancyGridProblem()'s reason when the grid is not usable.
wheelchair_core::OccupancyMap fromOccupancyGrid(const nav_msgs::OccupancyGrid& msg,
                                                const wheelchair_core::MapLimits& limits = {});

/// The localizer's verdict with the rider's sentence of its state (wheelchair_core::riderSentence).
wheelchair_msgs::LocalizationStatus toLocalizationStatusMsg(
    const wheelchair_core::LocalizationStatus& status, const ros::Time& stamp);

nav_msgs::Path toPathMsg(const std::vector<wheelchair_core::Pose2D>& poses,
                         const std::string& frame_id, const ros::Time& stamp);
std::vector<wheelchair_core::Pose2D> fromPathMsg(const nav_msgs::Path& path);

}  // namespace wheelchair_ros
