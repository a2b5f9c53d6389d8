// The display's two colour themes (dark, light) and the contrast pairs they must satisfy:
// every text on its background >= 4.5:1 (WCAG AA), the status line >= 7:1 (AAA), and the map's
// graphics (walls, route, chair, highlight frame) >= 3:1 against the floor (WCAG 1.4.11).
// Colour is never the only cue: shapes, frames and words carry every meaning as well.
#pragma once

#include <wheelchair_display/contrast.h>

#include <string>
#include <vector>

namespace wheelchair_display {

struct Theme {
  std::string name;
  Rgb background, text;  ///< the window; prompt and list text
  Rgb status_background, status_text;
  Rgb floor, wall, unknown, obstacle;  ///< the map: free, occupied, unknown, live obstacles
  Rgb route, route_casing, destination;
  Rgb chair_fill, chair_outline;
  Rgb label_background, label_text, label_border;
  Rgb highlight_background, highlight_text, highlight_frame, highlight_frame_alt;  ///< alt: flash
  Rgb stop_background, stop_text;
  Rgb button_background, button_text, button_frame;
  Rgb ring;  ///< the dwell ring
};

Theme darkTheme();
Theme lightTheme();
/// "dark" or "light"; throws std::invalid_argument naming the known themes.
Theme themeNamed(const std::string& name);

/// One foreground / background pair of a theme and the ratio it needs.
struct ContrastPair {
  std::string what;  ///< e.g. "status text on status background"
  Rgb foreground, background;
  double required;  ///< 7 (status line), 4.5 (text), 3 (graphics)
  double ratio() const { return contrastRatio(foreground, background); }
};
/// Every pair the theme draws text or map graphics with.
std::vector<ContrastPair> contrastPairs(const Theme& theme);

}  // namespace wheelchair_display
