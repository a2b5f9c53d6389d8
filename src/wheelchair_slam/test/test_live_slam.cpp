// The live mode's core (LiveSlam): the synthetic two-lap drive of test_graph_slam fed scan by
// scan while the worker thread closes the loops and grows the map; and the SLAM nodelet's
// parameter list (slam_node_config.h, ROS-free).
#include <gtest/gtest.h>
#include <wheelchair_core/config.h>
#include <wheelchair_slam/live_slam.h>
#include <yaml-cpp/yaml.h>

#include <atomic>
#include <chrono>

#include "slam_node_config.h"
#include "synthetic_world.h"

namespace wheelchair_slam {
namespace {

using wheelchair_core::Pose2D;

using wheelchair_slam_test::maxError;

TEST(LiveSlam, ClosesTheLoopsOnItsWorkerAndTheGrownMapEqualsTheMapOfEveryScan) {
  std::mt19937 rng(11);
  const auto truth = wheelchair_slam_test::loopDrive(0.2, 2);
  const auto odometry = wheelchair_slam_test::driftingOdometry(truth, 1.03, 0.02, 0.002, rng);
  const auto world = wheelchair_slam_test::officeWorld();
  ASSERT_GT(maxError(odometry, truth), 2.0) << "the odometry must be bad for the test to mean it";

  std::atomic<int> maps{0};
  wheelchair_core::OccupancyMap last;
  std::mutex last_mutex;
  wheelchair_mapping::MapperConfig grid;
  LiveSlam slam(SlamConfig(), grid, 0.05, [&](const wheelchair_core::OccupancyMap& m) {
    std::lock_guard<std::mutex> lock(last_mutex);
    last = m;
    ++maps;
  });
  for (size_t i = 0; i < truth.size(); ++i) {
    ASSERT_TRUE(slam.addScan(wheelchair_slam_test::castScan(world, truth[i], 0.2 * i, 0.01, rng),
                             odometry[i]));
  }
  ASSERT_TRUE(slam.waitIdle(std::chrono::seconds(60))) << "the back end never caught up";
  const SlamStats stats = slam.stats();
  EXPECT_GT(stats.loops_verified, 5u) << "the second lap closes loops with the first";
  EXPECT_EQ(slam.scans(), truth.size());
  // Live, without the offline run's final pass: the loops still bound the drift.
  EXPECT_LT(maxError(slam.trajectory(), truth), 0.10);
  // map -> odom applied to the last odometry is the last scan's pose.
  const Pose2D last_pose = slam.trajectory().back();
  const Pose2D via_odom = wheelchair_core::compose(slam.mapToOdom(), odometry.back());
  EXPECT_NEAR(via_odom.x, last_pose.x, 1e-9);
  EXPECT_NEAR(via_odom.y, last_pose.y, 1e-9);
  EXPECT_GT(maps.load(), 0);
  const wheelchair_core::OccupancyMap rebuilt = slam.buildMapNow();
  std::lock_guard<std::mutex> lock(last_mutex);
  ASSERT_EQ(last.width, rebuilt.width);
  ASSERT_EQ(last.height, rebuilt.height);
  EXPECT_EQ(last.data, rebuilt.data) << "the incrementally grown map is the map of every scan";
}

TEST(LiveSlam, AScanOlderThanTheLastOrWithNonFiniteOdometryIsNotUsed) {
  std::mt19937 rng(3);
  const auto world = wheelchair_slam_test::officeWorld();
  LiveSlam slam(SlamConfig(), wheelchair_mapping::MapperConfig(), 1.0, nullptr);
  const Pose2D start{-7.5, -4.0, 0.0};
  ASSERT_TRUE(slam.addScan(wheelchair_slam_test::castScan(world, start, 1.0, 0.01, rng), start));
  EXPECT_FALSE(slam.addScan(wheelchair_slam_test::castScan(world, start, 0.5, 0.01, rng), start));
  EXPECT_FALSE(slam.addScan(wheelchair_slam_test::castScan(world, start, 1.1, 0.01, rng),
                            Pose2D{NAN, 0.0, 0.0}));
  EXPECT_EQ(slam.scans(), 1u);
}

SlamNodeConfig load(const std::string& yaml) {
  return wheelchair_core::loadConfig<SlamNodeConfig>(
      wheelchair_core::YamlParameterSource(YAML::Load(yaml), "/slam"), readSlamNodeConfig);
}

TEST(SlamNodeConfig, ReadsTheCoresKeysTheMapsAndItsOwn) {
  const SlamNodeConfig c =
      load("{loops: {search_radius: 3.0}, resolution: 0.1, map_period: 5.0, map_frame: m}");
  EXPECT_EQ(c.slam.loops.search_radius, 3.0);
  EXPECT_EQ(c.map.resolution, 0.1);
  EXPECT_EQ(c.map_period, 5.0);
  EXPECT_EQ(c.map_frame, "m");
}

TEST(SlamNodeConfig, UnknownRenamedAndInvalidKeysAreRefusedByName) {
  auto refused = [](const std::string& yaml, const std::string& named) {
    try {
      load(yaml);
    } catch (const wheelchair_core::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused("{map_perod: 2.0}", "map_perod"));
  EXPECT_TRUE(refused("{global_frame: map}", "map_frame"));
  EXPECT_TRUE(refused("{map_period: 0.0}", "map_period"));
  EXPECT_TRUE(refused("{start_pose: [1.0, 2.0, 0.0]}", "continue_dir"));
  EXPECT_TRUE(refused("{continue_dir: d, start_pose: [1.0, 2.0]}", "start_pose"));
  EXPECT_TRUE(refused("{odom_frame: map}", "differ"));
}

}  // namespace
}  // namespace wheelchair_slam
