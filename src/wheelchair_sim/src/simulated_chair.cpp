#include <wheelchair_sim/simulated_chair.h>

namespace wheelchair_sim {

bool Schedule::due(double now) {
  if (now + 1e-9 < next_) return false;
  next_ += period_;
  if (next_ <= now) next_ = now + period_;
  return true;
}

SimulatedChair::SimulatedChair(const wheelchair_description::ChairParams& chair,
                               const SimParams& params,
                               std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world)
    : sim_(chair, params, world),
      odometry_(chair, params, static_cast<uint64_t>(params.seed) * 7919u + 1u),
      odom_schedule_(params.odom_rate),
      scan_schedule_(params.laser_rate) {
  if (world && params.laser_enabled) {
    laser_.emplace(params, wheelchair_core::Pose2D{chair.laser_x, chair.laser_y, chair.laser_yaw},
                   world);
  }
  if (world && params.rear_laser_enabled) {
    rear_laser_.emplace(
        rearLaserParams(params),
        wheelchair_core::Pose2D{chair.rear_laser_x, chair.rear_laser_y, chair.rear_laser_yaw},
        world);
  }
  odometry_.reset(wheelchair_core::Pose2D(), sim_.readWheels().angle);
}

SensorOutputs SimulatedChair::advance(double dt) {
  const bool was_collided = sim_.collided();
  sim_.step(dt);
  odometry_.update(sim_.readWheels().angle, dt);
  SensorOutputs out;
  out.collision_started = sim_.collided() && !was_collided;
  out.odometry_due = odom_schedule_.due(sim_.time());
  if ((laser_ || rear_laser_) && scan_schedule_.due(sim_.time())) {
    const std::vector<Disc> discs = sim_.obstacles().presentAt(sim_.time());
    if (laser_) {
      out.scan = laser_->scan(sim_.pose(), discs);
      out.scan->stamp = sim_.time();
    }
    if (rear_laser_) {
      out.rear_scan = rear_laser_->scan(sim_.pose(), discs);
      out.rear_scan->stamp = sim_.time();
    }
  }
  return out;
}

bool SimulatedChair::teleport(const wheelchair_core::Pose2D& pose) { return sim_.teleport(pose); }

bool SimulatedChair::reset(const wheelchair_core::Pose2D& pose) {
  if (!sim_.teleport(pose)) return false;
  odometry_.reset(wheelchair_core::Pose2D(), sim_.readWheels().angle);
  return true;
}

}  // namespace wheelchair_sim
