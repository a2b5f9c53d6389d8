#include <wheelchair_core/polygon.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_core {

double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b, double* along) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  if (along) *along = t * std::sqrt(len2);
  return (a + t * ab - p).norm();
}

bool insidePolygon(const Polygon& poly, const Eigen::Vector2d& p) {
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

double distanceToBoundary(const Polygon& poly, const Eigen::Vector2d& p) {
  double best = INFINITY;
  for (size_t i = 0; i < poly.size(); ++i)
    best = std::min(best, pointSegmentDistance(p, poly[i], poly[(i + 1) % poly.size()]));
  return best;
}

Box boundingBox(const std::vector<Eigen::Vector2d>& points) {
  Box box;
  for (const Eigen::Vector2d& v : points) {
    box.min = box.min.cwiseMin(v);
    box.max = box.max.cwiseMax(v);
  }
  return box;
}

double signedArea2(const Polygon& poly) {
  double a = 0.0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& p = poly[i];
    const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a;
}

std::string polygonProblem(const Polygon& poly, bool origin_inside) {
  if (poly.size() < 3) return "a polygon needs at least 3 vertices";
  for (const Eigen::Vector2d& v : poly)
    if (!v.allFinite()) return "a polygon vertex is not finite";
  if (std::abs(signedArea2(poly)) < 1e-12) return "the polygon has no area";
  if (origin_inside && !insidePolygon(poly, Eigen::Vector2d::Zero()))
    return "the frame origin (base_link) must lie inside the polygon";
  return "";
}

double circumscribedRadius(const Polygon& poly) {
  double r = 0.0;
  for (const Eigen::Vector2d& v : poly) r = std::max(r, v.norm());
  return r;
}

double inscribedRadius(const Polygon& poly) {
  return distanceToBoundary(poly, Eigen::Vector2d::Zero());
}

Polygon transformPolygon(const Polygon& poly, const Pose2D& pose) {
  Polygon out;
  out.reserve(poly.size());
  for (const Eigen::Vector2d& v : poly) out.push_back(transformPoint(pose, v));
  return out;
}

}  // namespace wheelchair_core
