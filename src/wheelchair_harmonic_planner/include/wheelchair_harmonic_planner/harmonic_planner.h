// The harmonic-potential planner plugin (paper section 2.3, Algorithm 2).
#pragma once

#include <wheelchair_harmonic_planner/config_space.h>
#include <wheelchair_harmonic_planner/footprint_planning.h>
#include <wheelchair_harmonic_planner/global_planner.h>
#include <wheelchair_harmonic_planner/gradient_descent.h>
#include <wheelchair_harmonic_planner/harmonic_solver.h>

#include <memory>
#include <optional>

namespace wheelchair_harmonic_planner {

/// Reads inscribed_radius, min_clearance, clearance_band, band_conductance,
/// unknown_is_obstacle from the parameters (defaults: ConfigSpaceParams()).
ConfigSpaceParams configSpaceParams(const ParameterMap& params);

/// Map-dependent work happens in initialize(): the C-space and, with the default direct solver,
/// the factors of the map's equation (`prepare_on_map`), so that a rider's first goal on a map
/// costs what every later goal costs (the solves, the descent and the footprint gate). Not when
/// a goal is already tracked (a map change during a drive): the host replans that goal at once,
/// and its earlier field is first checked on the new map (warm start, often no factorization).
class HarmonicPlanner : public GlobalPlanner {
 public:
  void initialize(const std::string& name, const wheelchair_core::OccupancyMap& map,
                  const ParameterMap& params) override;
  bool makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                Certificate& certificate) override;
  /// 100 * log u / (lowest finite log u): 0 at the goal, 100 at the farthest connected cell.
  bool potentialGrid(wheelchair_core::OccupancyMap& grid) const override;

  /// The last solved potential (log u), e.g. for publishing; null before the first plan.
  const HarmonicSolution* solution() const { return solution_ ? &*solution_ : nullptr; }
  const ConfigSpace* configSpace() const { return cspace_.get(); }
  const FootprintChecker* footprintChecker() const { return checker_.get(); }
  /// The direct solver's factors of the current map (factorizations counts them).
  const HarmonicFactorCache& factorCache() const { return factor_cache_; }

 private:
  std::string name_;
  std::unique_ptr<ConfigSpace> cspace_;
  FootprintPlanningParams footprint_params_;
  std::unique_ptr<FootprintChecker> checker_;   ///< on cspace_
  wheelchair_core::OccupancyMap map_geometry_;  ///< the map without its cells
  HarmonicSolverParams solver_params_;
  DescentParams descent_params_;
  std::optional<HarmonicSolution> solution_;  ///< kept as warm start for the same goal cell
  HarmonicFactorCache factor_cache_;          ///< direct solver's factors for cspace_
  bool solution_current_ = false;             ///< solved on the current map
  /// `prepare_on_map` (default true): factor a new map in initialize() unless a goal is tracked.
  bool prepare_on_map_ = true;
};

}  // namespace wheelchair_harmonic_planner
