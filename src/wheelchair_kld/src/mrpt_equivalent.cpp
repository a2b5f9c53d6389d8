#include <wheelchair_kld/mrpt_equivalent.h>
#include <wheelchair_kld/odometry_motion_model.h>

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

mrpt::poses::CPosePDFParticles::Ptr mrptOdometrySamples(const mrpt::math::TPose2D& from,
                                                        const mrpt::math::TPose2D& to,
                                                        const MotionNoise& noise,
                                                        mrpt::random::CRandomGenerator& rng,
                                                        size_t n) {
  const OdometryIncrement u = decomposeOdometry(from, to);
  auto samples = mrpt::poses::CPosePDFParticles::Create(n);
  for (auto& p : samples->m_particles) {
    p.d = sampleMotionModel(u, mrpt::math::TPose2D(0, 0, 0), noise, rng);
    p.log_w = -std::log(static_cast<double>(n));
  }
  return samples;
}

}  // namespace wheelchair_kld
