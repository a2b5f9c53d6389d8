#include <wheelchair_kld/mrpt_equivalent.h>

#include <cmath>

namespace wheelchair_kld {

mrpt::bayes::CParticleFilter::TParticleFilterOptions mrptFilterOptions(const KldParams& params) {
  mrpt::bayes::CParticleFilter::TParticleFilterOptions options;
  options.adaptiveSampleSize = true;
  options.resamplingMethod = mrpt::bayes::CParticleFilter::prMultinomial;
  options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
  options.powFactor = params.measurement.likelihood_exponent;
  return options;
}

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mrptThrunMotion(const KldParams& params) {
  mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion;
  motion.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
  const MotionNoise& mn = params.motion;
  motion.thrunModel.alfa1_rot_rot = static_cast<float>(std::sqrt(mn.alpha1));
  motion.thrunModel.alfa2_rot_trans = static_cast<float>(std::sqrt(mn.alpha2));
  motion.thrunModel.alfa3_trans_trans = static_cast<float>(std::sqrt(mn.alpha3));
  motion.thrunModel.alfa4_trans_rot = static_cast<float>(std::sqrt(mn.alpha4));
  motion.thrunModel.additional_std_XY = static_cast<float>(mn.min_xy_std);
  motion.thrunModel.additional_std_phi = static_cast<float>(mn.min_theta_std);
  return motion;
}

}  // namespace wheelchair_kld
