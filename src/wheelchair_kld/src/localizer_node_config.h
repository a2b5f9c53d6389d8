// Everything the localizer nodelet reads from its private parameters: the filter's KldParams
// and the node's own frames, timings and start-up choices. One loader reads them all
// (wheelchair_ros::loadParameters): an unknown key, a renamed one or an invalid value refuses
// the nodelet.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/map_limits.h>
#include <wheelchair_kld/kld_params.h>

#include <string>

namespace wheelchair_kld {

struct LocalizerNodeConfig {
  KldParams filter;
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  /// [s] map -> odom is stamped this far past the scan (REP-105: valid until the next one).
  double transform_tolerance = 0.1;
  int expected_beams = 0;  ///< 0: the first scan's beam count
  bool global_localization_on_start = false;
  int scan_queue_size = 5;  ///< scans waiting for odometry (0.5 s of lag at 10 Hz)
  double tf_timeout = 0.5;  ///< [s] no usable scan for this long while scans arrive: no data
  int seed = 1;             ///< of every random draw of the filter
  /// Any node can publish /map: a bigger or broken one is refused, the last good one kept.
  wheelchair_core::MapLimits map_limits;

  std::string validate() const;
};

/// Every key: readKldParams' and the node's own (global_frame was renamed map_frame).
void readLocalizerNodeConfig(wheelchair_core::ConfigReader& reader, LocalizerNodeConfig& config);

}  // namespace wheelchair_kld
