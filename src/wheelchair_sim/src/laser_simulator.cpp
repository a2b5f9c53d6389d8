#include <wheelchair_sim/free_threshold.h>
#include <wheelchair_sim/laser_simulator.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace wheelchair_sim {

namespace core = wheelchair_core;

LaserSimulator::LaserSimulator(const SimParams& params, const core::Pose2D& mount,
                               std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world)
    : params_(params),
      mount_(mount),
      world_(std::move(world)),
      rng_(static_cast<uint64_t>(params.seed) + 0x9E3779B97F4A7C15ull) {
  const std::string problem = params_.validate();
  if (!problem.empty()) throw std::invalid_argument("laser: " + problem);
  if (!world_) throw std::invalid_argument("LaserSimulator needs a world grid");
}

core::Pose2D LaserSimulator::laserPose(const core::Pose2D& base) const {
  const Eigen::Vector2d at = core::transformPoint(base, mount_.position());
  return {at.x(), at.y(), base.yaw + mount_.yaw};
}

core::LaserScan2D LaserSimulator::scan(const core::Pose2D& base_pose,
                                       const std::vector<Disc>& discs) {
  const core::Pose2D sensor = laserPose(base_pose);
  core::LaserScan2D out;
  out.angle_min = -0.5 * params_.laser_fov;
  out.angle_increment = params_.laser_fov / (params_.laser_beams - 1);
  out.angle_max = out.angle_min + out.angle_increment * (params_.laser_beams - 1);
  out.range_min = params_.laser_range_min;
  out.range_max = params_.laser_range_max;
  out.ranges.resize(params_.laser_beams);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int i = 0; i < params_.laser_beams; ++i) {
    float range = 0.0f;
    bool valid = false;
    const double angle = sensor.yaw + out.angle_min + i * out.angle_increment;
    world_->simulateScanRay(sensor.x, sensor.y, angle, range, valid, params_.laser_range_max,
                            kFreeThreshold);
    double r = range;
    const double to_disc = rayToDiscs(sensor.position(), angle, discs);
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
