#include <wheelchair_harmonic_planner/footprint_planning.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_harmonic_planner/ompl_planner.h>
#include <wheelchair_harmonic_planner/path_metrics.h>
#include <wheelchair_harmonic_planner/plan_failure.h>

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <pluginlib/class_list_macros.hpp>

#include <chrono>
#include <cmath>

namespace wheelchair_harmonic_planner {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

ob::PlannerPtr makeOmplPlanner(const std::string& type, const ob::SpaceInformationPtr& si) {
  if (type == "RRTConnect") return std::make_shared<og::RRTConnect>(si);
  if (type == "RRTstar") return std::make_shared<og::RRTstar>(si);
  if (type == "PRMstar") return std::make_shared<og::PRMstar>(si);
  if (type == "BITstar") return std::make_shared<og::BITstar>(si);
  throw std::invalid_argument("OmplPlanner: unknown algorithm '" + type +
                              "' (RRTConnect, RRTstar, PRMstar, BITstar)");
}

}  // namespace

void OmplPlanner::initialize(const std::string& name, const wheelchair_core::OccupancyMap& map,
                             const ParameterMap& params) {
  name_ = name;
  planner_type_ = getParam(params, "algorithm", planner_type_);
  time_limit_ = getParam(params, "time_limit", time_limit_);
  simplify_ = getParam(params, "simplify", simplify_);
  if (!(time_limit_ > 0.0)) throw std::invalid_argument("OmplPlanner: time_limit must be > 0");
  const double seed = getParam(params, "seed", 0.0);
  if (seed > 0.0) ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  const ConfigSpaceParams cspace_params = configSpaceParams(params);
  footprint_params_ = footprintPlanningParams(params, cspace_params);
  checker_.reset();
  cspace_ = std::make_unique<ConfigSpace>(map, cspace_params);
  checker_ = std::make_unique<FootprintChecker>(*cspace_, footprint_params_.footprint);
  // Fail now, not at the first goal, if the planner name is wrong.
  makeOmplPlanner(planner_type_, std::make_shared<ob::SpaceInformation>(
                                     std::make_shared<ob::RealVectorStateSpace>(2)));
}

bool OmplPlanner::makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                           Certificate& cert) {
  const auto t0 = std::chrono::steady_clock::now();
  plan.clear();
  cert = Certificate();
  cert.planner = "OmplPlanner/" + planner_type_;
  const auto finish = [&](bool ok) { return finishPlan(ok, t0, plan, cert); };
  int sx, sy, gx, gy;
  if (!checkEndpoints(cspace_.get(), start, goal, sx, sy, gx, gy, cert.failure_reason)) {
    return finish(false);
  }
  const ConfigSpace& cs = *cspace_;
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  double x0, y0, x1, y1;
  cs.gridToWorld(-0.5, -0.5, x0, y0);
  cs.gridToWorld(cs.width() - 0.5, cs.height() - 0.5, x1, y1);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, x0);
  bounds.setHigh(0, x1);
  bounds.setLow(1, y0);
  bounds.setHigh(1, y1);
  space->setBounds(bounds);
  og::SimpleSetup ss(space);
  ss.setStateValidityChecker([&cs](const ob::State* s) {
    const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
    int ix, iy;
    return cs.worldToCell(v->values[0], v->values[1], ix, iy) && cs.isFree(ix, iy);
  });
  // Check motions every quarter cell.
  ss.getSpaceInformation()->setStateValidityCheckingResolution(0.25 * cs.resolution() /
                                                               space->getMaximumExtent());
  ob::ScopedState<> s(space), g(space);
  s[0] = start.x;
  s[1] = start.y;
  g[0] = goal.x;
  g[1] = goal.y;
  ss.setStartAndGoalStates(s, g, 0.5 * cs.resolution());
  ss.getProblemDefinition()->setOptimizationObjective(
      std::make_shared<ob::PathLengthOptimizationObjective>(ss.getSpaceInformation()));
  ss.setPlanner(makeOmplPlanner(planner_type_, ss.getSpaceInformation()));
  const ob::PlannerStatus status = ss.solve(time_limit_);
  if (status != ob::PlannerStatus::EXACT_SOLUTION) {
    cert.failure_reason = "OMPL " + planner_type_ + " found no exact solution in " +
                          std::to_string(time_limit_) + " s (" + status.asString() + ")";
    return finish(false);
  }
  if (simplify_) ss.simplifySolution(std::max(0.0, time_limit_ * 0.2));
  og::PathGeometric path = ss.getSolutionPath();
  path.interpolate(std::max<unsigned>(2, static_cast<unsigned>(path.length() / cs.resolution())));
  for (size_t i = 0; i < path.getStateCount(); ++i) {
    const auto* v = path.getState(i)->as<ob::RealVectorStateSpace::StateType>();
    plan.push_back(Pose2D{v->values[0], v->values[1], 0.0});
  }
  plan.push_back(goal);
  assignHeadings(plan, goal.yaw);
  if (!pathIsCollisionFree(cs, plan)) {
    cert.failure_reason = "OMPL path leaves the free C-space after post-processing";
    return finish(false);
  }
  cert.path_stage = "ompl";
  const bool ok = enforceFootprint(*checker_, footprint_params_, start, goal, plan, cert);
  fillPathFigures(cs, plan, cert);
  return finish(ok);
}

}  // namespace wheelchair_harmonic_planner

PLUGINLIB_EXPORT_CLASS(wheelchair_harmonic_planner::OmplPlanner,
                       wheelchair_harmonic_planner::GlobalPlanner)
