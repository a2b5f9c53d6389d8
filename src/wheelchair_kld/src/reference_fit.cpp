#include <wheelchair_kld/reference_fit.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_kld {

using wheelchair_core::Pose2D;

namespace {
mrpt::math::TPose2D toMrpt(const Pose2D& p) { return mrpt::math::TPose2D(p.x, p.y, p.yaw); }

/// The best pose of a grid of (2 n + 1)^3 offsets of `step_xy` / `step_theta` around `centre`
/// (offsets in the centre's frame), by the model's log-likelihood.
Pose2D gridPeak(const MeasurementModel& model, const Pose2D& centre, int n_xy, double step_xy,
                int n_theta, double step_theta) {
  Pose2D best = centre;
  double best_log = -INFINITY;
  for (int i = -n_xy; i <= n_xy; ++i)
    for (int j = -n_xy; j <= n_xy; ++j)
      for (int k = -n_theta; k <= n_theta; ++k) {
        const Pose2D p =
            wheelchair_core::compose(centre, Pose2D{i * step_xy, j * step_xy, k * step_theta});
        const double l = model.logLikelihood(toMrpt(p));
        if (l > best_log) {
          best_log = l;
          best = p;
        }
      }
  return best;
}
}  // namespace

ReferenceFit referenceFit(const LocalizationMap& map, const MeasurementParams& params,
                          const wheelchair_core::LaserScan2D& scan, const Pose2D& sensor_pose,
                          const Pose2D& base, double inlier_tolerance, double search_xy,
                          double search_theta) {
  MeasurementParams all = params;
  all.beam_step = 1;
  all.likelihood_exponent = 1.0;
  MeasurementModel model(map, all);
  model.setScan(scan, sensor_pose);
  ReferenceFit r;
  r.fit = model.fitCounts(toMrpt(base), inlier_tolerance);
  r.endpoint_distances = model.endpointDistances(toMrpt(base));
  const double step_xy = 0.02, step_theta = 0.5 * M_PI / 180;
  Pose2D peak = gridPeak(model, base, static_cast<int>(std::ceil(search_xy / step_xy)), step_xy,
                         static_cast<int>(std::ceil(search_theta / step_theta)), step_theta);
  peak = gridPeak(model, peak, 2, step_xy / 4, 2, step_theta / 4);
  peak = gridPeak(model, peak, 2, step_xy / 16, 2, step_theta / 16);
  // The offset of the laser's peak pose in the reference laser's frame.
  const Pose2D laser_ref = wheelchair_core::compose(base, sensor_pose);
  const Pose2D laser_peak = wheelchair_core::compose(peak, sensor_pose);
  r.peak_offset = wheelchair_core::between(laser_ref, laser_peak);
  return r;
}

ReferenceFitSummary summarizeReferenceFits(const std::vector<ReferenceFit>& fits) {
  ReferenceFitSummary s;
  s.scans = fits.size();
  if (fits.empty()) return s;
  std::vector<double> d;
  double xy2 = 0, th2 = 0;
  for (const ReferenceFit& f : fits) {
    s.inlier_share_mean += f.fit.echoes > 0 ? double(f.fit.inliers) / f.fit.echoes : 0.0;
    s.known_fit_mean += f.fit.knownFit();
    d.insert(d.end(), f.endpoint_distances.begin(), f.endpoint_distances.end());
    const Pose2D& o = f.peak_offset;
    xy2 += o.x * o.x + o.y * o.y;
    th2 += o.yaw * o.yaw;
    s.peak_x_mean += o.x;
    s.peak_y_mean += o.y;
    s.peak_theta_mean += o.yaw;
  }
  const double n = static_cast<double>(fits.size());
  s.inlier_share_mean /= n;
  s.known_fit_mean /= n;
  s.peak_xy_rms = std::sqrt(xy2 / n);
  s.peak_theta_rms = std::sqrt(th2 / n);
  s.peak_x_mean /= n;
  s.peak_y_mean /= n;
  s.peak_theta_mean /= n;
  if (!d.empty()) {
    std::sort(d.begin(), d.end());
    auto at = [&](double q) {
      return d[std::min(d.size() - 1, static_cast<size_t>(q * d.size()))];
    };
    s.distance_p50 = at(0.5);
    s.distance_p90 = at(0.9);
    s.distance_p95 = at(0.95);
  }
  return s;
}

}  // namespace wheelchair_kld
