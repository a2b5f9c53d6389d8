// Time-parametrized references for the output y = P_l: along a planned path (off-tracking
// compensated) and for a bounded in-place rotation.
#pragma once

#include <wheelchair_controller/motion_profile.h>
#include <wheelchair_controller/outer_law.h>
#include <wheelchair_controller/smooth_path.h>

#include <memory>

namespace wheelchair_controller {

/// Comfort limits of the path motion (of the axle centre P along the path).
struct PathLimits {
  MotionLimits longitudinal{0.8, 0.5, 1.0};  ///< speed [m/s], accel [m/s^2], jerk [m/s^3]
  double lateral_accel = 0.5;                ///< v^2 kappa [m/s^2]
  double lateral_jerk = 1.0;                 ///< v^3 dkappa/ds [m/s^3]
  double yaw_rate = 0.8;                     ///< v kappa [rad/s]
};

/// A reference for P_l over [0, duration()].
class OutputTrajectory {
 public:
  virtual ~OutputTrajectory() = default;
  virtual double duration() const = 0;
  /// Reference at time t; value and derivatives w.r.t. t.
  virtual OutputReference at(double t) const = 0;
  /// Heading of the chair the reference assumes at time t.
  virtual double heading(double t) const = 0;
};

/// Speed limit along the path from curvature: min(v_max, sqrt(a_lat/|kappa|),
/// w_max/|kappa|, (j_lat/|dkappa/ds|)^(1/3)), sampled at the path's points.
std::vector<double> curvatureSpeedLimit(const SmoothPath& path, const PathLimits& limits);

/// Acceleration and jerk magnitudes of the rider (the centre of mass P_c, `rider_offset` behind
/// the axle) along a path profile, evaluated every `step` s (jerk: differences over `step`).
struct RiderComfort {
  double max_accel = 0.0, max_jerk = 0.0;
  std::vector<double> violations;  ///< arc lengths where a limit was exceeded
};
RiderComfort riderComfort(const SmoothPath& path, const JerkLimitedProfile& profile,
                          double rider_offset, double accel_limit, double jerk_limit,
                          double step = 0.1);

/// The body (axle centre P) follows the smooth path with a jerk-limited speed profile, and P_l
/// is referenced at P + L t(s): if P_l tracks it, P stays on the planned path with the heading
/// of its tangent (no corner cutting). With P(s), tangent t, normal n, curvature k:
///   y = P + L t,  y' = t + L k n,  y'' = k n + L (k' n - k^2 t)   (' = d/ds)
///   y_dot = s_dot y',  y_ddot = s_ddot y' + s_dot^2 y''.
/// The nominal profile uses `margin` (< 1) of the accel/jerk limits, the rest being left to
/// the feedback; where the rider's combined (longitudinal + lateral + yaw) acceleration or jerk
/// would still exceed (1 + margin)/2 of the limits, the speed limit is lowered there and the
/// profile recomputed (a few iterations).
class PathOutputTrajectory : public OutputTrajectory {
 public:
  PathOutputTrajectory(std::shared_ptr<const SmoothPath> path, double lookahead,
                       double rider_offset, const PathLimits& limits, double margin,
                       double initial_speed = 0.0);
  double duration() const override { return profile_->duration(); }
  OutputReference at(double t) const override;
  double heading(double t) const override;
  const SmoothPath& path() const { return *path_; }
  const JerkLimitedProfile& profile() const { return *profile_; }

 private:
  std::shared_ptr<const SmoothPath> path_;
  double lookahead_;
  std::unique_ptr<JerkLimitedProfile> profile_;
};

/// In-place rotation about the axle centre from theta0 to theta1 (shortest way) with a
/// jerk-limited angle profile: y = P + L (cos phi, sin phi),
/// y_dot = L phi_dot n, y_ddot = L phi_ddot n - L phi_dot^2 t.
class RotationOutputTrajectory : public OutputTrajectory {
 public:
  RotationOutputTrajectory(const Eigen::Vector2d& centre, double theta0, double theta1,
                           double lookahead, const MotionLimits& limits);
  double duration() const override { return profile_ ? profile_->duration() : 0.0; }
  OutputReference at(double t) const override;
  double heading(double t) const override;

 private:
  Eigen::Vector2d centre_;
  double theta0_, direction_, lookahead_;
  std::unique_ptr<JerkLimitedProfile> profile_;  ///< null for a zero rotation
};

/// Reference of a point `lookahead` ahead of a body at `position` with heading `heading`,
/// moving with speed v, accel a along the heading, and yaw rate w, yaw accel w_dot.
OutputReference pointAheadReference(const Eigen::Vector2d& position, double heading, double v,
                                    double a, double w, double w_dot, double lookahead);

}  // namespace wheelchair_controller
