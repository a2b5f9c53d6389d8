#include "search_attempt.h"

#include "geodesic_distance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace wheelchair_planner {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

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

/// The pose after `d` metres along an arc of curvature `kappa` (straight for kappa = 0).
Pose2D arcEnd(const Pose2D& p, double kappa, double d) {
  if (std::abs(kappa) < 1e-9) return {p.x + d * std::cos(p.yaw), p.y + d * std::sin(p.yaw), p.yaw};
  const double yaw = p.yaw + kappa * d;
  return {p.x + (std::sin(yaw) - std::sin(p.yaw)) / kappa,
          p.y + (std::cos(p.yaw) - std::cos(yaw)) / kappa, yaw};
}

}  // namespace

SearchAttempt::SearchAttempt(const FootprintChecker& checker, const Pose2D& start,
                             const Pose2D& goal, const FootprintSearchParams& params,
                             const FootprintSearchParams::Attempt& attempt, const SweepModel& sweep)
    : checker_(checker),
      cs_(checker.configSpace()),
      start_(start),
      goal_(goal),
      params_(params),
      attempt_(attempt),
      sweep_(sweep),
      bin_angle_(2.0 * M_PI / params.heading_bins),
      closest_pose_(start),
      closest_block_{kInf, start.x, start.y} {
  curvatures_.push_back(0.0);
  for (const double r : params.radii) {
    curvatures_.push_back(1.0 / r);
    curvatures_.push_back(-1.0 / r);
  }
}

bool SearchAttempt::prepare(std::string& reason) {
  int sx, sy, gx, gy;
  if (!cs_.worldToCell(start_.x, start_.y, sx, sy) || !cs_.worldToCell(goal_.x, goal_.y, gx, gy)) {
    reason = "footprint search: start or goal outside the map";
    return false;
  }
  const double axle_radius = checker_.inscribedRadius() + params_.min_clearance - cs_.resolution();
  h_ = geodesicToGoal(cs_, axle_radius, gx, gy);
  if (!std::isfinite(h_[cs_.index(sx, sy)])) {
    reason = "footprint search: the goal is not reachable even for the chair's axle disc";
    return false;
  }
  rule_ = clearanceRule(checker_, start_, params_.min_clearance);
  if (rule_.start_clearance <= 0.0) {
    std::ostringstream os;
    os.precision(3);
    const FootprintContact at_start = checker_.clearance(start_);
    os << "footprint search: at the start the body overlaps an obstacle at (" << at_start.x << ", "
       << at_start.y << ")";
    reason = os.str();
    return false;
  }
  return true;
}

bool SearchAttempt::poseOk(const Pose2D& p, bool start_rotation, FootprintContact& c) const {
  const double required =
      rule_.required(p, start_rotation) + (start_rotation ? 0.0 : attempt_.margin);
  c = checker_.clearance(p, required, params_.soft_clearance);
  return c.clearance >= required;
}

double SearchAttempt::heuristic(const Pose2D& p) const {
  int ix, iy;
  if (!cs_.worldToCell(p.x, p.y, ix, iy)) return kInf;
  return attempt_.heuristic_weight * h_[cs_.index(ix, iy)];
}

int64_t SearchAttempt::key(const Pose2D& p) const {
  const int64_t ix = static_cast<int64_t>(std::floor(p.x / params_.xy_bin)) + (1 << 20);
  const int64_t iy = static_cast<int64_t>(std::floor(p.y / params_.xy_bin)) + (1 << 20);
  int64_t it = static_cast<int64_t>(std::lround(p.yaw / bin_angle_)) % params_.heading_bins;
  if (it < 0) it += params_.heading_bins;
  return (ix * (int64_t{1} << 22) + iy) * params_.heading_bins + it;
}

double SearchAttempt::penalty(double c) const {
  const double span = std::max(1e-6, params_.soft_clearance - params_.min_clearance);
  const double t = std::clamp((params_.soft_clearance - c) / span, 0.0, 1.0);
  return params_.clearance_weight * t * t;
}

void SearchAttempt::push(const Node& n) {
  const int64_t k = key(n.pose);
  const auto it = best_g_.find(k);
  if (it != best_g_.end() && it->second <= n.g + 1e-9) return;
  best_g_[k] = n.g;
  nodes_.push_back(n);
  open_.push({n.g + heuristic(n.pose), static_cast<int>(nodes_.size()) - 1});
}

void SearchAttempt::seedStart() {
  push({start_, 0.0, -1, 0.0, false});
  for (const double dir : {1.0, -1.0}) {
    for (int k = 1; k <= params_.heading_bins / 2; ++k) {
      const Pose2D p{start_.x, start_.y, start_.yaw + dir * k * bin_angle_};
      FootprintContact c;
      if (!poseOk(p, true, c)) break;
      push({p, params_.rotation_cost * k * bin_angle_, 0, 0.0, true});
    }
  }
}

std::vector<Pose2D> SearchAttempt::pathTo(int idx) const {
  std::vector<int> chain;
  for (int i = idx; i >= 0; i = nodes_[i].parent) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<Pose2D> path{Pose2D{start_.x, start_.y, 0.0}};
  for (size_t c = 1; c < chain.size(); ++c) {
    const Node& n = nodes_[chain[c]];
    if (n.rotation) continue;
    const Pose2D& from = nodes_[n.parent].pose;
    const int sub = std::max(1, static_cast<int>(std::ceil(attempt_.step / 0.05)));
    for (int k = 1; k <= sub; ++k) path.push_back(arcEnd(from, n.kappa, attempt_.step * k / sub));
  }
  path.front().yaw = path.size() > 1 ? path[1].yaw : start_.yaw;
  path.push_back(goal_);
  return path;
}

bool SearchAttempt::acceptCandidate(int idx, FootprintSearchResult& result) {
  // Cheap first: the final rotation to the goal heading, every 5 degrees.
  bool rotation_ok = true;
  FootprintContact c;
  for (const Pose2D& p : wheelchair_controller::rotationInPlace(
           goal_.x, goal_.y, nodes_[idx].pose.yaw, goal_.yaw, 5.0 * M_PI / 180.0))
    rotation_ok = rotation_ok && poseOk(p, false, c);
  if (!rotation_ok) {
    std::ostringstream os;
    os.precision(3);
    os << "the body would hit at (" << c.x << ", " << c.y
       << ") rotating in place to the goal heading";
    last_candidate_reason_ = os.str();
    return false;
  }
  std::vector<Pose2D> path = pathTo(idx);
  const SweepCheck check = checkSweep(checker_, sweep_.sweep(start_, path), rule_);
  if (!check.ok) {
    last_candidate_reason_ = check.reason;
    return false;
  }
  result.path = std::move(path);
  result.sweep = check;
  return true;
}

void SearchAttempt::expand(int idx, const Node& node) {
  for (const double kappa : curvatures_) {
    // Coarse here (5 cm / 5 degrees); a candidate's whole sweep is verified finely.
    const int n = std::max(
        {1, static_cast<int>(std::ceil(attempt_.step / 0.05)),
         static_cast<int>(std::ceil(std::abs(kappa) * attempt_.step / (5.0 * M_PI / 180.0)))});
    double cmin = kInf;
    FootprintContact block{kInf, 0.0, 0.0};
    for (int s = 1; s <= n; ++s) {
      FootprintContact c;
      if (!poseOk(arcEnd(node.pose, kappa, attempt_.step * s / n), false, c)) {
        block = c;
        break;
      }
      cmin = std::min(cmin, c.clearance);
    }
    const Pose2D end = arcEnd(node.pose, kappa, attempt_.step);
    if (std::isfinite(block.clearance)) {
      const double hb = heuristic(node.pose);
      if (hb < closest_ || (hb == closest_ && block.clearance < closest_block_.clearance)) {
        closest_ = hb;
        closest_pose_ = node.pose;
        closest_block_ = block;
      }
      continue;
    }
    const double cost =
        attempt_.step * (1.0 + penalty(cmin) + params_.turn_weight * std::abs(kappa));
    push({end, node.g + cost, idx, kappa, false});
  }
}

std::string SearchAttempt::failureReason(size_t expansions, double seconds,
                                         const std::string& limit) const {
  std::ostringstream os;
  os.precision(3);
  os << "no footprint-feasible path (" << expansions << " expansions, " << seconds << " s): ";
  if (!last_candidate_reason_.empty()) {
    os << "every arrival at the goal fails its sweep; last: " << last_candidate_reason_;
  } else if (std::isfinite(closest_block_.clearance)) {
    os << "closest approach with base_link at (" << closest_pose_.x << ", " << closest_pose_.y
       << "), " << closest_ / attempt_.heuristic_weight
       << " m from the goal, where the body would hit at (" << closest_block_.x << ", "
       << closest_block_.y << ")";
  } else {
    os << "no motion from the start keeps the minimum clearance";
  }
  if (!limit.empty()) os << " [" << limit << "]";
  return os.str();
}

FootprintSearchResult SearchAttempt::run(double time_limit) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  FootprintSearchResult result;
  const auto finish = [&](bool found) {
    result.found = found;
    result.time = elapsed();
    if (!found) result.path.clear();
    return result;
  };
  if (!prepare(result.reason)) return finish(false);
  seedStart();
  while (!open_.empty()) {
    if ((result.expansions & 63) == 0 && elapsed() > time_limit) {
      result.reason = "footprint search: time limit reached";
      break;
    }
    if (result.expansions >= static_cast<size_t>(params_.attempt_expansions)) {
      result.reason = "footprint search: expansion limit reached";
      break;
    }
    const int idx = open_.top().second;
    open_.pop();
    bool& done = expanded_[key(nodes_[idx].pose)];
    if (done) continue;
    done = true;
    ++result.expansions;
    const Node node = nodes_[idx];  // expand() may grow nodes_
    if (joinsGoalAhead(node.pose, goal_, params_)) {
      if (acceptCandidate(idx, result)) return finish(true);
      if (++candidates_ >= params_.max_candidates) {
        result.reason = "footprint search: no candidate's sweep is feasible";
        break;
      }
    }
    expand(idx, node);
  }
  result.reason = failureReason(result.expansions, elapsed(), result.reason);
  return finish(false);
}

}  // namespace wheelchair_planner
