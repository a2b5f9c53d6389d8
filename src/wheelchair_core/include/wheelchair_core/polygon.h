// Planar geometry on points and polygons: the chair's footprint, obstacle outlines, paths. The
// one place for point-to-segment distance, point-in-polygon and bounding boxes.
#pragma once

#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace wheelchair_core {

/// A polygon's vertices in order (the chair's footprint: base_link frame, x forward, y left).
using Polygon = std::vector<Eigen::Vector2d>;

/// Distance from `p` to the segment [a, b]; `along` (if given) receives the distance from `a`
/// along the segment to the point nearest to `p`.
double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b, double* along = nullptr);

/// True if `p` lies inside `polygon` (even-odd rule; points on an edge may go either way).
bool insidePolygon(const Polygon& polygon, const Eigen::Vector2d& p);

/// Distance from `p` to the nearest edge of `polygon` (inside or outside).
double distanceToBoundary(const Polygon& polygon, const Eigen::Vector2d& p);

/// Axis-aligned bounds of a set of points.
struct Box {
  Eigen::Vector2d min{1e300, 1e300};
  Eigen::Vector2d max{-1e300, -1e300};
  bool empty() const { return min.x() > max.x(); }
};
Box boundingBox(const std::vector<Eigen::Vector2d>& points);

/// Twice the signed area (> 0: counter-clockwise).
double signedArea2(const Polygon& polygon);

/// Empty if `polygon` can serve as a footprint: at least 3 finite vertices, a non-zero area,
/// and (if `origin_inside`) the frame origin inside it; else the reason.
std::string polygonProblem(const Polygon& polygon, bool origin_inside = false);

/// Largest distance of a vertex from the frame origin (the radius a body swings through).
double circumscribedRadius(const Polygon& polygon);

/// Distance from the frame origin to the nearest edge (the largest disc about the origin inside
/// the polygon when the origin is inside).
double inscribedRadius(const Polygon& polygon);

/// The polygon placed at `pose` (its vertices in the pose's parent frame).
Polygon transformPolygon(const Polygon& polygon, const Pose2D& pose);

}  // namespace wheelchair_core
