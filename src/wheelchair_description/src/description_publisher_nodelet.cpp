// The chair's robot model: /robot_description from the chair file, fixed joints on /tf_static,
// wheel joints from /joint_states on /tf (angle zero until the first message) at most at
// ~publish_frequency.
#include <wheelchair_core/callback_cpu.h>
#include <wheelchair_core/config.h>
#include <wheelchair_description/chair_file.h>
#include <wheelchair_description/urdf_generator.h>
#include <wheelchair_ros/parameters.h>

#include "urdf_transforms.h"

#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <pluginlib/class_list_macros.hpp>

#include <cmath>
#include <map>
#include <memory>

namespace wheelchair_description {

namespace {

/// The publisher's private parameters.
struct PublisherSettings {
  std::string chair_file;           ///< "" = wheelchair_description's own (defaultChairFile)
  double publish_frequency = 20.0;  ///< [Hz] most wheel transforms per second; 0 = no timer
  std::string validate() const {
    return wheelchair_core::ConfigChecks()
        .nonNegative("publish_frequency", publish_frequency)
        .result();
  }
};

void readPublisherSettings(wheelchair_core::ConfigReader& reader, PublisherSettings& s) {
  reader.renamed("chair_params", "chair_file");
  reader.read("chair_file", s.chair_file);
  reader.read("publish_frequency", s.publish_frequency);
}

}  // namespace

class DescriptionPublisherNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    const auto settings =
        wheelchair_ros::loadParameters<PublisherSettings>(pnh, readPublisherSettings);
    std::string chair_file, urdf;
    try {
      chair_file = resolveChairFile(settings.chair_file);
      urdf = chairUrdf(loadChairParams(chair_file));
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    if (!model_.initString(urdf)) throw std::runtime_error("generated URDF does not parse");
    nh.setParam("robot_description", urdf);
    for (const auto& joint : movingJoints(model_)) positions_[joint->name] = {joint, 0.0};

    static_broadcaster_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
    broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    static_broadcaster_->sendTransform(fixedJointTransforms(model_, ros::Time::now()));
    joint_sub_ =
        nh.subscribe("joint_states", 10, &DescriptionPublisherNodelet::onJointStates, this);
    if (settings.publish_frequency > 0.0) {
      period_ = ros::Duration(1.0 / settings.publish_frequency);
      timer_ = nh.createTimer(period_, &DescriptionPublisherNodelet::onTimer, this);
    }
    NODELET_INFO("robot_description from %s; %zu moving joints", chair_file.c_str(),
                 positions_.size());
  }

  void onJointStates(const sensor_msgs::JointState::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    if (msg->position.size() != msg->name.size()) {
      NODELET_WARN_THROTTLE(5.0, "joint_states ignored: %zu names but %zu positions",
                            msg->name.size(), msg->position.size());
      return;
    }
    for (std::size_t i = 0; i < msg->name.size(); ++i) {
      const auto it = positions_.find(msg->name[i]);
      if (it == positions_.end()) continue;
      if (!std::isfinite(msg->position[i])) {
        NODELET_WARN_THROTTLE(5.0, "joint_states: non-finite position of %s ignored",
                              msg->name[i].c_str());
        continue;
      }
      it->second.position = msg->position[i];
    }
    last_message_ = ros::Time::now();
    const ros::Time stamp = msg->header.stamp.isZero() ? last_message_ : msg->header.stamp;
    // At most publish_frequency, not at every /joint_states (the base driver's 50 Hz): only
    // rviz needs the wheel angles, and every /tf message wakes every tf listener.
    if (stamp - last_stamp_ >= period_) publishMovingJoints(stamp);
  }

  /// Keeps the wheels in the tree while no joint_states arrive (at their last angles, stamped
  /// now), whatever the stamps of the messages are.
  void onTimer(const ros::TimerEvent&) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    const ros::Time now = ros::Time::now();
    if (last_message_.isZero() || now - last_message_ >= period_) publishMovingJoints(now);
  }

  void publishMovingJoints(const ros::Time& stamp) {
    if (stamp <= last_stamp_) return;  // tf rejects repeated or older data
    std::vector<geometry_msgs::TransformStamped> transforms;
    for (const auto& [name, joint] : positions_)
      transforms.push_back(jointTransform(*joint.joint, joint.position, stamp));
    broadcaster_->sendTransform(transforms);
    last_stamp_ = stamp;
  }

  struct JointPosition {
    urdf::JointConstSharedPtr joint;
    double position = 0.0;
  };

  urdf::Model model_;
  std::map<std::string, JointPosition> positions_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> broadcaster_;
  ros::Subscriber joint_sub_;
  ros::Timer timer_;
  ros::Duration period_{0.05};
  ros::Time last_stamp_;    ///< stamp of the last wheel transforms sent
  ros::Time last_message_;  ///< arrival of the last joint_states
};

}  // namespace wheelchair_description

PLUGINLIB_EXPORT_CLASS(wheelchair_description::DescriptionPublisherNodelet, nodelet::Nodelet)
