#include <mrpt/math/wrap2pi.h>
#include <wheelchair_kld/likelihood_peak.h>

#include <cmath>

namespace wheelchair_kld {

using mrpt::math::TPose2D;

TPose2D likelihoodPeakNear(const MeasurementModel& model, const TPose2D& start,
                           const PeakSearch& search) {
  TPose2D best = start;
  double best_log = model.logLikelihood(best);
  int evaluations = 1;
  double sxy = search.step_xy, sth = search.step_theta;
  while (sxy >= search.min_step_xy && evaluations < search.max_evaluations) {
    const double moves[6][3] = {{sxy, 0, 0},  {-sxy, 0, 0}, {0, sxy, 0},
                                {0, -sxy, 0}, {0, 0, sth},  {0, 0, -sth}};
    int chosen = -1;
    TPose2D chosen_pose;
    double chosen_log = best_log;
    for (const auto& m : moves) {
      const TPose2D p(best.x + m[0], best.y + m[1], mrpt::math::wrapToPi(best.phi + m[2]));
      if (std::hypot(p.x - start.x, p.y - start.y) > search.max_xy ||
          std::abs(mrpt::math::wrapToPi(p.phi - start.phi)) > search.max_theta)
        continue;
      const double l = model.logLikelihood(p);
      ++evaluations;
      if (l > chosen_log) {
        chosen_log = l;
        chosen_pose = p;
        chosen = 1;
      }
    }
    if (chosen >= 0) {
      best = chosen_pose;
      best_log = chosen_log;
    } else {
      sxy *= 0.5;
      sth *= 0.5;
    }
  }
  return best;
}

}  // namespace wheelchair_kld
