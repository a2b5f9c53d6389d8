#include <mrpt/math/wrap2pi.h>
#include <wheelchair_kld/odometry_motion_model.h>

#include <cmath>

namespace wheelchair_kld {

using mrpt::math::TPose2D;
using mrpt::math::wrapToPi;

OdometryIncrement decomposeOdometry(const TPose2D& from, const TPose2D& to) {
  OdometryIncrement u;
  const double dx = to.x - from.x, dy = to.y - from.y;
  u.trans = std::hypot(dx, dy);
  u.rot1 = u.trans == 0 ? 0.0 : wrapToPi(std::atan2(dy, dx) - from.phi);
  if (std::abs(u.rot1) > M_PI / 2) {  // driving backwards
    u.rot1 = wrapToPi(u.rot1 + M_PI);
    u.trans = -u.trans;
  }
  u.rot2 = wrapToPi(to.phi - from.phi - u.rot1);
  return u;
}

TPose2D sampleMotionModel(const OdometryIncrement& u, const TPose2D& pose, const MotionNoise& n,
                          mrpt::random::CRandomGenerator& rng) {
  // Noise magnitudes: for a tiny translation the heading change is all rot2 (see the header).
  const bool tiny = std::abs(u.trans) < kMinTransForDirectionNoise;
  const double rot1_noise = tiny ? 0.0 : u.rot1,
               rot2_noise = tiny ? wrapToPi(u.rot1 + u.rot2) : u.rot2;
  const double r1 = rot1_noise * rot1_noise, r2 = rot2_noise * rot2_noise, t2 = u.trans * u.trans;
  const double rot1 = u.rot1 - rng.drawGaussian1D(0, std::sqrt(n.alpha1 * r1 + n.alpha2 * t2));
  const double trans =
      u.trans - rng.drawGaussian1D(0, std::sqrt(n.alpha3 * t2 + n.alpha4 * (r1 + r2)));
  const double rot2 = u.rot2 - rng.drawGaussian1D(0, std::sqrt(n.alpha1 * r2 + n.alpha2 * t2));
  const double heading = pose.phi + rot1;
  return TPose2D(pose.x + trans * std::cos(heading) + rng.drawGaussian1D(0, n.min_xy_std),
                 pose.y + trans * std::sin(heading) + rng.drawGaussian1D(0, n.min_xy_std),
                 wrapToPi(heading + rot2 + rng.drawGaussian1D(0, n.min_theta_std)));
}

}  // namespace wheelchair_kld
