// KLD-sampling Monte Carlo localization (Fox 2003; paper section 2.2, Algorithm 1, with the
// listing's defects fixed), with augmented-MCL recovery and a fixed-size MCL mode.
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/localization_status.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_kld/kld_params.h>
#include <wheelchair_kld/localization_map.h>
#include <wheelchair_kld/measurement_model.h>
#include <wheelchair_kld/pose_estimate.h>

#include <Eigen/Core>

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wheelchair_kld {

enum class UpdateResult { kUpdated, kNoMotion, kRejected, kNotInitialized };

/// Share of the echoes that end within the tolerance of a mapped obstacle, the short returns
/// (up to `max_short_share` of the echoes) left out: echoes of something the map lacks are no
/// sign of a wrong pose.
double inlierShare(const MeasurementModel::FitCounts& fit, double max_short_share);

class KldLocalizer {
 public:
  /// `seed` drives every random draw: equal seeds and inputs give equal results.
  KldLocalizer(std::shared_ptr<const LocalizationMap> map, const KldParams& params, uint64_t seed);

  /// Global localization: `particles` (0: global_particles) poses uniform over the known-free
  /// space.
  void initGlobal(int particles = 0);
  /// Particles drawn from N(mean, cov) (x, y, yaw of base_link in the map frame).
  void initGaussian(const wheelchair_core::Pose2D& mean, const Eigen::Matrix3d& cov);
  bool initialized() const { return !particles_.empty(); }

  /// One filter step for a scan taken when base_link was at `odom` in the odom frame, by a
  /// laser at `sensor_pose` in base_link. Runs only after update_min_d / update_min_a of travel
  /// since the last step (or right after an initialization, or when `force`). A rejected scan
  /// leaves the filter untouched and its reason in lastRejection().
  UpdateResult update(const wheelchair_core::Pose2D& odom, const wheelchair_core::LaserScan2D& scan,
                      const wheelchair_core::Pose2D& sensor_pose, bool force = false);

  size_t particleCount() const { return particles_.size(); }
  /// Every particle's pose (base_link in the map frame).
  std::vector<wheelchair_core::Pose2D> particlePoses() const;
  const PoseEstimate& estimate() const { return estimate_; }
  /// Whether the estimate can be trusted: the state, the numbers behind it and, when not
  /// localized, the reason with its numbers.
  wheelchair_core::LocalizationStatus status() const;
  const std::string& lastRejection() const { return last_rejection_; }
  /// Number of beams the scan must have (0: any); set from the first scan otherwise.
  void setExpectedBeams(int n) { expected_beams_ = n; }
  double wSlow() const { return w_slow_; }
  double wFast() const { return w_fast_; }
  /// Share of the last scan's echoes that fit the map at the estimate.
  double inlierFraction() const { return inliers_; }
  /// Where the last scan's echoes fell at the estimate (inliers, contradictions, unknown).
  const MeasurementModel::FitCounts& lastFit() const { return fit_; }
  /// Mean inlier share over the last fit_window updates (1 before the first update).
  double meanFit() const;
  /// Global re-localizations triggered by a persistent misfit so far.
  int relocalizations() const { return relocalizations_; }
  /// Particles weighed by the scan in the last update (sampling loop, a re-localization's
  /// uniform poses, refinement passes): the work update_max_particles bounds.
  int lastUpdateWeighings() const { return weighings_; }
  /// Whether update_max_particles bounds the updates now (not in a requested global
  /// localization that has not localized yet, not fixed-size MCL).
  bool updatesBounded() const;
  const KldParams& params() const { return params_; }
  const LocalizationMap& map() const { return *map_; }

 private:
  /// The sampling loop of Algorithm 1: draws, predicts, weighs until M >= max(M_x, M_min)
  /// (bounded by M_max), or exactly fixed_particles in fixed-size mode.
  /// `m_max`: the most particles the loop draws; `fresh`: uniform poses added after the loop
  /// and weighed too (a re-localization spread over updates).
  void sampleStep(const mrpt::math::TPose2D& odom_from, const mrpt::math::TPose2D& odom_to,
                  int m_max, int fresh);
  /// Starts a global re-localization: relocalize_particles uniform poses, all at once or, when
  /// the updates are bounded, spread over the following updates.
  void startRelocalization();
  /// `n` poses uniform over the known-free space, equally weighted.
  void spreadUniform(int n);
  /// Re-applies the current scan with kernel-jittered redraws: `steps` passes from pass `first`
  /// of refine_steps (the kernel halves at every pass), after initGlobal.
  void refineAtFirstScan(const MeasurementModel& model, int first, int steps);
  /// Index of the particle whose cumulative weight interval holds `r` in [0, total).
  size_t drawAncestor(const std::vector<double>& cumulative, double r) const;
  /// Raises the weights to the power that keeps min_effective_fraction of them effective.
  void temperWeights();
  /// Normalizes weights (Algorithm 1, lines 20-23) and updates the cluster estimate.
  void normalizeAndEstimate();
  void resetRecovery();
  /// Floors the share of clusters that fit the scan as well as a correct pose does.
  void keepPlausibleHypotheses();
  /// Records the fit of this update; starts a global re-localization on a persistent misfit.
  void checkFit();

  std::shared_ptr<const LocalizationMap> map_;
  KldParams params_;
  mrpt::random::CRandomGenerator rng_;
  MeasurementModel measurement_;
  MeasurementModel fit_model_;  ///< every fit_beam_step-th beam: the inlier share at the estimate
  std::vector<Particle> particles_;
  PoseEstimate estimate_;
  std::optional<mrpt::math::TPose2D> last_odom_;
  bool pending_first_update_ = false;
  int refine_left_ = 0;  ///< refinement passes still due after initGlobal
  int refine_done_ = 0;  ///< ... and done so far
  int expected_beams_ = 0;
  double w_slow_ = 0, w_fast_ = 0;
  double inliers_ = 0;  ///< inlier fraction of the last scan at the estimate
  std::string last_rejection_;
  std::deque<double> fit_window_;  ///< inlier shares of the last fit_window updates
  int relocalizations_ = 0;
  MeasurementModel::FitCounts fit_;
  int poor_fits_ = 0;
  bool recovering_ = false;     ///< since a re-localization, until localized again
  bool global_search_ = false;  ///< since a requested initGlobal, until first localized
  int spread_left_ = 0;         ///< a re-localization's uniform poses not drawn yet
  int weighings_ = 0;           ///< particles weighed in the last update
};

}  // namespace wheelchair_kld
