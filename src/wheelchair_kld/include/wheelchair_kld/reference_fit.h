// How well a reference pose (a corrected log's, itself a SLAM estimate) agrees with the map the
// localizer is given: where its echoes fall, and where the untempered likelihood field of the
// scan peaks near it. The spread of those peaks around the reference is the accuracy floor no
// filter can beat against that reference on that map; their mean is a bias of the setup (a
// laser offset, an angle convention).
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_kld/localization_map.h>
#include <wheelchair_kld/measurement_model.h>

#include <vector>

namespace wheelchair_kld {

struct ReferenceFit {
  MeasurementModel::FitCounts fit;  ///< at the reference pose (every beam)
  /// Distances of the echoes' endpoints to the nearest obstacle surface at the reference [m]
  /// (capped at the map's max_distance; endpoints off the map left out).
  std::vector<double> endpoint_distances;
  /// The likelihood field's peak within `search_xy` / `search_theta` of the reference, in the
  /// reference laser's frame (x forward) [m, m, rad].
  wheelchair_core::Pose2D peak_offset;
};

/// The fit of `scan` (taken by a laser at `sensor_pose` on the robot) at the robot pose `base`,
/// with every beam and the likelihood field of `params` (untempered: the peak does not depend
/// on the exponent), searched on a grid of 2 cm / 0.5 deg refined twice by 4 (to 1.25 mm / 0.03
/// deg).
ReferenceFit referenceFit(const LocalizationMap& map, const MeasurementParams& params,
                          const wheelchair_core::LaserScan2D& scan,
                          const wheelchair_core::Pose2D& sensor_pose,
                          const wheelchair_core::Pose2D& base, double inlier_tolerance,
                          double search_xy = 0.2, double search_theta = 0.06);

/// What a trajectory of reference fits says.
struct ReferenceFitSummary {
  size_t scans = 0;
  double inlier_share_mean = 0;  ///< inliers / echoes at the references
  double known_fit_mean = 0;     ///< inliers / (inliers + contradictions)
  /// Endpoint distances to the nearest obstacle over all scans: median, 90th and 95th
  /// percentile [m] (the spread a likelihood field's sigma_hit stands for).
  double distance_p50 = 0, distance_p90 = 0, distance_p95 = 0;
  /// Peak offsets: RMS of the position offset [m] and of the heading offset [rad]; their means
  /// (a bias) along the laser's x (forward) and y (left) [m] and in heading [rad].
  double peak_xy_rms = 0, peak_theta_rms = 0;
  double peak_x_mean = 0, peak_y_mean = 0, peak_theta_mean = 0;
};
ReferenceFitSummary summarizeReferenceFits(const std::vector<ReferenceFit>& fits);

}  // namespace wheelchair_kld
