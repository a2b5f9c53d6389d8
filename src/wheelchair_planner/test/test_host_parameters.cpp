// The planner host's one loader (readHostSetup) on a YAML file as on its private namespace: the
// host's keys, the shared settings with the chair file's footprint, the plugin's own keys read by
// the plugin, anything else refused; the old names refused with the new ones.
#include "../src/host_parameters.h"

#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>

using namespace wheelchair_planner;
using wheelchair_core::ConfigError;

namespace {

/// A plugin with one key of its own.
class FakePlanner : public GlobalPlanner {
 public:
  void configure(const PlannerSettings& settings, wheelchair_core::ConfigReader& reader) override {
    settings_ = settings;
    reader.read("fake_speed", speed_);
  }
  void setMap(const wheelchair_core::OccupancyMap&) override {}
  bool makePlan(const Pose2D&, const Pose2D&, std::vector<Pose2D>&, Certificate&) override {
    return false;
  }
  PlannerSettings settings_;
  double speed_ = 1.0;
};

struct Loaded {
  HostSetup setup;
  std::shared_ptr<FakePlanner> planner;
  std::string created;
};

Loaded load(const std::string& yaml) {
  const wheelchair_core::YamlParameterSource source(YAML::Load(yaml), "test");
  Loaded out;
  out.setup = wheelchair_core::loadConfig<HostSetup>(
      source, [&](wheelchair_core::ConfigReader& reader, HostSetup& s) {
        out.planner = readHostSetup(reader, s, [&](const std::string& name) {
          out.created = name;
          return std::make_shared<FakePlanner>();
        });
      });
  return out;
}

std::string refusal(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

const std::string kChairFile = wheelchair_description::test::chairFile();

}  // namespace

TEST(HostParameters, TheChairFilesFootprintAndEveryKeyReachTheirFields) {
  const Loaded l = load("{planner: fake/Planner, chair_file: " + kChairFile +
                        ", map_frame: world, base_frame: base, max_pose_age: 0.8,"
                        " min_clearance: 0.06, clearance_band: 0.25, band_conductance: 0.1,"
                        " unknown_is_obstacle: false, footprint_repair: false,"
                        " footprint_search_time: 10.0, footprint_goal_tolerance: 0.2,"
                        " footprint_search_expansions: 5000, footprint_reverse: false,"
                        " footprint_max_cusps: 2, footprint_max_reverse_length: 4.0,"
                        " footprint_reverse_cost: 3.0, footprint_cusp_cost: 1.5,"
                        " fake_speed: 2.5}");
  EXPECT_EQ(l.created, "fake/Planner");
  EXPECT_EQ(l.setup.host.map_frame, "world");
  EXPECT_EQ(l.setup.host.base_frame, "base");
  EXPECT_DOUBLE_EQ(l.setup.host.max_pose_age, 0.8);
  const PlannerSettings& s = l.planner->settings_;
  const auto chair = wheelchair_description::loadChairParams(kChairFile);
  EXPECT_EQ(s.footprint, chair.footprint);
  EXPECT_DOUBLE_EQ(s.cspace.inscribed_radius, chair.inscribedRadius());
  EXPECT_DOUBLE_EQ(s.cspace.min_clearance, 0.06);
  EXPECT_DOUBLE_EQ(s.cspace.clearance_band, 0.25);
  EXPECT_DOUBLE_EQ(s.cspace.band_conductance, 0.1);
  EXPECT_FALSE(s.cspace.unknown_is_obstacle);
  EXPECT_FALSE(s.gate.repair);
  EXPECT_DOUBLE_EQ(s.gate.search.time_limit, 10.0);
  EXPECT_DOUBLE_EQ(s.gate.search.goal_tolerance, 0.2);
  EXPECT_EQ(s.gate.search.max_expansions, 5000);
  EXPECT_FALSE(s.gate.search.reverse);
  EXPECT_EQ(s.gate.search.max_cusps, 2);
  EXPECT_DOUBLE_EQ(s.gate.search.max_reverse_length, 4.0);
  EXPECT_DOUBLE_EQ(s.gate.search.reverse_cost, 3.0);
  EXPECT_DOUBLE_EQ(s.gate.search.cusp_cost, 1.5);
  EXPECT_DOUBLE_EQ(l.planner->speed_, 2.5) << "the plugin read its own key";
}

TEST(HostParameters, DefaultsLoadTheHarmonicPlannerWithTheChairsHalfWidth) {
  const Loaded l = load("{chair_file: " + kChairFile + "}");
  EXPECT_EQ(l.created, "wheelchair_harmonic_planner/HarmonicPlanner");
  EXPECT_DOUBLE_EQ(l.planner->settings_.cspace.inscribed_radius, 0.31);
  const Loaded overridden = load("{chair_file: " + kChairFile + ", inscribed_radius: 0.35}");
  EXPECT_DOUBLE_EQ(overridden.planner->settings_.cspace.inscribed_radius, 0.35);
}

TEST(HostParameters, RefusesAKeyNobodyReadsOldNamesAndInvalidValues) {
  const std::string unknown = refusal("{chair_file: " + kChairFile + ", footprint_serch_time: 3}");
  EXPECT_NE(unknown.find("unknown parameter 'footprint_serch_time'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("fake_speed"), std::string::npos) << "the plugin's keys are known too";
  EXPECT_NE(refusal("{chair_params: " + kChairFile + "}").find("now called 'chair_file'"),
            std::string::npos);
  const std::string old_plugin =
      refusal("{chair_file: " + kChairFile + ", planner: wheelchair_harmonic_planner/OmplPlanner}");
  EXPECT_NE(old_plugin.find("now called 'wheelchair_ompl_planner/OmplPlanner'"), std::string::npos)
      << old_plugin;
  EXPECT_NE(refusal("{chair_file: /nonexistent/chair.yaml}").find("chair_file"), std::string::npos);
  EXPECT_NE(refusal("{chair_file: " + kChairFile + ", footprint_reverse_cost: 0.5}")
                .find("footprint_reverse_cost must be >= 1"),
            std::string::npos);
  EXPECT_NE(refusal("{chair_file: " + kChairFile + ", footprint_search_time: 0}")
                .find("footprint_search_time must be positive"),
            std::string::npos);
  EXPECT_NE(refusal("{chair_file: " + kChairFile + ", max_pose_age: -1}").find("max_pose_age"),
            std::string::npos);
  EXPECT_NE(
      refusal("{chair_file: " + kChairFile + ", band_conductance: 0}").find("band_conductance"),
      std::string::npos);
}
