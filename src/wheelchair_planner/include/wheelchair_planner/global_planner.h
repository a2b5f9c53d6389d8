// The global-planner plugin interface (nav2's nav2_core::GlobalPlanner cut; nav2 and nav_core
// are not in Debian): the host configures a plugin once with typed settings and the plugin's own
// keys, hands it each new map, and asks for plans. ROS-free; exported with pluginlib as
// `<wheelchair_planner plugin="...">` in a plugin package's package.xml.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_planner/certificate.h>
#include <wheelchair_planner/planner_settings.h>

#include <chrono>
#include <string>
#include <vector>

namespace wheelchair_planner {

class GlobalPlanner {
 public:
  virtual ~GlobalPlanner() = default;

  /// Once, before the first map (pluginlib needs a default constructor): the settings every
  /// plugin shares (validated) and the plugin's own keys, read through `reader` (the host's
  /// private parameters; the host then refuses any key that neither it nor the plugin read).
  /// Throws wheelchair_core::ConfigError on an invalid value.
  virtual void configure(const PlannerSettings& settings,
                         wheelchair_core::ConfigReader& reader) = 0;

  /// Whenever the map changes, the first time before the first plan. Throws
  /// std::invalid_argument on a map it cannot use.
  virtual void setMap(const wheelchair_core::OccupancyMap& map) = 0;

  /// The map after a small change of its cells (the live obstacle layer over the static map:
  /// same grid, some cells blocked or freed again), between plans. A plugin with a faster
  /// map-change path overrides it (the harmonic plugin adapts its C-space and factorization in
  /// place); by default it is setMap(). Throws like setMap().
  virtual void updateMap(const wheelchair_core::OccupancyMap& map) { setMap(map); }

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

/// A plugin's own configuration from the host's reader: `read(reader, config)` names its keys,
/// then config.validate(); throws wheelchair_core::ConfigError naming the source and problem.
template <typename Config, typename ReadKeys>
Config readPluginConfig(wheelchair_core::ConfigReader& reader, ReadKeys&& read) {
  Config config;
  read(reader, config);
  const std::string problem = config.validate();
  if (!problem.empty())
    throw wheelchair_core::ConfigError(reader.source().where() + ": " + problem);
  return config;
}

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

}  // namespace wheelchair_planner
