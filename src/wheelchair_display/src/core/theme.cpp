#include <wheelchair_display/theme.h>

#include <stdexcept>

namespace wheelchair_display {

Theme darkTheme() {
  Theme t;
  t.name = "dark";
  t.background = rgbFromHex("#000000");
  t.text = rgbFromHex("#FFFFFF");
  t.status_background = rgbFromHex("#000000");
  t.status_text = rgbFromHex("#FFFFFF");
  t.floor = rgbFromHex("#2E2E2E");
  t.wall = rgbFromHex("#A6A6A6");
  t.unknown = rgbFromHex("#000000");
  t.obstacle = rgbFromHex("#FF8C1A");
  t.route = rgbFromHex("#33D6FF");
  t.route_casing = rgbFromHex("#000000");
  t.destination = rgbFromHex("#FFFFFF");
  t.chair_fill = rgbFromHex("#FF66CC");
  t.chair_outline = rgbFromHex("#000000");
  t.label_background = rgbFromHex("#000000");
  t.label_text = rgbFromHex("#FFFFFF");
  t.label_border = rgbFromHex("#BFBFBF");
  t.highlight_background = rgbFromHex("#FFD400");
  t.highlight_text = rgbFromHex("#000000");
  t.highlight_frame = rgbFromHex("#FFD400");
  t.highlight_frame_alt = rgbFromHex("#FFFFFF");
  t.stop_background = rgbFromHex("#D40000");
  t.stop_text = rgbFromHex("#FFFFFF");
  t.button_background = rgbFromHex("#FFFFFF");
  t.button_text = rgbFromHex("#000000");
  t.button_frame = rgbFromHex("#FFD400");
  t.ring = rgbFromHex("#FFD400");
  return t;
}

Theme lightTheme() {
  Theme t;
  t.name = "light";
  t.background = rgbFromHex("#FFFFFF");
  t.text = rgbFromHex("#000000");
  t.status_background = rgbFromHex("#FFFFFF");
  t.status_text = rgbFromHex("#000000");
  t.floor = rgbFromHex("#F5F5F5");
  t.wall = rgbFromHex("#1A1A1A");
  t.unknown = rgbFromHex("#B3B3B3");
  t.obstacle = rgbFromHex("#A34700");
  t.route = rgbFromHex("#0047B3");
  t.route_casing = rgbFromHex("#FFFFFF");
  t.destination = rgbFromHex("#000000");
  t.chair_fill = rgbFromHex("#C2185B");
  t.chair_outline = rgbFromHex("#000000");
  t.label_background = rgbFromHex("#FFFFFF");
  t.label_text = rgbFromHex("#000000");
  t.label_border = rgbFromHex("#404040");
  t.highlight_background = rgbFromHex("#FFD400");
  t.highlight_text = rgbFromHex("#000000");
  t.highlight_frame = rgbFromHex("#000000");
  t.highlight_frame_alt = rgbFromHex("#B35900");
  t.stop_background = rgbFromHex("#B00000");
  t.stop_text = rgbFromHex("#FFFFFF");
  t.button_background = rgbFromHex("#000000");
  t.button_text = rgbFromHex("#FFFFFF");
  t.button_frame = rgbFromHex("#005CE6");
  t.ring = rgbFromHex("#000000");
  return t;
}

Theme themeNamed(const std::string& name) {
  if (name == "dark") return darkTheme();
  if (name == "light") return lightTheme();
  throw std::invalid_argument("unknown theme '" + name + "' (known: dark, light)");
}

std::vector<ContrastPair> contrastPairs(const Theme& t) {
  constexpr double kStatus = 7.0, kText = 4.5, kGraphics = 3.0;
  return {
      {"status text on status background", t.status_text, t.status_background, kStatus},
      {"prompt and list text on background", t.text, t.background, kText},
      {"place name on its label", t.label_text, t.label_background, kText},
      {"highlighted name on the highlight", t.highlight_text, t.highlight_background, kText},
      {"STOP on the stop area", t.stop_text, t.stop_background, kText},
      {"button text on the button", t.button_text, t.button_background, kText},
      {"walls on the floor", t.wall, t.floor, kGraphics},
      {"route on the floor", t.route, t.floor, kGraphics},
      {"chair on the floor", t.chair_fill, t.floor, kGraphics},
      {"chair outline on its fill", t.chair_outline, t.chair_fill, kGraphics},
      {"destination on the floor", t.destination, t.floor, kGraphics},
      {"live obstacles on the floor", t.obstacle, t.floor, kGraphics},
      {"highlight frame on the floor", t.highlight_frame, t.floor, kGraphics},
      {"flashing highlight frame on the floor", t.highlight_frame_alt, t.floor, kGraphics},
      {"highlight frame on the background", t.highlight_frame, t.background, kGraphics},
      {"label border on the floor", t.label_border, t.floor, kGraphics},
      {"button frame on the background", t.button_frame, t.background, kGraphics},
      {"stop area on the background", t.stop_background, t.background, kGraphics},
      {"dwell ring on the floor", t.ring, t.floor, kGraphics},
  };
}

}  // namespace wheelchair_display
