// MRPT's own Monte Carlo localization set up as ours is, for the side-by-side tables (replay's
// --mrpt, kld_bench): the same likelihood tempering and odometry noise, and MRPT's KLD
// resampling. ROS-free.
#pragma once

#include <wheelchair_kld/kld_params.h>

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPosePDFParticles.h>
#include <mrpt/random/RandomGenerators.h>

#include <cstddef>

namespace wheelchair_kld {

/// Standard proposal, adaptive (KLD) sample size with multinomial resampling (the only one
/// MRPT allows with a changing count), the likelihood raised to our exponent (powFactor).
mrpt::bayes::CParticleFilter::TParticleFilterOptions mrptFilterOptions(const KldParams& params);

/// MRPT's Thrun odometry model with our noise: it draws with std = alfa * |motion| where ours
/// has variance = alpha * motion^2, hence alfa = sqrt(alpha); our floors as additional stds.
mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mrptThrunMotion(const KldParams& params);

/// The odometry increment from `from` to `to` as `n` samples of our odometry model (Thrun's
/// Table 5.6 with a backwards motion kept as such and a turn on the spot's few-mm creep adding
/// no direction noise), for CActionRobotMovement2D::poseChange. The weights are normalized
/// (log_w = -log n): MRPT draws a sample by accumulating exp(log_w) up to a uniform number in
/// [0, 1), so with Create()'s log_w 0 each it drew the first sample for every particle and its
/// cloud got no motion noise at all (replay --mrpt lost Intel, 29 m RMS; normalized 7.2 cm).
mrpt::poses::CPosePDFParticles::Ptr mrptOdometrySamples(const mrpt::math::TPose2D& from,
                                                        const mrpt::math::TPose2D& to,
                                                        const MotionNoise& noise,
                                                        mrpt::random::CRandomGenerator& rng,
                                                        size_t n = 1000);

}  // namespace wheelchair_kld
