// A planar laser scan as the localizer sees it, and its validation.
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>
#include <vector>

namespace wheelchair_kld {

struct LaserScan {
  std::vector<float> ranges;     ///< [m]; +inf or >= range_max means "no echo" (REP-117)
  double angle_min = -M_PI / 2;  ///< [rad] of beam 0 in the laser frame
  double angle_increment = M_PI / 360;
  double range_min = 0.05;          ///< [m]
  double range_max = 30.0;          ///< [m]
  mrpt::math::TPose2D sensor_pose;  ///< laser frame in base_link
};

/// Returns "" for a usable scan, otherwise the reason it must be rejected: NaN or -inf ranges,
/// a beam count other than `expected_beams` (0 accepts any), non-finite geometry, or fewer than
/// `min_valid_fraction` of the beams carrying an echo.
std::string validateScan(const LaserScan& scan, int expected_beams,
                         double min_valid_fraction = 0.2);

/// Converts an MRPT scan (e.g. from COccupancyGridMap2D::laserScanSimulator); invalid beams
/// become +inf.
LaserScan fromMrptScan(const mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace wheelchair_kld
