// Starting off the reference (e.g. the paper's Figure 6: the chair 0.3 m beside the path's
// start, or after an in-place alignment): rather than leaving the whole initial error to the
// feedback (a step in the error: the rider gets the outer law's full acceleration at once), the
// reference starts at the chair's P_l and its offset decays smoothly to the planned one.
#pragma once

#include <wheelchair_controller/motion_profile.h>
#include <wheelchair_controller/output_trajectory.h>

#include <memory>

namespace wheelchair_controller {

/// base(t) + offset * (1 - s(t / T)) with the quintic smoothstep s(x) = 10x^3 - 15x^4 + 6x^5
/// (s', s'' zero at both ends: no step in the reference's velocity or acceleration).
class OffsetDecayTrajectory : public OutputTrajectory {
 public:
  OffsetDecayTrajectory(std::shared_ptr<const OutputTrajectory> base, const Eigen::Vector2d& offset,
                        double decay_time);
  double duration() const override { return base_->duration(); }
  OutputReference at(double t) const override;
  double heading(double t) const override { return base_->heading(t); }
  double decayTime() const { return decay_time_; }

 private:
  std::shared_ptr<const OutputTrajectory> base_;
  Eigen::Vector2d offset_;
  double decay_time_;
};

/// Shortest decay time keeping the offset's own acceleration and jerk within limits
/// (max s'' = 10/sqrt(3) / T^2, max s''' = 60 / T^3), capped to the base's duration.
double offsetDecayTime(double offset, const MotionLimits& limits, double duration);

/// The base trajectory started from P_l = y: wrapped in an OffsetDecayTrajectory when y is
/// more than `min_offset` from the base's start, else the base itself.
std::shared_ptr<const OutputTrajectory> startingFrom(std::shared_ptr<const OutputTrajectory> base,
                                                     const Eigen::Vector2d& y,
                                                     const MotionLimits& limits,
                                                     double min_offset = 0.005);

/// The base trajectory resumed from rest at its time t0: after a pause in the control steps the
/// chair has braked to rest while the reference stood or ran on. Time is warped,
///   tau(t) = t0 + T S(t/T) for t < T, t0 + T/2 + (t - T) after, S(x) = integral_0^x s,
/// with the quintic smoothstep s (tau' = s(t/T) rises 0 -> 1 with zero slope at both ends):
/// the same path, the reference's speed from 0 to the base's over T without a step in
/// acceleration (y_dot = tau' y_dot_base, y_ddot = tau'^2 y_ddot_base + tau'' y_dot_base).
class RestartFromRestTrajectory : public OutputTrajectory {
 public:
  RestartFromRestTrajectory(std::shared_ptr<const OutputTrajectory> base, double t0,
                            double ramp_time);
  double duration() const override { return duration_; }
  OutputReference at(double t) const override;
  double heading(double t) const override;

 private:
  /// tau(t) (clamped to the base's duration) and its first two derivatives.
  double baseTime(double t, double& rate, double& rate_dot) const;

  std::shared_ptr<const OutputTrajectory> base_;
  double t0_, ramp_, duration_;
};

/// Shortest ramp T keeping the warp's own acceleration (v max s' / T = 1.875 v / T) and jerk
/// (v max|s''| / T^2 = 5.774 v / T^2) of a reference at speed v within limits (at least 0.5 s).
double restartRampTime(double speed, const MotionLimits& limits);

/// The time in [from, to] of the base trajectory whose reference lies nearest `y` (coarse
/// samples every `step`, then refined).
double nearestTime(const OutputTrajectory& base, const Eigen::Vector2d& y, double from, double to,
                   double step = 0.05);

}  // namespace wheelchair_controller
