#include <wheelchair_core/polygon.h>
#include <wheelchair_navigator/route.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace wheelchair_navigator {

namespace {

/// How far ahead of the cursor the nearest vertex is searched [m]: a route never comes back
/// this close to itself within one such window in the worlds the chair drives (doorways,
/// loops round furniture), and a chair moves far less than this between two poses.
constexpr double kSearchWindow = 3.0;

/// Occupied in the nav_msgs convention.
bool occupied(int8_t value) { return value >= 50; }

}  // namespace

Route::Route(std::vector<Pose2D> poses) : poses_(std::move(poses)) {
  along_.reserve(poses_.size());
  double s = 0.0;
  for (size_t i = 0; i < poses_.size(); ++i) {
    if (i > 0) s += (poses_[i].position() - poses_[i - 1].position()).norm();
    along_.push_back(s);
  }
}

double Route::advance(const Pose2D& pose) {
  if (poses_.empty()) return 0.0;
  const Eigen::Vector2d here = pose.position();
  size_t best = cursor_;
  double best_d = (poses_[cursor_].position() - here).squaredNorm();
  for (size_t i = cursor_ + 1; i < poses_.size() && along_[i] - along_[cursor_] < kSearchWindow;
       ++i) {
    const double d = (poses_[i].position() - here).squaredNorm();
    if (d < best_d) best_d = d, best = i;
  }
  cursor_ = best;
  return length() - along_[cursor_] + std::sqrt(best_d);
}

Eigen::Vector2d Route::pointAt(double distance) const {
  if (poses_.empty()) return Eigen::Vector2d::Constant(NAN);
  if (distance <= 0.0) return poses_.front().position();
  for (size_t i = 1; i < poses_.size(); ++i) {
    if (along_[i] >= distance) {
      const double step = along_[i] - along_[i - 1];
      const double f = step > 0.0 ? (distance - along_[i - 1]) / step : 0.0;
      return poses_[i - 1].position() + f * (poses_[i].position() - poses_[i - 1].position());
    }
  }
  return poses_.back().position();
}

std::vector<Eigen::Vector2d> Route::stretch(double from, double to) const {
  std::vector<Eigen::Vector2d> out;
  if (poses_.empty() || to < from) return out;
  out.push_back(pointAt(from));
  for (size_t i = 0; i < poses_.size(); ++i)
    if (along_[i] > from && along_[i] < to) out.push_back(poses_[i].position());
  out.push_back(pointAt(to));
  return out;
}

double distanceToStretch(const std::vector<Pose2D>& path,
                         const std::vector<Eigen::Vector2d>& stretch, double horizon) {
  double best = std::numeric_limits<double>::infinity();
  if (path.empty() || stretch.empty()) return best;
  double walked = 0.0;
  for (size_t i = 0; i < path.size() && walked <= horizon; ++i) {
    if (i > 0) walked += (path[i].position() - path[i - 1].position()).norm();
    const Eigen::Vector2d p = path[i].position();
    if (stretch.size() == 1) best = std::min(best, (p - stretch[0]).norm());
    for (size_t k = 0; k + 1 < stretch.size(); ++k)
      best = std::min(best, wheelchair_core::pointSegmentDistance(p, stretch[k], stretch[k + 1]));
  }
  return best;
}

std::optional<Eigen::Vector2d> layerObstacleAhead(const Route& route,
                                                  const wheelchair_core::OccupancyMap& layer,
                                                  const wheelchair_core::OccupancyMap& static_map,
                                                  double lookahead, double corridor) {
  if (route.empty() || layer.width <= 0 || !(layer.resolution > 0.0)) return std::nullopt;
  const double step = layer.resolution / 2;
  const int reach = static_cast<int>(std::ceil(corridor / layer.resolution));
  const double start = route.cursorAlong();
  const double end = std::min(route.length(), start + lookahead);
  for (double s = start; s <= end; s += step) {
    const Eigen::Vector2d p = route.pointAt(s);
    int cx, cy;
    if (!layer.worldToCell(p.x(), p.y(), cx, cy)) continue;
    for (int dy = -reach; dy <= reach; ++dy) {
      for (int dx = -reach; dx <= reach; ++dx) {
        const int ix = cx + dx, iy = cy + dy;
        if (!layer.inBounds(ix, iy) || !occupied(layer.at(ix, iy))) continue;
        double x, y;
        layer.cellToWorld(ix, iy, x, y);
        if ((Eigen::Vector2d(x, y) - p).norm() > corridor) continue;
        int sx, sy;
        const bool mapped = static_map.width > 0 && static_map.worldToCell(x, y, sx, sy) &&
                            occupied(static_map.at(sx, sy));
        if (!mapped) return Eigen::Vector2d(x, y);
      }
    }
  }
  return std::nullopt;
}

}  // namespace wheelchair_navigator
