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
                                   std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world)
    : world_(std::move(world)) {
  if (footprint.size() < 3) throw std::invalid_argument("footprint needs >= 3 vertices");
  if (!world_) throw std::invalid_argument("FootprintChecker needs a world grid");
  const double res = world_->getResolution();
  // Edges every half cell: nothing thicker than a cell can slip between two samples.
  for (size_t i = 0; i < footprint.size(); ++i) {
    const Eigen::Vector2d a = footprint[i];
    const Eigen::Vector2d b = footprint[(i + 1) % footprint.size()];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * res))));
    for (int k = 0; k < n; ++k) samples_.push_back(a + (b - a) * (double(k) / n));
  }
  // Interior every cell: catches obstacles already inside after a teleport.
  Eigen::Vector2d lo = footprint[0], hi = footprint[0];
  for (const auto& v : footprint) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (double x = lo.x() + 0.5 * res; x < hi.x(); x += res) {
    for (double y = lo.y() + 0.5 * res; y < hi.y(); y += res) {
      if (insidePolygon(footprint, {x, y})) samples_.emplace_back(x, y);
    }
  }
}

bool FootprintChecker::blocked(double x, double y) const {
  const double res = world_->getResolution();
  const int ix = static_cast<int>(std::floor((x - world_->getXMin()) / res));
  const int iy = static_cast<int>(std::floor((y - world_->getYMin()) / res));
  if (ix < 0 || iy < 0 || ix >= static_cast<int>(world_->getSizeX()) ||
      iy >= static_cast<int>(world_->getSizeY())) {
    return true;
  }
  return world_->getCell(ix, iy) < kFreeThreshold;
}

bool FootprintChecker::collides(const Eigen::Vector3d& pose) const {
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  for (const auto& p : samples_) {
    if (blocked(pose.x() + c * p.x() - s * p.y(), pose.y() + s * p.x() + c * p.y())) return true;
  }
  return false;
}

}  // namespace wheelchair_sim
