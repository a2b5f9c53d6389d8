// ROS layer of the KLD localizer: /map, /scan and tf odom->base_link in; tf map->odom,
// /kld_pose, /particlecloud, kld/particle_count and /localization/status (the typed verdict,
// latched) out; /initialpose and the global_localization service.
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <message_filters/subscriber.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Int32.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_core/callback_cpu.h>
#include <wheelchair_kld/kld_localizer.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>
#include <wheelchair_ros/shared_tf.h>
#include <pluginlib/class_list_macros.hpp>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>

#include "localizer_node_config.h"

namespace wheelchair_kld {

using wheelchair_core::LocalizationState;
using wheelchair_core::LocalizationStatus;
using wheelchair_core::Pose2D;

class KldLocalizerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    // Callbacks (a latched /map at once) may run on the manager's worker threads while this
    // still runs: they wait until everything, last_status_ included, is set up.
    std::lock_guard<std::mutex> lock(mutex_);
    ros::NodeHandle& nh = getNodeHandle();
    config_ = wheelchair_ros::loadParameters<LocalizerNodeConfig>(getPrivateNodeHandle(),
                                                                  readLocalizerNodeConfig);
    global_on_start_ = config_.global_localization_on_start;
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();  // one /tf listener per process
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("kld_pose", 5, true);
    cloud_pub_ = nh.advertise<geometry_msgs::PoseArray>("particlecloud", 2, true);
    count_pub_ = nh.advertise<std_msgs::Int32>("kld/particle_count", 5);
    status_pub_ = nh.advertise<wheelchair_msgs::LocalizationStatus>("localization/status", 5, true);
    map_sub_ = nh.subscribe("map", 1, &KldLocalizerNodelet::onMap, this);
    // Like amcl: a scan waits (in a bounded queue, without blocking a thread) until odom ->
    // base_link is known at its stamp; odometry may lag the laser by a few tens of ms.
    scan_sub_.subscribe(nh, "scan", 5);
    scan_sub_.registerCallback(&KldLocalizerNodelet::onScanArrived, this);
    scan_filter_ = std::make_unique<tf2_ros::MessageFilter<sensor_msgs::LaserScan>>(
        scan_sub_, *tf_buffer_, config_.odom_frame, static_cast<uint32_t>(config_.scan_queue_size),
        nh);
    scan_filter_->registerCallback(&KldLocalizerNodelet::onScan, this);
    scan_filter_->registerFailureCallback(
        [this](const sensor_msgs::LaserScan::ConstPtr& msg,
               tf2_ros::filter_failure_reasons::FilterFailureReason reason) {
          onScanDropped(msg, reason);
        });
    init_sub_ = nh.subscribe("initialpose", 2, &KldLocalizerNodelet::onInitialPose, this);
    global_srv_ = nh.advertiseService("global_localization",
                                      &KldLocalizerNodelet::onGlobalLocalization, this);
    publishStatus(noData("no map yet"));
  }

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    std::lock_guard<std::mutex> lock(mutex_);
    std::shared_ptr<const LocalizationMap> map;
    try {
      map = std::make_shared<LocalizationMap>(
          wheelchair_mapping::toMrptGrid(
              wheelchair_ros::fromOccupancyGrid(*msg, config_.map_limits)),
          config_.filter.measurement.max_distance);
    } catch (const std::exception& e) {
      NODELET_ERROR("kld: map rejected: %s", e.what());
      return;
    }
    const bool had = localizer_ != nullptr;
    std::optional<PoseEstimate> keep;
    if (had && localizer_->status().localized()) keep = localizer_->estimate();
    if (had)
      NODELET_WARN("kld: new map (%ux%u cells); %s", msg->info.width, msg->info.height,
                   keep ? "keeping the current estimate" : "not localized: waiting for a pose");
    localizer_ = std::make_unique<KldLocalizer>(map, config_.filter, config_.seed);
    localizer_->setExpectedBeams(config_.expected_beams);
    if (keep) {
      localizer_->initGaussian(keep->mean, keep->cov);
    } else if (pending_init_) {
      localizer_->initGaussian(pending_init_->first, pending_init_->second);
    } else if (global_on_start_) {
      localizer_->initGlobal();
    }
    pending_init_.reset();
    publishStatus(localizer_->status());
  }

  void onInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    std::lock_guard<std::mutex> lock(mutex_);
    if (!msg->header.frame_id.empty() && msg->header.frame_id != config_.map_frame) {
      NODELET_WARN("kld: initial pose in frame '%s' ignored (expected '%s')",
                   msg->header.frame_id.c_str(), config_.map_frame.c_str());
      return;
    }
    const Pose2D pose = wheelchair_ros::toPose2D(msg->pose.pose);
    Eigen::Matrix3d cov = wheelchair_ros::planarCovariance(msg->pose.covariance);
    if (!pose.isFinite() || !cov.allFinite()) {
      NODELET_WARN("kld: initial pose with non-finite values ignored");
      return;
    }
    if (cov(0, 0) <= 0 && cov(1, 1) <= 0 && cov(2, 2) <= 0) {  // rviz may send zeros
      cov(0, 0) = cov(1, 1) = 0.25 * 0.25;
      cov(2, 2) = 0.26 * 0.26;
    }
    NODELET_INFO("kld: initial pose (%.2f, %.2f, %.1f deg)", pose.x, pose.y, pose.yaw * 180 / M_PI);
    if (localizer_)
      localizer_->initGaussian(pose, cov);
    else
      pending_init_ = std::make_pair(pose, cov);
  }

  bool onGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!localizer_) {
      NODELET_WARN("kld: global localization requested before a map arrived; will start then");
      global_on_start_ = true;
      return true;
    }
    NODELET_INFO("kld: global localization over the free space");
    localizer_->initGlobal();
    return true;
  }

  /// Every scan as it arrives (before the tf wait): reports a sustained tf failure -- no scan
  /// could be used for tf_timeout although scans keep coming -- as not localized. A single late
  /// or dropped scan never changes the status.
  void onScanArrived(const sensor_msgs::LaserScan::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time now = ros::Time::now();
    if (last_tf_ok_.isZero() || now < last_tf_ok_) last_tf_ok_ = now;  // start, or time reset
    if (!tf_buffer_->_frameExists(msg->header.frame_id))
      warnThrottled("tf frame",
                    "kld: scan skipped, tf missing: unknown frame '" + msg->header.frame_id + "'");
    if ((now - last_tf_ok_).toSec() > config_.tf_timeout) {
      std::ostringstream why;
      why << "tf missing: no " << config_.odom_frame << " -> " << config_.base_frame
          << " transform at the scan times for more than " << config_.tf_timeout << " s";
      publishStatus(noData(why.str()));
    }
  }

  /// A scan the message filter gave up on (queue full, or older than the tf buffer).
  void onScanDropped(const sensor_msgs::LaserScan::ConstPtr& msg,
                     tf2_ros::filter_failure_reasons::FilterFailureReason reason) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::ostringstream text;
    text << "kld: scan skipped, tf missing: no " << config_.odom_frame << " -> '"
         << msg->header.frame_id << "' transform at its stamp "
         << (reason == tf2_ros::filter_failure_reasons::OutTheBack ? "(older than the tf buffer)"
                                                                   : "(scan queue full)");
    warnThrottled("tf dropped", text.str());
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    std::lock_guard<std::mutex> lock(mutex_);
    if (!localizer_) {
      publishStatus(noData("no map yet"));
      return;
    }
    // A scan the filter released after a newer one is already past (more than 1 s back: the
    // clock was reset, e.g. a restarted simulator, and the scan is taken).
    if (msg->header.stamp <= last_scan_stamp_ &&
        msg->header.stamp + ros::Duration(1.0) > last_scan_stamp_)
      return;
    Pose2D odom, laser;
    wheelchair_core::LaserScan2D scan = wheelchair_ros::fromLaserScanMsg(*msg);
    try {
      odom = wheelchair_ros::toPose2D(
          tf_buffer_->lookupTransform(config_.odom_frame, config_.base_frame, msg->header.stamp)
              .transform);
      const auto mount =
          tf_buffer_->lookupTransform(config_.base_frame, msg->header.frame_id, ros::Time(0))
              .transform;
      if (wheelchair_ros::laserPose2D(mount, laser)) wheelchair_core::mirrorScanAngles(scan);
    } catch (const tf2::TransformException& e) {
      warnThrottled("tf", std::string("kld: scan skipped, tf missing: ") + e.what());
      return;
    }
    last_scan_stamp_ = msg->header.stamp;
    last_tf_ok_ = ros::Time::now();
    const auto result = localizer_->update(odom, scan, laser);
    if (result == UpdateResult::kRejected) {
      warnThrottled(localizer_->lastRejection(),
                    "kld: scan rejected: " + localizer_->lastRejection());
      publishStatus(noData("bad scan: " + localizer_->lastRejection()));
      return;
    }
    const auto status = localizer_->status();
    publishStatus(status);
    if (!localizer_->initialized()) return;
    if (result == UpdateResult::kUpdated) publishEstimate(msg->header.stamp);
    publishMapToOdom(msg->header.stamp, odom);
  }

  void publishEstimate(const ros::Time& stamp) {
    geometry_msgs::PoseWithCovarianceStamped pose;
    pose.header.stamp = stamp;
    pose.header.frame_id = config_.map_frame;
    pose.pose = wheelchair_ros::toPoseWithCovarianceMsg(localizer_->estimate().mean,
                                                        localizer_->estimate().cov);
    pose_pub_.publish(pose);
    cloud_pub_.publish(
        wheelchair_ros::toPoseArrayMsg(localizer_->particlePoses(), config_.map_frame, stamp));
    std_msgs::Int32 count;
    count.data = static_cast<int>(localizer_->particleCount());
    count_pub_.publish(count);
  }

  /// map->odom = estimate (map->base_link) composed with the inverse of odom->base_link,
  /// future-dated by the transform tolerance (REP-105).
  void publishMapToOdom(const ros::Time& stamp, const Pose2D& odom) {
    geometry_msgs::TransformStamped t;
    t.header.stamp = stamp + ros::Duration(config_.transform_tolerance);
    t.header.frame_id = config_.map_frame;
    t.child_frame_id = config_.odom_frame;
    t.transform = wheelchair_ros::toTransformMsg(
        wheelchair_core::compose(localizer_->estimate().mean, wheelchair_core::inverse(odom)));
    tf_broadcaster_.sendTransform(t);
  }

  /// A warning at most every 2 s per reason (so that each kind of bad input is named).
  void warnThrottled(const std::string& reason, const std::string& text) {
    const ros::WallTime now = ros::WallTime::now();
    auto it = last_warning_.find(reason);
    if (it != last_warning_.end() && (now - it->second).toSec() < 2.0) return;
    if (last_warning_.size() > 100) last_warning_.clear();  // reasons embed numbers
    last_warning_[reason] = now;
    NODELET_WARN("%s", text.c_str());
  }

  /// No map, or no usable scan / tf: the filter's numbers (if any) with that reason.
  LocalizationStatus noData(const std::string& why) const {
    LocalizationStatus s = localizer_ ? localizer_->status() : LocalizationStatus();
    s.state = LocalizationState::kNoData;
    s.detail = why;
    return s;
  }

  /// The verdict on /localization/status (the supervisor's, controller's and HMI's input),
  /// logged when its text changes.
  void publishStatus(const LocalizationStatus& status) {
    const std::string text = status.localized() ? "localized" : status.detail;
    if (text != last_status_) {
      if (status.localized())
        NODELET_INFO("kld: localized");
      else
        warnThrottled("status: " + status.detail, "kld: not localized: " + status.detail);
      last_status_ = text;
    }
    status_pub_.publish(wheelchair_ros::toLocalizationStatusMsg(status, ros::Time::now()));
  }

  LocalizerNodeConfig config_;
  ros::Time last_tf_ok_, last_scan_stamp_;
  bool global_on_start_ = false;  ///< from the config, or asked for before the map came
  std::mutex mutex_;
  std::unique_ptr<KldLocalizer> localizer_;
  std::optional<std::pair<Pose2D, Eigen::Matrix3d>> pending_init_;
  std::string last_status_;
  std::map<std::string, ros::WallTime> last_warning_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Publisher pose_pub_, cloud_pub_, count_pub_, status_pub_;
  message_filters::Subscriber<sensor_msgs::LaserScan> scan_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::LaserScan>> scan_filter_;
  ros::Subscriber map_sub_, init_sub_;
  ros::ServiceServer global_srv_;
};

}  // namespace wheelchair_kld

PLUGINLIB_EXPORT_CLASS(wheelchair_kld::KldLocalizerNodelet, nodelet::Nodelet)
