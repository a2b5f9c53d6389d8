#include <mrpt/math/wrap2pi.h>
#include <wheelchair_kld/kld_bound.h>
#include <wheelchair_kld/kld_localizer.h>
#include <wheelchair_kld/likelihood_peak.h>
#include <wheelchair_kld/odometry_motion_model.h>
#include <wheelchair_kld/pose_bins.h>
#include <wheelchair_kld/scan_validation.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace wheelchair_kld {

using mrpt::math::TPose2D;

namespace {
constexpr double kGoldenRatioFraction = 0.6180339887498949;  // (sqrt(5) - 1) / 2

TPose2D toMrpt(const wheelchair_core::Pose2D& p) { return TPose2D(p.x, p.y, p.yaw); }
}  // namespace

KldLocalizer::KldLocalizer(std::shared_ptr<const LocalizationMap> map, const KldParams& params,
                           uint64_t seed)
    : map_(std::move(map)),
      params_(params),
      measurement_(*map_, params_.measurement),
      fit_model_(*map_, [&] {
        MeasurementParams m = params.measurement;
        m.beam_step = params.fit_beam_step;
        m.type = MeasurementModelType::kLikelihoodField;  // the peak search's likelihood
        return m;
      }()) {
  rng_.randomize(static_cast<uint32_t>(seed));
}

void KldLocalizer::resetRecovery() {
  w_slow_ = w_fast_ = 0;
  last_odom_.reset();  // a new set is the pose now: earlier odometry must not move it
  pending_first_update_ = true;
  fit_window_.clear();
  poor_fits_ = 0;
  recovering_ = false;
}

double inlierShare(const MeasurementModel::FitCounts& fit, double max_short_share) {
  const int excused = std::min(fit.shorts, static_cast<int>(max_short_share * fit.echoes));
  const int counted = fit.echoes - excused;
  return counted > 0 ? static_cast<double>(fit.inliers) / counted : 0.0;
}

double KldLocalizer::meanFit() const {
  if (fit_window_.empty()) return 1.0;
  double sum = 0;
  for (double f : fit_window_) sum += f;
  return sum / fit_window_.size();
}

void KldLocalizer::checkFit() {
  fit_window_.push_back(inliers_);
  const size_t window = static_cast<size_t>(std::max(1, params_.fit_window));
  while (fit_window_.size() > window) fit_window_.pop_front();
  const bool poor = fit_.inliers + fit_.contradictions >= params_.relocalize_min_echoes &&
                    fit_.knownFit() < params_.relocalize_max_fit;
  poor_fits_ = poor ? poor_fits_ + 1 : 0;
  const bool lost =
      params_.relocalize_on_mean_fit
          ? fit_window_.size() == window && meanFit() < params_.fit_min_mean
          : params_.relocalize_updates > 0 && poor_fits_ >= params_.relocalize_updates;
  if (lost) startRelocalization();
}

bool KldLocalizer::updatesBounded() const {
  return params_.update_max_particles > 0 && params_.fixed_particles == 0 && !global_search_;
}

void KldLocalizer::spreadUniform(int n) {
  particles_.assign(n, Particle());
  for (auto& p : particles_) {
    p.d = map_->sampleFreePose(rng_);
    p.log_w = -std::log(static_cast<double>(n));
  }
  resetRecovery();
  refine_left_ = params_.refine_steps;
  refine_done_ = 0;
  normalizeAndEstimate();
}

void KldLocalizer::initGlobal(int particles) {
  const int n = params_.fixed_particles > 0 ? params_.fixed_particles
                : particles > 0             ? particles
                                            : params_.global_particles;
  spreadUniform(n);
  spread_left_ = 0;
  global_search_ = true;
}

void KldLocalizer::startRelocalization() {
  ++relocalizations_;
  const int total =
      params_.fixed_particles > 0 ? params_.fixed_particles : params_.relocalize_particles;
  // Bounded: the first share now (weighed at the next update with as many fresh ones beside it),
  // the rest at the following updates.
  const int first =
      updatesBounded() ? std::min(total, std::max(1, params_.update_max_particles / 4)) : total;
  spreadUniform(first);
  spread_left_ = total - first;
  recovering_ = true;
}

void KldLocalizer::initGaussian(const wheelchair_core::Pose2D& mean, const Eigen::Matrix3d& cov) {
  const int n = params_.fixed_particles > 0 ? params_.fixed_particles : params_.init_particles;
  Eigen::LLT<Eigen::Matrix3d> llt(cov + 1e-12 * Eigen::Matrix3d::Identity());
  const Eigen::Matrix3d l = llt.matrixL();
  particles_.assign(n, Particle());
  for (auto& p : particles_) {
    const Eigen::Vector3d z(rng_.drawGaussian1D(0, 1), rng_.drawGaussian1D(0, 1),
                            rng_.drawGaussian1D(0, 1));
    const Eigen::Vector3d e = l * z;
    p.d = TPose2D(mean.x + e(0), mean.y + e(1), mrpt::math::wrapToPi(mean.yaw + e(2)));
    p.log_w = -std::log(static_cast<double>(n));
  }
  resetRecovery();
  refine_left_ = 0;
  spread_left_ = 0;
  global_search_ = false;
  normalizeAndEstimate();
}

std::vector<wheelchair_core::Pose2D> KldLocalizer::particlePoses() const {
  std::vector<wheelchair_core::Pose2D> poses;
  poses.reserve(particles_.size());
  for (const auto& p : particles_) poses.push_back({p.d.x, p.d.y, p.d.phi});
  return poses;
}

UpdateResult KldLocalizer::update(const wheelchair_core::Pose2D& odom_pose,
                                  const wheelchair_core::LaserScan2D& scan,
                                  const wheelchair_core::Pose2D& sensor_pose, bool force) {
  if (expected_beams_ == 0) expected_beams_ = static_cast<int>(scan.ranges.size());
  last_rejection_ = validateScan(scan, expected_beams_, params_.min_echo_fraction);
  if (last_rejection_.empty() && !sensor_pose.isFinite())
    last_rejection_ = "laser pose in the base frame is not finite";
  if (last_rejection_.empty() && !odom_pose.isFinite())
    last_rejection_ = "odometry pose is not finite";
  if (!last_rejection_.empty()) return UpdateResult::kRejected;
  if (!initialized()) return UpdateResult::kNotInitialized;
  const TPose2D odom = toMrpt(odom_pose);
  const TPose2D from = last_odom_.value_or(odom);
  const double moved = std::hypot(odom.x - from.x, odom.y - from.y);
  const double turned = std::abs(mrpt::math::wrapToPi(odom.phi - from.phi));
  if (!force && !pending_first_update_ && moved < params_.update_min_d &&
      turned < params_.update_min_a)
    return UpdateResult::kNoMotion;
  measurement_.setScan(scan, sensor_pose);
  weighings_ = 0;
  // A re-localization's cloud is refined over several updates (relocalize_refine_per_update
  // passes each), so no update of a moving chair stalls the node; the first global
  // localization (the chair waits for it) gets every pass at once.
  const int refine_now = refine_left_ <= 0 ? 0
                         : recovering_
                             ? std::min(refine_left_, params_.relocalize_refine_per_update)
                             : refine_left_;
  // After a re-localization the set stays within relocalize_particles until localized again:
  // the spread set would otherwise ask for M_max and stall the node for seconds.
  int set_max = params_.fixed_particles > 0 ? params_.fixed_particles
                : recovering_
                    ? std::min(params_.max_particles,
                               std::max(params_.min_particles, params_.relocalize_particles))
                    : params_.max_particles;
  int fresh = spread_left_;
  if (updatesBounded()) {
    // update_max_particles weighings: the set and its refinement passes; of the set, half at
    // most for a re-localization's next uniform poses.
    set_max = std::min(set_max, params_.update_max_particles / (1 + refine_now));
    fresh = std::min(fresh, set_max / 2);
  }
  spread_left_ -= fresh;
  sampleStep(from, odom, set_max - fresh, fresh);
  if (refine_now > 0) {
    refineAtFirstScan(measurement_, refine_done_, refine_now);
    refine_left_ -= refine_now;
    refine_done_ += refine_now;
  }
  last_odom_ = odom;
  pending_first_update_ = false;
  normalizeAndEstimate();
  keepPlausibleHypotheses();
  fit_model_.setScan(scan, sensor_pose);
  if (params_.peak_estimate) {
    PeakSearch search;
    search.max_xy = params_.peak_max_xy;
    search.max_theta = params_.peak_max_theta;
    const TPose2D peak = likelihoodPeakNear(fit_model_, toMrpt(estimate_.mean), search);
    estimate_.mean = {peak.x, peak.y, peak.phi};
  }
  fit_ = fit_model_.fitCounts(toMrpt(estimate_.mean), params_.inlier_tolerance);
  inliers_ = inlierShare(fit_, params_.fit_max_short_share);
  const int relocalizations_before = relocalizations_;
  checkFit();
  if (relocalizations_ == relocalizations_before && status().localized()) {
    recovering_ = false;
    global_search_ = false;
  }
  return UpdateResult::kUpdated;
}

void KldLocalizer::sampleStep(const TPose2D& odom_from, const TPose2D& odom_to, int m_max,
                              int fresh) {
  const OdometryIncrement u = decomposeOdometry(odom_from, odom_to);
  // Cumulative weights of the previous set for drawing with probability w_{t-1} (line 6).
  std::vector<double> cumulative(particles_.size());
  double acc = 0;
  for (size_t i = 0; i < particles_.size(); ++i)
    cumulative[i] = acc += std::exp(particles_[i].log_w);
  // Augmented MCL: share of random poses from the short/long-term likelihood averages.
  const double inject = (w_slow_ > 0 && params_.alpha_slow > 0)
                            ? std::max(0.0, 1.0 - w_fast_ / (params_.recovery_ratio * w_slow_))
                            : 0.0;
  const bool fixed = params_.fixed_particles > 0;
  const int m_min = std::min(m_max, fixed ? params_.fixed_particles : params_.min_particles);
  const int beams = std::max(1, measurement_.beamCount());
  PoseBins bins(params_.bin_xy, params_.bin_theta);
  std::vector<Particle> next;
  next.reserve(std::min<size_t>(m_max, 4 * particles_.size() + m_min) + fresh);
  double m_x = 0, w_sum = 0, log_max = -1e300;
  double stratum = rng_.drawUniform(0.0, 1.0);
  int drawn = 0;
  // Algorithm 1 main loop, run until M >= max(M_x, M_min) (bounded by M_max).
  for (int m = 0; m < m_max && (m < m_min || m < m_x); ++m) {
    Particle p;
    const bool random = inject > 0 && rng_.drawUniform(0.0, 1.0) < inject;
    if (random) {
      p.d = map_->sampleFreePose(rng_);
    } else {
      // Ancestor by a golden-ratio (Weyl) sequence from a random start: every prefix of the
      // draws is stratified over the cumulative weights, so equally likely modes (a symmetric
      // world) keep their shares instead of drifting apart under multinomial noise, whatever
      // count M the KLD bound stops at.
      stratum = stratum + kGoldenRatioFraction;
      stratum -= std::floor(stratum);
      const size_t i = drawAncestor(cumulative, stratum * acc);
      p.d = sampleMotionModel(u, particles_[i].d, params_.motion, rng_);  // line 7
    }
    p.log_w = measurement_.logLikelihood(p.d);  // line 8
    if (!random) {
      w_sum += std::exp(p.log_w / (params_.measurement.likelihood_exponent * beams));
      ++drawn;
    }
    log_max = std::max(log_max, p.log_w);
    next.push_back(p);                                              // line 9
    if (!fixed && bins.insert(p.d))                                 // lines 10-12
      m_x = klBound(bins.count(), params_.epsilon, params_.delta);  // line 14
  }
  // A spread re-localization's next uniform poses, weighed beside the survivors of the earlier
  // ones (not in the augmented-MCL averages, as the injected poses).
  for (int k = 0; k < fresh; ++k) {
    Particle p;
    p.d = map_->sampleFreePose(rng_);
    p.log_w = measurement_.logLikelihood(p.d);
    log_max = std::max(log_max, p.log_w);
    next.push_back(p);
  }
  weighings_ += static_cast<int>(next.size());
  particles_.swap(next);
  for (auto& p : particles_) p.log_w -= log_max;  // rescale before normalizing
  temperWeights();
  // Short/long-term averages of the per-beam likelihood (geometric mean over beams).
  if (drawn > 0 && params_.alpha_slow > 0) {
    const double w_avg = w_sum / drawn;
    if (w_slow_ == 0) {
      w_slow_ = w_fast_ = w_avg;
    } else {
      w_slow_ += params_.alpha_slow * (w_avg - w_slow_);
      w_fast_ += params_.alpha_fast * (w_avg - w_fast_);
    }
  }
}

size_t KldLocalizer::drawAncestor(const std::vector<double>& cumulative, double r) const {
  return std::min<size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin(),
      cumulative.size() - 1);
}

void KldLocalizer::refineAtFirstScan(const MeasurementModel& model, int first, int steps) {
  double sxy = std::ldexp(params_.refine_xy, -first),
         sth = std::ldexp(params_.refine_theta, -first);
  for (int step = 0; step < steps; ++step, sxy *= 0.5, sth *= 0.5) {
    std::vector<double> cumulative(particles_.size());
    double acc = 0;
    for (size_t i = 0; i < particles_.size(); ++i)
      cumulative[i] = acc += std::exp(particles_[i].log_w);
    std::vector<Particle> next(particles_.size());
    double stratum = rng_.drawUniform(0.0, 1.0), log_max = -1e300;
    for (auto& p : next) {
      stratum += kGoldenRatioFraction;
      stratum -= std::floor(stratum);
      const TPose2D& a = particles_[drawAncestor(cumulative, stratum * acc)].d;
      p.d = TPose2D(a.x + rng_.drawGaussian1D(0, sxy), a.y + rng_.drawGaussian1D(0, sxy),
                    mrpt::math::wrapToPi(a.phi + rng_.drawGaussian1D(0, sth)));
      p.log_w = model.logLikelihood(p.d);
      log_max = std::max(log_max, p.log_w);
    }
    weighings_ += static_cast<int>(next.size());
    for (auto& p : next) p.log_w -= log_max;
    particles_.swap(next);
    temperWeights();
  }
}

namespace {
/// Effective sample size of weights exp(beta * log_w).
double effectiveSampleSize(const std::vector<Particle>& particles, double beta) {
  double sum = 0, sum_sq = 0;
  for (const auto& p : particles) {
    const double w = std::exp(beta * p.log_w);
    sum += w;
    sum_sq += w * w;
  }
  return sum * sum / sum_sq;
}
}  // namespace

void KldLocalizer::temperWeights() {
  const double target = params_.min_effective_fraction * particles_.size();
  if (effectiveSampleSize(particles_, 1.0) >= target) return;
  double lo = 0.0, hi = 1.0;  // ESS decreases with beta: bisect for ESS(beta) = target
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (effectiveSampleSize(particles_, mid) >= target ? lo : hi) = mid;
  }
  for (auto& p : particles_) p.log_w *= lo;
}

void KldLocalizer::normalizeAndEstimate() {
  double total = 0;
  for (const auto& p : particles_) total += std::exp(p.log_w);  // line 20
  const double log_total = std::log(total);
  for (auto& p : particles_) p.log_w -= log_total;  // lines 21-23
  estimate_ = estimateDominantCluster(particles_, params_.cluster_xy, params_.cluster_theta);
}

void KldLocalizer::keepPlausibleHypotheses() {
  const PoseEstimate& e = estimate_;
  if (e.cluster_count < 2) return;
  std::vector<double> log_scale(e.cluster_weights.size(), 0.0);
  bool changed = false;
  for (size_t c = 0; c < e.cluster_weights.size(); ++c) {
    const double w = e.cluster_weights[c];
    if (static_cast<int>(c) == e.best_cluster || w < 0.01 || w >= params_.hypothesis_min_weight)
      continue;
    const TPose2D mean = toMrpt(clusterMean(particles_, e, static_cast<int>(c)));
    if (measurement_.inlierFraction(mean, params_.inlier_tolerance) < params_.fit_min_mean)
      continue;
    log_scale[c] = std::log(params_.hypothesis_min_weight / w);
    changed = true;
  }
  if (!changed) return;
  for (size_t i = 0; i < particles_.size(); ++i)
    particles_[i].log_w += log_scale[e.particle_cluster[i]];
  normalizeAndEstimate();
}

wheelchair_core::LocalizationStatus KldLocalizer::status() const {
  using State = wheelchair_core::LocalizationState;
  wheelchair_core::LocalizationStatus s;
  s.particles = static_cast<int>(particles_.size());
  if (!initialized()) {
    s.state = State::kUninitialized;
    s.detail = "not initialized (no initial pose, no global localization)";
    return s;
  }
  const double sxy = std::sqrt(std::max(estimate_.cov(0, 0), estimate_.cov(1, 1)));
  const double sth = std::sqrt(estimate_.cov(2, 2));
  s.position_std = sxy;
  s.heading_std = sth;
  s.hypotheses = estimate_.cluster_count;
  s.best_weight = estimate_.cluster_weight;
  if (!pending_first_update_) {
    s.inlier_fraction = inliers_;
    s.mean_fit = meanFit();
  }
  std::ostringstream why;
  s.state = State::kLocalized;
  if (pending_first_update_) {
    s.state = State::kLocalizing;
    why << "waiting for the first scan after initialization";
  } else if (estimate_.cluster_weight < params_.localized_min_cluster_weight) {
    s.state = State::kAmbiguous;
    why << "ambiguous: " << estimate_.cluster_count << " pose hypotheses (best holds "
        << static_cast<int>(100 * estimate_.cluster_weight) << " % of the weight)";
  } else if (sxy > params_.localized_max_xy_std) {
    s.state = State::kUncertain;
    why << "position uncertainty too large (sigma " << sxy << " m)";
  } else if (sth > params_.localized_max_theta_std) {
    s.state = State::kUncertain;
    why << "heading uncertainty too large (sigma " << sth * 180 / M_PI << " deg)";
  } else if (inliers_ < params_.localized_min_inliers || meanFit() < params_.fit_min_mean) {
    s.state = State::kMisfit;
    why << "scan does not fit the map at the estimate (" << static_cast<int>(100 * inliers_)
        << " % of the echoes within " << params_.inlier_tolerance << " m of an obstacle, "
        << static_cast<int>(100 * meanFit()) << " % over the last " << fit_window_.size()
        << " updates)";
  } else if (w_slow_ > 0 && w_fast_ < params_.recovery_ratio * w_slow_) {
    s.state = State::kMisfit;
    why << "scans no longer match the map (short/long-term likelihood " << w_fast_ / w_slow_ << ")";
  }
  s.detail = why.str();
  return s;
}

}  // namespace wheelchair_kld
