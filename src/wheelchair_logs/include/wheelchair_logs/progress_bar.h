// A one-line progress bar on a terminal (stderr), redrawn at most every percent.
#pragma once

#include <cstdio>
#include <string>

namespace wheelchair_logs {

class ProgressBar {
 public:
  /// Draws only if `stream` is a terminal (and `enabled`).
  ProgressBar(std::FILE* stream, std::string label, bool enabled = true);
  void update(double fraction, const std::string& status);
  /// Ends the bar's line (before other output, and at the end).
  void breakLine();

 private:
  std::FILE* stream_;
  std::string label_;
  bool enabled_;
  int last_percent_ = -1;
  bool drawn_ = false;
};

}  // namespace wheelchair_logs
