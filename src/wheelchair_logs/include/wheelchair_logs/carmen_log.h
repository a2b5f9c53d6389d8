// Laser scans with their poses from CARMEN logs (FLASER and ROBOTLASER1 lines), plain or
// gzip-compressed. Other messages (ODOM, PARAM, comments, ...) are ignored.
#pragma once

#include <wheelchair_logs/log_scan.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

namespace wheelchair_logs {

struct CarmenOptions {
  /// Readings at or beyond this are the scanner's "no echo" code (SICK: 81.9 m) and become
  /// +inf (REP-117: no return within range).
  double no_echo_range = 80.0;
  /// range_max of FLASER scans (ROBOTLASER1 lines carry their own, capped at this) [m].
  double range_max = 80.0;
  /// range_min of every scan [m] (the logs do not carry one).
  double range_min = 0.0;
};

/// Parses one log line. Returns a scan for a valid FLASER / ROBOTLASER1 line; nothing for any
/// other message; nothing with `error` set for a corrupt or truncated laser line.
/// FLASER carries no angles: n beams span 180 deg from -90 deg, in steps of 180/n deg for even
/// n (180, 360) and 180/(n-1) deg for odd n (181, 361).
std::optional<LogScan> parseCarmenLine(const std::string& line, const CarmenOptions& options,
                                       std::string& error);

class CarmenLogReader {
 public:
  /// Throws std::runtime_error (one line naming the file) if the file cannot be opened.
  CarmenLogReader(const std::string& path, const CarmenOptions& options = CarmenOptions());
  ~CarmenLogReader();
  CarmenLogReader(const CarmenLogReader&) = delete;
  CarmenLogReader& operator=(const CarmenLogReader&) = delete;

  /// Next valid scan, false at the end of the file. A corrupt laser line is reported by
  /// problemsOfLastCall() and skipped.
  bool next(LogScan& out);
  /// "<file>:<line>: <problem>" for each corrupt line met during the last next() call.
  const std::string& problemsOfLastCall() const { return problems_; }
  size_t corruptLines() const { return corrupt_lines_; }
  size_t problemCount() const { return corrupt_lines_; }
  /// Fraction of the (compressed) file read so far, 0..1.
  double progress() const;

 private:
  bool readLine(std::string& line);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  CarmenOptions options_;
  size_t line_number_ = 0;
  size_t corrupt_lines_ = 0;
  std::string problems_;
};

}  // namespace wheelchair_logs
