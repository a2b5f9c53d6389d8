// Laser measurement models on the LocalizationMap: the likelihood field (default) and the beam
// model (Thrun, Burgard, Fox ch. 6), over a subsampled set of beams.
#pragma once

#include <mrpt/math/TPose2D.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_kld/kld_params.h>
#include <wheelchair_kld/localization_map.h>

#include <vector>

namespace wheelchair_kld {

class MeasurementModel {
 public:
  MeasurementModel(const LocalizationMap& map, const MeasurementParams& params);

  /// Selects every beam_step-th beam of a validated scan taken by a laser at `sensor_pose` in
  /// base_link and precomputes it there. Returns (REP-117) the returns, as echoes up to
  /// min(max_range, range_max) and beyond it as carrying no information, and the no-return
  /// beams; readings to be discarded are left out. Returns the number of beams used.
  int setScan(const wheelchair_core::LaserScan2D& scan, const wheelchair_core::Pose2D& sensor_pose);
  int beamCount() const { return static_cast<int>(beams_.size()); }

  /// Tempered log p(z | pose, map) of the current scan for a robot (base_link) pose.
  double logLikelihood(const mrpt::math::TPose2D& pose) const;

  /// Share of the echoes whose endpoint lies within `tolerance` of an obstacle for this pose
  /// (how well the scan fits the map there).
  double inlierFraction(const mrpt::math::TPose2D& pose, double tolerance) const;

  /// Where the echoes' endpoints fall for this pose: within `tolerance` of an obstacle (inliers),
  /// in known-free space farther than that (contradictions: the map says nothing is there), or
  /// in unknown space / off the map (no evidence either way).
  struct FitCounts {
    int echoes = 0, inliers = 0, contradictions = 0;
    /// Of the contradictions, the short returns: the echo ends in mapped free space before the
    /// map's first obstacle along its beam (by more than the tolerance). Something the map lacks
    /// stands there (a box, a person: amcl's z_short); a wrong pose gives long returns too.
    int shorts = 0;
    /// inliers / (inliers + contradictions): how well the scan fits where the map knows (1
    /// without such echoes).
    double knownFit() const {
      return inliers + contradictions > 0 ? double(inliers) / (inliers + contradictions) : 1.0;
    }
  };
  FitCounts fitCounts(const mrpt::math::TPose2D& pose, double tolerance) const;
  /// Distance of each echo's endpoint to the nearest obstacle surface for this pose [m] (capped
  /// at the map's max_distance; endpoints off the map left out).
  std::vector<double> endpointDistances(const mrpt::math::TPose2D& pose) const;

 private:
  struct Beam {
    double end_x, end_y;  ///< endpoint in base_link (likelihood field)
    double angle;         ///< beam direction in base_link (beam model)
    double range;
    bool max_range;  ///< no echo within the model's range
  };
  double logLikelihoodField(const mrpt::math::TPose2D& pose) const;
  double logBeamModel(const mrpt::math::TPose2D& pose) const;

  const LocalizationMap& map_;
  MeasurementParams params_;
  std::vector<float> field_log_;  ///< per-cell log(z_hit N(d; 0, sigma) + z_rand / max_range)
  double outside_log_;
  mrpt::math::TPose2D sensor_pose_;
  std::vector<Beam> beams_;
};

}  // namespace wheelchair_kld
