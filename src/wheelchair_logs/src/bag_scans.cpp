#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2_msgs/TFMessage.h>
#include <wheelchair_logs/bag_scans.h>
#include <wheelchair_ros/conversions.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace wheelchair_logs {

struct BagScanReader::Impl {
  rosbag::Bag bag;
  std::unique_ptr<tf2::BufferCore> tf;
  std::unique_ptr<rosbag::View> scans;
  rosbag::View::iterator it;
  size_t index = 0;
  size_t count = 1;
};

BagScanReader::BagScanReader(const std::string& path, const std::string& scan_topic,
                             const std::string& fixed_frame, const std::string& base_frame,
                             const std::string& odom_topic)
    : impl_(std::make_unique<Impl>()),
      path_(path),
      fixed_frame_(fixed_frame),
      base_frame_(base_frame) {
  try {
    impl_->bag.open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    throw std::runtime_error(path + ": cannot open bag (" + e.what() + ")");
  }
  std::vector<std::string> tf_topics{"/tf", "/tf_static"};
  if (!odom_topic.empty()) tf_topics.push_back(odom_topic);
  rosbag::View tf_view(impl_->bag, rosbag::TopicQuery(tf_topics));
  const ros::Duration length = tf_view.getEndTime() - tf_view.getBeginTime();
  impl_->tf = std::make_unique<tf2::BufferCore>(length + ros::Duration(10.0));
  for (const rosbag::MessageInstance& m : tf_view) {
    const bool is_static = m.getTopic() == "/tf_static";
    if (auto msg = m.instantiate<tf2_msgs::TFMessage>()) {
      for (const auto& t : msg->transforms) impl_->tf->setTransform(t, "bag", is_static);
    } else if (auto odom = m.instantiate<nav_msgs::Odometry>()) {
      geometry_msgs::TransformStamped t;
      t.header = odom->header;
      t.child_frame_id = odom->child_frame_id;
      t.transform.translation.x = odom->pose.pose.position.x;
      t.transform.translation.y = odom->pose.pose.position.y;
      t.transform.translation.z = odom->pose.pose.position.z;
      t.transform.rotation = odom->pose.pose.orientation;
      impl_->tf->setTransform(t, "bag");
    }
  }
  impl_->scans = std::make_unique<rosbag::View>(impl_->bag, rosbag::TopicQuery(scan_topic));
  impl_->count = std::max<size_t>(1, impl_->scans->size());
  impl_->it = impl_->scans->begin();
}

BagScanReader::~BagScanReader() = default;

double BagScanReader::progress() const {
  return std::min(1.0, static_cast<double>(impl_->index) / impl_->count);
}

bool BagScanReader::next(LogScan& out) {
  problems_.clear();
  for (; impl_->it != impl_->scans->end(); ++impl_->it) {
    const size_t index = ++impl_->index;
    auto msg = impl_->it->instantiate<sensor_msgs::LaserScan>();
    if (!msg) continue;
    geometry_msgs::TransformStamped t, base;
    try {
      t = impl_->tf->lookupTransform(fixed_frame_, msg->header.frame_id, msg->header.stamp);
      if (!base_frame_.empty())
        base = impl_->tf->lookupTransform(fixed_frame_, base_frame_, msg->header.stamp);
    } catch (const tf2::TransformException& e) {
      ++skipped_;
      if (!problems_.empty()) problems_ += "\n";
      problems_ += path_ + ":scan " + std::to_string(index) + ": no tf: " + e.what();
      continue;
    }
    out.scan = wheelchair_ros::fromLaserScanMsg(*msg);
    if (wheelchair_ros::laserPose2D(t.transform, out.laser_pose))
      wheelchair_core::mirrorScanAngles(out.scan);
    out.odom_pose = base_frame_.empty() ? out.laser_pose : wheelchair_ros::toPose2D(base.transform);
    out.line = index;
    ++impl_->it;
    return true;
  }
  return false;
}

}  // namespace wheelchair_logs
