#include <wheelchair_controller/controller_nodelet.h>
#include <wheelchair_core/callback_cpu.h>
#include <wheelchair_core/kinematics.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>

#include "controller_parameters.h"

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <pluginlib/class_list_macros.hpp>

#include <cmath>
#include <cstdio>

namespace wheelchair_controller {

namespace {

/// The path's poses; a pose whose orientation is not a unit quaternion gets a NaN heading, so
/// that the path is refused as non-finite.
std::vector<Pose2D> pathPoses(const nav_msgs::Path& msg) {
  std::vector<Pose2D> poses = wheelchair_ros::fromPathMsg(msg);
  for (size_t i = 0; i < poses.size(); ++i)
    if (!wheelchair_ros::isNormalized(msg.poses[i].pose.orientation)) poses[i].yaw = NAN;
  return poses;
}

/// The actionlib status of the current path while the tracker is in `state`.
uint8_t goalStatusOf(TrackerState state) {
  using actionlib_msgs::GoalStatus;
  switch (state) {
    case TrackerState::kIdle:
      return GoalStatus::PENDING;
    case TrackerState::kAligning:
    case TrackerState::kTracking:
    case TrackerState::kReversing:
    case TrackerState::kRotatingToGoal:
      return GoalStatus::ACTIVE;
    case TrackerState::kStopping:
      return GoalStatus::PREEMPTING;
    case TrackerState::kGoalReached:
      return GoalStatus::SUCCEEDED;
    case TrackerState::kAborted:
      break;
  }
  return GoalStatus::ABORTED;
}

}  // namespace

ControllerNodelet::~ControllerNodelet() {
  registration_.reset();  // no hold or report reaches this nodelet any more
  {
    std::lock_guard<std::mutex> lock(mutex_);
    shutdown_ = true;
  }
  request_cv_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void ControllerNodelet::onInit() {
  cpu_ = &wheelchair_core::callbackCpuTotal(getName());  // before any callback can run
  references_cpu_ = &wheelchair_core::callbackCpuTotal(getName() + " (path references)");
  ros::NodeHandle& nh = getNodeHandle();
  // The chair's controller: the only one that commands the base driver (a second one in the
  // process is refused, before anything is set up).
  channel_ = wheelchair_ros::driveChannel();
  try {
    registration_ = channel_->attachController(
        {[this](const wheelchair_ros::SafetyHold& h) { onHold(h); },
         [this](const wheelchair_ros::DriverReport& r) { onDriverReport(r); }});
  } catch (const std::logic_error& e) {
    throw wheelchair_core::ConfigError(getName() + ": " + e.what());
  }
  const ControllerParameters params = wheelchair_ros::loadParameters<ControllerParameters>(
      getPrivateNodeHandle(), readControllerParameters);
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  chair_ = wheelchair_description::loadChairParams(params.chair_file);
  {
    std::lock_guard<std::mutex> lock(mutex_);  // the channel may call before onInit ends
    tracker_ = std::make_unique<PathTracker>(chair_, params.tracker);
  }
  map_frame_ = params.map_frame;
  base_frame_ = params.base_frame;
  gap_timeout_ = params.tracker.gap_timeout;
  wall_gap_timeout_ = params.wall_gap_timeout;

  tf_buffer_ = wheelchair_ros::sharedTfBuffer();  // one /tf listener per process
  torque_pub_ = nh.advertise<wheelchair_msgs::WheelTorques>("wheel_torques", 10);
  reference_pub_ = pnh.advertise<geometry_msgs::PointStamped>("reference", 10);
  error_pub_ = pnh.advertise<geometry_msgs::Vector3Stamped>("tracking_error", 10);
  status_pub_ = pnh.advertise<std_msgs::String>("status", 10, true);
  path_status_pub_ = pnh.advertise<actionlib_msgs::GoalStatus>("path_status", 10, true);
  worker_ = std::thread(&ControllerNodelet::buildReferences, this);
  path_sub_ = nh.subscribe("plan", 1, &ControllerNodelet::onPath, this);
  speed_limit_guard_ = std::make_unique<wheelchair_ros::ExpectedPublisher>(
      nh.resolveName("safety/speed_limit"), params.speed_limit_publisher);
  speed_limit_sub_ = nh.subscribe("safety/speed_limit", 1, &ControllerNodelet::onSpeedLimit, this);
  user_stop_sub_ = nh.subscribe("user_stop", 5, &ControllerNodelet::onUserStop, this);
  localization_sub_ =
      nh.subscribe("localization/status", 5, &ControllerNodelet::onLocalizationStatus, this);
  odom_sub_ = nh.subscribe("odom", 10, &ControllerNodelet::onOdometry, this);
  timer_ = nh.createTimer(ros::Duration(1.0 / params.rate), &ControllerNodelet::onTimer, this);
}

void ControllerNodelet::onPath(const nav_msgs::Path::ConstPtr& msg) {
  const wheelchair_core::CallbackCpuScope cpu(cpu_);
  std::vector<Pose2D> poses = pathPoses(*msg);
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  std::lock_guard<std::mutex> lock(mutex_);
  ++path_sequence_;  // a newer path supersedes one still being built
  pending_ = PendingPath{path_sequence_, tracker_->stopCount(), stamp};
  std::string rejection = tracker_->refuseIfHeld();  // shows on the status when refused
  if (rejection.empty() && !msg->header.frame_id.empty() && msg->header.frame_id != map_frame_) {
    rejection = "path in frame '" + msg->header.frame_id + "', expected '" + map_frame_ + "'";
    tracker_->abort(rejection);
  }
  if (rejection.empty()) {
    // Cheap checks now (a NaN or empty path stops at once), the reference on the worker.
    rejection = pathRejectionReason(poses, kMinPathLength);
    if (!rejection.empty()) {
      tracker_->abort(rejection);
    } else {
      request_ = PathRequest{std::move(poses), tracker_->startSpeed(), path_sequence_,
                             tracker_->stopCount(), stamp};
      request_cv_.notify_one();
    }
  }
  if (!rejection.empty()) settlePending();  // the refusal concerns this path
  if (!rejection.empty()) NODELET_WARN("controller: path rejected: %s", rejection.c_str());
}

void ControllerNodelet::buildReferences() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    request_cv_.wait(lock, [this] { return shutdown_ || request_.has_value(); });
    if (shutdown_) return;
    const PathRequest request = std::move(*request_);
    request_.reset();
    lock.unlock();
    const PreparedPath prepared = [&] {
      const wheelchair_core::CallbackCpuScope cpu(references_cpu_);
      return preparePath(request.poses, chair_, tracker_->config(), request.initial_speed);
    }();
    lock.lock();
    // Swap in only if no newer path came and no stop began meanwhile.
    if (request.sequence != path_sequence_) continue;
    settlePending();  // swapped in or dropped: what the status says next concerns this path
    if (request.stop_count != tracker_->stopCount()) continue;
    const std::string rejection = tracker_->setPreparedPath(prepared);
    if (!rejection.empty()) NODELET_WARN("controller: path rejected: %s", rejection.c_str());
  }
}

void ControllerNodelet::onHold(const wheelchair_ros::SafetyHold& hold) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!tracker_) return;  // not set up yet: the supervisor says it again at its next check
  if (hold.stop) {
    const std::string reason = "safety stop: " + hold.sentence;
    if (safety_hold_ && *safety_hold_ == reason) return;  // the same verdict again
    safety_hold_ = reason;
    tracker_->hold("safety", reason);
  } else if (safety_hold_) {
    safety_hold_.reset();
    tracker_->release("safety");
  }
}

void ControllerNodelet::onDriverReport(const wheelchair_ros::DriverReport& report) {
  if (!report.latched) return;  // faults that end no drive (at rest) are the supervisor's news
  std::lock_guard<std::mutex> lock(mutex_);
  if (!tracker_) return;  // nothing to end yet
  tracker_->abort("the motors stopped: " + report.sentence);
}

void ControllerNodelet::onSpeedLimit(const ros::MessageEvent<std_msgs::Float64 const>& event) {
  // Only the chair's supervisor: another node's limit (a raise above the field's) is refused.
  if (!speed_limit_guard_->accept(event.getPublisherName())) return;
  std::lock_guard<std::mutex> lock(mutex_);
  tracker_->setSpeedLimit(event.getMessage()->data);
}

void ControllerNodelet::onUserStop(const std_msgs::Empty::ConstPtr&) {
  std::lock_guard<std::mutex> lock(mutex_);
  tracker_->abort("user stop");
}

void ControllerNodelet::onLocalizationStatus(
    const wheelchair_msgs::LocalizationStatus::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (msg->localized) {
    tracker_->release("localization");
  } else {
    tracker_->hold("localization",
                   "localization lost: " + (msg->detail.empty() ? msg->sentence : msg->detail));
  }
}

void ControllerNodelet::onOdometry(const nav_msgs::Odometry::ConstPtr& msg) {
  const wheelchair_core::CallbackCpuScope cpu(cpu_);
  std::lock_guard<std::mutex> lock(mutex_);
  wheels_.stamp = msg->header.stamp.toSec();
  const wheelchair_core::WheelRates rates =
      wheelchair_core::wheelRates({msg->twist.twist.linear.x, msg->twist.twist.angular.z},
                                  {chair_.wheel_radius, chair_.half_track});
  wheels_.eta = {rates.right, rates.left};
}

std::optional<PoseMeasurement> ControllerNodelet::lookupPose() {
  try {
    const geometry_msgs::TransformStamped t =
        tf_buffer_->lookupTransform(map_frame_, base_frame_, ros::Time(0));
    return PoseMeasurement{t.header.stamp.toSec(), wheelchair_ros::toPose2D(t.transform)};
  } catch (const tf2::TransformException&) {
    return std::nullopt;
  }
}

void ControllerNodelet::onTimer(const ros::TimerEvent&) {
  const wheelchair_core::CallbackCpuScope cpu(cpu_);
  const ros::Time now = ros::Time::now();
  const ros::WallTime wall = ros::WallTime::now();
  const std::optional<PoseMeasurement> pose = lookupPose();
  wheelchair_ros::DriveCommand command;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // A pause (the process stopped or starved) while driving: the motors braked on their
    // watchdog while the reference would have run on. The tracker brakes to rest and re-times
    // the drive from there, or ends it after a hang (PathTracker::stepsPaused). It sees a gap
    // of ROS time itself; one of wall time only shows here (a simulated clock may stand).
    if (!last_step_.isZero()) {
      const double gap = (now - last_step_).toSec(), wall_gap = (wall - last_wall_step_).toSec();
      if (wall_gap > wall_gap_timeout_ && gap <= gap_timeout_) tracker_->stepsPaused(wall_gap);
    }
    last_step_ = now;
    last_wall_step_ = wall;
    command = publish(tracker_->update(now.toSec(), pose, wheels_), now);
  }
  // To the base driver of this process (the only torque input it takes), after unlocking: the
  // channel's hold and report calls come into this nodelet under the channel's lock.
  channel_->submit(command);
}

void ControllerNodelet::settlePending() {
  if (!pending_) return;
  status_path_stamp_ = pending_->stamp;
  pending_.reset();
}

void ControllerNodelet::publishStatus(const TrackerOutput& out) {
  // A stop drops the path still being built (buildReferences): the stop answers it.
  if (pending_ && pending_->stop_count != tracker_->stopCount()) settlePending();
  std::string status = toString(out.state);
  if (!out.reason.empty()) status += ": " + out.reason;
  if (status != last_status_) {
    std_msgs::String s;
    s.data = status;
    status_pub_.publish(s);
    last_status_ = status;
    if (!out.reason.empty()) NODELET_WARN("controller: %s", status.c_str());
  }
  if (!out.reason.empty()) NODELET_WARN_THROTTLE(5.0, "controller: %s", status.c_str());
  if (status == last_path_status_ && status_path_stamp_ == last_path_stamp_) return;
  actionlib_msgs::GoalStatus s;
  s.goal_id.stamp = status_path_stamp_;
  s.text = status;
  s.status = goalStatusOf(out.state);
  path_status_pub_.publish(s);
  last_path_status_ = status;
  last_path_stamp_ = status_path_stamp_;
}

wheelchair_ros::DriveCommand ControllerNodelet::publish(const TrackerOutput& out,
                                                        const ros::Time& now) {
  wheelchair_ros::DriveCommand command;
  command.right = out.command.torque(0);
  command.left = out.command.torque(1);
  command.brake = out.command.brake;
  command.stamp = now.toSec();
  command.sequence = ++command_sequence_;
  // The same, for logs and rviz (and the simulator's direct mode in the controller's tests).
  wheelchair_msgs::WheelTorques cmd;
  cmd.header.stamp = now;
  cmd.header.frame_id = base_frame_;
  cmd.right = out.command.torque(0);
  cmd.left = out.command.torque(1);
  cmd.brake = out.command.brake;
  torque_pub_.publish(cmd);

  publishStatus(out);
  if (!out.has_reference) return command;
  geometry_msgs::PointStamped ref;
  ref.header.stamp = now;
  ref.header.frame_id = map_frame_;
  ref.point.x = out.reference.position.x();
  ref.point.y = out.reference.position.y();
  reference_pub_.publish(ref);
  geometry_msgs::Vector3Stamped err;
  err.header = ref.header;
  err.vector.x = out.reference.position.x() - out.y.x();
  err.vector.y = out.reference.position.y() - out.y.y();
  err.vector.z = out.body_deviation;  // axle centre's distance from the planned path
  error_pub_.publish(err);
  return command;
}

}  // namespace wheelchair_controller

PLUGINLIB_EXPORT_CLASS(wheelchair_controller::ControllerNodelet, nodelet::Nodelet)
