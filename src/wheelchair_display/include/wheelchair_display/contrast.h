// Colours and the WCAG 2.x contrast ratio: the maths behind "every text >= 4.5:1, the status
// line >= 7:1" (WCAG 2.1 success criteria 1.4.3 / 1.4.6; 1.4.11: graphics >= 3:1).
#pragma once

#include <cstdint>
#include <string>

namespace wheelchair_display {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
};

/// "#RRGGBB" -> Rgb; throws std::invalid_argument for anything else.
Rgb rgbFromHex(const std::string& hex);
std::string toHex(const Rgb& colour);

/// WCAG relative luminance of an sRGB colour: 0 (black) .. 1 (white).
double relativeLuminance(const Rgb& colour);

/// (L_lighter + 0.05) / (L_darker + 0.05): 1 (same) .. 21 (black on white), either order.
double contrastRatio(const Rgb& a, const Rgb& b);

}  // namespace wheelchair_display
