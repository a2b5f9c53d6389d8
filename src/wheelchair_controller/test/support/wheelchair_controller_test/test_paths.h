// Hand-made smooth paths at the scale of a home (test support of the controller's tests, the
// benchmark and the simulator-driven rostests), and the paper's Figure 6 cosine path.
#pragma once

#include <wheelchair_controller/smooth_path.h>

#include <string>
#include <vector>

namespace wheelchair_controller {

/// Builds a path of base_link poses every `spacing` m from a start pose and segments. The poses'
/// yaw is the chair's heading; after reverse() the segments are driven backwards (the chair
/// keeps facing the other way: path_direction.h), after forward() forwards again.
class PathBuilder {
 public:
  explicit PathBuilder(const Pose2D& start, double spacing = 0.05);
  PathBuilder& straight(double length);
  /// Arc of the given radius turning the chair's heading by angle [rad] (positive: left).
  PathBuilder& arc(double radius, double angle);
  PathBuilder& reverse() {
    sign_ = -1.0;
    return *this;
  }
  PathBuilder& forward() {
    sign_ = 1.0;
    return *this;
  }
  /// The poses; the last one's yaw is set to goal_heading if given.
  std::vector<Pose2D> poses() const { return poses_; }
  std::vector<Pose2D> posesWithGoalHeading(double goal_heading) const;

 private:
  std::vector<Pose2D> poses_;
  double spacing_;
  double sign_ = 1.0;  ///< +1 forwards, -1 in reverse
};

struct NamedPath {
  std::string name;
  std::vector<Pose2D> poses;  ///< the chair starts at rest at poses.front()
};

/// Ten paths of a home-like scale (hallway, doorway turns, S-curves, around a table, ...).
std::vector<NamedPath> homeTestPaths();

/// Ten paths in the `flat` world (test/worlds/flat.yaml, map frame) between its rooms, through
/// its 90 cm doorways (living room - hallway, living room - kitchen), around the dining table
/// and the kitchen island. Drawn for the chair's footprint (1.10 m x 0.62 m, axle 0.30 m behind
/// the front): every pose keeps >= 3 cm from the walls (checked on the map). The 80 cm doors
/// open off the 1.2 m hallway, where a 90-degree turn of this footprint sweeps 1.14 m behind
/// the axle: no path enters them.
std::vector<NamedPath> flatTestPaths();

/// A three-point turn from the origin heading +x: 0.3 m straight, forward left (radius 0.8 m,
/// quarter turn), back right (the tail swings), forward left (radius 1.0 m) and 0.5 m straight.
/// Two cusps.
std::vector<Pose2D> threePointTurnPath();

/// Figure 6: y = amplitude cos(2 pi x / wavelength), x in [0, length]; the chair starts at the
/// origin heading +x, i.e. `amplitude` to the side of the path's start.
std::vector<Pose2D> cosinePath(double amplitude = 0.3, double wavelength = 4.0, double length = 8.0,
                               double spacing = 0.05);

}  // namespace wheelchair_controller
