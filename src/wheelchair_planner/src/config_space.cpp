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
  const size_t n = static_cast<size_t>(width_) * height_;
  obstacle_.resize(n);
  for (size_t k = 0; k < n; ++k) obstacle_[k] = isObstacleValue(map.data[k]) ? 1 : 0;
  free_.assign(n, 0);
  distance_.assign(n, 0.0f);
  conductance_.assign(n, 0.0f);
  // The whole grid padded by one blocked cell on every side: outside the map is an obstacle.
  const std::vector<float> dist = transform(map, -1, -1, width_ + 1, height_ + 1);
  max_transform_ = dist.empty() ? 0.0f : *std::max_element(dist.begin(), dist.end());
  setCells(dist, width_ + 2, -1, -1, 0, 0, width_, height_, nullptr);
}

ConfigSpaceChange ConfigSpace::update(const wheelchair_core::OccupancyMap& map) {
  ConfigSpaceChange change;
  if (map.width != width_ || map.height != height_ || map.resolution != resolution_ ||
      map.origin_x != origin_x_ || map.origin_y != origin_y_ || map.origin_yaw != 0.0 ||
      map.data.size() != obstacle_.size()) {
    const int revision = revision_;
    *this = ConfigSpace(map, params_);
    revision_ = revision + 1;
    change.rebuilt = true;
    return change;
  }
  // The cells whose obstacle state changed, and their bounding box.
  int bx0 = width_, by0 = height_, bx1 = -1, by1 = -1;
  for (size_t k = 0; k < obstacle_.size(); ++k) {
    if ((isObstacleValue(map.data[k]) ? 1 : 0) == obstacle_[k]) continue;
    const int ix = static_cast<int>(k % width_), iy = static_cast<int>(k / width_);
    bx0 = std::min(bx0, ix);
    bx1 = std::max(bx1, ix);
    by0 = std::min(by0, iy);
    by1 = std::max(by1, iy);
  }
  if (bx1 < 0) return change;
  // A cell farther than the largest transform value R from every changed cell keeps its nearest
  // obstacle, so only the window W (the changed box grown by R) can change; there the transform
  // of W grown by R again is exact wherever it is at most R (an obstacle outside it is farther).
  const int margin = static_cast<int>(std::ceil(max_transform_)) + 1;
  const int x0 = std::max(0, bx0 - margin), x1 = std::min(width_, bx1 + 1 + margin);
  const int y0 = std::max(0, by0 - margin), y1 = std::min(height_, by1 + 1 + margin);
  const int qx0 = std::max(-1, x0 - margin), qx1 = std::min(width_ + 1, x1 + margin);
  const int qy0 = std::max(-1, y0 - margin), qy1 = std::min(height_ + 1, y1 + margin);
  const std::vector<float> dist = transform(map, qx0, qy0, qx1, qy1);
  const int stride = qx1 - qx0;
  for (int iy = y0; iy < y1; ++iy) {
    for (int ix = x0; ix < x1; ++ix) {
      if (dist[static_cast<size_t>(iy - qy0) * stride + (ix - qx0)] > max_transform_) {
        // A removed obstacle left space farther from every obstacle than before: the bound no
        // longer holds, start again.
        const int revision = revision_;
        *this = ConfigSpace(map, params_);
        revision_ = revision + 1;
        change.rebuilt = true;
        return change;
      }
    }
  }
  for (int iy = by0; iy <= by1; ++iy)
    for (int ix = bx0; ix <= bx1; ++ix) obstacle_[index(ix, iy)] = isObstacleValue(map.at(ix, iy));
  setCells(dist, stride, qx0, qy0, x0, y0, x1, y1, &change.cells);
  std::sort(change.cells.begin(), change.cells.end());
  change.x0 = x0;
  change.y0 = y0;
  change.x1 = x1;
  change.y1 = y1;
  ++revision_;
  return change;
}

bool ConfigSpace::isObstacleValue(int8_t v) const {
  return v >= params_.occupied_threshold || (v < 0 && params_.unknown_is_obstacle);
}

std::vector<float> ConfigSpace::transform(const wheelchair_core::OccupancyMap& map, int x0, int y0,
                                          int x1, int y1) const {
  cv::Mat passable(y1 - y0, x1 - x0, CV_8UC1, cv::Scalar(0));
  for (int iy = std::max(0, y0); iy < std::min(height_, y1); ++iy) {
    auto* row = passable.ptr<uint8_t>(iy - y0);
    for (int ix = std::max(0, x0); ix < std::min(width_, x1); ++ix)
      row[ix - x0] = isObstacleValue(map.at(ix, iy)) ? 0 : 255;
  }
  // Exact Euclidean distance to the nearest obstacle cell centre: thresholding it is the
  // dilation of the obstacles by a disc (the C-space), and it also gives the clearance.
  cv::Mat dist;
  cv::distanceTransform(passable, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  std::vector<float> out(static_cast<size_t>(dist.rows) * dist.cols);
  for (int r = 0; r < dist.rows; ++r)
    std::copy(dist.ptr<float>(r), dist.ptr<float>(r) + dist.cols,
              out.begin() + static_cast<long>(r) * dist.cols);
  return out;
}

void ConfigSpace::setCells(const std::vector<float>& dist, int stride, int dx0, int dy0, int x0,
                           int y0, int x1, int y1, std::vector<size_t>* changed) {
  const double hard = params_.inscribed_radius + params_.min_clearance;
  const double band_width = params_.clearance_band - params_.min_clearance;
  for (int iy = y0; iy < y1; ++iy) {
    const float* drow = &dist[static_cast<size_t>(iy - dy0) * stride - dx0];
    for (int ix = x0; ix < x1; ++ix) {
      // The obstacle cell's edge is half a cell closer than its centre.
      const double d = std::max(0.0, (drow[ix] - 0.5) * resolution_);
      const size_t k = index(ix, iy);
      distance_[k] = static_cast<float>(d);
      uint8_t free = 0;
      float conductance = 0.0f;
      if (d > hard) {
        // Keep the outermost ring blocked so that neighbour lookups never leave the grid.
        free = ix == 0 || iy == 0 || ix == width_ - 1 || iy == height_ - 1 ? 0 : 1;
        const double s = band_width > 0.0 ? smoothstep((d - hard) / band_width) : 1.0;
        conductance =
            static_cast<float>(params_.band_conductance + (1.0 - params_.band_conductance) * s);
      }
      if (changed && (free != free_[k] || conductance != conductance_[k])) changed->push_back(k);
      free_[k] = free;
      conductance_[k] = conductance;
    }
  }
}

size_t ConfigSpace::freeCount() const {
  return static_cast<size_t>(std::count(free_.begin(), free_.end(), uint8_t{1}));
}

}  // namespace wheelchair_planner
