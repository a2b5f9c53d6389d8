// One-switch group scanning: a rider with a single reliable gesture (tongue switch, BCI event,
// sip-and-puff) picks one of N places. Rooms are highlighted in turn; a press selects the
// highlighted room, then its places are highlighted; a press selects the place, a second
// press confirms it. While the chair drives, any press stops it.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_hmi/places.h>

#include <string>
#include <vector>

namespace wheelchair_hmi {

struct ScannerOptions {
  double scan_interval = 2.0;    ///< [s] between two highlights
  double confirm_timeout = 8.0;  ///< [s] without a confirming press: back to scanning rooms
  int item_cycles = 2;           ///< full cycles through a room's places before going back

  /// "" if usable, else every problem.
  std::string validate() const;
};

/// The keys of ScannerOptions, named as the fields.
void readScannerOptions(wheelchair_core::ConfigReader& reader, ScannerOptions& options);

/// What the scanner wants the rest of the system to do after an event.
struct ScanOutput {
  enum class Kind { kNone, kHighlight, kAskConfirm, kGo, kStop, kCancelled };
  Kind kind = Kind::kNone;
  std::string text;              ///< what to announce to the rider
  const Place* place = nullptr;  ///< highlighted, to confirm, or the goal
  std::string group;             ///< highlighted room (group phase)
};

class SwitchScanner {
 public:
  enum class Phase { kGroups, kItems, kConfirm, kDriving };

  /// Groups are the rooms, larger rooms first (fewer scan steps on average). Throws
  /// std::invalid_argument without places or with options that do not validate().
  SwitchScanner(std::vector<Place> places, ScannerOptions options);

  /// Starts scanning rooms at time `now` [s].
  ScanOutput start(double now);
  /// Advances the highlight when the scan interval has elapsed.
  ScanOutput tick(double now);
  /// A switch event.
  ScanOutput press(double now);
  /// The chair reached (or gave up on) its goal: scan rooms again.
  ScanOutput finished(double now);
  /// A goal was sent another way (named place by service/topic, rviz): the chair drives, so a
  /// press now stops it.
  void driving(double now);

  Phase phase() const { return phase_; }
  const std::vector<Place>& places() const { return places_; }
  const std::vector<std::string>& groups() const { return group_names_; }
  const std::vector<std::vector<size_t>>& groupMembers() const { return group_members_; }
  // Where the scan stands (scan_state.h reads them): the highlighted room, the highlighted
  // place's index among the room's members, the time of the last step or press.
  size_t group() const { return group_; }
  size_t item() const { return item_; }
  double lastStep() const { return last_step_; }
  const ScannerOptions& options() const { return options_; }

 private:
  ScanOutput highlight();
  ScanOutput enterGroups(double now);

  std::vector<Place> places_;
  ScannerOptions options_;
  std::vector<std::string> group_names_;
  std::vector<std::vector<size_t>> group_members_;
  Phase phase_ = Phase::kGroups;
  size_t group_ = 0;
  size_t item_ = 0;
  int item_steps_ = 0;
  double last_step_ = 0.0;
};

/// Expected effort to reach each destination for a rider who presses as soon as the target is
/// highlighted: presses (including the confirmation) and scan steps (highlights shown,
/// counting the first), by simulating the scanner itself.
struct ScanEffort {
  double mean_steps = 0.0;
  int max_steps = 0;
  int max_presses = 0;
  double linear_mean_steps = 0.0;  ///< plain one-by-one scanning of the same places
};
ScanEffort measureScanEffort(const std::vector<Place>& places, const ScannerOptions& options);

}  // namespace wheelchair_hmi
