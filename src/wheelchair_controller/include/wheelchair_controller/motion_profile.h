// Jerk-limited time parametrization of a 1-D motion (distance along a path, or an angle) with
// a position-dependent speed limit: the comfort limits of a seated passenger.
#pragma once

#include <vector>

namespace wheelchair_controller {

/// Limits of a 1-D motion: |v| <= speed, |a| <= accel, |j| <= jerk.
struct MotionLimits {
  double speed = 0.0;
  double accel = 0.0;
  double jerk = 0.0;
};

/// One sample of a 1-D motion: time, position, speed, acceleration.
struct ProfileSample {
  double t = 0.0, s = 0.0, v = 0.0, a = 0.0;
};

/// Jerk in [-jerk, jerk] that brings (v, a) to (v_target, 0) as fast as the limits allow
/// without overshooting v_target (bang-bang in jerk, accel held at +-accel). dt is the step the
/// caller integrates with (it settles the last step exactly).
double approachJerk(double v, double a, double v_target, const MotionLimits& limits, double dt);

/// Advances (s, v, a) by dt with constant jerk j, keeping |a| <= accel.
ProfileSample integrateJerk(const ProfileSample& x, double j, double dt, double max_accel);

/// Time-optimal (greedy) jerk-limited motion from s = 0 with speed v0 to a stop at s = length,
/// never faster than speed_limit(s) (sampled uniformly on [0, length], last value ignored: the
/// motion ends at rest). At every step the largest jerk is chosen whose state can still brake
/// (jerk-limited) below the limit ahead and to rest before the end.
class JerkLimitedProfile {
 public:
  JerkLimitedProfile(double length, std::vector<double> speed_limit, const MotionLimits& limits,
                     double v0 = 0.0, double dt = 0.01);

  double duration() const { return samples_.back().t; }
  double length() const { return length_; }
  /// Sample at time t (clamped to [0, duration]); linear interpolation between steps.
  ProfileSample at(double t) const;

 private:
  double limitAt(double s) const;
  bool canBrake(const ProfileSample& x) const;

  double length_;
  std::vector<double> speed_limit_;
  std::vector<double> limit_ahead_;  ///< min of speed_limit_ from each sample to the end
  MotionLimits limits_;
  double dt_;
  std::vector<ProfileSample> samples_;
};

}  // namespace wheelchair_controller
