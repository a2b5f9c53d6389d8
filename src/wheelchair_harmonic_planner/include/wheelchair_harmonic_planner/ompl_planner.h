// A sampling-based planner plugin on the same hard C-space as the harmonic planner, for
// comparison: OMPL's RRTConnect, RRT*, PRM* or BIT* (parameter `algorithm`), with a time limit
// and OMPL's path simplification.
#pragma once

#include <wheelchair_harmonic_planner/config_space.h>
#include <wheelchair_harmonic_planner/footprint_planning.h>
#include <wheelchair_harmonic_planner/global_planner.h>

#include <memory>

namespace wheelchair_harmonic_planner {

class OmplPlanner : public GlobalPlanner {
 public:
  /// Parameters: algorithm (RRTConnect | RRTstar | PRMstar | BITstar), time_limit [s],
  /// simplify (bool), seed (> 0: OMPL's global seed; effective only before the process's first
  /// OMPL plan), plus the C-space parameters of configSpaceParams().
  void initialize(const std::string& name, const wheelchair_core::OccupancyMap& map,
                  const ParameterMap& params) override;
  bool makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                Certificate& certificate) override;

 private:
  std::string name_;
  std::string planner_type_ = "RRTConnect";
  double time_limit_ = 1.0;
  bool simplify_ = true;
  std::unique_ptr<ConfigSpace> cspace_;
  FootprintPlanningParams footprint_params_;
  std::unique_ptr<FootprintChecker> checker_;  ///< on cspace_
};

}  // namespace wheelchair_harmonic_planner
