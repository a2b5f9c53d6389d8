#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/graphslam/levmarq.h>
#include <wheelchair_slam/pose_graph.h>

#include <stdexcept>

namespace wheelchair_slam {

using wheelchair_core::Pose2D;

Eigen::Vector3d edgeResidual(const GraphEdge& edge, const Pose2D& a, const Pose2D& b) {
  const Pose2D e = wheelchair_core::between(edge.measurement, wheelchair_core::between(a, b));
  return {e.x, e.y, e.yaw};
}

Eigen::Matrix3d rotateCovariance(const Eigen::Matrix3d& covariance, double yaw) {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  const double c = std::cos(yaw), s = std::sin(yaw);
  r(0, 0) = c;
  r(0, 1) = s;
  r(1, 0) = -s;
  r(1, 1) = c;
  return r * covariance * r.transpose();
}

size_t PoseGraph::addNode(const Pose2D& pose) {
  poses_.push_back(pose);
  return poses_.size() - 1;
}

size_t PoseGraph::addEdge(const GraphEdge& edge) {
  if (edge.from >= poses_.size() || edge.to >= poses_.size() || edge.from == edge.to)
    throw std::invalid_argument("PoseGraph::addEdge: edge between unknown or equal nodes");
  edges_.push_back(edge);
  return edges_.size() - 1;
}

double PoseGraph::chi2(size_t i) const {
  const GraphEdge& e = edges_[i];
  const Eigen::Vector3d r = edgeResidual(e, poses_[e.from], poses_[e.to]);
  return r.dot(e.information * r);
}

double PoseGraph::totalChi2() const {
  double sum = 0.0;
  for (size_t i = 0; i < edges_.size(); ++i) {
    if (edges_[i].active) sum += chi2(i);
  }
  return sum;
}

namespace {

/// The active edges and every node as MRPT's graph.
mrpt::graphs::CNetworkOfPoses2DInf toMrptGraph(const std::vector<Pose2D>& poses,
                                               const std::vector<GraphEdge>& edges) {
  mrpt::graphs::CNetworkOfPoses2DInf graph;
  graph.root = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    graph.nodes[i] = mrpt::poses::CPose2D(poses[i].x, poses[i].y, poses[i].yaw);
  }
  for (const GraphEdge& e : edges) {
    if (!e.active) continue;
    mrpt::poses::CPosePDFGaussianInf pdf;
    pdf.mean = mrpt::poses::CPose2D(e.measurement.x, e.measurement.y, e.measurement.yaw);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) pdf.cov_inv(r, c) = e.information(r, c);
    graph.insertEdge(e.from, e.to, pdf);
  }
  return graph;
}

}  // namespace

void PoseGraph::save(const std::string& path) const {
  try {
    toMrptGraph(poses_, edges_).saveToTextFile(path);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot write the pose graph (" + e.what() + ")");
  }
}

OptimizeResult PoseGraph::optimize(int max_iterations) {
  OptimizeResult result;
  result.initial_chi2 = totalChi2();
  if (poses_.size() < 2 || edges_.empty()) return result;
  mrpt::graphs::CNetworkOfPoses2DInf graph = toMrptGraph(poses_, edges_);
  mrpt::graphslam::TResultInfoSpaLevMarq info;
  mrpt::containers::yaml params = mrpt::containers::yaml::Map();
  params["max_iterations"] = static_cast<uint64_t>(max_iterations);
  mrpt::graphslam::optimize_graph_spa_levmarq(graph, info, nullptr, params);
  for (size_t i = 0; i < poses_.size(); ++i) {
    const mrpt::poses::CPose2D& p = graph.nodes[i];
    poses_[i] = {p.x(), p.y(), wheelchair_core::normalizeAngle(p.phi())};
  }
  result.iterations = info.num_iters;
  result.final_chi2 = totalChi2();
  return result;
}

RobustOptimizeResult optimizeRejectingFalseLoops(PoseGraph& graph, int max_iterations,
                                                 double max_chi2) {
  RobustOptimizeResult result;
  for (;;) {
    graph.optimize(max_iterations);
    ++result.optimizations;
    double worst = max_chi2;
    size_t worst_edge = graph.edges().size();
    for (size_t i = 0; i < graph.edges().size(); ++i) {
      const GraphEdge& e = graph.edges()[i];
      if (!e.active || e.kind != EdgeKind::kLoopClosure) continue;
      const double c = graph.chi2(i);
      if (c > worst) {
        worst = c;
        worst_edge = i;
      }
    }
    if (worst_edge == graph.edges().size()) return result;
    graph.deactivateEdge(worst_edge);
    result.removed.push_back(worst_edge);
  }
}

}  // namespace wheelchair_slam
