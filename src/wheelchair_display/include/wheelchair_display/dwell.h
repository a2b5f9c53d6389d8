// Dwell selection: what a head mouse, an eye tracker or a joystick mouse emulator produces is a
// pointer that rests on something. Resting on one target for `dwell_time` chooses it; the ring
// drawn at the pointer fills meanwhile (progress 0..1). Small jitter (within `radius` pixels of
// where the dwell began) is allowed; moving further or onto another target starts again. A
// target that fired fires again only after the pointer has left it (no repeats while resting).
#pragma once

#include <Eigen/Core>

namespace wheelchair_display {

constexpr int kNoTarget = -1;

class DwellTimer {
 public:
  DwellTimer(double dwell_time, double radius);

  struct State {
    int target = kNoTarget;  ///< what the pointer dwells on
    double progress = 0.0;   ///< 0..1 of the dwell time (0 after firing)
    bool fired = false;      ///< this update chose `target`
  };

  /// The pointer at `pointer` [px] over `target` (kNoTarget: nothing to choose) at `now` [s].
  State update(double now, const Eigen::Vector2d& pointer, int target);
  /// Forgets the current dwell (the pointer left the window).
  void reset();
  /// Something was just chosen at `pointer` and the screen changes under it: nothing is chosen
  /// again until the pointer has moved more than the radius away (a dwell that opened a room
  /// does not go on to choose whatever the room shows under the resting pointer).
  void rest(const Eigen::Vector2d& pointer);

  double dwellTime() const { return dwell_time_; }

 private:
  double dwell_time_, radius_;
  int target_ = kNoTarget;
  int fired_target_ = kNoTarget;
  bool resting_ = false;
  double start_ = 0.0;
  Eigen::Vector2d anchor_{0.0, 0.0};
};

}  // namespace wheelchair_display
