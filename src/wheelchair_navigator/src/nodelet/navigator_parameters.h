// Every private parameter of the navigator nodelet, read by its one loader: the core's
// NavigatorConfig and the nodelet's own (frames, files, rate, the planner's service, the
// controller's status topic).
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_navigator/navigator_config.h>

#include <string>

namespace wheelchair_navigator {

struct NavigatorParameters {
  NavigatorConfig navigator;
  std::string map_frame = "map";
  std::string base_frame = "base_link";
  /// The chair's description (its footprint, for the goal check): "" = wheelchair_description's
  /// chair.yaml, found at run time.
  std::string chair_file;
  /// Named places of the map ({name, room, x, y, yaw}, as the HMI's): "" = no named goals.
  std::string places_file;
  double rate = 10.0;  ///< [Hz] pose, timeouts, feedback
  std::string planner_service = "planner/make_plan";
  std::string controller_path_status = "controller/path_status";

  std::string validate() const {
    const std::string core = navigator.validate();
    wheelchair_core::ConfigChecks checks;
    checks.check(core.empty(), core)
        .check(!map_frame.empty() && !base_frame.empty(), "map_frame and base_frame must be set")
        .positive("rate", rate)
        .check(!planner_service.empty(), "planner_service must name the planner's service")
        .check(!controller_path_status.empty(), "controller_path_status must name a topic");
    return checks.result();
  }
};

/// The keys: NavigatorConfig's, map_frame (was global_frame), base_frame, chair_file (was
/// chair_params), places_file, rate, planner_service, controller_path_status.
inline void readNavigatorParameters(wheelchair_core::ConfigReader& reader, NavigatorParameters& p) {
  readNavigatorConfig(reader, p.navigator);
  reader.renamed("global_frame", "map_frame");
  reader.renamed("chair_params", "chair_file");
  reader.read("map_frame", p.map_frame);
  reader.read("base_frame", p.base_frame);
  reader.read("chair_file", p.chair_file);
  reader.read("places_file", p.places_file);
  reader.read("rate", p.rate);
  reader.read("planner_service", p.planner_service);
  reader.read("controller_path_status", p.controller_path_status);
}

}  // namespace wheelchair_navigator
