#include <wheelchair_controller/output_trajectory.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace wheelchair_controller {
namespace {

Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
Eigen::Vector2d normal(double angle) { return {-std::sin(angle), std::cos(angle)}; }

double limitFor(double rate, double limit, double power) {
  constexpr double kTiny = 1e-9;
  return std::abs(rate) < kTiny ? std::numeric_limits<double>::infinity()
                                : std::pow(limit / std::abs(rate), power);
}

}  // namespace

std::vector<double> curvatureSpeedLimit(const SmoothPath& path, const PathLimits& limits) {
  std::vector<double> v;
  for (const PathPoint& p : path.points()) {
    v.push_back(
        std::min({limits.longitudinal.speed, limitFor(p.curvature, limits.lateral_accel, 0.5),
                  limitFor(p.curvature, limits.yaw_rate, 1.0),
                  limitFor(p.curvature_rate, limits.lateral_jerk, 1.0 / 3.0)}));
  }
  return v;
}

OutputReference pointAheadReference(const Eigen::Vector2d& position, double heading, double v,
                                    double a, double w, double w_dot, double lookahead) {
  const Eigen::Vector2d t = unit(heading), n = normal(heading);
  OutputReference r;
  r.position = position + lookahead * t;
  r.velocity = v * t + lookahead * w * n;
  // d/dt (v t + L w n) = a t + v w n + L w_dot n - L w^2 t.
  r.acceleration = (a - lookahead * w * w) * t + (v * w + lookahead * w_dot) * n;
  return r;
}

namespace {

/// Body motion on the path at time t: point, speed, accel, yaw rate and yaw acceleration.
struct BodyMotion {
  PathPoint point;
  double v, a, w, w_dot;
};
BodyMotion bodyMotion(const SmoothPath& path, const JerkLimitedProfile& profile, double t) {
  const ProfileSample m = profile.at(t);
  const PathPoint p = path.at(m.s);
  // w = kappa s_dot, w_dot = kappa' s_dot^2 + kappa s_ddot.
  return {p, m.v, m.a, p.curvature * m.v, p.curvature_rate * m.v * m.v + p.curvature * m.a};
}

}  // namespace

RiderComfort riderComfort(const SmoothPath& path, const JerkLimitedProfile& profile,
                          double rider_offset, double accel_limit, double jerk_limit, double step) {
  RiderComfort c;
  Eigen::Vector2d previous = Eigen::Vector2d::Zero();
  for (double t = 0.0; t <= profile.duration() + step; t += step) {
    const BodyMotion b = bodyMotion(path, profile, t);
    // The rider point behind the axle: pointAheadReference with a negative offset.
    const Eigen::Vector2d acc = pointAheadReference(b.point.position, b.point.heading, b.v, b.a,
                                                    b.w, b.w_dot, -rider_offset)
                                    .acceleration;
    const double jerk = t > 0.0 ? (acc - previous).norm() / step : 0.0;
    previous = acc;
    c.max_accel = std::max(c.max_accel, acc.norm());
    c.max_jerk = std::max(c.max_jerk, jerk);
    if (acc.norm() > accel_limit || jerk > jerk_limit) c.violations.push_back(b.point.s);
  }
  return c;
}

PathOutputTrajectory::PathOutputTrajectory(std::shared_ptr<const SmoothPath> path, double lookahead,
                                           double rider_offset, const PathLimits& limits,
                                           double margin, double initial_speed)
    : path_(std::move(path)), lookahead_(lookahead) {
  PathLimits nominal = limits;
  nominal.longitudinal.accel *= margin;
  nominal.longitudinal.jerk *= margin;
  nominal.lateral_accel *= margin;
  nominal.lateral_jerk *= margin;
  const double check = margin + 0.1;  // the nominal longitudinal limits stay below it
  std::vector<double> speed_limit = curvatureSpeedLimit(*path_, nominal);
  constexpr int kIterations = 8;
  constexpr double kSlowdown = 0.8, kSpread = 0.5;  // factor, [m] around a violation
  const double spacing = path_->length() / (speed_limit.size() - 1);
  for (int it = 0; it < kIterations; ++it) {
    profile_ = std::make_unique<JerkLimitedProfile>(path_->length(), speed_limit,
                                                    nominal.longitudinal, initial_speed);
    const RiderComfort c =
        riderComfort(*path_, *profile_, rider_offset, check * limits.longitudinal.accel,
                     check * limits.longitudinal.jerk);
    if (c.violations.empty()) break;
    std::vector<bool> slow(speed_limit.size(), false);
    for (double s : c.violations) {
      const int lo = std::max(0, static_cast<int>((s - kSpread) / spacing));
      const int hi = std::min(static_cast<int>(speed_limit.size()) - 1,
                              static_cast<int>((s + kSpread) / spacing) + 1);
      for (int i = lo; i <= hi; ++i) slow[i] = true;
    }
    for (size_t i = 0; i < speed_limit.size(); ++i)
      if (slow[i]) speed_limit[i] *= kSlowdown;
  }
}

// Body on the path: v = s_dot, yaw rate w = kappa s_dot, w_dot = kappa' s_dot^2 + kappa s_ddot.
OutputReference PathOutputTrajectory::at(double t) const {
  const BodyMotion b = bodyMotion(*path_, *profile_, t);
  return pointAheadReference(b.point.position, b.point.heading, b.v, b.a, b.w, b.w_dot, lookahead_);
}

double PathOutputTrajectory::heading(double t) const {
  return path_->at(profile_->at(t).s).heading;
}

RotationOutputTrajectory::RotationOutputTrajectory(const Eigen::Vector2d& centre, double theta0,
                                                   double theta1, double lookahead,
                                                   const MotionLimits& limits)
    : centre_(centre), theta0_(theta0), lookahead_(lookahead) {
  const double delta = std::remainder(theta1 - theta0, 2.0 * M_PI);
  direction_ = delta >= 0.0 ? 1.0 : -1.0;
  constexpr double kMinAngle = 1e-4;
  if (std::abs(delta) > kMinAngle)
    profile_ = std::make_unique<JerkLimitedProfile>(
        std::abs(delta), std::vector<double>{limits.speed, limits.speed}, limits);
}

OutputReference RotationOutputTrajectory::at(double t) const {
  const ProfileSample m = profile_ ? profile_->at(t) : ProfileSample{};
  return pointAheadReference(centre_, theta0_ + direction_ * m.s, 0.0, 0.0, direction_ * m.v,
                             direction_ * m.a, lookahead_);
}

double RotationOutputTrajectory::heading(double t) const {
  return theta0_ + direction_ * (profile_ ? profile_->at(t).s : 0.0);
}

}  // namespace wheelchair_controller
