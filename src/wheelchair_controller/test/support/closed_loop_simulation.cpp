#include <wheelchair_controller_test/closed_loop_simulation.h>
#include <wheelchair_controller_test/wheel_speed_estimator.h>
#include <wheelchair_sim/simulator.h>

#include <chrono>
#include <cmath>
#include <deque>
#include <random>

namespace wheelchair_controller {
namespace wd = wheelchair_description;

namespace {

constexpr double kConvergedError = 0.02;  // [m]

/// Rider (centre of mass P_c) velocity.
Eigen::Vector2d riderVelocity(const wd::State& x, const ChairParams& p) {
  return (wd::nullSpaceBasis(x.head<5>(), p) * x.tail<2>()).head<2>();
}

Eigen::Vector2d quantize(const Eigen::Vector2d& angles, double ticks_per_rev) {
  if (ticks_per_rev <= 0.0) return angles;
  const double tick = 2.0 * M_PI / ticks_per_rev;
  return (angles / tick).array().floor().matrix() * tick;
}

bool active(TrackerState s) {
  return s == TrackerState::kAligning || s == TrackerState::kTracking ||
         s == TrackerState::kReversing || s == TrackerState::kRotatingToGoal;
}

}  // namespace

ClosedLoopResult simulateClosedLoop(const std::vector<Pose2D>& path, const Pose2D& start,
                                    const ChairParams& model, const TrackerConfig& config,
                                    const PlantConfig& plant) {
  ClosedLoopResult res;
  PathTracker tracker(model, config);
  std::mt19937 rng(plant.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  WheelSpeedEstimator wheels;

  const ChairParams& chair = plant.chair;
  // The real chair is the simulator's (wheelchair_sim: eq. 15 by RK4, rolling resistance, the
  // parking brake), without a world to collide with.
  wheelchair_sim::SimParams sim_params;
  sim_params.physics_rate = plant.physics_rate;
  sim_params.rolling_resistance = plant.rolling_resistance;
  // The same smoothing of the resistance's sign as the controller's model of it
  // (rollingResistanceTorque: 2 cm/s of rim speed), so that a plant with the model's parameters
  // is the model; a mismatch is what PlantConfig::chair says.
  sim_params.resistance_smoothing = 0.02 / chair.wheel_radius;
  wheelchair_sim::Simulator chair_sim(chair, sim_params, nullptr);
  chair_sim.setState(wd::stateAtAxlePose(start.x, start.y, start.yaw, chair));
  const wd::State* state = &chair_sim.state();
  const double dt_ctrl = 1.0 / plant.control_rate;
  const int noise_period =
      std::max(1, static_cast<int>(std::round(plant.control_rate / plant.pose_noise_rate)));
  Eigen::Vector3d pose_error = Eigen::Vector3d::Zero();
  const int window = std::max(1, static_cast<int>(std::round(plant.comfort_window / dt_ctrl)));

  std::deque<Eigen::Vector2d> rider_v, rider_a;  // histories for the comfort averages
  double err2_sum = 0.0, dev2_sum = 0.0, travelled = 0.0;
  int active_steps = 0;
  tracker.setPath(path);
  wheels.update(-dt_ctrl, quantize(state->segment<2>(wd::kPsiR), plant.encoder_ticks_per_rev));

  for (int k = 0; k * dt_ctrl < plant.max_time; ++k) {
    const double t = k * dt_ctrl;
    const wd::State& x = *state;
    const Eigen::Vector3d truth = wd::axlePose(x, chair);
    if (k % noise_period == 0) {
      pose_error = {plant.pose_noise_xy * noise(rng), plant.pose_noise_xy * noise(rng),
                    plant.pose_noise_theta * noise(rng)};
    }
    const bool corrected =
        plant.localization_correction_time >= 0.0 && t >= plant.localization_correction_time;
    const Eigen::Vector3d measured =
        truth + pose_error + (corrected ? plant.localization_correction : Eigen::Vector3d::Zero());
    const PoseMeasurement pose{t, {measured.x(), measured.y(), measured.z()}};
    const Eigen::Vector2d eta =
        wheels.update(t, quantize(x.segment<2>(wd::kPsiR), plant.encoder_ticks_per_rev));

    const auto t0 = std::chrono::steady_clock::now();
    const TrackerOutput out = tracker.update(t, pose, {t, eta});
    res.step_seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());

    // The true output point the tracker controls in this phase (P_l, or P_r in reverse).
    const Eigen::Vector2d y_true =
        outputPoint(x.head<5>(), chair, out.has_reference ? out.output_offset : model.lookahead);
    if (out.has_reference && active(out.state)) {
      const double e = (y_true - out.reference.position).norm();
      err2_sum += e * e;
      res.max_error = std::max(res.max_error, e);
      if (e > kConvergedError) res.convergence_distance = travelled;
      const bool on_path =
          tracker.state() == TrackerState::kTracking || tracker.state() == TrackerState::kReversing;
      const double dev = on_path ? out.body_deviation : 0.0;
      dev2_sum += dev * dev;
      res.body_deviation_max = std::max(res.body_deviation_max, dev);
      ++active_steps;
    }
    res.trace.push_back({t, y_true, out.reference.position, truth, out.command.torque, out.state});
    res.max_torque = std::max(res.max_torque, out.command.torque.cwiseAbs().maxCoeff());

    // Comfort: accelerations and jerks of the rider averaged over the comfort window.
    rider_v.push_back(riderVelocity(x, chair));
    if (static_cast<int>(rider_v.size()) > window) {
      rider_a.push_back((rider_v.back() - rider_v.front()) / (window * dt_ctrl));
      rider_v.pop_front();
      if (rider_a.back().norm() > res.max_accel) {
        res.max_accel = rider_a.back().norm();
        res.max_accel_time = t;
      }
    }
    if (static_cast<int>(rider_a.size()) > window) {
      const double jerk = ((rider_a.back() - rider_a.front()) / (window * dt_ctrl)).norm();
      if (jerk > res.max_jerk) {
        res.max_jerk = jerk;
        res.max_jerk_time = t;
      }
      rider_a.pop_front();
    }

    if (out.state == TrackerState::kGoalReached || out.state == TrackerState::kAborted) {
      res.duration = t;
      break;
    }
    // The plant, for one control period: the command held (zero-order hold) while the
    // simulator integrates; torques [right, left], the brake engages the parking brakes.
    const Eigen::Vector3d before = truth;
    chair_sim.applyWheelTorques(out.command.torque(0), out.command.torque(1), out.command.brake);
    chair_sim.step(dt_ctrl);
    travelled += (wd::axlePose(*state, chair) - before).head<2>().norm();
    res.max_speed = std::max(res.max_speed, std::abs(wd::bodyVelocity(state->tail<2>(), chair)(0)));
    res.duration = t;
  }
  const wd::State& x = *state;
  res.final_state = tracker.state();
  res.reason = tracker.reason();
  res.mse_cm2 = active_steps ? 1e4 * err2_sum / active_steps : 0.0;
  res.body_deviation_rms = active_steps ? std::sqrt(dev2_sum / active_steps) : 0.0;
  const Eigen::Vector3d end = wd::axlePose(x, chair);
  res.final_position_error = (end.head<2>() - path.back().position()).norm();
  res.final_heading_error = std::remainder(end.z() - path.back().yaw, 2.0 * M_PI);
  return res;
}

PlantConfig heavierRiderPlant(const ChairParams& chair) {
  PlantConfig plant;
  plant.chair = chair;
  plant.chair.total_mass += 15.0;
  plant.chair.body_inertia *= 1.15;
  return plant;
}

}  // namespace wheelchair_controller
