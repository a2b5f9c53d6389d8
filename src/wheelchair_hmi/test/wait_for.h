// Test helper: spins until a condition holds or a wall-clock timeout passes.
#pragma once

#include <ros/ros.h>

#include <functional>

inline bool waitFor(const std::function<bool()>& done, double seconds = 10.0) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && !done() && ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  return done();
}
