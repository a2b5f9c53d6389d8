// rostest client of the simulator on the motor bus (~motor_bus = udp) with the real base driver
// in between: commands (the drive channel of this process, which loads the driver nodelet, as in
// the chair process; with a permit per command) -> driver -> CAN frames over UDP -> emulated
// motor controller -> simulated wheels -> encoder frames -> driver's /odom. The expectation is the
// simulator's ground truth (sim/ground_truth), independent of the driver's encoder odometry. Room
// world of test/worlds: free for x in [-2, 8], y in [-3, 3]; chair at the origin facing +x.
#include <wheelchair_sim_testing/ros_wait.h>

#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/drive_channel.h>

#include <cmath>
#include <cstdio>
#include <functional>

namespace {

using wheelchair_sim::test::waitFor;

double yawOf(const nav_msgs::Odometry& m) { return wheelchair_ros::yawOf(m.pose.pose.orientation); }

class SimOnBus : public ::testing::Test {
 protected:
  void SetUp() override {
    truth_sub_ = nh_.subscribe<nav_msgs::Odometry>(
        "sim/ground_truth", 100, [this](const nav_msgs::Odometry::ConstPtr& m) {
          truth_ = *m;
          max_speed_ = std::max(max_speed_, m->twist.twist.linear.x);
          ++truths_;
        });
    odom_sub_ = nh_.subscribe<nav_msgs::Odometry>("odom", 100,
                                                  [this](const nav_msgs::Odometry::ConstPtr& m) {
                                                    odom_ = *m;
                                                    ++odoms_;
                                                  });
    ASSERT_TRUE(waitFor([this] { return truths_ > 0 && odoms_ > 0; }, 20.0))
        << "no sim/ground_truth from the simulator or no /odom from the base driver (encoders)";
  }

  /// A controller and a supervisor at 50 Hz of simulated time (the driver's watchdogs run in
  /// simulated time).
  void startTorques(double left, double right) {
    timer_ = nh_.createTimer(ros::Duration(0.02), [this, left, right](const ros::TimerEvent&) {
      auto channel = wheelchair_ros::driveChannel();
      wheelchair_ros::DrivePermit permit;
      permit.sequence = ++sequence_;
      permit.stamp = ros::Time::now().toSec();
      channel->grant(permit);
      wheelchair_ros::DriveCommand m;
      m.stamp = ros::Time::now().toSec();
      m.sequence = sequence_;
      m.left = left;
      m.right = right;
      m.brake = false;
      channel->submit(m);
    });
  }
  void stopTorques() { timer_.stop(); }

  /// Spins until `seconds` of simulated time have passed.
  bool waitSim(double seconds) {
    const ros::Time end = ros::Time::now() + ros::Duration(seconds);
    return waitFor([&] { return ros::Time::now() >= end; }, 30.0);
  }

  ros::NodeHandle nh_;
  ros::Subscriber truth_sub_, odom_sub_;
  ros::Timer timer_;
  std::uint64_t sequence_ = 0;
  nav_msgs::Odometry truth_, odom_;
  double max_speed_ = 0.0;
  int truths_ = 0, odoms_ = 0;
};

// Equal positive torques drive the chair forward; the driver's encoder odometry measures the
// ground-truth displacement; command silence brakes the chair to a stop.
TEST_F(SimOnBus, TorquesThroughTheDriverMoveTheChairAndSilenceBrakes) {
  ASSERT_TRUE(waitSim(0.5));  // chair at rest, driver and controller past their start-up
  const nav_msgs::Odometry truth0 = truth_, odom0 = odom_;
  ASSERT_LT(std::abs(truth0.twist.twist.linear.x), 1e-6);

  startTorques(10.0, 10.0);
  ASSERT_TRUE(waitSim(2.0));
  ASSERT_GT(truth_.pose.pose.position.x - truth0.pose.pose.position.x, 0.3)
      << "positive torques must move the chair forward (+x)";
  EXPECT_GT(max_speed_, 0.3);

  stopTorques();
  ASSERT_TRUE(waitSim(1.0));  // driver's command timeout is 0.1 s: brake well before this
  EXPECT_LT(std::abs(truth_.twist.twist.linear.x), 1e-3) << "command silence must brake the chair";
  EXPECT_LT(std::abs(odom_.twist.twist.linear.x), 1e-3) << "the driver must see the chair stopped";

  // Both at rest now: compare whole displacements, no time alignment needed.
  const double truth_dx = truth_.pose.pose.position.x - truth0.pose.pose.position.x;
  const double truth_dy = truth_.pose.pose.position.y - truth0.pose.pose.position.y;
  const double odom_dx = odom_.pose.pose.position.x - odom0.pose.pose.position.x;
  const double odom_dy = odom_.pose.pose.position.y - odom0.pose.pose.position.y;
  const double truth_d = std::hypot(truth_dx, truth_dy);
  std::printf("ground truth %.4f m, encoder odometry %.4f m, yaw %.4f / %.4f rad\n", truth_d,
              std::hypot(odom_dx, odom_dy), yawOf(truth_) - yawOf(truth0),
              yawOf(odom_) - yawOf(odom0));
  EXPECT_GT(truth_dx, 0.5);
  EXPECT_NEAR(std::hypot(odom_dx, odom_dy), truth_d, 0.03 * truth_d);
  EXPECT_GT(odom_dx, 0.0) << "encoder odometry must see forward motion as +x";
  EXPECT_NEAR(yawOf(odom_) - yawOf(odom0), yawOf(truth_) - yawOf(truth0), 0.02);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_sim_bus");
  ros::NodeHandle nh;
  nodelet::Loader loader(false);  // the driver, with bus.test's /base_driver parameters
  if (!loader.load("/base_driver", "wheelchair_base_driver/BaseDriverNodelet", {}, {})) return 1;
  const int result = RUN_ALL_TESTS();
  loader.unload("/base_driver");
  return result;
}
