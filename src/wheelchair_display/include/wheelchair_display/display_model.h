// What the display knows, ROS-free: the HMI's scanning state, the localizer's and the safety
// supervisor's verdicts, the current drive and the pointer's choice. The ROS layer converts the
// typed messages (wheelchair_msgs/HmiState, LocalizationStatus, SafetyStatus, and later the
// navigator's move_base result) into these; describe() (rider_text.h) turns them into words.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace wheelchair_display {

/// wheelchair_msgs/HmiState.
struct ScanView {
  enum class State { kIdle, kRooms, kPlaces, kConfirming, kDriving };
  State state = State::kIdle;
  std::vector<std::string> items;
  int highlighted = -1;
  std::string room, place;
  double time_left = 0.0, step_time = 0.0;  ///< [s]
  std::string sentence;  ///< the HMI's last words to the rider (places named by identifier)

  /// The highlighted item's name, or "".
  std::string highlightedItem() const {
    return highlighted >= 0 && highlighted < static_cast<int>(items.size()) ? items[highlighted]
                                                                            : std::string();
  }
  bool scanning() const {
    return state == State::kRooms || state == State::kPlaces || state == State::kConfirming;
  }
  /// The rider pressed the switch on a room (its places are scanned) or a place (to confirm):
  /// the switch's choice leads and the pointer's targets on the map wait. While the HMI only
  /// offers rooms, the pointer chooses freely (a pointer rider's HMI scans all the time).
  bool switchEngaged() const { return state == State::kPlaces || state == State::kConfirming; }
};

/// wheelchair_msgs/LocalizationStatus: only whether the chair can be driven on, and the
/// localizer's own words for the rider (its table of reasons is the localizer's, not ours).
struct LocalizationView {
  enum class State { kUnknown, kLocalized, kNotLocalized };  ///< kUnknown: none received yet
  State state = State::kUnknown;
  std::string sentence;
};

/// wheelchair_msgs/SafetyStatus: a stop and the supervisor's own words for it.
struct SafetyView {
  bool known = false;    ///< a status was received
  bool stop = false;     ///< a stop for a reason other than waiting for the first data
  std::string sentence;  ///< the supervisor's sentence for the rider
};

/// The drive the display shows: a destination being checked, the drive, and its outcome.
struct DriveView {
  enum class Phase {
    kNone,            ///< nothing chosen
    kChecking,        ///< asking the planner whether the chosen destination can be reached
    kReachable,       ///< it can: waiting for the rider's confirmation
    kRefused,         ///< it cannot (the planner's answer, or not on free floor)
    kDriving,         ///< on the way
    kArrived,         ///< outcome: reached
    kStoppedByRider,  ///< outcome: the rider's stop
    kFailed           ///< outcome: the drive ended without arriving
  };
  Phase phase = Phase::kNone;
  std::string destination;         ///< place id ("kitchen_door") or "" for a spot on the map
  double distance = std::nan("");  ///< [m] route length (reachable) or what is left (driving)
  /// The navigator's sentence: with an outcome, how the drive ended; while driving, why it is
  /// held up (something in the way, the way blocked); "" when it gives none.
  std::string sentence;

  bool outcome() const {
    return phase == Phase::kArrived || phase == Phase::kStoppedByRider || phase == Phase::kFailed ||
           phase == Phase::kRefused;
  }
};

struct DisplayInputs {
  bool have_map = false;
  bool have_pose = false;  ///< the chair's pose in the map (tf) is known and recent
  LocalizationView localization;
  SafetyView safety;
  ScanView scan;
  DriveView drive;
  std::string pointer_room;  ///< the room the pointer opened (its places are the targets), or ""
};

}  // namespace wheelchair_display
