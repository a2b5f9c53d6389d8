#include <wheelchair_display/contrast.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace wheelchair_display {
namespace {

/// An sRGB channel (0..255) linearized as WCAG defines it.
double linearChannel(uint8_t value) {
  const double c = value / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

Rgb rgbFromHex(const std::string& hex) {
  const bool shape =
      hex.size() == 7 && hex[0] == '#' && std::all_of(hex.begin() + 1, hex.end(), [](char c) {
        return std::isxdigit(static_cast<unsigned char>(c));
      });
  if (!shape) throw std::invalid_argument("colour '" + hex + "' is not #RRGGBB");
  const auto channel = [&](int i) {
    return static_cast<uint8_t>(std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16));
  };
  return {channel(0), channel(1), channel(2)};
}

std::string toHex(const Rgb& colour) {
  char text[8];
  std::snprintf(text, sizeof(text), "#%02X%02X%02X", colour.r, colour.g, colour.b);
  return text;
}

double relativeLuminance(const Rgb& colour) {
  return 0.2126 * linearChannel(colour.r) + 0.7152 * linearChannel(colour.g) +
         0.0722 * linearChannel(colour.b);
}

double contrastRatio(const Rgb& a, const Rgb& b) {
  const double la = relativeLuminance(a), lb = relativeLuminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

}  // namespace wheelchair_display
