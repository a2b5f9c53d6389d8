// Measuring binary of bench/reachability: every ordered pair of a world's named places planned
// with the chair's body by the chair's planner (this package's harmonic plugin and the footprint
// gate every plugin passes, the settings of the shipped chair and chair_sim.yaml's search time),
// without ROS: one JSON object per pair on stdout.
//   reachability_pairs WORLD.yaml PLACES.yaml [--time S] [--from NAME] [--to NAME] [--max N]
//                      [--attempts "W,MARGIN,STEP,BACKWARD,ONE_SLICE;..."] (the search's settings,
//                      to try others) [--pose NAME,X,Y,YAW] (a place of one's own, added)
#include <wheelchair_core/map_io.h>
#include <wheelchair_description_testing/chair_file.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_planner/planner_settings.h>

#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace wheelchair_harmonic_planner;

namespace {

struct Place {
  std::string name;
  wheelchair_core::Pose2D pose;
};

std::vector<Place> loadPlaces(const std::string& path) {
  std::vector<Place> places;
  for (const YAML::Node& p : YAML::LoadFile(path)["places"])
    places.push_back({p["name"].as<std::string>(),
                      {p["x"].as<double>(), p["y"].as<double>(), p["yaw"].as<double>()}});
  return places;
}

/// The text with the characters JSON does not take as they are escaped.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr,
            "usage: %s WORLD.yaml PLACES.yaml [--time S] [--from NAME] [--to NAME] [--max N]\n",
            argv[0]);
    return 2;
  }
  double time_limit = 10.0;  // chair_sim.yaml's footprint_search_time
  std::string only_from, only_to;
  int max_pairs = 0;
  std::string attempts;
  std::vector<std::string> extra;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--time")
      time_limit = std::atof(argv[i + 1]);
    else if (key == "--from")
      only_from = argv[i + 1];
    else if (key == "--to")
      only_to = argv[i + 1];
    else if (key == "--max")
      max_pairs = std::atoi(argv[i + 1]);
    else if (key == "--attempts")
      attempts = argv[i + 1];
    else if (key == "--pose")
      extra.push_back(argv[i + 1]);
    else {
      fprintf(stderr, "unknown option %s\n", key.c_str());
      return 2;
    }
  }
  PlannerSettings settings =
      wheelchair_planner::plannerSettings(wheelchair_description::test::shippedChair());
  settings.gate.search.time_limit = time_limit;
  if (!attempts.empty()) {
    settings.gate.search.attempts.clear();
    for (size_t at = 0; at < attempts.size();) {
      size_t end = attempts.find(';', at);
      if (end == std::string::npos) end = attempts.size();
      double w = 0.0, m = 0.0, step = 0.0;
      int backward = 0, one_slice = 0;
      if (sscanf(attempts.substr(at, end - at).c_str(), "%lf,%lf,%lf,%d,%d", &w, &m, &step,
                 &backward, &one_slice) < 3) {
        fprintf(stderr, "bad --attempts %s\n", attempts.c_str());
        return 2;
      }
      settings.gate.search.attempts.push_back({w, m, step, backward != 0, one_slice != 0});
      at = end + 1;
    }
  }
  HarmonicPlanner planner;
  planner.configure(settings, HarmonicPlannerConfig());
  planner.setMap(wheelchair_core::loadMap(argv[1]));
  std::vector<Place> places = loadPlaces(argv[2]);
  for (const std::string& e : extra) {
    char name[64];
    Place p;
    if (sscanf(e.c_str(), "%63[^,],%lf,%lf,%lf", name, &p.pose.x, &p.pose.y, &p.pose.yaw) != 4) {
      fprintf(stderr, "bad --pose %s\n", e.c_str());
      return 2;
    }
    p.name = name;
    places.push_back(p);
  }
  int done = 0;
  for (const Place& a : places) {
    if (!only_from.empty() && a.name != only_from) continue;
    for (const Place& b : places) {
      if (&a == &b || (!only_to.empty() && b.name != only_to)) continue;
      if (max_pairs > 0 && done >= max_pairs) return 0;
      ++done;
      std::vector<wheelchair_core::Pose2D> plan;
      Certificate cert;
      const auto t0 = std::chrono::steady_clock::now();
      const bool ok = planner.makePlan(a.pose, b.pose, plan, cert);
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      printf(
          "{\"start\": %s, \"goal\": %s, \"ok\": %s, \"time\": %.4f, \"stage\": %s, \"cusps\": "
          "%d, \"reversed\": %.3f, \"search_time\": %.4f, \"expansions\": %d, \"clearance\": "
          "%.4f, \"reason\": %s}\n",
          quoted(a.name).c_str(), quoted(b.name).c_str(), ok ? "true" : "false", wall,
          quoted(cert.path_stage).c_str(), cert.cusps, cert.reversed_length, cert.search_time,
          cert.search_expansions, cert.footprint_clearance,
          quoted(ok ? "" : cert.failure_reason).c_str());
      fflush(stdout);
    }
  }
  return 0;
}
