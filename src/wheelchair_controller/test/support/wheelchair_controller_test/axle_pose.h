// The model state's axle pose (wheelchair_description::axlePose) as the controller's pose type.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_description/model.h>

namespace wheelchair_controller {

inline wheelchair_core::Pose2D axlePose2D(const wheelchair_description::State& x,
                                          const wheelchair_description::ChairParams& p) {
  const Eigen::Vector3d pose = wheelchair_description::axlePose(x, p);
  return {pose.x(), pose.y(), pose.z()};
}

}  // namespace wheelchair_controller
