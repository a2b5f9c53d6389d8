// rostest: feeds the localizer node a map, tf and synthetic scans of a drive in the flat world
// (laserScanSimulator, noisy odometry) and checks /kld_pose and /localization/status against the
// truth.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_ros/conversions.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "synthetic_drive.h"

using namespace wheelchair_kld::test;
using wheelchair_ros::toPose2D;
using wheelchair_ros::toPoseMsg;
using Status = wheelchair_msgs::LocalizationStatus;

namespace {
geometry_msgs::TransformStamped transform(const wheelchair_core::Pose2D& p,
                                          const std::string& parent, const std::string& child,
                                          const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform = wheelchair_ros::toTransformMsg(p);
  return t;
}
}  // namespace

/// The localizer node with the flat world's map, the laser's static tf and an initial pose at
/// the start of a synthetic drive (laserScanSimulator, noisy odometry).
class KldLocalizerNode : public testing::Test {
 protected:
  void SetUp() override {
    std::string world;
    ASSERT_TRUE(pnh_.getParam("world", world));
    const auto map = wheelchair_core::loadMap(world);
    drive_ = simulateDrive(loadWorldGrid(world), worldRoute("flat"), dp_);
    pose_sub_ = nh_.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
        "kld_pose", 10, [this](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex_);
          last_pose_ = *m;
          ++poses_;
        });
    status_sub_ =
        nh_.subscribe<Status>("localization/status", 50, [this](const Status::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex_);
          statuses_.push_back(*m);
        });
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 10);
    init_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", 1, true);
    static_tf_.sendTransform(transform(dp_.sensor_pose, "base_link", "laser", ros::Time::now()));
    map_pub_.publish(wheelchair_ros::toOccupancyGrid(map, "map", ros::Time::now()));
    // Wait for the localizer to subscribe and to have the map.
    for (int i = 0; i < 100 && (scan_pub_.getNumSubscribers() == 0 || statusCount() == 0); ++i)
      ros::Duration(0.05).sleep();
    ASSERT_GT(scan_pub_.getNumSubscribers(), 0u);
    geometry_msgs::PoseWithCovarianceStamped init;
    init.header.frame_id = "map";
    init.header.stamp = ros::Time::now();
    init.pose.pose = toPoseMsg(drive_[0].truth);
    init.pose.covariance[0] = init.pose.covariance[7] = 0.01;
    init.pose.covariance[35] = 0.0025;
    init_pub_.publish(init);
    ros::Duration(0.3).sleep();
  }

  sensor_msgs::LaserScan scanMsg(size_t i, const ros::Time& stamp) const {
    sensor_msgs::LaserScan scan = wheelchair_ros::toLaserScanMsg(drive_[i].scan, "laser");
    scan.header.stamp = stamp;
    return scan;
  }
  /// Sends odom -> base_link of drive sample i stamped `stamp`.
  void sendOdom(size_t i, const ros::Time& stamp) {
    tf_.sendTransform(transform(drive_[i].odom, "odom", "base_link", stamp));
  }
  Status status() {
    std::lock_guard<std::mutex> lock(mutex_);
    return statuses_.empty() ? Status() : statuses_.back();
  }
  bool localized() { return status().state == Status::LOCALIZED; }
  /// Statuses received from index `from` on.
  std::vector<Status> statusesSince(size_t from) {
    std::lock_guard<std::mutex> lock(mutex_);
    return {statuses_.begin() + std::min(from, statuses_.size()), statuses_.end()};
  }
  size_t statusCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return statuses_.size();
  }
  int poses() {
    std::lock_guard<std::mutex> lock(mutex_);
    return poses_;
  }
  geometry_msgs::PoseWithCovarianceStamped lastPose() {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_pose_;
  }

  ros::NodeHandle nh_, pnh_{"~"};
  DriveParams dp_;
  std::vector<DriveSample> drive_;
  std::mutex mutex_;
  geometry_msgs::PoseWithCovarianceStamped last_pose_;
  std::vector<Status> statuses_;
  int poses_ = 0;
  ros::Subscriber pose_sub_, status_sub_;
  ros::Publisher map_pub_, scan_pub_, init_pub_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  tf2_ros::TransformBroadcaster tf_;
};

TEST_F(KldLocalizerNode, TracksASyntheticDriveAndReportsLocalized) {
  const size_t n = std::min<size_t>(drive_.size(), 120);
  double worst = 0;
  for (size_t i = 0; i < n; ++i) {
    const ros::Time stamp = ros::Time::now();
    sendOdom(i, stamp);
    ros::Duration(0.01).sleep();
    scan_pub_.publish(scanMsg(i, stamp));
    ros::Duration(0.04).sleep();
    if (poses() > 0 && i > 10) {
      const auto p = toPose2D(lastPose().pose.pose);
      worst = std::max(worst, std::hypot(p.x - drive_[i].truth.x, p.y - drive_[i].truth.y));
    }
  }
  ros::Duration(0.2).sleep();
  EXPECT_GT(poses(), 20);
  EXPECT_EQ(lastPose().header.frame_id, "map");
  const auto p = toPose2D(lastPose().pose.pose);
  EXPECT_LT(std::hypot(p.x - drive_[n - 1].truth.x, p.y - drive_[n - 1].truth.y), 0.1);
  EXPECT_LT(worst, 0.25);
  EXPECT_TRUE(localized()) << status().detail;
}

// Odometry that lags the laser by 30 ms (each scan is published before the odom -> base_link
// transform at its stamp), even once by 130 ms, must not flip the status; a 1 s tf outage while
// scans keep coming must (naming the reason), and the status must recover once odometry is back.
TEST_F(KldLocalizerNode, ToleratesOdometryLagButReportsATfOutage) {
  size_t i = 0;
  auto step = [&](bool with_odom) {
    const ros::Time stamp = ros::Time::now();
    scan_pub_.publish(scanMsg(i, stamp));
    ros::Duration(0.03).sleep();
    if (with_odom) sendOdom(i, stamp);
    ros::Duration(0.07).sleep();
    ++i;
  };
  sendOdom(0, ros::Time::now());
  for (; i < 15;) step(true);  // first updates after the initial pose
  ASSERT_TRUE(localized()) << status().detail;
  const size_t lag_from = statusCount();
  for (; i < 45;) step(i != 30);  // scan 30's odometry never comes: it waits 130 ms for scan 31's
  const auto during_lag = statusesSince(lag_from);
  EXPECT_GE(during_lag.size(), 25u) << "scans with lagging odometry were not used";
  for (const auto& s : during_lag)
    EXPECT_EQ(s.state, Status::LOCALIZED) << "flipped by a 30 ms odom lag: " << s.detail;

  const size_t outage_from = statusCount();
  for (const size_t end = i + 10; i < end;) step(false);  // 1 s without odometry
  bool reported = false;
  for (const auto& s : statusesSince(outage_from))
    reported |= s.state == Status::NO_DATA && s.detail.rfind("tf missing", 0) == 0;
  EXPECT_TRUE(reported) << "a 1 s tf outage was not reported; last status: " << status().detail;

  for (const size_t end = i + 10; i < end;) step(true);
  EXPECT_TRUE(localized()) << "no recovery after the tf outage: " << status().detail;
}

// The nodelet's one loader refuses an old or misspelt parameter: `rosrun` exits 1 naming it.
TEST(KldLocalizerParams, AnOldOrUnknownParameterRefusesTheNode) {
  auto run = [](const std::string& args, std::string& output) {
    FILE* pipe = popen(
        ("rosrun wheelchair_kld kld_localizer __name:=refused " + args + " 2>&1").c_str(), "r");
    char buf[512];
    while (pipe && fgets(buf, sizeof buf, pipe)) output += buf;
    const int status = pipe ? pclose(pipe) : -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  std::string old_name, misspelt;
  EXPECT_EQ(run("_global_frame:=map", old_name), 1) << old_name;
  EXPECT_NE(old_name.find("'global_frame' is now called 'map_frame'"), std::string::npos)
      << old_name;
  ros::param::del("/refused");
  EXPECT_EQ(run("_fit_mean:=0.5", misspelt), 1) << misspelt;
  EXPECT_NE(misspelt.find("unknown parameter 'fit_mean'"), std::string::npos) << misspelt;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_kld_localizer_node");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
