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

TEST(GraphSlam, RecoversADriftingDriveAroundABlockToAFewCentimetres) {
  const wheelchair_slam_test::Drive d = wheelchair_slam_test::syntheticDrive();
  ASSERT_GT(wheelchair_slam_test::maxError(d.odometry, d.truth), 2.0)
      << "the odometry must be bad for the test to mean anything";
  GraphSlam slam{SlamConfig()};
  for (size_t i = 0; i < d.scans.size(); ++i) slam.addScan(d.scans[i], d.odometry[i]);
  slam.finish();
  const auto estimate = slam.trajectory();
  ASSERT_EQ(estimate.size(), d.truth.size());
  EXPECT_LT(wheelchair_slam_test::maxError(estimate, d.truth), 0.05);
  size_t kept = 0;
  for (const LoopClosure& l : slam.loopClosures()) kept += l.kept;
  EXPECT_GT(kept, 5u) << "the second lap closes loops with the first";
  EXPECT_EQ(slam.stats().scans, d.truth.size());
}

TEST(GraphSlam, WithoutLoopClosuresTheSameDriveDrifts) {
  const wheelchair_slam_test::Drive d = wheelchair_slam_test::syntheticDrive();
  SlamConfig config;
  config.loops.enabled = false;
  GraphSlam slam{config};
  for (size_t i = 0; i < d.scans.size(); ++i) slam.addScan(d.scans[i], d.odometry[i]);
  slam.finish();
  EXPECT_TRUE(slam.loopClosures().empty());
  // Scan matching alone is far better than odometry, but the loops are what bound the error.
  EXPECT_LT(wheelchair_slam_test::maxError(slam.trajectory(), d.truth),
            wheelchair_slam_test::maxError(d.odometry, d.truth));
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
