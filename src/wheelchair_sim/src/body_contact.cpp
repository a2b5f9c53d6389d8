#include <wheelchair_sim/body_contact.h>
#include <wheelchair_sim/free_threshold.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_sim {

namespace core = wheelchair_core;

BodyContact::BodyContact(const core::Polygon& footprint,
                         std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world) {
  if (footprint.size() < 3) throw std::invalid_argument("footprint needs >= 3 vertices");
  if (!world) throw std::invalid_argument("BodyContact needs a world grid");
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
  const core::Box box = core::boundingBox(footprint);
  for (double x = box.min.x() + 0.5 * res; x < box.max.x(); x += res) {
    for (double y = box.min.y() + 0.5 * res; y < box.max.y(); y += res) {
      if (core::insidePolygon(footprint, {x, y})) interior_.emplace_back(x, y);
    }
  }
}

bool BodyContact::anyBlocked(const std::vector<Eigen::Vector2d>& samples,
                             const core::Pose2D& pose) const {
  for (const auto& sample : samples) {
    const Eigen::Vector2d p = core::transformPoint(pose, sample);
    const int ix = static_cast<int>(std::floor((p.x() - x_min_) / resolution_));
    const int iy = static_cast<int>(std::floor((p.y() - y_min_) / resolution_));
    if (ix < 0 || iy < 0 || ix >= size_x_ || iy >= size_y_) return true;
    if (blocked_[static_cast<size_t>(iy) * size_x_ + ix]) return true;
  }
  return false;
}

bool BodyContact::outlineTouches(const core::Pose2D& pose) const {
  return anyBlocked(outline_, pose);
}

bool BodyContact::touches(const core::Pose2D& pose) const {
  return anyBlocked(outline_, pose) || anyBlocked(interior_, pose);
}

}  // namespace wheelchair_sim
