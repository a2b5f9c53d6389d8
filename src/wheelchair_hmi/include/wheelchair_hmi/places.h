// Named places of a map (kitchen, bed, desk, door...), grouped by room: the destinations a
// rider chooses from.
#pragma once

#include <wheelchair_core/pose2d.h>

#include <string>
#include <vector>

namespace wheelchair_hmi {

struct Place {
  std::string name;
  std::string room;
  wheelchair_core::Pose2D pose;  ///< in the map frame; yaw: the heading to arrive with
};

/// Reads `places: [{name, room, x, y, yaw}, ...]`. Throws std::runtime_error naming the file
/// and the problem (missing key, non-finite number, duplicate name, no places).
std::vector<Place> loadPlaces(const std::string& yaml_path);

/// The place called `name`, or nullptr.
const Place* findPlace(const std::vector<Place>& places, const std::string& name);

}  // namespace wheelchair_hmi
