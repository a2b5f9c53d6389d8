#include <wheelchair_display/layout.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_display {
namespace {

int scaled(double fraction, int of, int minimum) {
  return std::max(minimum, static_cast<int>(std::lround(fraction * of)));
}

}  // namespace

Layout computeLayout(int width, int height, bool with_list) {
  Layout l;
  l.status_font_px = scaled(0.07, height, 48);  // 54 px at 768 lines, 76 at 1080
  l.prompt_font_px = scaled(0.048, height, 34);
  l.list_font_px = scaled(0.045, height, 32);
  l.label_font_px = scaled(0.034, height, 24);
  l.stop_font_px = scaled(0.075, height, 48);
  l.padding = scaled(0.012, height, 8);

  const int stop_w = scaled(0.17, width, 160);
  l.stop = {width - stop_w, 0, stop_w, height};
  const int left_w = width - stop_w;
  // Two lines of status text (DejaVu's line height is 1.17 em), padding and room for a frame.
  l.status = {0, 0, left_w,
              static_cast<int>(std::lround(2.4 * l.status_font_px)) + 2 * l.padding + 16};
  const int prompt_h = scaled(0.135, height, 90);
  l.prompt = {0, height - prompt_h, left_w, prompt_h};
  const int middle_y = l.status.bottom(), middle_h = l.prompt.y - middle_y;
  const int list_w = with_list ? scaled(0.3, left_w, 220) : 0;
  l.list = {0, middle_y, list_w, middle_h};
  l.map = {list_w, middle_y, left_w - list_w, middle_h};
  const int button_w = scaled(0.3, left_w, 220);
  l.go_button = {left_w - button_w - l.padding, l.prompt.y + l.padding, button_w,
                 prompt_h - 2 * l.padding};
  const int carer = prompt_h / 2;
  l.carer_button = {l.padding, l.prompt.y + (prompt_h - carer) / 2, carer, carer};
  return l;
}

}  // namespace wheelchair_display
