// Every setting of the SLAM core in one struct, with its defaults in the declaration: how
// scans are matched, when a scan becomes a keyframe, how odometry is trusted, how loops are
// found and verified, and how the final grid is built. readSlamConfig() names every key, so the
// offline tool (YAML) and the live nodelet (ROS parameters) read the same keys.
#pragma once

#include <wheelchair_core/config.h>

#include <string>

namespace wheelchair_slam {

/// Scan-to-map matching (MRPT's ICP, point-to-point, on point maps).
struct MatcherConfig {
  double max_range = 25.0;          ///< returns farther than this are not matched [m]
  double point_spacing = 0.05;      ///< scan points closer than this to the previous are dropped
  int local_map_keyframes = 12;     ///< the local map is built from this many last keyframes
  double map_voxel = 0.05;          ///< reference points averaged per cell of this [m] (0: not)
  double icp_threshold_dist = 0.4;  ///< initial pairing distance [m]
  double icp_threshold_ang = 0.02;  ///< pairing distance grows by this per metre of range [rad]
  double icp_smallest_dist = 0.04;  ///< ICP stops refining below this pairing distance [m]
  double icp_alfa = 0.6;            ///< pairing distance factor after each convergence
  int icp_max_iterations = 80;
  double min_goodness = 0.5;  ///< fraction of paired points below which a match is refused
  /// Standard deviation of one point's position that scales the ICP covariance [m].
  double point_sigma = 0.03;
  bool refine = true;                ///< point-to-line refinement after MRPT's ICP
  double refine_max_distance = 0.2;  ///< its pairing distance [m]
  double refine_kernel = 0.05;       ///< its Cauchy kernel width [m]
  std::string validate() const;
};

/// When a scan becomes a node of the pose graph.
struct KeyframeConfig {
  double distance = 0.25;  ///< travelled since the last keyframe [m]
  double angle = 0.2;      ///< turned since the last keyframe [rad]
  std::string validate() const;
};

/// Odometry's uncertainty (each odometry edge's covariance grows with the motion).
struct OdometryNoise {
  double sigma_xy_per_m = 0.1;     ///< [m per m travelled]
  double sigma_yaw_per_rad = 0.1;  ///< [rad per rad turned]
  double sigma_yaw_per_m = 0.05;   ///< [rad per m travelled]
  double sigma_xy_floor = 0.01;    ///< [m]
  double sigma_yaw_floor = 0.005;  ///< [rad]
  std::string validate() const;
};

/// Loop closures: candidates by distance in the optimized graph, verified by a correlative
/// search then ICP, kept only if consistent with the rest of the graph after optimization.
struct LoopClosureConfig {
  bool enabled = true;
  double search_radius = 4.0;      ///< candidate keyframes within this of the new one [m]
  double min_path_gap = 6.0;       ///< ... and at least this far back along the path [m]
  int submap_half_width = 5;       ///< the candidate's submap: this many keyframes either side
  double window_xy = 1.0;          ///< correlative search half width [m]
  double window_yaw = 0.25;        ///< correlative search half width [rad]
  double search_step_yaw = 0.015;  ///< [rad]
  double grid_resolution = 0.05;   ///< correlative grid cell [m]
  double min_score = 0.55;         ///< correlative score (mean likelihood of the points), 0..1
  double min_goodness = 0.65;      ///< ICP goodness of the refined match
  int every_n_keyframes = 2;       ///< attempt on every n-th keyframe
  /// An accepted closure whose chi2 (3 dof) after optimization exceeds this is removed.
  double max_chi2 = 16.27;  ///< 99.9 % of chi2(3)
  /// The loop edge's covariance is the ICP covariance times this (ambiguity of a far match).
  double covariance_scale = 4.0;
  /// At the end, every keyframe is matched (ICP from the optimized graph) against the submaps
  /// of up to final_per_keyframe earlier places within final_radius: the dense closures a
  /// drive's one pass of loop detection misses.
  bool final_pass = true;
  double final_radius = 2.0;  ///< [m]
  int final_per_keyframe = 2;
  double final_max_shift = 0.3;  ///< a match that moves the keyframe more than this is refused [m]
  std::string validate() const;
};

struct SlamConfig {
  MatcherConfig matcher;
  KeyframeConfig keyframes;
  OdometryNoise odometry;
  LoopClosureConfig loops;
  /// Scan-match edges: ICP covariance times this (ICP is over-confident on real scans).
  double match_covariance_scale = 2.0;
  int optimizer_iterations = 50;
  /// Scan matching is held to the odometry's prediction with the odometry's information where
  /// the scan does not constrain the pose.
  bool odometry_prior = false;
  std::string validate() const;
};

/// Names every key of SlamConfig ("matcher/max_range", "loops/search_radius", ...).
void readSlamConfig(wheelchair_core::ConfigReader& reader, SlamConfig& config);

}  // namespace wheelchair_slam
