// The live obstacle layer: what the laser sees now that the static map does not have (a person,
// a chair left in a doorway). An Elfes grid (eq. 1, elfesUpdate) on the static map's cells,
// updated from each scan at the localized laser pose: a return marks its cell, the cells a beam
// passes are cleared (free rays), and without new evidence every cell decays back to the prior
// 0.5, so an obstacle that went out of view is forgotten within `forget_time`. Returns within
// `map_margin` of a static-map obstacle belong to the map and mark nothing (localization noise
// on a door frame must not narrow the door). ROS-free.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/inverse_sensor_model.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_mapping {

struct ObstacleLayerConfig {
  /// P_s^o of a return's cell and of a passed cell; only cells within max_insertion_range of
  /// the laser are updated (beam_width is not used by the layer: one cell per return).
  InverseSensorModel model{0.7, 0.35, 8.0, true, 0.0, 0.0};
  /// A cell is an obstacle while its probability is at least this (two returns from the prior).
  double obstacle_probability = 0.8;
  /// Cells are kept within [1 - max_probability, max_probability]: bounds how many free rays
  /// clear an obstacle (4 with the defaults) and how long the decay takes.
  double max_probability = 0.97;
  /// [s] a cell at max_probability falls below obstacle_probability after this long without
  /// evidence (log-odds decay exponentially toward the prior).
  double forget_time = 5.0;
  /// [m] returns this close to a static-map obstacle cell are the map's, not obstacles.
  double map_margin = 0.10;

  std::string validate() const;
};

/// Keys: p_occ_hit, p_occ_pass, max_insertion_range, no_return_is_free, no_return_range,
/// obstacle_probability, max_probability, forget_time, map_margin.
void readObstacleLayerConfig(wheelchair_core::ConfigReader& reader, ObstacleLayerConfig& config);

class ObstacleLayer {
 public:
  /// The layer on `static_map`'s grid (zero yaw). Throws std::invalid_argument for an invalid
  /// configuration or map.
  ObstacleLayer(const wheelchair_core::OccupancyMap& static_map, const ObstacleLayerConfig& config);

  /// Decays to the scan's stamp (unless decayTo() went beyond it), then fuses it (eq. 1 per
  /// cell). Skips the whole scan, saying why, for a non-finite pose, a geometry
  /// scanGeometryProblem refuses, a stamp older than the last scan's, or no usable beam.
  InsertResult insert(const wheelchair_core::LaserScan2D& scan,
                      const wheelchair_core::Pose2D& sensor_pose);
  /// Decays every cell to time `stamp` [s] (nothing if not later than the last decay), e.g. to
  /// now while no scan arrives; a later scan with an earlier stamp is still fused.
  void decayTo(double stamp);

  /// The layer on the static map's grid: kOccupied where an obstacle is, kFree where the
  /// evidence says free, kUnknown where there is none (prior).
  wheelchair_core::OccupancyMap layer() const;
  double probability(int ix, int iy) const;
  bool isObstacle(int ix, int iy) const;
  size_t obstacleCount() const;
  double lastStamp() const { return last_stamp_; }  ///< of the last fused scan
  const ObstacleLayerConfig& config() const { return config_; }

 private:
  void touch(size_t k);
  void update(size_t k, double logodds_sensor);

  ObstacleLayerConfig config_;
  wheelchair_core::OccupancyMap geometry_;  ///< the static map's geometry (data unused)
  std::vector<uint8_t> near_map_;           ///< within map_margin of a static obstacle
  std::vector<float> logodds_;              ///< log-odds of occupied, 0 = prior 0.5
  std::vector<uint8_t> active_flag_;
  std::vector<size_t> active_;        ///< cells with non-zero log-odds (the ones that decay)
  std::vector<uint32_t> updated_in_;  ///< the scan that last updated each cell
  uint32_t scan_count_ = 0;
  double logodds_hit_ = 0.0, logodds_pass_ = 0.0, logodds_obstacle_ = 0.0, logodds_max_ = 0.0;
  double decay_rate_ = 0.0;      ///< [1/s]
  double last_stamp_ = -1e300;   ///< of the last fused scan
  double decay_stamp_ = -1e300;  ///< time the cells were last decayed to
};

}  // namespace wheelchair_mapping
