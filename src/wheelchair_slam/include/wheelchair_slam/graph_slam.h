// Graph SLAM of a 2-D laser with odometry: each scan matched against a local map of the last
// keyframes (ICP), keyframes as nodes of a pose graph with odometry and scan-match edges whose
// information comes from the match, loop closures found by distance in the optimized graph and
// verified by a correlative search, ICP and a chi2 test after optimization (a closure the rest
// of the graph disagrees with is removed again).
//
// Front end and back end: GraphSlam matches each scan and adds keyframes (the front end); the
// loop closing and optimization (LoopCloser, the back end) work on a KeyframeGraph. Offline both
// run in addScan, one after the other. Live (live_slam.h) the back end works on a copy of the
// graph on its own thread and its result is merged back, so a scan never waits for a loop
// search or an optimization.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_slam/icp_matcher.h>
#include <wheelchair_slam/pose_graph.h>
#include <wheelchair_slam/scan_points.h>
#include <wheelchair_slam/slam_config.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace wheelchair_slam {

struct LoopClosure {
  size_t from = 0, to = 0;  ///< keyframes (older, newer)
  double score = 0.0;       ///< correlative score
  double goodness = 0.0;    ///< ICP goodness
  bool kept = true;         ///< false: removed by the chi2 test
  size_t edge = 0;          ///< index in the graph's edges
};

/// How one scan was matched (for diagnosis: slam writes them to matches.csv).
struct ScanMatchInfo {
  bool matched = false;  ///< false: the match was refused and odometry used
  bool keyframe = false;
  double goodness = 0.0, inliers = 0.0;
  double sigma_x = 0.0, sigma_y = 0.0, sigma_yaw = 0.0;  ///< of the match, map frame
  wheelchair_core::Pose2D correction;  ///< matched pose seen from the odometry's prediction
};

struct SlamStats {
  size_t scans = 0, keyframes = 0, match_failures = 0;
  size_t loop_attempts = 0, loops_verified = 0, loops_removed = 0, optimizations = 0;
  size_t final_pass_loops = 0;  ///< of loops_verified, found by the final pass
  size_t drives = 1;            ///< drives joined in one graph (a continued map: 2 or more)
  double seconds_matching = 0.0, seconds_loops = 0.0, seconds_optimizing = 0.0;
};

/// A node of the pose graph: a scan kept for matching and loop closing.
struct Keyframe {
  size_t scan = 0;  ///< index of its scan among all scans added
  /// Its returns in the sensor frame; never changed, so copies of the graph share them.
  std::shared_ptr<const Points> points;
  /// Travelled from the first scan [m]; a new drive starts past every older keyframe.
  double path_length = 0.0;
  wheelchair_core::Pose2D odometry;
  size_t drive = 0;  ///< 0: the first drive; the drives of a continued map count on
};

/// Each scan's place in the graph.
struct ScanRecord {
  size_t keyframe = 0;               ///< the keyframe (graph node) it is attached to
  wheelchair_core::Pose2D relative;  ///< its pose in that keyframe's frame
  wheelchair_core::Pose2D odometry;  ///< the odometry at the scan
  double stamp = 0.0;
};

/// The back end's state: the keyframes, their pose graph and its loop closures. A copy is
/// cheap (the keyframes' points are shared), so the live back end works on one.
struct KeyframeGraph {
  PoseGraph graph;
  std::vector<Keyframe> keyframes;
  std::vector<LoopClosure> loops;
};

/// The points of keyframes first..last (and before exclude_from) in the map frame.
Points keyframePoints(const KeyframeGraph& g, size_t first, size_t last, size_t exclude_from);

/// Up to `count` keyframes within `radius` of `at`, nearest first.
std::vector<size_t> nearestKeyframes(const KeyframeGraph& g, const wheelchair_core::Pose2D& at,
                                     double radius, size_t count);

/// Where a new drive's first scan lies among the keyframes of a map (LoopCloser::locate).
struct DriveStart {
  bool located = false;
  wheelchair_core::Pose2D pose;  ///< the scan's pose in the map frame
  size_t anchor = 0;             ///< the nearest keyframe of the submap it was matched against
  std::vector<size_t> submap;    ///< the keyframes it was matched against
  MatchResult match;
  double score = 0.0;  ///< correlative score
};

/// The back end: loop closures (candidates by distance, correlative search, ICP, agreement),
/// optimization with the chi2 test against false closures, the final pass of dense closures.
/// Each call only reads and changes the graph it is given. Not thread-safe itself (one MRPT ICP
/// object): the live mode gives the back end a LoopCloser of its own.
class LoopCloser {
 public:
  explicit LoopCloser(const SlamConfig& config);
  ~LoopCloser();

  /// Looks for a closure of keyframe k with an older place; when one is verified it is added
  /// and the graph optimized (optimizeAndPrune). Returns whether one was added.
  bool closeLoop(KeyframeGraph& g, size_t k, SlamStats& stats) const;
  /// Optimizes, removing the closures the rest of the graph disagrees with (chi2 test).
  void optimizeAndPrune(KeyframeGraph& g, SlamStats& stats) const;
  /// The final pass of loop closures (LoopClosureConfig::final_pass): every keyframe matched
  /// against up to final_per_keyframe earlier passes within final_radius.
  void densifyLoops(KeyframeGraph& g, SlamStats& stats) const;
  /// Locates `points` (a scan in the sensor frame) among the 2 submap_half_width + 1 keyframes
  /// nearest `guess` within loops.search_radius (nearestKeyframes): correlative search over the
  /// loop window, refined by ICP, accepted on the loop closures' score, goodness and agreement.
  DriveStart locate(const KeyframeGraph& g, const Points& points,
                    const wheelchair_core::Pose2D& guess) const;

 private:
  size_t pathGapLimit(const KeyframeGraph& g, size_t k) const;
  void addLoopEdge(KeyframeGraph& g, size_t j, size_t k, const MatchResult& match, double score,
                   SlamStats& stats) const;

  SlamConfig config_;
  IcpMatcher matcher_;
};

class GraphSlam {
 public:
  /// Throws wheelchair_core::ConfigError for an invalid configuration.
  explicit GraphSlam(const SlamConfig& config);
  /// Continues a saved map (slam_session.h): its keyframes, graph and scans. The next scan
  /// starts a new drive (startDrive; without it, at mapToOdom() of the saved drive).
  GraphSlam(const SlamConfig& config, KeyframeGraph graph, std::vector<ScanRecord> scans);
  ~GraphSlam();

  /// The next scan starts a new drive (a continued map, a restarted chair) near `guess` in the
  /// map frame: it is located among the keyframes there (LoopCloser::locate) and joined to the
  /// graph by that match instead of by odometry.
  void startDrive(const wheelchair_core::Pose2D& guess);
  /// Adds a scan with the odometry pose at its time; returns the scan's estimated pose, or
  /// nullopt (nothing added) when it starts a drive and could not be located in the map.
  std::optional<wheelchair_core::Pose2D> addScan(const wheelchair_core::LaserScan2D& scan,
                                                 const wheelchair_core::Pose2D& odometry);
  /// Final optimization and consistency check.
  void finish();

  /// Live mode: addScan queues the keyframes due for a loop search (takeLoopRequests) instead
  /// of searching; a back end searches on a copy of keyframeGraph() and mergeBackEnd() takes
  /// its result.
  void setDeferLoops(bool defer) { defer_loops_ = defer; }
  std::vector<size_t> takeLoopRequests();
  const KeyframeGraph& keyframeGraph() const { return state_; }
  /// The back end's graph, copied from keyframeGraph() when it had `nodes` keyframes and
  /// `edges` edges: the keyframes added since are moved with the newest one it knew (their
  /// relative poses kept), the edges added since are appended.
  void mergeBackEnd(KeyframeGraph worked, size_t nodes, size_t edges, const SlamStats& stats);

  /// The estimated pose of every scan added, in order.
  std::vector<wheelchair_core::Pose2D> trajectory() const;
  /// The estimated pose of the last scan added (the identity before the first).
  wheelchair_core::Pose2D lastPose() const;
  /// map -> odometry frame of the current drive: last scan's pose (+) its odometry^-1.
  wheelchair_core::Pose2D mapToOdom() const;
  const std::vector<double>& stamps() const { return stamps_; }
  const std::vector<ScanRecord>& scanRecords() const { return scans_; }
  const PoseGraph& graph() const { return state_.graph; }
  /// The scan index of each keyframe (graph node).
  std::vector<size_t> keyframeScans() const;
  const std::vector<LoopClosure>& loopClosures() const { return state_.loops; }
  const SlamStats& stats() const { return stats_; }
  const std::vector<ScanMatchInfo>& matchInfo() const { return match_info_; }
  const SlamConfig& config() const { return config_; }
  /// Whether the next scan starts a drive that must be located first.
  bool awaitingDriveStart() const { return drive_start_.has_value(); }

 private:
  wheelchair_core::Pose2D scanPose(size_t index) const;
  void addKeyframe(size_t scan, const wheelchair_core::Pose2D& pose,
                   const wheelchair_core::Pose2D& odometry, Points points, const MatchResult* match,
                   const DriveStart* start);
  std::optional<wheelchair_core::Pose2D> addFirstScanOfDrive(
      const wheelchair_core::LaserScan2D& scan, const wheelchair_core::Pose2D& odometry,
      Points points);
  void rebuildLocalMap();
  Eigen::Matrix3d odometryInformation(const wheelchair_core::Pose2D& motion) const;

  SlamConfig config_;
  IcpMatcher matcher_;
  LoopCloser closer_;
  KeyframeGraph state_;
  std::vector<ScanRecord> scans_;
  std::vector<ScanMatchInfo> match_info_;
  std::vector<double> stamps_;
  ReferenceCloud local_map_;
  wheelchair_core::Pose2D last_odometry_;
  double path_length_ = 0.0;
  SlamStats stats_;
  bool defer_loops_ = false;
  std::vector<size_t> loop_requests_;
  /// Set: the next scan starts a drive there (or, drive_start_is_map_to_odom_, at this map ->
  /// odom composed with its odometry).
  std::optional<wheelchair_core::Pose2D> drive_start_;
  bool drive_start_is_map_to_odom_ = false;
  size_t drive_ = 0;
  size_t drive_first_keyframe_ = 0;
  /// The keyframes a drive's first scan was located against: part of the local map until the
  /// drive has keyframes enough of its own.
  std::vector<size_t> drive_submap_;
};

}  // namespace wheelchair_slam
