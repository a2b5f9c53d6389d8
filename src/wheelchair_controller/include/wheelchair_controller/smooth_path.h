// A planned path (poses of base_link, the axle centre P) turned into a smooth curve with
// heading, curvature and its derivative, parametrized by arc length.
#pragma once

#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace wheelchair_controller {

using wheelchair_core::Pose2D;

/// A point of the smooth path at arc length s.
struct PathPoint {
  double s = 0.0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double heading = 0.0;         ///< tangent direction [rad] (unwrapped along the path)
  double curvature = 0.0;       ///< kappa = d heading / ds [1/m]
  double curvature_rate = 0.0;  ///< d kappa / ds [1/m^2]
};

/// Why a path is refused (empty string: accepted).
std::string pathRejectionReason(const std::vector<Pose2D>& poses, double min_length);

/// Which ends of a piece are cusps (the chair stops there and the next piece goes on the other
/// way): such an end is smoothed with an odd extension (see SmoothPath).
struct CuspEnds {
  bool start = false;
  bool end = false;
};

class SmoothPath {
 public:
  /// Resamples the polyline every `spacing` metres and smooths it with a moving average over
  /// +-smoothing_half_window metres (ends kept: the window shrinks there). A cusp end is first
  /// extended by the point reflection of its last metres through the end point and cut back
  /// after smoothing: the end stays where it is and the curvature falls smoothly to zero there.
  /// Throws std::invalid_argument on a path that pathRejectionReason refuses.
  explicit SmoothPath(const std::vector<Pose2D>& poses, double spacing = 0.05,
                      double smoothing_half_window = 0.15, const CuspEnds& cusps = {});

  double length() const { return points_.back().s; }
  /// Point at arc length s (clamped to [0, length]); linear interpolation.
  PathPoint at(double s) const;
  const std::vector<PathPoint>& points() const { return points_; }
  /// Heading the chair must have at the goal: the last planned pose's yaw.
  double goalHeading() const { return goal_heading_; }
  /// Distance from a point to the planned polyline (as given, before smoothing).
  double distanceToPlanned(const Eigen::Vector2d& point) const;

 private:
  std::vector<Eigen::Vector2d> planned_;
  std::vector<PathPoint> points_;
  double spacing_;
  double goal_heading_;
};

}  // namespace wheelchair_controller
