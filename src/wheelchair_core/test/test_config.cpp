#include <gtest/gtest.h>
#include <wheelchair_core/config.h>
#include <yaml-cpp/yaml.h>

namespace wheelchair_core {
namespace {

struct Limits {
  double timeout = 0.3;
  int beams = 0;
  bool enabled = true;
  std::string frame = "map";
  std::vector<Eigen::Vector2d> footprint;
  std::string validate() const {
    return ConfigChecks().positive("timeout", timeout).nonNegative("beams", beams).result();
  }
};

void readLimits(ConfigReader& r, Limits& c) {
  r.renamed("scan_timeout", "timeout");
  r.read("timeout", c.timeout);
  r.read("beams", c.beams);
  r.read("enabled", c.enabled);
  r.read("frame", c.frame);
  r.read("footprint", c.footprint);
}

Limits load(const std::string& yaml) {
  return loadConfig<Limits>(YamlParameterSource(YAML::Load(yaml), "test.yaml"), readLimits);
}

std::string errorOf(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Config, KeysOverwriteDefaultsAndAbsentKeysKeepThem) {
  const Limits c =
      load("timeout: 0.5\nframe: odom\nfootprint: [[0.4, -0.3], [0.4, 0.3], [-0.8, 0]]");
  EXPECT_DOUBLE_EQ(c.timeout, 0.5);
  EXPECT_EQ(c.frame, "odom");
  EXPECT_EQ(c.beams, 0);
  EXPECT_TRUE(c.enabled);
  ASSERT_EQ(c.footprint.size(), 3u);
  EXPECT_DOUBLE_EQ(c.footprint[2].x(), -0.8);
}

TEST(Config, AnIntegerIsAcceptedForANumber) { EXPECT_DOUBLE_EQ(load("timeout: 2").timeout, 2.0); }

TEST(Config, AMisspeltKeyIsRefusedWithTheKnownKeys) {
  const std::string e = errorOf("timout: 0.5");
  EXPECT_NE(e.find("test.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown parameter 'timout'"), std::string::npos) << e;
  EXPECT_NE(e.find("timeout"), std::string::npos) << e;
}

TEST(Config, ARenamedKeyIsRefusedNamingTheNewOne) {
  const std::string e = errorOf("scan_timeout: 0.5");
  EXPECT_NE(e.find("'scan_timeout' is now called 'timeout'"), std::string::npos) << e;
}

TEST(Config, AnInvalidValueIsRefusedWithTheReason) {
  const std::string e = errorOf("timeout: -1");
  EXPECT_NE(e.find("timeout must be positive (got -1)"), std::string::npos) << e;
}

TEST(Config, AValueOfTheWrongTypeIsRefused) {
  EXPECT_NE(errorOf("enabled: maybe").find("'enabled' must be true or false"), std::string::npos);
  EXPECT_NE(errorOf("footprint: [[1, 2, 3]]").find("[x, y] pairs"), std::string::npos);
  // The item that is wrong is named.
  EXPECT_NE(errorOf("footprint: [[1, 2], [0, a]]").find("'footprint[1][1]' is not a number"),
            std::string::npos);
  EXPECT_NE(errorOf("footprint: [[1, 2], [3]]").find("'footprint[1]' is not an [x, y] pair"),
            std::string::npos);
  EXPECT_NE(errorOf("timeout: [1, 2]").find("must be a number"), std::string::npos);
}

TEST(Config, NestedKeysAreFlattenedWithSlashes) {
  const YamlParameterSource src(YAML::Load("search: {time: 3.0, cusps: 2}\nrate: 1"), "n");
  const auto keys = src.keys();
  EXPECT_EQ(keys.size(), 3u);
  double time = 0;
  int cusps = 0;
  EXPECT_TRUE(src.get("search/time", time));
  EXPECT_TRUE(src.get("search/cusps", cusps));
  EXPECT_DOUBLE_EQ(time, 3.0);
  EXPECT_EQ(cusps, 2);
  EXPECT_FALSE(src.get("search/other", time));
  EXPECT_FALSE(src.get("rate/x", time));
}

TEST(Config, ARequiredKeyMustBePresent) {
  const YamlParameterSource src(YAML::Load("a: 1"), "req.yaml");
  ConfigReader r(src);
  double b = 0;
  EXPECT_THROW(r.require("b", b), ConfigError);
}

}  // namespace
}  // namespace wheelchair_core
