#include <wheelchair_display/map_view.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_display {

Orientation orientationNamed(const std::string& name) {
  if (name == "north_up") return Orientation::kNorthUp;
  if (name == "chair_up") return Orientation::kChairUp;
  throw std::invalid_argument("unknown orientation '" + name + "' (known: north_up, chair_up)");
}

Eigen::Vector2d ViewTransform::toScreen(const Eigen::Vector2d& world) const {
  const Eigen::Vector2d q = Eigen::Rotation2Dd(rotation) * (world - world_centre);
  return screen_centre + scale * Eigen::Vector2d(q.x(), -q.y());
}

Eigen::Vector2d ViewTransform::toWorld(const Eigen::Vector2d& screen) const {
  const Eigen::Vector2d d = (screen - screen_centre) / scale;
  return world_centre + Eigen::Rotation2Dd(-rotation) * Eigen::Vector2d(d.x(), -d.y());
}

double viewRotation(Orientation orientation, double chair_yaw) {
  return orientation == Orientation::kNorthUp ? 0.0 : 0.5 * M_PI - chair_yaw;
}

ViewTransform fitView(const Rect& viewport, const std::vector<Eigen::Vector2d>& frame,
                      double rotation, double margin_px, double min_extent) {
  ViewTransform view;
  view.rotation = rotation;
  view.screen_centre = {viewport.centreX(), viewport.centreY()};
  if (frame.empty()) {
    view.scale = std::max(1.0, (std::min(viewport.w, viewport.h) - 2 * margin_px) / min_extent);
    return view;
  }
  const Eigen::Rotation2Dd turn(rotation);
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& p : frame) {
    const Eigen::Vector2d q = turn * p;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(Eigen::Vector2d(min_extent, min_extent));
  const double usable_w = std::max(1.0, viewport.w - 2 * margin_px);
  const double usable_h = std::max(1.0, viewport.h - 2 * margin_px);
  view.scale = std::min(usable_w / extent.x(), usable_h / extent.y());
  view.world_centre = turn.inverse() * (0.5 * (lo + hi));
  return view;
}

}  // namespace wheelchair_display
