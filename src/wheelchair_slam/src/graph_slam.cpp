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

Points everySecond(const Points& points) {
  Points sparse;
  for (size_t i = 0; i < points.size(); i += 2) sparse.push_back(points[i]);
  return sparse;
}

SearchWindow loopWindow(const LoopClosureConfig& lc) {
  SearchWindow window;
  window.xy = lc.window_xy;
  window.yaw = lc.window_yaw;
  window.step_yaw = lc.search_step_yaw;
  return window;
}

/// The correlative search's pose refined by ICP, and whether the two agree.
bool refinedAgrees(const LoopClosureConfig& lc, const SearchResult& found,
                   const MatchResult& refined) {
  const Pose2D shift = wheelchair_core::between(found.pose, refined.pose);
  return refined.accepted && std::hypot(shift.x, shift.y) < 3 * lc.grid_resolution &&
         std::abs(shift.yaw) < 3 * lc.search_step_yaw;
}

}  // namespace

Points keyframePoints(const KeyframeGraph& g, size_t first, size_t last, size_t exclude_from) {
  Points out;
  for (size_t k = first; k <= last && k < g.keyframes.size() && k < exclude_from; ++k) {
    appendTransformed(*g.keyframes[k].points, g.graph.poses()[k], out);
  }
  return out;
}

// ---- the back end -------------------------------------------------------------------------

LoopCloser::LoopCloser(const SlamConfig& config)
    : config_(validated(config)), matcher_(config.matcher) {}

LoopCloser::~LoopCloser() = default;

size_t LoopCloser::pathGapLimit(const KeyframeGraph& g, size_t k) const {
  const double path_k = g.keyframes[k].path_length;
  size_t limit = 0;
  while (limit < k && path_k - g.keyframes[limit].path_length >= config_.loops.min_path_gap)
    ++limit;
  return limit;
}

bool LoopCloser::closeLoop(KeyframeGraph& g, size_t k, SlamStats& stats) const {
  const auto start = std::chrono::steady_clock::now();
  const LoopClosureConfig& lc = config_.loops;
  const Pose2D pk = g.graph.poses()[k];
  size_t best = k;
  double best_d = lc.search_radius;
  const size_t limit = pathGapLimit(g, k);
  for (size_t j = 0; j < limit; ++j) {
    const Pose2D& pj = g.graph.poses()[j];
    const double d = std::hypot(pj.x - pk.x, pj.y - pk.y);
    if (d < best_d) {
      best_d = d;
      best = j;
    }
  }
  if (best == k) {
    stats.seconds_loops += secondsSince(start);
    return false;
  }
  ++stats.loop_attempts;
  const size_t w = static_cast<size_t>(lc.submap_half_width);
  const size_t first = best > w ? best - w : 0;
  const Points submap = keyframePoints(g, first, best + w, limit);
  const Points& scan = *g.keyframes[k].points;
  const LikelihoodGrid grid(submap, lc.grid_resolution, lc.grid_resolution);
  const SearchResult found = correlativeSearch(grid, everySecond(scan), pk, loopWindow(lc));
  if (found.score < lc.min_score) {
    stats.seconds_loops += secondsSince(start);
    return false;
  }
  const ReferenceCloud reference(submap, config_.matcher.map_voxel);
  const MatchResult refined = matcher_.match(reference, scan, found.pose, lc.min_goodness);
  if (!refinedAgrees(lc, found, refined)) {
    stats.seconds_loops += secondsSince(start);
    return false;
  }
  addLoopEdge(g, best, k, refined, found.score, stats);
  stats.seconds_loops += secondsSince(start);
  optimizeAndPrune(g, stats);
  return true;
}

std::vector<size_t> nearestKeyframes(const KeyframeGraph& g, const Pose2D& at, double radius,
                                     size_t count) {
  std::vector<std::pair<double, size_t>> near;
  for (size_t j = 0; j < g.keyframes.size() && j < g.graph.size(); ++j) {
    const Pose2D& pj = g.graph.poses()[j];
    const double d = std::hypot(pj.x - at.x, pj.y - at.y);
    if (d < radius) near.emplace_back(d, j);
  }
  std::sort(near.begin(), near.end());
  std::vector<size_t> out;
  for (size_t i = 0; i < near.size() && i < count; ++i) out.push_back(near[i].second);
  return out;
}

DriveStart LoopCloser::locate(const KeyframeGraph& g, const Points& points,
                              const Pose2D& guess) const {
  const LoopClosureConfig& lc = config_.loops;
  DriveStart out;
  out.pose = guess;
  // The keyframes nearest the predicted start, whichever drive and place in the graph's order
  // they have: a continued map's index neighbours of the nearest keyframe may be another
  // drive's, elsewhere (the study's session 6 was never placed so).
  out.submap = nearestKeyframes(g, guess, lc.search_radius,
                                2 * static_cast<size_t>(lc.submap_half_width) + 1);
  if (out.submap.empty()) return out;
  out.anchor = out.submap.front();
  Points submap;
  for (size_t j : out.submap) appendTransformed(*g.keyframes[j].points, g.graph.poses()[j], submap);
  const LikelihoodGrid grid(submap, lc.grid_resolution, lc.grid_resolution);
  const SearchResult found = correlativeSearch(grid, everySecond(points), guess, loopWindow(lc));
  out.score = found.score;
  if (found.score < lc.min_score) return out;
  const ReferenceCloud reference(submap, config_.matcher.map_voxel);
  out.match = matcher_.match(reference, points, found.pose, lc.min_goodness);
  if (!refinedAgrees(lc, found, out.match)) return out;
  out.pose = out.match.pose;
  out.located = true;
  return out;
}

void LoopCloser::addLoopEdge(KeyframeGraph& g, size_t j, size_t k, const MatchResult& match,
                             double score, SlamStats& stats) const {
  ++stats.loops_verified;
  const Pose2D pj = g.graph.poses()[j];
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
  loop.edge = g.graph.addEdge(e);
  g.loops.push_back(loop);
}

void LoopCloser::densifyLoops(KeyframeGraph& g, SlamStats& stats) const {
  const auto start = std::chrono::steady_clock::now();
  const LoopClosureConfig& lc = config_.loops;
  const size_t w = static_cast<size_t>(lc.submap_half_width);
  for (size_t k = 1; k < g.keyframes.size(); ++k) {
    const Pose2D pk = g.graph.poses()[k];
    const size_t limit = pathGapLimit(g, k);
    // The nearest keyframe of each earlier pass through the neighbourhood.
    std::vector<std::pair<double, size_t>> near;
    for (size_t j = 0; j < limit; ++j) {
      const Pose2D& pj = g.graph.poses()[j];
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
      for (const LoopClosure& l : g.loops) known |= l.kept && l.to == k && l.from == j;
      if (known) continue;
      chosen.push_back(j);
    }
    for (size_t j : chosen) {
      const size_t first = j > w ? j - w : 0;
      const ReferenceCloud reference(keyframePoints(g, first, j + w, limit),
                                     config_.matcher.map_voxel);
      const MatchResult m = matcher_.match(reference, *g.keyframes[k].points, pk, lc.min_goodness);
      const Pose2D shift = wheelchair_core::between(pk, m.pose);
      if (!m.accepted || std::hypot(shift.x, shift.y) > lc.final_max_shift ||
          std::abs(shift.yaw) > lc.window_yaw) {
        continue;
      }
      addLoopEdge(g, j, k, m, 0.0, stats);
      ++stats.final_pass_loops;
    }
  }
  stats.seconds_loops += secondsSince(start);
}

void LoopCloser::optimizeAndPrune(KeyframeGraph& g, SlamStats& stats) const {
  const auto start = std::chrono::steady_clock::now();
  const RobustOptimizeResult r =
      optimizeRejectingFalseLoops(g.graph, config_.optimizer_iterations, config_.loops.max_chi2);
  stats.optimizations += r.optimizations;
  for (size_t edge : r.removed) {
    for (LoopClosure& l : g.loops) {
      if (l.edge == edge) l.kept = false;
    }
    ++stats.loops_removed;
  }
  stats.seconds_optimizing += secondsSince(start);
}

// ---- the front end ------------------------------------------------------------------------

GraphSlam::GraphSlam(const SlamConfig& config)
    : config_(validated(config)), matcher_(config.matcher), closer_(config) {}

GraphSlam::GraphSlam(const SlamConfig& config, KeyframeGraph graph, std::vector<ScanRecord> scans)
    : GraphSlam(config) {
  state_ = std::move(graph);
  scans_ = std::move(scans);
  if (state_.keyframes.empty() || scans_.empty()) return;
  for (const ScanRecord& r : scans_) stamps_.push_back(r.stamp);
  match_info_.resize(scans_.size());
  for (const Keyframe& k : state_.keyframes) match_info_[k.scan].keyframe = true;
  last_odometry_ = scans_.back().odometry;
  path_length_ = state_.keyframes.back().path_length;
  drive_ = state_.keyframes.back().drive;
  stats_.scans = scans_.size();
  stats_.keyframes = state_.keyframes.size();
  stats_.drives = drive_ + 1;
  for (const LoopClosure& l : state_.loops) stats_.loops_verified += l.kept;
  // The saved drive's map -> odom until startDrive says otherwise (the odometry goes on).
  drive_start_ = mapToOdom();
  drive_start_is_map_to_odom_ = true;
}

GraphSlam::~GraphSlam() = default;

Pose2D GraphSlam::scanPose(size_t index) const {
  const ScanRecord& r = scans_[index];
  return wheelchair_core::compose(state_.graph.poses()[r.keyframe], r.relative);
}

std::vector<Pose2D> GraphSlam::trajectory() const {
  std::vector<Pose2D> out;
  out.reserve(scans_.size());
  for (size_t i = 0; i < scans_.size(); ++i) out.push_back(scanPose(i));
  return out;
}

Pose2D GraphSlam::lastPose() const {
  return scans_.empty() ? Pose2D{} : scanPose(scans_.size() - 1);
}

Pose2D GraphSlam::mapToOdom() const {
  if (scans_.empty()) return Pose2D{};
  return wheelchair_core::compose(lastPose(), wheelchair_core::inverse(last_odometry_));
}

std::vector<size_t> GraphSlam::keyframeScans() const {
  std::vector<size_t> out;
  for (const Keyframe& k : state_.keyframes) out.push_back(k.scan);
  return out;
}

std::vector<size_t> GraphSlam::takeLoopRequests() {
  std::vector<size_t> out;
  out.swap(loop_requests_);
  return out;
}

void GraphSlam::startDrive(const Pose2D& guess) {
  drive_start_ = guess;
  drive_start_is_map_to_odom_ = false;
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

void GraphSlam::rebuildLocalMap() {
  const size_t n = state_.keyframes.size();
  const size_t width = static_cast<size_t>(config_.matcher.local_map_keyframes);
  size_t first = n > width ? n - width : 0;
  first = std::max(first, drive_first_keyframe_);
  Points points = keyframePoints(state_, first, n - 1, n);
  if (n - drive_first_keyframe_ < width) {  // a young drive: also the map where it started
    for (size_t k : drive_submap_)
      appendTransformed(*state_.keyframes[k].points, state_.graph.poses()[k], points);
  }
  local_map_ = ReferenceCloud(points, config_.matcher.map_voxel);
}

std::optional<Pose2D> GraphSlam::addScan(const wheelchair_core::LaserScan2D& scan,
                                         const Pose2D& odometry) {
  const auto start = std::chrono::steady_clock::now();
  Points points = scanPoints(scan, config_.matcher.max_range, config_.matcher.point_spacing);
  if (drive_start_ || state_.keyframes.empty()) {
    std::optional<Pose2D> pose = addFirstScanOfDrive(scan, odometry, std::move(points));
    stats_.seconds_matching += secondsSince(start);
    return pose;
  }
  stamps_.push_back(scan.stamp);
  ++stats_.scans;
  const size_t index = scans_.size();
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
  const size_t kf = state_.keyframes.size() - 1;
  const Pose2D kf_pose = state_.graph.poses()[kf];
  const Pose2D from_kf = wheelchair_core::between(kf_pose, match.pose);
  const bool new_keyframe = std::hypot(from_kf.x, from_kf.y) >= config_.keyframes.distance ||
                            std::abs(from_kf.yaw) >= config_.keyframes.angle;
  stats_.seconds_matching += secondsSince(start);
  info.keyframe = new_keyframe;
  match_info_.push_back(info);
  if (!new_keyframe) {
    scans_.push_back({kf, from_kf, odometry, scan.stamp});
    return match.pose;
  }
  scans_.push_back({kf + 1, Pose2D{}, odometry, scan.stamp});
  addKeyframe(index, match.pose, odometry, std::move(points), match.accepted ? &match : nullptr,
              nullptr);
  return scanPose(index);
}

std::optional<Pose2D> GraphSlam::addFirstScanOfDrive(const wheelchair_core::LaserScan2D& scan,
                                                     const Pose2D& odometry, Points points) {
  Pose2D guess = odometry;  // a first drive without a start: the map frame is the odometry's
  if (drive_start_) {
    guess = drive_start_is_map_to_odom_ ? wheelchair_core::compose(*drive_start_, odometry)
                                        : *drive_start_;
  }
  DriveStart located;
  located.pose = guess;
  if (!state_.keyframes.empty()) {
    located = closer_.locate(state_, points, guess);
    if (!located.located) return std::nullopt;
    ++drive_;
    ++stats_.drives;
    // Every older keyframe is "far back along the path": loop candidates from the start.
    path_length_ = state_.keyframes.back().path_length + config_.loops.min_path_gap;
  }
  drive_start_.reset();
  stamps_.push_back(scan.stamp);
  ++stats_.scans;
  const size_t index = scans_.size();
  drive_first_keyframe_ = state_.keyframes.size();
  drive_submap_ = located.submap;
  scans_.push_back({drive_first_keyframe_, Pose2D{}, odometry, scan.stamp});
  ScanMatchInfo info;
  info.keyframe = true;
  info.matched = located.located;
  info.goodness = located.match.goodness;
  info.inliers = located.match.inliers;
  info.correction = wheelchair_core::between(guess, located.pose);
  match_info_.push_back(info);
  last_odometry_ = odometry;
  addKeyframe(index, located.pose, odometry, std::move(points), nullptr,
              located.located ? &located : nullptr);
  return located.pose;
}

void GraphSlam::addKeyframe(size_t scan, const Pose2D& pose, const Pose2D& odometry, Points points,
                            const MatchResult* match, const DriveStart* start) {
  const size_t node = state_.graph.addNode(pose);
  state_.keyframes.push_back(
      {scan, std::make_shared<const Points>(std::move(points)), path_length_, odometry, drive_});
  ++stats_.keyframes;
  if (start) {
    // A new drive joins the graph where it was located (never removed: it holds the drive).
    const Pose2D anchor = state_.graph.poses()[start->anchor];
    GraphEdge m;
    m.from = start->anchor;
    m.to = node;
    m.kind = EdgeKind::kScanMatch;
    m.measurement = wheelchair_core::between(anchor, pose);
    m.information = informationOf(
        rotateCovariance(start->match.covariance * config_.loops.covariance_scale, anchor.yaw));
    state_.graph.addEdge(m);
  } else if (node > 0 && state_.keyframes[node - 1].drive == drive_) {
    const Keyframe& prev = state_.keyframes[node - 1];
    const Pose2D prev_pose = state_.graph.poses()[node - 1];
    GraphEdge odo;
    odo.from = node - 1;
    odo.to = node;
    odo.kind = EdgeKind::kOdometry;
    odo.measurement = wheelchair_core::between(prev.odometry, odometry);
    odo.information = odometryInformation(odo.measurement);
    state_.graph.addEdge(odo);
    if (match) {
      GraphEdge m;
      m.from = node - 1;
      m.to = node;
      m.kind = EdgeKind::kScanMatch;
      m.measurement = wheelchair_core::between(prev_pose, pose);
      m.information = informationOf(
          rotateCovariance(match->covariance * config_.match_covariance_scale, prev_pose.yaw));
      state_.graph.addEdge(m);
    }
  }
  if (config_.loops.enabled && node > 0 &&
      node % static_cast<size_t>(config_.loops.every_n_keyframes) == 0) {
    if (defer_loops_) {
      loop_requests_.push_back(node);
    } else {
      closer_.closeLoop(state_, node, stats_);
    }
  }
  rebuildLocalMap();
}

void GraphSlam::mergeBackEnd(KeyframeGraph worked, size_t nodes, size_t edges,
                             const SlamStats& back_end) {
  const size_t n_now = state_.graph.size();
  if (nodes > 0 && n_now > nodes) {
    const Pose2D anchor_before = state_.graph.poses()[nodes - 1];
    const Pose2D anchor_after = worked.graph.poses()[nodes - 1];
    for (size_t i = nodes; i < n_now; ++i) {
      worked.graph.addNode(wheelchair_core::compose(
          anchor_after, wheelchair_core::between(anchor_before, state_.graph.poses()[i])));
      worked.keyframes.push_back(state_.keyframes[i]);
    }
  }
  for (size_t e = edges; e < state_.graph.edges().size(); ++e) {
    worked.graph.addEdge(state_.graph.edges()[e]);
  }
  state_ = std::move(worked);
  stats_.loop_attempts += back_end.loop_attempts;
  stats_.loops_verified += back_end.loops_verified;
  stats_.loops_removed += back_end.loops_removed;
  stats_.optimizations += back_end.optimizations;
  stats_.final_pass_loops += back_end.final_pass_loops;
  stats_.seconds_loops += back_end.seconds_loops;
  stats_.seconds_optimizing += back_end.seconds_optimizing;
  rebuildLocalMap();
}

void GraphSlam::finish() {
  if (state_.graph.size() < 2) return;
  closer_.optimizeAndPrune(state_, stats_);
  if (config_.loops.enabled && config_.loops.final_pass) {
    closer_.densifyLoops(state_, stats_);
    closer_.optimizeAndPrune(state_, stats_);
  }
  rebuildLocalMap();
}

}  // namespace wheelchair_slam
