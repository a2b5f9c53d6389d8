// wheelchair_core::OccupancyMap <-> mrpt::maps::COccupancyGridMap2D (the grid the localizer, the
// simulator and the mapper work on). MRPT cells hold the probability of being FREE;
// wheelchair_core::OccupancyMap holds the occupancy in percent (nav_msgs), so p_free = 1 - value /
// 100 and unknown = 0.5.
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <wheelchair_core/occupancy_map.h>

namespace wheelchair_mapping {

/// How MRPT probabilities become cell values: occupied if P(occ) > occupied_thresh, free if
/// P(occ) < free_thresh, else unknown (trinary); or round(100 P(occ)) with unknown only for
/// cells still exactly at the prior 0.5 (not trinary).
struct GridThresholds {
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  bool trinary = true;
};

/// Same extent, resolution and origin (origin_yaw must be 0); throws std::invalid_argument
/// for an empty or inconsistent map.
mrpt::maps::COccupancyGridMap2D toMrptGrid(const wheelchair_core::OccupancyMap& map);

wheelchair_core::OccupancyMap fromMrptGrid(const mrpt::maps::COccupancyGridMap2D& grid,
                                           const GridThresholds& thresholds = GridThresholds());

}  // namespace wheelchair_mapping
