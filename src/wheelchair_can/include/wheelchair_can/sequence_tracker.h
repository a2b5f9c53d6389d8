// Classifies 8-bit rolling sequence counters: in order, lost frames, duplicates, reordering.
#pragma once

#include <cstdint>

namespace wheelchair_can {

class SequenceTracker {
 public:
  enum class Verdict { kInOrder, kDuplicate, kReordered };
  /// Accepts `sequence` unless it repeats or goes back (then the state is unchanged).
  /// `lost` receives the number of skipped counter values (0 when in order).
  Verdict accept(std::uint8_t sequence, std::uint32_t* lost) {
    *lost = 0;
    if (!started_) {
      started_ = true;
      last_ = sequence;
      return Verdict::kInOrder;
    }
    const std::uint8_t step = static_cast<std::uint8_t>(sequence - last_);
    if (step == 0) return Verdict::kDuplicate;
    if (step >= 128) return Verdict::kReordered;
    *lost = step - 1u;
    last_ = sequence;
    return Verdict::kInOrder;
  }
  /// Forget the last value (after a silence: the next value is accepted as it is).
  void reset() { started_ = false; }

 private:
  bool started_ = false;
  std::uint8_t last_ = 0;
};

}  // namespace wheelchair_can
