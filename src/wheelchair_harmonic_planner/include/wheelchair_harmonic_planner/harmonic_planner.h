// The harmonic-potential planner plugin (paper section 2.3, Algorithm 2).
#pragma once

#include <wheelchair_harmonic_planner/gradient_descent.h>
#include <wheelchair_harmonic_planner/harmonic_solver.h>
#include <wheelchair_planner/global_planner.h>
#include <wheelchair_planner/planning_map.h>

#include <memory>
#include <optional>
#include <string>

namespace wheelchair_harmonic_planner {

using wheelchair_planner::Certificate;
using wheelchair_planner::FootprintChecker;
using wheelchair_planner::PlannerSettings;

/// The plugin's own keys.
struct HarmonicPlannerConfig {
  std::string solver = "direct";       ///< "direct" (LDL^T, log-space solves) or "sor"
  HarmonicSolverParams solver_params;  ///< its `method` is set from `solver` by configure()
  /// Factor a new map in setMap() unless a goal is tracked (see HarmonicPlanner).
  bool prepare_on_map = true;

  std::string validate() const;
};

/// Keys: solver, tolerance, max_iterations, omega, sweeps_per_rescale, prepare_on_map.
void readHarmonicPlannerConfig(wheelchair_core::ConfigReader& reader,
                               HarmonicPlannerConfig& config);

/// Map-dependent work happens in setMap(): the C-space and, with the default direct solver,
/// the factors of the map's equation (`prepare_on_map`), so that a rider's first goal on a map
/// costs what every later goal costs (the solves, the descent and the footprint gate). Not when
/// a goal is already tracked (a map change during a drive): the host replans that goal at once,
/// and its earlier field is first checked on the new map (warm start, often no factorization).
class HarmonicPlanner : public wheelchair_planner::GlobalPlanner {
 public:
  void configure(const PlannerSettings& settings, wheelchair_core::ConfigReader& reader) override;
  /// The same with the plugin's configuration given (tests, the benchmark). Throws
  /// wheelchair_core::ConfigError if it is invalid.
  void configure(const PlannerSettings& settings, const HarmonicPlannerConfig& config);
  void setMap(const wheelchair_core::OccupancyMap& map) override;
  /// A map of the same grid with some cells changed: the C-space updated in a window around
  /// them and the direct solver's factors adapted (updateHarmonicFactor), no new factorization
  /// while only cells free in the factored map are blocked or freed again; another grid: setMap.
  void updateMap(const wheelchair_core::OccupancyMap& map) override;
  bool makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                Certificate& certificate) override;
  /// 100 * log u / (lowest finite log u): 0 at the goal, 100 at the farthest connected cell.
  bool potentialGrid(wheelchair_core::OccupancyMap& grid) const override;

  /// The last solved potential (log u), e.g. for publishing; null before the first plan.
  const HarmonicSolution* solution() const { return solution_ ? &*solution_ : nullptr; }
  const ConfigSpace* configSpace() const { return map_ ? &map_->cspace() : nullptr; }
  const FootprintChecker* footprintChecker() const { return map_ ? &map_->checker() : nullptr; }
  /// The direct solver's factors of the current map (factorizations counts them).
  const HarmonicFactorCache& factorCache() const { return factor_cache_; }

 private:
  PlannerSettings settings_;
  HarmonicPlannerConfig config_;
  std::unique_ptr<wheelchair_planner::PlanningMap> map_;
  wheelchair_core::OccupancyMap map_geometry_;  ///< the map without its cells
  DescentParams descent_params_;
  std::optional<HarmonicSolution> solution_;  ///< kept as warm start for the same goal cell
  HarmonicFactorCache factor_cache_;          ///< direct solver's factors for map_'s C-space
  bool solution_current_ = false;             ///< solved on the current map
};

}  // namespace wheelchair_harmonic_planner
