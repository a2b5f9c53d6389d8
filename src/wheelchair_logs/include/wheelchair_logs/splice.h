// A kidnapping spliced into a real log: the drive jumps from one part of it to another while the
// odometry sees nothing (how the localizer's kidnap detection is measured on real data).
#pragma once

#include <wheelchair_logs/log_scan.h>

#include <vector>

namespace wheelchair_logs {

/// Scans 0..at, then from..end with their odometry (odom_pose) moved to continue from scan
/// `at`'s and their stamps to follow it (0.2 s later). Throws std::invalid_argument when `at`
/// or `from` is not a scan of the log.
std::vector<LogScan> spliceKidnapping(const std::vector<LogScan>& scans, long at, long from);

}  // namespace wheelchair_logs
