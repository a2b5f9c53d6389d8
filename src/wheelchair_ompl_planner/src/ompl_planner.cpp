#include <wheelchair_ompl_planner/ompl_planner.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner/plan_failure.h>

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace wheelchair_ompl_planner {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

const std::vector<std::string>& algorithms() {
  static const std::vector<std::string> names{"RRTConnect", "RRTstar", "PRMstar", "BITstar"};
  return names;
}

ob::PlannerPtr makeOmplPlanner(const std::string& type, const ob::SpaceInformationPtr& si) {
  if (type == "RRTConnect") return std::make_shared<og::RRTConnect>(si);
  if (type == "RRTstar") return std::make_shared<og::RRTstar>(si);
  if (type == "PRMstar") return std::make_shared<og::PRMstar>(si);
  if (type == "BITstar") return std::make_shared<og::BITstar>(si);
  throw std::invalid_argument("OmplPlanner: unknown algorithm '" + type + "'");
}

}  // namespace

std::string OmplPlannerConfig::validate() const {
  wheelchair_core::ConfigChecks checks;
  std::string known;
  for (const std::string& name : algorithms()) known += (known.empty() ? "" : ", ") + name;
  checks
      .check(std::find(algorithms().begin(), algorithms().end(), algorithm) != algorithms().end(),
             "unknown algorithm '" + algorithm + "' (" + known + ")")
      .positive("time_limit", time_limit)
      .check(seed >= 0, "seed must be >= 0");
  return checks.result();
}

void readOmplPlannerConfig(wheelchair_core::ConfigReader& reader, OmplPlannerConfig& config) {
  reader.read("algorithm", config.algorithm);
  reader.read("time_limit", config.time_limit);
  reader.read("simplify", config.simplify);
  reader.read("seed", config.seed);
}

void OmplPlanner::configure(const PlannerSettings& settings,
                            wheelchair_core::ConfigReader& reader) {
  configure(settings,
            wheelchair_planner::readPluginConfig<OmplPlannerConfig>(reader, readOmplPlannerConfig));
}

void OmplPlanner::configure(const PlannerSettings& settings, const OmplPlannerConfig& config) {
  if (const std::string problem = config.validate(); !problem.empty())
    throw wheelchair_core::ConfigError("OmplPlanner: " + problem);
  settings_ = settings;
  config_ = config;
  if (config.seed > 0) ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(config.seed));
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  // Made once here (fail now, not at the first goal). Its construction draws from OMPL's seed
  // sequence: without it a seeded run plans other paths (bench/planners' OMPL figures).
  makeOmplPlanner(config.algorithm, std::make_shared<ob::SpaceInformation>(
                                        std::make_shared<ob::RealVectorStateSpace>(2)));
}

void OmplPlanner::setMap(const wheelchair_core::OccupancyMap& map) {
  map_.reset();
  map_ = std::make_unique<wheelchair_planner::PlanningMap>(map, settings_);
}

bool OmplPlanner::makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                           Certificate& cert) {
  const auto t0 = std::chrono::steady_clock::now();
  plan.clear();
  cert = Certificate();
  cert.planner = "OmplPlanner/" + config_.algorithm;
  const auto finish = [&](bool ok) { return wheelchair_planner::finishPlan(ok, t0, plan, cert); };
  int sx, sy, gx, gy;
  if (!wheelchair_planner::checkEndpoints(map_ ? &map_->cspace() : nullptr, start, goal, sx, sy, gx,
                                          gy, cert.failure_reason)) {
    return finish(false);
  }
  const wheelchair_planner::ConfigSpace& cs = map_->cspace();
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
  ss.setPlanner(makeOmplPlanner(config_.algorithm, ss.getSpaceInformation()));
  const ob::PlannerStatus status = ss.solve(config_.time_limit);
  if (status != ob::PlannerStatus::EXACT_SOLUTION) {
    cert.failure_reason = "OMPL " + config_.algorithm + " found no exact solution in " +
                          std::to_string(config_.time_limit) + " s (" + status.asString() + ")";
    return finish(false);
  }
  if (config_.simplify) ss.simplifySolution(std::max(0.0, config_.time_limit * 0.2));
  og::PathGeometric path = ss.getSolutionPath();
  path.interpolate(std::max<unsigned>(2, static_cast<unsigned>(path.length() / cs.resolution())));
  for (size_t i = 0; i < path.getStateCount(); ++i) {
    const auto* v = path.getState(i)->as<ob::RealVectorStateSpace::StateType>();
    plan.push_back(Pose2D{v->values[0], v->values[1], 0.0});
  }
  plan.push_back(goal);
  wheelchair_planner::assignHeadings(plan, goal.yaw);
  return finish(map_->gateFirstStagePath(settings_.gate, "ompl",
                                         "OMPL path leaves the free C-space after post-processing",
                                         start, goal, plan, cert));
}

}  // namespace wheelchair_ompl_planner
