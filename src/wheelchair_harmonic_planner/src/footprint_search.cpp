#include <wheelchair_harmonic_planner/footprint_search.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>
#include <unordered_map>

namespace wheelchair_harmonic_planner {

namespace {

// The last straight piece to the goal must continue the arrival heading: a piece off to the
// side or behind would make the chair turn sharply on the spot just before the goal (the
// controller follows it), moving the axle and its rear sideways.
bool joinsGoalAhead(const Pose2D& arrival, const Pose2D& goal, const FootprintSearchParams& p) {
  const double dx = goal.x - arrival.x, dy = goal.y - arrival.y;
  const double distance = std::hypot(dx, dy);
  if (distance > p.goal_tolerance) return false;
  if (distance <= p.goal_join_slack) return true;
  const double ahead = std::cos(arrival.yaw) * dx + std::sin(arrival.yaw) * dy;
  const double aside = -std::sin(arrival.yaw) * dx + std::cos(arrival.yaw) * dy;
  return ahead > 0.0 && std::abs(aside) <= std::tan(p.goal_join_angle) * ahead;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

/// 8-connected Dijkstra distance to the goal cell over the cells where the axle may be (its
/// inscribed disc plus the hard clearance, less a cell): a lower bound of the path length.
std::vector<double> geodesicToGoal(const ConfigSpace& cs, double axle_radius, int gx, int gy) {
  const int w = cs.width(), h = cs.height();
  std::vector<double> dist(static_cast<size_t>(w) * h, kInf);
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[cs.index(gx, gy)] = 0.0;
  open.push({0.0, cs.index(gx, gy)});
  const double res = cs.resolution();
  while (!open.empty()) {
    const auto [d, k] = open.top();
    open.pop();
    if (d > dist[k]) continue;
    const int ix = static_cast<int>(k % w), iy = static_cast<int>(k / w);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = ix + dx, ny = iy + dy;
        if ((dx == 0 && dy == 0) || !cs.inBounds(nx, ny)) continue;
        if (cs.obstacleDistance(nx, ny) < axle_radius) continue;
        const double nd = d + res * ((dx != 0 && dy != 0) ? M_SQRT2 : 1.0);
        const size_t nk = cs.index(nx, ny);
        if (nd < dist[nk]) {
          dist[nk] = nd;
          open.push({nd, nk});
        }
      }
    }
  }
  return dist;
}

struct Node {
  Pose2D pose;
  double g = 0.0;
  int parent = -1;
  double kappa = 0.0;
  bool rotation = false;  ///< reached from the parent by an in-place rotation (start only)
};

Pose2D arcEnd(const Pose2D& p, double kappa, double d) {
  if (std::abs(kappa) < 1e-9) return {p.x + d * std::cos(p.yaw), p.y + d * std::sin(p.yaw), p.yaw};
  const double yaw = p.yaw + kappa * d;
  return {p.x + (std::sin(yaw) - std::sin(p.yaw)) / kappa,
          p.y + (std::cos(p.yaw) - std::cos(yaw)) / kappa, yaw};
}

/// One weighted A* run with `attempt`'s settings, at most `time_limit` seconds.
FootprintSearchResult searchOnce(const FootprintChecker& checker, const Pose2D& start,
                                 const Pose2D& goal, const FootprintSearchParams& params,
                                 const FootprintSearchParams::Attempt& attempt, double time_limit,
                                 const SweepParams& sweep_params) {
  const auto t0 = std::chrono::steady_clock::now();
  FootprintSearchResult result;
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const auto finish = [&](bool found) {
    result.found = found;
    result.time = elapsed();
    if (!found) result.path.clear();
    return result;
  };
  const ConfigSpace& cs = checker.configSpace();
  int sx, sy, gx, gy;
  if (!cs.worldToCell(start.x, start.y, sx, sy) || !cs.worldToCell(goal.x, goal.y, gx, gy)) {
    result.reason = "footprint search: start or goal outside the map";
    return finish(false);
  }
  const double axle_radius = checker.inscribedRadius() + params.min_clearance - cs.resolution();
  const std::vector<double> h = geodesicToGoal(cs, axle_radius, gx, gy);
  if (!std::isfinite(h[cs.index(sx, sy)])) {
    result.reason = "footprint search: the goal is not reachable even for the chair's axle disc";
    return finish(false);
  }
  const auto heuristic = [&](const Pose2D& p) {
    int ix, iy;
    if (!cs.worldToCell(p.x, p.y, ix, iy)) return kInf;
    return attempt.heuristic_weight * h[cs.index(ix, iy)];
  };
  const double bin_angle = 2.0 * M_PI / params.heading_bins;
  const auto key = [&](const Pose2D& p) {
    const int64_t ix = static_cast<int64_t>(std::floor(p.x / params.xy_bin)) + (1 << 20);
    const int64_t iy = static_cast<int64_t>(std::floor(p.y / params.xy_bin)) + (1 << 20);
    int64_t it = static_cast<int64_t>(std::lround(p.yaw / bin_angle)) % params.heading_bins;
    if (it < 0) it += params.heading_bins;
    return (ix * (int64_t{1} << 22) + iy) * params.heading_bins + it;
  };
  const double span = std::max(1e-6, params.soft_clearance - params.min_clearance);
  const auto penalty = [&](double c) {
    const double t = std::clamp((params.soft_clearance - c) / span, 0.0, 1.0);
    return params.clearance_weight * t * t;
  };

  std::vector<Node> nodes;
  std::unordered_map<int64_t, double> best_g;
  std::unordered_map<int64_t, bool> expanded;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  const auto push = [&](const Node& n) {
    const int64_t k = key(n.pose);
    const auto it = best_g.find(k);
    if (it != best_g.end() && it->second <= n.g + 1e-9) return;
    best_g[k] = n.g;
    nodes.push_back(n);
    open.push({n.g + heuristic(n.pose), static_cast<int>(nodes.size()) - 1});
  };
  // The start, and the headings reachable from it by rotating in place either way.
  const ClearanceRule rule = clearanceRule(checker, start, params.min_clearance);
  if (rule.start_clearance <= 0.0) {
    std::ostringstream os;
    os.precision(3);
    const FootprintContact at_start = checker.clearance(start);
    os << "footprint search: at the start the body overlaps an obstacle at (" << at_start.x << ", "
       << at_start.y << ")";
    result.reason = os.str();
    return finish(false);
  }
  // Clearance of a pose if it keeps what the rule requires there, else the blocking contact.
  const auto poseOk = [&](const Pose2D& p, bool start_rotation, FootprintContact& c) {
    const double required =
        rule.required(p, start_rotation) + (start_rotation ? 0.0 : attempt.margin);
    c = checker.clearance(p, required, params.soft_clearance);
    return c.clearance >= required;
  };
  push({start, 0.0, -1, 0.0, false});
  for (const double dir : {1.0, -1.0}) {
    for (int k = 1; k <= params.heading_bins / 2; ++k) {
      const Pose2D p{start.x, start.y, start.yaw + dir * k * bin_angle};
      FootprintContact c;
      if (!poseOk(p, true, c)) break;
      push({p, params.rotation_cost * k * bin_angle, 0, 0.0, true});
    }
  }
  std::vector<double> curvatures{0.0};
  for (const double r : params.radii) {
    curvatures.push_back(1.0 / r);
    curvatures.push_back(-1.0 / r);
  }
  // Where the search came closest to the goal, and what blocked it there (for the reason).
  double closest = kInf;
  Pose2D closest_pose = start;
  FootprintContact closest_block{kInf, start.x, start.y};
  int candidates = 0;
  std::string last_candidate_reason;

  const auto pathTo = [&](int idx) {
    std::vector<int> chain;
    for (int i = idx; i >= 0; i = nodes[i].parent) chain.push_back(i);
    std::reverse(chain.begin(), chain.end());
    std::vector<Pose2D> path{Pose2D{start.x, start.y, 0.0}};
    for (size_t c = 1; c < chain.size(); ++c) {
      const Node& n = nodes[chain[c]];
      if (n.rotation) continue;
      const Pose2D& from = nodes[n.parent].pose;
      const int sub = std::max(1, static_cast<int>(std::ceil(attempt.step / 0.05)));
      for (int k = 1; k <= sub; ++k) path.push_back(arcEnd(from, n.kappa, attempt.step * k / sub));
    }
    path.front().yaw = path.size() > 1 ? path[1].yaw : start.yaw;
    path.push_back(goal);
    return path;
  };

  while (!open.empty()) {
    if ((result.expansions & 63) == 0 && elapsed() > time_limit) {
      result.reason = "footprint search: time limit reached";
      break;
    }
    if (result.expansions >= static_cast<size_t>(params.attempt_expansions)) {
      result.reason = "footprint search: expansion limit reached";
      break;
    }
    const int idx = open.top().second;
    open.pop();
    const int64_t k = key(nodes[idx].pose);
    if (expanded[k]) continue;
    expanded[k] = true;
    ++result.expansions;
    const Node node = nodes[idx];
    if (joinsGoalAhead(node.pose, goal, params)) {
      // Cheap first: the final rotation to the goal heading, every 5 degrees.
      bool rotation_ok = true;
      FootprintContact c;
      for (const Pose2D& p :
           rotationInPlace(goal.x, goal.y, node.pose.yaw, goal.yaw, 5.0 * M_PI / 180.0))
        rotation_ok = rotation_ok && poseOk(p, false, c);
      std::vector<Pose2D> path = rotation_ok ? pathTo(idx) : std::vector<Pose2D>();
      const SweepCheck check =
          rotation_ok ? checkSweep(checker, executedSweep(start, path, sweep_params), rule)
                      : SweepCheck();
      if (!rotation_ok) {
        std::ostringstream os;
        os.precision(3);
        os << "the body would hit at (" << c.x << ", " << c.y
           << ") rotating in place to the goal heading";
        last_candidate_reason = os.str();
      } else if (check.ok) {
        result.path = std::move(path);
        result.sweep = check;
        return finish(true);
      }
      if (rotation_ok) last_candidate_reason = check.reason;
      if (++candidates >= params.max_candidates) {
        result.reason = "footprint search: no candidate's sweep is feasible";
        break;
      }
    }
    for (const double kappa : curvatures) {
      // Coarse here (5 cm / 5 degrees); a candidate's whole sweep is verified finely.
      const int n = std::max(
          {1, static_cast<int>(std::ceil(attempt.step / 0.05)),
           static_cast<int>(std::ceil(std::abs(kappa) * attempt.step / (5.0 * M_PI / 180.0)))});
      double cmin = kInf;
      FootprintContact block{kInf, 0.0, 0.0};
      for (int s = 1; s <= n; ++s) {
        FootprintContact c;
        if (!poseOk(arcEnd(node.pose, kappa, attempt.step * s / n), false, c)) {
          block = c;
          break;
        }
        cmin = std::min(cmin, c.clearance);
      }
      const Pose2D end = arcEnd(node.pose, kappa, attempt.step);
      if (std::isfinite(block.clearance)) {
        const double hb = heuristic(node.pose);
        if (hb < closest || (hb == closest && block.clearance < closest_block.clearance)) {
          closest = hb;
          closest_pose = node.pose;
          closest_block = block;
        }
        continue;
      }
      const double cost =
          attempt.step * (1.0 + penalty(cmin) + params.turn_weight * std::abs(kappa));
      push({end, node.g + cost, idx, kappa, false});
    }
  }
  std::ostringstream os;
  os.precision(3);
  os << "no footprint-feasible path (" << result.expansions << " expansions, " << elapsed()
     << " s): ";
  if (!last_candidate_reason.empty()) {
    os << "every arrival at the goal fails its sweep; last: " << last_candidate_reason;
  } else if (std::isfinite(closest_block.clearance)) {
    os << "closest approach with base_link at (" << closest_pose.x << ", " << closest_pose.y
       << "), " << closest / attempt.heuristic_weight
       << " m from the goal, where the body would hit at (" << closest_block.x << ", "
       << closest_block.y << ")";
  } else {
    os << "no motion from the start keeps the minimum clearance";
  }
  if (!result.reason.empty()) os << " [" << result.reason << "]";
  result.reason = os.str();
  return finish(false);
}

}  // namespace

FootprintSearchResult footprintSearch(const FootprintChecker& checker, const Pose2D& start,
                                      const Pose2D& goal, const FootprintSearchParams& params,
                                      const SweepParams& sweep_params) {
  const auto t0 = std::chrono::steady_clock::now();
  const size_t n = params.attempts.size();
  FootprintSearchResult result;
  size_t expansions = 0, attempts = 0;
  for (size_t i = 0; i < n; ++i) {
    const double used =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (used >= params.time_limit) break;
    result = searchOnce(checker, start, goal, params, params.attempts[i], params.time_limit - used,
                        sweep_params);
    expansions += result.expansions;
    ++attempts;
    // No expansion: refused before searching (outside the map, goal unreachable for the axle
    // disc, start overlapping), which no other setting changes.
    if (result.found || result.expansions == 0) break;
  }
  if (n == 0) result.reason = "footprint search: no attempt configured";
  if (!result.found && attempts > 1)
    result.reason = std::to_string(attempts) + " search settings tried; last: " + result.reason;
  result.expansions = expansions;
  result.time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace wheelchair_harmonic_planner
