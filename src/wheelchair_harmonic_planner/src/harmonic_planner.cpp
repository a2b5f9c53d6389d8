#include <wheelchair_harmonic_planner/footprint_planning.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_harmonic_planner/path_metrics.h>
#include <wheelchair_harmonic_planner/plan_failure.h>

#include <pluginlib/class_list_macros.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace wheelchair_harmonic_planner {

ConfigSpaceParams configSpaceParams(const ParameterMap& params) {
  ConfigSpaceParams p;
  p.inscribed_radius = getParam(params, "inscribed_radius", p.inscribed_radius);
  p.min_clearance = getParam(params, "min_clearance", p.min_clearance);
  p.clearance_band = getParam(params, "clearance_band", p.clearance_band);
  p.band_conductance = getParam(params, "band_conductance", p.band_conductance);
  p.unknown_is_obstacle = getParam(params, "unknown_is_obstacle", p.unknown_is_obstacle);
  validate(p);
  return p;
}

void HarmonicPlanner::initialize(const std::string& name, const wheelchair_core::OccupancyMap& map,
                                 const ParameterMap& params) {
  name_ = name;
  HarmonicSolverParams s;
  s.tolerance = getParam(params, "tolerance", s.tolerance);
  s.max_iterations = static_cast<int>(getParam(params, "max_iterations", 1.0 * s.max_iterations));
  s.omega = getParam(params, "omega", s.omega);
  s.sweeps_per_rescale =
      static_cast<int>(getParam(params, "sweeps_per_rescale", 1.0 * s.sweeps_per_rescale));
  if (!(s.tolerance > 0.0) || s.max_iterations < 1 || s.omega < 0.0 || s.omega >= 2.0) {
    throw std::invalid_argument(
        "HarmonicPlanner: tolerance > 0, max_iterations >= 1 and "
        "omega in [0, 2) are required");
  }
  s.method = solverMethodFromName(getParam(params, "solver", std::string("direct")));
  if (s.method == HarmonicSolverParams::Method::kMultigrid && params.count("max_iterations") == 0) {
    s.max_iterations = 2000;  // V-cycles
  }
  solver_params_ = s;
  prepare_on_map_ = getParam(params, "prepare_on_map", true);
  const ConfigSpaceParams cspace_params = configSpaceParams(params);
  footprint_params_ = footprintPlanningParams(params, cspace_params);
  checker_.reset();
  factor_cache_.reset();  // its factors belong to the C-space replaced here
  cspace_ = std::make_unique<ConfigSpace>(map, cspace_params);
  checker_ = std::make_unique<FootprintChecker>(*cspace_, footprint_params_.footprint);
  map_geometry_ = map;
  map_geometry_.data.clear();
  solution_current_ = false;  // the previous solution stays as a warm start
  if (prepare_on_map_ && !solution_) prepareHarmonicFactor(*cspace_, solver_params_, factor_cache_);
}

bool HarmonicPlanner::makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                               Certificate& cert) {
  const auto t0 = std::chrono::steady_clock::now();
  plan.clear();
  cert = Certificate();
  cert.planner = "HarmonicPlanner";
  const auto finish = [&](bool ok) { return finishPlan(ok, t0, plan, cert); };
  int sx, sy, gx, gy;
  if (!checkEndpoints(cspace_.get(), start, goal, sx, sy, gx, gy, cert.failure_reason)) {
    return finish(false);
  }
  const bool same_goal = solution_ && solution_->goal_ix == gx && solution_->goal_iy == gy;
  if (!(same_goal && solution_current_)) {
    // A new goal: the old field's storage is recycled (the factors for this map are cached).
    if (solution_ && !same_goal) factor_cache_.spare = std::move(solution_->log_u);
    HarmonicSolution next = solveHarmonic(*cspace_, gx, gy, solver_params_,
                                          same_goal ? &*solution_ : nullptr, &factor_cache_);
    solution_ = std::move(next);
    solution_current_ = true;
  }
  cert.solver_iterations = solution_->iterations;
  cert.solver_residual = solution_->residual;
  cert.solver_converged = solution_->converged;
  cert.warm_started = solution_->warm_started;
  if (!solution_->converged) {
    cert.failure_reason = "harmonic solver did not converge (residual " +
                          std::to_string(solution_->residual) + " after " +
                          std::to_string(solution_->iterations) + " sweeps)";
    solution_current_ = false;
    return finish(false);
  }
  if (!solution_->reachable(sx, sy)) {
    cert.failure_reason = "start and goal are not connected in the configuration space";
    return finish(false);
  }
  DescentResult d = descend(*cspace_, *solution_, start.x, start.y, descent_params_);
  cert.descent_reached_goal = d.reached_goal;
  cert.plateau_steps = d.fallback_steps;
  cert.min_gradient = d.min_gradient;
  if (!d.reached_goal) {
    cert.failure_reason = d.failure_reason;
    return finish(false);
  }
  plan = std::move(d.path);
  plan.front().x = start.x;
  plan.front().y = start.y;
  plan.push_back(goal);
  assignHeadings(plan, goal.yaw);
  if (!pathIsCollisionFree(*cspace_, plan)) {
    cert.failure_reason = "internal error: descent path leaves the free C-space";
    return finish(false);
  }
  cert.path_stage = "harmonic";
  const bool ok = enforceFootprint(*checker_, footprint_params_, start, goal, plan, cert);
  fillPathFigures(*cspace_, plan, cert);
  return finish(ok);
}

bool HarmonicPlanner::potentialGrid(wheelchair_core::OccupancyMap& grid) const {
  if (!solution_ || solution_->width != map_geometry_.width ||
      solution_->height != map_geometry_.height) {
    return false;
  }
  grid = map_geometry_;
  double lowest = 0.0;
  for (const double l : solution_->log_u)
    if (std::isfinite(l)) lowest = std::min(lowest, l);
  grid.data.resize(solution_->log_u.size());
  for (size_t k = 0; k < grid.data.size(); ++k) {
    const double l = solution_->log_u[k];
    grid.data[k] = !std::isfinite(l) ? int8_t{-1}
                   : lowest < 0.0    ? static_cast<int8_t>(std::lround(100.0 * l / lowest))
                                     : int8_t{0};
  }
  return true;
}

}  // namespace wheelchair_harmonic_planner

PLUGINLIB_EXPORT_CLASS(wheelchair_harmonic_planner::HarmonicPlanner,
                       wheelchair_harmonic_planner::GlobalPlanner)
