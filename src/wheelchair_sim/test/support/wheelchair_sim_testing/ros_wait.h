// Shared by the simulator's rostest clients: spin the node while waiting for a condition.
#pragma once

#include <ros/ros.h>

#include <functional>

namespace wheelchair_sim::test {

/// Spins until `done` or `wall_seconds` of wall time pass.
inline bool waitFor(const std::function<bool()>& done, double wall_seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(wall_seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    if (done()) return true;
    ros::WallDuration(0.001).sleep();
  }
  return false;
}

}  // namespace wheelchair_sim::test
