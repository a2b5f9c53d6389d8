// bench/kld measurement: KLD-MCL vs the same filter with a fixed particle count vs MRPT's
// CMonteCarloLocalization2D with its own adaptive (KLD) sample size, on simulated drives in the
// project's worlds and the Intel real log (its path on the command line; bench/kld/run gives
// ../shared/data's). The fixed count compared with is measured first: the
// smallest count whose global localization in the office succeeds as often as KLD's (row
// office_global / fixed_mcl / particles_needed_for_kld_success). Prints only a JSON array of
// {case, method, metric, value, unit}.
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>
#include <wheelchair_kld/mrpt_equivalent.h>
#include <wheelchair_logs/carmen_log.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "drive_evaluation.h"

using wheelchair_core::LaserScan2D;
using wheelchair_core::Pose2D;
using namespace wheelchair_kld;
using namespace wheelchair_kld::test;

namespace {

std::ostringstream json;
bool first_row = true;
constexpr int kTrackingFixed = 2000;  ///< a fixed count that tracks as well as KLD (not globally)
constexpr uint32_t kGlobalSeeds = 20;

void row(const std::string& c, const std::string& method, const std::string& metric, double value,
         const std::string& unit) {
  json << (first_row ? "" : ",\n") << "{\"case\":\"" << c << "\",\"method\":\"" << method
       << "\",\"metric\":\"" << metric << "\",\"value\":" << value << ",\"unit\":\"" << unit
       << "\"}";
  first_row = false;
}

void report(const std::string& c, const std::string& method, const DriveSummary& s) {
  row(c, method, "position_rms", 100 * s.rms_xy, "cm");
  row(c, method, "heading_rms", s.rms_theta * 180 / M_PI, "deg");
  row(c, method, "mean_particles", s.mean_particles, "particles");
  row(c, method, "max_particles", s.max_particles, "particles");
  row(c, method, "mean_update_time", s.mean_ms, "ms");
  row(c, method, "p99_update_time", s.p99_ms, "ms");
  row(c, method, "mean_update_cpu_time", s.mean_cpu_ms, "ms");
}

Eigen::Matrix3d diagCov(double sxy, double sth) {
  return Eigen::Vector3d(sxy * sxy, sxy * sxy, sth * sth).asDiagonal();
}

/// The scan as MRPT's observation (for MRPT's own filter and map building).
mrpt::obs::CObservation2DRangeScan::Ptr toMrptObservation(const LaserScan2D& s,
                                                          const Pose2D& sensor_pose) {
  auto obs = mrpt::obs::CObservation2DRangeScan::Create();
  obs->aperture = static_cast<float>(s.angle_increment * (s.ranges.size() - 1));
  obs->rightToLeft = true;
  obs->maxRange = static_cast<float>(s.range_max);
  obs->sensorPose = mrpt::poses::CPose3D(sensor_pose.x, sensor_pose.y, 0, sensor_pose.yaw, 0, 0);
  obs->resizeScan(s.ranges.size());
  for (size_t i = 0; i < s.ranges.size(); ++i) {
    const bool ok = std::isfinite(s.ranges[i]) && s.ranges[i] < s.range_max;
    obs->setScanRange(i, ok ? s.ranges[i] : static_cast<float>(s.range_max));
    obs->setScanRangeValidity(i, ok);
  }
  return obs;
}

/// A real laser log with a reference (../shared/data's derived_*_gt_rawodom logs): the
/// FLASER pose (the laser's, SLAM-corrected) is the reference, the odom fields (raw odometry) the
/// filter's input. Empty if the file cannot be read.
std::vector<DriveSample> loadCarmenDrive(const std::string& path) {
  wheelchair_logs::CarmenOptions options;
  options.range_min = 0.05;
  options.range_max = 50.0;  // readings of ~81.9 m are "no echo" (no_echo_range 80 m)
  std::vector<DriveSample> out;
  try {
    wheelchair_logs::CarmenLogReader reader(path, options);
    for (wheelchair_logs::LogScan s; reader.next(s);)
      out.push_back({s.laser_pose, s.odom_pose, std::move(s.scan), Pose2D{0, 0, 0}});
    if (reader.corruptLines() > 0)
      std::cerr << "bench/kld: " << path << ": " << reader.corruptLines() << " corrupt lines\n";
  } catch (const std::runtime_error& e) {
    std::cerr << "bench/kld: " << e.what() << "\n";
  }
  return out;
}

/// The occupancy grid of the scans inserted at their corrected poses (mapping with known poses).
mrpt::maps::COccupancyGridMap2D mapFromDrive(const std::vector<DriveSample>& drive, float res) {
  mrpt::maps::COccupancyGridMap2D grid(-10, 10, -10, 10, res);
  grid.insertionOptions.maxDistanceInsertion = 30.0f;
  for (const auto& s : drive)
    grid.insertObservation(*toMrptObservation(s.scan, s.sensor_pose),
                           mrpt::poses::CPose3D(s.truth.x, s.truth.y, 0, s.truth.yaw, 0, 0));
  return grid;
}

/// MRPT's own particle filter with adaptive sample size, tracking from a box around `start`.
std::vector<StepRecord> runMrpt(const LocalizationMap& map, const std::vector<DriveSample>& drive,
                                const KldParams& kp) {
  auto grid = mrpt::maps::COccupancyGridMap2D::Create(map.grid());
  grid->likelihoodOptions.likelihoodMethod =
      mrpt::maps::COccupancyGridMap2D::lmLikelihoodField_Thrun;
  grid->likelihoodOptions.LF_decimation = kp.measurement.beam_step;
  grid->likelihoodOptions.LF_stdHit = static_cast<float>(kp.measurement.sigma_hit);
  grid->likelihoodOptions.LF_maxCorrsDistance = static_cast<float>(kp.measurement.max_distance);
  mrpt::slam::CMonteCarloLocalization2D pdf;
  pdf.options.metricMap = grid;
  pdf.options.KLD_params.KLD_binSize_XY = kp.bin_xy;
  pdf.options.KLD_params.KLD_binSize_PHI = kp.bin_theta;
  pdf.options.KLD_params.KLD_epsilon = kp.epsilon;
  pdf.options.KLD_params.KLD_delta = kp.delta;
  pdf.options.KLD_params.KLD_minSampleSize = kp.min_particles;
  pdf.options.KLD_params.KLD_maxSampleSize = kp.max_particles;
  const Pose2D& t0 = drive.front().truth;
  pdf.resetUniform(t0.x - 0.2, t0.x + 0.2, t0.y - 0.2, t0.y + 0.2, t0.yaw - 0.1, t0.yaw + 0.1,
                   2000);
  mrpt::bayes::CParticleFilter pf;
  // The same odometry noise and likelihood tempering as ours, instead of MRPT's defaults (1 %
  // translation noise, no tempering).
  pf.m_options = wheelchair_kld::mrptFilterOptions(kp);
  const auto motion = wheelchair_kld::mrptThrunMotion(kp);
  mrpt::random::CRandomGenerator motion_rng(1);
  std::vector<StepRecord> out;
  auto mrptPose = [](const Pose2D& p) { return mrpt::poses::CPose2D(p.x, p.y, p.yaw); };
  Pose2D last = drive.front().odom;
  bool first = true;
  for (const auto& s : drive) {
    StepRecord r;
    const mrpt::poses::CPose2D inc = mrptPose(s.odom) - mrptPose(last);
    if (first || inc.norm() >= kp.update_min_d || std::abs(inc.phi()) >= kp.update_min_a) {
      mrpt::obs::CActionCollection actions;
      mrpt::obs::CActionRobotMovement2D act;
      act.computeFromOdometry(inc, motion);
      // Our odometry model's samples, as replay --mrpt (MRPT's Thrun model decomposes a turn on
      // the spot's creep into two half turns and spreads the position by its alfa4)
      act.poseChange = wheelchair_kld::mrptOdometrySamples(
          mrpt::math::TPose2D(last.x, last.y, last.yaw),
          mrpt::math::TPose2D(s.odom.x, s.odom.y, s.odom.yaw), kp.motion, motion_rng);
      actions.insert(act);
      mrpt::obs::CSensoryFrame sf;
      sf.insert(toMrptObservation(s.scan, s.sensor_pose));
      const UpdateTimer timer;
      pf.executeOn(pdf, &actions, &sf);
      timer.stop(r);
      r.updated = true;
      last = s.odom;
      first = false;
    }
    mrpt::poses::CPose2D mean;
    pdf.getMean(mean);
    r.error_xy = std::hypot(mean.x() - s.truth.x, mean.y() - s.truth.y);
    r.error_theta = std::abs(wheelchair_core::angleDifference(mean.phi(), s.truth.yaw));
    r.particles = static_cast<int>(pdf.size());
    out.push_back(r);
  }
  return out;
}

/// Concatenated step records of several seeded drives.
void append(std::vector<StepRecord>& all, const std::vector<StepRecord>& more, size_t skip) {
  all.insert(all.end(), more.begin() + std::min(skip, more.size()), more.end());
}

/// KLD vs fixed-size MCL (with `fixed_needed` particles and with kTrackingFixed) vs MRPT's
/// filter, tracking the drives from a 10 cm / 3 deg prior at their first scan.
void compareTracking(const std::string& c, const std::shared_ptr<const LocalizationMap>& map,
                     const std::vector<std::vector<DriveSample>>& drives, const KldParams& kp,
                     int fixed_needed) {
  std::vector<std::pair<std::string, int>> methods = {
      {"kld", 0}, {"fixed_mcl_" + std::to_string(fixed_needed), fixed_needed}};
  if (kTrackingFixed != fixed_needed)
    methods.push_back({"fixed_mcl_" + std::to_string(kTrackingFixed), kTrackingFixed});
  double kld_ms = 0, kld_cpu = 0;
  for (const auto& [method, n] : methods) {
    KldParams p = kp;
    p.fixed_particles = n;
    std::vector<StepRecord> all;
    uint32_t seed = 1;
    for (const auto& drive : drives) {
      KldLocalizer loc(map, p, seed++);
      loc.initGaussian(drive[0].truth, diagCov(0.1, 0.05));
      append(all, runDrive(loc, drive), 5);
    }
    const auto s = summarize(all);
    report(c, method, s);
    if (n == 0) {
      kld_ms = s.mean_ms;
      kld_cpu = s.mean_cpu_ms;
    } else if (n == fixed_needed) {
      row(c, method, "mean_time_over_kld", s.mean_ms / kld_ms, "x");
      row(c, method, "mean_cpu_time_over_kld", s.mean_cpu_ms / kld_cpu, "x");
    }
  }
  std::vector<StepRecord> mrpt_all;
  for (const auto& drive : drives) append(mrpt_all, runMrpt(*map, drive, kp), 5);
  report(c, "mrpt_kld", summarize(mrpt_all));
}

/// The Intel Research Lab log: KLD vs fixed-size MCL vs MRPT's filter, from a 10 cm / 3 deg
/// prior at the first scan, on a map built from the same log's corrected scans (so the map fits
/// better than a separately surveyed one would: the figures are optimistic for all three).
void benchRealLog(const std::string& path, int fixed_needed) {
  const auto drive = path.empty() ? std::vector<DriveSample>() : loadCarmenDrive(path);
  if (drive.empty()) {
    std::cerr << "bench/kld: no scans from '" << path << "': real-log case skipped\n";
    return;
  }
  KldParams kp;
  kp.measurement.beam_step = 3;  // 180 beams at 1 deg: 60 used, as 361 / 6 in the worlds
  const auto map =
      std::make_shared<LocalizationMap>(mapFromDrive(drive, 0.05f), kp.measurement.max_distance);
  compareTracking("intel_real_log", map, {drive}, kp, fixed_needed);
}

struct GlobalResult {
  int ok = 0, worst = 0;  ///< successes of 20, worst number of updates to converge
  DriveSummary summary;
};

/// Global localization in the office from a uniform prior, 20 seeds, the first 40 scans of the
/// office route: success = localized within 20 cm for good. `fixed` = 0: KLD-MCL.
GlobalResult globalInOffice(const std::shared_ptr<const LocalizationMap>& map, const KldParams& kp,
                            int fixed) {
  KldParams gp = kp;
  gp.fixed_particles = fixed;
  GlobalResult g;
  std::vector<StepRecord> all;
  for (uint32_t seed = 1; seed <= kGlobalSeeds; ++seed) {
    DriveParams dp;
    dp.seed = seed;
    auto drive = simulateDrive(map->grid(), worldRoute("office"), dp);
    drive.resize(std::min<size_t>(drive.size(), 40));
    KldLocalizer loc(map, gp, seed);
    loc.initGlobal();
    const auto steps = runDrive(loc, drive);
    int updates = 0, at = -1;
    for (const auto& r : steps) {
      updates += r.updated;
      const bool good = r.localized && r.error_xy < 0.2;
      if (good && at < 0) at = updates;
      if (!good) at = -1;
    }
    if (at > 0) {
      ++g.ok;
      g.worst = std::max(g.worst, at);
    }
    append(all, steps, 0);
  }
  g.summary = summarize(all);
  const std::string method = fixed == 0 ? "kld" : "fixed_mcl_" + std::to_string(fixed);
  row("office_global", method, "success", g.ok, "of 20");
  row("office_global", method, "worst_updates_to_converge", g.worst, "updates");
  row("office_global", method, "mean_particles", g.summary.mean_particles, "particles");
  row("office_global", method, "max_particles", g.summary.max_particles, "particles");
  row("office_global", method, "mean_update_time", g.summary.mean_ms, "ms");
  row("office_global", method, "p99_update_time", g.summary.p99_ms, "ms");
  row("office_global", method, "mean_update_cpu_time", g.summary.mean_cpu_ms, "ms");
  return g;
}

/// The smallest fixed particle count (of a doubling-ish ladder) whose global-localization
/// success in the office matches KLD's: the count fixed-size MCL needs for KLD's success, and
/// so the count it must run with all the time (it cannot adapt when tracking).
int fixedCountForKldSuccess(const std::string& worlds, const KldParams& kp) {
  const auto map = std::make_shared<LocalizationMap>(loadWorldGrid(worlds + "/office.yaml"),
                                                     kp.measurement.max_distance);
  const int kld_ok = globalInOffice(map, kp, 0).ok;
  int needed = 0;
  for (const int n : {2000, 5000, 10000, 20000, 50000, 100000}) {
    if (globalInOffice(map, kp, n).ok >= kld_ok) {
      needed = n;
      break;
    }
  }
  row("office_global", "fixed_mcl", "particles_needed_for_kld_success", needed, "particles");
  if (needed == 0) {
    std::cerr << "bench/kld: no fixed count up to 100000 matches KLD's success; using 100000\n";
    needed = 100000;
  }
  return needed;
}

const char* kUsage =
    "usage: kld_bench [--worlds DIR] [--intel-log FILE] [real]\n"
    "  --worlds DIR      the project's test worlds (default test/worlds)\n"
    "  --intel-log FILE  derived_intel_gt_rawodom.clf (corrected FLASER poses + raw odometry);\n"
    "                    without it the real-log case is skipped\n"
    "  real              only the fixed-count search and the real-log case\n";

}  // namespace

int main(int argc, char** argv) {
  std::string worlds = "test/worlds", intel_log;
  bool only_real = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--worlds" && i + 1 < argc) {
      worlds = argv[++i];
    } else if (arg == "--intel-log" && i + 1 < argc) {
      intel_log = argv[++i];
    } else if (arg == "real") {
      only_real = true;
    } else {
      std::cerr << "kld_bench: bad argument '" << arg << "'\n" << kUsage;
      return 2;
    }
  }
  const KldParams kp;
  // Measured first: every fixed-size comparison below uses the count it needs for KLD's
  // global-localization success (the real-log case too).
  const int needed = fixedCountForKldSuccess(worlds, kp);
  benchRealLog(intel_log, needed);
  if (!only_real) {
    for (const std::string world : {"flat", "office"}) {
      const auto map = std::make_shared<LocalizationMap>(
          loadWorldGrid(worlds + "/" + world + ".yaml"), kp.measurement.max_distance);
      std::vector<std::vector<DriveSample>> drives;
      for (uint32_t seed = 1; seed <= 3; ++seed) {
        DriveParams dp;
        dp.seed = seed;
        drives.push_back(simulateDrive(map->grid(), worldRoute(world), dp));
      }
      compareTracking(world + "_tracking", map, drives, kp, needed);
    }
  }
  std::cout << "[\n" << json.str() << "\n]\n";
  return 0;
}
