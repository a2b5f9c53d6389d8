#include <gtest/gtest.h>
#include <wheelchair_display/display_config.h>
#include <yaml-cpp/yaml.h>

namespace wheelchair_display {
namespace {

DisplayConfig fromYaml(const std::string& text) {
  const wheelchair_core::YamlParameterSource source(YAML::Load(text), "display.yaml");
  return wheelchair_core::loadConfig<DisplayConfig>(source, readDisplayConfig);
}

}  // namespace

TEST(DisplayConfig, TheDefaultsAreValidAndDwellIsOneAndAHalfSeconds) {
  EXPECT_EQ(DisplayConfig().validate(), "");
  EXPECT_DOUBLE_EQ(DisplayConfig().dwell_time, 1.5);
  EXPECT_EQ(fromYaml("{}").theme, "dark");
}

TEST(DisplayConfig, EveryKeyIsRead) {
  const DisplayConfig c = fromYaml(
      "{theme: light, orientation: chair_up, dwell_time: 2.0, dwell_radius: 0.1, "
      "stop_on_hover: false, outcome_hold: 10, min_view_extent: 3, room_pad: 0.4, carer_hold: 2, "
      "flash_period: 1.5, speech: false, speech_voice: en-gb, speech_volume: 150, "
      "speech_rate: 120, speak_highlight: true}");
  EXPECT_EQ(c.theme, "light");
  EXPECT_EQ(c.orientation, "chair_up");
  EXPECT_DOUBLE_EQ(c.dwell_time, 2.0);
  EXPECT_FALSE(c.stop_on_hover);
  EXPECT_FALSE(c.speech.enabled);
  EXPECT_EQ(c.speech.voice, "en-gb");
  EXPECT_EQ(c.speech.volume, 150);
  EXPECT_EQ(c.speech.rate, 120);
  EXPECT_TRUE(c.speak_highlight);
}

TEST(DisplayConfig, AnUnknownKeyIsRefusedNamingIt) {
  try {
    fromYaml("{dwell: 2.0}");
    FAIL() << "accepted an unknown key";
  } catch (const wheelchair_core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("dwell"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("dwell_time"), std::string::npos) << e.what();
  }
}

TEST(DisplayConfig, InvalidValuesAreRefused) {
  EXPECT_THROW(fromYaml("{theme: blue}"), wheelchair_core::ConfigError);
  EXPECT_THROW(fromYaml("{orientation: east_up}"), wheelchair_core::ConfigError);
  EXPECT_THROW(fromYaml("{dwell_time: 0.0}"), wheelchair_core::ConfigError);
  EXPECT_THROW(fromYaml("{speech_volume: 500}"), wheelchair_core::ConfigError);
  EXPECT_THROW(fromYaml("{flash_period: 0.2}"), wheelchair_core::ConfigError);  // > 3 flashes/s
}

}  // namespace wheelchair_display
