// The supervisor nodelet in a live graph: healthy data keeps it quiet; a person stepping onto
// the path, or a silent laser, stops the chair with the reason (scenario from ~scenario).
// Scenario command_path: the nodelet is loaded into this process, which plays the base driver on
// the drive channel: permits at the check rate, a latch that no topic releases, only the rider
// (wheelchair_ros::releaseStopByRider), and no permit once the supervisor is unloaded.
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/SafetyStatus.h>
#include <wheelchair_ros/drive_channel.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

namespace {

/// Feeds the supervisor a chair at (2, 2) facing +x on a straight path in a free 10 x 4 m map.
class World {
 public:
  World() {
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    plan_pub_ = nh_.advertise<nav_msgs::Path>("plan", 1, true);
    pose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("kld_pose", 1);
    localized_pub_ = nh_.advertise<wheelchair_msgs::LocalizationStatus>("localization/status", 1);
    scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 1);
    stop_sub_ = nh_.subscribe<std_msgs::Bool>(
        "safety/stop", 5, [this](const std_msgs::Bool::ConstPtr& m) { stop_ = m->data; });
    status_sub_ = nh_.subscribe<wheelchair_msgs::SafetyStatus>(
        "safety/status", 5,
        [this](const wheelchair_msgs::SafetyStatus::ConstPtr& m) { status_ = *m; });
    nav_msgs::OccupancyGrid map;
    map.header.frame_id = "map";
    map.info.resolution = 0.05;
    map.info.width = 200;
    map.info.height = 80;
    map.info.origin.orientation.w = 1.0;
    map.data.assign(200 * 80, 0);
    map_pub_.publish(map);
    nav_msgs::Path plan;
    plan.header.frame_id = "map";
    for (double x = 1.0; x <= 8.5; x += 0.1) {
      geometry_msgs::PoseStamped p;
      p.pose.position.x = x;
      p.pose.position.y = 2.0;
      p.pose.orientation.w = 1.0;
      plan.poses.push_back(p);
    }
    plan_pub_.publish(plan);
  }

  /// One 10 Hz cycle of healthy data; the scan shows a person 0.9 m ahead if asked.
  void cycle(bool scan, bool person) {
    const ros::Time now = ros::Time::now();
    geometry_msgs::TransformStamped tf;
    tf.header.stamp = now;
    tf.header.frame_id = "map";
    tf.child_frame_id = "base_link";
    tf.transform.translation.x = 2.0;
    tf.transform.translation.y = 2.0;
    tf.transform.rotation.w = 1.0;
    broadcaster_.sendTransform(tf);
    tf.child_frame_id = "laser";
    tf.header.frame_id = "base_link";
    tf.transform.translation.x = 0.0;
    tf.transform.translation.y = 0.0;
    broadcaster_.sendTransform(tf);
    geometry_msgs::PoseWithCovarianceStamped pose;
    pose.header.stamp = now;
    pose.header.frame_id = "map";
    pose.pose.covariance[0] = pose.pose.covariance[7] = pose.pose.covariance[35] = 1e-3;
    pose_pub_.publish(pose);
    wheelchair_msgs::LocalizationStatus localized;
    localized.header.stamp = now;
    localized.state = wheelchair_msgs::LocalizationStatus::LOCALIZED;
    localized.localized = true;
    localized_pub_.publish(localized);
    if (!scan) return;
    sensor_msgs::LaserScan s;
    s.header.stamp = now;
    s.header.frame_id = "laser";
    s.angle_min = -M_PI / 2;
    s.angle_increment = M_PI / 360;
    s.range_min = 0.05;
    s.range_max = 10.0;
    s.ranges.assign(361, std::numeric_limits<float>::infinity());
    if (person)
      for (int i = 170; i <= 190; ++i) s.ranges[i] = 0.9f;  // +-5 deg straight ahead
    scan_pub_.publish(s);
  }

  /// Runs cycles for `seconds`; returns true when the stop flag became `want`.
  bool runUntil(double seconds, bool scan, bool person, bool want) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      cycle(scan, person);
      ros::WallDuration(0.1).sleep();
      ros::spinOnce();
      if (stop_ == want && ready_) return true;
      ready_ = stop_ != -1;
    }
    return false;
  }

  /// Runs cycles for `seconds`.
  void run(double seconds, bool scan) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      cycle(scan, false);
      ros::WallDuration(0.1).sleep();
      ros::spinOnce();
    }
  }

  int stop_ = -1;
  bool ready_ = false;
  wheelchair_msgs::SafetyStatus status_;

 private:
  ros::NodeHandle nh_;
  ros::Publisher map_pub_, plan_pub_, pose_pub_, localized_pub_, scan_pub_;
  ros::Subscriber stop_sub_, status_sub_;
  tf2_ros::TransformBroadcaster broadcaster_;
};

}  // namespace

std::unique_ptr<nodelet::Loader> loader;  ///< the supervisor, in scenario command_path

std::string scenario() {
  std::string name;
  ros::param::param<std::string>("~scenario", name, "person");
  return name;
}

TEST(SafetyNode, ScenarioStopsWithItsReason) {
  if (scenario() == "command_path") GTEST_SKIP() << "see SupervisorInTheCommandPath";
  const std::string scenario = ::scenario();
  World world;
  ASSERT_TRUE(world.runUntil(15.0, true, false, false)) << "healthy data: " << world.status_;
  EXPECT_EQ(world.status_.reason, wheelchair_msgs::SafetyStatus::NONE) << world.status_;
  EXPECT_FALSE(world.status_.stop);
  if (scenario == "person") {
    ASSERT_TRUE(world.runUntil(5.0, true, true, true));
    EXPECT_EQ(world.status_.reason, wheelchair_msgs::SafetyStatus::OBSTACLE) << world.status_;
    EXPECT_NE(world.status_.sentence.find("in the way"), std::string::npos) << world.status_;
    ASSERT_FALSE(world.runUntil(1.0, true, false, false)) << "resumed without a command";
  } else {
    const ros::WallTime silent = ros::WallTime::now();
    ASSERT_TRUE(world.runUntil(5.0, false, false, true));
    EXPECT_LT((ros::WallTime::now() - silent).toSec(), 0.3 + 0.35);  // timeout + 2 cycles
    EXPECT_EQ(world.status_.reason, wheelchair_msgs::SafetyStatus::LASER_SILENT) << world.status_;
    EXPECT_NE(world.status_.sentence.find("laser scanner is silent"), std::string::npos)
        << world.status_;
    EXPECT_GT(world.status_.value, world.status_.limit) << world.status_;  // age > scan_timeout
  }
}

/// What the base driver of this process receives from the supervisor.
struct DriverSide {
  struct Permit {
    wheelchair_ros::DrivePermit permit;
    ros::WallTime received;
  };
  std::mutex mutex;
  std::vector<Permit> permits;
  int releases = 0;

  std::vector<Permit> since(const ros::WallTime& t) {
    std::lock_guard<std::mutex> lock(mutex);
    std::vector<Permit> out;
    for (const Permit& p : permits)
      if (p.received >= t) out.push_back(p);
    return out;
  }
};

// The issue: the supervisor could be unloaded and nothing noticed; its latch was released by
// /safety/stop false from any node and a re-published plan (the chair drove 1.12 m).
TEST(SafetyNode, SupervisorInTheCommandPath) {
  if (scenario() != "command_path") GTEST_SKIP() << "scenario " << scenario();
  ASSERT_TRUE(loader);
  auto driver = std::make_shared<DriverSide>();
  auto channel = wheelchair_ros::driveChannel();
  auto registration =
      channel->attachDriver({[](const wheelchair_ros::DriveCommand&) { return false; },
                             [driver](const wheelchair_ros::DrivePermit& p) {
                               std::lock_guard<std::mutex> lock(driver->mutex);
                               driver->permits.push_back({p, ros::WallTime::now()});
                             },
                             [driver](const wheelchair_ros::RiderRelease&) {
                               std::lock_guard<std::mutex> lock(driver->mutex);
                               ++driver->releases;
                             }});
  World world;
  std::mutex limit_mutex;
  double topic_limit = NAN;  // the supervisor's /safety/speed_limit
  ros::NodeHandle limit_nh;
  ros::Subscriber limit_sub = limit_nh.subscribe<std_msgs::Float64>(
      "safety/speed_limit", 5, [&](const std_msgs::Float64::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(limit_mutex);
        topic_limit = m->data;
      });
  ASSERT_TRUE(world.runUntil(15.0, true, false, false)) << "healthy data: " << world.status_;

  // A permit at the check rate (50 Hz; >= 30 in a second on a loaded machine), sequence
  // numbered, fresh, saying go.
  ros::WallTime t = ros::WallTime::now();
  world.run(1.0, true);
  std::vector<DriverSide::Permit> permits = driver->since(t);
  ASSERT_GE(permits.size(), 30u) << "permits in 1 s";
  for (size_t i = 1; i < permits.size(); ++i) {
    EXPECT_GT(permits[i].permit.sequence, permits[i - 1].permit.sequence);
    EXPECT_EQ(permits[i].permit.session, permits[0].permit.session);
  }
  EXPECT_FALSE(permits.back().permit.stop);
  EXPECT_NEAR(permits.back().permit.stamp, ros::Time::now().toSec(), 0.2);
  // Each carries the supervisor's speed limit, the one it publishes (the driver holds it): the
  // field ahead of a chair at rest in a free map allows driving.
  EXPECT_GT(permits.back().permit.speed_limit, 0.5);
  {
    std::lock_guard<std::mutex> lock(limit_mutex);
    EXPECT_EQ(permits.back().permit.speed_limit, topic_limit);
  }

  // A silent laser: a stop, and the permits say so.
  ASSERT_TRUE(world.runUntil(5.0, false, false, true));
  EXPECT_EQ(world.status_.reason, wheelchair_msgs::SafetyStatus::LASER_SILENT) << world.status_;
  t = ros::WallTime::now();
  world.run(0.3, true);
  permits = driver->since(t);
  ASSERT_FALSE(permits.empty());
  EXPECT_TRUE(permits.back().permit.stop);
  EXPECT_EQ(permits.back().permit.speed_limit, 0.0) << "a stop is a limit of 0";

  // Another node says "no stop" and re-sends the plan and a goal: the stop holds.
  ros::NodeHandle nh;
  ros::Publisher foreign_stop = nh.advertise<std_msgs::Bool>("safety/stop", 1);
  ros::Publisher goal_pub = nh.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
  ros::WallDuration(0.5).sleep();  // connections
  std_msgs::Bool no_stop;
  no_stop.data = false;
  foreign_stop.publish(no_stop);
  geometry_msgs::PoseStamped goal;
  goal.header.frame_id = "map";
  goal.header.stamp = ros::Time::now();
  goal.pose.position.x = 8.0;
  goal.pose.position.y = 2.0;
  goal.pose.orientation.w = 1.0;
  goal_pub.publish(goal);
  const ros::WallTime foreign = ros::WallTime::now();
  world.run(2.0, true);  // healthy data again
  EXPECT_TRUE(world.status_.stop) << "a foreign /safety/stop false or goal released the stop: "
                                  << world.status_;
  for (const auto& p : driver->since(foreign))
    ASSERT_TRUE(p.permit.stop) << "a permit to go without the rider's release";
  EXPECT_TRUE(driver->since(ros::WallTime::now() - ros::WallDuration(0.2)).back().permit.stop);

  // The rider's release (the HMI's call) lifts it; the driver's latch is released too.
  EXPECT_TRUE(wheelchair_ros::releaseStopByRider("test: the rider chose a destination"));
  EXPECT_TRUE(world.runUntil(2.0, true, false, false)) << world.status_;
  t = ros::WallTime::now();
  world.run(0.3, true);
  permits = driver->since(t);
  ASSERT_FALSE(permits.empty());
  EXPECT_FALSE(permits.back().permit.stop);
  {
    std::lock_guard<std::mutex> lock(driver->mutex);
    EXPECT_EQ(driver->releases, 1);
  }

  // Unloaded, the supervisor permits nothing more (the driver brakes after permit_timeout).
  ASSERT_TRUE(loader->unload("/safety"));
  EXPECT_FALSE(channel->hasSupervisor());
  t = ros::WallTime::now();
  world.run(0.5, true);
  EXPECT_TRUE(driver->since(t).empty()) << "permits after the supervisor was unloaded";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_safety_node");
  ros::NodeHandle nh;
  if (scenario() == "command_path") {
    loader = std::make_unique<nodelet::Loader>(false);  // /safety's parameters from the .test
    if (!loader->load("/safety", "wheelchair_safety/SafetyNodelet", {}, {})) return 1;
  }
  const int result = RUN_ALL_TESTS();
  loader.reset();
  return result;
}
