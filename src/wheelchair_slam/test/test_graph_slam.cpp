// Graph SLAM on a synthetic drive: two laps around the block of an office, scans ray-cast at
// the exact poses, odometry with a 3 % scale error and a heading drift of 0.02 rad per metre.
#include <gtest/gtest.h>
#include <wheelchair_core/config.h>
#include <wheelchair_slam/graph_slam.h>
#include <yaml-cpp/yaml.h>

#include "synthetic_world.h"

namespace wheelchair_slam {
namespace {

using wheelchair_core::Pose2D;

struct Drive {
  std::vector<Pose2D> truth, odometry;
  std::vector<wheelchair_core::LaserScan2D> scans;
};

Drive syntheticDrive() {
  std::mt19937 rng(11);
  Drive d;
  d.truth = wheelchair_slam_test::loopDrive(0.2, 2);
  d.odometry = wheelchair_slam_test::driftingOdometry(d.truth, 1.03, 0.02, 0.002, rng);
  const auto world = wheelchair_slam_test::officeWorld();
  for (size_t i = 0; i < d.truth.size(); ++i) {
    d.scans.push_back(wheelchair_slam_test::castScan(world, d.truth[i], 0.2 * i, 0.01, rng));
  }
  return d;
}

/// Largest position error after aligning the first poses (the map frame starts there).
double maxError(const std::vector<Pose2D>& estimate, const std::vector<Pose2D>& truth) {
  const Pose2D align = wheelchair_core::compose(truth[0], wheelchair_core::inverse(estimate[0]));
  double worst = 0.0;
  for (size_t i = 0; i < truth.size(); ++i) {
    const Pose2D p = wheelchair_core::compose(align, estimate[i]);
    worst = std::max(worst, std::hypot(p.x - truth[i].x, p.y - truth[i].y));
  }
  return worst;
}

TEST(GraphSlam, RecoversADriftingDriveAroundABlockToAFewCentimetres) {
  const Drive d = syntheticDrive();
  ASSERT_GT(maxError(d.odometry, d.truth), 2.0)
      << "the odometry must be bad for the test to mean anything";
  GraphSlam slam{SlamConfig()};
  for (size_t i = 0; i < d.scans.size(); ++i) slam.addScan(d.scans[i], d.odometry[i]);
  slam.finish();
  const auto estimate = slam.trajectory();
  ASSERT_EQ(estimate.size(), d.truth.size());
  EXPECT_LT(maxError(estimate, d.truth), 0.05);
  size_t kept = 0;
  for (const LoopClosure& l : slam.loopClosures()) kept += l.kept;
  EXPECT_GT(kept, 5u) << "the second lap closes loops with the first";
  EXPECT_EQ(slam.stats().scans, d.truth.size());
}

TEST(GraphSlam, WithoutLoopClosuresTheSameDriveDrifts) {
  const Drive d = syntheticDrive();
  SlamConfig config;
  config.loops.enabled = false;
  GraphSlam slam{config};
  for (size_t i = 0; i < d.scans.size(); ++i) slam.addScan(d.scans[i], d.odometry[i]);
  slam.finish();
  EXPECT_TRUE(slam.loopClosures().empty());
  // Scan matching alone is far better than odometry, but the loops are what bound the error.
  EXPECT_LT(maxError(slam.trajectory(), d.truth), maxError(d.odometry, d.truth));
}

TEST(SlamConfig, AnUnknownKeyAndAnInvalidValueAreRefusedByName) {
  const YAML::Node typo = YAML::Load("loops: {search_radiuss: 3}");
  EXPECT_THROW(
      {
        try {
          wheelchair_core::loadConfig<SlamConfig>(
              wheelchair_core::YamlParameterSource(typo, "slam.yaml"), readSlamConfig);
        } catch (const wheelchair_core::ConfigError& e) {
          EXPECT_NE(std::string(e.what()).find("loops/search_radiuss"), std::string::npos);
          throw;
        }
      },
      wheelchair_core::ConfigError);
  const YAML::Node bad = YAML::Load("matcher: {min_goodness: 1.5}");
  EXPECT_THROW(wheelchair_core::loadConfig<SlamConfig>(
                   wheelchair_core::YamlParameterSource(bad, "slam.yaml"), readSlamConfig),
               wheelchair_core::ConfigError);
  SlamConfig invalid;
  invalid.keyframes.distance = -1;
  EXPECT_THROW(GraphSlam{invalid}, wheelchair_core::ConfigError);
}

}  // namespace
}  // namespace wheelchair_slam
