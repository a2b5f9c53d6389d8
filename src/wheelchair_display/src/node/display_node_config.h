// The display node's parameters: the core's DisplayConfig and the node's own (files, frames,
// window), read by one loader (wheelchair_ros::loadParameters) that refuses unknown keys.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_display/display_config.h>

#include <string>

namespace wheelchair_display {

struct DisplayNodeConfig {
  DisplayConfig display;
  std::string places_file;  ///< required: the named places (wheelchair_hmi's file)
  std::string chair_file;   ///< the chair's description; "" = wheelchair_description's
  std::string map_frame = "map";
  std::string base_frame = "base_link";
  double pose_timeout = 1.0;          ///< [s] an older map->base_frame pose counts as unknown
  double route_check_timeout = 15.0;  ///< [s] waiting for the route check's answer
  bool fullscreen = true;
  int width = 0;               ///< [px] window size when not full screen (0: 1024)
  int height = 0;              ///< [px] (0: 768)
  std::string speech_wav_dir;  ///< if set, every announcement is written there as NNN.wav (+ .txt)

  std::string validate() const {
    wheelchair_core::ConfigChecks checks;
    checks.check(!places_file.empty(), "places_file is empty")
        .check(!map_frame.empty() && !base_frame.empty(), "map_frame and base_frame must be set")
        .positive("pose_timeout", pose_timeout)
        .positive("route_check_timeout", route_check_timeout)
        .inRange("width", width, 0, 10000)
        .inRange("height", height, 0, 10000);
    const std::string display_problem = display.validate();
    checks.check(display_problem.empty(), display_problem);
    return checks.result();
  }
};

inline void readDisplayNodeConfig(wheelchair_core::ConfigReader& reader, DisplayNodeConfig& c) {
  readDisplayConfig(reader, c.display);
  reader.require("places_file", c.places_file);
  reader.read("chair_file", c.chair_file);
  reader.renamed("chair_params", "chair_file");
  reader.read("map_frame", c.map_frame);
  reader.renamed("global_frame", "map_frame");
  reader.renamed("frame_id", "map_frame");
  reader.read("base_frame", c.base_frame);
  reader.read("pose_timeout", c.pose_timeout);
  reader.read("route_check_timeout", c.route_check_timeout);
  reader.read("fullscreen", c.fullscreen);
  reader.read("width", c.width);
  reader.read("height", c.height);
  reader.read("speech_wav_dir", c.speech_wav_dir);
}

}  // namespace wheelchair_display
