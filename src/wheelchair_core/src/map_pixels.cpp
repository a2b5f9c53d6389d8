#include <wheelchair_core/map_pixels.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_core {

int8_t pixelToCell(double color_avg, double alpha, const MapFileOptions& options) {
  const double v = options.negate ? 255.0 - color_avg : color_avg;
  if (options.mode == MapMode::kRaw) {
    return static_cast<int8_t>(static_cast<uint8_t>(v));  // as map_server: 255 -> -1
  }
  // Trinary: map_saver's unknown grey is unknown whatever the thresholds say. With
  // free_thresh > 0.196 (Nav2's default 0.25) p = 50/255 fell below it and unknown space loaded
  // as free: the planner planned into it (Nav2 PR #5138 / #5278).
  if (options.mode == MapMode::kTrinary && v == kTrinaryUnknownPixel) return kUnknown;
  const double p = (255.0 - v) / 255.0;
  if (p > options.occupied_thresh) return kOccupied;
  if (p < options.free_thresh) return kFree;
  if (options.mode == MapMode::kTrinary || alpha < 1.0) return kUnknown;
  const double ratio = (p - options.free_thresh) / (options.occupied_thresh - options.free_thresh);
  return static_cast<int8_t>(1 + 98 * ratio);
}

uint8_t cellToPixel(int8_t cell, const MapFileOptions& options) {
  uint8_t v = kTrinaryUnknownPixel;
  switch (options.mode) {
    case MapMode::kTrinary:
      if (cell == kFree) v = 254;
      if (cell == kOccupied) v = 0;
      break;
    case MapMode::kScale:
      if (cell >= 0) v = static_cast<uint8_t>(std::lround(255.0 - 2.55 * std::min<int>(cell, 100)));
      break;
    case MapMode::kRaw:
      v = static_cast<uint8_t>(cell);
      break;
  }
  return options.negate ? static_cast<uint8_t>(255 - v) : v;
}

}  // namespace wheelchair_core
