// rosrun wheelchair_mapping build_map --log FILE --out map.yaml [options]
// Builds an occupancy grid offline from a CARMEN log (FLASER / ROBOTLASER1 with their poses:
// use the corrected logs for true poses) or a rosbag (LaserScan + tf), writes map.yaml +
// map.pgm and a PNG preview.
#include <sys/resource.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_logs/bag_scans.h>
#include <wheelchair_logs/carmen_log.h>
#include <wheelchair_logs/map_preview.h>
#include <wheelchair_logs/progress_bar.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/map_consistency.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace wheelchair_mapping {
namespace {

using wheelchair_logs::BagScanReader;
using wheelchair_logs::CarmenLogReader;
using wheelchair_logs::LogScan;
using wheelchair_logs::ProgressBar;
using wheelchair_logs::savePreviewPng;

const char* kUsage =
    "usage: build_map --log FILE --out MAP.yaml [--resolution M] [--max-range M]\n"
    "                 [--no-echo-free M] [--hit-depth M] [--hold-out N] [--preview FILE.png]\n"
    "                 [--quiet] [--stats-json] [--scan-topic T] [--frame F]\n"
    "  FILE              CARMEN log (plain or .gz) or rosbag (.bag)\n"
    "  --resolution M    cell size (default 0.05)\n"
    "  --max-range M     cells farther than this from the laser are not updated (default 20)\n"
    "  --no-echo-free M  treat no-echo beams as free space up to M metres (default: skip them)\n"
    "  --hit-depth M     a return marks the cell M metres behind the echo (default 0)\n"
    "  --hold-out N      keep every Nth scan out of the map and report the fraction of its\n"
    "                    endpoints on occupied cells (map consistency)\n"
    "  --preview FILE    PNG preview (default: MAP.png next to MAP.yaml)\n"
    "  --stats-json      print one JSON object with the figures on stdout\n"
    "  --scan-topic T    rosbag: LaserScan topic (default /scan)\n"
    "  --frame F         rosbag: fixed frame of the laser poses, from /tf (default odom)\n";

struct Args {
  std::string log, out, preview, scan_topic = "/scan", frame = "odom";
  double resolution = 0.05, max_range = 20.0, no_echo_free = 0.0;
  double hit_depth = MapperConfig().model.hit_depth;
  int hold_out = 0;
  bool quiet = false, stats_json = false;
};

bool parseArgs(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto value = [&](auto& out) {
      if (i + 1 >= argc) return false;
      const std::string v = argv[++i];
      if constexpr (std::is_same_v<std::decay_t<decltype(out)>, std::string>) {
        out = v;
        return true;
      } else {
        char* end = nullptr;
        out = static_cast<std::decay_t<decltype(out)>>(std::strtod(v.c_str(), &end));
        return end && *end == '\0';
      }
    };
    bool ok = true;
    if (k == "--log")
      ok = value(a.log);
    else if (k == "--out")
      ok = value(a.out);
    else if (k == "--preview")
      ok = value(a.preview);
    else if (k == "--resolution")
      ok = value(a.resolution);
    else if (k == "--max-range")
      ok = value(a.max_range);
    else if (k == "--no-echo-free")
      ok = value(a.no_echo_free);
    else if (k == "--hit-depth")
      ok = value(a.hit_depth);
    else if (k == "--hold-out")
      ok = value(a.hold_out);
    else if (k == "--quiet")
      a.quiet = true;
    else if (k == "--stats-json")
      a.stats_json = true;
    else
      ok = false;
    if (!ok) {
      std::cerr << "build_map: bad or incomplete argument '" << k << "'\n";
      return false;
    }
  }
  if (a.log.empty() || a.out.empty()) return false;
  if (a.preview.empty()) a.preview = std::filesystem::path(a.out).replace_extension(".png");
  return true;
}

MapperConfig mapperConfig(const Args& a) {
  MapperConfig c;
  c.resolution = a.resolution;
  c.model.max_insertion_range = a.max_range;
  c.model.no_return_is_free = a.no_echo_free > 0;
  c.model.no_return_range = a.no_echo_free;
  c.model.hit_depth = a.hit_depth;
  return c;
}

/// What the CARMEN reader found about the log's conventions (a bag has none of these).
void reportConventions(const CarmenLogReader& reader, const Args& a) {
  if (a.quiet) return;
  const auto& e = reader.noEcho();
  if (e.found)
    std::cerr << "build_map: no-echo code " << e.code << " m (" << e.at_code << " of " << e.readings
              << " readings; readings >= " << reader.options().no_echo_range << " m are no echo)\n";
  else
    std::cerr << "build_map: no no-echo code in the log (no reading repeats at its maximum)\n";
}
void reportConventions(const BagScanReader&, const Args&) {}

size_t duplicates(const CarmenLogReader& reader) { return reader.duplicatesDropped(); }
size_t duplicates(const BagScanReader&) { return 0; }

template <typename Reader>
int build(Reader& reader, const Args& a) {
  reportConventions(reader, a);
  const auto start = std::chrono::steady_clock::now();
  BayesMapper mapper(mapperConfig(a));
  ProgressBar bar(stderr, "build_map", !a.quiet);
  std::vector<LogScan> held_out;
  size_t read = 0, skipped = 0;
  for (LogScan s; reader.next(s);) {
    if (!reader.problemsOfLastCall().empty()) {
      bar.breakLine();
      std::cerr << reader.problemsOfLastCall() << " (skipped)\n";
    }
    ++read;
    if (a.hold_out > 0 && read % a.hold_out == 0) {
      held_out.push_back(std::move(s));
      continue;
    }
    const InsertResult r = mapper.insert(s.scan, s.laser_pose);
    if (!r.inserted) {
      ++skipped;
      bar.breakLine();
      std::cerr << a.log << ":" << s.line << ": scan skipped: " << r.reason << "\n";
    }
    bar.update(reader.progress(), std::to_string(mapper.scansInserted()) + " scans");
  }
  if (!reader.problemsOfLastCall().empty()) {
    bar.breakLine();
    std::cerr << reader.problemsOfLastCall() << " (skipped)\n";
  }
  bar.update(1.0, std::to_string(mapper.scansInserted()) + " scans");
  bar.breakLine();
  if (mapper.scansInserted() == 0) {
    std::cerr << a.log << ": no usable laser scan in the log\n";
    return 1;
  }
  const wheelchair_core::OccupancyMap map = mapper.map();
  wheelchair_core::saveMap(map, a.out);
  savePreviewPng(mapper.grid(), a.preview);
  EndpointConsistency consistency;
  for (const LogScan& s : held_out) {
    addEndpoints(map, s.scan, s.laser_pose, a.max_range, consistency);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_mb = usage.ru_maxrss / 1024.0;
  if (!a.quiet) {
    std::cerr << "build_map: " << a.out << " (" << map.width << " x " << map.height << " cells at "
              << a.resolution << " m) from " << mapper.scansInserted() << " scans; " << skipped
              << " skipped, " << reader.problemCount() << " corrupt lines / scans without tf, "
              << duplicates(reader) << " duplicate scans dropped; " << seconds << " s, peak "
              << peak_mb << " MB; preview " << a.preview << "\n";
    if (consistency.endpoints > 0) {
      std::cerr << "build_map: held-out scans: " << 100 * consistency.onFraction() << " % of "
                << consistency.endpoints << " endpoints on occupied cells, "
                << 100 * consistency.nearFraction() << " % within one cell\n";
    }
  }
  if (a.stats_json) {
    std::cout << "{\"scans\": " << mapper.scansInserted() << ", \"skipped\": " << skipped
              << ", \"corrupt_lines\": " << reader.problemCount()
              << ", \"duplicates\": " << duplicates(reader) << ", \"seconds\": " << seconds
              << ", \"peak_rss_mb\": " << peak_mb << ", \"width\": " << map.width
              << ", \"height\": " << map.height
              << ", \"held_out_endpoints\": " << consistency.endpoints
              << ", \"on_occupied\": " << consistency.onFraction()
              << ", \"within_one_cell\": " << consistency.nearFraction() << "}\n";
  }
  return 0;
}

int run(const Args& a) {
  const std::string ext = std::filesystem::path(a.log).extension().string();
  if (ext == ".bag") {
    BagScanReader reader(a.log, a.scan_topic, a.frame);
    return build(reader, a);
  }
  CarmenLogReader reader(a.log);
  return build(reader, a);
}

}  // namespace
}  // namespace wheelchair_mapping

int main(int argc, char** argv) {
  wheelchair_mapping::Args args;
  if (!wheelchair_mapping::parseArgs(argc, argv, args)) {
    std::cerr << wheelchair_mapping::kUsage;
    return 2;
  }
  try {
    return wheelchair_mapping::run(args);
  } catch (const std::exception& e) {
    std::cerr << "build_map: " << e.what() << "\n";
    return 1;
  }
}
