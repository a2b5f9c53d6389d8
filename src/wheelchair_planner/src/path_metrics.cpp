#include <wheelchair_planner/path_metrics.h>

#include <cmath>
#include <limits>

namespace wheelchair_planner {

double pathLength(const std::vector<Pose2D>& path) {
  double length = 0.0;
  for (size_t i = 1; i < path.size(); ++i)
    length += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  return length;
}

void assignHeadings(std::vector<Pose2D>& path, double final_yaw) {
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const double dx = path[i + 1].x - path[i].x, dy = path[i + 1].y - path[i].y;
    path[i].yaw = (dx == 0.0 && dy == 0.0 && i > 0) ? path[i - 1].yaw : std::atan2(dy, dx);
  }
  if (!path.empty()) path.back().yaw = final_yaw;
}

namespace {

std::vector<Pose2D> resample(const std::vector<Pose2D>& path, double spacing) {
  std::vector<Pose2D> out;
  if (path.empty()) return out;
  out.push_back(path.front());
  double carried = 0.0;
  for (size_t i = 1; i < path.size(); ++i) {
    const double dx = path[i].x - path[i - 1].x, dy = path[i].y - path[i - 1].y;
    const double seg = std::hypot(dx, dy);
    double s = spacing - carried;
    while (s <= seg) {
      Pose2D p;
      p.x = path[i - 1].x + dx * s / seg;
      p.y = path[i - 1].y + dy * s / seg;
      out.push_back(p);
      s += spacing;
    }
    carried = seg - (s - spacing);
  }
  return out;
}

}  // namespace

double maxCurvature(const std::vector<Pose2D>& path, double spacing) {
  const std::vector<Pose2D> p = resample(path, spacing);
  double kappa = 0.0;
  for (size_t i = 2; i < p.size(); ++i) {
    const double h0 = std::atan2(p[i - 1].y - p[i - 2].y, p[i - 1].x - p[i - 2].x);
    const double h1 = std::atan2(p[i].y - p[i - 1].y, p[i].x - p[i - 1].x);
    const double turn = std::abs(std::remainder(h1 - h0, 2.0 * M_PI));
    kappa = std::max(kappa, turn / spacing);
  }
  return kappa;
}

void fillPathFigures(const ConfigSpace& cs, const std::vector<Pose2D>& path, Certificate& cert) {
  cert.length = pathLength(path);
  cert.max_curvature = maxCurvature(path);
  cert.clearance.clear();
  cert.min_clearance = std::numeric_limits<double>::infinity();
  for (const Pose2D& p : path) {
    const double c = cs.clearanceAt(p.x, p.y);
    cert.clearance.push_back(c);
    if (c < cert.min_clearance) {
      cert.min_clearance = c;
      cert.min_clearance_x = p.x;
      cert.min_clearance_y = p.y;
    }
  }
  if (path.empty()) cert.min_clearance = 0.0;
}

bool pathIsCollisionFree(const ConfigSpace& cs, const std::vector<Pose2D>& path) {
  for (size_t i = 0; i < path.size(); ++i) {
    const Pose2D& a = i == 0 ? path[0] : path[i - 1];
    const Pose2D& b = path[i];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int n = std::max(1, static_cast<int>(std::ceil(4.0 * len / cs.resolution())));
    for (int k = 0; k <= n; ++k) {
      int ix, iy;
      const double t = static_cast<double>(k) / n;
      const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
      if (!cs.worldToCell(x, y, ix, iy) ||
          cs.clearanceAt(x, y) < cs.params().min_clearance - 0.5 * cs.resolution()) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace wheelchair_planner
