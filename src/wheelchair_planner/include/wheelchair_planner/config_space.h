// The chair's configuration space on an occupancy grid: a hard C-space (obstacles dilated by the
// chair's inscribed radius plus a minimum margin) and a soft clearance band that shapes the
// potential where the free space allows (see README, "Configuration space"). Shared by every
// planner plugin.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/occupancy_map.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_planner {

struct ConfigSpaceParams {
  double inscribed_radius = 0.31;  ///< chair half width [m] (ChairParams::inscribedRadius())
  double min_clearance = 0.05;     ///< hard minimum gap beyond the footprint [m]
  double clearance_band = 0.20;    ///< preferred gap beyond the footprint (paper's 20 cm) [m]
  double band_conductance = 0.05;  ///< conductance at the hard boundary (1 in open space)
  bool unknown_is_obstacle = true;
  int occupied_threshold = 50;  ///< cells >= this value are obstacles

  /// Empty if usable, else every non-finite or inconsistent parameter.
  std::string validate() const;
};

/// Keys: inscribed_radius, min_clearance, clearance_band, band_conductance, unknown_is_obstacle.
void readConfigSpaceParams(wheelchair_core::ConfigReader& reader, ConfigSpaceParams& params);

/// What ConfigSpace::update() changed.
struct ConfigSpaceChange {
  /// Recomputed from scratch (another grid geometry, or a distance beyond the bound that makes
  /// a windowed update exact): every cell may have changed.
  bool rebuilt = false;
  /// Cells whose free state or conductance changed (when not rebuilt), in index order.
  std::vector<size_t> cells;
  /// Cells whose obstacle distance may have changed: [x0, x1) x [y0, y1) (empty if none).
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool distancesChanged() const { return rebuilt || (x1 > x0 && y1 > y0); }
};

class ConfigSpace {
 public:
  /// Builds the C-space. Cells outside the map count as obstacles (the border row/column of the
  /// grid is always blocked so that every path stays inside the map). Throws
  /// std::invalid_argument on invalid parameters or a map it cannot use.
  ConfigSpace(const wheelchair_core::OccupancyMap& map, const ConfigSpaceParams& params);

  /// The same C-space for `map`, a map of this grid with some cells changed (e.g. the live
  /// obstacle layer over the static map), recomputed in place: only in a window around the
  /// changed cells, exactly as a new ConfigSpace(map, params()) would have it (the window is
  /// wide enough that no cell outside it can change: the largest obstacle distance of the grid
  /// bounds how far a changed cell can reach). A map of another geometry is rebuilt. Objects
  /// that refer to this one (the footprint checker) stay valid. Throws like the constructor.
  ConfigSpaceChange update(const wheelchair_core::OccupancyMap& map);
  /// Incremented by every update() that changed something (0 after construction).
  int revision() const { return revision_; }

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const ConfigSpaceParams& params() const { return params_; }

  size_t index(int ix, int iy) const { return static_cast<size_t>(iy) * width_ + ix; }
  bool inBounds(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width_ && iy < height_; }
  /// True if the chair's centre may be in this cell (hard C-space).
  bool isFree(int ix, int iy) const { return inBounds(ix, iy) && free_[index(ix, iy)] != 0; }
  /// Distance from the cell centre to the nearest obstacle cell [m] (0 inside obstacles).
  double obstacleDistance(int ix, int iy) const { return distance_[index(ix, iy)]; }
  /// Distance from a world point to the nearest obstacle cell edge, bilinearly interpolated
  /// between cell centres [m] (0 in obstacles).
  double distanceAt(double x, double y) const;
  /// Distance of the cell holding a world point to the nearest obstacle [m]; 0 outside the map.
  double cellDistanceAt(double x, double y) const {
    int ix, iy;
    return worldToCell(x, y, ix, iy) ? distance_[index(ix, iy)] : 0.0;
  }
  /// Clearance beyond the inscribed circle at a world point, bilinearly interpolated [m].
  double clearanceAt(double x, double y) const {
    return distanceAt(x, y) - params_.inscribed_radius;
  }
  /// Conductance of a free cell in (0, 1]: 1 at >= clearance_band, band_conductance at the
  /// hard boundary, smooth in between; 1 everywhere when clearance_band <= min_clearance.
  double conductance(int ix, int iy) const { return conductance_[index(ix, iy)]; }

  /// World <-> continuous cell coordinates (cell (i, j) centre at (i, j)).
  void worldToGrid(double x, double y, double& gx, double& gy) const;
  void gridToWorld(double gx, double gy, double& x, double& y) const;
  /// Cell containing a world point; false if outside the map.
  bool worldToCell(double x, double y, int& ix, int& iy) const;

  const std::vector<uint8_t>& freeMask() const { return free_; }
  size_t freeCount() const;

 private:
  /// Distance transform (cell centre to the nearest obstacle cell centre, in cells) of the
  /// cells [x0, x1) x [y0, y1), which may reach one cell beyond the map (its outside is an
  /// obstacle), seeing only the obstacles inside that window; row-major, (x1 - x0) per row.
  std::vector<float> transform(const wheelchair_core::OccupancyMap& map, int x0, int y0, int x1,
                               int y1) const;
  /// Distance, free state and conductance of the cells [x0, x1) x [y0, y1) from `dist`, a
  /// transform whose element 0 is grid cell (dx0, dy0), `stride` per row; the cells whose free
  /// state or conductance changed are appended to `changed` if not null.
  void setCells(const std::vector<float>& dist, int stride, int dx0, int dy0, int x0, int y0,
                int x1, int y1, std::vector<size_t>* changed);
  bool isObstacleValue(int8_t v) const;

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.05;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  ConfigSpaceParams params_;
  std::vector<uint8_t> free_;
  std::vector<uint8_t> obstacle_;  ///< the map's obstacle cells (what update() compares)
  std::vector<float> distance_;
  std::vector<float> conductance_;
  /// Upper bound of the distance transform (cell centre to obstacle centre) over the grid [cells].
  float max_transform_ = 0.0f;
  int revision_ = 0;
};

// Inline: the footprint checker calls these ~10^7 times per search.
inline void ConfigSpace::worldToGrid(double x, double y, double& gx, double& gy) const {
  gx = (x - origin_x_) / resolution_ - 0.5;
  gy = (y - origin_y_) / resolution_ - 0.5;
}

inline void ConfigSpace::gridToWorld(double gx, double gy, double& x, double& y) const {
  x = origin_x_ + (gx + 0.5) * resolution_;
  y = origin_y_ + (gy + 0.5) * resolution_;
}

inline bool ConfigSpace::worldToCell(double x, double y, int& ix, int& iy) const {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  const double fx = std::floor((x - origin_x_) / resolution_);
  const double fy = std::floor((y - origin_y_) / resolution_);
  if (fx < 0 || fy < 0 || fx >= width_ || fy >= height_) return false;
  ix = static_cast<int>(fx);
  iy = static_cast<int>(fy);
  return true;
}

inline double ConfigSpace::distanceAt(double x, double y) const {
  int cx, cy;
  if (!worldToCell(x, y, cx, cy)) return 0.0;  // outside the map is an obstacle
  double gx, gy;
  worldToGrid(x, y, gx, gy);
  gx = std::clamp(gx, 0.0, width_ - 1.0);
  gy = std::clamp(gy, 0.0, height_ - 1.0);
  const int x0 = std::min(static_cast<int>(gx), width_ - 2 < 0 ? 0 : width_ - 2);
  const int y0 = std::min(static_cast<int>(gy), height_ - 2 < 0 ? 0 : height_ - 2);
  const int x1 = std::min(x0 + 1, width_ - 1), y1 = std::min(y0 + 1, height_ - 1);
  const double tx = gx - x0, ty = gy - y0;
  const double d = (1 - tx) * (1 - ty) * distance_[index(x0, y0)] +
                   tx * (1 - ty) * distance_[index(x1, y0)] +
                   (1 - tx) * ty * distance_[index(x0, y1)] + tx * ty * distance_[index(x1, y1)];
  return d;
}

}  // namespace wheelchair_planner
