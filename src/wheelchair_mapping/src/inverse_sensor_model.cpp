#include <wheelchair_core/config.h>
#include <wheelchair_mapping/inverse_sensor_model.h>

#include <cmath>

namespace wheelchair_mapping {

// Eq. (1): P^o = P_s^o P_m^o / (P_s^o P_m^o + (1 - P_s^o)(1 - P_m^o)).
double elfesUpdate(double p_sensor, double p_prior) {
  const double occupied = p_sensor * p_prior;
  return occupied / (occupied + (1.0 - p_sensor) * (1.0 - p_prior));
}

double returnCellRange(double measured_range, double hit_depth) {
  return measured_range + hit_depth;
}

std::string InverseSensorModel::validate() const {
  return wheelchair_core::ConfigChecks()
      .check(p_occ_hit > 0.5 && p_occ_hit < 1.0, "p_occ_hit must be in (0.5, 1)")
      .check(p_occ_pass > 0.0 && p_occ_pass < 0.5, "p_occ_pass must be in (0, 0.5)")
      .positive("max_insertion_range", max_insertion_range)
      .finite("no_return_range", no_return_range)
      .check(beam_width >= 0.0 && beam_width < 0.5, "beam_width must be in [0, 0.5) rad")
      .check(hit_depth >= 0.0 && hit_depth <= 0.1, "hit_depth must be in [0, 0.1] m")
      .result();
}

}  // namespace wheelchair_mapping
