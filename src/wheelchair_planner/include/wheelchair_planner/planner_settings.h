// The typed settings the planner host hands every plugin: the chair's footprint (from its
// description file), the C-space and the footprint gate. Each plugin reads its own keys itself
// (global_planner.h); nothing travels as a string.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_planner/config_space.h>
#include <wheelchair_planner/footprint_gate.h>

#include <string>

namespace wheelchair_planner {

struct PlannerSettings {
  wheelchair_core::Polygon footprint;  ///< base_link polygon whose sweep every plan must clear
  ConfigSpaceParams cspace;
  FootprintGateParams gate;

  std::string validate() const;
};

/// The settings for a chair: its footprint polygon and, as the C-space's inscribed radius, its
/// half width (ChairParams::inscribedRadius()); everything else the structs' defaults.
PlannerSettings plannerSettings(const wheelchair_description::ChairParams& chair);

/// Keys: the C-space's (readConfigSpaceParams) and the gate's footprint_repair,
/// footprint_search_time, footprint_search_expansions (one budget for the whole search),
/// footprint_goal_tolerance, footprint_reverse, footprint_max_cusps,
/// footprint_max_reverse_length, footprint_reverse_cost, footprint_cusp_cost.
void readPlannerSettings(wheelchair_core::ConfigReader& reader, PlannerSettings& settings);

}  // namespace wheelchair_planner
