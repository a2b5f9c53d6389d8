#include <wheelchair_planner/footprint_checker.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_planner {

using wheelchair_core::Polygon;

namespace {

/// The part of the polygon with x in [x0, x1] (Sutherland-Hodgman against the two lines): its
/// vertices span a convex hull that contains that part (also for a non-convex polygon).
Polygon clipToSlab(const Polygon& poly, double x0, double x1) {
  Polygon out = poly;
  for (const double sign : {1.0, -1.0}) {  // keep x >= x0, then x <= x1
    const double edge = sign > 0.0 ? x0 : x1;
    Polygon in;
    in.swap(out);
    for (size_t i = 0; i < in.size(); ++i) {
      const Eigen::Vector2d& a = in[i];
      const Eigen::Vector2d& b = in[(i + 1) % in.size()];
      const bool a_in = sign * (a.x() - edge) >= 0.0, b_in = sign * (b.x() - edge) >= 0.0;
      if (a_in) out.push_back(a);
      if (a_in != b_in) {
        const double t = (edge - a.x()) / (b.x() - a.x());
        out.emplace_back(edge, a.y() + t * (b.y() - a.y()));
      }
    }
  }
  return out;
}

/// A point of base_link placed at the pose whose heading has cosine c and sine s.
Eigen::Vector2d place(const Pose2D& pose, double c, double s, const Eigen::Vector2d& v) {
  return {pose.x + c * v.x() - s * v.y(), pose.y + s * v.x() + c * v.y()};
}

}  // namespace

FootprintChecker::FootprintChecker(const ConfigSpace& cspace, const Polygon& polygon)
    : cspace_(cspace), polygon_(polygon) {
  if (const std::string problem = wheelchair_core::polygonProblem(polygon, true); !problem.empty())
    throw std::invalid_argument("footprint: " + problem);
  const double res = cspace.resolution();
  // Boundary: every edge sampled at most half a cell apart, vertices included.
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * res))));
    for (int k = 0; k < n; ++k) boundary_.push_back(a + (static_cast<double>(k) / n) * (b - a));
  }
  // Arc length along the boundary to each sample (the skip in clearance()).
  double along = 0.0;
  for (size_t i = 0; i < boundary_.size(); ++i) {
    if (i > 0) along += (boundary_[i] - boundary_[i - 1]).norm();
    boundary_s_.push_back(along);
  }
  circumscribed_radius_ = wheelchair_core::circumscribedRadius(polygon);
  inscribed_radius_ = wheelchair_core::inscribedRadius(polygon);
  // Interior: a lattice of 0.7 cell spacing (every cell the polygon covers holds a sample),
  // grouped in columns of constant x.
  const wheelchair_core::Box box = wheelchair_core::boundingBox(polygon);
  const double x0 = box.min.x(), x1 = box.max.x(), y0 = box.min.y(), y1 = box.max.y();
  // Cover: slabs along x about half the body's width long, each in the disc about its bounding
  // box's centre through its farthest vertex (the maximum distance over a polygon is at one).
  const int slabs = std::max(1, static_cast<int>(std::ceil((x1 - x0) / (0.5 * (y1 - y0)))));
  for (int i = 0; i < slabs; ++i) {
    const Polygon part =
        clipToSlab(polygon, x0 + (x1 - x0) * i / slabs, x0 + (x1 - x0) * (i + 1) / slabs);
    if (part.empty()) continue;
    const wheelchair_core::Box b = wheelchair_core::boundingBox(part);
    Disc disc{0.5 * (b.min + b.max), 0.0};
    for (const Eigen::Vector2d& v : part)
      disc.radius = std::max(disc.radius, (v - disc.centre).norm());
    cover_.push_back(disc);
  }
  const double h = 0.7 * res;
  for (double x = x0 + 0.5 * h; x < x1; x += h) {
    Column col;
    for (double y = y0 + 0.5 * h; y < y1; y += h)
      if (wheelchair_core::insidePolygon(polygon, {x, y})) col.points.emplace_back(x, y);
    if (col.points.empty()) continue;
    col.centre = {x, 0.5 * (col.points.front().y() + col.points.back().y())};
    for (const Eigen::Vector2d& p : col.points)
      col.radius = std::max(col.radius, (p - col.centre).norm());
    columns_.push_back(std::move(col));
  }
}

FootprintContact FootprintChecker::clearance(const Pose2D& pose, double stop_below,
                                             double enough) const {
  // The enclosing disc (less the interpolation error): a lower bound of the body's clearance.
  const double bound =
      cspace_.distanceAt(pose.x, pose.y) - circumscribed_radius_ - 0.5 * cspace_.resolution();
  if (bound >= enough) return {bound, pose.x, pose.y};
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  if (enough < 1e9) {
    const FootprintContact covered = coverBound(pose, c, s);
    if (covered.clearance >= enough) return covered;
  }
  FootprintContact best;
  best.clearance = 1e9;
  // The interpolated distance field changes by at most sqrt(2) per metre (each axis by at most
  // 1): after a sample at distance d, the samples within (d - enough) / sqrt(2) of boundary
  // length are all at least `enough` away and are skipped (below `enough` the value is exact,
  // above it a lower bound: the skipped samples count with their bound).
  const size_t n = boundary_.size();
  FootprintContact skipped{1e9, 0.0, 0.0};
  for (size_t i = 0; i < n;) {
    const Eigen::Vector2d p = place(pose, c, s, boundary_[i]);
    const double d = cspace_.distanceAt(p.x(), p.y());
    if (d < best.clearance) {
      best = {d, p.x(), p.y()};
      if (d < stop_below) return best;
    }
    const double reach = boundary_s_[i] + (d - enough) * M_SQRT1_2;
    const size_t from = i;
    ++i;
    while (i < n && boundary_s_[i] < reach) ++i;
    if (i > from + 1) {
      const double bound = d - M_SQRT2 * (boundary_s_[i - 1] - boundary_s_[from]);
      if (bound < skipped.clearance) {
        const Eigen::Vector2d q = place(pose, c, s, boundary_[i - 1]);
        skipped = {bound, q.x(), q.y()};
      }
    }
  }
  if (skipped.clearance < best.clearance) best = skipped;
  // An obstacle cell wholly inside the body: the boundary does not see it, the interior does.
  for (const Column& col : columns_) {
    const Eigen::Vector2d centre = place(pose, c, s, col.centre);
    if (cspace_.cellDistanceAt(centre.x(), centre.y()) >= col.radius) continue;  // all free
    for (const Eigen::Vector2d& v : col.points) {
      const Eigen::Vector2d p = place(pose, c, s, v);
      if (cspace_.cellDistanceAt(p.x(), p.y()) <= 0.0) return {-cspace_.resolution(), p.x(), p.y()};
    }
  }
  return best;
}

FootprintContact FootprintChecker::coverBound(const Pose2D& pose, double c, double s) const {
  // A body point within r of a disc centre is at least (distance there - r) from obstacles;
  // half a cell less for the bilinear interpolation, as for the enclosing disc.
  FootprintContact worst;
  worst.clearance = 1e9;
  for (const Disc& d : cover_) {
    const Eigen::Vector2d p = place(pose, c, s, d.centre);
    const double bound = cspace_.distanceAt(p.x(), p.y()) - d.radius - 0.5 * cspace_.resolution();
    if (bound < worst.clearance) worst = {bound, p.x(), p.y()};
  }
  return worst;
}

}  // namespace wheelchair_planner
