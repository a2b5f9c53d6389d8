// The relation metric of Kuemmerle et al. ("On measuring the accuracy of SLAM algorithms",
// Autonomous Robots 27(4), 2009): the error of an estimated trajectory on reference relations
// (the pose of scan t2 in the frame of scan t1), translational and rotational, with mean, std
// and max. ROS-free, shared by bench/slam and the replay tool.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_logs/timed_pose.h>

#include <cstddef>
#include <string>
#include <vector>

namespace wheelchair_logs {

struct Relation {
  double t1 = 0.0, t2 = 0.0;      ///< stamps in the relation file's time base
  wheelchair_core::Pose2D delta;  ///< pose at t2 in the frame of the pose at t1
};

/// A .relations file: "t1 t2 dx dy dz droll dpitch dyaw" per line (dz, droll, dpitch ignored).
/// Throws std::runtime_error naming the file and line for a bad line.
std::vector<Relation> readRelations(const std::string& path);

/// Relations between the poses of a reference trajectory (for a log whose reference is a
/// corrected trajectory, not a relations file): consecutive poses (local accuracy), or every
/// pair (global consistency).
std::vector<Relation> referenceRelations(const std::vector<TimedPose>& reference, bool all_pairs);

struct RelationErrors {
  size_t relations = 0;               ///< in the file
  std::vector<double> translational;  ///< [m], one per matched relation
  std::vector<double> rotational;     ///< [rad], absolute
};

/// Each relation's two stamps (minus `offset`: relation time = trajectory time + offset) are
/// matched to the nearest pose of `trajectory` (sorted by stamp) within `tolerance`; a
/// relation with an unmatched end, or with both ends on one pose, is skipped.
RelationErrors relationErrors(const std::vector<Relation>& relations,
                              const std::vector<TimedPose>& trajectory, double offset,
                              double tolerance);

struct ErrorSummary {
  size_t count = 0;
  double mean = 0.0, std = 0.0, max = 0.0;
};
ErrorSummary summarize(const std::vector<double>& values);

}  // namespace wheelchair_logs
