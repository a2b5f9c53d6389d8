#include <wheelchair_mapping/mapper_config.h>

namespace wheelchair_mapping {

std::string MapperConfig::validate() const {
  const std::string model_problem = model.validate();
  return wheelchair_core::ConfigChecks()
      .positive("resolution", resolution)
      .positive("initial_size", initial_size)
      .nonNegative("growth_margin", growth_margin)
      .check(expected_beams >= 0, "expected_beams must not be negative (0: any)")
      .check(model_problem.empty(), model_problem)
      .result();
}

void readMapperConfig(wheelchair_core::ConfigReader& r, MapperConfig& c) {
  r.read("resolution", c.resolution);
  r.read("initial_size", c.initial_size);
  r.read("growth_margin", c.growth_margin);
  r.read("expected_beams", c.expected_beams);
  InverseSensorModel& m = c.model;
  r.read("p_occ_hit", m.p_occ_hit);
  r.read("p_occ_pass", m.p_occ_pass);
  r.read("max_insertion_range", m.max_insertion_range);
  r.read("no_return_is_free", m.no_return_is_free);
  r.read("no_return_range", m.no_return_range);
  r.read("beam_width", m.beam_width);
  r.read("hit_depth", m.hit_depth);
}

}  // namespace wheelchair_mapping
