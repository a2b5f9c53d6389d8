#include <wheelchair_planner/config_space.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_planner {

std::string ConfigSpaceParams::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.nonNegative("inscribed_radius", inscribed_radius)
      .nonNegative("min_clearance", min_clearance)
      .nonNegative("clearance_band", clearance_band)
      .check(std::isfinite(band_conductance) && band_conductance > 0.0 && band_conductance <= 1.0,
             "band_conductance must be in (0, 1]")
      .check(occupied_threshold >= 1 && occupied_threshold <= 100,
             "occupied_threshold must be in [1, 100]");
  return checks.result();
}

void readConfigSpaceParams(wheelchair_core::ConfigReader& reader, ConfigSpaceParams& p) {
  reader.read("inscribed_radius", p.inscribed_radius);
  reader.read("min_clearance", p.min_clearance);
  reader.read("clearance_band", p.clearance_band);
  reader.read("band_conductance", p.band_conductance);
  reader.read("unknown_is_obstacle", p.unknown_is_obstacle);
}

namespace {

/// Smooth ramp 0 -> 1 for t in [0, 1] (C1 smoothstep).
double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

ConfigSpace::ConfigSpace(const wheelchair_core::OccupancyMap& map, const ConfigSpaceParams& params)
    : width_(map.width),
      height_(map.height),
      resolution_(map.resolution),
      origin_x_(map.origin_x),
      origin_y_(map.origin_y),
      params_(params) {
  if (const std::string problem = params.validate(); !problem.empty())
    throw std::invalid_argument("ConfigSpaceParams: " + problem);
  if (map.width <= 0 || map.height <= 0 || !(map.resolution > 0.0) ||
      map.data.size() != static_cast<size_t>(map.width) * map.height) {
    throw std::invalid_argument("ConfigSpace: map is empty or its size does not match its data");
  }
  if (!std::isfinite(map.origin_x) || !std::isfinite(map.origin_y) || map.origin_yaw != 0.0) {
    throw std::invalid_argument("ConfigSpace: map origin must be finite with zero yaw");
  }
  // Obstacle image padded by one blocked cell on every side: outside the map is an obstacle.
  cv::Mat passable(height_ + 2, width_ + 2, CV_8UC1, cv::Scalar(0));
  for (int iy = 0; iy < height_; ++iy) {
    auto* row = passable.ptr<uint8_t>(iy + 1);
    for (int ix = 0; ix < width_; ++ix) {
      const int v = map.at(ix, iy);
      const bool obstacle = v >= params.occupied_threshold || (v < 0 && params.unknown_is_obstacle);
      row[ix + 1] = obstacle ? 0 : 255;
    }
  }
  // Exact Euclidean distance to the nearest obstacle cell centre: thresholding it is the
  // dilation of the obstacles by a disc (the C-space), and it also gives the clearance.
  cv::Mat dist;
  cv::distanceTransform(passable, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const size_t n = static_cast<size_t>(width_) * height_;
  free_.assign(n, 0);
  distance_.assign(n, 0.0f);
  conductance_.assign(n, 0.0f);
  const double hard = params.inscribed_radius + params.min_clearance;
  const double band_width = params.clearance_band - params.min_clearance;
  for (int iy = 0; iy < height_; ++iy) {
    const float* drow = dist.ptr<float>(iy + 1);
    for (int ix = 0; ix < width_; ++ix) {
      // The obstacle cell's edge is half a cell closer than its centre.
      const double d = std::max(0.0, (drow[ix + 1] - 0.5) * resolution_);
      const size_t k = index(ix, iy);
      distance_[k] = static_cast<float>(d);
      if (d > hard) {
        free_[k] = 1;
        const double s = band_width > 0.0 ? smoothstep((d - hard) / band_width) : 1.0;
        conductance_[k] =
            static_cast<float>(params.band_conductance + (1.0 - params.band_conductance) * s);
      }
    }
  }
  // Keep the outermost ring blocked so that neighbour lookups never leave the grid.
  for (int ix = 0; ix < width_; ++ix) free_[index(ix, 0)] = free_[index(ix, height_ - 1)] = 0;
  for (int iy = 0; iy < height_; ++iy) free_[index(0, iy)] = free_[index(width_ - 1, iy)] = 0;
}

void ConfigSpace::worldToGrid(double x, double y, double& gx, double& gy) const {
  gx = (x - origin_x_) / resolution_ - 0.5;
  gy = (y - origin_y_) / resolution_ - 0.5;
}

void ConfigSpace::gridToWorld(double gx, double gy, double& x, double& y) const {
  x = origin_x_ + (gx + 0.5) * resolution_;
  y = origin_y_ + (gy + 0.5) * resolution_;
}

bool ConfigSpace::worldToCell(double x, double y, int& ix, int& iy) const {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  const double fx = std::floor((x - origin_x_) / resolution_);
  const double fy = std::floor((y - origin_y_) / resolution_);
  if (fx < 0 || fy < 0 || fx >= width_ || fy >= height_) return false;
  ix = static_cast<int>(fx);
  iy = static_cast<int>(fy);
  return true;
}

double ConfigSpace::distanceAt(double x, double y) const {
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

size_t ConfigSpace::freeCount() const {
  return static_cast<size_t>(std::count(free_.begin(), free_.end(), uint8_t{1}));
}

}  // namespace wheelchair_planner
