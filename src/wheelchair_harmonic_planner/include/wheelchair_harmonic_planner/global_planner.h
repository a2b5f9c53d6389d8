// The global-planner plugin interface (nav_core::BaseGlobalPlanner's shape; nav_core is not in
// Debian). ROS-free: parameters arrive as strings, the map as an OccupancyMap.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_harmonic_planner/plan_types.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace wheelchair_harmonic_planner {

/// Planner parameters by name (the host fills it from the plugin's private ROS parameters).
using ParameterMap = std::map<std::string, std::string>;

/// Reads a number; `fallback` if absent; throws std::invalid_argument if present but not finite.
double getParam(const ParameterMap& params, const std::string& name, double fallback);
std::string getParam(const ParameterMap& params, const std::string& name,
                     const std::string& fallback);
bool getParam(const ParameterMap& params, const std::string& name, bool fallback);

class GlobalPlanner {
 public:
  virtual ~GlobalPlanner() = default;

  /// Called once after construction (pluginlib needs a default constructor), and again with a
  /// new map whenever the map changes. Throws std::invalid_argument on bad parameters.
  virtual void initialize(const std::string& name, const wheelchair_core::OccupancyMap& map,
                          const ParameterMap& params) = 0;

  /// Plans from start to goal (map frame). On success `plan` runs from start to goal with
  /// headings; on failure it is empty and certificate.failure_reason says why. The certificate
  /// is filled in both cases.
  virtual bool makePlan(const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                        Certificate& certificate) = 0;

  /// The potential field of the last plan as a grid on the map's cells, scaled 0 (goal) to 100
  /// (highest potential), -1 where undefined (obstacles, not connected), for rviz. False if the
  /// planner has none (sampling planners) or has not planned yet.
  virtual bool potentialGrid(wheelchair_core::OccupancyMap& /*grid*/) const { return false; }

 protected:
  GlobalPlanner() = default;
};

/// Closes a makePlan call of any planner: records success and the time since `started`; a
/// failed plan is left empty. Returns `ok`.
inline bool finishPlan(bool ok, std::chrono::steady_clock::time_point started,
                       std::vector<Pose2D>& plan, Certificate& cert) {
  cert.success = ok;
  cert.planning_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!ok) plan.clear();
  return ok;
}

}  // namespace wheelchair_harmonic_planner
