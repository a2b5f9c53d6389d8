// Where everything sits on the rider's screen, for any size (1024x768 old chair PCs to
// 1920x1080): the status line on top, the STOP area down the whole right edge, the map in the
// middle, the list of scanned items (or the carer's tools) on the left when there is one, and the
// prompt with the Go button at the bottom. Font sizes scale with the screen height and never go
// below the rider's minimums (status line 48 px).
#pragma once

namespace wheelchair_display {

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
  int right() const { return x + w; }
  int bottom() const { return y + h; }
  double centreX() const { return x + 0.5 * w; }
  double centreY() const { return y + 0.5 * h; }
  bool contains(double px, double py) const {
    return px >= x && py >= y && px < x + w && py < y + h;
  }
  bool intersects(const Rect& o) const {
    return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
  }
  Rect adjusted(int d) const { return {x + d, y + d, w - 2 * d, h - 2 * d}; }
};

struct Layout {
  Rect status;         ///< the status line (up to two lines of text)
  Rect map;            ///< the map view
  Rect list;           ///< scanned items or carer tools (w = 0 when hidden)
  Rect prompt;         ///< what the next action does
  Rect go_button;      ///< inside the prompt bar, on its right
  Rect carer_button;   ///< inside the prompt bar, on its left (small: not a rider's target)
  Rect stop;           ///< full height, right edge
  int status_font_px;  ///< >= 48
  int prompt_font_px;
  int list_font_px;
  int label_font_px;
  int stop_font_px;
  int padding;
};

/// The regions of a `width` x `height` screen; `with_list` shows the left panel.
Layout computeLayout(int width, int height, bool with_list);

}  // namespace wheelchair_display
