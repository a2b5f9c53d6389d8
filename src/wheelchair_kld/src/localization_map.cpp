#include <wheelchair_kld/localization_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wheelchair_kld {

namespace {
constexpr float kOccupiedBelow = 0.35f;  // MRPT free-probability below which a cell is an obstacle
constexpr float kFreeAbove = 0.65f;      // ... above which it is known free

/// Exact 1-D squared Euclidean distance transform (Felzenszwalb & Huttenlocher 2012).
void distanceTransform1D(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
                         std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  const double inf = std::numeric_limits<double>::infinity();
  int k = 0;
  v[0] = 0;
  z[0] = -inf;
  z[1] = inf;
  for (int q = 1; q < n; ++q) {
    double s = ((f[q] + q * q) - (f[v[k]] + v[k] * v[k])) / (2.0 * (q - v[k]));
    while (s <= z[k]) {
      --k;
      s = ((f[q] + q * q) - (f[v[k]] + v[k] * v[k])) / (2.0 * (q - v[k]));
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = inf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    d[q] = (q - v[k]) * (q - v[k]) + f[v[k]];
  }
}
}  // namespace

LocalizationMap::LocalizationMap(const mrpt::maps::COccupancyGridMap2D& grid, double max_distance)
    : grid_(grid),
      size_x_(grid.getSizeX()),
      size_y_(grid.getSizeY()),
      x_min_(grid.getXMin()),
      y_min_(grid.getYMin()),
      resolution_(grid.getResolution()),
      inv_resolution_(1.0 / grid.getResolution()),
      max_distance_(max_distance) {
  if (size_x_ <= 0 || size_y_ <= 0) throw std::invalid_argument("empty grid map");
  const size_t n = static_cast<size_t>(size_x_) * size_y_;
  distance_.assign(n, 0.0f);
  free_mask_.assign(n, 0);
  std::vector<uint8_t> obstacle(n, 0);
  for (int iy = 0; iy < size_y_; ++iy)
    for (int ix = 0; ix < size_x_; ++ix) {
      const float p_free = grid_.getCell(ix, iy);
      const size_t i = static_cast<size_t>(iy) * size_x_ + ix;
      obstacle[i] = p_free < kOccupiedBelow;
      if (p_free > kFreeAbove) {
        free_mask_[i] = 1;
        free_cells_.push_back(static_cast<int>(i));
      }
    }
  // The distance is measured to the obstacles' surface cells (those with a non-obstacle
  // 4-neighbour), on both sides: the inside of a thick wall is as far from the surface a laser
  // sees as free space is. With distance 0 over the whole wall, endpoints that overshoot into a
  // wall cost nothing while short ones do, which biased the estimate towards the walls
  // (several cm in the simulator, where 180-degree scans see walls on one side).
  const double big = 1e12;
  std::vector<double> sq(n, big);
  auto obstacleAt = [&](int ix, int iy) {
    return ix < 0 || iy < 0 || ix >= size_x_ || iy >= size_y_ ||
           obstacle[static_cast<size_t>(iy) * size_x_ + ix];
  };
  for (int iy = 0; iy < size_y_; ++iy)
    for (int ix = 0; ix < size_x_; ++ix)
      if (obstacleAt(ix, iy) && !(obstacleAt(ix - 1, iy) && obstacleAt(ix + 1, iy) &&
                                  obstacleAt(ix, iy - 1) && obstacleAt(ix, iy + 1)))
        sq[static_cast<size_t>(iy) * size_x_ + ix] = 0.0;
  // Separable squared EDT: columns then rows.
  const int m = std::max(size_x_, size_y_);
  std::vector<double> f(m), d(m), z(m + 1);
  std::vector<int> v(m);
  for (int ix = 0; ix < size_x_; ++ix) {
    f.resize(size_y_);
    d.resize(size_y_);
    for (int iy = 0; iy < size_y_; ++iy) f[iy] = sq[static_cast<size_t>(iy) * size_x_ + ix];
    distanceTransform1D(f, d, v, z);
    for (int iy = 0; iy < size_y_; ++iy) sq[static_cast<size_t>(iy) * size_x_ + ix] = d[iy];
  }
  f.resize(size_x_);
  d.resize(size_x_);
  for (int iy = 0; iy < size_y_; ++iy) {
    std::copy_n(sq.begin() + static_cast<size_t>(iy) * size_x_, size_x_, f.begin());
    distanceTransform1D(f, d, v, z);
    for (int ix = 0; ix < size_x_; ++ix)
      distance_[static_cast<size_t>(iy) * size_x_ + ix] =
          static_cast<float>(std::min<double>(std::sqrt(d[ix]) * resolution_, max_distance_));
  }
}

mrpt::math::TPose2D LocalizationMap::sampleFreePose(mrpt::random::CRandomGenerator& rng) const {
  if (free_cells_.empty()) throw std::runtime_error("map has no free cells");
  const int cell = free_cells_[rng.drawUniform32bit() % free_cells_.size()];
  const int ix = cell % size_x_, iy = cell / size_x_;
  return mrpt::math::TPose2D(x_min_ + (ix + rng.drawUniform(0.0, 1.0)) * resolution_,
                             y_min_ + (iy + rng.drawUniform(0.0, 1.0)) * resolution_,
                             rng.drawUniform(-M_PI, M_PI));
}

double LocalizationMap::castRay(double x, double y, double angle, double max_range) const {
  const double step = 0.5 * resolution_;
  const double c = std::cos(angle) * step, s = std::sin(angle) * step;
  double r = 0;
  for (; r < max_range; r += step, x += c, y += s) {
    const int cell = cellIndex(x, y);
    if (cell < 0) return max_range;
    if (distance_[cell] == 0.0f) return r;
  }
  return max_range;
}

}  // namespace wheelchair_kld
