// pluginlib's registration of the OMPL planner (the ROS side; the class is in the core).
#include <wheelchair_ompl_planner/ompl_planner.h>

#include <pluginlib/class_list_macros.hpp>

PLUGINLIB_EXPORT_CLASS(wheelchair_ompl_planner::OmplPlanner, wheelchair_planner::GlobalPlanner)
