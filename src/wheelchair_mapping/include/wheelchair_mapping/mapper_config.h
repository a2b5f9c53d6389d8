// What the mapper is set up with (defaults here, nowhere else), its checks and the one list of
// its parameter names, read by the mapping nodelet and usable by offline tools.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_mapping/inverse_sensor_model.h>

#include <string>

namespace wheelchair_mapping {

struct MapperConfig {
  double resolution = 0.05;    ///< [m]
  double initial_size = 20.0;  ///< side of the initial square grid centred on (0, 0) [m]
  /// Extra border added whenever the grid grows to fit a scan [m].
  double growth_margin = 5.0;
  int expected_beams = 0;  ///< 0: any beam count
  InverseSensorModel model;

  /// "" if usable, else every problem (the sensor model's included).
  std::string validate() const;
};

/// Every key: resolution, initial_size, growth_margin, expected_beams and the sensor model's
/// p_occ_hit, p_occ_pass, max_insertion_range, no_return_is_free, no_return_range, beam_width,
/// hit_depth.
void readMapperConfig(wheelchair_core::ConfigReader& reader, MapperConfig& config);

}  // namespace wheelchair_mapping
