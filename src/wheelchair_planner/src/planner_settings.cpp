#include <wheelchair_planner/planner_settings.h>

namespace wheelchair_planner {

std::string PlannerSettings::validate() const {
  wheelchair_core::ConfigChecks checks;
  const std::string polygon = wheelchair_core::polygonProblem(footprint, true);
  checks.check(polygon.empty(), "footprint: " + polygon);
  const std::string cspace_problem = cspace.validate();
  checks.check(cspace_problem.empty(), cspace_problem);
  const std::string gate_problem = gate.validate();
  checks.check(gate_problem.empty(), gate_problem);
  return checks.result();
}

PlannerSettings plannerSettings(const wheelchair_description::ChairParams& chair) {
  PlannerSettings settings;
  settings.footprint = chair.footprint;
  settings.cspace.inscribed_radius = chair.inscribedRadius();
  return settings;
}

void readPlannerSettings(wheelchair_core::ConfigReader& reader, PlannerSettings& settings) {
  readConfigSpaceParams(reader, settings.cspace);
  reader.read("footprint_repair", settings.gate.repair);
  reader.read("footprint_search_time", settings.gate.search.time_limit);
  reader.read("footprint_goal_tolerance", settings.gate.search.goal_tolerance);
  reader.read("footprint_search_expansions", settings.gate.search.max_expansions);
  reader.read("footprint_reverse", settings.gate.search.reverse);
  reader.read("footprint_max_cusps", settings.gate.search.max_cusps);
  reader.read("footprint_max_reverse_length", settings.gate.search.max_reverse_length);
  reader.read("footprint_reverse_cost", settings.gate.search.reverse_cost);
  reader.read("footprint_cusp_cost", settings.gate.search.cusp_cost);
}

}  // namespace wheelchair_planner
