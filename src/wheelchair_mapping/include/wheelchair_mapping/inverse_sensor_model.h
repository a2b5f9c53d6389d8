// The inverse sensor model of a laser beam and the paper's Bayes update (eq. 1).
#pragma once

#include <string>

namespace wheelchair_mapping {

/// Eq. (1) (Elfes 1989): the new occupancy probability of a cell from the sensor model's
/// P_s^o (probability the cell is occupied given the reading) and the stored P_m^o.
double elfesUpdate(double p_sensor, double p_prior);

/// The distance along the beam of the point whose cell receives a return's occupied evidence
/// P_s^o = p_occ_hit (eq. 1 unchanged): the measured range plus hit_depth; every cell before
/// that point's cell is passed.
double returnCellRange(double measured_range, double hit_depth);

/// What one beam says about the cells it crosses. MRPT stores cells as 8-bit log-odds
/// (steps of 1/16), so the probabilities actually applied are the quantized ones returned by
/// the effective*() helpers of BayesMapper.
struct InverseSensorModel {
  /// P_s^o of the cell where the beam ended (a return). A return must outweigh a few passes:
  /// beams grazing a wall cross its cells, and with 0.7 (log-odds 14 against a pass's -10, in
  /// MRPT's 1/16 steps) a wall cell hit once and crossed twice became free. With the 8-connected
  /// beams of BayesMapper the echoes of real logs at their SLAM-corrected poses fit the map
  /// (localizer inlier share) at 0.973 / 0.952 / 0.932 (Intel / FR101 / FR079) with 0.7 and
  /// 0.984 / 0.972 / 0.952 with 0.8 (log-odds 22: 2.2 passes); MRPT's default insertion (a
  /// return weighs 3 passes) gives 0.987 / 0.970 / 0.947. 0.85 and more thicken walls beyond 2
  /// cells under 1 cm range noise (test_mapping_accuracy).
  double p_occ_hit = 0.8;
  double p_occ_pass = 0.35;  ///< P_s^o of each cell the beam passed through
  /// Cells farther than this from the sensor are never updated; a return beyond it counts
  /// as a pass-through up to this range [m].
  double max_insertion_range = 20.0;
  /// REP-117 +inf (no return within range_max): the beam's cells are free up to
  /// no_return_range (<= 0: the scan's range_max), if enabled.
  bool no_return_is_free = true;
  double no_return_range = 0.0;
  /// Angular width of a beam [rad]; > 0 marks every cell across the beam's footprint at the
  /// return as occupied (0: one cell per return).
  double beam_width = 0.0;
  /// Depth behind the measured surface point at which a return's occupied evidence is placed
  /// [m] (returnCellRange). An echo is the surface, the boundary between free space and matter;
  /// the occupied cell is the one behind it. Where a world's surfaces lie on cell faces (every
  /// wall of the simulator's drawn worlds) the echo's own cell is, by a range error of either
  /// sign, half the time the free cell in front, and a hit outweighs 2.2 passes: walls one cell
  /// thick (simulator, exact laser: 96.58 % of cells right). There 2 range sigmas (0.02 for the
  /// 1 cm lasers) put 98 % of a face's echoes into the cell behind it (99.18 %). Real surfaces
  /// lie anywhere in a cell, and moving the evidence of those in a cell's last 2 cm one cell on
  /// costs the echoes there (Intel corrected, every 10th scan held out: 75.07 % on occupied
  /// cells at 0, 68.82 % at 0.01, 60.56 % at 0.02), so 0 (the echo's own cell) unless the
  /// surfaces are known to lie on cell faces.
  double hit_depth = 0.0;

  /// Empty if consistent, else every problem (probabilities in (0,1), hit > 0.5 > pass, hit_depth
  /// in [0, 0.1] m, ...).
  std::string validate() const;
};

}  // namespace wheelchair_mapping
