#include <wheelchair_slam/correlative_search.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_slam {

LikelihoodGrid::LikelihoodGrid(const Points& points, double resolution, double sigma)
    : resolution_(resolution) {
  if (points.empty()) return;
  Eigen::Vector2d lo = points.front(), hi = points.front();
  for (const Eigen::Vector2d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double margin = 3.0 * sigma + resolution;
  origin_ = lo - Eigen::Vector2d(margin, margin);
  width_ = static_cast<int>(std::ceil((hi.x() - lo.x() + 2 * margin) / resolution)) + 1;
  height_ = static_cast<int>(std::ceil((hi.y() - lo.y() + 2 * margin) / resolution)) + 1;
  cells_.assign(static_cast<size_t>(width_) * height_, 0.0f);
  const int reach = static_cast<int>(std::ceil(3.0 * sigma / resolution));
  const double inv2s2 = 1.0 / (2.0 * sigma * sigma);
  for (const Eigen::Vector2d& p : points) {
    const int cx = static_cast<int>(std::floor((p.x() - origin_.x()) / resolution));
    const int cy = static_cast<int>(std::floor((p.y() - origin_.y()) / resolution));
    for (int y = std::max(0, cy - reach); y <= std::min(height_ - 1, cy + reach); ++y) {
      for (int x = std::max(0, cx - reach); x <= std::min(width_ - 1, cx + reach); ++x) {
        const Eigen::Vector2d c = origin_ + resolution * Eigen::Vector2d(x + 0.5, y + 0.5);
        const float v = static_cast<float>(std::exp(-(c - p).squaredNorm() * inv2s2));
        float& cell = cells_[static_cast<size_t>(y) * width_ + x];
        cell = std::max(cell, v);
      }
    }
  }
}

double LikelihoodGrid::at(const Eigen::Vector2d& p) const {
  const int x = static_cast<int>(std::floor((p.x() - origin_.x()) / resolution_));
  const int y = static_cast<int>(std::floor((p.y() - origin_.y()) / resolution_));
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return 0.0;
  return cells_[static_cast<size_t>(y) * width_ + x];
}

double LikelihoodGrid::score(const Points& points, const wheelchair_core::Pose2D& pose) const {
  if (points.empty()) return 0.0;
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points) sum += at(wheelchair_core::transformPoint(pose, p));
  return sum / static_cast<double>(points.size());
}

SearchResult correlativeSearch(const LikelihoodGrid& grid, const Points& points,
                               const wheelchair_core::Pose2D& guess, const SearchWindow& window) {
  SearchResult best;
  best.pose = guess;
  if (points.empty() || grid.width() == 0) return best;
  const double res = grid.resolution();
  const int nxy = static_cast<int>(std::round(window.xy / res));
  const int nyaw = static_cast<int>(std::round(window.yaw / window.step_yaw));
  const int side = 2 * nxy + 1;
  struct Candidate {
    int yaw, dx, dy;
    double score;
  };
  std::vector<Candidate> tops;  // best of each yaw
  std::vector<int> offsets(points.size());
  std::vector<double> sums(static_cast<size_t>(side) * side);
  for (int k = -nyaw; k <= nyaw; ++k) {
    const double yaw = guess.yaw + k * window.step_yaw;
    const double c = std::cos(yaw), s = std::sin(yaw);
    std::fill(sums.begin(), sums.end(), 0.0);
    for (const Eigen::Vector2d& p : points) {
      const double wx = guess.x + c * p.x() - s * p.y();
      const double wy = guess.y + s * p.x() + c * p.y();
      const int cx = static_cast<int>(std::floor((wx - grid.origin().x()) / res));
      const int cy = static_cast<int>(std::floor((wy - grid.origin().y()) / res));
      for (int dy = -nxy; dy <= nxy; ++dy) {
        const int y = cy + dy;
        if (y < 0 || y >= grid.height()) continue;
        const float* row = grid.row(y);
        double* out = sums.data() + static_cast<size_t>(dy + nxy) * side;
        const int x0 = std::max(0, cx - nxy), x1 = std::min(grid.width() - 1, cx + nxy);
        for (int x = x0; x <= x1; ++x) out[x - cx + nxy] += row[x];
      }
    }
    const auto it = std::max_element(sums.begin(), sums.end());
    const int idx = static_cast<int>(it - sums.begin());
    tops.push_back({k, idx % side - nxy, idx / side - nxy, *it / points.size()});
  }
  const auto top =
      std::max_element(tops.begin(), tops.end(),
                       [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  best.score = top->score;
  const double yaw = guess.yaw + top->yaw * window.step_yaw;
  best.pose = {guess.x + top->dx * res, guess.y + top->dy * res,
               wheelchair_core::normalizeAngle(yaw)};
  for (const Candidate& t : tops) {
    const bool far = std::abs(t.yaw - top->yaw) > 3 || std::abs(t.dx - top->dx) > 3 ||
                     std::abs(t.dy - top->dy) > 3;
    if (far) best.second_score = std::max(best.second_score, t.score);
  }
  return best;
}

}  // namespace wheelchair_slam
