// What the localizer asks of a laser scan beyond a usable geometry (REP-117 meanings:
// wheelchair_core::classifyBeam).
#pragma once

#include <wheelchair_core/laser_scan.h>

#include <string>

namespace wheelchair_kld {

/// "" for a scan the localizer can use, otherwise why it must be rejected: a beam count other
/// than `expected_beams` (0 accepts any), a geometry wheelchair_core::scanGeometryProblem
/// refuses, an erroneous (NaN) or too-close (-inf) reading anywhere, or fewer than
/// `min_echo_fraction` of the beams being returns.
std::string validateScan(const wheelchair_core::LaserScan2D& scan, int expected_beams,
                         double min_echo_fraction);

}  // namespace wheelchair_kld
