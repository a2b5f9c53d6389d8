// Edits of the places file (the format of loadPlaces, places.h): the carer's on the rider
// display (add the chair's pose as a named place, rename or delete one) and the SLAM nodelet's
// save_place; both write the file back with savePlaces.
#pragma once

#include <wheelchair_hmi/places.h>

#include <string>
#include <vector>

namespace wheelchair_hmi {

/// A name as typed ("Front door ") as the file's identifier ("front_door").
std::string placeId(const std::string& typed);

/// "" if `id` can name a new place of `places`, else why not (empty, taken, not a-z 0-9 _).
std::string placeNameProblem(const std::string& id, const std::vector<Place>& places);

/// Writes `places` into `yaml_path`, keeping the file's other keys (map, rooms) and adding a new
/// room to `rooms`. Written to a temporary file and renamed: a crash never leaves half a file.
/// Throws std::runtime_error naming the file.
void savePlaces(const std::string& yaml_path, const std::vector<Place>& places);

}  // namespace wheelchair_hmi
