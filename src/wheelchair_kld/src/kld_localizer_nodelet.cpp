// ROS layer of the KLD localizer: /map, /scan and tf odom->base_link in; tf map->odom,
// /kld_pose, /particlecloud, kld/particle_count and kld/localized ("localized" or the reason
// why not) out; /initialpose and the global_localization service.
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <message_filters/subscriber.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Int32.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_kld/kld_localizer.h>
#include <wheelchair_kld/ros/conversions.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/shared_tf.h>
#include <Eigen/Dense>
#include <pluginlib/class_list_macros.hpp>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>

namespace wheelchair_kld {

namespace {
KldParams loadParams(const ros::NodeHandle& pnh) {
  KldParams p;
  pnh.param("kld_epsilon", p.epsilon, p.epsilon);
  pnh.param("kld_delta", p.delta, p.delta);
  pnh.param("bin_xy", p.bin_xy, p.bin_xy);
  pnh.param("bin_theta", p.bin_theta, p.bin_theta);
  pnh.param("min_particles", p.min_particles, p.min_particles);
  pnh.param("max_particles", p.max_particles, p.max_particles);
  pnh.param("global_particles", p.global_particles, p.global_particles);
  pnh.param("init_particles", p.init_particles, p.init_particles);
  pnh.param("fixed_particles", p.fixed_particles, p.fixed_particles);
  pnh.param("update_min_d", p.update_min_d, p.update_min_d);
  pnh.param("update_min_a", p.update_min_a, p.update_min_a);
  pnh.param("recovery_alpha_slow", p.alpha_slow, p.alpha_slow);
  pnh.param("recovery_alpha_fast", p.alpha_fast, p.alpha_fast);
  pnh.param("odom_alpha1", p.motion.alpha1, p.motion.alpha1);
  pnh.param("odom_alpha2", p.motion.alpha2, p.motion.alpha2);
  pnh.param("odom_alpha3", p.motion.alpha3, p.motion.alpha3);
  pnh.param("odom_alpha4", p.motion.alpha4, p.motion.alpha4);
  std::string model = "likelihood_field";
  pnh.param("laser_model_type", model, model);
  p.measurement.type =
      model == "beam" ? MeasurementModelType::kBeam : MeasurementModelType::kLikelihoodField;
  pnh.param("laser_beam_step", p.measurement.beam_step, p.measurement.beam_step);
  pnh.param("laser_sigma_hit", p.measurement.sigma_hit, p.measurement.sigma_hit);
  pnh.param("laser_z_hit", p.measurement.z_hit, p.measurement.z_hit);
  pnh.param("laser_z_rand", p.measurement.z_rand, p.measurement.z_rand);
  pnh.param("laser_max_range", p.measurement.max_range, p.measurement.max_range);
  pnh.param("laser_likelihood_exponent", p.measurement.likelihood_exponent,
            p.measurement.likelihood_exponent);
  return p;
}
}  // namespace

class KldLocalizerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    // Callbacks (a latched /map at once) may run on the manager's worker threads while this
    // still runs: they wait until everything, last_status_ included, is set up.
    std::lock_guard<std::mutex> lock(mutex_);
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    params_ = loadParams(pnh);
    pnh.param("global_frame", map_frame_, map_frame_);
    pnh.param("odom_frame", odom_frame_, odom_frame_);
    pnh.param("base_frame", base_frame_, base_frame_);
    pnh.param("transform_tolerance", transform_tolerance_, transform_tolerance_);
    pnh.param("expected_beams", expected_beams_, expected_beams_);
    pnh.param("global_localization_on_start", global_on_start_, global_on_start_);
    pnh.param("scan_queue_size", scan_queue_size_, scan_queue_size_);
    pnh.param("tf_timeout", tf_timeout_, tf_timeout_);
    pnh.param("max_map_cells", map_limits_.max_cells, map_limits_.max_cells);
    int seed = 1;
    pnh.param("seed", seed, seed);
    seed_ = static_cast<uint64_t>(seed);
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();  // one /tf listener per process
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("kld_pose", 5, true);
    cloud_pub_ = nh.advertise<geometry_msgs::PoseArray>("particlecloud", 2, true);
    count_pub_ = nh.advertise<std_msgs::Int32>("kld/particle_count", 5);
    status_pub_ = nh.advertise<std_msgs::String>("kld/localized", 5, true);
    // Stand-in (helper H4) until the localizer's own typed status (helper H3) lands.
    typed_status_pub_ =
        nh.advertise<wheelchair_msgs::LocalizationStatus>("localization/status", 5, true);
    map_sub_ = nh.subscribe("map", 1, &KldLocalizerNodelet::onMap, this);
    // Like amcl: a scan waits (in a bounded queue, without blocking a thread) until odom ->
    // base_link is known at its stamp; odometry may lag the laser by a few tens of ms.
    scan_sub_.subscribe(nh, "scan", 5);
    scan_sub_.registerCallback(&KldLocalizerNodelet::onScanArrived, this);
    scan_filter_ = std::make_unique<tf2_ros::MessageFilter<sensor_msgs::LaserScan>>(
        scan_sub_, *tf_buffer_, odom_frame_, static_cast<uint32_t>(std::max(1, scan_queue_size_)),
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
    publishStatus("no map yet");
  }

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::shared_ptr<const LocalizationMap> map;
    try {
      map = std::make_shared<LocalizationMap>(
          wheelchair_mapping::toMrptGrid(wheelchair_ros::fromOccupancyGrid(*msg, map_limits_)),
          params_.measurement.max_distance);
    } catch (const std::exception& e) {
      NODELET_ERROR("kld: map rejected: %s", e.what());
      return;
    }
    const bool had = localizer_ != nullptr;
    std::optional<PoseEstimate> keep;
    if (had && localizer_->status().localized) keep = localizer_->estimate();
    if (had)
      NODELET_WARN("kld: new map (%ux%u cells); %s", msg->info.width, msg->info.height,
                   keep ? "keeping the current estimate" : "not localized: waiting for a pose");
    localizer_ = std::make_unique<KldLocalizer>(map, params_, seed_);
    localizer_->setExpectedBeams(expected_beams_);
    if (keep) {
      localizer_->initGaussian(keep->mean, keep->cov);
    } else if (pending_init_) {
      localizer_->initGaussian(pending_init_->first, pending_init_->second);
    } else if (global_on_start_) {
      localizer_->initGlobal();
    }
    pending_init_.reset();
    publishStatus(localizer_->status().reason);
  }

  void onInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!msg->header.frame_id.empty() && msg->header.frame_id != map_frame_) {
      NODELET_WARN("kld: initial pose in frame '%s' ignored (expected '%s')",
                   msg->header.frame_id.c_str(), map_frame_.c_str());
      return;
    }
    const auto pose = toPose2D(msg->pose.pose);
    auto cov = fromRosCovariance(msg->pose.covariance);
    if (!(std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.phi)) ||
        !cov.asEigen().allFinite()) {
      NODELET_WARN("kld: initial pose with non-finite values ignored");
      return;
    }
    if (cov(0, 0) <= 0 && cov(1, 1) <= 0 && cov(2, 2) <= 0) {  // rviz may send zeros
      cov(0, 0) = cov(1, 1) = 0.25 * 0.25;
      cov(2, 2) = 0.26 * 0.26;
    }
    NODELET_INFO("kld: initial pose (%.2f, %.2f, %.1f deg)", pose.x, pose.y, pose.phi * 180 / M_PI);
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
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time now = ros::Time::now();
    if (last_tf_ok_.isZero() || now < last_tf_ok_) last_tf_ok_ = now;  // start, or time reset
    if (!tf_buffer_->_frameExists(msg->header.frame_id))
      warnThrottled("tf frame",
                    "kld: scan skipped, tf missing: unknown frame '" + msg->header.frame_id + "'");
    if ((now - last_tf_ok_).toSec() > tf_timeout_) {
      std::ostringstream why;
      why << "tf missing: no " << odom_frame_ << " -> " << base_frame_
          << " transform at the scan times for more than " << tf_timeout_ << " s";
      publishStatus(why.str());
    }
  }

  /// A scan the message filter gave up on (queue full, or older than the tf buffer).
  void onScanDropped(const sensor_msgs::LaserScan::ConstPtr& msg,
                     tf2_ros::filter_failure_reasons::FilterFailureReason reason) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::ostringstream text;
    text << "kld: scan skipped, tf missing: no " << odom_frame_ << " -> '" << msg->header.frame_id
         << "' transform at its stamp "
         << (reason == tf2_ros::filter_failure_reasons::OutTheBack ? "(older than the tf buffer)"
                                                                   : "(scan queue full)");
    warnThrottled("tf dropped", text.str());
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!localizer_) {
      publishStatus("no map yet");
      return;
    }
    // A scan the filter released after a newer one is already past (more than 1 s back: the
    // clock was reset, e.g. a restarted simulator, and the scan is taken).
    if (msg->header.stamp <= last_scan_stamp_ &&
        msg->header.stamp + ros::Duration(1.0) > last_scan_stamp_)
      return;
    mrpt::math::TPose2D odom, laser;
    try {
      odom = toPose2D(
          tf_buffer_->lookupTransform(odom_frame_, base_frame_, msg->header.stamp).transform);
      laser = toPose2D(
          tf_buffer_->lookupTransform(base_frame_, msg->header.frame_id, ros::Time(0)).transform);
    } catch (const tf2::TransformException& e) {
      warnThrottled("tf", std::string("kld: scan skipped, tf missing: ") + e.what());
      return;
    }
    last_scan_stamp_ = msg->header.stamp;
    last_tf_ok_ = ros::Time::now();
    const auto result = localizer_->update(odom, fromScanMsg(*msg, laser));
    if (result == UpdateResult::kRejected) {
      warnThrottled(localizer_->lastRejection(),
                    "kld: scan rejected: " + localizer_->lastRejection());
      publishStatus("bad scan: " + localizer_->lastRejection());
      return;
    }
    const auto status = localizer_->status();
    publishStatus(status.localized ? "" : status.reason);
    if (!localizer_->initialized()) return;
    if (result == UpdateResult::kUpdated) publishEstimate(msg->header.stamp);
    publishMapToOdom(msg->header.stamp, odom);
  }

  void publishEstimate(const ros::Time& stamp) {
    geometry_msgs::PoseWithCovarianceStamped pose;
    pose.header.stamp = stamp;
    pose.header.frame_id = map_frame_;
    pose.pose = toPoseWithCovariance(localizer_->estimate());
    pose_pub_.publish(pose);
    auto cloud = toPoseArray(localizer_->particles());
    cloud.header = pose.header;
    cloud_pub_.publish(cloud);
    std_msgs::Int32 count;
    count.data = static_cast<int>(localizer_->particles().size());
    count_pub_.publish(count);
  }

  /// map->odom = estimate (map->base_link) composed with the inverse of odom->base_link,
  /// future-dated by the transform tolerance (REP-105).
  void publishMapToOdom(const ros::Time& stamp, const mrpt::math::TPose2D& odom) {
    const auto& e = localizer_->estimate().mean;
    const double yaw = e.phi - odom.phi;
    const double c = std::cos(yaw), s = std::sin(yaw);
    geometry_msgs::TransformStamped t;
    t.header.stamp = stamp + ros::Duration(transform_tolerance_);
    t.header.frame_id = map_frame_;
    t.child_frame_id = odom_frame_;
    t.transform.translation.x = e.x - (c * odom.x - s * odom.y);
    t.transform.translation.y = e.y - (s * odom.x + c * odom.y);
    t.transform.rotation.z = std::sin(yaw / 2);
    t.transform.rotation.w = std::cos(yaw / 2);
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

  /// "localized" or the reason why not (the safety supervisor's input).
  void publishStatus(const std::string& why_not) {
    std_msgs::String s;
    s.data = why_not.empty() ? "localized" : why_not;
    if (s.data != last_status_) {
      if (why_not.empty())
        NODELET_INFO("kld: localized");
      else
        warnThrottled("status: " + why_not, "kld: not localized: " + why_not);
      last_status_ = s.data;
    }
    status_pub_.publish(s);
    wheelchair_msgs::LocalizationStatus typed;
    typed.header.stamp = ros::Time::now();
    typed.localized = why_not.empty();
    typed.state = typed.localized ? wheelchair_msgs::LocalizationStatus::LOCALIZED
                  : localizer_ && localizer_->initialized()
                      ? wheelchair_msgs::LocalizationStatus::MISFIT
                      : wheelchair_msgs::LocalizationStatus::UNINITIALIZED;
    typed.sentence =
        typed.localized ? "The chair knows where it is." : "The chair does not know where it is.";
    typed.detail = why_not;
    typed.position_std = typed.heading_std = typed.inlier_fraction = typed.mean_fit = NAN;
    typed.best_weight = NAN;
    typed_status_pub_.publish(typed);
  }

  KldParams params_;
  std::string map_frame_ = "map", odom_frame_ = "odom", base_frame_ = "base_link";
  double transform_tolerance_ = 0.1;
  int expected_beams_ = 0;
  int scan_queue_size_ = 5;  ///< scans waiting for odometry (0.5 s of lag at 10 Hz)
  /// Any node can publish /map: a bigger or broken one is refused, the last good one kept.
  wheelchair_core::MapLimits map_limits_;
  double tf_timeout_ = 0.5;  ///< no usable scan for this long while scans arrive: not localized
  ros::Time last_tf_ok_, last_scan_stamp_;
  bool global_on_start_ = false;
  uint64_t seed_ = 1;
  std::mutex mutex_;
  std::unique_ptr<KldLocalizer> localizer_;
  std::optional<std::pair<mrpt::math::TPose2D, mrpt::math::CMatrixDouble33>> pending_init_;
  std::string last_status_;
  std::map<std::string, ros::WallTime> last_warning_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Publisher pose_pub_, cloud_pub_, count_pub_, status_pub_, typed_status_pub_;
  message_filters::Subscriber<sensor_msgs::LaserScan> scan_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::LaserScan>> scan_filter_;
  ros::Subscriber map_sub_, init_sub_;
  ros::ServiceServer global_srv_;
};

}  // namespace wheelchair_kld

PLUGINLIB_EXPORT_CLASS(wheelchair_kld::KldLocalizerNodelet, nodelet::Nodelet)
