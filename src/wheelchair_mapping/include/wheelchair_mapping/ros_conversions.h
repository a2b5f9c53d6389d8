// OccupancyMap <-> nav_msgs/OccupancyGrid (library wheelchair_mapping_ros).
#pragma once

#include <geometry_msgs/Transform.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>
#include <wheelchair_mapping/laser_scan.h>
#include <wheelchair_mapping/occupancy_map.h>

#include <string>

namespace wheelchair_mapping {

nav_msgs::MapMetaData toMapMetaData(const OccupancyMap& map, const ros::Time& load_time);

nav_msgs::OccupancyGrid toOccupancyGrid(const OccupancyMap& map, const std::string& frame_id,
                                        const ros::Time& stamp);

/// Throws std::invalid_argument when the message's data size differs from width x height or
/// the resolution is not positive.
OccupancyMap fromOccupancyGrid(const nav_msgs::OccupancyGrid& msg);

/// The scan's fields as they are (REP-117 conventions are applied by the mapper).
LaserScan2D fromLaserScanMsg(const sensor_msgs::LaserScan& msg);

/// The 2D pose (x, y, yaw) of a laser from its 3D transform. Returns true if the laser is
/// upside down (its z axis points down): its scan angles then turn the other way.
bool laserPose2D(const geometry_msgs::Transform& transform, Pose2D& pose);

/// Turns a scan's angles the other way (for an upside-down laser).
void mirrorScanAngles(LaserScan2D& scan);

}  // namespace wheelchair_mapping
