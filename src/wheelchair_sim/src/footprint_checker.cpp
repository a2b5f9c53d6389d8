#include <wheelchair_sim/footprint_checker.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_sim {

bool insidePolygon(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

FootprintChecker::FootprintChecker(std::vector<Eigen::Vector2d> footprint,
                                   std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world) {
  if (footprint.size() < 3) throw std::invalid_argument("footprint needs >= 3 vertices");
  if (!world) throw std::invalid_argument("FootprintChecker needs a world grid");
  x_min_ = world->getXMin();
  y_min_ = world->getYMin();
  resolution_ = world->getResolution();
  size_x_ = static_cast<int>(world->getSizeX());
  size_y_ = static_cast<int>(world->getSizeY());
  blocked_.resize(static_cast<size_t>(size_x_) * size_y_);
  for (int iy = 0; iy < size_y_; ++iy) {
    for (int ix = 0; ix < size_x_; ++ix) {
      blocked_[static_cast<size_t>(iy) * size_x_ + ix] = world->getCell(ix, iy) < kFreeThreshold;
    }
  }
  const double res = resolution_;
  // Edges every half cell: nothing thicker than a cell can slip between two samples.
  for (size_t i = 0; i < footprint.size(); ++i) {
    const Eigen::Vector2d a = footprint[i];
    const Eigen::Vector2d b = footprint[(i + 1) % footprint.size()];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * res))));
    for (int k = 0; k < n; ++k) outline_.push_back(a + (b - a) * (double(k) / n));
  }
  // Interior every cell: catches obstacles already inside after a teleport.
  Eigen::Vector2d lo = footprint[0], hi = footprint[0];
  for (const auto& v : footprint) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (double x = lo.x() + 0.5 * res; x < hi.x(); x += res) {
    for (double y = lo.y() + 0.5 * res; y < hi.y(); y += res) {
      if (insidePolygon(footprint, {x, y})) interior_.emplace_back(x, y);
    }
  }
}

bool FootprintChecker::anyBlocked(const std::vector<Eigen::Vector2d>& samples,
                                  const Eigen::Vector3d& pose) const {
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  for (const auto& p : samples) {
    const double x = pose.x() + c * p.x() - s * p.y(), y = pose.y() + s * p.x() + c * p.y();
    const int ix = static_cast<int>(std::floor((x - x_min_) / resolution_));
    const int iy = static_cast<int>(std::floor((y - y_min_) / resolution_));
    if (ix < 0 || iy < 0 || ix >= size_x_ || iy >= size_y_) return true;
    if (blocked_[static_cast<size_t>(iy) * size_x_ + ix]) return true;
  }
  return false;
}

bool FootprintChecker::outlineCollides(const Eigen::Vector3d& pose) const {
  return anyBlocked(outline_, pose);
}

bool FootprintChecker::collides(const Eigen::Vector3d& pose) const {
  return anyBlocked(outline_, pose) || anyBlocked(interior_, pose);
}

}  // namespace wheelchair_sim
