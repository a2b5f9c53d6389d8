// Measuring binary of bench/planners: one case (a world or a generated maze), every method,
// JSON objects {"case","method","metric","value","unit"} on stdout (one per line, the run script
// joins them), and optionally a PNG with the paths over the map. The harmonic planner is this
// package's; the OMPL plugin is loaded by name through pluginlib (the workspace sourced), as the
// planner host loads it.
#include <wheelchair_core/config.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_description_testing/chair_file.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner_test/maze.h>

#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <yaml-cpp/yaml.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pluginlib/class_loader.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <queue>
#include <string>
#include <vector>

using namespace wheelchair_harmonic_planner;
using namespace wheelchair_planner;

namespace {

std::string case_name;

void emit(const std::string& method, const std::string& metric, double value,
          const std::string& unit) {
  printf(
      "{\"case\": \"%s\", \"method\": \"%s\", \"metric\": \"%s\", \"value\": %.6g, \"unit\": "
      "\"%s\"}\n",
      case_name.c_str(), method.c_str(), metric.c_str(), std::isfinite(value) ? value : -1.0,
      unit.c_str());
  fflush(stdout);  // rows measured before a timeout of the run script are kept
}

/// Bench mazes: 1.8 m passages (36 cells) between 0.2 m walls, so that the chair's body (0.80 m
/// behind the axle, 0.62 m wide) fits in a passage and turns its corners.
constexpr int kMazeCorridor = 36;
constexpr int kMazeWall = 4;

/// True if maze passages (i, j) and (i + di, j + dj) are joined (the wall cell between them is
/// free).
bool mazeJoined(const wheelchair_core::OccupancyMap& map, int i, int j, int di, int dj) {
  double x, y;
  mazePassageCentre(i, j, kMazeCorridor, kMazeWall, map.resolution, x, y);
  const double half = 0.5 * (kMazeCorridor + kMazeWall) * map.resolution;
  const int wx = static_cast<int>(std::floor((x + half * di) / map.resolution));
  const int wy = static_cast<int>(std::floor((y + half * dj) / map.resolution));
  return wx > 0 && wy > 0 && wx < map.width && wy < map.height &&
         map.at(wx, wy) == wheelchair_core::kFree;
}

/// Start and goal at the centres of passages s and g (n x n passages, index i + n j), with the
/// headings of the passage route between them (breadth-first over joined passages): the start
/// faces its route's first passage and the goal is reached along its last one, so neither needs
/// a turn on the spot (a passage leaves 4 cm around the turning body, under the 5 cm minimum).
void mazeRouteEnds(const wheelchair_core::OccupancyMap& map, int n, int s, int g, Pose2D& start,
                   Pose2D& goal) {
  const int di[4] = {1, 0, -1, 0}, dj[4] = {0, 1, 0, -1};
  std::vector<int> from(static_cast<size_t>(n) * n, -1);
  std::queue<int> open;
  from[s] = s;
  open.push(s);
  while (!open.empty()) {
    const int c = open.front();
    open.pop();
    for (int d = 0; d < 4; ++d) {
      const int ni = c % n + di[d], nj = c / n + dj[d];
      if (ni < 0 || nj < 0 || ni >= n || nj >= n || from[nj * n + ni] >= 0) continue;
      if (!mazeJoined(map, c % n, c / n, di[d], dj[d])) continue;
      from[nj * n + ni] = c;
      open.push(nj * n + ni);
    }
  }
  mazePassageCentre(s % n, s / n, kMazeCorridor, kMazeWall, map.resolution, start.x, start.y);
  mazePassageCentre(g % n, g / n, kMazeCorridor, kMazeWall, map.resolution, goal.x, goal.y);
  if (from[g] < 0 || g == s) return;  // not connected (a perfect maze always is)
  int second = g;
  while (from[second] != s) second = from[second];
  start.yaw = std::atan2(second / n - s / n, second % n - s % n);
  const int last = from[g];
  goal.yaw = std::atan2(g / n - last / n, g % n - last % n);
}

/// Shortest path length on the 8-connected free cells of the hard C-space (Dijkstra) [m].
double gridShortest(const ConfigSpace& cs, const Pose2D& s, const Pose2D& g) {
  int sx, sy, gx, gy;
  if (!cs.worldToCell(s.x, s.y, sx, sy) || !cs.worldToCell(g.x, g.y, gx, gy)) return NAN;
  std::vector<double> dist(static_cast<size_t>(cs.width()) * cs.height(), INFINITY);
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  dist[cs.index(sx, sy)] = 0.0;
  q.push({0.0, cs.index(sx, sy)});
  while (!q.empty()) {
    const auto [d, k] = q.top();
    q.pop();
    if (d > dist[k]) continue;
    const int x = static_cast<int>(k % cs.width()), y = static_cast<int>(k / cs.width());
    if (x == gx && y == gy) return d * cs.resolution();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx || dy) && cs.isFree(x + dx, y + dy)) {
          const double nd = d + ((dx && dy) ? M_SQRT2 : 1.0);
          if (nd < dist[cs.index(x + dx, y + dy)]) {
            dist[cs.index(x + dx, y + dy)] = nd;
            q.push({nd, cs.index(x + dx, y + dy)});
          }
        }
      }
  }
  return NAN;
}

void report(const std::string& method, bool ok, double seconds, const std::vector<Pose2D>& path,
            const ConfigSpace& cs, double shortest) {
  emit(method, "success", ok ? 1.0 : 0.0, "bool");
  emit(method, "time", seconds * 1e3, "ms");
  if (!ok) return;
  Certificate c;
  fillPathFigures(cs, path, c);
  emit(method, "length", c.length, "m");
  emit(method, "length_vs_shortest", c.length / shortest, "ratio");
  emit(method, "min_clearance", c.min_clearance, "m");
  emit(method, "max_curvature", c.max_curvature, "1/m");
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/// A planner's map-dependent work, done when the map arrives (setMap): the C-space and, for
/// the harmonic planner, the map's factorization. `done`: when it ended (the plan's timer).
struct Prepared {
  std::chrono::steady_clock::time_point started, done;
  double cpu = 0.0;  ///< [s]
};

Prepared prepare(GlobalPlanner& planner, const wheelchair_core::OccupancyMap& map) {
  Prepared p;
  const double cpu0 = cpuSeconds();
  p.started = std::chrono::steady_clock::now();
  planner.setMap(map);
  p.done = std::chrono::steady_clock::now();
  p.cpu = cpuSeconds() - cpu0;
  return p;
}

/// prepare_time (map arrival), first_plan_time (map arrival + the first plan, i.e. a planner
/// that gets its map and a goal at once) and prepare_cpu_time.
void emitPreparation(const std::string& method, const Prepared& p, double plan_seconds) {
  const double prepare_seconds = std::chrono::duration<double>(p.done - p.started).count();
  emit(method, "prepare_time", prepare_seconds * 1e3, "ms");
  emit(method, "first_plan_time", (prepare_seconds + plan_seconds) * 1e3, "ms");
  emit(method, "prepare_cpu_time", p.cpu * 1e3, "ms");
}

/// Median, min and max of `reps` CPU-time measurements of f() [ms], emitted as metric (median),
/// metric_min and metric_max.
template <class F>
void emitCpuSpread(const std::string& method, const std::string& metric, int reps, F f) {
  std::vector<double> ms;
  for (int r = 0; r < reps; ++r) {
    const double cpu0 = cpuSeconds();
    f();
    ms.push_back((cpuSeconds() - cpu0) * 1e3);
  }
  std::sort(ms.begin(), ms.end());
  emit(method, metric, ms[ms.size() / 2], "ms");
  emit(method, metric + "_min", ms.front(), "ms");
  emit(method, metric + "_max", ms.back(), "ms");
}

/// The default solver alone: cold (CPU time of solveHarmonic: ordering, factorization and the
/// solves; after the planner's cold plan, whose factor is still held), then warm, i.e. a new goal
/// (the start cell) on the same map with the cached factors (5 repetitions), and the gradient
/// descent on that field; the factorization's phases (assemble, analyze, factorize); then cold
/// again on freed factors.
void solveColdAndWarm(const ConfigSpace& cs, const Pose2D& start, const Pose2D& goal) {
  int gx, gy, sx, sy;
  cs.worldToCell(goal.x, goal.y, gx, gy);
  cs.worldToCell(start.x, start.y, sx, sy);
  HarmonicFactorCache cache;
  const double cpu0 = cpuSeconds();
  const HarmonicSolution sol = solveHarmonic(cs, gx, gy, HarmonicSolverParams(), nullptr, &cache);
  emit("harmonic", "solve_cpu_time", (cpuSeconds() - cpu0) * 1e3, "ms");
  emit("harmonic", "solve_converged", sol.converged ? 1.0 : 0.0, "bool");
  const auto emitPhases = [&](const std::string& prefix) {
    emit("harmonic", prefix + "assemble_cpu_time", cache.timing.assemble * 1e3, "ms");
    emit("harmonic", prefix + "analyze_cpu_time", cache.timing.analyze * 1e3, "ms");
    emit("harmonic", prefix + "factorize_cpu_time", cache.timing.factorize * 1e3, "ms");
  };
  emitPhases("factor_");
  HarmonicSolution back;
  emitCpuSpread("harmonic", "warm_solve_cpu_time", 5, [&] {
    if (!back.log_u.empty()) cache.spare = std::move(back.log_u);
    back = solveHarmonic(cs, sx, sy, HarmonicSolverParams(), nullptr, &cache);
  });
  emit("harmonic", "warm_solve_converged", back.converged && back.factor_reused ? 1.0 : 0.0,
       "bool");
  DescentResult d;
  emitCpuSpread("harmonic", "descent_cpu_time", 5, [&] { d = descend(cs, back, goal.x, goal.y); });
  emit("harmonic", "descent_reached_goal", d.reached_goal ? 1.0 : 0.0, "bool");
  // The cold solve once more after the factors were freed: a new map in a running planner,
  // whose previous factorization's memory is recycled (no fresh pages), first as a map with
  // other free cells (its ordering forgotten), then as one with the same free cells (only
  // conductances changed, or the same map again): the previous ordering replaces AMD.
  for (const std::string prefix : {"new_map_", "same_cells_"}) {
    cache.reset();
    if (prefix == "new_map_") cache.ordering.reset();
    const double cpu1 = cpuSeconds();
    solveHarmonic(cs, gx, gy, HarmonicSolverParams(), nullptr, &cache);
    emit("harmonic", prefix + "solve_cpu_time", (cpuSeconds() - cpu1) * 1e3, "ms");
    emitPhases(prefix + "factor_");
  }
}

/// Whole plans with the planner plugin on one map: the trip cold, then (after a plan to another
/// goal, the start cell) the same trip again, now a new goal for the planner whose factors for
/// this map are cached, then a replan to the same goal after a small map change (a 20 cm block
/// dropped on the free cell nearest the map centre that is not the start or goal cell): the
/// planner warm-starts from its last solution.
void newGoalAndReplan(const wheelchair_core::OccupancyMap& map, const ConfigSpace& cs,
                      const PlannerSettings& settings, const Pose2D& start, const Pose2D& goal) {
  int gx, gy, sx, sy;
  cs.worldToCell(goal.x, goal.y, gx, gy);
  cs.worldToCell(start.x, start.y, sx, sy);
  HarmonicPlanner planner;
  planner.configure(settings, HarmonicPlannerConfig());
  planner.setMap(map);
  std::vector<Pose2D> plan;
  Certificate cert;
  planner.makePlan(start, goal, plan, cert);
  planner.makePlan(start, start, plan, cert);
  const double cpu0 = cpuSeconds();
  const bool again = planner.makePlan(start, goal, plan, cert);
  emit("harmonic_new_goal", "success", again ? 1.0 : 0.0, "bool");
  emit("harmonic_new_goal", "cpu_time", (cpuSeconds() - cpu0) * 1e3, "ms");
  wheelchair_core::OccupancyMap changed = map;
  long best = -1;
  double best_d = INFINITY;
  for (int iy = 0; iy < cs.height(); ++iy)
    for (int ix = 0; ix < cs.width(); ++ix) {
      const double d = std::hypot(ix - cs.width() / 2.0, iy - cs.height() / 2.0);
      if (cs.isFree(ix, iy) && d < best_d && std::hypot(ix - gx, iy - gy) > 20 &&
          std::hypot(ix - sx, iy - sy) > 20) {
        best_d = d;
        best = static_cast<long>(cs.index(ix, iy));
      }
    }
  const int bx = static_cast<int>(best % cs.width()), by = static_cast<int>(best / cs.width());
  for (int iy = by - 2; iy < by + 2; ++iy)
    for (int ix = bx - 2; ix < bx + 2; ++ix) changed.at(ix, iy) = wheelchair_core::kOccupied;
  const double cpu1 = cpuSeconds();
  const auto t1 = std::chrono::steady_clock::now();
  planner.setMap(changed);
  const bool ok = planner.makePlan(start, goal, plan, cert);
  emit("harmonic_replan", "success", ok ? 1.0 : 0.0, "bool");
  emit("harmonic_replan", "time", seconds(t1) * 1e3, "ms");
  emit("harmonic_replan", "cpu_time", (cpuSeconds() - cpu1) * 1e3, "ms");
  emit("harmonic_replan", "warm_started", cert.warm_started ? 1.0 : 0.0, "bool");
  emit("harmonic_replan", "solver_iterations", cert.solver_iterations, "solves+sweeps");
}

/// The live obstacle layer's case: an obstacle of 1 m x 1 m (the largest) appears off
/// the current route (on the free cell nearest the map centre at least 1.5 m from it) and the
/// planner replans to the same goal: through updateMap (the C-space window and the factor
/// columns it reaches recomputed, harmonic_obstacle_replan) and, on a second planner with the same
/// history, through setMap (a new C-space and factorization, harmonic_obstacle_replan_setmap:
/// the path before updateMap existed).
void obstacleReplan(const wheelchair_core::OccupancyMap& map, const ConfigSpace& cs,
                    const PlannerSettings& settings, const Pose2D& start, const Pose2D& goal) {
  HarmonicPlanner fast, full;
  std::vector<Pose2D> route, plan;
  Certificate cert;
  for (HarmonicPlanner* p : {&fast, &full}) {
    p->configure(settings, HarmonicPlannerConfig());
    p->setMap(map);
    p->makePlan(start, goal, route, cert);
  }
  const int reach = static_cast<int>(std::ceil(1.5 / cs.resolution()));
  std::vector<uint8_t> near_route(static_cast<size_t>(cs.width()) * cs.height(), 0);
  std::vector<Pose2D> keep_off = route;
  keep_off.push_back(start);
  keep_off.push_back(goal);
  for (const Pose2D& p : keep_off) {
    int px, py;
    cs.worldToCell(p.x, p.y, px, py);
    for (int iy = std::max(0, py - reach); iy < std::min(cs.height(), py + reach + 1); ++iy)
      for (int ix = std::max(0, px - reach); ix < std::min(cs.width(), px + reach + 1); ++ix)
        if ((ix - px) * (ix - px) + (iy - py) * (iy - py) <= reach * reach)
          near_route[cs.index(ix, iy)] = 1;
  }
  long best = -1;
  double best_d = INFINITY;
  for (int iy = 0; iy < cs.height(); ++iy)
    for (int ix = 0; ix < cs.width(); ++ix) {
      const double d = std::hypot(ix - cs.width() / 2.0, iy - cs.height() / 2.0);
      if (cs.isFree(ix, iy) && !near_route[cs.index(ix, iy)] && d < best_d) {
        best_d = d;
        best = static_cast<long>(cs.index(ix, iy));
      }
    }
  if (best < 0) return;
  const int side = static_cast<int>(std::lround(1.0 / cs.resolution()));
  const int bx = static_cast<int>(best % cs.width()) - side / 2;
  const int by = static_cast<int>(best / cs.width()) - side / 2;
  wheelchair_core::OccupancyMap changed = map;
  for (int iy = std::max(0, by); iy < std::min(map.height, by + side); ++iy)
    for (int ix = std::max(0, bx); ix < std::min(map.width, bx + side); ++ix)
      changed.at(ix, iy) = wheelchair_core::kOccupied;
  const int factorizations = fast.factorCache().factorizations;
  double cpu0 = cpuSeconds();
  auto t0 = std::chrono::steady_clock::now();
  fast.updateMap(changed);
  const double update_ms = seconds(t0) * 1e3, update_cpu_ms = (cpuSeconds() - cpu0) * 1e3;
  const double plan_cpu0 = cpuSeconds();
  bool ok = fast.makePlan(start, goal, plan, cert);
  const double plan_cpu_ms = (cpuSeconds() - plan_cpu0) * 1e3;
  const std::string m = "harmonic_obstacle_replan";
  emit(m, "success", ok ? 1.0 : 0.0, "bool");
  emit(m, "time", seconds(t0) * 1e3, "ms");
  emit(m, "cpu_time", (cpuSeconds() - cpu0) * 1e3, "ms");
  emit(m, "update_time", update_ms, "ms");
  emit(m, "update_cpu_time", update_cpu_ms, "ms");
  emit(m, "plan_cpu_time", plan_cpu_ms, "ms");  // solve + descent + footprint gate
  emit(m, "footprint_repaired", cert.path_stage == "footprint_search" ? 1.0 : 0.0, "bool");
  emit(m, "factor_columns_updated", static_cast<double>(fast.factorCache().updated_columns),
       "columns");
  emit(m, "factorizations", fast.factorCache().factorizations - factorizations, "count");
  emit(m, "obstacle_area", side * side * cs.resolution() * cs.resolution(), "m^2");
  cpu0 = cpuSeconds();
  t0 = std::chrono::steady_clock::now();
  full.setMap(changed);
  ok = full.makePlan(start, goal, plan, cert);
  emit(m + "_setmap", "success", ok ? 1.0 : 0.0, "bool");
  emit(m + "_setmap", "time", seconds(t0) * 1e3, "ms");
  emit(m + "_setmap", "cpu_time", (cpuSeconds() - cpu0) * 1e3, "ms");
}

}  // namespace

// Usage: planner_bench CASE (world.yaml | mazeN) SX SY GX GY [png|-] [jacobi_max_sweeps]
//        [sor_max_sweeps] [rate | replan]   (replan: only the obstacle replan case)
int main(int argc, char** argv) {
  if (argc < 6) {
    fprintf(stderr, "usage: planner_bench <world.yaml|mazeN> sx sy gx gy [out.png] [jacobi]\n");
    return 2;
  }
  const std::string what = argv[1];
  const bool maze = what.rfind("maze", 0) == 0;
  const wheelchair_core::OccupancyMap map =
      maze ? makeMaze(std::stoi(what.substr(4)), kMazeCorridor, kMazeWall, 1)
           : wheelchair_core::loadMap(what);
  case_name = maze ? what : what.substr(what.find_last_of('/') + 1);
  Pose2D start{std::stod(argv[2]), std::stod(argv[3]), 0.0};
  Pose2D goal{std::stod(argv[4]), std::stod(argv[5]), 0.0};
  if (maze) {  // passage indices -> world poses along the passage's open side
    const int n = (map.width - kMazeWall) / (kMazeCorridor + kMazeWall);
    auto idx = [&](double v) { return v < 0 ? n + static_cast<int>(v) : static_cast<int>(v); };
    mazeRouteEnds(map, n, idx(start.x) + n * idx(start.y), idx(goal.x) + n * idx(goal.y), start,
                  goal);
  }
  // The chair of chair.yaml: its footprint, its half width (0.31 m) as the inscribed radius.
  const PlannerSettings settings = plannerSettings(wheelchair_description::test::shippedChair());
  const double cspace_cpu0 = cpuSeconds();
  const ConfigSpace cs(map, settings.cspace);
  emit("harmonic", "cspace_cpu_time", (cpuSeconds() - cspace_cpu0) * 1e3, "ms");
  const double shortest = gridShortest(cs, start, goal);
  emit("grid_dijkstra", "length", shortest, "m");
  if (argc > 9 && std::string(argv[9]) == "replan") {
    obstacleReplan(map, cs, settings, start, goal);
    return 0;
  }
  std::vector<std::pair<std::string, std::vector<Pose2D>>> drawn;
  fprintf(stderr, "start %.2f %.2f %.2f goal %.2f %.2f %.2f\n", start.x, start.y, start.yaw, goal.x,
          goal.y, goal.yaw);

  // harmonic: cold plan (C-space + solve + descent) with each solver: the default direct
  // log-space LDL^T and SOR (capped at sor_max sweeps, argv[8], so that 2048^2 stays short).
  // Wall and process CPU time.
  const std::string sor_max = argc > 8 ? argv[8] : "20000";
  // "rate" (argv[9]): one of several start/goal pairs for the success rate: the default solver
  // and the other planners only, no per-solver profile.
  const bool rate_only = argc > 9 && std::string(argv[9]) == "rate";
  const std::vector<std::string> solvers =
      rate_only ? std::vector<std::string>{"direct"} : std::vector<std::string>{"direct", "sor"};
  for (const std::string& solver : solvers) {
    const std::string method = solver == "direct" ? "harmonic" : "harmonic_" + solver;
    HarmonicPlanner planner;
    HarmonicPlannerConfig config;
    config.solver = solver;
    if (solver == "sor") config.solver_params.max_iterations = std::stoi(sor_max);
    planner.configure(settings, config);
    const Prepared prepared = prepare(planner, map);
    const double cpu0 = cpuSeconds();
    std::vector<Pose2D> plan;
    Certificate cert;
    const bool ok = planner.makePlan(start, goal, plan, cert);
    const double plan_cpu = cpuSeconds() - cpu0, plan_seconds = seconds(prepared.done);
    report(method, ok, plan_seconds, plan, cs, shortest);
    emitPreparation(method, prepared, plan_seconds);
    if (!ok) fprintf(stderr, "%s: %s\n", method.c_str(), cert.failure_reason.c_str());
    emit(method, "footprint_repaired", cert.path_stage == "footprint_search" ? 1.0 : 0.0, "bool");
    emit(method, "cpu_time", plan_cpu * 1e3, "ms");
    emit(method, "first_plan_cpu_time", (prepared.cpu + plan_cpu) * 1e3, "ms");
    emit(method, "solver_iterations", cert.solver_iterations,
         solver == "sor" ? "sweeps" : "solves+sweeps");
    emit(method, "solver_residual", cert.solver_residual, "relative");
    if (ok) emit(method, "min_gradient", cert.min_gradient, "1/m");
    if (ok) emit(method, "plateau_steps", cert.plateau_steps, "steps");
    if (ok && solver == "direct") drawn.push_back({"harmonic", plan});
    if (solver == "direct" && !rate_only) {
      solveColdAndWarm(cs, start, goal);
      newGoalAndReplan(map, cs, settings, start, goal);
      obstacleReplan(map, cs, settings, start, goal);
    }
  }
  pluginlib::ClassLoader<GlobalPlanner> loader("wheelchair_planner",
                                               "wheelchair_planner::GlobalPlanner");
  for (const std::string algo : {"RRTConnect", "RRTstar", "PRMstar", "BITstar"}) {
    boost::shared_ptr<GlobalPlanner> planner;
    try {
      planner = loader.createInstance("wheelchair_ompl_planner/OmplPlanner");
    } catch (const pluginlib::PluginlibException& e) {
      fprintf(stderr, "no OMPL plugin (source the workspace): %s\n", e.what());
      break;
    }
    YAML::Node keys;
    keys["algorithm"] = algo;
    keys["time_limit"] = algo == "RRTConnect" ? 5.0 : 2.0;
    keys["seed"] = 1;
    const wheelchair_core::YamlParameterSource source(keys, "planner_bench");
    wheelchair_core::ConfigReader reader(source);
    planner->configure(settings, reader);
    reader.rejectUnknown();
    const Prepared prepared = prepare(*planner, map);
    std::vector<Pose2D> plan;
    Certificate cert;
    const bool ok = planner->makePlan(start, goal, plan, cert);
    const double plan_seconds = seconds(prepared.done);
    report("ompl_" + algo, ok, plan_seconds, plan, cs, shortest);
    emitPreparation("ompl_" + algo, prepared, plan_seconds);
    if (!ok) fprintf(stderr, "ompl_%s: %s\n", algo.c_str(), cert.failure_reason.c_str());
    emit("ompl_" + algo, "footprint_repaired", cert.path_stage == "footprint_search" ? 1.0 : 0.0,
         "bool");
    if (ok) drawn.push_back({algo, plan});
  }
  {  // MRPT's grid planner (wavefront on the occupancy grid, circular robot)
    mrpt::nav::PlannerSimple2D planner;
    planner.robotRadius = 0.36f;  // inscribed radius + minimum clearance
    planner.minStepInReturnedPath = 0.05f;
    const auto grid = wheelchair_mapping::toMrptGrid(map);
    std::deque<mrpt::math::TPoint2D> raw;
    bool not_found = true;
    const auto t0 = std::chrono::steady_clock::now();
    planner.computePath(grid, mrpt::poses::CPose2D(start.x, start.y, 0),
                        mrpt::poses::CPose2D(goal.x, goal.y, 0), raw, not_found);
    const double t = seconds(t0);
    std::vector<Pose2D> plan;
    for (const auto& p : raw) plan.push_back({p.x, p.y, 0.0});
    report("mrpt_PlannerSimple2D", !not_found && !plan.empty(), t, plan, cs, shortest);
    if (!not_found) drawn.push_back({"mrpt", plan});
  }
  const int jacobi_max = argc > 7 ? std::stoi(argv[7]) : 0;
  if (jacobi_max > 0) {  // the paper's plain Jacobi, on the sizes where it can finish
    int gx, gy;
    cs.worldToCell(goal.x, goal.y, gx, gy);
    const auto t0 = std::chrono::steady_clock::now();
    const JacobiResult j = solvePaperJacobi(cs, gx, gy, 1e-9, jacobi_max);
    const double t = seconds(t0);
    HarmonicSolution as_log;
    as_log.width = cs.width();
    as_log.height = cs.height();
    as_log.goal_ix = gx;
    as_log.goal_iy = gy;
    as_log.log_u.resize(j.phi.size());
    for (size_t k = 0; k < j.phi.size(); ++k)
      as_log.log_u[k] = cs.freeMask()[k] && j.phi[k] < 1.0 ? std::log(1.0 - j.phi[k]) : -INFINITY;
    const DescentResult d = descend(cs, as_log, start.x, start.y);
    report("paper_jacobi", d.reached_goal, t, d.path, cs, shortest);
    emit("paper_jacobi", "sweeps", j.iterations, "sweeps");
    emit("paper_jacobi", "converged", j.converged ? 1.0 : 0.0, "bool");
  }
  if (argc > 6 && std::string(argv[6]) != "-") {
    cv::Mat img(map.height, map.width, CV_8UC3);
    for (int iy = 0; iy < map.height; ++iy)
      for (int ix = 0; ix < map.width; ++ix) {
        const int v = map.at(ix, iy);
        const uchar g = v < 0 ? 160 : (v >= 50 ? 0 : (cs.isFree(ix, iy) ? 255 : 215));
        img.at<cv::Vec3b>(map.height - 1 - iy, ix) = cv::Vec3b(g, g, g);
      }
    const cv::Scalar colours[] = {{0, 0, 255},   {255, 0, 0},   {0, 160, 0},
                                  {255, 0, 255}, {0, 160, 255}, {128, 128, 0}};
    for (size_t m = 0; m < drawn.size(); ++m) {
      for (size_t i = 1; i < drawn[m].second.size(); ++i) {
        auto px = [&](const Pose2D& p) {
          return cv::Point(static_cast<int>(p.x / map.resolution),
                           map.height - 1 - static_cast<int>(p.y / map.resolution));
        };
        cv::line(img, px(drawn[m].second[i - 1]), px(drawn[m].second[i]), colours[m % 6], 1);
      }
      cv::putText(img, drawn[m].first, cv::Point(5, 15 + 14 * static_cast<int>(m)),
                  cv::FONT_HERSHEY_SIMPLEX, 0.4, colours[m % 6], 1);
    }
    cv::imwrite(argv[6], img);
  }
  return 0;
}
