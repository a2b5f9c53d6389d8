#include <wheelchair_slam/scan_points.h>

namespace wheelchair_slam {

Points scanPoints(const wheelchair_core::LaserScan2D& scan, double max_range, double min_spacing) {
  Points out;
  out.reserve(scan.ranges.size());
  const double spacing2 = min_spacing * min_spacing;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const float r = scan.ranges[i];
    if (wheelchair_core::classifyBeam(r, scan) != wheelchair_core::Beam::kReturn) continue;
    if (r > max_range) continue;
    const double a = scan.angle(i);
    const Eigen::Vector2d p(r * std::cos(a), r * std::sin(a));
    if (!out.empty() && (p - out.back()).squaredNorm() < spacing2) continue;
    out.push_back(p);
  }
  return out;
}

void appendTransformed(const Points& points, const wheelchair_core::Pose2D& pose, Points& out) {
  out.reserve(out.size() + points.size());
  for (const Eigen::Vector2d& p : points) out.push_back(wheelchair_core::transformPoint(pose, p));
}

}  // namespace wheelchair_slam
