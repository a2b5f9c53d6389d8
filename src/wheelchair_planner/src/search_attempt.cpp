#include "search_attempt.h"

#include <wheelchair_core/kinematics.h>

#include "geodesic_distance.h"
#include "reeds_shepp.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace wheelchair_planner {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The last straight piece to the goal must continue the arrival's direction of motion (ahead
// forwards, behind in reverse): a piece off to the side or against it would make the chair turn
// sharply on the spot just before the goal (the controller follows it), moving the axle and its
// rear sideways.
bool joinsGoalAlongTheMotion(const Pose2D& arrival, bool reverse, const Pose2D& goal,
                             const FootprintSearchParams& p) {
  const double dx = goal.x - arrival.x, dy = goal.y - arrival.y;
  const double distance = std::hypot(dx, dy);
  if (distance > p.goal_tolerance) return false;
  if (distance <= p.goal_join_slack) return true;
  const double motion = arrival.yaw + (reverse ? M_PI : 0.0);
  const double ahead = std::cos(motion) * dx + std::sin(motion) * dy;
  const double aside = -std::sin(motion) * dx + std::cos(motion) * dy;
  return ahead > 0.0 && std::abs(aside) <= std::tan(p.goal_join_angle) * ahead;
}

/// The pose after `d` metres along an arc of curvature `kappa` (straight for kappa = 0); d < 0
/// drives it in reverse (the heading changes by kappa d).
Pose2D arcEnd(const Pose2D& p, double kappa, double d) {
  return wheelchair_core::integrateArc(p, {d, kappa * d});
}

}  // namespace

SearchAttempt::SearchAttempt(const FootprintChecker& checker, const Pose2D& start,
                             const Pose2D& goal, const FootprintSearchParams& params,
                             const FootprintSearchParams::Attempt& attempt, const SweepModel& sweep,
                             HeuristicFields& fields)
    : checker_(checker),
      cs_(checker.configSpace()),
      start_(attempt.backward ? goal : start),
      goal_(attempt.backward ? start : goal),
      chair_start_(start),
      chair_goal_(goal),
      params_(params),
      attempt_(attempt),
      sweep_(sweep),
      fields_(fields),
      bin_angle_(2.0 * M_PI / params.heading_bins),
      closest_pose_(start_),
      closest_block_{kInf, start_.x, start_.y} {
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
  std::vector<double>& field = attempt_.backward ? fields_.to_start : fields_.to_goal;
  if (field.empty()) field = geodesicToGoal(cs_, axle_radius, gx, gy);
  h_ = &field;
  if (!std::isfinite((*h_)[cs_.index(sx, sy)])) {
    reason = "footprint search: the goal is not reachable even for the chair's axle disc";
    return false;
  }
  rule_ = clearanceRule(checker_, chair_start_, params_.min_clearance);
  if (rule_.start_clearance <= 0.0) {
    std::ostringstream os;
    os.precision(3);
    const FootprintContact at_start = checker_.clearance(chair_start_);
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
  return attempt_.heuristic_weight * (*h_)[cs_.index(ix, iy)];
}

int64_t SearchAttempt::cellKey(const Pose2D& p) const { return key(p, false) / 2; }

int64_t SearchAttempt::key(const Pose2D& p, bool reverse) const {
  const int64_t ix = static_cast<int64_t>(std::floor(p.x / params_.xy_bin)) + (1 << 20);
  const int64_t iy = static_cast<int64_t>(std::floor(p.y / params_.xy_bin)) + (1 << 20);
  int64_t it = static_cast<int64_t>(std::lround(p.yaw / bin_angle_)) % params_.heading_bins;
  if (it < 0) it += params_.heading_bins;
  // The direction of arrival is part of the state: going on the same way costs no cusp.
  return ((ix * (int64_t{1} << 22) + iy) * params_.heading_bins + it) * 2 + (reverse ? 1 : 0);
}

double SearchAttempt::penalty(double c) const {
  const double span = std::max(1e-6, params_.soft_clearance - params_.min_clearance);
  const double t = std::clamp((params_.soft_clearance - c) / span, 0.0, 1.0);
  return params_.clearance_weight * t * t;
}

bool SearchAttempt::reachedAsCheaply(const Pose2D& p, bool reverse, double g) const {
  const auto it = best_g_.find(key(p, reverse));
  return it != best_g_.end() && it->second <= g + 1e-9;
}

void SearchAttempt::push(const Node& n) {
  const int64_t k = key(n.pose, n.reverse);
  const auto it = best_g_.find(k);
  if (it != best_g_.end() && it->second <= n.g + 1e-9) return;
  best_g_[k] = n.g;
  nodes_.push_back(n);
  if (!partners_.empty()) by_cell_[cellKey(n.pose)].push_back(static_cast<int>(nodes_.size()) - 1);
  open_.push({n.g + heuristic(n.pose), static_cast<int>(nodes_.size()) - 1});
}

void SearchAttempt::seedStart() {
  push({start_, 0.0, -1, 0.0, false, false, false, 0, 0.0});
  for (const double dir : {1.0, -1.0}) {
    for (int k = 1; k <= params_.heading_bins / 2; ++k) {
      // A backward run begins at the goal: its rotations there are the chair's last motion.
      const Pose2D p{start_.x, start_.y, start_.yaw + dir * k * bin_angle_};
      FootprintContact c;
      if (!poseOk(p, !attempt_.backward, c)) break;
      push({p, params_.rotation_cost * k * bin_angle_, 0, 0.0, true, false, false, 0, 0.0});
    }
  }
}

std::vector<Pose2D> SearchAttempt::pathTo(int idx, bool with_goal) const {
  std::vector<int> chain;
  for (int i = idx; i >= 0; i = nodes_[i].parent) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<Pose2D> path{Pose2D{start_.x, start_.y, 0.0}};
  for (size_t c = 1; c < chain.size(); ++c) {
    const Node& n = nodes_[chain[c]];
    if (n.rotation) continue;
    const Pose2D& from = nodes_[n.parent].pose;
    const int sub = std::max(1, static_cast<int>(std::ceil(attempt_.step / 0.05)));
    const double d = n.reverse ? -attempt_.step : attempt_.step;
    for (int k = 1; k <= sub; ++k) path.push_back(arcEnd(from, n.kappa, d * k / sub));
  }
  path.front().yaw = path.size() > 1 ? path[1].yaw : start_.yaw;
  if (with_goal) path.push_back(goal_);
  return path;
}

bool SearchAttempt::acceptCandidate(int idx) {
  // Cheap first: the final rotation to the goal heading, every 5 degrees.
  bool rotation_ok = true;
  FootprintContact c;
  // (A backward run ends at the chair's start: this is the rotation it begins with.)
  for (const Pose2D& p : wheelchair_controller::rotationInPlace(
           goal_.x, goal_.y, nodes_[idx].pose.yaw, goal_.yaw, 5.0 * M_PI / 180.0))
    rotation_ok = rotation_ok && poseOk(p, attempt_.backward, c);
  if (!rotation_ok) {
    std::ostringstream os;
    os.precision(3);
    os << "the body would hit at (" << c.x << ", " << c.y << ") rotating in place "
       << (attempt_.backward ? "at the start" : "to the goal heading");
    last_candidate_reason_ = os.str();
    return false;
  }
  return acceptPath(pathTo(idx));
}

std::vector<Pose2D> SearchAttempt::drivenPath(std::vector<Pose2D> path) const {
  if (!attempt_.backward || path.size() < 2) return path;
  // The poses carry the chair's heading, so the same poses in the other order are the same
  // motion driven the other way: each forward piece becomes a reverse one and back.
  std::reverse(path.begin(), path.end());
  path.front().yaw = path[1].yaw;  // as pathTo: the controller turns at rest to the path
  path.back().yaw = chair_goal_.yaw;
  return path;
}

bool SearchAttempt::acceptPath(std::vector<Pose2D> path) {
  std::vector<Pose2D> driven = drivenPath(std::move(path));
  const SweepCheck check = checkSweep(checker_, sweep_.sweep(chair_start_, driven), rule_);
  if (!check.ok) {
    last_candidate_reason_ = check.reason;
    return false;
  }
  result_.path = std::move(driven);
  result_.sweep = check;
  return true;
}

bool SearchAttempt::tryAnalytic(int idx, const Node& node) {
  const ReedsSheppShot shot = reedsSheppShot(node.pose, goal_, params_.analytic_radius, 0.05);
  if (shot.poses.size() < 2) return false;
  const bool cusp = node.moved && shot.first_reverse != node.reverse;
  if (node.cusps + shot.cusps + (cusp ? 1 : 0) > params_.max_cusps) return false;
  const double reversed = attempt_.backward ? shot.length - shot.reversed : shot.reversed;
  if (reversed > 1e-9 && !params_.reverse) return false;
  if (node.reversed + reversed > params_.max_reverse_length + 1e-9) return false;
  // A stretch too short to drive between two stops (the controller needs some length to
  // accelerate and brake): not worth a cusp.
  if (shot.cusps > 0 && shot.shortest_run < 2.0 * attempt_.step) return false;
  FootprintContact c;
  for (size_t i = 1; i < shot.poses.size(); ++i)
    if (!poseOk(shot.poses[i], false, c)) return false;
  std::vector<Pose2D> path = pathTo(idx, false);
  if (path.size() == 1) path.front().yaw = node.pose.yaw;
  path.insert(path.end(), shot.poses.begin() + 1, shot.poses.end());
  if (!acceptPath(std::move(path))) return false;
  result_.cusps = node.cusps + shot.cusps + (cusp ? 1 : 0);
  result_.reversed_length = node.reversed + reversed;
  return true;
}

void SearchAttempt::expand(int idx, const Node& node) {
  for (const bool reverse : {false, true}) {
    const bool driven_reverse = drivenInReverse(reverse);
    if (driven_reverse && !params_.reverse) continue;
    // A change of direction (a cusp: the chair stops) and the reversed metres are limited.
    const bool cusp = node.moved && reverse != node.reverse;
    if (cusp && node.cusps >= params_.max_cusps) continue;
    if (driven_reverse && node.reversed + attempt_.step > params_.max_reverse_length + 1e-9)
      continue;
    const double d = reverse ? -attempt_.step : attempt_.step;
    for (const double kappa : curvatures_) {
      // Its cost without the clearance penalty is a lower bound: where a node as cheap reached
      // that state already, push() would refuse this one, so its poses are not checked (most
      // primitives of a lattice land on states reached before; a Hybrid A* closed-set check).
      const Pose2D end = arcEnd(node.pose, kappa, d);
      const double base = attempt_.step * (1.0 + params_.turn_weight * std::abs(kappa)) *
                              (driven_reverse ? params_.reverse_cost : 1.0) +
                          (cusp ? params_.cusp_cost : 0.0);
      if (reachedAsCheaply(end, reverse, node.g + base)) continue;
      // Coarse here (5 cm / 5 degrees); a candidate's whole sweep is verified finely.
      const int n = std::max(
          {1, static_cast<int>(std::ceil(attempt_.step / 0.05)),
           static_cast<int>(std::ceil(std::abs(kappa) * attempt_.step / (5.0 * M_PI / 180.0)))});
      double cmin = kInf;
      FootprintContact block{kInf, 0.0, 0.0};
      for (int s = 1; s <= n; ++s) {
        FootprintContact c;
        if (!poseOk(arcEnd(node.pose, kappa, d * s / n), false, c)) {
          block = c;
          break;
        }
        cmin = std::min(cmin, c.clearance);
      }
      if (std::isfinite(block.clearance)) {
        const double hb = heuristic(node.pose);
        if (hb < closest_ || (hb == closest_ && block.clearance < closest_block_.clearance)) {
          closest_ = hb;
          closest_pose_ = node.pose;
          closest_block_ = block;
        }
        continue;
      }
      // Forwards is preferred: a reversed metre costs reverse_cost times a forward one, and
      // every cusp (stop, change of direction) cusp_cost metres.
      const double cost = attempt_.step *
                              (1.0 + penalty(cmin) + params_.turn_weight * std::abs(kappa)) *
                              (driven_reverse ? params_.reverse_cost : 1.0) +
                          (cusp ? params_.cusp_cost : 0.0);
      push({end, node.g + cost, idx, kappa, false, true, reverse, node.cusps + (cusp ? 1 : 0),
            node.reversed + (driven_reverse ? attempt_.step : 0.0)});
    }
  }
}

bool SearchAttempt::tryMeet(int idx, const Node& node) {
  if (!meeting_ || partners_.empty() || meet_tries_ >= params_.max_candidates) return false;
  const int64_t ix = static_cast<int64_t>(std::floor(node.pose.x / params_.xy_bin));
  const int64_t iy = static_cast<int64_t>(std::floor(node.pose.y / params_.xy_bin));
  const int bins = params_.heading_bins;
  int64_t it = static_cast<int64_t>(std::lround(node.pose.yaw / bin_angle_)) % bins;
  if (it < 0) it += bins;
  for (const SearchAttempt* other : partners_) {
    // Forward run's node f (start ... f), backward run's node b (b ... goal, as driven).
    const SearchAttempt& fwd = attempt_.backward ? *other : *this;
    const SearchAttempt& bwd = attempt_.backward ? *this : *other;
    for (int64_t dx = -1; dx <= 1; ++dx) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        for (int64_t dt = -1; dt <= 1; ++dt) {
          const int64_t t = ((it + dt) % bins + bins) % bins;
          const int64_t k =
              ((ix + dx + (1 << 20)) * (int64_t{1} << 22) + (iy + dy + (1 << 20))) * bins + t;
          const auto found = other->by_cell_.find(k);
          if (found == other->by_cell_.end()) continue;
          for (const int j : found->second) {
            const int fi = attempt_.backward ? j : idx, bi = attempt_.backward ? idx : j;
            const Node& f = fwd.nodes_[fi];
            const Node& b = bwd.nodes_[bi];
            // As driven: f is reached moving f.reverse, the chair leaves b in reverse if b's
            // primitive was forward in the backward run's direction.
            const bool f_rev = f.reverse, b_rev = bwd.drivenInReverse(b.reverse);
            const bool join_rev = f.moved ? f_rev : b_rev;
            if (!joinsGoalAlongTheMotion(f.pose, join_rev, b.pose, params_)) continue;
            const int cusps = f.cusps + b.cusps + (f.moved && f_rev != join_rev ? 1 : 0) +
                              (b.moved && b_rev != join_rev ? 1 : 0);
            const double join = std::hypot(b.pose.x - f.pose.x, b.pose.y - f.pose.y);
            const double reversed = f.reversed + b.reversed + (join_rev ? join : 0.0);
            if (cusps > params_.max_cusps || reversed > params_.max_reverse_length + 1e-9) continue;
            if (join_rev && !params_.reverse) continue;
            FootprintContact c;
            if (!poseOk({0.5 * (f.pose.x + b.pose.x), 0.5 * (f.pose.y + b.pose.y), f.pose.yaw},
                        false, c))
              continue;
            std::vector<Pose2D> path = fwd.pathTo(fi, false);
            std::vector<Pose2D> rest = bwd.pathTo(bi, false);
            std::reverse(rest.begin(), rest.end());
            path.insert(path.end(), rest.begin(), rest.end());
            if (path.size() < 2) continue;
            path.front().yaw = path[1].yaw;
            path.back().yaw = chair_goal_.yaw;
            ++meet_tries_;
            // acceptPath takes the path in this run's own direction.
            if (attempt_.backward) std::reverse(path.begin(), path.end());
            const bool ok = acceptPath(std::move(path));
            if (ok) {
              result_.cusps = cusps;
              result_.reversed_length = reversed;
              return true;
            }
            if (meet_tries_ >= params_.max_candidates) return false;
          }
        }
      }
    }
  }
  return false;
}

std::string SearchAttempt::failureReason() const {
  std::ostringstream os;
  os.precision(3);
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
  return os.str();
}

SearchAttempt::Status SearchAttempt::advance(size_t expansions,
                                             std::chrono::steady_clock::time_point deadline) {
  if (status_ != Status::kRunning) return status_;
  if (!started_) {
    started_ = true;
    // A backward run's field is to the chair's start, which may be tighter than the axle disc
    // (parked by a table): then only that run ends, the forward runs decide.
    if (!prepare(result_.reason))
      return status_ = attempt_.backward ? Status::kExhausted : Status::kRefused;
    seedStart();
  }
  const size_t stop_at = expansions_ + expansions;
  while (!open_.empty() && expansions_ < stop_at) {
    if ((expansions_ & 63) == 0 && std::chrono::steady_clock::now() > deadline) return status_;
    const int idx = open_.top().second;
    open_.pop();
    bool& done = expanded_[key(nodes_[idx].pose, nodes_[idx].reverse)];
    if (done) continue;
    done = true;
    ++expansions_;
    const Node node = nodes_[idx];  // expand() may grow nodes_
    // Analytic expansion near the goal: each node that comes closer than any tried before, and
    // every tenth expansion there.
    const double to_goal = heuristic(node.pose) / attempt_.heuristic_weight;
    if (to_goal <= params_.analytic_distance &&
        (to_goal < analytic_best_ - 0.05 || expansions_ >= analytic_last_ + 10)) {
      analytic_best_ = std::min(analytic_best_, to_goal);
      analytic_last_ = expansions_;
      if (tryAnalytic(idx, node)) {
        result_.found = true;
        return status_ = Status::kFound;
      }
    }
    if (tryMeet(idx, node)) {
      result_.found = true;
      return status_ = Status::kFound;
    }
    if (joinsGoalAlongTheMotion(node.pose, node.reverse, goal_, params_)) {
      if (acceptCandidate(idx)) {
        result_.found = true;
        result_.cusps = node.cusps;
        result_.reversed_length = node.reversed;
        return status_ = Status::kFound;
      }
      if (++candidates_ >= params_.max_candidates) return status_ = Status::kExhausted;
    }
    expand(idx, node);
  }
  if (open_.empty()) status_ = Status::kExhausted;
  return status_;
}

}  // namespace wheelchair_planner
