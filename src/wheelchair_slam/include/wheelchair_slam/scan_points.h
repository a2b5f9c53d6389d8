// The returns of a laser scan as the planar points the matchers work on.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <Eigen/Core>

#include <vector>

namespace wheelchair_slam {

using Points = std::vector<Eigen::Vector2d>;

/// The returns of `scan` within `max_range`, in the sensor frame, in beam order; a point closer
/// than `min_spacing` to the last kept point is dropped (even density along walls).
Points scanPoints(const wheelchair_core::LaserScan2D& scan, double max_range, double min_spacing);

/// `points` (in the frame of `pose`) in the pose's parent frame, appended to `out`.
void appendTransformed(const Points& points, const wheelchair_core::Pose2D& pose, Points& out);

}  // namespace wheelchair_slam
