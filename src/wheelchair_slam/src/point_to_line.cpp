#include <wheelchair_slam/point_to_line.h>
#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>

namespace wheelchair_slam {

using wheelchair_core::Pose2D;

MatchResult refinePointToLine(const ReferenceCloud& reference, const Points& scan,
                              const Pose2D& guess, const PointToLineOptions& options,
                              const PosePrior* prior) {
  MatchResult out;
  out.pose = guess;
  if (reference.empty()) return out;
  Pose2D pose = guess;
  const double gate2 = options.max_distance * options.max_distance;
  const double k2 = options.kernel * options.kernel;
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  double weighted_sq = 0.0, weights = 0.0;
  size_t pairs = 0;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    h.setZero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    weighted_sq = weights = 0.0;
    pairs = 0;
    const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
    for (const Eigen::Vector2d& p : scan) {
      const Eigen::Vector2d w(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y());
      double d2 = 0.0;
      const size_t i = reference.nearest(w, d2);
      if (i >= reference.size() || d2 > gate2) continue;
      const Eigen::Vector2d& n = reference.normal(i);
      if (n.squaredNorm() < 0.5) continue;
      const double r = n.dot(w - reference.point(i));
      const Eigen::Vector3d j(n.x(), n.y(),
                              n.x() * (-s * p.x() - c * p.y()) + n.y() * (c * p.x() - s * p.y()));
      const double weight = 1.0 / (1.0 + r * r / k2);
      h += weight * j * j.transpose();
      g += weight * r * j;
      weighted_sq += weight * r * r;
      weights += weight;
      ++pairs;
    }
    if (pairs < options.min_pairs) return out;
    // The scan's terms in information units (1 / point_sigma^2), comparable with the prior's.
    const double scale = 1.0 / (options.point_sigma * options.point_sigma);
    Eigen::Matrix3d system = scale * h;
    g *= scale;
    if (prior) {
      const Eigen::Vector3d d(pose.x - prior->mean.x, pose.y - prior->mean.y,
                              wheelchair_core::angleDifference(pose.yaw, prior->mean.yaw));
      system += prior->information;
      g += prior->information * d;
    }
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(system);
    if (ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() <= 1e-9) return out;
    const Eigen::Vector3d step = -ldlt.solve(g);
    pose = {pose.x + step.x(), pose.y + step.y(),
            wheelchair_core::normalizeAngle(pose.yaw + step.z())};
    if (step.head<2>().norm() < 1e-5 && std::abs(step.z()) < 1e-5) break;
  }
  const double dof = std::max<double>(1.0, weights - 3.0);
  const double sigma2 = std::max(options.point_sigma * options.point_sigma, weighted_sq / dof);
  out.pose = pose;
  // A direction the scan leaves free gets a large but finite variance.
  out.covariance = sigma2 * (h + 1e-6 * Eigen::Matrix3d::Identity()).inverse();
  out.inliers = static_cast<double>(pairs) / std::max<size_t>(1, scan.size());
  out.accepted = out.covariance.allFinite() && pose.isFinite();
  return out;
}

}  // namespace wheelchair_slam
