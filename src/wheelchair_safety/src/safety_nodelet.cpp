// ROS layer of the safety supervisor: feeds it the localizer's estimate and status, tf
// map -> base_link, the laser (returns projected into the map), the map, the plan, the base
// driver's status and the rider's stop. In the command path through the process's drive channel
// (wheelchair_ros/drive_channel.h): at every check a sequence-numbered permit to the base driver
// (which brakes without a fresh one: unloading, crashing or hanging the supervisor stops the
// chair) and its verdict to the controller (a hold while it says stop). A stop latches until the
// rider's release (wheelchair_ros::releaseStopByRider, called by the HMI), never by a topic.
// Publishes the latched stop flag and the typed status (wheelchair_msgs/SafetyStatus), outputs
// only, whenever the verdict changes.
// Its callbacks run on a thread and callback queue of its own ("safety"), not the nodelet
// manager's shared pool, and a scan never waits for tf inside a callback: the supervisor's view
// of the laser and its permits do not wait behind another nodelet's callback (under the legacy
// PC's CPU cap a 50 ms tf wait per scan held its permit timer past the driver's 100 ms).
#include <wheelchair_core/callback_cpu.h>
#include <wheelchair_description/chair_file.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/drive_channel.h>
#include <wheelchair_ros/parameters.h>
#include <wheelchair_ros/shared_tf.h>
#include <wheelchair_safety/safety_supervisor.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float64.h>
#include <tf2_ros/buffer.h>
#include <pluginlib/class_list_macros.hpp>

#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>

#include "safety_status_msg.h"

namespace wheelchair_safety {

/// Every private parameter of the nodelet: the supervisor's limits and its own.
struct SafetyNodeletConfig {
  SafetyLimits limits;
  ProtectiveField field;
  wheelchair_core::MapLimits map_limits;  ///< a bigger or broken /map is refused
  /// [Hz] checks per second (and at once on a new goal), each with a permit to the driver: the
  /// command rate (the driver's permit_timeout is 100 ms).
  double rate = 50.0;
  /// The chair (wheelchair_description's chair.yaml, found at run time; "" = that one): the
  /// field's stop and its front, the corridor's width and the rear overhang come from it.
  std::string chair_file;
  std::string map_frame = "map";
  std::string odom_frame = "odom";  ///< a scan is placed by odometry at its stamp, then map -> odom
  std::string base_frame = "base_link";

  std::string validate() const {
    const std::string limits_problem = limits.validate(), field_problem = field.validate();
    const std::string map_problem = map_limits.validate();
    wheelchair_core::ConfigChecks checks;
    checks.check(limits_problem.empty(), limits_problem)
        .check(field_problem.empty(), field_problem)
        .check(map_problem.empty(), map_problem)
        .positive("rate", rate)
        .check(!map_frame.empty(), "map_frame must not be empty")
        .check(!odom_frame.empty(), "odom_frame must not be empty")
        .check(!base_frame.empty(), "base_frame must not be empty");
    return checks.result();
  }
};

void readSafetyNodeletConfig(wheelchair_core::ConfigReader& reader, SafetyNodeletConfig& config) {
  readSafetyLimits(reader, config.limits);
  readProtectiveField(reader, config.field);
  wheelchair_core::readMapLimits(reader, config.map_limits);
  reader.read("rate", config.rate);
  reader.read("chair_file", config.chair_file);
  reader.read("map_frame", config.map_frame);
  reader.read("odom_frame", config.odom_frame);
  reader.read("base_frame", config.base_frame);
}

/// The defaults that are the chair's (its file, one place): the protective field's stop
/// (protective_field/...) and front (the footprint's), the corridor (half the width + 10 cm),
/// the rear overhang (the footprint's). A private parameter still overrides each (tests).
SafetyNodeletConfig chairDefaults(const wheelchair_description::ChairParams& chair) {
  SafetyNodeletConfig config;
  double front = 0.0, rear = 0.0;
  for (const Eigen::Vector2d& corner : chair.footprint) {
    front = std::max(front, corner.x());
    rear = std::max(rear, -corner.x());
  }
  config.field.reaction_time = chair.stop.reaction_time;
  config.field.brake_decel = chair.stop.brake_decel;
  config.field.brake_jerk = chair.stop.brake_jerk;
  config.field.drive_accel = chair.stop.drive_accel;
  config.field.margin = chair.stop.margin;
  config.field.front_offset = front;
  config.limits.corridor_half_width = 0.5 * chair.width + 0.10;
  config.limits.rear_overhang = rear;
  return config;
}

class SafetyNodelet : public nodelet::Nodelet {
 public:
  ~SafetyNodelet() override {
    running_ = false;
    if (thread_.joinable()) thread_.join();  // no callback of this nodelet runs any more
    timer_.stop();
    registration_.reset();  // no permit any more: the driver brakes within its permit_timeout
  }

 private:
  void onInit() override {
    ros::NodeHandle nh(getNodeHandle());  // the nodelet's names and remappings, its own queue
    nh.setCallbackQueue(&queue_);
    // The chair's supervisor: the one that permits motion (a second one is refused).
    channel_ = wheelchair_ros::driveChannel();
    try {
      registration_ = channel_->attachSupervisor(
          {[this](const wheelchair_ros::DriverReport& r) { onDriverReport(r); },
           [this](const wheelchair_ros::RiderRelease& r) { onRiderRelease(r); }});
    } catch (const std::logic_error& e) {
      throw wheelchair_core::ConfigError(getName() + ": " + e.what());
    }
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    const auto config = wheelchair_ros::loadParameters<SafetyNodeletConfig>(
        pnh, readSafetyNodeletConfig, chairDefaults(wheelchair_description::loadChairOf(pnh)));
    // The field in effect, for the log and for tests that place a person at its edge.
    pnh.setParam("field/reaction_time", config.field.reaction_time);
    pnh.setParam("field/brake_decel", config.field.brake_decel);
    pnh.setParam("field/brake_jerk", config.field.brake_jerk);
    pnh.setParam("field/drive_accel", config.field.drive_accel);
    pnh.setParam("field/margin", config.field.margin);
    pnh.setParam("field/front_offset", config.field.front_offset);
    map_frame_ = config.map_frame;
    odom_frame_ = config.odom_frame;
    base_frame_ = config.base_frame;
    scan_wait_ = config.limits.scan_timeout;
    map_limits_ = config.map_limits;
    driver_fault_grace_ = config.limits.driver_fault_grace;
    {
      std::lock_guard<std::mutex> lock(mutex_);  // the channel may call before onInit ends
      supervisor_ = std::make_unique<SafetySupervisor>(config.limits, config.field);
    }
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();  // one /tf listener per process

    stop_pub_ = nh.advertise<std_msgs::Bool>("safety/stop", 1, true);
    status_pub_ = nh.advertise<wheelchair_msgs::SafetyStatus>("safety/status", 1, true);
    speed_limit_pub_ = nh.advertise<std_msgs::Float64>("safety/speed_limit", 1);
    subs_.push_back(nh.subscribe("map", 1, &SafetyNodelet::onMap, this));
    subs_.push_back(nh.subscribe("plan", 1, &SafetyNodelet::onPlan, this));
    subs_.push_back(nh.subscribe("scan", 5, &SafetyNodelet::onScan, this));
    subs_.push_back(nh.subscribe("rear_scan", 5, &SafetyNodelet::onRearScan, this));
    subs_.push_back(nh.subscribe("kld_pose", 5, &SafetyNodelet::onEstimate, this));
    subs_.push_back(nh.subscribe("localization/status", 5, &SafetyNodelet::onLocalization, this));
    subs_.push_back(nh.subscribe("odom", 5, &SafetyNodelet::onOdometry, this));
    subs_.push_back(nh.subscribe("user_stop", 5, &SafetyNodelet::onUserStop, this));
    subs_.push_back(nh.subscribe("move_base_simple/goal", 5, &SafetyNodelet::onGoal, this));
    ready_ = true;
    timer_ = nh.createTimer(ros::Duration(1.0 / config.rate), &SafetyNodelet::onTimer, this);
    running_ = true;
    thread_ = std::thread([this] { spin(); });
  }

  /// The supervisor's own thread: its callbacks only, one at a time (as on a nodelet's queue).
  void spin() {
    pthread_setname_np(pthread_self(), "safety");  // per-thread CPU in /proc names it
    // every callback of this nodelet runs on this thread: its CPU is the nodelet's
    std::atomic<int64_t>* cpu = &wheelchair_core::callbackCpuTotal(getName());
    while (running_ && ros::ok()) {
      const wheelchair_core::CallbackCpuScope measured(cpu);
      queue_.callAvailable(ros::WallDuration(0.05));
    }
  }

  /// A map any node may have published: refused with the reason unless usable (an uncaught
  /// throw here aborted the whole chair process); the supervisor keeps the last good map.
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    const std::string problem = wheelchair_ros::occupancyGridProblem(*msg, map_limits_);
    if (!problem.empty()) {
      NODELET_ERROR("safety: map refused, keeping the last good one: %s", problem.c_str());
      return;
    }
    wheelchair_core::OccupancyMap map = wheelchair_ros::fromOccupancyGrid(*msg, map_limits_);
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onMap(map);
  }

  /// A new plan is checked at once (not at the next tick): a plan that backs up with the rear
  /// laser silent is stopped before the controller has moved the chair.
  void onPlan(const nav_msgs::Path::ConstPtr& msg) {
    const auto path = wheelchair_ros::fromPathMsg(*msg);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      supervisor_->onPath(path);
    }
    update();
  }

  void onEstimate(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
    const Eigen::Matrix3d cov = wheelchair_ros::planarCovariance(msg->pose.covariance);
    std::lock_guard<std::mutex> lock(mutex_);
    covariance_ = cov;
    if (have_status_)  // until the localizer has said whether it is localized: no data yet
      supervisor_->onLocalization(msg->header.stamp.toSec(), localized_, cov, why_not_);
  }

  /// The localizer's verdict: `localized`, and its technical reason when it is not.
  void onLocalization(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    have_status_ = true;
    localized_ = msg->localized;
    why_not_ = msg->detail.empty() ? msg->sentence : msg->detail;
    supervisor_->onLocalization(ros::Time::now().toSec(), localized_, covariance_, why_not_);
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    keep(front_waiting_, msg);
    placeWaiting();
  }

  /// A scan's returns in the map frame, its sensor at `in_map` (`scan` mirrored in place when
  /// the sensor is mounted upside down; `sensor_pose` set to the sensor's 2D pose).
  static std::vector<Eigen::Vector2d> placedReturns(wheelchair_core::LaserScan2D& scan,
                                                    const geometry_msgs::Transform& in_map,
                                                    wheelchair_core::Pose2D& sensor_pose) {
    if (wheelchair_ros::laserPose2D(in_map, sensor_pose))
      wheelchair_core::mirrorScanAngles(scan);  // mounted upside down
    return wheelchair_core::scanEndpoints(scan, sensor_pose);
  }

  /// The front scan, placed: its returns and what the laser sees along the path.
  void useScan(const sensor_msgs::LaserScan& msg, const geometry_msgs::Transform& laser_in_map) {
    wheelchair_core::LaserScan2D scan = wheelchair_ros::fromLaserScanMsg(msg);
    wheelchair_core::Pose2D laser_pose;
    const auto returns = placedReturns(scan, laser_in_map, laser_pose);
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onScan(msg.header.stamp.toSec(), returns);
    supervisor_->onLaserView(scan, laser_pose);
  }

  /// The rear scan, placed: its returns in the map frame.
  void useRearScan(const sensor_msgs::LaserScan& msg, const geometry_msgs::Transform& in_map) {
    wheelchair_core::LaserScan2D scan = wheelchair_ros::fromLaserScanMsg(msg);
    wheelchair_core::Pose2D sensor_pose;
    const auto returns = placedReturns(scan, in_map, sensor_pose);
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onRearScan(msg.header.stamp.toSec(), returns);
  }

  /// Scans wait here, oldest first, until odometry reaches their stamps (never inside a
  /// blocking tf lookup: it held the supervisor's timer, and with it the permits, behind it).
  static void keep(std::deque<sensor_msgs::LaserScan::ConstPtr>& waiting,
                   const sensor_msgs::LaserScan::ConstPtr& msg) {
    waiting.push_back(msg);
    while (waiting.size() > kMaxWaitingScans) waiting.pop_front();
  }

  /// Every waiting scan tf can place now (on each scan, odometry message and check).
  void placeWaiting() {
    placeOrKeep(front_waiting_, "scan", &SafetyNodelet::useScan);
    placeOrKeep(rear_waiting_, "rear scan", &SafetyNodelet::useRearScan);
  }

  /// The sensor's pose in the map without waiting for the localizer: odometry at the scan's
  /// stamp (odom -> sensor) composed with the localizer's latest map -> odom (which it dates a
  /// transform_tolerance ahead, so the scan's own stamp often is not there yet: that lookup
  /// waited for the localizer's update of this very scan). A scan odometry has not reached yet
  /// waits (up to scan_timeout: the watchdog has stopped the chair by then); one tf can never
  /// place (no map frame yet, an unknown frame) is dropped with a warning.
  void placeOrKeep(std::deque<sensor_msgs::LaserScan::ConstPtr>& waiting, const char* which,
                   void (SafetyNodelet::*use)(const sensor_msgs::LaserScan&,
                                              const geometry_msgs::Transform&)) {
    while (!waiting.empty()) {
      const sensor_msgs::LaserScan::ConstPtr msg = waiting.front();
      geometry_msgs::TransformStamped in_map;
      try {
        // A tree without odometry (map -> base_link directly, as in rigs): at the scan's stamp.
        in_map =
            tf_buffer_->_frameExists(odom_frame_)
                ? tf_buffer_->lookupTransform(map_frame_, ros::Time(0), msg->header.frame_id,
                                              msg->header.stamp, odom_frame_)
                : tf_buffer_->lookupTransform(map_frame_, msg->header.frame_id, msg->header.stamp);
      } catch (const tf2::ExtrapolationException& e) {
        if ((ros::Time::now() - msg->header.stamp).toSec() <= scan_wait_) return;  // later
        NODELET_WARN_THROTTLE(2.0, "%s skipped: no %s -> %s at its stamp: %s", which,
                              odom_frame_.c_str(), msg->header.frame_id.c_str(), e.what());
        waiting.pop_front();
        continue;
      } catch (const tf2::TransformException& e) {
        NODELET_WARN_THROTTLE(2.0, "%s skipped: no %s -> %s: %s", which, map_frame_.c_str(),
                              msg->header.frame_id.c_str(), e.what());
        waiting.pop_front();  // the scan watchdog then runs out and stops the chair
        continue;
      }
      waiting.pop_front();
      (this->*use)(*msg, in_map.transform);
    }
  }

  /// The forward speed scales the protective field; odometry has moved on: waiting scans.
  void onOdometry(const nav_msgs::Odometry::ConstPtr& msg) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      supervisor_->onSpeed(msg->header.stamp.toSec(), msg->twist.twist.linear.x);
    }
    placeWaiting();
  }

  /// The rear laser (it guards reverse motion).
  void onRearScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    keep(rear_waiting_, msg);
    placeWaiting();
  }

  void onUserStop(const std_msgs::Empty::ConstPtr&) {
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onUserStop(ros::Time::now().toSec());
  }

  /// A goal is not a release (any node can publish one, and re-publishing a plan cannot undo a
  /// stop): the verdict goes out at once, before the planner's path reaches the controller.
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr&) { update(); }

  /// The rider's own command to go on (the HMI, through the drive channel): clears the latched
  /// stop; if a condition still holds, this very check stops again.
  void onRiderRelease(const wheelchair_ros::RiderRelease& release) {
    if (!ready_) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (supervisor_->latched().stop)
        NODELET_WARN("safety: stop released by the rider (%s)", release.source.c_str());
      supervisor_->onUserCommand(ros::Time::now().toSec());
    }
    update();
  }

  /// The driver's state (drive channel, on every change; any node could publish the driver's
  /// status topic): a fault or a latched stop (a foreign command, a hang...) that lasts
  /// driver_fault_grace is the supervisor's stop too, held until the rider's release.
  void onDriverReport(const wheelchair_ros::DriverReport& report) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!supervisor_) return;  // not set up yet: the driver reports again on its next change
    if ((report.fault || report.latched) && !report.sentence.empty())
      driver_sentence_ = report.sentence;  // the rider hears the driver's words for its stop
    // A latched driver stop is final (the grace is for a motor controller that re-arms within a
    // command period): it counts at once, before its consequences (odometry and with it tf stop
    // when the motor side loses power) make the rider hear another reason.
    const double now = ros::Time::now().toSec();
    supervisor_->onDriverStatus(
        report.latched ? now - driver_fault_grace_ : now, report.fault || report.latched,
        report.sentence + (report.detail.empty() ? "" : ": ") + report.detail);
  }

  void onTimer(const ros::TimerEvent&) {
    placeWaiting();
    update();
  }

  void update() {
    geometry_msgs::TransformStamped base_in_map;
    bool have_pose = false;
    try {
      base_in_map = tf_buffer_->lookupTransform(map_frame_, base_frame_, ros::Time(0));
      have_pose = true;
    } catch (const tf2::TransformException&) {
    }
    std::unique_lock<std::mutex> lock(mutex_);
    if (have_pose)
      supervisor_->onPose(base_in_map.header.stamp.toSec(),
                          wheelchair_ros::toPose2D(base_in_map.transform));
    const ros::Time now = ros::Time::now();
    wheelchair_msgs::SafetyStatus status = toSafetyStatus(supervisor_->check(now.toSec()), now);
    const SpeedLimit limit = supervisor_->speedLimit();
    publishSpeedLimit(limit);
    if (status.reason == wheelchair_msgs::SafetyStatus::DRIVER_FAULT && !driver_sentence_.empty())
      status.sentence = driver_sentence_;  // e.g. "another program tried to drive the chair"
    wheelchair_ros::DrivePermit permit;
    permit.sequence = ++permit_sequence_;
    permit.stamp = now.toSec();
    permit.stop = status.stop;
    permit.speed_limit = limit.speed;  // the driver holds it itself (the controller follows it)
    wheelchair_ros::SafetyHold hold;
    hold.stop = status.stop;
    hold.sentence = status.sentence;
    hold.detail = status.detail;
    const bool changed = !published_ || !sameVerdict(status, last_);
    if (changed) {
      if (status.stop) NODELET_WARN("STOP: %s: %s", status.sentence.c_str(), status.detail.c_str());
      std_msgs::Bool stop;
      stop.data = status.stop;
      stop_pub_.publish(stop);
      status_pub_.publish(status);
      published_ = true;
      last_ = status;
    }
    lock.unlock();
    // After unlocking (the channel calls the driver and the controller, whose reports come back
    // here): the verdict to the controller first, so that a stop holds it before the permit
    // tells the driver; every check, so that a controller loaded later learns it too.
    channel_->hold(hold);
    channel_->grant(permit);
  }

  /// Every check: the controller drives no faster (+inf: no limit from the field).
  void publishSpeedLimit(const SpeedLimit& limit) {
    std_msgs::Float64 msg;
    msg.data = limit.speed;
    speed_limit_pub_.publish(msg);
    if (std::isfinite(limit.speed) && limit.detail != last_limit_detail_)
      NODELET_INFO_THROTTLE(1.0, "speed limit %.2f m/s: %s", limit.speed, limit.detail.c_str());
    last_limit_detail_ = std::isfinite(limit.speed) ? limit.detail : "";
  }

  static constexpr size_t kMaxWaitingScans = 5;  ///< the subscriptions' queue length

  std::string last_limit_detail_;
  std::mutex mutex_;
  std::unique_ptr<SafetySupervisor> supervisor_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  std::string map_frame_, odom_frame_, base_frame_;
  double scan_wait_ = 0.3;  ///< [s] a scan waits for odometry at most this long (scan_timeout)
  std::deque<sensor_msgs::LaserScan::ConstPtr> front_waiting_, rear_waiting_;  ///< its thread
  wheelchair_core::MapLimits map_limits_;
  bool have_status_ = false, localized_ = false;
  std::string why_not_ = "no localizer status yet";
  double driver_fault_grace_ = 0.0;
  std::string driver_sentence_;  ///< the driver's words for its last fault or latched stop
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Identity();
  ros::CallbackQueue queue_;  ///< before the subscriptions and the timer: they outlive it not
  ros::Publisher stop_pub_, status_pub_, speed_limit_pub_;
  std::vector<ros::Subscriber> subs_;
  ros::Timer timer_;
  std::shared_ptr<wheelchair_ros::DriveChannel> channel_;
  std::unique_ptr<wheelchair_ros::DriveChannel::Registration> registration_;
  std::uint64_t permit_sequence_ = 0;
  std::atomic<bool> ready_{false};  ///< set up: a release may check
  bool published_ = false;
  wheelchair_msgs::SafetyStatus last_;
  std::atomic<bool> running_{false};
  std::thread thread_;  ///< last: started at the end of onInit, joined first
};

}  // namespace wheelchair_safety

PLUGINLIB_EXPORT_CLASS(wheelchair_safety::SafetyNodelet, nodelet::Nodelet)
