#include <wheelchair_controller/smooth_path.h>
#include <wheelchair_core/polygon.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_controller {
namespace {

constexpr double kMinPointSpacing = 1e-4;  // [m] consecutive points closer are duplicates

std::vector<Eigen::Vector2d> distinctPoints(const std::vector<Pose2D>& poses) {
  std::vector<Eigen::Vector2d> out;
  for (const Pose2D& p : poses) {
    const Eigen::Vector2d xy = p.position();
    if (out.empty() || (xy - out.back()).norm() > kMinPointSpacing) out.push_back(xy);
  }
  return out;
}

double polylineLength(const std::vector<Eigen::Vector2d>& pts) {
  double len = 0.0;
  for (size_t i = 1; i < pts.size(); ++i) len += (pts[i] - pts[i - 1]).norm();
  return len;
}

/// Points every `spacing` metres along the polyline (first and last kept).
std::vector<Eigen::Vector2d> resample(const std::vector<Eigen::Vector2d>& pts, double spacing) {
  const double len = polylineLength(pts);
  const int n = std::max(2, static_cast<int>(std::ceil(len / spacing)) + 1);
  const double step = len / (n - 1);
  std::vector<Eigen::Vector2d> out{pts.front()};
  size_t seg = 1;
  double seg_start = 0.0;
  for (int i = 1; i < n - 1; ++i) {
    const double s = i * step;
    while (seg < pts.size() - 1 && seg_start + (pts[seg] - pts[seg - 1]).norm() < s) {
      seg_start += (pts[seg] - pts[seg - 1]).norm();
      ++seg;
    }
    const double seg_len = (pts[seg] - pts[seg - 1]).norm();
    const double f = std::clamp((s - seg_start) / seg_len, 0.0, 1.0);
    out.push_back(pts[seg - 1] + f * (pts[seg] - pts[seg - 1]));
  }
  out.push_back(pts.back());
  return out;
}

/// Centred moving average with a window shrinking at the ends (ends fixed).
template <typename T>
std::vector<T> movingAverage(const std::vector<T>& x, int half_window) {
  std::vector<T> out(x.size());
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < n; ++i) {
    const int w = std::min({half_window, i, n - 1 - i});
    T sum = x[i] * 0.0;
    for (int k = -w; k <= w; ++k) sum += x[i + k];
    out[i] = sum / static_cast<double>(2 * w + 1);
  }
  return out;
}

/// Central difference of a uniformly sampled sequence (one-sided at the ends).
std::vector<double> derivative(const std::vector<double>& x, double h) {
  const size_t n = x.size();
  std::vector<double> d(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? i : i + 1;
    d[i] = (x[b] - x[a]) / ((b - a) * h);
  }
  return d;
}

}  // namespace

std::string pathRejectionReason(const std::vector<Pose2D>& poses, double min_length) {
  if (poses.empty()) return "empty path";
  for (const Pose2D& p : poses)
    if (!p.isFinite()) return "non-finite pose in path";
  if (polylineLength(distinctPoints(poses)) < min_length) return "zero-length path";
  return "";
}

SmoothPath::SmoothPath(const std::vector<Pose2D>& poses, double spacing,
                       double smoothing_half_window, const CuspEnds& cusps)
    : spacing_(spacing) {
  const std::string reason = pathRejectionReason(poses, 2.0 * kMinPointSpacing);
  if (!reason.empty()) throw std::invalid_argument("SmoothPath: " + reason);
  planned_ = distinctPoints(poses);
  goal_heading_ = poses.back().yaw;
  const int half = std::max(0, static_cast<int>(std::round(smoothing_half_window / spacing)));
  std::vector<Eigen::Vector2d> pts = resample(planned_, spacing);
  // A cusp end is extended by the point reflection of the path's last metres through the end
  // point (an odd extension): the symmetric smoothing then keeps the end point exactly, where
  // the next piece starts, and the curvature falls smoothly to zero there (no ragged curvature
  // of a shrinking window), so the chair stops and starts on a straight.
  const size_t extension = 2 * static_cast<size_t>(half);
  const auto reflected = [&](const Eigen::Vector2d& end, auto first, auto last) {
    std::vector<Eigen::Vector2d> out;
    for (auto it = first; it != last && out.size() < extension; ++it)
      out.push_back(2.0 * end - *it);
    return out;
  };
  std::vector<Eigen::Vector2d> before, after;
  if (cusps.start) {
    before = reflected(pts.front(), pts.begin() + 1, pts.end());
    std::reverse(before.begin(), before.end());
  }
  if (cusps.end) after = reflected(pts.back(), pts.rbegin() + 1, pts.rend());
  const size_t n = pts.size();
  pts.insert(pts.begin(), before.begin(), before.end());
  pts.insert(pts.end(), after.begin(), after.end());
  // Smooth twice (a triangular kernel), then resample so the spacing is uniform again.
  pts = movingAverage(movingAverage(pts, half), half);
  pts = std::vector<Eigen::Vector2d>(pts.begin() + before.size(), pts.begin() + before.size() + n);
  pts = resample(pts, spacing);
  const double h = polylineLength(pts) / (pts.size() - 1);

  std::vector<double> xs, ys;
  for (const auto& p : pts) {
    xs.push_back(p.x());
    ys.push_back(p.y());
  }
  const std::vector<double> dx = derivative(xs, h), dy = derivative(ys, h);
  std::vector<double> heading(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    heading[i] = std::atan2(dy[i], dx[i]);
    if (i > 0) {  // unwrap
      heading[i] = heading[i - 1] + std::remainder(heading[i] - heading[i - 1], 2.0 * M_PI);
    }
  }
  const std::vector<double> kappa = movingAverage(derivative(heading, h), 1);
  const std::vector<double> kappa_rate = movingAverage(derivative(kappa, h), 1);
  for (size_t i = 0; i < pts.size(); ++i)
    points_.push_back({i * h, pts[i], heading[i], kappa[i], kappa_rate[i]});
}

PathPoint SmoothPath::at(double s) const {
  const double step = points_[1].s - points_[0].s;
  const double pos = std::clamp(s, 0.0, length()) / step;
  const size_t i = std::min(static_cast<size_t>(pos), points_.size() - 2);
  const double f = std::clamp(pos - i, 0.0, 1.0);
  const PathPoint &a = points_[i], &b = points_[i + 1];
  PathPoint p;
  p.s = std::clamp(s, 0.0, length());
  p.position = a.position + f * (b.position - a.position);
  p.heading = a.heading + f * (b.heading - a.heading);
  p.curvature = a.curvature + f * (b.curvature - a.curvature);
  p.curvature_rate = a.curvature_rate + f * (b.curvature_rate - a.curvature_rate);
  return p;
}

double SmoothPath::distanceToPlanned(const Eigen::Vector2d& point) const {
  if (planned_.size() == 1) return (point - planned_.front()).norm();
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 1; i < planned_.size(); ++i)
    best =
        std::min(best, wheelchair_core::pointSegmentDistance(point, planned_[i - 1], planned_[i]));
  return best;
}

}  // namespace wheelchair_controller
