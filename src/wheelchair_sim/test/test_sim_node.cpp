// rostest client of the simulator node, in the room world of test/worlds (free for
// x in [-2, 8], y in [-3, 3]), chair starting at the origin facing +x, ideal dynamics.
#include <wheelchair_sim/SetPose.h>

#include <wheelchair_sim_testing/ros_wait.h>

#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <wheelchair_description_testing/chair_file.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <wheelchair_ros/conversions.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <thread>

namespace {

constexpr double kFrontWall = 8.0;

using wheelchair_sim::test::waitFor;

/// Keeps publishing the same torques (a controller at 50 Hz wall time) while alive.
class TorquePublisher {
 public:
  TorquePublisher(ros::NodeHandle& nh, double right, double left)
      : pub_(nh.advertise<wheelchair_msgs::WheelTorques>("wheel_torques", 10)) {
    thread_ = std::thread([this, right, left] {
      while (running_ && ros::ok()) {
        wheelchair_msgs::WheelTorques m;
        m.right = right;
        m.left = left;
        pub_.publish(m);
        ros::WallDuration(0.02).sleep();
      }
    });
  }
  ~TorquePublisher() {
    running_ = false;
    thread_.join();
  }

 private:
  ros::Publisher pub_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

struct Latest {
  std::mutex mutex;
  std::vector<nav_msgs::Odometry> truth;
  nav_msgs::Odometry odom;
  std::vector<nav_msgs::Odometry> odom_history;
  sensor_msgs::LaserScan scan;
  int scans = 0, odoms = 0;
  bool collision = false, collision_known = false;
};

class SimNode : public ::testing::Test {
 protected:
  void SetUp() override {
    subs_.push_back(nh_.subscribe<nav_msgs::Odometry>(
        "sim/ground_truth", 100,
        [this](const nav_msgs::Odometry::ConstPtr& m) { latest_.truth.push_back(*m); }));
    subs_.push_back(nh_.subscribe<nav_msgs::Odometry>(
        "odom", 10, [this](const nav_msgs::Odometry::ConstPtr& m) {
          latest_.odom = *m;
          latest_.odom_history.push_back(*m);
          ++latest_.odoms;
        }));
    subs_.push_back(nh_.subscribe<sensor_msgs::LaserScan>(
        "scan", 10, [this](const sensor_msgs::LaserScan::ConstPtr& m) {
          latest_.scan = *m;
          ++latest_.scans;
        }));
    subs_.push_back(nh_.subscribe<std_msgs::Bool>("sim/collision", 10,
                                                  [this](const std_msgs::Bool::ConstPtr& m) {
                                                    latest_.collision = m->data;
                                                    latest_.collision_known = true;
                                                  }));
    ASSERT_TRUE(waitFor([this] { return !latest_.truth.empty() && latest_.odoms > 0; }, 20.0))
        << "no /sim/ground_truth or /odom from the simulator";
  }

  const nav_msgs::Odometry& truth() const { return latest_.truth.back(); }

  /// Waits until ground truth and odometry stamped after the current (simulated) time came in.
  bool waitForFreshState() {
    // This node's sim time is the last /clock it received, which may lag the simulator's own
    // by a few clock periods: a state stamped just after `now` can still predate a service call
    // made at `now` (seen once in fresh-clone CI after a teleport). 50 ms of margin covers it.
    const ros::Time after = ros::Time::now() + ros::Duration(0.05);
    return waitFor(
        [&] { return truth().header.stamp > after && latest_.odom.header.stamp > after; }, 10.0);
  }

  ros::NodeHandle nh_;
  std::vector<ros::Subscriber> subs_;
  Latest latest_;
};

// Equal torques: v grows by a dt with a = 2 tau / r / (M_T + 2 m_w + 2 I_w / r^2).
TEST_F(SimNode, TorquesDriveTheChairAsTheModelPredicts) {
  const auto chair = wheelchair_description::test::shippedChair();
  const double tau = 8.0;
  const double a = 2.0 * tau / chair.wheel_radius /
                   (chair.total_mass + 2 * chair.wheel_mass +
                    2 * chair.wheel_inertia / std::pow(chair.wheel_radius, 2));
  TorquePublisher torques(nh_, tau, tau);
  ASSERT_TRUE(waitFor([this] { return truth().twist.twist.linear.x > 0.05; }, 20.0));
  const nav_msgs::Odometry first = truth();
  ASSERT_TRUE(
      waitFor([&] { return (truth().header.stamp - first.header.stamp).toSec() > 2.0; }, 30.0));
  const nav_msgs::Odometry last = truth();
  const double dt = (last.header.stamp - first.header.stamp).toSec();
  const double v0 = first.twist.twist.linear.x;
  EXPECT_NEAR(last.twist.twist.linear.x - v0, a * dt, 1e-6);
  EXPECT_NEAR(last.pose.pose.position.x - first.pose.pose.position.x, v0 * dt + 0.5 * a * dt * dt,
              1e-6);
  EXPECT_NEAR(last.pose.pose.position.y, 0.0, 1e-9);
  EXPECT_EQ(last.header.frame_id, "map");
  EXPECT_EQ(last.child_frame_id, "base_link");
  // Error-free odometry (this test's parameters) agrees with the truth of the same instant:
  // every /odom of the drive that has a ground truth with its stamp (under load a subscriber
  // queue may drop the one or the other, so not necessarily the last).
  int compared = 0;
  for (const auto& odom : latest_.odom_history) {
    if (odom.header.stamp < first.header.stamp) continue;
    for (const auto& t : latest_.truth) {
      if (t.header.stamp != odom.header.stamp) continue;
      EXPECT_NEAR(odom.pose.pose.position.x, t.pose.pose.position.x, 1e-3);
      ++compared;
    }
  }
  EXPECT_GT(compared, 10) << "too few /odom with a ground truth of the same stamp";
}

TEST_F(SimNode, ScansArriveWithTheSicksHeaderAndSeeTheFrontWall) {
  ASSERT_TRUE(waitFor([this] { return latest_.scans >= 3; }, 20.0));
  const sensor_msgs::LaserScan& s = latest_.scan;
  EXPECT_EQ(s.header.frame_id, "laser");
  ASSERT_EQ(s.ranges.size(), 361u);
  EXPECT_NEAR(s.angle_min, -M_PI / 2, 1e-6);
  EXPECT_NEAR(s.angle_max, M_PI / 2, 1e-6);
  EXPECT_NEAR(s.angle_increment, M_PI / 360, 1e-7);
  EXPECT_NEAR(s.angle_min + s.angle_increment * (s.ranges.size() - 1), s.angle_max, 1e-6);
  EXPECT_GT(s.header.stamp.toSec(), 0.0);
  const auto chair = wheelchair_description::test::shippedChair();
  // Beam 180 looks straight ahead from the laser at x = laser_x to the wall at x = 8.
  // Tolerance: 1 cm noise (3 sigma) + MRPT's ~4 cm range quantization.
  EXPECT_NEAR(s.ranges[180], kFrontWall - chair.laser_x, 0.08);
  // Beam 0 looks right (-y) to the wall at y = -3.
  EXPECT_NEAR(s.ranges[0], 3.0, 0.08);
}

TEST_F(SimNode, PushIntoAWallRaisesTheCollisionFlagAndStopsTheChair) {
  ASSERT_TRUE(waitFor([this] { return latest_.collision_known; }, 10.0));
  EXPECT_FALSE(latest_.collision);
  TorquePublisher torques(nh_, 30.0, 30.0);
  ASSERT_TRUE(waitFor([this] { return latest_.collision; }, 60.0)) << "no collision reported";
  ASSERT_TRUE(waitForFreshState());
  EXPECT_EQ(truth().twist.twist.linear.x, 0.0);
  const double held = truth().pose.pose.position.x;
  EXPECT_GT(held + 0.30, kFrontWall - 0.1);  // the footprint's front reached the wall
  EXPECT_LT(held + 0.30, kFrontWall);
  ASSERT_TRUE(waitForFreshState());
  EXPECT_EQ(truth().pose.pose.position.x, held) << "the chair must be held after a collision";
}

TEST_F(SimNode, TeleportMovesTheTruthNotTheOdometryAndResetRestartsOdometry) {
  ros::ServiceClient teleport = nh_.serviceClient<wheelchair_sim::SetPose>("sim/teleport");
  ros::ServiceClient reset = nh_.serviceClient<wheelchair_sim::SetPose>("sim/reset");
  ASSERT_TRUE(teleport.waitForExistence(ros::Duration(10.0)));
  wheelchair_sim::SetPose srv;
  srv.request.x = 3.0;
  srv.request.y = 1.0;
  srv.request.yaw = 1.0;
  ASSERT_TRUE(teleport.call(srv));
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  ASSERT_TRUE(waitForFreshState());
  EXPECT_NEAR(truth().pose.pose.position.x, 3.0, 1e-9);
  EXPECT_NEAR(truth().pose.pose.position.y, 1.0, 1e-9);
  EXPECT_NEAR(wheelchair_ros::yawOf(truth().pose.pose.orientation), 1.0, 1e-9);
  EXPECT_NEAR(latest_.odom.pose.pose.position.x, 0.0, 1e-9) << "odometry must not see a kidnap";

  srv.request.x = kFrontWall;  // inside the wall
  ASSERT_TRUE(teleport.call(srv));
  EXPECT_FALSE(srv.response.success);
  EXPECT_NEAR(truth().pose.pose.position.x, 3.0, 1e-9);

  {
    TorquePublisher torques(nh_, 10.0, 10.0);
    ASSERT_TRUE(waitFor([this] { return latest_.odom.pose.pose.position.x > 0.1; }, 20.0));
  }
  srv.request.x = -1.0;
  srv.request.y = 0.0;
  srv.request.yaw = 0.0;
  TorquePublisher idle(nh_, 0.0, 0.0);  // no torque left over to move the chair after the reset
  ros::WallDuration(0.2).sleep();
  ASSERT_TRUE(reset.call(srv));
  EXPECT_TRUE(srv.response.success);
  // Messages stamped before the reset may still be queued: wait for the reset state itself.
  EXPECT_TRUE(waitFor(
      [this] {
        return std::abs(latest_.odom.pose.pose.position.x) < 1e-3 &&
               std::abs(truth().pose.pose.position.x + 1.0) < 1e-3;
      },
      10.0))
      << "odometry x " << latest_.odom.pose.pose.position.x << ", truth x "
      << truth().pose.pose.position.x;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_sim_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
