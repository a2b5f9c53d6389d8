// Is the way to a goal cut by something the static map does not have? Asked when the planner
// finds no route at the start of a drive: if the static map connects the chair to the goal and
// the obstacle layer's obstacles (the chair's half width around each) cut every such
// connection, the way is blocked by something that may move (a person in a doorway, a chair
// left in a corridor): the navigator waits for it rather than refusing at once. A flood fill
// over the static map's C-space cells (the chair's centre, 8-connected), ROS-free.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <optional>

namespace wheelchair_planner {
class ConfigSpace;
}  // namespace wheelchair_planner

namespace wheelchair_navigator {

/// The point where the layer cuts the way from `start` to `goal`: the first cell of a shortest
/// static-map connection (in cells) that the layer's obstacles block. nullopt if the static map
/// does not connect them (no way there at all), if the way stays open with the layer, or if
/// `layer` is not on the C-space's grid; the start itself if the layer blocks the chair's cell.
/// `cspace`: the static map's (hard C-space: where the chair's centre may be); a layer cell >= 50
/// that `static_map` has free blocks every cell within `radius` [m] of it.
std::optional<Eigen::Vector2d> layerCut(const wheelchair_planner::ConfigSpace& cspace,
                                        const wheelchair_core::OccupancyMap& static_map,
                                        const wheelchair_core::OccupancyMap& layer,
                                        const wheelchair_core::Pose2D& start,
                                        const wheelchair_core::Pose2D& goal, double radius);

}  // namespace wheelchair_navigator
