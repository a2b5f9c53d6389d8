// The localizer's one parameter list: every key read, defaults valid, unknown / renamed keys and
// invalid values refused with a message that names them.
#include <gtest/gtest.h>
#include <wheelchair_kld/kld_params.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "localizer_node_config.h"

using namespace wheelchair_kld;
using wheelchair_core::ConfigError;
using wheelchair_core::YamlParameterSource;

namespace {

LocalizerNodeConfig load(const std::string& yaml) {
  const YamlParameterSource source(YAML::Load(yaml), "test.yaml");
  return wheelchair_core::loadConfig<LocalizerNodeConfig>(source, readLocalizerNodeConfig);
}

std::string errorOf(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(KldParams, TheDefaultsAreValid) {
  EXPECT_EQ(KldParams().validate(), "");
  EXPECT_EQ(LocalizerNodeConfig().validate(), "");
}

// Issue 21: the re-localization rule's every threshold is a key of the nodelet (its loader is
// this one), checked and refused by name.
TEST(KldParams, TheRelocalizationRuleIsParameterized) {
  const LocalizerNodeConfig c = load(
      "{relocalize_max_fit: 0.3, relocalize_min_echoes: 40, relocalize_updates: 3,"
      " relocalize_on_mean_fit: true, relocalize_particles: 5000, fit_beam_step: 2}");
  EXPECT_DOUBLE_EQ(c.filter.relocalize_max_fit, 0.3);
  EXPECT_EQ(c.filter.relocalize_min_echoes, 40);
  EXPECT_EQ(c.filter.relocalize_updates, 3);
  EXPECT_TRUE(c.filter.relocalize_on_mean_fit);
  EXPECT_EQ(c.filter.relocalize_particles, 5000);
  EXPECT_EQ(c.filter.fit_beam_step, 2);
  EXPECT_NE(errorOf("{relocalize_max_fit: 1.5}").find("relocalize_max_fit"), std::string::npos);
  EXPECT_NE(errorOf("{relocalize_updates: -1}").find("relocalize_updates"), std::string::npos);
  EXPECT_NE(errorOf("{relocalize_particles: 0}").find("relocalize_particles"), std::string::npos);
  EXPECT_NE(errorOf("{fit_beam_step: 0}").find("fit_beam_step"), std::string::npos);
}

// The per-update bound is a key, 0 turns it off, and one below twice min_particles is refused.
TEST(KldParams, TheUpdateBoundIsAParameter) {
  EXPECT_EQ(load("{update_max_particles: 8000}").filter.update_max_particles, 8000);
  EXPECT_EQ(load("{update_max_particles: 0}").filter.update_max_particles, 0);
  EXPECT_EQ(load("{relocalize_refine_per_update: 0}").filter.relocalize_refine_per_update, 0);
  EXPECT_NE(errorOf("{update_max_particles: 300}").find("update_max_particles"), std::string::npos);
  EXPECT_NE(errorOf("{relocalize_refine_per_update: -1}").find("relocalize_refine_per_update"),
            std::string::npos);
}

TEST(KldParams, EveryThresholdIsAParameter) {
  const LocalizerNodeConfig c = load(
      "{fit_min_mean: 0.7, fit_window: 20, kld_epsilon: 0.1, recovery_alpha_slow: 0.002,"
      " localized_min_inliers: 0.6, hypothesis_min_weight: 0.2, refine_steps: 2,"
      " laser_min_echo_fraction: 0.3, laser_model_type: beam, laser_beam_step: 3,"
      " laser_max_distance: 1.5, odom_alpha3: 0.1, odom_min_xy_std: 0.01,"
      " map_frame: world, tf_timeout: 1.5, expected_beams: 181, seed: 7}");
  EXPECT_DOUBLE_EQ(c.filter.fit_min_mean, 0.7);
  EXPECT_EQ(c.filter.fit_window, 20);
  EXPECT_DOUBLE_EQ(c.filter.epsilon, 0.1);
  EXPECT_DOUBLE_EQ(c.filter.alpha_slow, 0.002);
  EXPECT_DOUBLE_EQ(c.filter.localized_min_inliers, 0.6);
  EXPECT_DOUBLE_EQ(c.filter.hypothesis_min_weight, 0.2);
  EXPECT_EQ(c.filter.refine_steps, 2);
  EXPECT_DOUBLE_EQ(c.filter.min_echo_fraction, 0.3);
  EXPECT_EQ(c.filter.measurement.type, MeasurementModelType::kBeam);
  EXPECT_EQ(c.filter.measurement.beam_step, 3);
  EXPECT_DOUBLE_EQ(c.filter.measurement.max_distance, 1.5);
  EXPECT_DOUBLE_EQ(c.filter.motion.alpha3, 0.1);
  EXPECT_DOUBLE_EQ(c.filter.motion.min_xy_std, 0.01);
  EXPECT_EQ(c.map_frame, "world");
  EXPECT_DOUBLE_EQ(c.tf_timeout, 1.5);
  EXPECT_EQ(c.expected_beams, 181);
  EXPECT_EQ(c.seed, 7);
  // Keys not given keep the struct's defaults.
  EXPECT_DOUBLE_EQ(c.filter.bin_xy, KldParams().bin_xy);
  EXPECT_EQ(c.odom_frame, "odom");
}

TEST(KldParams, AMisspeltKeyIsRefusedNamingTheKnownOnes) {
  const std::string e = errorOf("{fit_mean: 0.7}");
  EXPECT_NE(e.find("test.yaml: unknown parameter 'fit_mean'"), std::string::npos) << e;
  EXPECT_NE(e.find("fit_min_mean"), std::string::npos) << e;
}

TEST(KldParams, TheOldNameOfTheMapFrameIsRefusedNamingTheNewOne) {
  const std::string e = errorOf("{global_frame: map}");
  EXPECT_NE(e.find("'global_frame' is now called 'map_frame'"), std::string::npos) << e;
}

TEST(KldParams, InvalidValuesAreRefusedSayingWhy) {
  EXPECT_NE(errorOf("{kld_delta: 1.5}").find("kld_delta must lie in (0, 1)"), std::string::npos);
  EXPECT_NE(errorOf("{fit_min_mean: 1.2}").find("fit_min_mean must lie in [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorOf("{min_particles: 500, max_particles: 100}").find("max_particles"),
            std::string::npos);
  EXPECT_NE(errorOf("{laser_sigma_hit: 0}").find("laser_sigma_hit must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf("{laser_model_type: beams}").find("likelihood_field or beam"),
            std::string::npos);
  EXPECT_NE(errorOf("{scan_queue_size: 0}").find("scan_queue_size"), std::string::npos);
  EXPECT_NE(errorOf("{map_frame: ''}").find("must be named"), std::string::npos);
}
