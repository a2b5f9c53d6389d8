// What the one-switch HMI shows the rider right now, ROS-free: the fields of
// wheelchair_msgs/HmiState (the nodelet publishes it latched on /hmi/state at every change), read
// from the scanner. The rider's display draws it; auditory scanning speaks it.
#pragma once

#include <wheelchair_hmi/switch_scanner.h>

#include <string>
#include <vector>

namespace wheelchair_hmi {

struct ScanState {
  /// As HmiState's constants (IDLE 0 ... DRIVING 4).
  enum class Kind { kIdle = 0, kRooms = 1, kPlaces = 2, kConfirming = 3, kDriving = 4 };
  Kind state = Kind::kIdle;
  std::vector<std::string> items;  ///< what is scanned, in order ([place] while confirming)
  int highlighted = -1;            ///< index into items, -1: none
  std::string room;                ///< the highlighted or chosen room
  std::string place;               ///< the highlighted place, the one to confirm, or the goal
  double time_left = 0.0;          ///< [s] until the highlight moves on or the choice lapses
  double step_time = 0.0;          ///< [s] the whole step time_left counts down
  std::string sentence;            ///< the HMI's last words to the rider

  /// Everything but the time left: a change the display must see (the time left it counts
  /// down itself).
  bool sameShown(const ScanState& other) const;
};

/// The scanner's state at time `now` [s]. `goal` names the place the chair drives to (""
/// for a goal that is no named place); it is used only while driving.
ScanState scanState(const SwitchScanner& scanner, double now, const std::string& goal);

/// The place at `pose` (within `tolerance` m and 0.05 rad), or "": names a goal from elsewhere
/// (the display, rviz, the go_to_place service) by its place.
std::string placeAt(const std::vector<Place>& places, const wheelchair_core::Pose2D& pose,
                    double tolerance = 0.01);

}  // namespace wheelchair_hmi
