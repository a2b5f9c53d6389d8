#include <wheelchair_slam/correlative_search.h>
#include <wheelchair_slam/graph_slam.h>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace wheelchair_slam {

using wheelchair_core::Pose2D;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const SlamConfig& validated(const SlamConfig& config) {
  const std::string problem = config.validate();
  if (!problem.empty()) throw wheelchair_core::ConfigError("SLAM configuration: " + problem);
  return config;
}

Eigen::Matrix3d informationOf(const Eigen::Matrix3d& covariance) {
  const Eigen::Matrix3d sym = 0.5 * (covariance + covariance.transpose());
  return sym.inverse();
}

}  // namespace

GraphSlam::GraphSlam(const SlamConfig& config)
    : config_(validated(config)), matcher_(config.matcher) {}

Pose2D GraphSlam::scanPose(size_t index) const {
  const ScanRecord& r = scans_[index];
  return wheelchair_core::compose(graph_.poses()[r.keyframe], r.relative);
}

std::vector<Pose2D> GraphSlam::trajectory() const {
  std::vector<Pose2D> out;
  out.reserve(scans_.size());
  for (size_t i = 0; i < scans_.size(); ++i) out.push_back(scanPose(i));
  return out;
}

std::vector<size_t> GraphSlam::keyframeScans() const {
  std::vector<size_t> out;
  for (const Keyframe& k : keyframes_) out.push_back(k.scan);
  return out;
}

Eigen::Matrix3d GraphSlam::odometryInformation(const Pose2D& motion) const {
  const OdometryNoise& n = config_.odometry;
  const double d = std::hypot(motion.x, motion.y);
  const double sxy = n.sigma_xy_floor + n.sigma_xy_per_m * d;
  const double syaw =
      n.sigma_yaw_floor + n.sigma_yaw_per_rad * std::abs(motion.yaw) + n.sigma_yaw_per_m * d;
  Eigen::Matrix3d info = Eigen::Matrix3d::Zero();
  info(0, 0) = info(1, 1) = 1.0 / (sxy * sxy);
  info(2, 2) = 1.0 / (syaw * syaw);
  return info;
}

Points GraphSlam::keyframePoints(size_t first, size_t last, size_t exclude_from) const {
  Points out;
  for (size_t k = first; k <= last && k < keyframes_.size() && k < exclude_from; ++k) {
    appendTransformed(keyframes_[k].points, graph_.poses()[k], out);
  }
  return out;
}

void GraphSlam::rebuildLocalMap() {
  const size_t n = keyframes_.size();
  const size_t width = static_cast<size_t>(config_.matcher.local_map_keyframes);
  const size_t first = n > width ? n - width : 0;
  local_map_ = ReferenceCloud(keyframePoints(first, n - 1, n), config_.matcher.map_voxel);
}

Pose2D GraphSlam::addScan(const wheelchair_core::LaserScan2D& scan, const Pose2D& odometry) {
  const auto start = std::chrono::steady_clock::now();
  Points points = scanPoints(scan, config_.matcher.max_range, config_.matcher.point_spacing);
  stamps_.push_back(scan.stamp);
  ++stats_.scans;
  const size_t index = scans_.size();
  if (keyframes_.empty()) {
    scans_.push_back({0, Pose2D{}});
    match_info_.emplace_back();
    match_info_.back().keyframe = true;
    addKeyframe(index, odometry, odometry, std::move(points), nullptr);
    last_odometry_ = odometry;
    stats_.seconds_matching += secondsSince(start);
    return odometry;
  }
  const Pose2D motion = wheelchair_core::between(last_odometry_, odometry);
  path_length_ += std::hypot(motion.x, motion.y);
  last_odometry_ = odometry;
  const Pose2D predicted = wheelchair_core::compose(scanPose(index - 1), motion);
  // The odometry's information about this motion, in the map frame.
  const Eigen::Matrix3d prior =
      informationOf(rotateCovariance(odometryInformation(motion).inverse(), -predicted.yaw));
  MatchResult match =
      matcher_.match(local_map_, points, predicted, config_.odometry_prior ? &prior : nullptr);
  if (!match.accepted) {
    ++stats_.match_failures;
    match.pose = predicted;
  }
  ScanMatchInfo info;
  info.matched = match.accepted;
  info.goodness = match.goodness;
  info.inliers = match.inliers;
  info.sigma_x = std::sqrt(match.covariance(0, 0));
  info.sigma_y = std::sqrt(match.covariance(1, 1));
  info.sigma_yaw = std::sqrt(match.covariance(2, 2));
  info.correction = wheelchair_core::between(predicted, match.pose);
  const size_t kf = keyframes_.size() - 1;
  const Pose2D kf_pose = graph_.poses()[kf];
  const Pose2D from_kf = wheelchair_core::between(kf_pose, match.pose);
  const bool new_keyframe = std::hypot(from_kf.x, from_kf.y) >= config_.keyframes.distance ||
                            std::abs(from_kf.yaw) >= config_.keyframes.angle;
  stats_.seconds_matching += secondsSince(start);
  info.keyframe = new_keyframe;
  match_info_.push_back(info);
  if (!new_keyframe) {
    scans_.push_back({kf, from_kf});
    return match.pose;
  }
  scans_.push_back({kf + 1, Pose2D{}});
  addKeyframe(index, match.pose, odometry, std::move(points), match.accepted ? &match : nullptr);
  return scanPose(index);
}

void GraphSlam::addKeyframe(size_t scan, const Pose2D& pose, const Pose2D& odometry, Points points,
                            const MatchResult* match) {
  const size_t node = graph_.addNode(pose);
  keyframes_.push_back({scan, std::move(points), path_length_, odometry});
  ++stats_.keyframes;
  if (node > 0) {
    const Keyframe& prev = keyframes_[node - 1];
    const Pose2D prev_pose = graph_.poses()[node - 1];
    GraphEdge odo;
    odo.from = node - 1;
    odo.to = node;
    odo.kind = EdgeKind::kOdometry;
    odo.measurement = wheelchair_core::between(prev.odometry, odometry);
    odo.information = odometryInformation(odo.measurement);
    graph_.addEdge(odo);
    if (match) {
      GraphEdge m;
      m.from = node - 1;
      m.to = node;
      m.kind = EdgeKind::kScanMatch;
      m.measurement = wheelchair_core::between(prev_pose, pose);
      m.information = informationOf(
          rotateCovariance(match->covariance * config_.match_covariance_scale, prev_pose.yaw));
      graph_.addEdge(m);
    }
  }
  if (config_.loops.enabled && node > 0 &&
      node % static_cast<size_t>(config_.loops.every_n_keyframes) == 0) {
    tryLoopClosure(node);
  }
  rebuildLocalMap();
}

void GraphSlam::tryLoopClosure(size_t k) {
  const auto start = std::chrono::steady_clock::now();
  const LoopClosureConfig& lc = config_.loops;
  const Pose2D pk = graph_.poses()[k];
  size_t best = k;
  double best_d = lc.search_radius;
  const size_t limit = pathGapLimit(k);
  for (size_t j = 0; j < limit; ++j) {
    const Pose2D& pj = graph_.poses()[j];
    const double d = std::hypot(pj.x - pk.x, pj.y - pk.y);
    if (d < best_d) {
      best_d = d;
      best = j;
    }
  }
  if (best == k) {
    stats_.seconds_loops += secondsSince(start);
    return;
  }
  ++stats_.loop_attempts;
  const size_t w = static_cast<size_t>(lc.submap_half_width);
  const size_t first = best > w ? best - w : 0;
  const Points submap = keyframePoints(first, best + w, limit);
  const Points& scan = keyframes_[k].points;
  Points sparse;
  for (size_t i = 0; i < scan.size(); i += 2) sparse.push_back(scan[i]);
  const LikelihoodGrid grid(submap, lc.grid_resolution, lc.grid_resolution);
  SearchWindow window;
  window.xy = lc.window_xy;
  window.yaw = lc.window_yaw;
  window.step_yaw = lc.search_step_yaw;
  const SearchResult found = correlativeSearch(grid, sparse, pk, window);
  if (found.score < lc.min_score) {
    stats_.seconds_loops += secondsSince(start);
    return;
  }
  const ReferenceCloud reference(submap, config_.matcher.map_voxel);
  const MatchResult refined = matcher_.match(reference, scan, found.pose, lc.min_goodness);
  const Pose2D shift = wheelchair_core::between(found.pose, refined.pose);
  const bool agrees = std::hypot(shift.x, shift.y) < 3 * lc.grid_resolution &&
                      std::abs(shift.yaw) < 3 * lc.search_step_yaw;
  if (!refined.accepted || !agrees) {
    stats_.seconds_loops += secondsSince(start);
    return;
  }
  addLoopEdge(best, k, refined, found.score);
  stats_.seconds_loops += secondsSince(start);
  optimizeAndPrune();
}

size_t GraphSlam::pathGapLimit(size_t k) const {
  const double path_k = keyframes_[k].path_length;
  size_t limit = 0;
  while (limit < k && path_k - keyframes_[limit].path_length >= config_.loops.min_path_gap) ++limit;
  return limit;
}

void GraphSlam::addLoopEdge(size_t j, size_t k, const MatchResult& match, double score) {
  ++stats_.loops_verified;
  const Pose2D pj = graph_.poses()[j];
  GraphEdge e;
  e.from = j;
  e.to = k;
  e.kind = EdgeKind::kLoopClosure;
  e.measurement = wheelchair_core::between(pj, match.pose);
  e.information =
      informationOf(rotateCovariance(match.covariance * config_.loops.covariance_scale, pj.yaw));
  LoopClosure loop;
  loop.from = j;
  loop.to = k;
  loop.score = score;
  loop.goodness = match.goodness;
  loop.edge = graph_.addEdge(e);
  loops_.push_back(loop);
}

void GraphSlam::densifyLoops() {
  const auto start = std::chrono::steady_clock::now();
  const LoopClosureConfig& lc = config_.loops;
  const size_t w = static_cast<size_t>(lc.submap_half_width);
  for (size_t k = 1; k < keyframes_.size(); ++k) {
    const Pose2D pk = graph_.poses()[k];
    const size_t limit = pathGapLimit(k);
    // The nearest keyframe of each earlier pass through the neighbourhood.
    std::vector<std::pair<double, size_t>> near;
    for (size_t j = 0; j < limit; ++j) {
      const Pose2D& pj = graph_.poses()[j];
      const double d = std::hypot(pj.x - pk.x, pj.y - pk.y);
      if (d < lc.final_radius) near.emplace_back(d, j);
    }
    std::sort(near.begin(), near.end());
    std::vector<size_t> chosen;
    for (const auto& [d, j] : near) {
      if (static_cast<int>(chosen.size()) >= lc.final_per_keyframe) break;
      bool same_pass = false;
      for (size_t c : chosen) same_pass |= (j > c ? j - c : c - j) <= 2 * w;
      if (same_pass) continue;
      bool known = false;
      for (const LoopClosure& l : loops_) known |= l.kept && l.to == k && l.from == j;
      if (known) continue;
      chosen.push_back(j);
    }
    for (size_t j : chosen) {
      const size_t first = j > w ? j - w : 0;
      const ReferenceCloud reference(keyframePoints(first, j + w, limit),
                                     config_.matcher.map_voxel);
      const MatchResult m = matcher_.match(reference, keyframes_[k].points, pk, lc.min_goodness);
      const Pose2D shift = wheelchair_core::between(pk, m.pose);
      if (!m.accepted || std::hypot(shift.x, shift.y) > lc.final_max_shift ||
          std::abs(shift.yaw) > lc.window_yaw) {
        continue;
      }
      addLoopEdge(j, k, m, 0.0);
      ++stats_.final_pass_loops;
    }
  }
  stats_.seconds_loops += secondsSince(start);
}

void GraphSlam::optimizeAndPrune() {
  const auto start = std::chrono::steady_clock::now();
  const RobustOptimizeResult r =
      optimizeRejectingFalseLoops(graph_, config_.optimizer_iterations, config_.loops.max_chi2);
  stats_.optimizations += r.optimizations;
  for (size_t edge : r.removed) {
    for (LoopClosure& l : loops_) {
      if (l.edge == edge) l.kept = false;
    }
    ++stats_.loops_removed;
  }
  stats_.seconds_optimizing += secondsSince(start);
}

void GraphSlam::finish() {
  if (graph_.size() < 2) return;
  optimizeAndPrune();
  if (config_.loops.enabled && config_.loops.final_pass) {
    densifyLoops();
    optimizeAndPrune();
  }
}

}  // namespace wheelchair_slam
