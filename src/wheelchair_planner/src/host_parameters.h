// Every private parameter of the planner host, read by its one loader: the host's own keys, the
// settings every plugin shares (with the footprint of ~chair_file) and the plugin's own keys,
// all through the same reader, so that the loader refuses any key nobody read.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/map_limits.h>
#include <wheelchair_description/chair_file.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_planner/global_planner.h>
#include <wheelchair_planner/planner_settings.h>

#include <exception>
#include <map>
#include <string>

namespace wheelchair_planner {

struct HostParameters {
  std::string planner = "wheelchair_harmonic_planner/HarmonicPlanner";  ///< pluginlib name
  /// The chair's description (its footprint): wheelchair_description's chair.yaml, found at run
  /// time.
  std::string chair_file = wheelchair_description::defaultChairFile();
  std::string map_frame = "map";
  std::string base_frame = "base_link";
  double max_pose_age = 0.5;              ///< [s] oldest tf map -> base_link a plan may start from
  wheelchair_core::MapLimits map_limits;  ///< a bigger or broken /map is refused

  std::string validate() const {
    wheelchair_core::ConfigChecks checks;
    checks.check(!planner.empty(), "planner must name a plugin")
        .check(!chair_file.empty(), "chair_file must name the chair's description file")
        .check(!map_frame.empty() && !base_frame.empty(), "map_frame and base_frame must be set")
        .positive("max_pose_age", max_pose_age)
        .check(map_limits.validate().empty(), map_limits.validate());
    return checks.result();
  }
};

/// Plugin names of before the planner split (issue 19) and what they are called now.
inline const std::map<std::string, std::string>& renamedPlanners() {
  static const std::map<std::string, std::string> renamed{
      {"wheelchair_harmonic_planner/OmplPlanner", "wheelchair_ompl_planner/OmplPlanner"}};
  return renamed;
}

/// Keys: planner (an old plugin name is refused with the new one), chair_file (was
/// chair_params), map_frame, base_frame, max_pose_age, max_map_cells.
inline void readHostParameters(wheelchair_core::ConfigReader& reader, HostParameters& p) {
  reader.renamed("chair_params", "chair_file");
  reader.read("planner", p.planner);
  reader.read("chair_file", p.chair_file);
  reader.read("map_frame", p.map_frame);
  reader.read("base_frame", p.base_frame);
  reader.read("max_pose_age", p.max_pose_age);
  wheelchair_core::readMapLimits(reader, p.map_limits);
  const auto renamed = renamedPlanners().find(p.planner);
  if (renamed != renamedPlanners().end()) {
    throw wheelchair_core::ConfigError(reader.source().where() + ": planner '" + p.planner +
                                       "' is now called '" + renamed->second + "'");
  }
}

/// Everything the host's loader reads.
struct HostSetup {
  HostParameters host;
  PlannerSettings settings;  ///< handed to the plugin (validated)
  std::string validate() const { return host.validate(); }
};

/// The loader's reading: the host's keys, the chair's footprint and the shared settings, then
/// `create(planner name)` (a pointer to a new plugin, throwing ConfigError if it cannot) and the
/// plugin's configure(), which reads its own keys. Returns the configured plugin.
template <typename Create>
auto readHostSetup(wheelchair_core::ConfigReader& reader, HostSetup& s, Create&& create) {
  const std::string where = reader.source().where() + ": ";
  readHostParameters(reader, s.host);
  try {
    s.settings = plannerSettings(wheelchair_description::loadChairParams(s.host.chair_file));
  } catch (const std::exception& e) {
    throw wheelchair_core::ConfigError(where + "chair_file: " + e.what());
  }
  readPlannerSettings(reader, s.settings);
  if (const std::string problem = s.settings.validate(); !problem.empty())
    throw wheelchair_core::ConfigError(where + problem);
  auto planner = create(s.host.planner);
  planner->configure(s.settings, reader);
  return planner;
}

}  // namespace wheelchair_planner
