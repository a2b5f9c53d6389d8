// Graph SLAM of a 2-D laser with odometry: each scan matched against a local map of the last
// keyframes (ICP), keyframes as nodes of a pose graph with odometry and scan-match edges whose
// information comes from the match, loop closures found by distance in the optimized graph and
// verified by a correlative search, ICP and a chi2 test after optimization (a closure the rest
// of the graph disagrees with is removed again).
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_slam/icp_matcher.h>
#include <wheelchair_slam/pose_graph.h>
#include <wheelchair_slam/scan_points.h>
#include <wheelchair_slam/slam_config.h>

#include <cstddef>
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
  double seconds_matching = 0.0, seconds_loops = 0.0, seconds_optimizing = 0.0;
};

class GraphSlam {
 public:
  /// Throws wheelchair_core::ConfigError for an invalid configuration.
  explicit GraphSlam(const SlamConfig& config);

  /// Adds a scan with the odometry pose at its time; returns the scan's estimated pose.
  wheelchair_core::Pose2D addScan(const wheelchair_core::LaserScan2D& scan,
                                  const wheelchair_core::Pose2D& odometry);
  /// Final optimization and consistency check.
  void finish();

  /// The estimated pose of every scan added, in order.
  std::vector<wheelchair_core::Pose2D> trajectory() const;
  const std::vector<double>& stamps() const { return stamps_; }
  const PoseGraph& graph() const { return graph_; }
  /// The scan index of each keyframe (graph node).
  std::vector<size_t> keyframeScans() const;
  const std::vector<LoopClosure>& loopClosures() const { return loops_; }
  const SlamStats& stats() const { return stats_; }
  const std::vector<ScanMatchInfo>& matchInfo() const { return match_info_; }

 private:
  struct Keyframe {
    size_t scan = 0;
    Points points;             ///< sensor frame
    double path_length = 0.0;  ///< travelled from the first scan [m]
    wheelchair_core::Pose2D odometry;
  };
  struct ScanRecord {
    size_t keyframe = 0;
    wheelchair_core::Pose2D relative;  ///< pose in the keyframe's frame
  };

  wheelchair_core::Pose2D scanPose(size_t index) const;
  void addKeyframe(size_t scan, const wheelchair_core::Pose2D& pose,
                   const wheelchair_core::Pose2D& odometry, Points points,
                   const MatchResult* match);
  void rebuildLocalMap();
  void tryLoopClosure(size_t keyframe);
  Points keyframePoints(size_t first, size_t last, size_t exclude_from) const;
  void optimizeAndPrune();
  /// The final pass of loop closures (LoopClosureConfig::final_pass).
  void densifyLoops();
  /// Keyframes before the returned index are at least min_path_gap back along the path from k.
  size_t pathGapLimit(size_t k) const;
  /// Adds a verified closure from keyframe j to k at k's matched pose.
  void addLoopEdge(size_t j, size_t k, const MatchResult& match, double score);
  Eigen::Matrix3d odometryInformation(const wheelchair_core::Pose2D& motion) const;

  SlamConfig config_;
  IcpMatcher matcher_;
  PoseGraph graph_;
  std::vector<Keyframe> keyframes_;
  std::vector<ScanRecord> scans_;
  std::vector<ScanMatchInfo> match_info_;
  std::vector<double> stamps_;
  std::vector<LoopClosure> loops_;
  ReferenceCloud local_map_;
  wheelchair_core::Pose2D last_odometry_;
  double path_length_ = 0.0;
  SlamStats stats_;
};

}  // namespace wheelchair_slam
