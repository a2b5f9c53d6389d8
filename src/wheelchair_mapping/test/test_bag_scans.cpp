// Scans from a rosbag: laser poses from the bag's /tf + /tf_static at each scan's stamp; scans
// without tf are reported and skipped; the map built from them has the wall where it is.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>
#include <wheelchair_logs/bag_scans.h>
#include <wheelchair_mapping/bayes_mapper.h>

#include <cmath>

#include "map_test_files.h"

namespace wheelchair_mapping {
namespace {

using wheelchair_logs::BagScanReader;
using wheelchair_logs::LogScan;

geometry_msgs::TransformStamped transform(const std::string& parent, const std::string& child,
                                          double t, double x, double yaw) {
  geometry_msgs::TransformStamped tf;
  tf.header.stamp = ros::Time(t);
  tf.header.frame_id = parent;
  tf.child_frame_id = child;
  tf.transform.translation.x = x;
  tf.transform.rotation.z = std::sin(yaw / 2);
  tf.transform.rotation.w = std::cos(yaw / 2);
  return tf;
}

sensor_msgs::LaserScan scanAt(double t) {
  sensor_msgs::LaserScan s;
  s.header.stamp = ros::Time(t);
  s.header.frame_id = "laser";
  s.angle_min = -0.1;
  s.angle_max = 0.1;
  s.angle_increment = 0.1;
  s.range_min = 0.1;
  s.range_max = 10.0;
  s.ranges.assign(3, 5.025f - 0.1f * static_cast<float>(t));  // a wall at x = 5.325 in odom
  return s;
}

TEST(BagScans, PosesFromTfAndScansWithoutTfSkipped) {
  wheelchair_core::test::TempDir dir;
  const std::string path = dir.file("drive.bag");
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    tf2_msgs::TFMessage fixed;
    fixed.transforms.push_back(transform("base_link", "laser", 0.5, 0.3, 0.0));
    bag.write("/tf_static", ros::Time(0.5), fixed);
    for (int k = 0; k <= 10; ++k) {
      const double t = 1.0 + 0.5 * k;  // odom -> base_link: 0.1 m per second along x
      tf2_msgs::TFMessage moving;
      moving.transforms.push_back(transform("odom", "base_link", t, 0.1 * t, 0.0));
      moving.transforms.back().transform.translation.y = 0.025;  // beams along a cell's middle
      bag.write("/tf", ros::Time(t), moving);
    }
    for (int t = 1; t <= 5; ++t) bag.write("/scan", ros::Time(t), scanAt(t));
    bag.write("/scan", ros::Time(100), scanAt(100));  // long after the last tf
  }
  BagScanReader reader(path, "/scan", "odom");
  BayesMapper mapper(MapperConfig{});
  LogScan s;
  int n = 0;
  while (reader.next(s)) {
    ++n;
    EXPECT_NEAR(s.laser_pose.x, 0.1 * n + 0.3, 1e-9);
    EXPECT_NEAR(s.laser_pose.yaw, 0.0, 1e-12);
    EXPECT_TRUE(mapper.insert(s.scan, s.laser_pose).inserted);
  }
  EXPECT_EQ(n, 5);
  EXPECT_EQ(reader.problemCount(), 1u);
  EXPECT_NE(reader.problemsOfLastCall().find(path + ":scan 6: no tf"), std::string::npos)
      << reader.problemsOfLastCall();
  int ix, iy;
  const wheelchair_core::OccupancyMap map = mapper.map();
  ASSERT_TRUE(map.worldToCell(5.325, 0.025, ix, iy));
  EXPECT_EQ(map.at(ix, iy), wheelchair_core::kOccupied);
  EXPECT_THROW(BagScanReader(dir.file("none.bag"), "/scan", "odom"), std::runtime_error);
}

}  // namespace
}  // namespace wheelchair_mapping
