// rosrun wheelchair_kld replay --map MAP.yaml --log FILE [options]
// Runs the localizer's core on a recorded drive (a CARMEN log, plain or gzip, or a rosbag) and
// writes, per scan, the estimate, its covariance, the status, the particle count and the update
// time; with a reference (a corrected log of the same drive, matched by identical readings or by
// stamp) and/or a relations file, prints the error table (position / heading RMS, mean, max;
// Kuemmerle relation error) and the re-localizations. A progress bar on a terminal.
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPosePDFParticles.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>
#include <wheelchair_core/config.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_kld/kld_localizer.h>
#include <wheelchair_kld/mrpt_equivalent.h>
#include <wheelchair_kld/odometry_motion_model.h>
#include <wheelchair_kld/reference_fit.h>
#include <wheelchair_logs/bag_scans.h>
#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_logs/progress_bar.h>
#include <wheelchair_logs/reference.h>
#include <wheelchair_logs/relations.h>
#include <wheelchair_logs/splice.h>
#include <wheelchair_logs/trajectory_plot.h>
#include <wheelchair_mapping/mrpt_conversions.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using wheelchair_core::Pose2D;
using wheelchair_logs::LogScan;

const char* kUsage =
    "usage: replay --map MAP.yaml --log FILE [--out poses.csv] [--plot plot.png] [--json]\n"
    "  [--reference CORRECTED_LOG] [--match readings|stamp] [--offset S] [--tolerance S]\n"
    "  [--relations FILE] [--relations-offset S] [--initial x,y,yaw | --global]\n"
    "  [--config PARAMS.yaml] [--odometry fields|gfs] [--laser-x M] [--seed N] [--quiet]\n"
    "  [--kidnap-at K --kidnap-from J]: after the K-th scan the drive continues with the J-th\n"
    "  and later scans, the odometry unaware (a kidnapping spliced into a real log)\n"
    "  [--mrpt]: MRPT's CMonteCarloLocalization2D (its KLD sample size) instead of ours, with\n"
    "  our map, motion noise, likelihood field, KLD bins and update distances (--config keys),\n"
    "  the increments drawn from our odometry model (--mrpt-thrun: from MRPT's Thrun model)\n"
    "  [--reference-fit]: no filter; how well the reference poses fit the map (inlier share,\n"
    "  endpoint distances, the likelihood field's peak near each reference: the floor)\n"
    "  bag input: [--scan-topic /scan] [--odom-frame odom] [--base-frame base_link]\n"
    "             [--odom-topic /odom]\n"
    "The initial pose is --initial, else the first reference pose (10 cm / 3 deg prior), else\n"
    "global localization. --config: localizer keys as the nodelet's (fit_min_inliers, ...).\n";

struct Args {
  std::string map, log, out, plot, reference, relations, config, initial;
  std::string match = "readings", odometry = "fields";
  std::string scan_topic = "/scan", odom_frame = "odom", base_frame = "base_link", odom_topic;
  double offset = 0, tolerance = 0.01, relations_offset = 0, relations_tolerance = 0.01;
  double laser_x = 0;
  long kidnap_at = -1, kidnap_from = -1;
  bool mrpt = false, mrpt_thrun = false;
  bool global = false, json = false, quiet = false, reference_fit = false;
  uint64_t seed = 1;
};

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(k + " needs a value");
      return argv[++i];
    };
    if (k == "--map")
      a.map = value();
    else if (k == "--log")
      a.log = value();
    else if (k == "--out")
      a.out = value();
    else if (k == "--plot")
      a.plot = value();
    else if (k == "--reference")
      a.reference = value();
    else if (k == "--match")
      a.match = value();
    else if (k == "--offset")
      a.offset = std::stod(value());
    else if (k == "--tolerance")
      a.tolerance = std::stod(value());
    else if (k == "--relations")
      a.relations = value();
    else if (k == "--relations-offset")
      a.relations_offset = std::stod(value());
    else if (k == "--relations-tolerance")
      a.relations_tolerance = std::stod(value());
    else if (k == "--initial")
      a.initial = value();
    else if (k == "--global")
      a.global = true;
    else if (k == "--config")
      a.config = value();
    else if (k == "--odometry")
      a.odometry = value();
    else if (k == "--laser-x")
      a.laser_x = std::stod(value());
    else if (k == "--seed")
      a.seed = std::stoull(value());
    else if (k == "--scan-topic")
      a.scan_topic = value();
    else if (k == "--odom-frame")
      a.odom_frame = value();
    else if (k == "--base-frame")
      a.base_frame = value();
    else if (k == "--odom-topic")
      a.odom_topic = value();
    else if (k == "--kidnap-at")
      a.kidnap_at = std::stol(value());
    else if (k == "--kidnap-from")
      a.kidnap_from = std::stol(value());
    else if (k == "--mrpt")
      a.mrpt = true;
    else if (k == "--mrpt-thrun")
      a.mrpt = a.mrpt_thrun = true;
    else if (k == "--reference-fit")
      a.reference_fit = true;
    else if (k == "--json")
      a.json = true;
    else if (k == "--quiet")
      a.quiet = true;
    else
      return false;
  }
  return !a.map.empty() && !a.log.empty();
}

bool isBag(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".bag") == 0;
}

std::vector<LogScan> readCarmen(const std::string& path, const wheelchair_logs::CarmenOptions& o) {
  wheelchair_logs::CarmenLogReader reader(path, o);
  std::vector<LogScan> scans;
  for (LogScan s; reader.next(s);) scans.push_back(std::move(s));
  return scans;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))];
}

struct Record {
  double stamp;
  Pose2D laser;  ///< the laser's estimated pose in the map (compared with the reference)
  wheelchair_kld::PoseEstimate estimate;
  wheelchair_core::LocalizationStatus status;
  double update_ms, cpu_ms;
  bool updated;
  int relocalizations;
  std::optional<Pose2D> reference;
  wheelchair_kld::MeasurementModel::FitCounts fit;
};

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

/// The laser's pose on the robot: a bag's tf gives it per scan (LogScan: laser and base poses
/// in the odom frame); a CARMEN log's laser is at --laser-x on the robot's axis.
Pose2D sensorPose(const LogScan& s, bool bag, const Args& a) {
  return bag ? wheelchair_core::between(s.odom_pose, s.laser_pose) : Pose2D{a.laser_x, 0, 0};
}

void printReferenceFit(const wheelchair_kld::ReferenceFitSummary& s, bool json) {
  const double deg = 180.0 / M_PI;
  if (json) {
    std::printf(
        "{\"references\": %zu, \"inlier_share_mean\": %.4f, \"known_fit_mean\": %.4f, "
        "\"distance_p50_m\": %.4f, \"distance_p90_m\": %.4f, \"distance_p95_m\": %.4f, "
        "\"peak_xy_rms_m\": %.4f, \"peak_theta_rms_deg\": %.3f, \"peak_x_mean_m\": %.4f, "
        "\"peak_y_mean_m\": %.4f, \"peak_theta_mean_deg\": %.3f}\n",
        s.scans, s.inlier_share_mean, s.known_fit_mean, s.distance_p50, s.distance_p90,
        s.distance_p95, s.peak_xy_rms, s.peak_theta_rms * deg, s.peak_x_mean, s.peak_y_mean,
        s.peak_theta_mean * deg);
    return;
  }
  std::printf("reference poses (%zu) on this map: inlier share %.3f, known-space fit %.3f\n",
              s.scans, s.inlier_share_mean, s.known_fit_mean);
  std::printf(
      "echo endpoints' distance to the nearest obstacle: median %.3f m, p90 %.3f, p95 %.3f\n",
      s.distance_p50, s.distance_p90, s.distance_p95);
  std::printf(
      "likelihood peak near each reference: RMS offset %.4f m, %.3f deg; mean offset (laser "
      "frame) x %.4f m, y %.4f m, heading %.3f deg\n",
      s.peak_xy_rms, s.peak_theta_rms * deg, s.peak_x_mean, s.peak_y_mean, s.peak_theta_mean * deg);
}

/// MRPT's own particle filter with its adaptive (KLD) sample size, given what ours is given:
/// the same map (likelihood field with our sigma_hit, z_hit / z_rand, beam step and distance
/// cap), the same odometry noise (MRPT's Thrun model draws with std = alfa * |motion| where ours
/// has variance = alpha * motion^2, hence alfa = sqrt(alpha)), our KLD bins, bounds and update
/// distances, and our initial Gaussian (drawn as a box of +-2 sigma).
class MrptKld {
 public:
  MrptKld(const wheelchair_kld::LocalizationMap& map, const wheelchair_kld::KldParams& kp,
          bool our_motion)
      : kp_(kp), our_motion_(our_motion) {
    grid_ = mrpt::maps::COccupancyGridMap2D::Create(map.grid());
    auto& lo = grid_->likelihoodOptions;
    lo.likelihoodMethod = mrpt::maps::COccupancyGridMap2D::lmLikelihoodField_Thrun;
    lo.LF_decimation = kp.measurement.beam_step;
    lo.LF_stdHit = static_cast<float>(kp.measurement.sigma_hit);
    lo.LF_zHit = static_cast<float>(kp.measurement.z_hit);
    lo.LF_zRandom = static_cast<float>(kp.measurement.z_rand);
    lo.LF_maxRange = static_cast<float>(kp.measurement.max_range);
    lo.LF_maxCorrsDistance = static_cast<float>(kp.measurement.max_distance);
    pdf_.options.metricMap = grid_;
    auto& kld = pdf_.options.KLD_params;
    kld.KLD_binSize_XY = kp.bin_xy;
    kld.KLD_binSize_PHI = kp.bin_theta;
    kld.KLD_epsilon = kp.epsilon;
    kld.KLD_delta = kp.delta;
    kld.KLD_minSampleSize = kp.min_particles;
    kld.KLD_maxSampleSize = kp.max_particles;
    pf_.m_options = wheelchair_kld::mrptFilterOptions(kp);  // multinomial: KLD needs it
    motion_ = wheelchair_kld::mrptThrunMotion(kp);
  }
  void initAround(const Pose2D& p, double sxy, double sth, int particles) {
    pdf_.resetUniform(p.x - 2 * sxy, p.x + 2 * sxy, p.y - 2 * sxy, p.y + 2 * sxy, p.yaw - 2 * sth,
                      p.yaw + 2 * sth, particles);
  }
  void initGlobal(int particles) { pdf_.resetUniformFreeSpace(grid_.get(), 0.7f, particles); }
  /// Returns true if the filter updated (the odometry moved update_min_d / update_min_a).
  bool update(const Pose2D& odom, const wheelchair_core::LaserScan2D& s, const Pose2D& sensor) {
    const mrpt::poses::CPose2D now(odom.x, odom.y, odom.yaw);
    if (first_) last_ = now;  // the first update: no motion
    const mrpt::poses::CPose2D inc = now - last_;
    if (!first_ && inc.norm() < kp_.update_min_d && std::abs(inc.phi()) < kp_.update_min_a)
      return false;
    mrpt::obs::CActionCollection actions;
    mrpt::obs::CActionRobotMovement2D act;
    act.computeFromOdometry(inc, motion_);
    if (our_motion_) act.poseChange = ourMotionSamples(odom);
    actions.insert(act);
    auto obs = mrpt::obs::CObservation2DRangeScan::Create();
    obs->aperture = static_cast<float>(std::abs(s.angle_increment) * (s.ranges.size() - 1));
    obs->rightToLeft = s.angle_increment > 0;
    obs->maxRange = static_cast<float>(std::min(s.range_max, kp_.measurement.max_range));
    // MRPT's scans are centred on the sensor's x axis: the offset of ours is in the pose.
    const double centre = 0.5 * (s.angle_min + s.angle(s.ranges.size() - 1));
    obs->sensorPose = mrpt::poses::CPose3D(sensor.x, sensor.y, 0, sensor.yaw + centre, 0, 0);
    obs->resizeScan(s.ranges.size());
    for (size_t i = 0; i < s.ranges.size(); ++i) {
      const bool ok =
          wheelchair_core::classifyBeam(s.ranges[i], s) == wheelchair_core::Beam::kReturn &&
          s.ranges[i] < obs->maxRange;
      obs->setScanRange(i, ok ? s.ranges[i] : obs->maxRange);
      obs->setScanRangeValidity(i, ok);
    }
    mrpt::obs::CSensoryFrame sf;
    sf.insert(obs);
    pf_.executeOn(pdf_, &actions, &sf);
    last_ = now;
    first_ = false;
    return true;
  }
  /// The increment's distribution as samples of our odometry model (mrpt_equivalent.h). MRPT's
  /// own Thrun model decomposes a 2 cm backwards creep during a turn on the spot as a 163 deg
  /// turn, 2 cm forward and a -170 deg turn: its alfa4 then spreads the position by ~0.8 m std,
  /// and the 200 particles lose the Intel track within 3 updates (--mrpt-thrun: 39 m RMS).
  mrpt::poses::CPosePDFParticles::Ptr ourMotionSamples(const Pose2D& odom) const {
    return wheelchair_kld::mrptOdometrySamples(
        mrpt::math::TPose2D(last_.x(), last_.y(), last_.phi()),
        mrpt::math::TPose2D(odom.x, odom.y, odom.yaw), kp_.motion,
        mrpt::random::getRandomGenerator());
  }

  Pose2D mean() const {
    mrpt::poses::CPose2D m;
    pdf_.getMean(m);
    return {m.x(), m.y(), m.phi()};
  }
  int size() const { return static_cast<int>(pdf_.size()); }

 private:
  wheelchair_kld::KldParams kp_;
  bool our_motion_;
  mrpt::maps::COccupancyGridMap2D::Ptr grid_;
  mrpt::slam::CMonteCarloLocalization2D pdf_;
  mrpt::bayes::CParticleFilter pf_;
  mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion_;
  mrpt::poses::CPose2D last_;
  bool first_ = true;
};

template <typename Reader>
int replay(Reader& reader, const Args& a, bool bag) {
  const auto map_file = wheelchair_core::loadMap(a.map);
  wheelchair_kld::KldParams params;
  if (!a.config.empty())
    params = wheelchair_core::loadConfig<wheelchair_kld::KldParams>(
        wheelchair_core::YamlParameterSource::fromFile(a.config), wheelchair_kld::readKldParams);
  const auto map = std::make_shared<wheelchair_kld::LocalizationMap>(
      wheelchair_mapping::toMrptGrid(map_file), params.measurement.max_distance);
  wheelchair_kld::KldLocalizer filter(map, params, a.seed);

  std::optional<wheelchair_logs::ReferenceTrajectory> reference;
  const auto how = wheelchair_logs::referenceMatchFromName(a.match);
  if (!a.reference.empty()) {
    wheelchair_logs::CarmenOptions ro;
    reference.emplace(readCarmen(a.reference, ro));
  }
  wheelchair_logs::ProgressBar bar(stderr, "replay", !a.quiet);
  std::vector<Record> records;
  bool started = false;
  std::vector<LogScan> scans;
  for (LogScan s; reader.next(s);) {
    if (!reader.problemsOfLastCall().empty() && !a.quiet) {
      bar.breakLine();
      std::cerr << reader.problemsOfLastCall() << " (skipped)\n";
    }
    scans.push_back(std::move(s));
  }
  if (a.kidnap_at >= 0)
    scans = wheelchair_logs::spliceKidnapping(scans, a.kidnap_at, a.kidnap_from);
  if (a.reference_fit) {
    if (!reference) throw std::invalid_argument("--reference-fit needs --reference");
    std::vector<wheelchair_kld::ReferenceFit> fits;
    std::ofstream out;
    if (!a.out.empty()) {
      out.open(a.out);
      if (!out) throw std::runtime_error(a.out + ": cannot write");
      out << "stamp,ref_x,ref_y,ref_yaw,echoes,inliers,contradictions,peak_dx,peak_dy,peak_dyaw\n";
      out.precision(10);
    }
    for (size_t i = 0; i < scans.size(); ++i) {
      const Pose2D sensor = sensorPose(scans[i], bag, a);
      const LogScan* ref = reference->match(scans[i], how, a.offset, a.tolerance);
      if (ref) {
        fits.push_back(wheelchair_kld::referenceFit(
            *map, params.measurement, scans[i].scan, sensor,
            wheelchair_core::compose(ref->laser_pose, wheelchair_core::inverse(sensor)),
            params.inlier_tolerance));
        const auto& f = fits.back();
        if (out.is_open())
          out << scans[i].scan.stamp << "," << ref->laser_pose.x << "," << ref->laser_pose.y << ","
              << ref->laser_pose.yaw << "," << f.fit.echoes << "," << f.fit.inliers << ","
              << f.fit.contradictions << "," << f.peak_offset.x << "," << f.peak_offset.y << ","
              << f.peak_offset.yaw << "\n";
      }
      bar.update(double(i + 1) / scans.size(), std::to_string(fits.size()) + " references");
    }
    bar.breakLine();
    printReferenceFit(wheelchair_kld::summarizeReferenceFits(fits), a.json);
    return 0;
  }
  std::optional<MrptKld> mrpt_filter;
  if (a.mrpt) {
    mrpt::random::getRandomGenerator().randomize(static_cast<uint32_t>(a.seed));
    mrpt_filter.emplace(*map, params, !a.mrpt_thrun);
  }
  // The initial prior: 10 cm / 3 deg.
  auto initAround = [&](const Pose2D& p) {
    if (mrpt_filter)
      mrpt_filter->initAround(p, 0.1, 0.052, std::max(params.min_particles, 2000));
    else
      filter.initGaussian(p, Eigen::Vector3d(0.01, 0.01, 0.0027).asDiagonal());
  };
  size_t kidnap_record = 0;
  for (size_t i = 0; i < scans.size(); ++i) {
    const LogScan& s = scans[i];
    if (a.kidnap_at >= 0 && static_cast<long>(i) == a.kidnap_at + 1) kidnap_record = records.size();
    const Pose2D sensor = sensorPose(s, bag, a);
    const LogScan* ref = reference ? reference->match(s, how, a.offset, a.tolerance) : nullptr;
    if (!started) {
      if (!a.initial.empty()) {
        Pose2D p;
        char c1, c2;
        std::istringstream in(a.initial);
        if (!(in >> p.x >> c1 >> p.y >> c2 >> p.yaw))
          throw std::invalid_argument("--initial wants x,y,yaw");
        initAround(wheelchair_core::compose(p, wheelchair_core::inverse(sensor)));
      } else if (ref && !a.global) {
        initAround(wheelchair_core::compose(ref->laser_pose, wheelchair_core::inverse(sensor)));
      } else if (a.global || !reference) {
        if (mrpt_filter)
          mrpt_filter->initGlobal(params.global_particles);
        else
          filter.initGlobal();
      } else {
        continue;  // wait for the first scan with a reference pose
      }
      started = true;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = threadCpuMs();
    auto result = wheelchair_kld::UpdateResult::kUpdated;
    if (mrpt_filter) {
      if (!mrpt_filter->update(s.odom_pose, s.scan, sensor))
        result = wheelchair_kld::UpdateResult::kNoMotion;
    } else {
      result = filter.update(s.odom_pose, s.scan, sensor);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const double cpu_ms = threadCpuMs() - cpu0;
    if (result == wheelchair_kld::UpdateResult::kRejected && !a.quiet) {
      bar.breakLine();
      std::cerr << a.log << ":" << s.line << ": scan rejected: " << filter.lastRejection() << "\n";
    }
    Record r{s.scan.stamp,
             wheelchair_core::compose(filter.estimate().mean, sensor),
             filter.estimate(),
             filter.status(),
             ms,
             cpu_ms,
             result == wheelchair_kld::UpdateResult::kUpdated,
             filter.relocalizations(),
             std::nullopt,
             filter.lastFit()};
    if (mrpt_filter) {  // MRPT's filter says nothing of its state: localized throughout
      r.estimate = wheelchair_kld::PoseEstimate{};
      r.estimate.mean = mrpt_filter->mean();
      r.laser = wheelchair_core::compose(r.estimate.mean, sensor);
      r.status = wheelchair_core::LocalizationStatus{};
      r.status.state = wheelchair_core::LocalizationState::kLocalized;
      r.status.particles = mrpt_filter->size();
      r.relocalizations = 0;
      r.fit = {};
    }
    if (ref) r.reference = ref->laser_pose;
    (void)kidnap_record;
    records.push_back(std::move(r));
    bar.update(double(i + 1) / scans.size(),
               std::to_string(records.size()) + " scans, " +
                   std::to_string(filter.particleCount()) + " particles, " +
                   std::to_string(filter.relocalizations()) + " re-localizations");
  }
  bar.breakLine();

  if (!a.out.empty()) {
    std::ofstream out(a.out);
    if (!out) throw std::runtime_error(a.out + ": cannot write");
    out << "stamp,x,y,yaw,cov_xx,cov_xy,cov_yy,cov_tt,state,particles,update_ms,cpu_ms,updated,"
           "inlier_fraction,mean_fit,relocalizations,echoes,inliers,contradictions,ref_x,ref_y,"
           "ref_yaw\n";
    out.precision(10);
    for (const auto& r : records) {
      out << r.stamp << "," << r.laser.x << "," << r.laser.y << "," << r.laser.yaw << ","
          << r.estimate.cov(0, 0) << "," << r.estimate.cov(0, 1) << "," << r.estimate.cov(1, 1)
          << "," << r.estimate.cov(2, 2) << "," << static_cast<int>(r.status.state) << ","
          << r.status.particles << "," << r.update_ms << "," << r.cpu_ms << "," << r.updated << ","
          << r.status.inlier_fraction << "," << r.status.mean_fit << "," << r.relocalizations << ","
          << r.fit.echoes << "," << r.fit.inliers << "," << r.fit.contradictions;
      if (r.reference)
        out << "," << r.reference->x << "," << r.reference->y << "," << r.reference->yaw;
      else
        out << ",,,";
      out << "\n";
    }
  }

  // The error table.
  std::vector<wheelchair_logs::PosePair> pairs;
  std::vector<wheelchair_logs::TimedPose> trajectory;
  std::vector<double> update_ms, cpu_ms;
  size_t localized = 0;
  for (const auto& r : records) {
    if (r.reference) pairs.push_back({r.laser, *r.reference});
    trajectory.push_back({r.stamp, r.laser});
    if (r.updated) update_ms.push_back(r.update_ms);
    if (r.updated) cpu_ms.push_back(r.cpu_ms);
    localized += r.status.localized();
  }
  const auto e = wheelchair_logs::poseErrors(pairs);
  std::optional<wheelchair_logs::RelationErrors> rel;
  if (!a.relations.empty())
    rel = wheelchair_logs::relationErrors(wheelchair_logs::readRelations(a.relations), trajectory,
                                          a.relations_offset, a.relations_tolerance);
  double mean_ms = 0, mean_cpu = 0;
  for (double v : update_ms) mean_ms += v / std::max<size_t>(1, update_ms.size());
  for (double v : cpu_ms) mean_cpu += v / std::max<size_t>(1, cpu_ms.size());
  const double deg = 180.0 / M_PI;
  const int relocs = filter.relocalizations();
  // Updates from the kidnapping until the status says "not localized", until the
  // re-localization starts, and until the estimate is back within 0.5 m of the reference
  // for good.
  long noticed = -1, relocalized = -1, back = -1, updates = 0;
  if (a.kidnap_at >= 0) {
    const int relocs_before = kidnap_record > 0 ? records[kidnap_record - 1].relocalizations : 0;
    for (size_t i = kidnap_record; i < records.size(); ++i) {
      const auto& r = records[i];
      updates += r.updated;
      if (noticed < 0 && r.updated && !r.status.localized()) noticed = updates;
      if (relocalized < 0 && r.relocalizations > relocs_before) relocalized = updates;
      if (!r.reference) continue;
      const bool near = std::hypot(r.laser.x - r.reference->x, r.laser.y - r.reference->y) < 0.5;
      if (!near)
        back = -1;
      else if (back < 0)
        back = updates;
    }
  }
  if (a.json) {
    std::printf(
        "{\"scans\": %zu, \"updates\": %zu, \"localized_share\": %.4f, \"relocalizations\": %d, "
        "\"matched\": %zu, \"position_rms_m\": %.4f, \"position_mean_m\": %.4f, "
        "\"position_max_m\": %.4f, \"heading_rms_deg\": %.3f, \"heading_max_deg\": %.3f, "
        "\"update_mean_ms\": %.3f, \"update_p99_ms\": %.3f, \"update_max_ms\": %.3f, "
        "\"cpu_mean_ms\": %.3f, \"cpu_p99_ms\": %.3f, \"cpu_max_ms\": %.3f",
        records.size(), update_ms.size(), double(localized) / std::max<size_t>(1, records.size()),
        relocs, e.count, e.position_rms, e.position_mean, e.position_max, e.heading_rms * deg,
        e.heading_max * deg, mean_ms, percentile(update_ms, 0.99), percentile(update_ms, 1.0),
        mean_cpu, percentile(cpu_ms, 0.99), percentile(cpu_ms, 1.0));
    if (rel) {
      const auto t = wheelchair_logs::summarize(rel->translational);
      const auto r = wheelchair_logs::summarize(rel->rotational);
      std::printf(
          ", \"relations\": %zu, \"relations_matched\": %zu, \"relation_trans_mean_m\": %.4f, "
          "\"relation_trans_std_m\": %.4f, \"relation_rot_mean_deg\": %.3f, "
          "\"relation_rot_std_deg\": %.3f",
          rel->relations, t.count, t.mean, t.std, r.mean * deg, r.std * deg);
    }
    if (a.kidnap_at >= 0)
      std::printf(
          ", \"kidnap_noticed_update\": %ld, \"kidnap_relocalized_update\": %ld, "
          "\"kidnap_back_update\": %ld",
          noticed, relocalized, back);
    std::printf("}\n");
  } else {
    std::printf("scans %zu, filter updates %zu, localized %.1f %%, re-localizations %d\n",
                records.size(), update_ms.size(),
                100.0 * localized / std::max<size_t>(1, records.size()), relocs);
    std::printf("update time [ms]: mean %.3f, p99 %.3f, max %.3f (thread CPU: %.3f, %.3f, %.3f)\n",
                mean_ms, percentile(update_ms, 0.99), percentile(update_ms, 1.0), mean_cpu,
                percentile(cpu_ms, 0.99), percentile(cpu_ms, 1.0));
    if (e.count > 0)
      std::printf(
          "against the reference (%zu scans): position RMS %.3f m, mean %.3f, max %.3f; heading "
          "RMS %.2f deg, mean %.2f, max %.2f\n",
          e.count, e.position_rms, e.position_mean, e.position_max, e.heading_rms * deg,
          e.heading_mean * deg, e.heading_max * deg);
    if (rel) {
      const auto t = wheelchair_logs::summarize(rel->translational);
      const auto r = wheelchair_logs::summarize(rel->rotational);
      std::printf("relation error (%zu of %zu matched): %.4f +- %.4f m, %.3f +- %.3f deg\n",
                  t.count, rel->relations, t.mean, t.std, r.mean * deg, r.std * deg);
    }
  }
  if (a.kidnap_at >= 0 && !a.json)
    std::printf(
        "kidnapping after scan %ld: noticed (not localized) at update %ld, re-localization at "
        "update %ld, back within 0.5 m at update %ld (-1: never)\n",
        a.kidnap_at, noticed, relocalized, back);
  if (!a.plot.empty()) {
    wheelchair_logs::PlotPath est{"estimate", 220, 30, 30, {}, {}};
    wheelchair_logs::PlotPath refp{"reference", 30, 160, 30, {}, {}};
    int last_relocs = 0;
    for (const auto& r : records) {
      est.poses.push_back(r.laser);
      if (r.reference) refp.poses.push_back(*r.reference);
      if (r.relocalizations > last_relocs) est.marks.push_back(r.laser);
      last_relocs = r.relocalizations;
    }
    std::vector<wheelchair_logs::PlotPath> paths{est};
    if (!refp.poses.empty()) paths.insert(paths.begin(), refp);
    wheelchair_logs::saveTrajectoryPlot(map_file, paths, a.plot);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  try {
    if (!parse(argc, argv, a)) {
      std::cerr << kUsage;
      return 2;
    }
    if (isBag(a.log)) {
      wheelchair_logs::BagScanReader reader(a.log, a.scan_topic, a.odom_frame, a.base_frame,
                                            a.odom_topic);
      return replay(reader, a, true);
    }
    wheelchair_logs::CarmenOptions options;
    options.odometry = wheelchair_logs::odometrySourceFromName(a.odometry);
    wheelchair_logs::CarmenLogReader reader(a.log, options);
    return replay(reader, a, false);
  } catch (const std::exception& e) {
    std::cerr << "replay: " << e.what() << "\n";
    return 1;
  }
}
