// Every private parameter of the controller nodelet: the tracker's keys (readTrackerConfig) and
// the nodelet's own. Read once in onInit by wheelchair_ros::loadParameters: an unknown or renamed
// key or an invalid value refuses the nodelet.
#pragma once

#include <wheelchair_controller/tracker_config.h>
#include <wheelchair_core/config.h>
#include <wheelchair_description/chair_file.h>
#include <wheelchair_ros/expected_publisher.h>

#include <string>

namespace wheelchair_controller {

struct ControllerParameters {
  TrackerConfig tracker;
  /// The chair's description (wheelchair_description's chair.yaml, found at run time).
  std::string chair_file = wheelchair_description::defaultChairFile();
  std::string map_frame = "map";
  std::string base_frame = "base_link";
  double rate = 50.0;  ///< [Hz] control steps and /wheel_torques
  /// [s] of wall time between control steps that is a pause as the tracker's gap_timeout is of
  /// ROS time (a simulated clock may not show a hang): PathTracker::stepsPaused.
  double wall_gap_timeout = 0.5;
  /// The one node whose /safety/speed_limit is taken ("": this process, the chair's own
  /// supervisor): another publisher's limit is refused and reported, so it can never raise it.
  std::string speed_limit_publisher;

  std::string validate() const {
    const std::string publisher_problem =
        wheelchair_ros::publisherNameProblem("speed_limit_publisher", speed_limit_publisher);
    wheelchair_core::ConfigChecks checks;
    checks.check(publisher_problem.empty(), publisher_problem);
    checks.positive("rate", rate)
        .positive("wall_gap_timeout", wall_gap_timeout)
        .check(tracker.gap_timeout > 1.0 / rate, "gap_timeout must exceed one control period")
        .check(!chair_file.empty(), "chair_file must name the chair's description file")
        .check(!map_frame.empty() && !base_frame.empty(), "map_frame and base_frame must be set");
    const std::string tracker_problem = tracker.validate();
    checks.check(tracker_problem.empty(), tracker_problem);
    return checks.result();
  }
};

inline void readControllerParameters(wheelchair_core::ConfigReader& reader,
                                     ControllerParameters& p) {
  reader.renamed("chair_params", "chair_file");
  reader.read("chair_file", p.chair_file);
  reader.read("map_frame", p.map_frame);
  reader.read("base_frame", p.base_frame);
  reader.read("rate", p.rate);
  reader.read("wall_gap_timeout", p.wall_gap_timeout);
  reader.read("speed_limit_publisher", p.speed_limit_publisher);
  readTrackerConfig(reader, p.tracker);
}

}  // namespace wheelchair_controller
