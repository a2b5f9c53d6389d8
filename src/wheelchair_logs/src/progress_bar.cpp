#include <unistd.h>
#include <wheelchair_logs/progress_bar.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_logs {

ProgressBar::ProgressBar(std::FILE* stream, std::string label, bool enabled)
    : stream_(stream), label_(std::move(label)), enabled_(enabled && isatty(fileno(stream))) {}

void ProgressBar::update(double fraction, const std::string& status) {
  if (!enabled_) return;
  const int percent = static_cast<int>(std::lround(100 * std::clamp(fraction, 0.0, 1.0)));
  if (percent == last_percent_) return;
  last_percent_ = percent;
  constexpr int kWidth = 40;
  const int filled = percent * kWidth / 100;
  std::fprintf(stream_, "\r%s [%s%s] %3d%% %s", label_.c_str(), std::string(filled, '#').c_str(),
               std::string(kWidth - filled, '.').c_str(), percent, status.c_str());
  std::fflush(stream_);
  drawn_ = true;
}

void ProgressBar::breakLine() {
  if (drawn_) std::fputc('\n', stream_);
  drawn_ = false;
  last_percent_ = -1;
}

}  // namespace wheelchair_logs
