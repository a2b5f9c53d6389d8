#include <wheelchair_base_driver/base_driver_nodelet.h>
#include <wheelchair_can/fake_bus.h>
#include <wheelchair_can/udp_transport.h>
#include <wheelchair_description/chair_file.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <pluginlib/class_list_macros.hpp>

#include <cmath>
#include <optional>

namespace wheelchair_base_driver {

namespace can = wheelchair_can;
namespace protocol = wheelchair_can::protocol;

namespace {
double rosNow() { return ros::Time::now().toSec(); }
double wallNow() { return ros::WallTime::now().toSec(); }
}  // namespace

BaseDriverNodelet::~BaseDriverNodelet() {
  registration_.reset();  // no command or permit reaches the driver any more
  timer_.stop();
  wall_timer_.stop();
  std::lock_guard<std::mutex> lock(mutex_);
  if (core_) core_->engageEstop(rosNow());  // leave the chair braked
}

BaseDriverSettings BaseDriverNodelet::loadSettings() {
  const ros::NodeHandle& pnh = getPrivateNodeHandle();
  const wheelchair_description::ChairParams chair = wheelchair_description::loadChairOf(pnh);
  BaseDriverSettings defaults;
  defaults.driver.geometry.wheel_radius = chair.wheel_radius;
  defaults.driver.geometry.half_track = chair.half_track;
  defaults.driver.max_torque = chair.max_wheel_torque;
  defaults.driver.max_speed = chair.max_speed;
  return wheelchair_ros::loadParameters(pnh, readBaseDriverSettings, defaults);
}

void BaseDriverNodelet::onInit() {
  ros::NodeHandle& nh = getNodeHandle();
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  // The chair's controller and supervisor reach the driver only through the drive channel of
  // this process; a second driver in the process is refused (before anything is set up).
  channel_ = wheelchair_ros::driveChannel();
  try {
    registration_ = channel_->attachDriver(
        {[this](const wheelchair_ros::DriveCommand& c) { return onCommand(c); },
         [this](const wheelchair_ros::DrivePermit& p) {
           std::lock_guard<std::mutex> lock(mutex_);
           if (core_)
             core_->onPermit(p.sequence, p.session, p.stamp, p.stop, rosNow(), p.speed_limit);
         },
         [this](const wheelchair_ros::RiderRelease& r) {
           std::lock_guard<std::mutex> lock(mutex_);
           if (!core_) return;
           if (core_->estopLatched() || core_->latchCause() != LatchCause::kNone)
             NODELET_WARN("base driver: stop released by the rider (%s)", r.source.c_str());
           core_->riderRelease(rosNow());
         }});
  } catch (const std::logic_error& e) {
    throw wheelchair_core::ConfigError(getName() + ": " + e.what());
  }
  settings_ = loadSettings();
  const DriverConfig& config = settings_.driver;

  TransportOptions options = settings_.transport;
  options.filters = driverReceiveFilters();
  options.clock = rosNow;
  transport_ = makeTransport(options);
  if (auto* udp = dynamic_cast<can::UdpTransport*>(transport_.get())) {
    pnh.setParam("udp_bound_port", static_cast<int>(udp->localPort()));
  }
  core_ = std::make_unique<BaseDriverCore>(config, *transport_);
  if (options.kind == "fake" && settings_.emulate_controller) startEmulatedController();

  // /odom, tf and /joint_states at most at odom_rate (0: on every encoder frame).
  odom_period_ = settings_.odom_rate > 0.0 ? 1.0 / settings_.odom_rate : 0.0;
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
  joint_pub_ = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
  status_pub_ = pnh.advertise<diagnostic_msgs::DiagnosticStatus>("status", 10, true);
  tf_ = std::make_unique<tf2_ros::TransformBroadcaster>();
  diagnostics_ = std::make_unique<diagnostic_updater::Updater>(nh, pnh, getName());
  diagnostics_->setHardwareID(transport_->describe());
  diagnostics_->add("CAN base driver", this, &BaseDriverNodelet::diagnose);

  torque_sub_ = nh.subscribe("wheel_torques", 10, &BaseDriverNodelet::onTorques, this,
                             ros::TransportHints().tcpNoDelay());
  estop_sub_ = nh.subscribe("estop", 10, &BaseDriverNodelet::onEstopTopic, this);
  estop_srv_ = pnh.advertiseService("estop", &BaseDriverNodelet::onEstopService, this);
  clear_srv_ = pnh.advertiseService("clear_estop", &BaseDriverNodelet::onClearEstopService, this);
  timer_ =
      nh.createTimer(ros::Duration(1.0 / settings_.spin_rate), &BaseDriverNodelet::onTimer, this);
  wall_timer_ = nh.createWallTimer(ros::WallDuration(0.05), &BaseDriverNodelet::onWallTimer, this);
  NODELET_INFO(
      "base driver on %s: r=%.3f m, b=%.3f m, max torque %.1f N m, max speed %.2f m/s, "
      "watchdogs %.0f/%.0f/%.0f ms (commands/controller/permits)",
      transport_->describe().c_str(), config.geometry.wheel_radius, config.geometry.half_track,
      config.max_torque, config.max_speed, config.command_timeout * 1e3,
      config.controller_timeout * 1e3, config.permit_timeout * 1e3);
}

void BaseDriverNodelet::startEmulatedController() {
  emulated_port_ =
      can::FakeBus::named(settings_.transport.fake_bus)->connect("emulated_motor_controller");
  emulated_plant_ = std::make_unique<can::SimpleWheelPlant>(settings_.emulated_wheel_inertia,
                                                            settings_.emulated_wheel_damping);
  can::EmulatedControllerConfig mc;
  mc.counts_per_rev = settings_.driver.geometry.counts_per_rev;
  mc.max_torque = settings_.driver.max_torque;
  emulated_controller_ =
      std::make_unique<can::EmulatedMotorController>(mc, *emulated_port_, *emulated_plant_);
  NODELET_INFO("fake transport with an emulated motor controller and a trivial wheel plant");
}

bool BaseDriverNodelet::onCommand(const wheelchair_ros::DriveCommand& c) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!core_) return false;
  const TorqueVerdict verdict =
      core_->onCommand({c.left, c.right, c.brake, c.stamp, c.sequence, c.session}, rosNow());
  if (verdict != TorqueVerdict::kAccepted) {
    NODELET_WARN_THROTTLE(1.0, "command rejected (%s): left %g right %g; braking",
                          torqueVerdictName(verdict), c.left, c.right);
  }
  return verdict == TorqueVerdict::kAccepted;
}

void BaseDriverNodelet::onTorques(
    const ros::MessageEvent<wheelchair_msgs::WheelTorques const>& event) {
  const std::string& publisher = event.getPublisherName();
  if (publisher == ros::this_node::getName()) return;  // this process: the controller's log copy
  std::lock_guard<std::mutex> lock(mutex_);
  if (core_->latchCause() != LatchCause::kForeignCommand)
    NODELET_ERROR(
        "wheel torques from %s: braked and latched (only the chair's controller "
        "commands the motors)",
        publisher.c_str());
  core_->onForeignCommand(publisher, rosNow());
}

void BaseDriverNodelet::onEstopTopic(const std_msgs::Bool::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (msg->data) {
    if (!core_->estopLatched()) NODELET_ERROR("emergency stop engaged (topic)");
    core_->engageEstop(rosNow());
  } else if (core_->estopLatched()) {
    NODELET_WARN_THROTTLE(1.0, "estop=false ignored: only the rider's command releases the stop");
  }
}

bool BaseDriverNodelet::onEstopService(std_srvs::Trigger::Request&,
                                       std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> lock(mutex_);
  core_->engageEstop(rosNow());
  NODELET_ERROR("emergency stop engaged (service)");
  res.success = true;
  res.message = "e-stop latched; only the rider's command releases it";
  return true;
}

/// Any node could call it and drive the chair on: the rider's own command (the HMI, through the
/// drive channel) is the only release.
bool BaseDriverNodelet::onClearEstopService(std_srvs::Trigger::Request&,
                                            std_srvs::Trigger::Response& res) {
  NODELET_WARN("clear_estop called: refused, only the rider can release the stop");
  res.success = false;
  res.message = "refused: only the rider can release the stop";
  return true;
}

void BaseDriverNodelet::onWallTimer(const ros::WallTimerEvent&) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    core_->checkWallLiveness(rosNow(), wallNow());
  }
  reportEvents();
}

void BaseDriverNodelet::reportEvents() {
  std::lock_guard<std::mutex> order(report_mutex_);
  std::optional<DriverEvent> event;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    event = core_->takeEvent();
  }
  if (!event) return;
  if (event->latched)
    NODELET_ERROR("base driver: STOP latched: %s (%s)", event->sentence.c_str(),
                  event->detail.c_str());
  wheelchair_ros::DriverReport report;
  report.stamp = event->stamp;
  report.fault = event->fault;
  report.latched = event->latched;
  report.sentence = event->sentence;
  report.detail = event->detail;
  channel_->report(report);
}

void BaseDriverNodelet::onTimer(const ros::TimerEvent&) {
  reportEvents();  // what the channel's calls changed since the last tick
  std::lock_guard<std::mutex> lock(mutex_);
  const double now = rosNow();
  if (emulated_controller_) {
    emulated_controller_->step(now);
    if (last_plant_time_ >= 0 && now > last_plant_time_)
      emulated_plant_->advance(now - last_plant_time_);
    last_plant_time_ = now;
  }
  core_->spinOnce(now, wallNow());
  const DriverState state = core_->state();
  if (state != last_logged_state_) {
    if (isFault(state)) {
      NODELET_ERROR("base driver: %s (controller faults: %s) - braking", driverStateName(state),
                    protocol::describeFaults(core_->controllerFaults()).c_str());
    } else {
      NODELET_INFO("base driver: %s", driverStateName(state));
    }
    last_logged_state_ = state;
    publishStatus();
    last_status_time_ = now;
  } else if (now - last_status_time_ >= 0.5 || now < last_status_time_) {
    publishStatus();  // 2 Hz refresh: counters change without a change of state
    last_status_time_ = now;
  }
  if (isFault(state)) {
    const can::TransportStats bus = transport_->stats();
    NODELET_WARN_THROTTLE(5.0, "base driver braking: %s; %s is %s (%s)", driverStateName(state),
                          transport_->describe().c_str(), can::busStateName(bus.state),
                          bus.last_error.empty() ? "no bus error" : bus.last_error.c_str());
  }
  const OdometryState& odo = core_->odometry();
  // 3/4 of the period: encoder frames (100 Hz) jitter, a late one must not halve the rate.
  if (odo.stamp > last_odom_stamp_ && odo.stamp - last_odom_stamp_ >= 0.75 * odom_period_) {
    last_odom_stamp_ = odo.stamp;
    publishOdometry(ros::Time(odo.stamp));
  }
  diagnostics_->update();
}

void BaseDriverNodelet::publishOdometry(const ros::Time& stamp) {
  const OdometryState& odo = core_->odometry();
  nav_msgs::Odometry msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = settings_.odom_frame;
  msg.child_frame_id = settings_.base_frame;
  msg.pose.pose = wheelchair_ros::toPoseMsg(odo.pose);
  msg.twist.twist.linear.x = odo.v;
  msg.twist.twist.angular.z = odo.omega;
  // Wheel odometry: x, y, yaw drift slowly; z, roll, pitch are not observed (large variance).
  const double kPose[6] = {1e-3, 1e-3, 1e6, 1e6, 1e6, 1e-2};
  const double kTwist[6] = {1e-3, 1e-3, 1e6, 1e6, 1e6, 1e-2};
  for (int i = 0; i < 6; ++i) {
    msg.pose.covariance[i * 7] = kPose[i];
    msg.twist.covariance[i * 7] = kTwist[i];
  }
  odom_pub_.publish(msg);
  if (settings_.publish_tf) {
    geometry_msgs::TransformStamped t;
    t.header = msg.header;
    t.child_frame_id = settings_.base_frame;
    t.transform = wheelchair_ros::toTransformMsg(odo.pose);
    tf_->sendTransform(t);
  }
  sensor_msgs::JointState joints;
  joints.header.stamp = stamp;
  joints.name = {settings_.left_wheel_joint, settings_.right_wheel_joint};
  joints.position = {odo.left_angle, odo.right_angle};
  joints.velocity = {odo.left_rate, odo.right_rate};
  joint_pub_.publish(joints);
}

void BaseDriverNodelet::publishStatus() {
  diagnostic_msgs::DiagnosticStatus status;
  diagnostic_updater::DiagnosticStatusWrapper wrapper;
  diagnose(wrapper);
  status = wrapper;
  status.name = getName();
  status.hardware_id = transport_->describe();
  status_pub_.publish(status);
}

void BaseDriverNodelet::diagnose(diagnostic_updater::DiagnosticStatusWrapper& s) {
  const DriverState state = core_->state();
  const can::TransportStats bus = transport_->stats();
  const DriverCounters& n = core_->counters();
  if (isFault(state) || bus.state == can::BusState::kBusOff ||
      bus.state == can::BusState::kClosed) {
    s.summary(diagnostic_msgs::DiagnosticStatus::ERROR, driverStateName(state));
  } else if (state == DriverState::kCommandTimeout || bus.state != can::BusState::kActive) {
    s.summary(diagnostic_msgs::DiagnosticStatus::WARN, driverStateName(state));
  } else {
    s.summary(diagnostic_msgs::DiagnosticStatus::OK, driverStateName(state));
  }
  s.add("state", driverStateName(state));
  s.add("sentence", core_->sentence());
  s.add("estop latched", core_->estopLatched());
  s.add("latched stop", latchCauseName(core_->latchCause()));
  s.add("latched stop detail", core_->latchDetail());
  s.add("braking", core_->lastCommand().brake);
  s.add("commanded left [N m]", core_->lastCommand().left);
  s.add("commanded right [N m]", core_->lastCommand().right);
  s.add("controller faults", protocol::describeFaults(core_->controllerFaults()));
  s.add("bus state", can::busStateName(bus.state));
  s.add("bus last error", bus.last_error.empty() ? core_->lastBusError() : bus.last_error);
  s.add("frames sent", n.frames_sent);
  s.add("send failures", n.send_failures);
  s.add("frames received", n.frames_received);
  s.add("error frames", n.error_frames);
  std::uint64_t decode_errors = 0;
  for (std::size_t i = 1; i < n.decode_errors.size(); ++i) decode_errors += n.decode_errors[i];
  s.add("decode errors", decode_errors);
  s.add("torque messages", n.torque_messages);
  s.add("rejected non-finite", n.rejected_non_finite);
  s.add("rejected out of range", n.rejected_out_of_range);
  s.add("rejected stale", n.rejected_stale);
  s.add("last rejection", core_->lastRejection());
  s.add("command timeouts", n.command_timeouts);
  s.add("heartbeat losses", n.heartbeat_losses);
  s.add("controller faults seen", n.controller_faults);
  s.add("encoder frames lost", n.encoder_lost);
  s.add("encoder frames duplicated/reordered", n.encoder_duplicated + n.encoder_reordered);
  s.add("foreign commands on the bus", n.foreign_commands);
  s.add("foreign torque publishers", n.foreign_publishers);
  s.add("permits", n.permits);
  s.add("permits refused", n.permits_refused);
  s.add("permit losses", n.permit_losses);
  s.add("latched stops", n.latches);
  s.add("speed limited", n.speed_limited);
  s.add("safety speed limit held [m/s]", core_->heldSpeedLimit());
}

}  // namespace wheelchair_base_driver

PLUGINLIB_EXPORT_CLASS(wheelchair_base_driver::BaseDriverNodelet, nodelet::Nodelet)
