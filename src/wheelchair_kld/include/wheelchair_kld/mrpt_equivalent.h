// MRPT's own Monte Carlo localization set up as ours is, for the side-by-side tables (replay's
// --mrpt, kld_bench): the same likelihood tempering and odometry noise, and MRPT's KLD
// resampling. ROS-free.
#pragma once

#include <wheelchair_kld/kld_params.h>

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionRobotMovement2D.h>

namespace wheelchair_kld {

/// Standard proposal, adaptive (KLD) sample size with multinomial resampling (the only one
/// MRPT allows with a changing count), the likelihood raised to our exponent (powFactor).
mrpt::bayes::CParticleFilter::TParticleFilterOptions mrptFilterOptions(const KldParams& params);

/// MRPT's Thrun odometry model with our noise: it draws with std = alfa * |motion| where ours
/// has variance = alpha * motion^2, hence alfa = sqrt(alpha); our floors as additional stds.
mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mrptThrunMotion(const KldParams& params);

}  // namespace wheelchair_kld
