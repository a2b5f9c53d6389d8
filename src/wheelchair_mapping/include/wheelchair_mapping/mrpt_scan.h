// MRPT range scans (e.g. from COccupancyGridMap2D::laserScanSimulator) as
// wheelchair_core::LaserScan2D.
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <wheelchair_core/laser_scan.h>

namespace wheelchair_mapping {

/// Evenly spread over the aperture, centred on the sensor's x axis (MRPT's convention, the
/// sensor's own pose on the robot is not applied); invalid ranges (no echo) become +inf.
wheelchair_core::LaserScan2D laserScanFromMrpt(const mrpt::obs::CObservation2DRangeScan& scan,
                                               double stamp);

}  // namespace wheelchair_mapping
