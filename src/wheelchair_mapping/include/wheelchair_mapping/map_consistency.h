// A standard map-consistency figure: the fraction of laser endpoints (of scans not used to
// build the map) that fall on occupied cells.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/occupancy_map.h>

#include <cstddef>

namespace wheelchair_mapping {

struct EndpointConsistency {
  size_t endpoints = 0;      ///< returns within [range_min, min(range_max, max_range)]
  size_t on_occupied = 0;    ///< ... whose cell is occupied
  size_t near_occupied = 0;  ///< ... with an occupied cell within one cell (8-neighbourhood)
  double onFraction() const { return endpoints ? double(on_occupied) / endpoints : 0.0; }
  double nearFraction() const { return endpoints ? double(near_occupied) / endpoints : 0.0; }
};

/// Adds the endpoints of `scan` taken at `sensor_pose` to `tally`.
void addEndpoints(const wheelchair_core::OccupancyMap& map,
                  const wheelchair_core::LaserScan2D& scan,
                  const wheelchair_core::Pose2D& sensor_pose, double max_range,
                  EndpointConsistency& tally);

}  // namespace wheelchair_mapping
