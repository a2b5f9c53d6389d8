// Scan-to-map matching: MRPT's ICP (mrpt::slam::CICP, classic point-to-point on point maps)
// brings the scan into place, then a point-to-line refinement (point_to_line.h) makes it
// precise and gives the match's covariance from its normal equations: large along a corridor,
// small across it.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_slam/scan_points.h>
#include <wheelchair_slam/slam_config.h>
#include <Eigen/Core>

#include <memory>
#include <optional>

namespace wheelchair_slam {

struct MatchResult {
  bool accepted = false;         ///< goodness >= the configured minimum
  wheelchair_core::Pose2D pose;  ///< the scan's pose in the reference frame
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< of pose (x, y, yaw)
  double goodness = 0.0;  ///< fraction of scan points paired by MRPT's ICP, 0..1
  double inliers = 0.0;   ///< fraction of scan points on a reference line, 0..1
  int iterations = 0;
};

/// A reference point set prepared for matching (MRPT builds its k-d tree once).
class ReferenceCloud {
 public:
  ReferenceCloud();
  ~ReferenceCloud();
  ReferenceCloud(ReferenceCloud&&) noexcept;
  ReferenceCloud& operator=(ReferenceCloud&&) noexcept;
  /// `points` averaged per cell of `voxel` metres (0: kept as they are), so that many scans of
  /// one wall make one even line of points, not a blob that fits no normal.
  explicit ReferenceCloud(const Points& points, double voxel = 0.0);
  size_t size() const;
  bool empty() const { return size() == 0; }
  const Eigen::Vector2d& point(size_t i) const;
  /// Unit normal of the surface at point i (from its neighbours), zero if they fit no line.
  const Eigen::Vector2d& normal(size_t i) const;
  /// Index of the point nearest to `p` and the squared distance to it (size() if empty).
  size_t nearest(const Eigen::Vector2d& p, double& distance2) const;

 private:
  friend class IcpMatcher;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class IcpMatcher {
 public:
  explicit IcpMatcher(const MatcherConfig& config);
  ~IcpMatcher();
  /// Aligns `scan` (points in the sensor frame) to `reference` starting from `guess`. With
  /// `prior_information`, the refinement holds the pose to `guess` with that information (in
  /// the reference frame) where the scan does not constrain it.
  MatchResult match(const ReferenceCloud& reference, const Points& scan,
                    const wheelchair_core::Pose2D& guess, double min_goodness,
                    const Eigen::Matrix3d* prior_information = nullptr) const;
  MatchResult match(const ReferenceCloud& reference, const Points& scan,
                    const wheelchair_core::Pose2D& guess,
                    const Eigen::Matrix3d* prior_information = nullptr) const {
    return match(reference, scan, guess, config_.min_goodness, prior_information);
  }

 private:
  MatcherConfig config_;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wheelchair_slam
