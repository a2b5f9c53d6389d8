#include "drive_evaluation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace wheelchair_kld::test {

namespace {
double threadCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e3 * ts.tv_sec + 1e-6 * ts.tv_nsec;
}
}  // namespace

UpdateTimer::UpdateTimer() : wall_(std::chrono::steady_clock::now()), cpu_ms_(threadCpuMs()) {}

void UpdateTimer::stop(StepRecord& r) const {
  r.update_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_).count();
  r.update_cpu_ms = threadCpuMs() - cpu_ms_;
}

std::vector<StepRecord> runDrive(KldLocalizer& localizer, const std::vector<DriveSample>& drive) {
  std::vector<StepRecord> out;
  out.reserve(drive.size());
  for (const auto& s : drive) {
    StepRecord r;
    const UpdateTimer timer;
    r.updated = localizer.update(s.odom, s.scan, s.sensor_pose) == UpdateResult::kUpdated;
    timer.stop(r);
    const auto& e = localizer.estimate().mean;
    r.error_xy = std::hypot(e.x - s.truth.x, e.y - s.truth.y);
    r.error_theta = std::abs(wheelchair_core::angleDifference(e.yaw, s.truth.yaw));
    r.particles = static_cast<int>(localizer.particleCount());
    r.localized = localizer.status().localized();
    out.push_back(r);
  }
  return out;
}

DriveSummary summarize(const std::vector<StepRecord>& steps, size_t from) {
  DriveSummary s;
  std::vector<double> times;
  double sxy = 0, sth = 0, sp = 0, cpu = 0;
  for (size_t i = from; i < steps.size(); ++i) {
    const auto& r = steps[i];
    if (!r.updated) continue;
    ++s.updates;
    sxy += r.error_xy * r.error_xy;
    sth += r.error_theta * r.error_theta;
    s.max_xy = std::max(s.max_xy, r.error_xy);
    sp += r.particles;
    s.max_particles = std::max(s.max_particles, r.particles);
    times.push_back(r.update_ms);
    cpu += r.update_cpu_ms;
  }
  if (s.updates == 0) return s;
  s.rms_xy = std::sqrt(sxy / s.updates);
  s.rms_theta = std::sqrt(sth / s.updates);
  s.mean_particles = sp / s.updates;
  s.mean_cpu_ms = cpu / s.updates;
  double tsum = 0;
  for (double t : times) tsum += t;
  s.mean_ms = tsum / times.size();
  std::sort(times.begin(), times.end());
  s.p99_ms = times[std::min(times.size() - 1, static_cast<size_t>(0.99 * times.size()))];
  return s;
}

}  // namespace wheelchair_kld::test
