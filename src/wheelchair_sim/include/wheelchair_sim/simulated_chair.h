// The whole simulated chair as the nodelet and the benchmark run it: ground truth
// (Simulator), wheel-encoder odometry and the lasers (front and rear), each sensor on its own
// schedule.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_sim/laser_simulator.h>
#include <wheelchair_sim/simulator.h>
#include <wheelchair_sim/wheel_odometry.h>

#include <optional>

namespace wheelchair_sim {

/// What became due during one advance().
struct SensorOutputs {
  bool odometry_due = false;                         ///< publish /odom, tf and ground truth now
  std::optional<wheelchair_core::LaserScan2D> scan;  ///< a new scan, stamped the new time
  std::optional<wheelchair_core::LaserScan2D> rear_scan;  ///< a new rear scan, the same time
  bool collision_started = false;  ///< the chair hit something during this advance
};

/// Fires every 1 / rate seconds of simulated time; never bunches up after a pause.
class Schedule {
 public:
  explicit Schedule(double rate) : period_(1.0 / rate) {}
  bool due(double now);

 private:
  double period_;
  double next_ = 0.0;
};

class SimulatedChair {
 public:
  /// `world` may be null (no laser, no collisions).
  SimulatedChair(const wheelchair_description::ChairParams& chair, const SimParams& params,
                 std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world);

  SensorOutputs advance(double dt);

  /// Moves the chair, the odometry does not notice (kidnapping). False if the pose collides.
  bool teleport(const wheelchair_core::Pose2D& pose);
  /// Moves the chair and restarts the odometry at the identity. False if the pose collides.
  bool reset(const wheelchair_core::Pose2D& pose);

  Simulator& simulator() { return sim_; }
  const Simulator& simulator() const { return sim_; }
  const WheelOdometry& odometry() const { return odometry_; }
  bool hasLaser() const { return laser_.has_value(); }
  bool hasRearLaser() const { return rear_laser_.has_value(); }

 private:
  Simulator sim_;
  WheelOdometry odometry_;
  std::optional<LaserSimulator> laser_, rear_laser_;
  Schedule odom_schedule_, scan_schedule_;
};

}  // namespace wheelchair_sim
