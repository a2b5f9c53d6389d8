// The filter's answer: weighted mean and covariance of the dominant particle cluster (instead of
// the listing's single heaviest particle), and the clusters behind it.
#pragma once

#include <mrpt/bayes/CProbabilityParticle.h>
#include <mrpt/math/TPose2D.h>
#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <vector>

namespace wheelchair_kld {

/// A pose hypothesis inside the filter (MRPT's particle type); log_w holds the log of its
/// normalized weight.
using Particle = mrpt::bayes::CProbabilityParticle<mrpt::math::TPose2D,
                                                   mrpt::bayes::particle_storage_mode::VALUE>;

struct PoseEstimate {
  wheelchair_core::Pose2D mean;                   ///< base_link in the map frame
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();  ///< (x, y, yaw) of the dominant cluster
  double cluster_weight = 0;  ///< share of the total weight in the dominant cluster
  int cluster_count = 0;      ///< clusters holding >= 1 % of the weight
  /// Cluster of every particle (index into cluster_weights).
  std::vector<int> particle_cluster;
  std::vector<double> cluster_weights;  ///< share of the total weight of every cluster
  int best_cluster = -1;
};

/// Weighted mean (circular for the heading) of the particles of cluster `c`.
wheelchair_core::Pose2D clusterMean(const std::vector<Particle>& particles, const PoseEstimate& est,
                                    int c);

/// Groups particles into connected cells of size (cell_xy, cell_xy, cell_theta) (heading wraps)
/// and returns the weighted mean / covariance of the heaviest group.
PoseEstimate estimateDominantCluster(const std::vector<Particle>& particles, double cell_xy,
                                     double cell_theta);

}  // namespace wheelchair_kld
