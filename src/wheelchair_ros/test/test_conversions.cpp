#include <gtest/gtest.h>
#include <wheelchair_ros/conversions.h>

#include <cmath>
#include <set>
#include <string>

namespace wheelchair_ros {
namespace {

using wheelchair_core::LaserScan2D;
using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;

TEST(RosConversions, RoundTripKeepsEverything) {
  OccupancyMap map;
  map.resolution = 0.1;
  map.origin_x = 1.25;
  map.origin_y = -4.5;
  map.origin_yaw = 0.3;
  map.width = 3;
  map.height = 2;
  map.data = {0, 100, -1, 50, 0, 0};
  const auto msg = toOccupancyGrid(map, "map", ros::Time(12.5));
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_EQ(msg.info.width, 3u);
  EXPECT_EQ(msg.info.height, 2u);
  EXPECT_NEAR(msg.info.origin.orientation.z, std::sin(0.15), 1e-12);
  EXPECT_EQ(msg.data[1], 100);  // row-major, row 0 at the bottom in both
  const OccupancyMap back = fromOccupancyGrid(msg);
  EXPECT_NEAR(back.resolution, 0.1, 1e-7);
  EXPECT_EQ(back.origin_x, 1.25);
  EXPECT_EQ(back.origin_y, -4.5);
  EXPECT_NEAR(back.origin_yaw, 0.3, 1e-12);
  EXPECT_EQ(back.data, map.data);
}

TEST(RosConversions, RejectsInconsistentMessages) {
  nav_msgs::OccupancyGrid msg;
  msg.info.width = 2;
  msg.info.height = 2;
  msg.info.resolution = 0.05f;
  msg.data.resize(3);
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
  msg.data.resize(4);
  msg.info.resolution = 0.0f;
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
  msg.info.resolution = -0.05f;
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
  msg.info.resolution = 0.05f;
  msg.info.origin.position.x = NAN;
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
}

// Any node can publish /map: a huge grid, garbage cells or an empty grid are refused with a
// reason before anything is copied (the 4000 x 4000 map that took the chair to 840 MB).
TEST(RosConversions, RefusesMapsBeyondTheMemoryCapOrWithBadCellsWithAReason) {
  nav_msgs::OccupancyGrid msg;
  msg.info.resolution = 0.05f;
  msg.info.width = msg.info.height = 4000;
  msg.data.assign(4000u * 4000u, 0);
  const std::string huge = occupancyGridProblem(msg);
  EXPECT_NE(huge.find("4000 x 4000"), std::string::npos) << huge;
  EXPECT_NE(huge.find("max_map_cells 1048576"), std::string::npos) << huge;
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
  wheelchair_core::MapLimits roomy;
  roomy.max_cells = 4000 * 4000;
  EXPECT_EQ(occupancyGridProblem(msg, roomy), "");  // the cap is a parameter
  // Width x height overflowing 32 bits is caught before the data size is compared.
  msg.info.width = msg.info.height = 70000;
  msg.data.clear();
  EXPECT_NE(occupancyGridProblem(msg, roomy).find("exceeds max_map_cells"), std::string::npos);
  msg.info.width = msg.info.height = 0;
  EXPECT_NE(occupancyGridProblem(msg).find("no cells"), std::string::npos);
  msg.info.width = 2;
  msg.info.height = 2;
  msg.data = {0, 100, -1, 101};
  EXPECT_NE(occupancyGridProblem(msg).find("cell 3 has value 101"), std::string::npos)
      << occupancyGridProblem(msg);
  msg.data[3] = -2;
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
  msg.data[3] = 50;
  EXPECT_EQ(occupancyGridProblem(msg), "");
  msg.info.resolution = -0.05f;
  EXPECT_NE(occupancyGridProblem(msg).find("resolution"), std::string::npos);
  msg.info.resolution = NAN;
  EXPECT_NE(occupancyGridProblem(msg).find("resolution"), std::string::npos);
}

TEST(RosConversions, ADefaultConstructedOriginIsNoRotation) {
  nav_msgs::OccupancyGrid msg;
  msg.info.width = msg.info.height = 1;
  msg.info.resolution = 0.05f;
  msg.data.resize(1);
  EXPECT_EQ(fromOccupancyGrid(msg).origin_yaw, 0.0);
}

TEST(RosConversions, YawRoundTripsThroughTheQuaternion) {
  for (double yaw = -3.1; yaw < 3.1; yaw += 0.37) {
    const geometry_msgs::Quaternion q = yawToQuaternion(yaw);
    EXPECT_TRUE(isNormalized(q));
    EXPECT_NEAR(yawOf(q), yaw, 1e-12);
  }
  geometry_msgs::Quaternion bad;
  bad.w = 2.0;
  EXPECT_FALSE(isNormalized(bad));
}

TEST(RosConversions, PosesAndPathsRoundTrip) {
  const std::vector<Pose2D> poses = {{1, 2, 0.5}, {3, -4, -2.0}};
  const nav_msgs::Path path = toPathMsg(poses, "map", ros::Time(3.0));
  ASSERT_EQ(path.poses.size(), 2u);
  EXPECT_EQ(path.poses[1].header.frame_id, "map");
  const auto back = fromPathMsg(path);
  EXPECT_NEAR(back[1].x, 3.0, 1e-12);
  EXPECT_NEAR(back[1].yaw, -2.0, 1e-12);
  const Pose2D t = toPose2D(toTransformMsg({0.5, 0.25, 1.0}));
  EXPECT_NEAR(t.yaw, 1.0, 1e-12);
}

TEST(RosConversions, PlanarCovarianceIsTheXYYawBlock) {
  Eigen::Matrix3d c;
  c << 1, 2, 3, 2, 5, 6, 3, 6, 9;
  const auto ros_cov = toRosCovariance(c);
  EXPECT_EQ(ros_cov[0], 1);
  EXPECT_EQ(ros_cov[5], 3);   // x-yaw
  EXPECT_EQ(ros_cov[35], 9);  // yaw-yaw
  EXPECT_EQ(ros_cov[14], 0);  // z-z
  EXPECT_EQ(planarCovariance(ros_cov), c);
}

TEST(RosConversions, AnEstimateAndACloudKeepTheirPosesAndCovariance) {
  Eigen::Matrix3d c;
  c << 0.04, 0.01, 0, 0.01, 0.09, 0, 0, 0, 0.0025;
  const auto estimate = toPoseWithCovarianceMsg({1.0, -2.0, 0.3}, c);
  EXPECT_EQ(toPose2D(estimate.pose).x, 1.0);
  EXPECT_NEAR(toPose2D(estimate.pose).yaw, 0.3, 1e-12);
  EXPECT_EQ(planarCovariance(estimate.covariance), c);
  const auto cloud = toPoseArrayMsg({{1, 2, 0.5}, {3, -4, -2.0}}, "map", ros::Time(2.0));
  ASSERT_EQ(cloud.poses.size(), 2u);
  EXPECT_EQ(cloud.header.frame_id, "map");
  EXPECT_EQ(cloud.header.stamp, ros::Time(2.0));
  EXPECT_NEAR(toPose2D(cloud.poses[1]).yaw, -2.0, 1e-12);
}

TEST(RosConversions, ALocalizationStatusKeepsItsStateNumbersAndReason) {
  wheelchair_core::LocalizationStatus status;
  status.state = wheelchair_core::LocalizationState::kAmbiguous;
  status.detail = "ambiguous: 2 pose hypotheses (best holds 60 % of the weight)";
  status.hypotheses = 2;
  status.best_weight = 0.6;
  status.particles = 1234;
  const auto m = toLocalizationStatusMsg(status, ros::Time(5.0));
  EXPECT_EQ(m.state, wheelchair_msgs::LocalizationStatus::AMBIGUOUS);
  EXPECT_FALSE(m.localized);
  EXPECT_EQ(m.detail, status.detail);
  EXPECT_FALSE(m.sentence.empty());
  EXPECT_EQ(m.sentence.find("hypotheses"), std::string::npos) << "no technical words for the rider";
  EXPECT_EQ(m.hypotheses, 2);
  EXPECT_EQ(m.particles, 1234);
  EXPECT_TRUE(std::isnan(m.position_std));
  EXPECT_EQ(m.header.stamp, ros::Time(5.0));
  status.state = wheelchair_core::LocalizationState::kLocalized;
  const auto ok = toLocalizationStatusMsg(status, ros::Time(6.0));
  EXPECT_EQ(ok.state, wheelchair_msgs::LocalizationStatus::LOCALIZED);
  EXPECT_TRUE(ok.localized);
  // Every state has its own sentence.
  std::set<std::string> sentences;
  for (int s = 0; s <= static_cast<int>(wheelchair_core::LocalizationState::kNoData); ++s)
    sentences.insert(
        wheelchair_core::riderSentence(static_cast<wheelchair_core::LocalizationState>(s)));
  EXPECT_EQ(sentences.size(), 7u);
}

TEST(RosConversions, AnUpsideDownLaserIsRecognized) {
  geometry_msgs::Transform t;
  t.rotation.x = 1.0;  // 180 deg about x: z points down
  t.rotation.w = 0.0;
  Pose2D pose;
  EXPECT_TRUE(laserPose2D(t, pose));
  t.rotation = yawToQuaternion(0.7);
  EXPECT_FALSE(laserPose2D(t, pose));
  EXPECT_NEAR(pose.yaw, 0.7, 1e-12);
}

TEST(RosConversions, LaserScanRoundTrips) {
  LaserScan2D s;
  s.stamp = 4.5;
  s.angle_min = -1.0;
  s.angle_max = 1.0;
  s.angle_increment = 1.0;
  s.range_min = 0.1;
  s.range_max = 8.0;
  s.ranges = {1.0f, INFINITY, 2.0f};
  const LaserScan2D back = fromLaserScanMsg(toLaserScanMsg(s, "laser"));
  EXPECT_DOUBLE_EQ(back.stamp, 4.5);
  EXPECT_EQ(back.ranges, s.ranges);
  EXPECT_FLOAT_EQ(back.range_max, 8.0f);
}

}  // namespace
}  // namespace wheelchair_ros
