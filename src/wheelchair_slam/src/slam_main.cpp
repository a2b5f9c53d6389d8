// rosrun wheelchair_slam slam --log FILE [--out DIR] [options]
// Maps a building from one drive: graph SLAM on a CARMEN log with raw odometry, writing the map
// (map.yaml + map.pgm), a preview with the trajectory and the loop closures (map.png), the
// optimized trajectory (trajectory.csv, trajectory.clf in the CARMEN corrected-log format that
// build_map reads), the raw odometry (odometry.csv) and the run's statistics (stats.json).
#include <sys/resource.h>
#include <wheelchair_core/map_io.h>

#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_logs/progress_bar.h>
#include <wheelchair_mapping/map_consistency.h>
#include <wheelchair_slam/graph_slam.h>
#include <wheelchair_slam/slam_map.h>
#include <wheelchair_slam/slam_session.h>
#include <wheelchair_slam/trajectory_io.h>
#include <yaml-cpp/yaml.h>
#include "bag_source.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace wheelchair_slam {
namespace {

const char* kUsage =
    "usage: slam --log FILE [--out DIR] [--odometry fields|gfs] [--config FILE.yaml]\n"
    "            [--resolution M] [--max-range M] [--hold-out N] [--odometry-only] [--quiet]\n"
    "            [--scan-topic T] [--odom-frame F] [--scans FIRST:END]\n"
    "            [--continue DIR [--start X,Y,YAW]]\n"
    "  FILE             CARMEN log (plain or .gz) with FLASER/ROBOTLASER1 and raw odometry,\n"
    "                   or a rosbag (.bag): LaserScan on --scan-topic (default /scan), the\n"
    "                   laser's odometry pose from /tf in --odom-frame (default odom)\n"
    "  --out DIR        output folder (default slam_out): map.yaml/.pgm/.png, trajectory.csv,\n"
    "                   trajectory.clf, odometry.csv, logged.csv (the log's own poses),\n"
    "                   matches.csv (how each scan matched), graph.graph (the pose graph,\n"
    "                   g2o), graph.scans (what --continue needs), stats.json\n"
    "  --odometry SRC   fields: the FLASER odom fields are raw odometry (default);\n"
    "                   gfs: a GMapping-corrected log, raw odometry from its ODOM increments\n"
    "  --config FILE    SLAM parameters (YAML, the keys of readSlamConfig; unknown keys refused)\n"
    "  --resolution M   map cell size (default 0.05)\n"
    "  --max-range M    map insertion range (default 20)\n"
    "  --hold-out N     keep every Nth scan out of the map (not out of SLAM) and report the\n"
    "                   fraction of its endpoints on occupied cells\n"
    "  --odometry-only  no scan matching: the trajectory is the raw odometry (a baseline)\n"
    "  --scans F:E      only the log's scans F .. E-1 (0-based; either may be left out)\n"
    "  --continue DIR   continue the map saved in DIR (graph.graph + graph.scans of an earlier\n"
    "                   run): this log is a new drive, located in that map and joined to its\n"
    "                   graph; the output holds the saved scans and the new ones\n"
    "  --start X,Y,YAW  where the new drive starts in the saved map (default: the saved\n"
    "                   drive's map -> odom applied to the log's odometry, i.e. the same\n"
    "                   odometry frame goes on)\n";

struct Args {
  std::string log, out = "slam_out", odometry = "fields", config;
  std::string scan_topic = "/scan", odom_frame = "odom";
  std::string continue_dir;
  std::optional<wheelchair_core::Pose2D> start;
  double resolution = 0.05, max_range = 20.0;
  int hold_out = 0;
  size_t first_scan = 0, end_scan = std::numeric_limits<size_t>::max();
  bool odometry_only = false, quiet = false;
};

/// "F:E", "F:" or ":E" as the scan range [F, E).
bool parseRange(const std::string& text, size_t& first, size_t& end) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos) return false;
  auto part = [](const std::string& p, size_t& out) {
    if (p.empty()) return true;
    char* e = nullptr;
    const long v = std::strtol(p.c_str(), &e, 10);
    if (!e || *e != '\0' || v < 0) return false;
    out = static_cast<size_t>(v);
    return true;
  };
  return part(text.substr(0, colon), first) && part(text.substr(colon + 1), end) && first < end;
}

bool parsePose(const std::string& text, std::optional<wheelchair_core::Pose2D>& pose) {
  wheelchair_core::Pose2D p;
  char c1 = 0, c2 = 0;
  std::istringstream s(text);
  if (!(s >> p.x >> c1 >> p.y >> c2 >> p.yaw) || c1 != ',' || c2 != ',' || !p.isFinite())
    return false;
  pose = p;
  return true;
}

bool parseArgs(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto text = [&](std::string& out) {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    auto number = [&](auto& out) {
      std::string v;
      if (!text(v)) return false;
      char* end = nullptr;
      out = static_cast<std::decay_t<decltype(out)>>(std::strtod(v.c_str(), &end));
      return end && *end == '\0';
    };
    bool ok = true;
    if (k == "--log")
      ok = text(a.log);
    else if (k == "--out")
      ok = text(a.out);
    else if (k == "--odometry")
      ok = text(a.odometry);
    else if (k == "--config")
      ok = text(a.config);
    else if (k == "--scan-topic")
      ok = text(a.scan_topic);
    else if (k == "--odom-frame")
      ok = text(a.odom_frame);
    else if (k == "--resolution")
      ok = number(a.resolution);
    else if (k == "--max-range")
      ok = number(a.max_range);
    else if (k == "--hold-out")
      ok = number(a.hold_out);
    else if (k == "--continue")
      ok = text(a.continue_dir);
    else if (k == "--scans") {
      std::string v;
      ok = text(v) && parseRange(v, a.first_scan, a.end_scan);
    } else if (k == "--start") {
      std::string v;
      ok = text(v) && parsePose(v, a.start);
    } else if (k == "--odometry-only")
      a.odometry_only = true;
    else if (k == "--quiet")
      a.quiet = true;
    else
      ok = false;
    if (!ok) {
      std::cerr << "slam: bad or incomplete argument '" << k << "'\n";
      return false;
    }
  }
  return !a.log.empty();
}

SlamConfig loadSlamConfig(const std::string& path) {
  if (path.empty()) return SlamConfig();
  const auto source = wheelchair_core::YamlParameterSource::fromFile(path);
  return wheelchair_core::loadConfig<SlamConfig>(source, readSlamConfig);
}

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

/// FLASER lines carry no angles: only scans of 180 deg from -90 deg can be written as FLASER.
bool flaserCompatible(const std::vector<wheelchair_core::LaserScan2D>& scans) {
  for (const auto& s : scans) {
    const size_t n = s.ranges.size();
    const double step = n % 2 == 0 ? M_PI / n : M_PI / std::max<size_t>(n - 1, 1);
    if (std::abs(s.angle_min + M_PI / 2) > 1e-3 || std::abs(s.angle_increment - step) > 1e-6)
      return false;
  }
  return true;
}

void writeMatchesCsv(const std::string& path, const std::vector<double>& stamps,
                     const std::vector<ScanMatchInfo>& info) {
  std::ofstream f(path);
  f << "stamp,matched,keyframe,goodness,inliers,sigma_x,sigma_y,sigma_yaw,correction_x,"
       "correction_y,correction_yaw\n";
  for (size_t i = 0; i < info.size() && i < stamps.size(); ++i) {
    const ScanMatchInfo& m = info[i];
    f << std::fixed << stamps[i] << "," << m.matched << "," << m.keyframe << "," << m.goodness
      << "," << m.inliers << "," << m.sigma_x << "," << m.sigma_y << "," << m.sigma_yaw << ","
      << m.correction.x << "," << m.correction.y << "," << m.correction.yaw << "\n";
  }
  if (!f) throw std::runtime_error(path + ": cannot write");
}

std::vector<TimedPose> timed(const std::vector<double>& stamps,
                             const std::vector<wheelchair_core::Pose2D>& poses) {
  std::vector<TimedPose> out;
  for (size_t i = 0; i < poses.size(); ++i) out.push_back({stamps[i], poses[i]});
  return out;
}

template <typename Reader>
int runWith(Reader& reader, const Args& a, const SlamConfig& config,
            std::chrono::steady_clock::time_point start) {
  std::unique_ptr<GraphSlam> slam_ptr;
  std::vector<wheelchair_core::LaserScan2D> scans;
  std::vector<wheelchair_core::Pose2D> odometry, logged;
  std::vector<double> stamps;
  if (!a.continue_dir.empty()) {
    SavedSlam saved = loadSlam(a.continue_dir, config);
    for (const ScanRecord& r : saved.records) {
      odometry.push_back(r.odometry);
      stamps.push_back(r.stamp);
    }
    scans = std::move(saved.scans);
    slam_ptr = std::make_unique<GraphSlam>(config, std::move(saved.graph), saved.records);
    logged = slam_ptr->trajectory();  // the saved run's poses stand for the log's own
    if (a.start) slam_ptr->startDrive(*a.start);
    if (!a.quiet)
      std::cerr << "slam: continuing " << a.continue_dir << " (" << scans.size() << " scans, "
                << slam_ptr->graph().size() << " keyframes)\n";
  } else {
    slam_ptr = std::make_unique<GraphSlam>(config);
  }
  GraphSlam& slam = *slam_ptr;
  const size_t saved_scans = scans.size();
  wheelchair_logs::ProgressBar bar(stderr, "slam", !a.quiet);
  size_t log_index = 0, not_located = 0;
  double last_read = -std::numeric_limits<double>::infinity();
  for (wheelchair_logs::LogScan s; reader.next(s);) {
    if (!reader.problemsOfLastCall().empty()) {
      bar.breakLine();
      std::cerr << reader.problemsOfLastCall() << " (skipped)\n";
    }
    if (s.scan.stamp < last_read) {
      bar.breakLine();
      std::cerr << a.log << ":" << s.line << ": scan skipped: its stamp goes backwards\n";
      continue;
    }
    last_read = s.scan.stamp;
    const size_t index = log_index++;  // the scan's number in the log (--scans)
    if (index < a.first_scan) continue;
    if (index >= a.end_scan) break;
    if (!stamps.empty() && s.scan.stamp < stamps.back()) {
      bar.breakLine();
      std::cerr << a.log << ":" << s.line << ": scan skipped: older than the saved map's last\n";
      continue;
    }
    if (!a.odometry_only && !slam.addScan(s.scan, s.odom_pose)) {
      ++not_located;  // a new drive not (yet) found in the saved map: the scan is left out
      continue;
    }
    if (not_located > 0 && !a.quiet) {
      bar.breakLine();
      std::cerr << "slam: the new drive was located in the saved map after " << not_located
                << " scans\n";
      not_located = 0;
    }
    odometry.push_back(s.odom_pose);
    logged.push_back(s.laser_pose);
    stamps.push_back(s.scan.stamp);
    scans.push_back(std::move(s.scan));
    bar.update(reader.progress(), std::to_string(scans.size()) + " scans, " +
                                      std::to_string(slam.stats().loops_verified) + " loops");
  }
  bar.update(1.0, std::to_string(scans.size()) + " scans");
  bar.breakLine();
  if (scans.size() == saved_scans && !a.continue_dir.empty()) {
    std::cerr << a.log << ": the new drive was never located in the saved map (give --start)\n";
    return 1;
  }
  if (scans.empty()) {
    std::cerr << a.log << ": no usable laser scan in the log\n";
    return 1;
  }
  if (!a.odometry_only) slam.finish();
  const double slam_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<wheelchair_core::Pose2D> poses = a.odometry_only ? odometry : slam.trajectory();

  namespace fs = std::filesystem;
  fs::create_directories(a.out);
  const fs::path out(a.out);
  writeTrajectoryCsv((out / "trajectory.csv").string(), timed(stamps, poses));
  writeTrajectoryCsv((out / "odometry.csv").string(), timed(stamps, odometry));
  writeTrajectoryCsv((out / "logged.csv").string(), timed(stamps, logged));
  if (!a.odometry_only) {
    writeMatchesCsv((out / "matches.csv").string(), stamps, slam.matchInfo());
    saveSlam(out.string(), slam, scans);
  }
  if (flaserCompatible(scans)) {
    writeCarmenLog((out / "trajectory.clf").string(), scans, poses, odometry);
  } else if (!a.quiet) {
    std::cerr << "slam: trajectory.clf not written: the scans are not FLASER scans (180 deg from "
                 "-90 deg in 180/181/360/361 beams)\n";
  }

  wheelchair_mapping::MapperConfig mapper_config;
  mapper_config.resolution = a.resolution;
  mapper_config.model.max_insertion_range = a.max_range;
  mapper_config.model.no_return_is_free = false;  // as build_map without --no-echo-free
  std::vector<wheelchair_core::LaserScan2D> map_scans, held_scans;
  std::vector<wheelchair_core::Pose2D> map_poses, held_poses;
  for (size_t i = 0; i < scans.size(); ++i) {
    const bool held = a.hold_out > 0 && (i + 1) % static_cast<size_t>(a.hold_out) == 0;
    (held ? held_scans : map_scans).push_back(scans[i]);
    (held ? held_poses : map_poses).push_back(poses[i]);
  }
  size_t skipped = 0;
  const auto mapper = buildMap(map_scans, map_poses, mapper_config, &skipped);
  const wheelchair_core::OccupancyMap map = mapper.map();
  wheelchair_core::saveMap(map, (out / "map.yaml").string());
  std::vector<std::pair<wheelchair_core::Pose2D, wheelchair_core::Pose2D>> loop_segments;
  for (const LoopClosure& l : slam.loopClosures()) {
    if (l.kept)
      loop_segments.emplace_back(slam.graph().poses()[l.from], slam.graph().poses()[l.to]);
  }
  savePreviewWithTrajectory(mapper, poses, loop_segments, (out / "map.png").string());
  wheelchair_mapping::EndpointConsistency consistency;
  for (size_t i = 0; i < held_scans.size(); ++i) {
    wheelchair_mapping::addEndpoints(map, held_scans[i], held_poses[i], a.max_range, consistency);
  }
  const double total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double log_seconds = stamps.back() - stamps.front();
  const SlamStats& st = slam.stats();
  size_t kept = 0;
  for (const LoopClosure& l : slam.loopClosures()) kept += l.kept;

  YAML::Emitter json;
  json << YAML::DoubleQuoted << YAML::Flow << YAML::BeginMap;
  json << YAML::Key << "log" << YAML::Value << a.log;
  json << YAML::Key << "scans" << YAML::Value << scans.size();
  json << YAML::Key << "keyframes" << YAML::Value << st.keyframes;
  json << YAML::Key << "drives" << YAML::Value << st.drives;
  json << YAML::Key << "continued_scans" << YAML::Value << saved_scans;
  json << YAML::Key << "match_failures" << YAML::Value << st.match_failures;
  json << YAML::Key << "loop_attempts" << YAML::Value << st.loop_attempts;
  json << YAML::Key << "loops_verified" << YAML::Value << st.loops_verified;
  json << YAML::Key << "loops_kept" << YAML::Value << kept;
  json << YAML::Key << "loops_removed_chi2" << YAML::Value << st.loops_removed;
  json << YAML::Key << "final_pass_loops" << YAML::Value << st.final_pass_loops;
  json << YAML::Key << "optimizations" << YAML::Value << st.optimizations;
  json << YAML::Key << "seconds_matching" << YAML::Value << st.seconds_matching;
  json << YAML::Key << "seconds_loops" << YAML::Value << st.seconds_loops;
  json << YAML::Key << "seconds_optimizing" << YAML::Value << st.seconds_optimizing;
  json << YAML::Key << "seconds_slam" << YAML::Value << slam_seconds;
  json << YAML::Key << "seconds_total" << YAML::Value << total_seconds;
  json << YAML::Key << "log_seconds" << YAML::Value << log_seconds;
  json << YAML::Key << "realtime_factor" << YAML::Value << log_seconds / total_seconds;
  json << YAML::Key << "peak_rss_mb" << YAML::Value << peakRssMb();
  json << YAML::Key << "map_scans_skipped" << YAML::Value << skipped;
  json << YAML::Key << "corrupt_lines" << YAML::Value << reader.corruptLines();
  json << YAML::Key << "held_out_endpoints" << YAML::Value << consistency.endpoints;
  json << YAML::Key << "on_occupied" << YAML::Value << consistency.onFraction();
  json << YAML::Key << "within_one_cell" << YAML::Value << consistency.nearFraction();
  json << YAML::EndMap;
  std::ofstream((out / "stats.json").string()) << json.c_str() << "\n";
  if (!a.quiet) {
    std::cerr << "slam: " << scans.size() << " scans, " << st.keyframes << " keyframes, " << kept
              << " loop closures kept (" << st.loops_removed << " removed by chi2), "
              << total_seconds << " s for a " << log_seconds << " s log ("
              << log_seconds / total_seconds << "x real time), peak " << peakRssMb() << " MB; "
              << out.string() << "/\n";
  }
  std::cout << json.c_str() << "\n";
  return 0;
}

int run(const Args& a) {
  const auto start = std::chrono::steady_clock::now();
  const SlamConfig config = loadSlamConfig(a.config);
  if (std::filesystem::path(a.log).extension() == ".bag") {
    BagOdometryReader reader(a.log, a.scan_topic, a.odom_frame);
    return runWith(reader, a, config, start);
  }
  wheelchair_logs::CarmenOptions options;
  options.odometry = wheelchair_logs::odometrySourceFromName(a.odometry);
  wheelchair_logs::CarmenLogReader reader(a.log, options);
  return runWith(reader, a, config, start);
}

}  // namespace
}  // namespace wheelchair_slam

int main(int argc, char** argv) {
  wheelchair_slam::Args args;
  if (!wheelchair_slam::parseArgs(argc, argv, args)) {
    std::cerr << wheelchair_slam::kUsage;
    return 2;
  }
  try {
    return wheelchair_slam::run(args);
  } catch (const std::exception& e) {
    std::cerr << "slam: " << e.what() << "\n";
    return 1;
  }
}
