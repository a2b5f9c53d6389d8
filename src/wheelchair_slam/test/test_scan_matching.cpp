// Scan-to-map matching on scans ray-cast in a synthetic office at exact poses.
#include <gtest/gtest.h>
#include <wheelchair_slam/correlative_search.h>
#include <wheelchair_slam/icp_matcher.h>
#include <wheelchair_slam/point_to_line.h>

#include "synthetic_world.h"

namespace wheelchair_slam {
namespace {

using wheelchair_core::Pose2D;
using wheelchair_slam_test::castScan;
using wheelchair_slam_test::officeWorld;

struct Views {
  Points reference;  ///< in the world frame
  Points scan;       ///< in the sensor frame
};

Views twoViews(const Pose2D& reference_pose, const Pose2D& scan_pose, double noise = 0.01) {
  std::mt19937 rng(7);
  const auto world = officeWorld();
  Views v;
  appendTransformed(scanPoints(castScan(world, reference_pose, 0.0, noise, rng), 25.0, 0.05),
                    reference_pose, v.reference);
  v.scan = scanPoints(castScan(world, scan_pose, 1.0, noise, rng), 25.0, 0.05);
  return v;
}

TEST(IcpMatcher, RecoversAKnownOffsetToACentimetre) {
  const Pose2D truth{-6.0, -3.7, 0.12};
  const Views v = twoViews({-6.4, -3.9, 0.0}, truth);
  const IcpMatcher matcher{MatcherConfig()};
  const MatchResult m = matcher.match(ReferenceCloud(v.reference), v.scan, {-6.25, -3.8, 0.05});
  ASSERT_TRUE(m.accepted);
  EXPECT_NEAR(m.pose.x, truth.x, 0.01);
  EXPECT_NEAR(m.pose.y, truth.y, 0.01);
  EXPECT_NEAR(m.pose.yaw, truth.yaw, 0.003);
  EXPECT_GT(m.inliers, 0.6);  // the rest of the scan sees what the reference did not
}

TEST(IcpMatcher, RefusesAScanOfAPlaceTheReferenceNeverSaw) {
  // The scan is of a small 3 x 2 m room with a diagonal wall, which is nowhere in the office.
  const std::vector<wheelchair_slam_test::Segment> room = {
      {{0, 0}, {3, 0}}, {{3, 0}, {3, 2}}, {{3, 2}, {0, 2}}, {{0, 2}, {0, 0}}, {{1, 0}, {3, 1.5}}};
  std::mt19937 rng(5);
  const Views office = twoViews({-6.0, -4.0, 0.0}, {-6.0, -4.0, 0.0});
  const Points scan = scanPoints(castScan(room, {0.5, 1.0, 0.0}, 0, 0.01, rng), 25.0, 0.05);
  const IcpMatcher matcher{MatcherConfig()};
  const MatchResult m = matcher.match(ReferenceCloud(office.reference), scan, {-6.0, -4.0, 0.0});
  EXPECT_FALSE(m.accepted) << "goodness " << m.goodness;
}

TEST(PointToLine, CovarianceIsLargeAlongACorridorAndSmallAcrossIt) {
  // Two parallel walls only: x (along them) is not observed, y is.
  std::vector<wheelchair_slam_test::Segment> corridor = {{{-50, 1}, {50, 1}},
                                                         {{-50, -1}, {50, -1}}};
  std::mt19937 rng(3);
  Points reference;
  appendTransformed(scanPoints(castScan(corridor, {0, 0, 0}, 0, 0.005, rng), 25.0, 0.05), Pose2D{},
                    reference);
  const Points scan = scanPoints(castScan(corridor, {0.3, 0.1, 0.02}, 1, 0.005, rng), 25.0, 0.05);
  const MatchResult m =
      refinePointToLine(ReferenceCloud(reference), scan, {0.3, 0.05, 0.0}, PointToLineOptions());
  ASSERT_TRUE(m.accepted);
  EXPECT_NEAR(m.pose.y, 0.1, 0.01);
  EXPECT_NEAR(m.pose.yaw, 0.02, 0.003);
  EXPECT_GT(m.covariance(0, 0), 100.0 * m.covariance(1, 1));
}

TEST(CorrelativeSearch, FindsAnOffsetTooFarForIcp) {
  const Pose2D truth{-6.0, -3.7, 0.12};
  const Views v = twoViews({-6.0, -4.0, 0.0}, truth);
  const Pose2D guess{-6.6, -3.3, -0.05};  // 0.72 m and 0.17 rad away
  const LikelihoodGrid grid(v.reference, 0.05, 0.05);
  SearchWindow window;
  window.xy = 1.0;
  window.yaw = 0.25;
  window.step_yaw = 0.01;
  const SearchResult found = correlativeSearch(grid, v.scan, guess, window);
  EXPECT_GT(found.score, 0.6);
  EXPECT_NEAR(found.pose.x, truth.x, 0.05);
  EXPECT_NEAR(found.pose.y, truth.y, 0.05);
  EXPECT_NEAR(found.pose.yaw, truth.yaw, 0.015);
  EXPECT_LT(grid.score(v.scan, guess), 0.3);
}

}  // namespace
}  // namespace wheelchair_slam
