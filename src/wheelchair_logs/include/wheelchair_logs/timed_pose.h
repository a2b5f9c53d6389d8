// A pose of a trajectory with its time stamp (estimates, references, relation ends).
#pragma once

#include <wheelchair_core/pose2d.h>

namespace wheelchair_logs {

struct TimedPose {
  double stamp = 0.0;  ///< [s]
  wheelchair_core::Pose2D pose;
};

}  // namespace wheelchair_logs
