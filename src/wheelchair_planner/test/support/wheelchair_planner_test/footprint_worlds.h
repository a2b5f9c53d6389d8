// Test worlds and independent checks of the footprint gate (test support): maps carved from
// rectangles, the L-corner, the chair's box, and a brute-force box-vs-cell clearance of the
// motion the controller drives for a plan, rebuilt here from its SmoothPath.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_planner/planner_settings.h>

#include <array>
#include <vector>

namespace wheelchair_planner {

/// The chair of chair.yaml: front-wheel drive, body 0.30 m ahead of and 0.80 m behind the axle.
const wheelchair_core::Polygon& chairBox();

/// chairBox() as the footprint, its half width (0.31 m) as the C-space's inscribed radius.
PlannerSettings chairBoxSettings();

/// All occupied, then the given world rectangles [x0, x1] x [y0, y1] carved free (5 cm cells).
wheelchair_core::OccupancyMap carved(double size,
                                     const std::vector<std::array<double, 4>>& free_boxes);

/// An L of two corridors of width w: east along y in [0.5, 0.5 + w], then north along
/// x in [6.5 - w, 6.5].
wheelchair_core::OccupancyMap lCorner(double w);

/// Brute force: the smallest distance from chairBox() at `pose` to any occupied cell square
/// (each cell sampled 6 x 6 on its area, edges included).
double bruteClearance(const wheelchair_core::OccupancyMap& map,
                      const wheelchair_core::Pose2D& pose);

/// The controller's execution of `plan` from `start`, rebuilt from its SmoothPath: start
/// rotation, per piece (split at its cusps) the smoothed path every 1 cm with its tangent (+ pi
/// in reverse) and the turn to it at the cusp, the goal rotation; brute-force clearance of every
/// pose.
double bruteSweepClearance(const wheelchair_core::OccupancyMap& map,
                           const wheelchair_core::Pose2D& start,
                           const std::vector<wheelchair_core::Pose2D>& plan);

}  // namespace wheelchair_planner
