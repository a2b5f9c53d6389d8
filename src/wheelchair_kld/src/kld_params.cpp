#include <wheelchair_kld/kld_params.h>

namespace wheelchair_kld {

using wheelchair_core::ConfigChecks;

std::string MotionNoise::validate() const {
  return ConfigChecks()
      .nonNegative("odom_alpha1", alpha1)
      .nonNegative("odom_alpha2", alpha2)
      .nonNegative("odom_alpha3", alpha3)
      .nonNegative("odom_alpha4", alpha4)
      .nonNegative("odom_min_xy_std", min_xy_std)
      .nonNegative("odom_min_theta_std", min_theta_std)
      .result();
}

std::string MeasurementParams::validate() const {
  return ConfigChecks()
      .check(beam_step >= 1, "laser_beam_step must be at least 1")
      .positive("laser_sigma_hit", sigma_hit)
      .inRange("laser_z_hit", z_hit, 0.0, 1.0)
      .inRange("laser_z_rand", z_rand, 0.0, 1.0)
      .inRange("laser_z_short", z_short, 0.0, 1.0)
      .inRange("laser_z_max", z_max, 0.0, 1.0)
      .check(z_hit + z_rand > 0, "laser_z_hit + laser_z_rand must be positive")
      .positive("laser_lambda_short", lambda_short)
      .positive("laser_max_range", max_range)
      .positive("laser_max_distance", max_distance)
      .positive("laser_likelihood_exponent", likelihood_exponent)
      .result();
}

std::string KldParams::validate() const {
  ConfigChecks c;
  c.inRange("laser_min_echo_fraction", min_echo_fraction, 0.0, 1.0)
      .positive("kld_epsilon", epsilon)
      .check(delta > 0 && delta < 1, "kld_delta must lie in (0, 1)")
      .positive("bin_xy", bin_xy)
      .positive("bin_theta", bin_theta)
      .check(min_particles >= 1, "min_particles must be at least 1")
      .check(max_particles >= min_particles, "max_particles must be at least min_particles")
      .check(global_particles >= 1, "global_particles must be at least 1")
      .check(init_particles >= 1, "init_particles must be at least 1")
      .check(fixed_particles >= 0, "fixed_particles must not be negative (0: KLD-sampling)")
      .check(min_effective_fraction > 0 && min_effective_fraction <= 1,
             "min_effective_fraction must lie in (0, 1]")
      .check(refine_steps >= 0, "refine_steps must not be negative")
      .nonNegative("refine_xy", refine_xy)
      .nonNegative("refine_theta", refine_theta)
      .nonNegative("update_min_d", update_min_d)
      .nonNegative("update_min_a", update_min_a)
      .inRange("recovery_alpha_slow", alpha_slow, 0.0, 1.0)
      .inRange("recovery_alpha_fast", alpha_fast, 0.0, 1.0)
      .positive("recovery_ratio", recovery_ratio)
      .positive("cluster_xy", cluster_xy)
      .positive("cluster_theta", cluster_theta)
      .positive("localized_max_xy_std", localized_max_xy_std)
      .positive("localized_max_theta_std", localized_max_theta_std)
      .inRange("localized_min_cluster_weight", localized_min_cluster_weight, 0.0, 1.0)
      .inRange("hypothesis_min_weight", hypothesis_min_weight, 0.0, 1.0)
      .inRange("localized_min_inliers", localized_min_inliers, 0.0, 1.0)
      .positive("inlier_tolerance", inlier_tolerance)
      .check(fit_window >= 1, "fit_window must be at least 1")
      .inRange("fit_min_mean", fit_min_mean, 0.0, 1.0)
      .check(fit_beam_step >= 1, "fit_beam_step must be at least 1")
      .inRange("fit_max_short_share", fit_max_short_share, 0.0, 1.0)
      .inRange("relocalize_max_fit", relocalize_max_fit, 0.0, 1.0)
      .check(relocalize_min_echoes >= 1, "relocalize_min_echoes must be at least 1")
      .check(relocalize_updates >= 0, "relocalize_updates must not be negative (0: off)")
      .check(relocalize_particles >= 1, "relocalize_particles must be at least 1")
      .check(relocalize_refine_per_update >= 0, "relocalize_refine_per_update must not be negative")
      .check(update_max_particles == 0 || update_max_particles >= 2 * min_particles,
             "update_max_particles must be 0 (unbounded) or at least twice min_particles")
      .positive("peak_max_xy", peak_max_xy)
      .positive("peak_max_theta", peak_max_theta);
  for (const std::string& nested : {motion.validate(), measurement.validate()})
    c.check(nested.empty(), nested);
  return c.result();
}

void readKldParams(wheelchair_core::ConfigReader& r, KldParams& p) {
  r.read("laser_min_echo_fraction", p.min_echo_fraction);
  r.read("kld_epsilon", p.epsilon);
  r.read("kld_delta", p.delta);
  r.read("bin_xy", p.bin_xy);
  r.read("bin_theta", p.bin_theta);
  r.read("min_particles", p.min_particles);
  r.read("max_particles", p.max_particles);
  r.read("global_particles", p.global_particles);
  r.read("init_particles", p.init_particles);
  r.read("fixed_particles", p.fixed_particles);
  r.read("min_effective_fraction", p.min_effective_fraction);
  r.read("refine_steps", p.refine_steps);
  r.read("refine_xy", p.refine_xy);
  r.read("refine_theta", p.refine_theta);
  r.read("update_min_d", p.update_min_d);
  r.read("update_min_a", p.update_min_a);
  r.read("recovery_alpha_slow", p.alpha_slow);
  r.read("recovery_alpha_fast", p.alpha_fast);
  r.read("recovery_ratio", p.recovery_ratio);
  r.read("cluster_xy", p.cluster_xy);
  r.read("cluster_theta", p.cluster_theta);
  r.read("localized_max_xy_std", p.localized_max_xy_std);
  r.read("localized_max_theta_std", p.localized_max_theta_std);
  r.read("localized_min_cluster_weight", p.localized_min_cluster_weight);
  r.read("hypothesis_min_weight", p.hypothesis_min_weight);
  r.read("localized_min_inliers", p.localized_min_inliers);
  r.read("inlier_tolerance", p.inlier_tolerance);
  r.read("fit_window", p.fit_window);
  r.read("fit_min_mean", p.fit_min_mean);
  r.read("fit_max_short_share", p.fit_max_short_share);
  r.read("fit_beam_step", p.fit_beam_step);
  r.read("relocalize_max_fit", p.relocalize_max_fit);
  r.read("relocalize_min_echoes", p.relocalize_min_echoes);
  r.read("relocalize_updates", p.relocalize_updates);
  r.read("relocalize_on_mean_fit", p.relocalize_on_mean_fit);
  r.read("relocalize_particles", p.relocalize_particles);
  r.read("relocalize_refine_per_update", p.relocalize_refine_per_update);
  r.read("update_max_particles", p.update_max_particles);
  r.read("peak_estimate", p.peak_estimate);
  r.read("peak_max_xy", p.peak_max_xy);
  r.read("peak_max_theta", p.peak_max_theta);

  MotionNoise& m = p.motion;
  r.read("odom_alpha1", m.alpha1);
  r.read("odom_alpha2", m.alpha2);
  r.read("odom_alpha3", m.alpha3);
  r.read("odom_alpha4", m.alpha4);
  r.read("odom_min_xy_std", m.min_xy_std);
  r.read("odom_min_theta_std", m.min_theta_std);

  MeasurementParams& z = p.measurement;
  std::string model = z.type == MeasurementModelType::kBeam ? "beam" : "likelihood_field";
  r.read("laser_model_type", model);
  if (model == "beam") {
    z.type = MeasurementModelType::kBeam;
  } else if (model == "likelihood_field") {
    z.type = MeasurementModelType::kLikelihoodField;
  } else {
    throw wheelchair_core::ConfigError(r.source().where() + ": laser_model_type must be " +
                                       "likelihood_field or beam (got '" + model + "')");
  }
  r.read("laser_beam_step", z.beam_step);
  r.read("laser_sigma_hit", z.sigma_hit);
  r.read("laser_z_hit", z.z_hit);
  r.read("laser_z_rand", z.z_rand);
  r.read("laser_z_short", z.z_short);
  r.read("laser_z_max", z.z_max);
  r.read("laser_lambda_short", z.lambda_short);
  r.read("laser_max_range", z.max_range);
  r.read("laser_max_distance", z.max_distance);
  r.read("laser_likelihood_exponent", z.likelihood_exponent);
}

}  // namespace wheelchair_kld
