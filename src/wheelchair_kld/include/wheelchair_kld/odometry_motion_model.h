// Odometry-based motion model: sample_motion_model_odometry (Thrun, Burgard, Fox, Table 5.6).
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <wheelchair_kld/kld_params.h>

namespace wheelchair_kld {

/// Odometry increment decomposed as rotation - translation - rotation. A backwards motion
/// keeps rot1 small and makes trans negative. rot1 is the true direction of travel even for a
/// tiny translation (a turn on the spot whose axle swings a few mm).
struct OdometryIncrement {
  double rot1 = 0, trans = 0, rot2 = 0;
};

/// Decomposes the odometry motion from `from` to `to` (both in the odom frame).
OdometryIncrement decomposeOdometry(const mrpt::math::TPose2D& from, const mrpt::math::TPose2D& to);

/// Below this travel [m] the direction of travel (rot1) is numerically meaningless: it adds no
/// rotation noise, the whole heading change counts as rot2 for the noise.
constexpr double kMinTransForDirectionNoise = 0.01;

/// Draws a successor of `pose` under the increment with alpha1..alpha4 noise.
mrpt::math::TPose2D sampleMotionModel(const OdometryIncrement& u, const mrpt::math::TPose2D& pose,
                                      const MotionNoise& noise,
                                      mrpt::random::CRandomGenerator& rng);

}  // namespace wheelchair_kld
