// What the map view shows and what the pointer can choose on it: rooms as areas around their
// places (the overview's targets), places with name labels that do not cover each other (a
// room's targets), and which part of the world the view frames now.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_display/layout.h>
#include <wheelchair_hmi/places.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace wheelchair_display {

/// A room of the places file as an area: the box around its places grown by a margin.
struct RoomArea {
  std::string name;
  wheelchair_core::Box box;
  std::vector<size_t> places;  ///< indices into the places list
};

/// The rooms in the order they first appear in `places`; each box grown by `pad` [m].
std::vector<RoomArea> roomAreas(const std::vector<wheelchair_hmi::Place>& places, double pad);
/// The smallest room area containing `p`, or -1.
int roomAt(const std::vector<RoomArea>& rooms, const Eigen::Vector2d& p);
/// The room called `name`, or -1.
int roomNamed(const std::vector<RoomArea>& rooms, const std::string& name);

/// The bounds of the map's known cells (free or occupied) [m]; empty for a map without any.
wheelchair_core::Box knownBounds(const wheelchair_core::OccupancyMap& map);

/// Label boxes for anchors (screen points) in priority order: each at the first of eight places
/// around its anchor (right, left, above, below, diagonals) that stays inside `bounds` and
/// covers no earlier label and nothing of `keep_clear` (the chair); when none is free, the first
/// inside `bounds` (covering). `sizes` are w x h px.
struct LabelBox {
  Rect rect;
  bool covers = false;  ///< it covers an earlier label
};
std::vector<LabelBox> placeLabels(const std::vector<Eigen::Vector2d>& anchors,
                                  const std::vector<std::pair<int, int>>& sizes, const Rect& bounds,
                                  int gap, const std::vector<Rect>& keep_clear = {});

/// The world points the view must show now: the chair (its footprint at `chair`, if known) with
/// the route and the goal while a drive or a choice is on; else the chosen room's area; else the
/// whole map (`overview`).
std::vector<Eigen::Vector2d> viewFrame(const wheelchair_core::Box& overview,
                                       const wheelchair_core::Polygon* chair_footprint_in_map,
                                       const std::vector<wheelchair_core::Pose2D>& route,
                                       const wheelchair_core::Pose2D* goal, const RoomArea* room);

}  // namespace wheelchair_display
