// The chair's configuration space on an occupancy grid: a hard C-space (obstacles dilated by the
// chair's inscribed radius plus a minimum margin) and a soft clearance band that shapes the
// potential where the free space allows (see README, "Configuration space"). Shared by every
// planner plugin.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/occupancy_map.h>

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

class ConfigSpace {
 public:
  /// Builds the C-space. Cells outside the map count as obstacles (the border row/column of the
  /// grid is always blocked so that every path stays inside the map). Throws
  /// std::invalid_argument on invalid parameters or a map it cannot use.
  ConfigSpace(const wheelchair_core::OccupancyMap& map, const ConfigSpaceParams& params);

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
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.05;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  ConfigSpaceParams params_;
  std::vector<uint8_t> free_;
  std::vector<float> distance_;
  std::vector<float> conductance_;
};

}  // namespace wheelchair_planner
