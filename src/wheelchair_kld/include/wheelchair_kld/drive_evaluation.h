// Runs a localizer over a recorded or simulated drive and scores it against ground truth.
#pragma once

#include <wheelchair_kld/kld_localizer.h>
#include <wheelchair_kld/synthetic_drive.h>

#include <vector>

namespace wheelchair_kld {

struct StepRecord {
  bool updated = false;
  bool localized = false;
  double error_xy = 0;     ///< [m] estimate vs truth
  double error_theta = 0;  ///< [rad], absolute
  int particles = 0;
  double update_ms = 0;  ///< wall time of the update call
};

/// Feeds every sample (odom + scan) to `localizer`; the estimate is scored after each call.
std::vector<StepRecord> runDrive(KldLocalizer& localizer, const std::vector<DriveSample>& drive);

struct DriveSummary {
  double rms_xy = 0, rms_theta = 0, max_xy = 0;
  double mean_particles = 0;
  int max_particles = 0;
  double mean_ms = 0, p99_ms = 0;
  int updates = 0;
};

/// Statistics over the updated steps with index >= `from`.
DriveSummary summarize(const std::vector<StepRecord>& steps, size_t from = 0);

}  // namespace wheelchair_kld
