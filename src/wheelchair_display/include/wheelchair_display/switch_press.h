// What one press of the rider's switch means at this moment, decided in one place. The switch
// reaches both the chair's HMI and this display; a press must never mean two things at once
// (the display confirming a pointer choice while the HMI takes the same press as choosing the
// highlighted room). The rule: while the HMI scans (rooms, places, a choice to confirm), the
// press is the HMI's and the display gives it no meaning of its own; a press while the chair
// drives stops it (the HMI stops it too: the same meaning, and the stop still works without the
// HMI); only when no HMI scans does a press confirm the pointer's choice waiting for it.
#pragma once

#include <wheelchair_display/display_model.h>

namespace wheelchair_display {

enum class PressMeaning {
  kHmis,     ///< the HMI's press (choose or confirm what it highlights): nothing here
  kStop,     ///< the chair drives: stop it
  kConfirm,  ///< drive to the pointer's choice waiting for its confirmation
  kNothing   ///< nothing to do with a press now
};

PressMeaning pressMeaning(const ScanView& scan, const DriveView& drive);

/// The pointer's choice (checking, reachable or refused) gives way when the rider presses the
/// switch on an HMI item (scanning moves from rooms to places, or to a confirmation): the
/// switch's choice leads. True on the HMI state change `before` -> `after` that does that.
bool switchTakesOver(const ScanView& before, const ScanView& after);

}  // namespace wheelchair_display
