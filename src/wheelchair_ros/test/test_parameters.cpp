// The nodelet parameter loader against a live parameter server: typed reads, nested keys, and
// the refusals (unknown key with the known ones, renamed key, invalid value, wrong type).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <wheelchair_ros/parameters.h>

namespace wheelchair_ros {
namespace {

struct Options {
  double timeout = 0.3;
  int beams = 0;
  std::string frame = "map";
  std::vector<Eigen::Vector2d> footprint;
  double search_time = 1.0;
  std::string validate() const {
    return wheelchair_core::ConfigChecks().positive("timeout", timeout).result();
  }
};

void readOptions(wheelchair_core::ConfigReader& r, Options& o) {
  r.renamed("scan_timeout", "timeout");
  r.read("timeout", o.timeout);
  r.read("beams", o.beams);
  r.read("frame", o.frame);
  r.read("footprint", o.footprint);
  r.read("search/time", o.search_time);
}

std::string errorOf(const ros::NodeHandle& nh) {
  try {
    loadParameters<Options>(nh, readOptions);
  } catch (const wheelchair_core::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, EveryKeyIsReadWithItsType) {
  const Options o = loadParameters<Options>(ros::NodeHandle("~"), readOptions);
  EXPECT_DOUBLE_EQ(o.timeout, 0.5);
  EXPECT_EQ(o.beams, 361);
  EXPECT_EQ(o.frame, "odom");
  ASSERT_EQ(o.footprint.size(), 3u);
  EXPECT_DOUBLE_EQ(o.footprint[2].x(), -0.8);
  EXPECT_DOUBLE_EQ(o.search_time, 3.0);
}

TEST(Parameters, AnUnknownKeyIsRefusedNamingItAndTheKnownKeys) {
  ros::NodeHandle nh("~unknown");
  nh.setParam("timout", 0.5);
  const std::string e = errorOf(nh);
  EXPECT_NE(e.find("unknown parameter 'timout'"), std::string::npos) << e;
  EXPECT_NE(e.find("search/time"), std::string::npos) << e;
  EXPECT_NE(e.find(nh.getNamespace()), std::string::npos) << e;
}

TEST(Parameters, ARenamedKeyIsRefusedNamingTheNewOne) {
  ros::NodeHandle nh("~renamed");
  nh.setParam("scan_timeout", 0.5);
  EXPECT_NE(errorOf(nh).find("'scan_timeout' is now called 'timeout'"), std::string::npos);
}

TEST(Parameters, AnInvalidValueIsRefused) {
  ros::NodeHandle nh("~invalid");
  nh.setParam("timeout", -2.0);
  EXPECT_NE(errorOf(nh).find("timeout must be positive"), std::string::npos);
}

TEST(Parameters, AValueOfTheWrongTypeIsRefused) {
  ros::NodeHandle nh("~wrong_type");
  nh.setParam("beams", "many");
  EXPECT_NE(errorOf(nh).find("'beams' must be an integer"), std::string::npos);
}

}  // namespace
}  // namespace wheelchair_ros

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_parameters");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
