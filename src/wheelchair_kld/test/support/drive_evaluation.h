// Test and bench harness (library wheelchair_kld_test_support, never installed): runs a
// localizer over a recorded or simulated drive and scores it against ground truth.
#pragma once

#include <wheelchair_kld/kld_localizer.h>

#include "synthetic_drive.h"

#include <chrono>
#include <vector>

namespace wheelchair_kld::test {

struct StepRecord {
  bool updated = false;
  bool localized = false;
  double error_xy = 0;     ///< [m] estimate vs truth
  double error_theta = 0;  ///< [rad], absolute
  int particles = 0;
  double update_ms = 0;      ///< wall time of the update call
  double update_cpu_ms = 0;  ///< CPU time of this thread in the update call (load-independent)
};

/// Wall and thread-CPU time of one call, in ms.
class UpdateTimer {
 public:
  UpdateTimer();
  /// Stores the time since construction into r.update_ms / r.update_cpu_ms.
  void stop(StepRecord& r) const;

 private:
  std::chrono::steady_clock::time_point wall_;
  double cpu_ms_;
};

/// Feeds every sample (odom + scan) to `localizer`; the estimate is scored after each call.
std::vector<StepRecord> runDrive(KldLocalizer& localizer, const std::vector<DriveSample>& drive);

struct DriveSummary {
  double rms_xy = 0, rms_theta = 0, max_xy = 0;
  double mean_particles = 0;
  int max_particles = 0;
  double mean_ms = 0, p99_ms = 0, mean_cpu_ms = 0;
  int updates = 0;
};

/// Statistics over the updated steps with index >= `from`.
DriveSummary summarize(const std::vector<StepRecord>& steps, size_t from = 0);

}  // namespace wheelchair_kld::test
