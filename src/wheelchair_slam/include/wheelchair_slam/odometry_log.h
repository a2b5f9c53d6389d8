// Laser scans with the robot's raw odometry from CARMEN logs (plain or gzip). The scan itself is
// parsed by wheelchair_logs' CARMEN reader; this adds what that reader does not give yet:
// the odometry of each scan (for issue 21's reader to take over).
//   kFields:        the odom_x odom_y odom_theta fields of FLASER (ROBOTLASER1: the robot pose)
//                   are raw odometry (raw logs, the derived_*_gt_rawodom.clf files).
//   kGfsIncrements: a GMapping-corrected log (.gfs.log): FLASER holds the corrected pose in both
//                   fields, and the last ODOM line before each FLASER is the previous scan's
//                   corrected pose (+) the raw odometry increment since it; the raw odometry is
//                   the chain of those increments (starting at 0, 0, 0).
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>

#include <cstddef>
#include <memory>
#include <string>

namespace wheelchair_slam {

enum class OdometrySource { kFields, kGfsIncrements };

/// "fields" / "gfs"; throws std::invalid_argument otherwise.
OdometrySource odometrySourceFromName(const std::string& name);

struct OdometryScan {
  wheelchair_core::LaserScan2D scan;
  wheelchair_core::Pose2D odometry;     ///< raw odometry at the scan
  wheelchair_core::Pose2D logged_pose;  ///< the laser pose the log holds
  size_t line = 0;                      ///< 1-based line number
};

class OdometryLogReader {
 public:
  /// Throws std::runtime_error naming the file if it cannot be opened.
  OdometryLogReader(const std::string& path, OdometrySource source);
  ~OdometryLogReader();
  OdometryLogReader(const OdometryLogReader&) = delete;
  OdometryLogReader& operator=(const OdometryLogReader&) = delete;

  /// Next valid laser scan; false at the end. Corrupt lines are skipped and reported by
  /// problemsOfLastCall().
  bool next(OdometryScan& out);
  const std::string& problemsOfLastCall() const { return problems_; }
  size_t corruptLines() const { return corrupt_lines_; }
  double progress() const;  ///< fraction of the file read, 0..1

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string problems_;
  size_t corrupt_lines_ = 0;
};

}  // namespace wheelchair_slam
