#include <wheelchair_core/polygon.h>
#include <wheelchair_safety/protective_field.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_safety {

std::string ProtectiveField::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.nonNegative("field/reaction_time", reaction_time)
      .positive("field/brake_decel", brake_decel)
      .positive("field/brake_jerk", brake_jerk)
      .nonNegative("field/drive_accel", drive_accel)
      .nonNegative("field/margin", margin)
      .nonNegative("field/front_offset", front_offset)
      .nonNegative("field/slowdown_length", slowdown_length)
      .nonNegative("field/view_tolerance", view_tolerance);
  return checks.result();
}

double ProtectiveField::stopDistance(double v) const {
  v = std::abs(v);
  const double a0 = drive_accel, a = brake_decel, j = brake_jerk, tr = reaction_time;
  // Reaction: still accelerating at a0.
  double d = v * tr + 0.5 * a0 * tr * tr;
  v += a0 * tr;
  // The jerk-limited brake: acceleration a0 -> 0 (the speed still grows by a0^2 / 2j) ...
  const double t1 = a0 / j;
  d += v * t1 + a0 * t1 * t1 / 2.0 - j * t1 * t1 * t1 / 6.0;
  v += a0 * a0 / (2.0 * j);
  // ... then 0 -> -a; at rest within that ramp if v <= a^2 / 2j ...
  if (v <= a * a / (2.0 * j)) return d + (2.0 / 3.0) * v * std::sqrt(2.0 * v / j) + margin;
  const double t2 = a / j;
  d += v * t2 - j * t2 * t2 * t2 / 6.0;
  v -= a * a / (2.0 * j);
  // ... then -a until rest.
  return d + v * v / (2.0 * a) + margin;
}

double ProtectiveField::maxStoppableSpeed(double distance) const {
  if (!(distance > stopDistance(0.0))) return 0.0;
  // stopDistance grows strictly with v: bisection.
  double lo = 0.0, hi = 1.0;
  while (stopDistance(hi) < distance && hi < 1e3) hi *= 2.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (stopDistance(mid) <= distance ? lo : hi) = mid;
  }
  return lo;
}

void readProtectiveField(wheelchair_core::ConfigReader& reader, ProtectiveField& field) {
  reader.read("field/reaction_time", field.reaction_time);
  reader.read("field/brake_decel", field.brake_decel);
  reader.read("field/brake_jerk", field.brake_jerk);
  reader.read("field/drive_accel", field.drive_accel);
  reader.read("field/margin", field.margin);
  reader.read("field/front_offset", field.front_offset);
  reader.read("field/slowdown_length", field.slowdown_length);
  reader.read("field/view_tolerance", field.view_tolerance);
}

std::vector<Eigen::Vector2d> pathAhead(const std::vector<Eigen::Vector2d>& path,
                                       const Eigen::Vector2d& here, double length) {
  std::vector<Eigen::Vector2d> ahead{here};
  if (path.empty()) return ahead;
  // From the nearest place on the path (not its nearest vertex, which may lie well behind).
  size_t start = 0;
  double best = (path[0] - here).norm();
  Eigen::Vector2d foot = path[0];
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    double along = 0.0;
    const double d = wheelchair_core::pointSegmentDistance(here, path[i], path[i + 1], &along);
    if (d < best) {
      best = d, start = i + 1;
      const double length_i = (path[i + 1] - path[i]).norm();
      foot = length_i > 0.0
                 ? Eigen::Vector2d(path[i] + (path[i + 1] - path[i]) * (along / length_i))
                 : path[i];
    }
  }
  ahead.push_back(foot);
  double travelled = (foot - here).norm();
  for (size_t i = start; i < path.size() && travelled < length; ++i) {
    travelled += (path[i] - ahead.back()).norm();
    ahead.push_back(path[i]);
  }
  return ahead;
}

double distanceAlongCorridor(const std::vector<Eigen::Vector2d>& ahead,
                             const Eigen::Vector2d& point, double half_width) {
  double walked = 0.0, nearest = INFINITY, at = INFINITY;
  for (size_t i = 0; i + 1 < ahead.size(); ++i) {
    double along = 0.0;
    const double dist =
        wheelchair_core::pointSegmentDistance(point, ahead[i], ahead[i + 1], &along);
    if (dist <= half_width && dist < nearest) nearest = dist, at = walked + along;
    walked += (ahead[i + 1] - ahead[i]).norm();
  }
  return at;
}

namespace {

/// Whether the laser sees `point` (map frame); if not, `why`.
bool sees(const wheelchair_core::LaserScan2D& scan, const wheelchair_core::Pose2D& laser_pose,
          const Eigen::Vector2d& point, double tolerance, const char** why) {
  const Eigen::Vector2d q =
      wheelchair_core::transformPoint(wheelchair_core::inverse(laser_pose), point);
  const double r = q.norm(), angle = std::atan2(q.y(), q.x());
  *why = "outside the field of view";
  if (scan.ranges.empty() || !(scan.angle_increment != 0.0)) return false;
  const long beam = std::lround((angle - scan.angle_min) / scan.angle_increment);
  if (beam < 0 || beam >= static_cast<long>(scan.ranges.size())) return false;
  const float range = scan.ranges[beam];
  switch (wheelchair_core::classifyBeam(range, scan)) {
    case wheelchair_core::Beam::kReturn:
      *why = "behind a return";
      return r <= range + tolerance;
    case wheelchair_core::Beam::kNoReturn:
      *why = "beyond the laser's range";
      return r <= scan.range_max;
    default:
      *why = "along an unusable beam";
      return false;  // too close, invalid, out of limits: nothing is known along that beam
  }
}

}  // namespace

double visibleLength(const std::vector<Eigen::Vector2d>& ahead,
                     const wheelchair_core::LaserScan2D& scan,
                     const wheelchair_core::Pose2D& laser_pose, double from, double tolerance,
                     const char** why) {
  const char* ignored = nullptr;
  if (why == nullptr) why = &ignored;
  *why = nullptr;
  constexpr double kStep = 0.05;
  // The path starts under the chair and passes the laser's face, where a few cm of pose jitter
  // between the chair's pose and the laser's (tf at two stamps) turn "just ahead" into
  // "behind": the check starts at the first point `from` beyond the axle and kFace ahead of
  // the laser.
  constexpr double kFace = 0.15;
  const wheelchair_core::Pose2D to_laser = wheelchair_core::inverse(laser_pose);
  bool started = false;
  double walked = 0.0;
  for (size_t i = 0; i + 1 < ahead.size(); ++i) {
    const Eigen::Vector2d a = ahead[i], d = ahead[i + 1] - ahead[i];
    const double length = d.norm();
    for (double s = 0.0; s < length; s += kStep) {
      const Eigen::Vector2d p = a + d * (s / length);
      if (!started) {
        if ((p - ahead.front()).norm() < from ||
            wheelchair_core::transformPoint(to_laser, p).x() < kFace)
          continue;
        started = true;
      }
      if (!sees(scan, laser_pose, p, tolerance, why)) return walked + s;
    }
    walked += length;
  }
  return walked;
}

}  // namespace wheelchair_safety
