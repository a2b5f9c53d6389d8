// The "back up" recovery (issue 24): a drive blocked in a dead end (nothing forward, the way on
// only behind) leaves by reversing along the way it came, then the navigator plans again from
// there (Navigator::setBackUpHook). The way it came is the trail of the chair's own poses while
// it drove forwards: the body has just swept it, so it fits, and the rear guard watches it for
// anyone who stepped in since. ROS-free.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_navigator/navigator.h>

#include <deque>
#include <vector>

namespace wheelchair_navigator {

struct BackUpConfig {
  double distance = 2.0;      ///< [m] how far back along the trail the recovery reverses
  double min_distance = 0.3;  ///< [m] a shorter trail is no way out: no back-up
  double spacing = 0.05;      ///< [m] between recorded poses
  double max_jump = 0.5;      ///< [m] a longer step (a relocalization) starts a new trail
  double keep = 6.0;          ///< [m] trail kept behind the chair
};

class BackUpTrail {
 public:
  explicit BackUpTrail(BackUpConfig config = BackUpConfig());

  /// The chair's pose as it moves (a few times a second). Only the stretch driven forwards
  /// since the last reverse step or jump is kept: that is the way back.
  void record(const Pose2D& pose);
  /// The route back: from the chair's pose along the trail, newest to oldest, up to
  /// config.distance, each pose with the heading the chair had there (so the controller drives
  /// it in reverse). Empty if the trail behind is shorter than min_distance.
  std::vector<Pose2D> route(const BlockedSituation& situation) const;
  /// [m] the trail's length behind its newest pose.
  double length() const;
  void clear() { trail_.clear(); }

 private:
  BackUpConfig config_;
  std::deque<Pose2D> trail_;  ///< oldest first
};

}  // namespace wheelchair_navigator
