#include <wheelchair_sim/footprint_checker.h>
#include <wheelchair_sim/laser_simulator.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace wheelchair_sim {

LaserSimulator::LaserSimulator(const SimParams& params, const Eigen::Vector3d& mount,
                               std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world)
    : params_(params),
      mount_(mount),
      world_(std::move(world)),
      rng_(static_cast<uint64_t>(params.seed) + 0x9E3779B97F4A7C15ull) {
  validate(params_);
  if (!world_) throw std::invalid_argument("LaserSimulator needs a world grid");
}

Eigen::Vector3d LaserSimulator::laserPose(const Eigen::Vector3d& base) const {
  const double c = std::cos(base.z()), s = std::sin(base.z());
  return {base.x() + c * mount_.x() - s * mount_.y(), base.y() + s * mount_.x() + c * mount_.y(),
          base.z() + mount_.z()};
}

Scan LaserSimulator::scan(const Eigen::Vector3d& base_pose, const std::vector<Disc>& discs) {
  const Eigen::Vector3d sensor = laserPose(base_pose);
  Scan out;
  out.angle_min = -0.5 * params_.laser_fov;
  out.angle_increment = params_.laser_fov / (params_.laser_beams - 1);
  out.range_min = params_.laser_range_min;
  out.range_max = params_.laser_range_max;
  out.ranges.resize(params_.laser_beams);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int i = 0; i < params_.laser_beams; ++i) {
    float range = 0.0f;
    bool valid = false;
    const double angle = sensor.z() + out.angle_min + i * out.angle_increment;
    world_->simulateScanRay(sensor.x(), sensor.y(), angle, range, valid, params_.laser_range_max,
                            kFreeThreshold);
    double r = range;
    const double to_disc = rayToDiscs(sensor.head<2>(), angle, discs);
    if (to_disc < (valid ? r : params_.laser_range_max)) {
      r = to_disc;
      valid = true;
    }
    if (params_.laser_range_noise > 0.0) r += params_.laser_range_noise * noise(rng_);
    const bool in_range = valid && r >= params_.laser_range_min && r <= params_.laser_range_max;
    out.ranges[i] = in_range ? static_cast<float>(r) : std::numeric_limits<float>::infinity();
  }
  return out;
}

}  // namespace wheelchair_sim
