#include <wheelchair_mapping/mrpt_scan.h>

#include <cmath>

namespace wheelchair_mapping {

wheelchair_core::LaserScan2D laserScanFromMrpt(const mrpt::obs::CObservation2DRangeScan& scan,
                                               double stamp) {
  wheelchair_core::LaserScan2D out;
  const size_t n = scan.getScanSize();
  const double step = n > 1 ? static_cast<double>(scan.aperture) / (n - 1) : 0.0;
  out.stamp = stamp;
  out.angle_increment = scan.rightToLeft ? step : -step;
  out.angle_min = scan.rightToLeft ? -scan.aperture / 2 : scan.aperture / 2;
  out.angle_max = out.angle_min + (n > 0 ? (n - 1) * out.angle_increment : 0.0);
  out.range_min = 0.0;
  out.range_max = scan.maxRange;
  out.ranges.resize(n);
  for (size_t i = 0; i < n; ++i) {
    out.ranges[i] = scan.getScanRangeValidity(i) ? scan.getScanRange(i) : INFINITY;
  }
  return out;
}

}  // namespace wheelchair_mapping
