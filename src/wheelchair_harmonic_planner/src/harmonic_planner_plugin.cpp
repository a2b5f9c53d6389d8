// pluginlib's registration of the harmonic planner (the ROS side; the class is in the core).
#include <wheelchair_harmonic_planner/harmonic_planner.h>

#include <pluginlib/class_list_macros.hpp>

PLUGINLIB_EXPORT_CLASS(wheelchair_harmonic_planner::HarmonicPlanner,
                       wheelchair_planner::GlobalPlanner)
