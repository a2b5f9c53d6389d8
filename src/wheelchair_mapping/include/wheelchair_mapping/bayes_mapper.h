// The paper's map making (section 2.1): laser scans fused into an occupancy grid with the
// recursive Bayes rule of eq. (1), every cell starting at the prior 0.5. Cells live in MRPT's
// COccupancyGridMap2D, whose log-odds update is eq. (1) in additive form.
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_mapping/mapper_config.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <wheelchair_mapping/scan_checks.h>

#include <cstddef>
#include <string>

namespace wheelchair_mapping {

struct InsertResult {
  bool inserted = false;
  std::string reason;  ///< why the scan was skipped (empty when inserted)
  int beams_used = 0;
};

class BayesMapper {
 public:
  /// Throws std::invalid_argument for an inconsistent configuration.
  explicit BayesMapper(const MapperConfig& config);

  /// Fuses one scan taken at `sensor_pose` (map frame). Skips the whole scan, saying why, when
  /// the pose is not finite, the geometry or beam count is wrong, the stamp is older than the
  /// last inserted scan's, or no beam is usable.
  InsertResult insert(const wheelchair_core::LaserScan2D& scan,
                      const wheelchair_core::Pose2D& sensor_pose);

  const mrpt::maps::COccupancyGridMap2D& grid() const { return grid_; }
  wheelchair_core::OccupancyMap map(const GridThresholds& thresholds = GridThresholds()) const;
  size_t scansInserted() const { return scans_inserted_; }

  /// The P_s^o actually applied after MRPT's 8-bit log-odds quantization.
  double effectiveHitProbability() const;
  double effectivePassProbability() const;

 private:
  void growToFit(double x_min, double x_max, double y_min, double y_max);
  void markFree(int ix, int iy);
  void markOccupied(int ix, int iy);
  void markFootprint(const wheelchair_core::Pose2D& pose, double angle, double range);
  /// Where the beam's last updated cell lies along it [m].
  double cellRange(const BeamUse& use) const;

  MapperConfig config_;
  mrpt::maps::COccupancyGridMap2D grid_;
  using Cell = mrpt::maps::COccupancyGridMap2D::cellType;
  Cell logodds_hit_;
  Cell logodds_pass_;
  double last_stamp_ = -INFINITY;
  size_t scans_inserted_ = 0;
};

}  // namespace wheelchair_mapping
