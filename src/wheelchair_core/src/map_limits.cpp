#include <wheelchair_core/config.h>
#include <wheelchair_core/map_limits.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_core {

std::string MapLimits::validate() const {
  return ConfigChecks().check(max_cells > 0, "max_map_cells must be positive").result();
}

void readMapLimits(ConfigReader& reader, MapLimits& limits) {
  reader.read("max_map_cells", limits.max_cells);
}

std::string mapProblem(std::uint64_t width, std::uint64_t height, double resolution,
                       double origin_x, double origin_y, const std::vector<int8_t>& data,
                       const MapLimits& limits) {
  const std::string size = std::to_string(width) + " x " + std::to_string(height);
  if (width == 0 || height == 0) return "map of " + size + " cells has no cells";
  if (width > static_cast<std::uint64_t>(limits.max_cells) ||
      height > static_cast<std::uint64_t>(limits.max_cells) ||
      width * height > static_cast<std::uint64_t>(limits.max_cells))
    return "map of " + size + " cells exceeds max_map_cells " + std::to_string(limits.max_cells);
  if (data.size() != width * height)
    return "map data has " + std::to_string(data.size()) + " cells, " + size + " expected";
  if (!std::isfinite(resolution) || !(resolution > 0))
    return "map resolution must be finite and positive (got " + std::to_string(resolution) + ")";
  if (!std::isfinite(origin_x) || !std::isfinite(origin_y)) return "map origin is not finite";
  const auto bad =
      std::find_if(data.begin(), data.end(), [](int8_t v) { return v < -1 || v > 100; });
  if (bad != data.end())
    return "map cell " + std::to_string(bad - data.begin()) + " has value " +
           std::to_string(static_cast<int>(*bad)) + " (allowed: -1 unknown, 0..100)";
  return "";
}

}  // namespace wheelchair_core
