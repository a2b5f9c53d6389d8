// Laser scans with their poses and the robot's raw odometry from CARMEN logs (FLASER and
// ROBOTLASER1 lines, plain or gzip-compressed): the one CARMEN reader of the project (build_map,
// replay, slam, the benchmarks). It applies the conventions real logs need:
// - the "no echo" code is detected per log (SICK: 81.83-81.91 m, clipped logs: their clip value,
//   others 32.767 m or ~51.1 m) and such readings become +inf (REP-117 "no return");
// - a scan given twice (ROBOTLASER1 and FLASER with the same stamp and readings) is returned once
//   and counted;
// - the raw odometry of each scan comes from the line's odom fields or, in a GMapping-corrected
//   log, from the ODOM increments between scans.
#pragma once

#include <wheelchair_logs/log_scan.h>

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <string>

namespace wheelchair_logs {

/// Where the raw odometry of a scan comes from (LogScan::odom_pose).
enum class OdometrySource {
  /// FLASER's odom_x odom_y odom_theta (ROBOTLASER1: the robot pose): raw logs and the
  /// derived_*_gt_rawodom.clf files.
  kFields,
  /// A GMapping-corrected log (.gfs.log): FLASER holds the corrected pose in both fields and the
  /// last ODOM line before each FLASER is the previous scan's corrected pose (+) the raw odometry
  /// increment since it; the raw odometry is the chain of those increments from (0, 0, 0).
  kGfsIncrements,
};

/// "fields" / "gfs"; throws std::invalid_argument otherwise.
OdometrySource odometrySourceFromName(const std::string& name);

struct CarmenOptions {
  /// Readings at or beyond this are the scanner's "no echo" code and become +inf. With
  /// detect_no_echo the reader replaces it by the code it finds in the log.
  double no_echo_range = 80.0;
  /// Find the no-echo code of the log in a first pass over it (see detectNoEcho()).
  bool detect_no_echo = true;
  /// range_max of FLASER scans (ROBOTLASER1 lines carry their own, capped at this) [m].
  double range_max = 80.0;
  /// range_min of every scan [m] (the logs do not carry one).
  double range_min = 0.0;
  OdometrySource odometry = OdometrySource::kFields;
  /// Return a scan only once when the log gives it twice (same readings, stamps within
  /// kDuplicateStampTolerance, among the last kDuplicateWindow scans).
  bool drop_duplicates = true;
};

/// Stamps of two lines of one scan differ by at most this [s] (they are printed alike).
constexpr double kDuplicateStampTolerance = 0.005;
/// How many of the latest scans a new one is compared with for duplicates.
constexpr size_t kDuplicateWindow = 4;

/// What the first pass found about the log's no-echo code.
struct NoEchoCode {
  bool found = false;
  double code = 0.0;       ///< the largest reading of the log, repeated like a code [m]
  double threshold = 0.0;  ///< readings >= this are "no echo" (code - kNoEchoBand)
  size_t at_code = 0;      ///< readings equal to the code
  size_t readings = 0;     ///< all readings of the log's laser lines
};

/// Readings within this below the code are other codes of the same scanner (SICK: 81.83 m
/// "dazzled" beside 81.91 m "no echo") [m].
constexpr double kNoEchoBand = 0.1;
/// The largest reading is a code when at least this share of all readings (and 10) equal it.
constexpr double kNoEchoMinShare = 0.001;

/// The no-echo code of a log: its largest reading, if it is repeated like a code (at least
/// kNoEchoMinShare of all readings and 10 readings exactly equal to it); readings within
/// kNoEchoBand below it count as no echo too. Not found: a log without such readings. Throws
/// std::runtime_error naming the file if it cannot be read.
NoEchoCode detectNoEcho(const std::string& path);

/// Parses one log line. Returns a scan for a valid FLASER / ROBOTLASER1 line; nothing for any
/// other message; nothing with `error` set for a corrupt or truncated laser line.
/// FLASER carries no angles: n beams span 180 deg from -90 deg, in steps of 180/n deg for even
/// n (180, 360) and 180/(n-1) deg for odd n (181, 361). odom_pose holds the line's odom fields.
std::optional<LogScan> parseCarmenLine(const std::string& line, const CarmenOptions& options,
                                       std::string& error);

class CarmenLogReader {
 public:
  /// Throws std::runtime_error (one line naming the file) if the file cannot be opened.
  CarmenLogReader(const std::string& path, const CarmenOptions& options = CarmenOptions());
  ~CarmenLogReader();
  CarmenLogReader(const CarmenLogReader&) = delete;
  CarmenLogReader& operator=(const CarmenLogReader&) = delete;

  /// Next valid scan, false at the end of the file. A corrupt line is reported by
  /// problemsOfLastCall() and skipped; a duplicate scan is skipped and counted.
  bool next(LogScan& out);
  /// "<file>:<line>: <problem>" for each corrupt line met during the last next() call.
  const std::string& problemsOfLastCall() const { return problems_; }
  size_t corruptLines() const { return corrupt_lines_; }
  size_t problemCount() const { return corrupt_lines_; }
  /// Scans dropped because the log gave them twice.
  size_t duplicatesDropped() const { return duplicates_; }
  /// The options in use (no_echo_range as detected).
  const CarmenOptions& options() const { return options_; }
  /// The first pass's finding (found = false when detection was off).
  const NoEchoCode& noEcho() const { return no_echo_; }
  /// PARAM robot_frontlaser_offset of the log [m along the robot's x axis], if it has one.
  std::optional<double> frontLaserOffset() const { return front_laser_offset_; }
  /// Fraction of the (compressed) file read so far, 0..1.
  double progress() const;

 private:
  bool readLine(std::string& line);
  void report(const std::string& problem);
  bool isDuplicate(const LogScan& scan);
  void applyOdometry(LogScan& scan);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  CarmenOptions options_;
  NoEchoCode no_echo_;
  std::optional<double> front_laser_offset_;
  size_t line_number_ = 0;
  size_t corrupt_lines_ = 0;
  size_t duplicates_ = 0;
  std::string problems_;
  std::deque<LogScan> recent_;  ///< the latest scans returned (duplicate check)
  // kGfsIncrements: the chain of raw odometry increments.
  bool have_previous_ = false, have_odom_line_ = false;
  wheelchair_core::Pose2D previous_corrected_, odometry_, last_odom_line_;
};

}  // namespace wheelchair_logs
