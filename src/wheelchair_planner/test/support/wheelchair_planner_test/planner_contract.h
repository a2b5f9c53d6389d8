// What every planner plugin must do, as gtest assertions shared by the plugins' tests (test
// support, header only: include it from a gtest).
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_planner/global_planner.h>
#include <wheelchair_planner_test/maze.h>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <vector>

namespace wheelchair_planner {

/// A configured plugin on a 6 m x 1.2 m corridor closed by a wall at x = 3 m: a goal in an
/// obstacle, a start outside the map, a goal beyond the wall and a non-finite goal each fail
/// with an empty plan and a reason that names the cause.
inline void expectClearFailuresForBadStartsAndGoals(GlobalPlanner& planner) {
  auto map = makeCorridor(6.0, 1.2, 0.05);
  for (int iy = 0; iy < map.height; ++iy) map.at(60, iy) = wheelchair_core::kOccupied;
  planner.setMap(map);
  std::vector<Pose2D> plan;
  Certificate cert;
  const Pose2D ok{1.0, 0.7, 0.0};
  EXPECT_FALSE(planner.makePlan(ok, {3.02, 0.7, 0.0}, plan, cert));
  EXPECT_NE(cert.failure_reason.find("goal"), std::string::npos) << cert.failure_reason;
  EXPECT_NE(cert.failure_reason.find("obstacle"), std::string::npos) << cert.failure_reason;
  EXPECT_TRUE(plan.empty());
  EXPECT_FALSE(planner.makePlan({-1.0, 0.7, 0.0}, ok, plan, cert));
  EXPECT_NE(cert.failure_reason.find("outside the map"), std::string::npos);
  EXPECT_FALSE(planner.makePlan(ok, {5.0, 0.7, 0.0}, plan, cert));  // beyond the wall
  EXPECT_FALSE(cert.failure_reason.empty());
  EXPECT_TRUE(plan.empty());
  EXPECT_FALSE(planner.makePlan(ok, {NAN, 0.7, 0.0}, plan, cert));
  EXPECT_NE(cert.failure_reason.find("not finite"), std::string::npos);
}

/// Configures `planner` from the keys of a YAML mapping as the host does (the plugin reads its
/// keys, then any key nobody read is refused): empty if accepted, else the ConfigError's text.
inline std::string configureRefusal(GlobalPlanner& planner, const PlannerSettings& settings,
                                    const std::string& yaml) {
  const wheelchair_core::YamlParameterSource source(YAML::Load(yaml), "test");
  wheelchair_core::ConfigReader reader(source);
  try {
    planner.configure(settings, reader);
    reader.rejectUnknown();
  } catch (const wheelchair_core::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace wheelchair_planner
