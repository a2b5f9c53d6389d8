// System tests of the driver nodelet over the UDP transport: this process plays the chair — it
// owns sim time (/clock), an EmulatedMotorController and a trivial wheel plant — talks to the
// driver through the protocol, and loads the driver nodelet itself, so that it can command it as
// the chair's controller and the safety supervisor do: through the process's drive channel
// (torque commands, permits every 20 ms, the rider's release). One .test file per behaviour
// selects one test with --gtest_filter; foreign_publisher.test adds a rostopic publisher.
#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_can/simple_wheel_plant.h>
#include <wheelchair_can/udp_transport.h>
#include <wheelchair_ros/drive_channel.h>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <std_srvs/Trigger.h>
#include <wheelchair_msgs/WheelTorques.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>

namespace wheelchair_base_driver {
namespace {

using wheelchair_can::EmulatedControllerConfig;
using wheelchair_can::EmulatedMotorController;
using wheelchair_can::SimpleWheelPlant;
using wheelchair_can::UdpTransport;

constexpr double kStep = 0.001;  // sim seconds per loop step (one step per 2 ms wall time)

class EmulatedChair {
 public:
  EmulatedChair() : plant_(0.5, 0.5) {
    ros::NodeHandle nh;
    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    int port = 0;
    for (int i = 0; i < 200 && !nh.getParam("/base_driver/udp_bound_port", port); ++i) {
      ros::WallDuration(0.05).sleep();
    }
    if (port <= 0) throw std::runtime_error("the driver did not publish ~udp_bound_port");
    transport_ = std::make_unique<UdpTransport>(0, static_cast<std::uint16_t>(port),
                                                [this] { return now_.load(); });
    EmulatedControllerConfig config;
    config.max_torque = 50.0;
    controller_ = std::make_unique<EmulatedMotorController>(config, *transport_, plant_);
    thread_ = std::thread([this] { loop(); });
  }
  ~EmulatedChair() {
    running_ = false;
    thread_.join();
  }
  double now() const { return now_.load(); }
  void setSupervised(bool supervised) { supervised_ = supervised; }
  /// [m/s] the supervisor's speed limit its permits carry (+inf: none).
  void setSpeedLimit(double limit) { speed_limit_ = limit; }
  template <typename F>
  auto with(F f) {  // runs f(controller, plant) under the loop's lock
    std::lock_guard<std::mutex> lock(mutex_);
    return f(*controller_, plant_);
  }
  /// Waits (in sim time, at most `timeout`) until `condition` holds; returns the sim time or -1.
  double waitUntil(const std::function<bool()>& condition, double timeout) {
    const double end = now() + timeout;
    while (now() < end && ros::ok()) {
      if (condition()) return now();
      ros::WallDuration(0.0002).sleep();
    }
    return condition() ? now() : -1.0;
  }

 private:
  void loop() {
    while (running_ && ros::ok()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        now_ = now_ + kStep;
        rosgraph_msgs::Clock clock;
        clock.clock = ros::Time(now_.load());
        clock_pub_.publish(clock);
        controller_->step(now_);
        plant_.advance(kStep);
      }
      // The supervisor: a permit every 20 ms of sim time, while it is "loaded".
      if (supervised_ && now_ >= next_permit_) {
        next_permit_ = now_ + 0.02;
        wheelchair_ros::DrivePermit permit;
        permit.sequence = ++permit_sequence_;
        permit.stamp = now_;
        permit.speed_limit = speed_limit_;
        channel_->grant(permit);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  std::atomic<double> now_{1.0};
  std::atomic<bool> running_{true}, supervised_{true};
  std::atomic<double> speed_limit_{INFINITY};
  double next_permit_ = 0.0;
  std::uint64_t permit_sequence_ = 0;
  std::shared_ptr<wheelchair_ros::DriveChannel> channel_ = wheelchair_ros::driveChannel();
  std::mutex mutex_;
  ros::Publisher clock_pub_;
  SimpleWheelPlant plant_;
  std::unique_ptr<UdpTransport> transport_;
  std::unique_ptr<EmulatedMotorController> controller_;
  std::thread thread_;
};

struct DriverNodeTest : ::testing::Test {
  void SetUp() override {
    estop_pub = nh.advertise<std_msgs::Bool>("/estop", 10, true);
    status_sub = nh.subscribe<diagnostic_msgs::DiagnosticStatus>(
        "/base_driver/status", 10, [this](const diagnostic_msgs::DiagnosticStatus::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex);
          status = *m;
        });
    odom_sub = nh.subscribe<nav_msgs::Odometry>("/odom", 10,
                                                [this](const nav_msgs::Odometry::ConstPtr& m) {
                                                  std::lock_guard<std::mutex> lock(mutex);
                                                  odom = *m;
                                                });
    joints_sub = nh.subscribe<sensor_msgs::JointState>(
        "/joint_states", 10, [this](const sensor_msgs::JointState::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex);
          joints = *m;
        });
    chair = std::make_unique<EmulatedChair>();
    // The driver sees the controller and acknowledges its start-up fault.
    ASSERT_GT(chair->waitUntil([this] { return statusMessage() == "waiting_for_command"; }, 5.0), 0)
        << "driver status: " << statusMessage();
  }
  std::string statusMessage() {
    std::lock_guard<std::mutex> lock(mutex);
    return status.message;
  }
  std::string statusValue(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& kv : status.values) {
      if (kv.key == key) return kv.value;
    }
    return "";
  }
  /// A command of the chair's controller, through the drive channel.
  void publish(double left, double right) {
    wheelchair_ros::DriveCommand command;
    command.left = left;
    command.right = right;
    command.brake = false;
    command.stamp = chair->now();
    command.sequence = ++sequence;
    wheelchair_ros::driveChannel()->submit(command);
    last_publish = chair->now();
  }
  /// The rider's command to go on (what the HMI relays).
  void riderRelease() { wheelchair_ros::driveChannel()->releaseByRider({chair->now(), "test"}); }
  /// Publishes (left, right) at 50 Hz for `duration` sim seconds.
  void drive(double duration, double left, double right) {
    const double end = chair->now() + duration;
    double next = chair->now();
    while (chair->now() < end && ros::ok()) {
      if (chair->now() >= next) {
        publish(left, right);
        next += 0.02;
      }
      ros::WallDuration(0.0005).sleep();
    }
  }
  bool braked() {
    return chair->with([](EmulatedMotorController&, SimpleWheelPlant& p) { return p.braked(); });
  }

  ros::NodeHandle nh;
  ros::Publisher estop_pub;
  ros::Subscriber status_sub, odom_sub, joints_sub;
  std::mutex mutex;
  diagnostic_msgs::DiagnosticStatus status;
  nav_msgs::Odometry odom;
  sensor_msgs::JointState joints;
  std::unique_ptr<EmulatedChair> chair;
  double last_publish = 0;
  std::uint64_t sequence = 0;
};

TEST_F(DriverNodeTest, TorquesReachTheMotorsWithScaleAndSign) {
  drive(1.0, 12.5, -7.25);
  chair->with([](EmulatedMotorController&, SimpleWheelPlant& p) {
    EXPECT_FALSE(p.braked());
    EXPECT_NEAR(p.leftTorque(), 12.5, 0.005);
    EXPECT_NEAR(p.rightTorque(), -7.25, 0.005);
    EXPECT_GT(p.leftRate(), 0.0);
    EXPECT_LT(p.rightRate(), 0.0);
  });
  const auto [wheels, rates] = chair->with([](EmulatedMotorController&, SimpleWheelPlant& p) {
    return std::make_pair(p.wheelAngles(), std::make_pair(p.leftRate(), p.rightRate()));
  });
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(status.message, "driving");
  ASSERT_EQ(joints.position.size(), 2u);
  // Odometry from the encoder frames follows the simulated wheels, up to three encoder frames
  // (100 Hz) of lag at the wheels' speed, plus a count's worth.
  const double lag = 3 * 0.01;
  EXPECT_NEAR(joints.position[0], wheels.left, std::abs(rates.first) * lag + 0.01);
  EXPECT_NEAR(joints.position[1], wheels.right, std::abs(rates.second) * lag + 0.01);
  EXPECT_LT(odom.twist.twist.angular.z, 0.0);  // left forward, right back: turning clockwise
  EXPECT_EQ(odom.header.frame_id, "odom");
  EXPECT_EQ(odom.child_frame_id, "base_link");
}

TEST_F(DriverNodeTest, CommandSilenceBrakesWithin100ms) {
  drive(0.5, 10.0, 10.0);
  ASSERT_FALSE(braked());
  const double silent_since = last_publish;
  const double braked_at = chair->waitUntil([this] { return braked(); }, 1.0);
  ASSERT_GT(braked_at, 0);
  // Watchdog 100 ms after the last message; allowance for the driver's 100 Hz timer, the
  // controller's 1 ms step and message transport in sim time.
  RecordProperty("brake_delay_ms", std::to_string((braked_at - silent_since) * 1e3));
  std::cerr << "brake " << (braked_at - silent_since) * 1e3 << " ms (sim) after the last message\n";
  EXPECT_GE(braked_at - silent_since, 0.1 - 1e-6);
  EXPECT_LE(braked_at - silent_since, 0.1 + 0.02);
  // A silence while driving ends the drive: latched until the rider's command.
  chair->waitUntil([this] { return statusMessage() == "latched_stop"; }, 0.5);
  EXPECT_EQ(statusMessage(), "latched_stop");
  EXPECT_EQ(statusValue("sentence"), "the chair's controller stopped sending commands");
}

TEST_F(DriverNodeTest, HeartbeatLossFaults) {
  drive(0.3, 5.0, 5.0);
  chair->with([](EmulatedMotorController& c, SimpleWheelPlant&) { c.setSilent(true); });
  const double silent_since = chair->now();
  double fault_at = -1;
  const double end = chair->now() + 1.0;
  double next = chair->now();
  while (chair->now() < end && fault_at < 0) {  // the controller keeps commanding
    if (chair->now() >= next) {
      publish(5.0, 5.0);
      next += 0.02;
    }
    if (statusMessage() == "latched_stop") fault_at = chair->now();  // lost while driving
    ros::WallDuration(0.0005).sleep();
  }
  ASSERT_GT(fault_at, 0) << statusMessage();
  // 200 ms after the last heartbeat, which was at most 50 ms before the silence.
  RecordProperty("fault_delay_ms", std::to_string((fault_at - silent_since) * 1e3));
  std::cerr << "fault " << (fault_at - silent_since) * 1e3 << " ms (sim) after the silence\n";
  EXPECT_LE(fault_at - silent_since, 0.2 + 0.02);
  EXPECT_GE(fault_at - silent_since, 0.2 - 0.05 - 1e-6);
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(status.level, diagnostic_msgs::DiagnosticStatus::ERROR);
  }
  EXPECT_EQ(statusValue("sentence"), "the motor controller stopped answering");
  EXPECT_GT(chair->waitUntil([this] { return braked(); }, 0.05), 0);
}

// The issue: any node could clear the e-stop (~clear_estop) and the chair drove again. The
// service now refuses; the topic cannot release it either; the rider's command does.
TEST_F(DriverNodeTest, EstopLatchesUntilTheRidersRelease) {
  drive(0.3, 8.0, 8.0);
  ASSERT_FALSE(braked());
  std_msgs::Bool on;
  on.data = true;
  estop_pub.publish(on);
  EXPECT_GT(chair->waitUntil([this] { return braked(); }, 0.05), 0);
  drive(0.3, 8.0, 8.0);
  EXPECT_TRUE(braked());
  std_msgs::Bool off;
  off.data = false;
  estop_pub.publish(off);  // the topic cannot release it
  drive(0.3, 8.0, 8.0);
  EXPECT_TRUE(braked());
  EXPECT_EQ(statusMessage(), "estop");
  std_srvs::Trigger clear;
  ASSERT_TRUE(ros::service::call("/base_driver/clear_estop", clear));
  EXPECT_FALSE(clear.response.success);
  EXPECT_EQ(clear.response.message, "refused: only the rider can release the stop");
  drive(0.3, 8.0, 8.0);
  EXPECT_TRUE(braked()) << "the chair drove on after another node's clear_estop";
  EXPECT_EQ(statusMessage(), "estop");
  riderRelease();
  drive(0.2, 8.0, 8.0);
  EXPECT_FALSE(braked());
  std_srvs::Trigger stop;
  ASSERT_TRUE(ros::service::call("/base_driver/estop", stop));
  drive(0.1, 8.0, 8.0);
  EXPECT_TRUE(braked());
}

// The issue: a second node publishing 20 N m at 500 Hz on /wheel_torques pushed the idle chair
// to 1.84 m/s. The driver takes no command from the topic: a foreign publisher (rostopic, in
// foreign_publisher.test) is braked on and latched with the reason until the rider's release.
TEST_F(DriverNodeTest, AForeignTorquePublisherIsBrakedOnAndLatched) {
  const double start = chair->with(
      [](EmulatedMotorController&, SimpleWheelPlant& p) { return p.wheelAngles().left; });
  ASSERT_GT(chair->waitUntil([this] { return statusMessage() == "latched_stop"; }, 20.0), 0)
      << "the foreign publisher was not noticed: " << statusMessage();
  EXPECT_EQ(statusValue("sentence"), "another program tried to drive the chair");
  EXPECT_NE(statusValue("latched stop detail").find("/intruder"), std::string::npos)
      << statusValue("latched stop detail");
  drive(1.0, 8.0, 8.0);  // not even the chair's own controller moves it now
  const double end = chair->with(
      [](EmulatedMotorController&, SimpleWheelPlant& p) { return p.wheelAngles().left; });
  EXPECT_LT(std::abs(end - start), 1e-6) << "the wheels turned";
  EXPECT_TRUE(braked());
}

// The issue: unloading the supervisor went unnoticed. Without fresh permits the driver brakes
// within the permit timeout (100 ms) and the drive ends, latched, until the rider's release.
TEST_F(DriverNodeTest, NoPermitsBrakeWithinThePermitTimeout) {
  drive(0.5, 8.0, 8.0);
  ASSERT_FALSE(braked());
  chair->setSupervised(false);
  const double since = chair->now();
  double braked_at = -1;
  const double end = chair->now() + 1.0;
  double next = chair->now();
  while (chair->now() < end && braked_at < 0) {  // the controller keeps commanding
    if (chair->now() >= next) {
      publish(8.0, 8.0);
      next += 0.02;
    }
    if (braked()) braked_at = chair->now();
    ros::WallDuration(0.0005).sleep();
  }
  ASSERT_GT(braked_at, 0);
  std::cerr << "brake " << (braked_at - since) * 1e3 << " ms (sim) after the last permit\n";
  EXPECT_LE(braked_at - since, 0.1 + 0.02 + 0.005);
  chair->waitUntil([this] { return statusMessage() == "latched_stop"; }, 0.5);
  EXPECT_EQ(statusValue("sentence"), "the safety supervisor is not running");
  chair->setSupervised(true);
  drive(0.3, 8.0, 8.0);
  EXPECT_TRUE(braked()) << "the supervisor back does not restart the drive: the rider does";
  riderRelease();
  drive(0.2, 8.0, 8.0);
  EXPECT_FALSE(braked());
}

// The supervisor's speed limit reaches the driver with its permits (the drive channel) and the
// driver holds it on the bus: the controller's 5 N m, which takes this plant past 1.2 m/s in
// 3 s, leaves the chair near the 0.3 m/s limit.
TEST_F(DriverNodeTest, TheSupervisorsSpeedLimitHoldsWhateverTheControllerCommands) {
  chair->setSpeedLimit(0.3);
  double fastest = 0.0;
  const double end = chair->now() + 3.0;
  double next = chair->now();
  while (chair->now() < end && ros::ok()) {
    if (chair->now() >= next) {
      publish(5.0, 5.0);
      next += 0.02;
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      fastest = std::max(fastest, std::abs(odom.twist.twist.linear.x));
    }
    ros::WallDuration(0.0005).sleep();
  }
  std::cerr << "fastest " << fastest << " m/s at the supervisor's 0.3 m/s\n";
  EXPECT_GT(fastest, 0.3) << "the chair should reach the limit";
  // The cut at 0.35 m/s, then at most 0.1 s at 1.7 m/s^2 before the torque is off on a loaded
  // machine: well below what the push reaches without the limit.
  EXPECT_LT(fastest, 0.3 + 0.05 + 0.17 + 0.03) << "the driver did not hold the limit";
  chair->waitUntil([this] { return statusValue("safety speed limit held [m/s]") == "0.3"; }, 1.0);
  EXPECT_EQ(statusValue("safety speed limit held [m/s]"), "0.3");
  EXPECT_NE(statusValue("speed limited"), "0");
}

TEST_F(DriverNodeTest, NanTorquesAreRejected) {
  drive(0.3, 8.0, 8.0);
  ASSERT_FALSE(braked());
  publish(std::nan(""), 8.0);
  const double sent = last_publish;
  const double braked_at = chair->waitUntil([this] { return braked(); }, 0.2);
  ASSERT_GT(braked_at, 0);
  EXPECT_LT(braked_at - sent, 0.05);  // at once, not after the 100 ms watchdog
  chair->waitUntil([this] { return statusValue("rejected non-finite") == "1"; }, 0.5);
  EXPECT_EQ(statusValue("rejected non-finite"), "1");
  drive(0.2, 8.0, 8.0);  // valid commands drive again
  EXPECT_FALSE(braked());
}

}  // namespace
}  // namespace wheelchair_base_driver

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "base_driver_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  // The driver in this process (its private parameters are the .test file's /base_driver/...),
  // reachable through the drive channel as in the chair process.
  nodelet::Loader loader(false);
  if (!loader.load("/base_driver", "wheelchair_base_driver/BaseDriverNodelet", {}, {})) {
    std::cerr << "the base driver nodelet did not load\n";
    return 1;
  }
  const int result = RUN_ALL_TESTS();
  loader.unload("/base_driver");
  return result;
}
