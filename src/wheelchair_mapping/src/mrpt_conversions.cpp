#include <wheelchair_mapping/mrpt_conversions.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_mapping {
namespace {

/// MRPT's setSize() snaps x_min/y_min to multiples of the resolution; map_server origins need
/// not be. This shim moves the grid's extent to the exact origin (cells are unchanged).
class ExactOriginGrid : public mrpt::maps::COccupancyGridMap2D {
 public:
  void moveOriginTo(double x, double y) {
    m_xMax = static_cast<float>(x + m_size_x * m_resolution);
    m_yMax = static_cast<float>(y + m_size_y * m_resolution);
    m_xMin = static_cast<float>(x);
    m_yMin = static_cast<float>(y);
  }
};

}  // namespace

mrpt::maps::COccupancyGridMap2D toMrptGrid(const wheelchair_core::OccupancyMap& map) {
  if (map.width <= 0 || map.height <= 0 || !(map.resolution > 0) ||
      map.data.size() != static_cast<size_t>(map.width) * map.height) {
    throw std::invalid_argument("toMrptGrid: empty or inconsistent wheelchair_core::OccupancyMap");
  }
  if (map.origin_yaw != 0.0) throw std::invalid_argument("toMrptGrid: origin_yaw must be 0");
  const auto res = static_cast<float>(map.resolution);
  ExactOriginGrid grid;
  grid.setSize(0.0f, map.width * res, 0.0f, map.height * res, res);
  if (grid.getSizeX() != static_cast<unsigned>(map.width) ||
      grid.getSizeY() != static_cast<unsigned>(map.height)) {
    throw std::logic_error("toMrptGrid: MRPT grid size differs from the map's");
  }
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      const int8_t v = map.at(ix, iy);
      const float p_free = (v < 0 || v > 100) ? 0.5f : 1.0f - v / 100.0f;
      grid.setCell(ix, iy, p_free);
    }
  }
  grid.moveOriginTo(map.origin_x, map.origin_y);
  return grid;
}

wheelchair_core::OccupancyMap fromMrptGrid(const mrpt::maps::COccupancyGridMap2D& grid,
                                           const GridThresholds& thresholds) {
  wheelchair_core::OccupancyMap map;
  map.resolution = grid.getResolution();
  map.origin_x = grid.getXMin();
  map.origin_y = grid.getYMin();
  map.width = static_cast<int>(grid.getSizeX());
  map.height = static_cast<int>(grid.getSizeY());
  map.data.assign(static_cast<size_t>(map.width) * map.height, wheelchair_core::kUnknown);
  const auto prior = mrpt::maps::COccupancyGridMap2D::p2l(0.5f);
  const auto& raw = grid.getRawMap();
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      const size_t i = static_cast<size_t>(iy) * map.width + ix;
      const double p_occ = 1.0 - mrpt::maps::COccupancyGridMap2D::l2p(raw[i]);
      int8_t& cell = map.data[i];
      if (!thresholds.trinary) {
        cell = raw[i] == prior ? wheelchair_core::kUnknown
                               : static_cast<int8_t>(std::lround(100.0 * p_occ));
      } else if (p_occ > thresholds.occupied_thresh) {
        cell = wheelchair_core::kOccupied;
      } else if (p_occ < thresholds.free_thresh) {
        cell = wheelchair_core::kFree;
      }
    }
  }
  return map;
}

}  // namespace wheelchair_mapping
