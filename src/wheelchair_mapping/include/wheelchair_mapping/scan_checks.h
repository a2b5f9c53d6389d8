// Decides what a laser scan and each of its beams may contribute to the map (REP-117).
#pragma once

#include <wheelchair_mapping/inverse_sensor_model.h>
#include <wheelchair_mapping/laser_scan.h>

#include <cstddef>
#include <string>

namespace wheelchair_mapping {

/// Empty if the scan's geometry is usable, else the reason: non-finite or zero angle
/// increment, beam count that disagrees with angle_min/max/increment or with
/// `expected_beams` (0: any), bad range limits.
std::string scanProblem(const LaserScan2D& scan, size_t expected_beams);

/// What a beam contributes: nothing, free cells up to `length` (no return, or a return beyond
/// the insertion range), or free cells then an occupied one at `length`.
struct BeamUse {
  enum Kind { kSkip, kPassThrough, kHit } kind = kSkip;
  double length = 0.0;
};

/// NaN, -inf, and finite ranges outside [range_min, range_max] are skipped; +inf is a
/// pass-through up to the no-return range if the model allows it.
BeamUse useOfBeam(float range, const LaserScan2D& scan, const InverseSensorModel& model);

}  // namespace wheelchair_mapping
