// The chair's ground truth: the paper's dynamic model (eq. 15) integrated with RK4 from the
// wheel torques, with optional rolling resistance, torque limits and wheel slip, and
// footprint collisions against the ground-truth grid. Time is injected: step(dt).
#pragma once

#include <wheelchair_core/kinematics.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_description/model.h>
#include <wheelchair_sim/body_contact.h>
#include <wheelchair_sim/obstacle_discs.h>
#include <wheelchair_sim/sim_params.h>
#include <wheelchair_sim/wheel_plant.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <random>

namespace wheelchair_sim {

class Simulator : public WheelPlant {
 public:
  /// `world` may be null: then there is nothing to collide with.
  Simulator(const wheelchair_description::ChairParams& chair, const SimParams& params,
            std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world);

  void applyWheelTorques(double right, double left, bool brake) override;
  WheelReading readWheels() const override;

  /// Advances simulated time by dt [s] (> 0) in RK4 steps of at most 1 / physics_rate.
  /// While in collision the chair is held at rest.
  void step(double dt);

  /// Puts the chair at rest with its axle centre (base_link) at `pose` and clears the
  /// collision flag. Returns false (and leaves everything unchanged) if that pose is not finite
  /// or collides. Wheel angles are kept (the encoders do not see a teleport).
  bool teleport(const wheelchair_core::Pose2D& pose);

  /// Sets the full state x of eq. 15 (e.g. an initial speed); keeps time and collision flag.
  void setState(const wheelchair_description::State& x) { x_ = x; }

  double time() const { return time_; }
  const wheelchair_description::State& state() const { return x_; }
  /// Ground-truth pose of base_link (axle centre P) in the world, yaw in [-pi, pi]. The chair
  /// starts at rest at the origin.
  wheelchair_core::Pose2D pose() const;
  /// Forward speed of P and yaw rate (eq. 10-11 of the wheel speeds).
  wheelchair_core::BodyTwist velocity() const;
  /// Torques that reached the wheels in the last RK4 step [right, left] (after limit and
  /// resistances).
  const Eigen::Vector2d& appliedTorques() const { return applied_; }
  bool collided() const { return collided_; }
  /// Does the footprint with base_link at `pose` overlap the map or an obstacle disc present
  /// now?
  bool collides(const wheelchair_core::Pose2D& pose) const;
  /// Obstacles that are not in the map (people); the laser sees them too.
  ObstacleDiscs& obstacles() { return obstacles_; }
  const ObstacleDiscs& obstacles() const { return obstacles_; }
  const wheelchair_description::ChairParams& chair() const { return chair_; }

 private:
  void integrate(double h);
  void addSlip(const Eigen::Vector2d& wheel_increment);
  bool touchesDisc(const wheelchair_core::Pose2D& pose) const;

  wheelchair_description::ChairParams chair_;
  SimParams params_;
  std::optional<BodyContact> contact_;
  ObstacleDiscs obstacles_;
  wheelchair_description::State x_ = wheelchair_description::State::Zero();
  Eigen::Vector2d command_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d applied_ = Eigen::Vector2d::Zero();
  bool brake_ = false;
  bool collided_ = false;
  double time_ = 0.0;
  std::mt19937_64 rng_;
};

}  // namespace wheelchair_sim
