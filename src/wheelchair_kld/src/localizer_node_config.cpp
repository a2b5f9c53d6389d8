#include "localizer_node_config.h"

namespace wheelchair_kld {

std::string LocalizerNodeConfig::validate() const {
  const std::string filter_problem = filter.validate();
  return wheelchair_core::ConfigChecks()
      .check(filter_problem.empty(), filter_problem)
      .check(!map_frame.empty() && !odom_frame.empty() && !base_frame.empty(),
             "map_frame, odom_frame and base_frame must be named")
      .nonNegative("transform_tolerance", transform_tolerance)
      .check(expected_beams >= 0, "expected_beams must not be negative (0: any)")
      .check(scan_queue_size >= 1, "scan_queue_size must be at least 1")
      .positive("tf_timeout", tf_timeout)
      .check(seed >= 0, "seed must not be negative")
      .check(map_limits.validate().empty(), map_limits.validate())
      .result();
}

void readLocalizerNodeConfig(wheelchair_core::ConfigReader& r, LocalizerNodeConfig& c) {
  readKldParams(r, c.filter);
  r.renamed("global_frame", "map_frame");
  r.read("map_frame", c.map_frame);
  r.read("odom_frame", c.odom_frame);
  r.read("base_frame", c.base_frame);
  r.read("transform_tolerance", c.transform_tolerance);
  r.read("expected_beams", c.expected_beams);
  r.read("global_localization_on_start", c.global_localization_on_start);
  r.read("scan_queue_size", c.scan_queue_size);
  r.read("tf_timeout", c.tf_timeout);
  r.read("seed", c.seed);
  wheelchair_core::readMapLimits(r, c.map_limits);
}

}  // namespace wheelchair_kld
