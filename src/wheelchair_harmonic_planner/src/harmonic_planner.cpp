#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner/plan_failure.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace wheelchair_harmonic_planner {

using wheelchair_planner::finishPlan;

std::string HarmonicPlannerConfig::validate() const {
  wheelchair_core::ConfigChecks checks;
  try {
    solverMethodFromName(solver);
  } catch (const std::invalid_argument& e) {
    checks.check(false, e.what());
  }
  const HarmonicSolverParams& s = solver_params;
  checks.positive("tolerance", s.tolerance)
      .check(s.max_iterations >= 1, "max_iterations must be >= 1")
      .check(s.omega >= 0.0 && s.omega < 2.0, "omega must lie in [0, 2)")
      .check(s.sweeps_per_rescale >= 1, "sweeps_per_rescale must be >= 1");
  return checks.result();
}

void readHarmonicPlannerConfig(wheelchair_core::ConfigReader& reader,
                               HarmonicPlannerConfig& config) {
  reader.read("solver", config.solver);
  reader.read("tolerance", config.solver_params.tolerance);
  reader.read("max_iterations", config.solver_params.max_iterations);
  reader.read("omega", config.solver_params.omega);
  reader.read("sweeps_per_rescale", config.solver_params.sweeps_per_rescale);
  reader.read("prepare_on_map", config.prepare_on_map);
}

void HarmonicPlanner::configure(const PlannerSettings& settings,
                                wheelchair_core::ConfigReader& reader) {
  configure(settings, wheelchair_planner::readPluginConfig<HarmonicPlannerConfig>(
                          reader, readHarmonicPlannerConfig));
}

void HarmonicPlanner::configure(const PlannerSettings& settings,
                                const HarmonicPlannerConfig& config) {
  if (const std::string problem = config.validate(); !problem.empty())
    throw wheelchair_core::ConfigError("HarmonicPlanner: " + problem);
  settings_ = settings;
  config_ = config;
  config_.solver_params.method = solverMethodFromName(config.solver);
}

void HarmonicPlanner::setMap(const wheelchair_core::OccupancyMap& map) {
  factor_cache_.reset();  // its factors belong to the C-space replaced here
  map_.reset();
  map_ = std::make_unique<wheelchair_planner::PlanningMap>(map, settings_);
  map_geometry_ = map;
  map_geometry_.data.clear();
  solution_current_ = false;  // the previous solution stays as a warm start
  if (config_.prepare_on_map && !solution_)
    prepareHarmonicFactor(map_->cspace(), config_.solver_params, factor_cache_);
}

void HarmonicPlanner::updateMap(const wheelchair_core::OccupancyMap& map) {
  if (!map_ || map.width != map_geometry_.width || map.height != map_geometry_.height ||
      map.resolution != map_geometry_.resolution || map.origin_x != map_geometry_.origin_x ||
      map.origin_y != map_geometry_.origin_y || map.origin_yaw != map_geometry_.origin_yaw) {
    setMap(map);
    return;
  }
  const wheelchair_planner::ConfigSpaceChange change = map_->update(map);
  if (!change.rebuilt && change.cells.empty()) return;  // nothing the plan depends on changed
  updateHarmonicFactor(map_->cspace(), change, config_.solver_params, factor_cache_);
  solution_current_ = false;  // the previous solution stays as a warm start
}

bool HarmonicPlanner::makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                               Certificate& cert) {
  const auto t0 = std::chrono::steady_clock::now();
  plan.clear();
  cert = Certificate();
  cert.planner = "HarmonicPlanner";
  const auto finish = [&](bool ok) { return finishPlan(ok, t0, plan, cert); };
  int sx, sy, gx, gy;
  if (!wheelchair_planner::checkEndpoints(configSpace(), start, goal, sx, sy, gx, gy,
                                          cert.failure_reason)) {
    return finish(false);
  }
  const bool same_goal = solution_ && solution_->goal_ix == gx && solution_->goal_iy == gy;
  if (!(same_goal && solution_current_)) {
    // A new goal: the old field's storage is recycled (the factors for this map are cached).
    if (solution_ && !same_goal) factor_cache_.spare = std::move(solution_->log_u);
    HarmonicSolution next = solveHarmonic(map_->cspace(), gx, gy, config_.solver_params,
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
  DescentResult d = descend(map_->cspace(), *solution_, start.x, start.y, descent_params_);
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
  wheelchair_planner::assignHeadings(plan, goal.yaw);
  return finish(map_->gateFirstStagePath(settings_.gate, "harmonic",
                                         "internal error: descent path leaves the free C-space",
                                         start, goal, plan, cert));
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
