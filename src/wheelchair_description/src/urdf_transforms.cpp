#include "urdf_transforms.h"

#include <tf2/LinearMath/Transform.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace wheelchair_description {
namespace {

tf2::Transform toTf(const urdf::Pose& pose) {
  const auto& q = pose.rotation;
  const auto& t = pose.position;
  return tf2::Transform(tf2::Quaternion(q.x, q.y, q.z, q.w), tf2::Vector3(t.x, t.y, t.z));
}

/// The motion a joint adds to its origin at `position`.
tf2::Transform jointMotion(const urdf::Joint& joint, double position) {
  const tf2::Vector3 axis(joint.axis.x, joint.axis.y, joint.axis.z);
  switch (joint.type) {
    case urdf::Joint::CONTINUOUS:
    case urdf::Joint::REVOLUTE:
      return tf2::Transform(tf2::Quaternion(axis, position));
    case urdf::Joint::PRISMATIC:
      return tf2::Transform(tf2::Quaternion::getIdentity(), axis * position);
    default:
      return tf2::Transform::getIdentity();
  }
}

geometry_msgs::TransformStamped stamped(const urdf::Joint& joint, const tf2::Transform& t,
                                        const ros::Time& stamp) {
  geometry_msgs::TransformStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = joint.parent_link_name;
  msg.child_frame_id = joint.child_link_name;
  msg.transform = tf2::toMsg(t);
  return msg;
}

}  // namespace

std::vector<geometry_msgs::TransformStamped> fixedJointTransforms(const urdf::Model& model,
                                                                  const ros::Time& stamp) {
  std::vector<geometry_msgs::TransformStamped> out;
  for (const auto& [name, joint] : model.joints_)
    if (joint->type == urdf::Joint::FIXED)
      out.push_back(stamped(*joint, toTf(joint->parent_to_joint_origin_transform), stamp));
  return out;
}

std::vector<urdf::JointConstSharedPtr> movingJoints(const urdf::Model& model) {
  std::vector<urdf::JointConstSharedPtr> out;
  for (const auto& [name, joint] : model.joints_)
    if (joint->type == urdf::Joint::CONTINUOUS || joint->type == urdf::Joint::REVOLUTE ||
        joint->type == urdf::Joint::PRISMATIC)
      out.push_back(joint);
  return out;
}

geometry_msgs::TransformStamped jointTransform(const urdf::Joint& joint, double position,
                                               const ros::Time& stamp) {
  return stamped(joint, toTf(joint.parent_to_joint_origin_transform) * jointMotion(joint, position),
                 stamp);
}

}  // namespace wheelchair_description
