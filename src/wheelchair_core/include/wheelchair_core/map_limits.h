// What a map may be before any consumer (localizer, planner, supervisor) takes it: a message on
// /map comes from any node, and one bad map must never take the chair process down. A negative
// resolution aborted the process; a 4000 x 4000 map took it to 840 MB and stalled it long enough
// for a "laser silent" stop. mapProblem() is the check, MapLimits the memory cap (one parameter
// per consumer, `max_map_cells`, sized for the chair's legacy PC).
#pragma once

#include <wheelchair_core/occupancy_map.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_core {

class ConfigReader;

struct MapLimits {
  /// [cells] the largest map taken: 1024 x 1024 = 51 m x 51 m at 5 cm (a home needs < 40 m).
  /// The harmonic planner prepares such a map in ~1 s and ~50 MB; 2048^2 takes 4 s and the
  /// chair process over its 150 MB budget.
  int max_cells = 1024 * 1024;

  std::string validate() const;
};

/// Key: max_map_cells.
void readMapLimits(ConfigReader& reader, MapLimits& limits);

/// "" if a grid with these fields is usable, else why not (one line, naming the numbers): no
/// cells, width x height beyond limits.max_cells, data size differing from width x height, a
/// resolution that is not finite and positive, a non-finite origin, a cell value outside
/// -1..100. Checks the size before touching the cells (a huge map is refused in O(1)).
std::string mapProblem(std::uint64_t width, std::uint64_t height, double resolution,
                       double origin_x, double origin_y, const std::vector<int8_t>& data,
                       const MapLimits& limits);

}  // namespace wheelchair_core
