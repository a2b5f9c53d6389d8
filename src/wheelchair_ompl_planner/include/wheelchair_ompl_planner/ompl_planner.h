// A sampling-based planner plugin on the same hard C-space as the harmonic planner, for
// comparison: OMPL's RRTConnect, RRT*, PRM* or BIT* (parameter `algorithm`), with a time limit
// and OMPL's path simplification; its plans pass the same footprint gate.
#pragma once

#include <wheelchair_planner/global_planner.h>
#include <wheelchair_planner/planning_map.h>

#include <memory>
#include <string>

namespace wheelchair_ompl_planner {

using wheelchair_planner::Certificate;
using wheelchair_planner::PlannerSettings;
using wheelchair_planner::Pose2D;

/// The plugin's own keys.
struct OmplPlannerConfig {
  std::string algorithm = "RRTConnect";  ///< RRTConnect | RRTstar | PRMstar | BITstar
  double time_limit = 1.0;               ///< [s] of OMPL's solve
  bool simplify = true;                  ///< OMPL's path simplification
  /// > 0: OMPL's global seed; effective only before the process's first OMPL plan.
  int seed = 0;

  std::string validate() const;
};

/// Keys: algorithm, time_limit, simplify, seed.
void readOmplPlannerConfig(wheelchair_core::ConfigReader& reader, OmplPlannerConfig& config);

class OmplPlanner : public wheelchair_planner::GlobalPlanner {
 public:
  void configure(const PlannerSettings& settings, wheelchair_core::ConfigReader& reader) override;
  /// The same with the plugin's configuration given (tests, the benchmark). Throws
  /// wheelchair_core::ConfigError if it is invalid.
  void configure(const PlannerSettings& settings, const OmplPlannerConfig& config);
  void setMap(const wheelchair_core::OccupancyMap& map) override;
  bool makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                Certificate& certificate) override;

 private:
  PlannerSettings settings_;
  OmplPlannerConfig config_;
  std::unique_ptr<wheelchair_planner::PlanningMap> map_;
};

}  // namespace wheelchair_ompl_planner
