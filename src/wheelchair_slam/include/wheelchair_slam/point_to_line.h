// Point-to-line ICP (Censi 2008, with a Cauchy weight): Gauss-Newton on the distances of the
// scan's points to the lines through their nearest reference points. The result's covariance
// is sigma^2 (J^T W J)^-1, sigma^2 the weighted residual variance (at least point_sigma^2).
#pragma once

#include <wheelchair_slam/icp_matcher.h>

namespace wheelchair_slam {

struct PointToLineOptions {
  double max_distance = 0.2;  ///< pairing distance [m]
  double kernel = 0.05;       ///< Cauchy kernel width [m]
  int iterations = 15;
  double point_sigma = 0.03;  ///< floor of the residual standard deviation [m]
  size_t min_pairs = 20;
};

/// A Gaussian prior on the pose (the odometry's prediction): it holds the directions the scan
/// does not constrain (along a corridor) instead of letting them drift.
struct PosePrior {
  wheelchair_core::Pose2D mean;
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
};

/// Refines `guess`; `result.accepted` is false (and the pose is the guess) when fewer than
/// min_pairs points pair or the normal equations are singular. The returned covariance is the
/// scan's alone (without the prior), so a graph that also holds the odometry does not count it
/// twice.
MatchResult refinePointToLine(const ReferenceCloud& reference, const Points& scan,
                              const wheelchair_core::Pose2D& guess,
                              const PointToLineOptions& options, const PosePrior* prior = nullptr);

}  // namespace wheelchair_slam
