// A SLAM run saved so that it can be continued (slam_toolbox's "continue mapping"): a new drive
// is located in the saved map and extends its pose graph (GraphSlam's continuing constructor).
//   graph.graph  the keyframe pose graph in g2o's text format (VERTEX_SE2, FIX, EDGE_SE2 with
//                the upper triangle of each edge's information), readable by g2o and MRPT;
//   graph.scans  what the g2o format cannot hold: each keyframe's scan, drive, path length and
//                odometry, each edge's kind, the loop closures, and every scan (ranges, its
//                keyframe and pose relative to it, odometry, stamp), so that the map is rebuilt
//                from all of them at their optimized poses.
// Text, one record per line; a bad file is refused naming the file and line.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_slam/graph_slam.h>

#include <string>
#include <vector>

namespace wheelchair_slam {

struct SavedSlam {
  KeyframeGraph graph;
  std::vector<ScanRecord> records;                  ///< one per scan
  std::vector<wheelchair_core::LaserScan2D> scans;  ///< every scan of the run, in order
};

/// Writes DIR/graph.graph and DIR/graph.scans (DIR must exist). `scans` are the scans given to
/// `slam`, in order. Written to temporary files and renamed. Throws std::runtime_error naming
/// the file.
void saveSlam(const std::string& dir, const GraphSlam& slam,
              const std::vector<wheelchair_core::LaserScan2D>& scans);

/// Reads what saveSlam wrote; the keyframes' points are made from their scans with
/// `config.matcher` (as GraphSlam made them). Throws std::runtime_error naming the file and
/// line.
SavedSlam loadSlam(const std::string& dir, const SlamConfig& config);

/// The g2o text of a pose graph: nodes and active edges, node 0 fixed. Edges in graph order.
void writeG2o(const std::string& path, const PoseGraph& graph);

}  // namespace wheelchair_slam
