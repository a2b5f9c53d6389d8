// The final map of a SLAM run: the paper's Elfes grid (eq. 1, prior 0.5; wheelchair_mapping's
// BayesMapper) rebuilt from every scan at its optimized pose, and a preview picture of it with
// the trajectory and the loop closures drawn.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_mapping/bayes_mapper.h>

#include <string>
#include <utility>
#include <vector>

namespace wheelchair_slam {

/// One scan into a map rebuilt from poses, as scan number `order` of it: the mapper's order
/// check (a stamp older than the last is refused, right for a live map from tf) is met by
/// stamping the copy with `order`; a map at given poses does not depend on time, and the scans
/// of a continued map's drives may come from clocks that started again.
wheelchair_mapping::InsertResult insertAtPose(wheelchair_mapping::BayesMapper& mapper,
                                              wheelchair_core::LaserScan2D scan,
                                              const wheelchair_core::Pose2D& pose, size_t order);

/// Every scan inserted at its pose (insertAtPose; scans the mapper refuses, e.g. non-finite
/// poses, are counted in `skipped`).
wheelchair_mapping::BayesMapper buildMap(const std::vector<wheelchair_core::LaserScan2D>& scans,
                                         const std::vector<wheelchair_core::Pose2D>& poses,
                                         const wheelchair_mapping::MapperConfig& config,
                                         size_t* skipped = nullptr);

/// The grid's preview (wheelchair_logs::savePreviewPng) with the trajectory in blue and each
/// loop closure as a red segment between its two poses. Throws std::runtime_error on failure.
void savePreviewWithTrajectory(
    const wheelchair_mapping::BayesMapper& mapper, const std::vector<wheelchair_core::Pose2D>& path,
    const std::vector<std::pair<wheelchair_core::Pose2D, wheelchair_core::Pose2D>>& loops,
    const std::string& png_path);

}  // namespace wheelchair_slam
