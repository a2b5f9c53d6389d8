// Saving a SLAM run and continuing it with a new drive (slam_session.h, GraphSlam's continuing
// constructor), on the synthetic office of synthetic_world.h: the truth is the poses the scans
// were cast from.
#include <gtest/gtest.h>
#include <wheelchair_slam/graph_slam.h>
#include <wheelchair_slam/live_slam.h>
#include <wheelchair_slam/slam_map.h>
#include <wheelchair_slam/slam_session.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "synthetic_world.h"

namespace wheelchair_slam {
namespace {

using wheelchair_core::Pose2D;

using wheelchair_slam_test::Drive;

/// `laps` laps around the block; the odometry starts at `odometry_start` (its own frame).
Drive drive(int laps, unsigned seed, const Pose2D& odometry_start, double stamp0) {
  std::mt19937 rng(seed);
  Drive d;
  d.truth = wheelchair_slam_test::loopDrive(0.2, laps);
  const auto odo = wheelchair_slam_test::driftingOdometry(d.truth, 1.03, 0.02, 0.002, rng);
  // The same odometry seen from another origin: start at odometry_start.
  const Pose2D shift = wheelchair_core::compose(odometry_start, wheelchair_core::inverse(odo[0]));
  for (const Pose2D& p : odo) d.odometry.push_back(wheelchair_core::compose(shift, p));
  const auto world = wheelchair_slam_test::officeWorld();
  for (size_t i = 0; i < d.truth.size(); ++i) {
    d.scans.push_back(
        wheelchair_slam_test::castScan(world, d.truth[i], stamp0 + 0.2 * i, 0.01, rng));
  }
  return d;
}

/// The first drive's map frame is its first pose (its odometry at the start): truth[0] there.
double maxError(const std::vector<Pose2D>& estimate, const std::vector<Pose2D>& truth,
                const Pose2D& map_to_world) {
  double worst = 0.0;
  for (size_t i = 0; i < truth.size(); ++i) {
    const Pose2D p = wheelchair_core::compose(map_to_world, estimate[i]);
    worst = std::max(worst, std::hypot(p.x - truth[i].x, p.y - truth[i].y));
  }
  return worst;
}

std::string tempDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(SlamSession, ASavedRunLoadsBackAsTheSameGraphAndScans) {
  const Drive d = drive(1, 3, {0, 0, 0}, 0.0);
  GraphSlam slam{SlamConfig()};
  for (size_t i = 0; i < d.scans.size(); ++i) slam.addScan(d.scans[i], d.odometry[i]);
  slam.finish();
  const std::string dir = tempDir("slam_session_roundtrip");
  saveSlam(dir, slam, d.scans);
  const SavedSlam back = loadSlam(dir, SlamConfig());
  const KeyframeGraph& g = slam.keyframeGraph();
  ASSERT_EQ(back.graph.keyframes.size(), g.keyframes.size());
  ASSERT_EQ(back.records.size(), d.scans.size());
  size_t active = 0;
  for (const GraphEdge& e : g.graph.edges()) active += e.active;
  ASSERT_EQ(back.graph.graph.edges().size(), active);
  for (size_t k = 0; k < g.keyframes.size(); ++k) {
    EXPECT_NEAR(back.graph.graph.poses()[k].x, g.graph.poses()[k].x, 1e-6);
    EXPECT_NEAR(back.graph.graph.poses()[k].yaw, g.graph.poses()[k].yaw, 1e-6);
    EXPECT_EQ(back.graph.keyframes[k].scan, g.keyframes[k].scan);
    EXPECT_EQ(back.graph.keyframes[k].points->size(), g.keyframes[k].points->size());
  }
  EXPECT_NEAR(back.graph.graph.totalChi2(), g.graph.totalChi2(), 1e-3 * g.graph.totalChi2() + 1e-6);
  for (size_t i = 0; i < d.scans.size(); ++i) {
    ASSERT_EQ(back.scans[i].ranges.size(), d.scans[i].ranges.size());
    for (size_t b = 0; b < d.scans[i].ranges.size(); ++b) {
      const float r = d.scans[i].ranges[b];
      if (std::isfinite(r))
        EXPECT_EQ(back.scans[i].ranges[b], r);
      else
        EXPECT_TRUE(std::isinf(back.scans[i].ranges[b]));  // +inf: no return (REP-117)
    }
  }
  size_t kept = 0;
  for (const LoopClosure& l : g.loops) kept += l.kept;
  EXPECT_EQ(back.graph.loops.size(), kept);
}

TEST(SlamSession, ASecondDriveWithItsOwnOdometryFrameContinuesTheMapToAFewCentimetres) {
  const Drive first = drive(1, 5, {0, 0, 0}, 0.0);
  GraphSlam one{SlamConfig()};
  for (size_t i = 0; i < first.scans.size(); ++i) one.addScan(first.scans[i], first.odometry[i]);
  one.finish();
  const std::string dir = tempDir("slam_session_continue");
  saveSlam(dir, one, first.scans);
  // Map frame = the first odometry pose at the first truth pose.
  const Pose2D map_to_world =
      wheelchair_core::compose(first.truth[0], wheelchair_core::inverse(first.odometry[0]));

  // The chair switched off and on: the second drive's odometry starts at (5, -3, 1) of a frame
  // of its own, and the carer's start pose is 0.3 m and 0.1 rad off.
  const Drive second = drive(1, 6, {5.0, -3.0, 1.0}, 1000.0);
  SavedSlam saved = loadSlam(dir, SlamConfig());
  GraphSlam two{SlamConfig(), std::move(saved.graph), saved.records};
  const Pose2D true_start =
      wheelchair_core::compose(wheelchair_core::inverse(map_to_world), second.truth[0]);
  two.startDrive(wheelchair_core::compose(true_start, {0.3, -0.2, 0.1}));
  for (size_t i = 0; i < second.scans.size(); ++i) {
    ASSERT_TRUE(two.addScan(second.scans[i], second.odometry[i])) << "scan " << i;
  }
  two.finish();
  EXPECT_EQ(two.stats().drives, 2u);
  const auto estimate = two.trajectory();
  ASSERT_EQ(estimate.size(), first.scans.size() + second.scans.size());
  const std::vector<Pose2D> new_part(estimate.begin() + first.scans.size(), estimate.end());
  EXPECT_LT(maxError(new_part, second.truth, map_to_world), 0.05);
  const std::vector<Pose2D> old_part(estimate.begin(), estimate.begin() + first.scans.size());
  EXPECT_LT(maxError(old_part, first.truth, map_to_world), 0.05);
  // The odometry alone, from the carer's start, is far off: the map is what placed the drive.
  std::vector<Pose2D> dead_reckoning;
  for (const Pose2D& o : second.odometry) {
    dead_reckoning.push_back(
        wheelchair_core::compose(wheelchair_core::compose(true_start, {0.3, -0.2, 0.1}),
                                 wheelchair_core::between(second.odometry[0], o)));
  }
  EXPECT_GT(maxError(dead_reckoning, second.truth, map_to_world), 1.0);
}

TEST(SlamSession, ALiveContinuedMapTakesANewDriveOnAClockThatStartedAgain) {
  // The saved drive ran from t = 1000 s; the new one's clock starts at 0 (the simulator's after
  // a restart): its scans are used once located, and the order is kept within the new drive.
  const Drive first = drive(1, 8, {0, 0, 0}, 1000.0);
  GraphSlam one{SlamConfig()};
  for (size_t i = 0; i < first.scans.size(); ++i) one.addScan(first.scans[i], first.odometry[i]);
  one.finish();
  const std::string dir = tempDir("slam_session_clock");
  saveSlam(dir, one, first.scans);
  const Pose2D map_to_world =
      wheelchair_core::compose(first.truth[0], wheelchair_core::inverse(first.odometry[0]));

  const Drive second = drive(1, 9, {2.0, 1.0, -0.5}, 0.0);
  const Pose2D true_start =
      wheelchair_core::compose(wheelchair_core::inverse(map_to_world), second.truth[0]);
  LiveSlam live(SlamConfig(), wheelchair_mapping::MapperConfig(), 1.0, nullptr,
                loadSlam(dir, SlamConfig()),
                wheelchair_core::compose(true_start, {0.1, -0.1, 0.03}));
  const size_t n = 60;
  for (size_t i = 0; i < n; ++i) {
    ASSERT_TRUE(live.addScan(second.scans[i], second.odometry[i])) << "scan " << i;
  }
  EXPECT_FALSE(live.addScan(second.scans[n - 2], second.odometry[n - 2]))
      << "within the new drive a scan older than the last is not used";
  ASSERT_TRUE(live.waitIdle(std::chrono::seconds(60)));
  EXPECT_EQ(live.stats().drives, 2u);
  const auto estimate = live.trajectory();
  ASSERT_EQ(estimate.size(), first.scans.size() + n);
  const std::vector<Pose2D> new_part(estimate.begin() + first.scans.size(), estimate.end());
  EXPECT_LT(maxError(new_part, {second.truth.begin(), second.truth.begin() + n}, map_to_world),
            0.05);
  // The map holds the new drive's scans too, though they are older than the saved drive's.
  wheelchair_mapping::BayesMapper saved_only(wheelchair_mapping::MapperConfig{});
  for (size_t i = 0; i < first.scans.size(); ++i)
    ASSERT_TRUE(insertAtPose(saved_only, first.scans[i], estimate[i], i).inserted);
  EXPECT_NE(live.buildMapNow().data, saved_only.map().data);
  size_t skipped = 99;
  std::vector<wheelchair_core::LaserScan2D> both(first.scans.begin(), first.scans.end());
  both.insert(both.end(), second.scans.begin(), second.scans.begin() + n);
  buildMap(both, estimate, wheelchair_mapping::MapperConfig{}, &skipped);
  EXPECT_EQ(skipped, 0u) << "no scan of either drive is refused for its clock";
}

// A continued map holds its drives one after another: the nearest keyframe's neighbours in the
// graph's order may lie in another drive, elsewhere. Here the saved lap's keyframes are put in
// a shuffled order (no index neighbour is a spatial one); a new drive's first scan, 0.3 m and
// 0.05 rad from its odometry-predicted start, is still matched against the keyframes nearest
// that start (checked against a search of its own) and placed to a few centimetres.
TEST(SlamSession, ANewDriveIsPlacedAmongTheKeyframesNearestItsPredictedStartNotItsIndexNeighbours) {
  const Drive d = drive(1, 5, {0, 0, 0}, 0.0);
  const SlamConfig config;
  GraphSlam slam{config};
  for (size_t i = 0; i < d.scans.size(); ++i) slam.addScan(d.scans[i], d.odometry[i]);
  slam.finish();
  const KeyframeGraph& g = slam.keyframeGraph();
  ASSERT_GT(g.keyframes.size(), 40u);
  std::vector<size_t> order(g.keyframes.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::mt19937 rng(17);
  std::shuffle(order.begin(), order.end(), rng);
  KeyframeGraph shuffled;
  for (size_t k : order) {
    shuffled.graph.addNode(g.graph.poses()[k]);
    shuffled.keyframes.push_back(g.keyframes[k]);
  }
  // Where the truth's pose 40 lies in the map frame (the map frame: the drive's first pose).
  const std::vector<Pose2D> estimate = slam.trajectory();
  const Pose2D world_to_map =
      wheelchair_core::compose(estimate[0], wheelchair_core::inverse(d.truth[0]));
  const Pose2D truth = wheelchair_core::compose(world_to_map, d.truth[40]);
  std::mt19937 noise(23);
  const Points points =
      scanPoints(wheelchair_slam_test::castScan(wheelchair_slam_test::officeWorld(), d.truth[40],
                                                100.0, 0.01, noise),
                 config.matcher.max_range, config.matcher.point_spacing);
  const Pose2D guess = wheelchair_core::compose(truth, Pose2D{0.3, -0.15, 0.05});

  const DriveStart start = LoopCloser(config).locate(shuffled, points, guess);
  std::vector<std::pair<double, size_t>> by_distance;  // the test's own nearest keyframes
  for (size_t j = 0; j < shuffled.keyframes.size(); ++j) {
    const Pose2D& p = shuffled.graph.poses()[j];
    by_distance.emplace_back(std::hypot(p.x - guess.x, p.y - guess.y), j);
  }
  std::sort(by_distance.begin(), by_distance.end());
  const size_t n = 2 * static_cast<size_t>(config.loops.submap_half_width) + 1;
  ASSERT_EQ(start.submap.size(), n);
  for (size_t i = 0; i < n; ++i) {
    EXPECT_EQ(start.submap[i], by_distance[i].second) << "the " << i << "th nearest keyframe";
  }
  EXPECT_EQ(start.anchor, by_distance[0].second);
  ASSERT_TRUE(start.located) << "score " << start.score;
  EXPECT_LT(std::hypot(start.pose.x - truth.x, start.pose.y - truth.y), 0.05);
  EXPECT_LT(std::abs(wheelchair_core::angleDifference(start.pose.yaw, truth.yaw)), 0.02);
}

TEST(SlamSession, ADriveStartedWhereTheMapHasNoKeyframeIsNotLocatedAndAddsNothing) {
  const Drive first = drive(1, 7, {0, 0, 0}, 0.0);
  GraphSlam slam{SlamConfig()};
  for (size_t i = 0; i < 60; ++i) slam.addScan(first.scans[i], first.odometry[i]);
  const size_t scans = slam.scanRecords().size();
  slam.startDrive({40.0, 40.0, 0.0});  // 40 m outside the office
  EXPECT_FALSE(slam.addScan(first.scans[100], first.odometry[100]));
  EXPECT_EQ(slam.scanRecords().size(), scans);
  EXPECT_TRUE(slam.awaitingDriveStart());
}

TEST(SlamSession, ABadFileIsRefusedNamingItsLine) {
  const Drive d = drive(1, 8, {0, 0, 0}, 0.0);
  GraphSlam slam{SlamConfig()};
  for (size_t i = 0; i < 40; ++i) slam.addScan(d.scans[i], d.odometry[i]);
  const std::string dir = tempDir("slam_session_bad");
  saveSlam(dir, slam,
           std::vector<wheelchair_core::LaserScan2D>(d.scans.begin(), d.scans.begin() + 40));
  {
    std::ofstream out(dir + "/graph.graph", std::ios::app);
    out << "EDGE_SE2 0 x 1 2 3 1 0 0 1 0 1\n";
  }
  try {
    loadSlam(dir, SlamConfig());
    FAIL() << "a bad edge was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("graph.graph:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'x' is not a number"), std::string::npos) << e.what();
  }
  EXPECT_THROW(loadSlam(dir + "/missing", SlamConfig()), std::runtime_error);
}

}  // namespace
}  // namespace wheelchair_slam
