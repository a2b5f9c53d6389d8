// The user's pipeline on real laser logs (../shared/data beside the repository; the tests skip
// without it): the map as build_map makes it from the corrected log (BayesMapper, defaults), the
// localizer with its defaults on the raw odometry, judged against the corrected poses.
#include <gtest/gtest.h>
#include <unistd.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_kld/kld_localizer.h>
#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_logs/reference.h>
#include <wheelchair_logs/splice.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/mrpt_conversions.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

namespace wheelchair_kld {
namespace {

using wheelchair_core::Pose2D;
using wheelchair_logs::LogScan;

const std::string kData = WHEELCHAIR_SHARED_DATA_DIR;

std::vector<LogScan> readLog(const std::string& path) {
  wheelchair_logs::CarmenLogReader reader(path);
  std::vector<LogScan> scans;
  for (LogScan s; reader.next(s);) scans.push_back(std::move(s));
  return scans;
}

/// build_map's map of a corrected log, as the user gets it: saved as map_server's trinary
/// YAML + PGM and loaded again.
std::shared_ptr<const LocalizationMap> buildMap(const std::string& corrected,
                                                const KldParams& params) {
  wheelchair_mapping::MapperConfig config;
  config.model.no_return_is_free = false;  // build_map's default (--no-echo-free 0)
  wheelchair_mapping::BayesMapper mapper(config);
  for (const LogScan& s : readLog(corrected)) mapper.insert(s.scan, s.laser_pose);
  const auto dir =
      std::filesystem::temp_directory_path() / ("kld_real_logs_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string yaml = (dir / "map.yaml").string();
  wheelchair_core::saveMap(mapper.map(), yaml);
  const auto map = wheelchair_core::loadMap(yaml);
  std::filesystem::remove_all(dir);
  return std::make_shared<LocalizationMap>(wheelchair_mapping::toMrptGrid(map),
                                           params.measurement.max_distance);
}

struct Replay {
  int relocalizations = 0;
  double position_rms = 0, heading_rms = 0;
  size_t matched = 0;
  /// After the splice: updates until "not localized", until the re-localization (-1: none).
  int noticed = -1, relocalized_at = -1;
  int max_weighings = 0;  ///< most particles weighed in one update after the first
  /// Largest position error at a reference more than 30 updates after the splice.
  double max_error_after = 0;
};

/// The raw log through the filter from the first reference pose (10 cm / 3 deg); with
/// kidnap_at >= 0 the drive jumps after that scan to scan kidnap_from, the odometry unaware.
Replay replay(const std::vector<LogScan>& raw, const std::string& reference_log,
              const std::shared_ptr<const LocalizationMap>& map, const KldParams& params,
              long kidnap_at = -1, long kidnap_from = -1) {
  wheelchair_logs::ReferenceTrajectory reference(readLog(reference_log));
  const std::vector<LogScan> scans =
      kidnap_at >= 0 ? wheelchair_logs::spliceKidnapping(raw, kidnap_at, kidnap_from) : raw;
  KldLocalizer filter(map, params, 1);
  Replay r;
  bool started = false;
  double sum_xy = 0, sum_th = 0;
  int updates_after = 0, relocs_before = 0;
  for (size_t i = 0; i < scans.size(); ++i) {
    const LogScan* ref = reference.match(scans[i], wheelchair_logs::ReferenceMatch::kReadings);
    if (!started) {
      if (!ref) continue;
      filter.initGaussian(ref->laser_pose, Eigen::Vector3d(0.01, 0.01, 0.0027).asDiagonal());
      started = true;
    }
    const bool first_update = !r.matched && updates_after == 0;
    const bool updated =
        filter.update(scans[i].odom_pose, scans[i].scan, Pose2D{}) == UpdateResult::kUpdated;
    if (updated && !first_update)
      r.max_weighings = std::max(r.max_weighings, filter.lastUpdateWeighings());
    if (kidnap_at >= 0 && static_cast<long>(i) == kidnap_at)
      relocs_before = filter.relocalizations();
    if (kidnap_at >= 0 && static_cast<long>(i) > kidnap_at && updated) {
      ++updates_after;
      if (r.noticed < 0 && !filter.status().localized()) r.noticed = updates_after;
      if (r.relocalized_at < 0 && filter.relocalizations() > relocs_before)
        r.relocalized_at = updates_after;
    }
    if (!ref) continue;
    const Pose2D& e = filter.estimate().mean;
    sum_xy += std::pow(e.x - ref->laser_pose.x, 2) + std::pow(e.y - ref->laser_pose.y, 2);
    sum_th += std::pow(wheelchair_core::angleDifference(e.yaw, ref->laser_pose.yaw), 2);
    if (kidnap_at >= 0 && updates_after > 30)
      r.max_error_after =
          std::max(r.max_error_after, std::hypot(e.x - ref->laser_pose.x, e.y - ref->laser_pose.y));
    ++r.matched;
  }
  r.relocalizations = filter.relocalizations();
  r.position_rms = std::sqrt(sum_xy / std::max<size_t>(1, r.matched));
  r.heading_rms = std::sqrt(sum_th / std::max<size_t>(1, r.matched));
  return r;
}

bool haveData(const std::vector<std::string>& files) {
  for (const auto& f : files)
    if (!std::filesystem::exists(f)) return false;
  return true;
}

const std::string kIntelRaw = kData + "/intel/derived_intel_gt_rawodom.clf";
const std::string kIntelCorrected = kData + "/intel/intel-corrected.log.gz";
const std::string kFr101Raw = kData + "/fr101/fr101.carmen.log.gz";
const std::string kFr101Corrected = kData + "/fr101/fr101.carmen.gfs.log.gz";

// Issue 21: on build_map's Intel map the mean-fit rule (window 10 below 0.85) threw the correct
// track away 5 times (1.28 m RMS); the contradiction rule keeps it, and the likelihood's peak as
// the estimate with the untempered likelihood brings it from 10.8 cm / 1.80 deg to 4.7 cm /
// 0.76 deg.
TEST(RealLogs, IntelTrackIsNeverThrownAwayOnTheBuildMapMap) {
  if (!haveData({kIntelRaw, kIntelCorrected}))
    GTEST_SKIP() << "no real logs at " << kData << " (../shared/data beside the repository)";
  const KldParams params;
  const auto map = buildMap(kIntelCorrected, params);
  const auto scans = readLog(kIntelRaw);
  const std::string& raw = kIntelRaw;
  const Replay r = replay(scans, raw, map, params);
  std::cout << "Intel: " << r.relocalizations << " re-localizations, " << r.position_rms << " m, "
            << r.heading_rms * 180 / M_PI << " deg RMS over " << r.matched << "\n";
  EXPECT_EQ(r.relocalizations, 0);
  EXPECT_EQ(r.matched, scans.size());
  EXPECT_LT(r.position_rms, 0.05);  // issue 21's target: 5 cm, 1 deg
  EXPECT_LT(r.heading_rms, 1.0 * M_PI / 180);

  // The filter before issue 21: the mean-fit rule on the posterior mean of the tempered
  // likelihood (exponent 0.1), whose fit sat low because the mean was 10 cm off.
  KldParams old_rule = params;
  old_rule.relocalize_on_mean_fit = true;
  old_rule.peak_estimate = false;
  old_rule.measurement.likelihood_exponent = 0.1;
  old_rule.fit_max_short_share = 0.0;  // every short return counted against the pose
  EXPECT_GT(replay(scans, raw, map, old_rule).relocalizations, 0) << "the old rule's failure";
}

// Two distant parts of the Intel drive spliced together (a kidnapping the odometry does not
// see): noticed at once, and the pose found again, whether by a global re-localization or by the
// augmented filter's random poses (300 -> 600 on the lattice-aligned build_map map: no
// re-localization, bounded or not; 0.20 m largest error after 30 updates).
TEST(RealLogs, AKidnappingSplicedIntoIntelIsNoticedWithinTwoUpdates) {
  if (!haveData({kIntelRaw, kIntelCorrected}))
    GTEST_SKIP() << "no real logs at " << kData << " (../shared/data beside the repository)";
  const KldParams params;
  const auto map = buildMap(kIntelCorrected, params);
  const auto scans = readLog(kIntelRaw);
  const std::string& raw = kIntelRaw;
  for (const auto& [at, from] : {std::pair<long, long>{300, 600}, {700, 150}}) {
    const Replay r = replay(scans, raw, map, params, at, from);
    std::cout << "splice " << at << " -> " << from << ": noticed at update " << r.noticed
              << ", re-localization at update " << r.relocalized_at
              << ", largest error after 30 updates " << r.max_error_after << " m\n";
    EXPECT_GE(r.noticed, 1);
    EXPECT_LE(r.noticed, 2);
    EXPECT_LE(r.relocalized_at, 10) << "a re-localization, if any, within a few updates";
    EXPECT_LT(r.max_error_after, 0.5) << "the pose is found again";
  }
}

// FR101's raw log on the map of its 292 corrected scans. The re-localizations are right: at
// 1351-1358 s (scans 4362-4393) the odometry turns while the scans say otherwise, the tracked
// pose leaves 86 of 354 echoes near an obstacle (132 in known-free space) and the re-localized
// pose explains 333. With the untempered likelihood the filter re-localizes twice in that episode
// (scans 4386 and 4393), never elsewhere.
TEST(RealLogs, Fr101RawLogTracksItsCorrectedPoses) {
  if (!haveData({kFr101Raw, kFr101Corrected}))
    GTEST_SKIP() << "no real logs at " << kData << " (../shared/data beside the repository)";
  const std::string &raw = kFr101Raw, &corrected = kFr101Corrected;
  const KldParams params;
  const auto map = buildMap(corrected, params);
  const Replay r = replay(readLog(raw), corrected, map, params);
  std::cout << "FR101: " << r.relocalizations << " re-localizations, " << r.position_rms << " m, "
            << r.heading_rms * 180 / M_PI << " deg RMS over " << r.matched << "\n";
  EXPECT_LE(r.relocalizations, 2);
  EXPECT_EQ(r.matched, 292u);
  EXPECT_LT(r.position_rms, 0.05);
  EXPECT_LT(r.heading_rms, 0.6 * M_PI / 180);
}

// FR101 with a kidnapping spliced in (scan 1500, then 3000 on): noticed at once, and while lost
// no update weighs more than update_max_particles (unbounded the set grew to 100000: 160-274 ms
// of CPU per update against the 0.21 s scan period); the pose is found again.
TEST(RealLogs, AKidnappingSplicedIntoFr101IsNoticedAndEveryUpdateStaysWithinTheBound) {
  if (!haveData({kFr101Raw, kFr101Corrected}))
    GTEST_SKIP() << "no real logs at " << kData << " (../shared/data beside the repository)";
  const std::string &raw = kFr101Raw, &corrected = kFr101Corrected;
  const KldParams params;
  const auto map = buildMap(corrected, params);
  const Replay r = replay(readLog(raw), corrected, map, params, 1500, 3000);
  std::cout << "FR101 splice 1500 -> 3000: noticed at update " << r.noticed << ", at most "
            << r.max_weighings << " particles weighed per update, largest error after 30 updates "
            << r.max_error_after << " m\n";
  EXPECT_GE(r.noticed, 1);
  EXPECT_LE(r.noticed, 2);
  EXPECT_LE(r.max_weighings, params.update_max_particles);
  EXPECT_GT(r.max_weighings, 5000) << "the bound was never approached: not a test of it";
  EXPECT_LT(r.max_error_after, 0.5);
}

}  // namespace
}  // namespace wheelchair_kld
