// A reference trajectory for a replayed log (e.g. the SLAM-corrected log of the same drive) and
// how a replayed scan finds its reference pose: the reference scan with the same readings (a
// corrected log carries the raw log's scans, whatever its time base), or the nearest stamp.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_logs/log_scan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace wheelchair_logs {

enum class ReferenceMatch {
  kReadings,  ///< identical readings (+inf alike)
  kStamp,     ///< nearest stamp within the tolerance, after the offset
};

/// "readings" / "stamp"; throws std::invalid_argument otherwise.
ReferenceMatch referenceMatchFromName(const std::string& name);

class ReferenceTrajectory {
 public:
  /// The reference poses are the scans' laser poses (a corrected log's FLASER poses).
  explicit ReferenceTrajectory(std::vector<LogScan> scans);

  /// The reference scan for `scan`, or nothing. kReadings: among reference scans with the same
  /// readings, the first after the previous match (a robot standing still repeats its scans).
  /// kStamp: the nearest reference stamp to scan.stamp + offset within tolerance.
  const LogScan* match(const LogScan& scan, ReferenceMatch how, double offset = 0.0,
                       double tolerance = 0.01);
  size_t size() const { return scans_.size(); }
  const std::vector<LogScan>& scans() const { return scans_; }

 private:
  std::vector<LogScan> scans_;  ///< sorted by stamp
  std::unordered_multimap<uint64_t, size_t> by_readings_;
  size_t last_match_ = 0;
};

/// A hash of a scan's readings (equal readings, equal hash; every +inf alike).
uint64_t readingsHash(const wheelchair_core::LaserScan2D& scan);
bool sameReadings(const wheelchair_core::LaserScan2D& a, const wheelchair_core::LaserScan2D& b);

/// Position and heading errors of estimates against their reference poses.
struct PoseErrors {
  size_t count = 0;
  double position_rms = 0, position_mean = 0, position_max = 0;  ///< [m]
  double heading_rms = 0, heading_mean = 0, heading_max = 0;     ///< [rad], absolute
};

struct PosePair {
  wheelchair_core::Pose2D estimate, reference;
};
PoseErrors poseErrors(const std::vector<PosePair>& pairs);

}  // namespace wheelchair_logs
