// Joint transforms of a URDF model as tf2 messages (the part of robot_state_publisher we need).
#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <urdf/model.h>

#include <vector>

namespace wheelchair_description {

/// Parent-to-child transforms of all fixed joints (for /tf_static).
std::vector<geometry_msgs::TransformStamped> fixedJointTransforms(const urdf::Model& model,
                                                                  const ros::Time& stamp);

/// Joints that move (continuous, revolute, prismatic).
std::vector<urdf::JointConstSharedPtr> movingJoints(const urdf::Model& model);

/// Parent-to-child transform of `joint` at joint position `position` (rad or m).
geometry_msgs::TransformStamped jointTransform(const urdf::Joint& joint, double position,
                                               const ros::Time& stamp);

}  // namespace wheelchair_description
