// The pose graph of the keyframes: nodes are keyframe poses, edges relative poses with their
// information matrices (odometry, scan matching, loop closures). Optimized with MRPT's sparse
// pose adjustment (mrpt::graphslam::optimize_graph_spa_levmarq on a CNetworkOfPoses2DInf).
#pragma once

#include <wheelchair_core/pose2d.h>
#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace wheelchair_slam {

enum class EdgeKind { kOdometry, kScanMatch, kLoopClosure };

struct GraphEdge {
  size_t from = 0, to = 0;
  wheelchair_core::Pose2D measurement;  ///< pose of `to` in the frame of `from`
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();  ///< of (x, y, yaw) of measurement
  EdgeKind kind = EdgeKind::kScanMatch;
  bool active = true;  ///< an inactive edge (a rejected loop closure) is not optimized
};

struct OptimizeResult {
  size_t iterations = 0;
  double initial_chi2 = 0.0, final_chi2 = 0.0;
};

/// The residual of `edge` for poses a (from) and b (to): measurement^-1 (+) (a^-1 (+) b).
Eigen::Vector3d edgeResidual(const GraphEdge& edge, const wheelchair_core::Pose2D& a,
                             const wheelchair_core::Pose2D& b);

/// The covariance of a pose given in the parent frame, seen in the frame rotated by `yaw`
/// (a relative measurement's covariance from an absolute match).
Eigen::Matrix3d rotateCovariance(const Eigen::Matrix3d& covariance, double yaw);

class PoseGraph {
 public:
  size_t addNode(const wheelchair_core::Pose2D& pose);
  size_t addEdge(const GraphEdge& edge);
  /// Keeps the edge (indices stay valid) but leaves it out of the optimization.
  void deactivateEdge(size_t index) { edges_[index].active = false; }
  /// Node 0 stays fixed.
  OptimizeResult optimize(int max_iterations);
  double chi2(size_t edge_index) const;
  /// The nodes and active edges in g2o's text format (VERTEX_SE2 / EDGE_SE2 lines, MRPT's
  /// saveToTextFile). Throws std::runtime_error naming the file on failure.
  void save(const std::string& path) const;
  /// Sum over the active edges.
  double totalChi2() const;

  const std::vector<wheelchair_core::Pose2D>& poses() const { return poses_; }
  const std::vector<GraphEdge>& edges() const { return edges_; }
  size_t size() const { return poses_.size(); }
  void setPose(size_t node, const wheelchair_core::Pose2D& pose) { poses_[node] = pose; }

 private:
  std::vector<wheelchair_core::Pose2D> poses_;
  std::vector<GraphEdge> edges_;
};

struct RobustOptimizeResult {
  std::vector<size_t> removed;  ///< loop-closure edges deactivated, in the order removed
  size_t optimizations = 0;
};

/// Optimizes, then while the active loop-closure edge with the largest chi2 exceeds `max_chi2`
/// (the rest of the graph disagrees with it: a false closure), deactivates it and optimizes
/// again. Odometry and scan-match edges are never removed.
RobustOptimizeResult optimizeRejectingFalseLoops(PoseGraph& graph, int max_iterations,
                                                 double max_chi2);

}  // namespace wheelchair_slam
