// Decides what each beam of a laser scan contributes to the map (REP-117).
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_mapping/inverse_sensor_model.h>

#include <cstddef>
#include <string>

namespace wheelchair_mapping {

/// What a beam contributes: nothing, free cells up to `length` (no return, or a return beyond
/// the insertion range), or free cells then an occupied one at `length`.
struct BeamUse {
  enum Kind { kSkip, kPassThrough, kHit } kind = kSkip;
  double length = 0.0;
};

/// By the REP-117 meaning of the beam (wheelchair_core::classifyBeam): NaN, -inf, and finite
/// ranges outside [range_min, range_max] are skipped; +inf is a pass-through up to the
/// no-return range if the model allows it.
BeamUse useOfBeam(float range, const wheelchair_core::LaserScan2D& scan,
                  const InverseSensorModel& model);

/// Why a whole scan taken at `sensor_pose` cannot be fused into a grid ("" if it can): a
/// non-finite pose, a geometry scanGeometryProblem refuses (`expected_beams`, 0: any), or a
/// stamp older than `last_stamp` (the grid's last fused scan).
std::string scanInsertProblem(const wheelchair_core::LaserScan2D& scan,
                              const wheelchair_core::Pose2D& sensor_pose, size_t expected_beams,
                              double last_stamp);

}  // namespace wheelchair_mapping
