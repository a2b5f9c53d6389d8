#include <wheelchair_display/switch_press.h>

namespace wheelchair_display {

PressMeaning pressMeaning(const ScanView& scan, const DriveView& drive) {
  if (drive.phase == DriveView::Phase::kDriving || scan.state == ScanView::State::kDriving)
    return PressMeaning::kStop;
  if (scan.scanning()) return PressMeaning::kHmis;
  if (drive.phase == DriveView::Phase::kReachable) return PressMeaning::kConfirm;
  return PressMeaning::kNothing;
}

bool switchTakesOver(const ScanView& before, const ScanView& after) {
  return after.switchEngaged() && !before.switchEngaged();
}

}  // namespace wheelchair_display
