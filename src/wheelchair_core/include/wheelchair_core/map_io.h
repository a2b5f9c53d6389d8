// map_server's YAML + PGM map files (image, resolution, origin, occupied_thresh,
// free_thresh, negate, mode), readable and writable without ROS.
#pragma once

#include <wheelchair_core/occupancy_map.h>

#include <stdexcept>
#include <string>

namespace wheelchair_core {

/// Thrown for any unreadable or invalid map file; what() is one line naming the file
/// and the problem, e.g. "flat.yaml: resolution must be positive (got -0.05)".
class MapFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class MapMode { kTrinary, kScale, kRaw };

struct MapFileOptions {
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  bool negate = false;
  MapMode mode = MapMode::kTrinary;
};

/// Loads a map_server YAML and its image (PGM; other formats OpenCV reads work too),
/// interpreting pixels exactly as map_server does. Throws MapFileError.
OccupancyMap loadMap(const std::string& yaml_path);

/// Writes `<stem>.yaml` + `<stem>.pgm` as map_server's map_saver does (trinary:
/// 0 occupied, 254 free, 205 unknown). Trinary maps round-trip exactly. Throws MapFileError.
void saveMap(const OccupancyMap& map, const std::string& yaml_path,
             const MapFileOptions& options = MapFileOptions());

}  // namespace wheelchair_core
