// The pose graph on hand-made graphs whose optimum is known.
#include <gtest/gtest.h>
#include <wheelchair_slam/pose_graph.h>

#include <cmath>

namespace wheelchair_slam {
namespace {

using wheelchair_core::Pose2D;

/// A square of side 4 m in 16 steps of 1 m (turning 90 deg at each corner).
std::vector<Pose2D> square() {
  std::vector<Pose2D> p;
  Pose2D at{0, 0, 0};
  for (int i = 0; i < 16; ++i) {
    p.push_back(at);
    const bool corner = i % 4 == 3;
    at = wheelchair_core::compose(at, {1.0, 0.0, corner ? M_PI / 2 : 0.0});
  }
  return p;
}

GraphEdge edge(size_t from, size_t to, const Pose2D& z, double sigma_xy, double sigma_yaw,
               EdgeKind kind) {
  GraphEdge e;
  e.from = from;
  e.to = to;
  e.measurement = z;
  e.information = Eigen::Vector3d(1 / (sigma_xy * sigma_xy), 1 / (sigma_xy * sigma_xy),
                                  1 / (sigma_yaw * sigma_yaw))
                      .asDiagonal();
  e.kind = kind;
  return e;
}

/// Odometry edges (exact measurements) and a drifted initial guess, plus the true loop edge.
PoseGraph drifted(const std::vector<Pose2D>& truth) {
  PoseGraph g;
  Pose2D guess = truth[0];
  g.addNode(guess);
  for (size_t i = 1; i < truth.size(); ++i) {
    const Pose2D z = wheelchair_core::between(truth[i - 1], truth[i]);
    guess = wheelchair_core::compose(guess, {z.x * 1.05, z.y, z.yaw + 0.04});
    g.addNode(guess);
    g.addEdge(edge(i - 1, i, z, 0.05, 0.02, EdgeKind::kOdometry));
  }
  const size_t last = truth.size() - 1;
  g.addEdge(edge(last, 0, wheelchair_core::between(truth[last], truth[0]), 0.02, 0.01,
                 EdgeKind::kLoopClosure));
  return g;
}

double maxError(const PoseGraph& g, const std::vector<Pose2D>& truth) {
  double worst = 0.0;
  for (size_t i = 0; i < truth.size(); ++i) {
    worst = std::max(worst, std::hypot(g.poses()[i].x - truth[i].x, g.poses()[i].y - truth[i].y));
  }
  return worst;
}

TEST(PoseGraph, ResidualIsZeroForPosesThatAgreeWithTheEdge) {
  const Pose2D a{1, 2, 0.3}, b{2, 1, -0.4};
  GraphEdge e = edge(0, 1, wheelchair_core::between(a, b), 1, 1, EdgeKind::kScanMatch);
  EXPECT_NEAR(edgeResidual(e, a, b).norm(), 0.0, 1e-12);
}

TEST(PoseGraph, OptimizationRecoversADriftedSquareFromItsLoopClosure) {
  const auto truth = square();
  PoseGraph g = drifted(truth);
  EXPECT_GT(maxError(g, truth), 1.0);
  const OptimizeResult r = g.optimize(100);
  EXPECT_LT(r.final_chi2, 1e-6);
  EXPECT_LT(maxError(g, truth), 1e-3);
}

TEST(PoseGraph, AFalseLoopClosureIsRemovedAndTheTrueOneKept) {
  const auto truth = square();
  PoseGraph g = drifted(truth);
  const size_t true_loop = g.edges().size() - 1;
  // A confident closure claiming node 10 sits 1.5 m from where node 2 is: a wrong place match.
  const size_t false_loop =
      g.addEdge(edge(2, 10, {1.5, 0.0, 0.0}, 0.02, 0.01, EdgeKind::kLoopClosure));
  const RobustOptimizeResult r = optimizeRejectingFalseLoops(g, 100, 16.27);
  ASSERT_EQ(r.removed.size(), 1u);
  EXPECT_EQ(r.removed[0], false_loop);
  EXPECT_TRUE(g.edges()[true_loop].active);
  EXPECT_FALSE(g.edges()[false_loop].active);
  EXPECT_LT(maxError(g, truth), 1e-3);
}

TEST(PoseGraph, RotatedCovarianceKeepsItsShapeInTheNewFrame) {
  Eigen::Matrix3d c = Eigen::Vector3d(4.0, 1.0, 0.1).asDiagonal();
  const Eigen::Matrix3d r = rotateCovariance(c, M_PI / 2);
  EXPECT_NEAR(r(0, 0), 1.0, 1e-12);
  EXPECT_NEAR(r(1, 1), 4.0, 1e-12);
  EXPECT_NEAR(r(2, 2), 0.1, 1e-12);
}

}  // namespace
}  // namespace wheelchair_slam
