#include <wheelchair_sim/sim_params.h>
#include <wheelchair_sim_testing/sim_config.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace wheelchair_sim {
namespace {

std::string writeTemp(const std::string& text) {
  const std::string path = ::testing::TempDir() + "sim_params_test.yaml";
  std::ofstream(path) << text;
  return path;
}

TEST(Params, ShippedFileLoadsWithTheSicksGeometry) {
  const SimParams p = loadSimParams(test::simConfigFile());
  EXPECT_EQ(p.laser_beams, 361);
  EXPECT_NEAR(p.laser_fov, M_PI, 1e-12);
  EXPECT_DOUBLE_EQ(p.laser_rate, 10.0);
  EXPECT_GE(p.physics_rate, 500.0);
}

TEST(Params, UnknownKeyIsNamed) {
  try {
    loadSimParams(writeTemp("laser_rte: 5\n"));
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("laser_rte"), std::string::npos);
  }
}

TEST(Params, TooSlowIntegrationIsRejected) {
  EXPECT_THROW(loadSimParams(writeTemp("physics_rate: 100\n")), std::runtime_error);
  SimParams p;
  p.laser_range_noise = -1.0;
  EXPECT_NE(p.validate().find("laser_range_noise"), std::string::npos) << p.validate();
}

}  // namespace
}  // namespace wheelchair_sim
