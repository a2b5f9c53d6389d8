#include <wheelchair_sim/simulator.h>
#include <wheelchair_sim/wheel_torques.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_sim {

namespace wd = wheelchair_description;

Simulator::Simulator(const wd::ChairParams& chair, const SimParams& params,
                     std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world)
    : chair_(chair), params_(params), rng_(static_cast<uint64_t>(params.seed)) {
  wd::validate(chair_);
  validate(params_);
  if (world) checker_.emplace(chair_.footprint, std::move(world));
  x_ = wd::stateAtAxlePose(0.0, 0.0, 0.0, chair_);
}

void Simulator::applyWheelTorques(double right, double left, bool brake) {
  command_ = {right, left};
  brake_ = brake;
}

WheelReading Simulator::readWheels() const {
  WheelReading r;
  r.angle = {x_(wd::kPsiR), x_(wd::kPsiL)};
  r.rate = {x_(wd::kEtaR), x_(wd::kEtaL)};
  return r;
}

void Simulator::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("step: dt must be > 0");
  const int n = static_cast<int>(std::ceil(dt * params_.physics_rate - 1e-9));
  const double h = dt / n;
  for (int i = 0; i < n; ++i) integrate(h);
  time_ += dt;
}

void Simulator::integrate(double h) {
  if (collided_) return;  // held at rest until teleported
  const wd::State before = x_;
  // Torques are held over the RK4 step (zero-order hold, like a motor controller's PWM).
  applied_ = wheelTorques(command_, brake_, x_.tail<2>(), chair_, params_);
  x_ = wd::integrateRK4(x_, applied_, h, chair_);
  if (params_.slip_noise > 0.0) addSlip(x_.segment<2>(wd::kPsiR) - before.segment<2>(wd::kPsiR));
  if ((checker_ && checker_->outlineCollides(pose())) || touchesDisc(pose())) {
    x_ = before;
    x_.tail<2>().setZero();
    collided_ = true;
  }
}

// Each wheel's contact point slips by a random distance whose variance grows with the
// distance it rolled (sigma^2 = slip_noise^2 * r |dpsi|): the body moves as if the wheel had
// turned a little more or less than the encoder says.
void Simulator::addSlip(const Eigen::Vector2d& wheel_increment) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector2d slip;
  for (int i = 0; i < 2; ++i) {
    const double rolled = chair_.wheel_radius * std::abs(wheel_increment(i));
    slip(i) = params_.slip_noise * std::sqrt(rolled) * normal(rng_);
  }
  Eigen::Vector3d p = pose();
  const double forward = 0.5 * (slip(0) + slip(1));
  p.z() += 0.5 * (slip(0) - slip(1)) / chair_.half_track;
  p.x() += forward * std::cos(p.z());
  p.y() += forward * std::sin(p.z());
  const wd::State moved = wd::stateAtAxlePose(p.x(), p.y(), p.z(), chair_);
  x_.head<3>() = moved.head<3>();
}

bool Simulator::teleport(double x, double y, double yaw) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw)) return false;
  const Eigen::Vector3d target(x, y, std::remainder(yaw, 2.0 * M_PI));
  if (collides(target)) return false;
  const Eigen::Vector2d wheels = x_.segment<2>(wd::kPsiR);
  x_ = wd::stateAtAxlePose(target.x(), target.y(), target.z(), chair_);
  x_.segment<2>(wd::kPsiR) = wheels;
  collided_ = false;
  return true;
}

Eigen::Vector3d Simulator::pose() const {
  Eigen::Vector3d p = wd::axlePose(x_, chair_);
  p.z() = std::remainder(p.z(), 2.0 * M_PI);
  return p;
}

Eigen::Vector2d Simulator::velocity() const { return wd::bodyVelocity(x_.tail<2>(), chair_); }

bool Simulator::collides(const Eigen::Vector3d& p) const {
  return (checker_ && checker_->collides(p)) || touchesDisc(p);
}

bool Simulator::touchesDisc(const Eigen::Vector3d& p) const {
  if (obstacles_.all().empty()) return false;
  const std::vector<Disc> present = obstacles_.presentAt(time_);
  if (present.empty()) return false;
  const double c = std::cos(p.z()), s = std::sin(p.z());
  std::vector<Eigen::Vector2d> outline;
  for (const Eigen::Vector2d& v : chair_.footprint)
    outline.emplace_back(p.x() + c * v.x() - s * v.y(), p.y() + s * v.x() + c * v.y());
  return polygonTouchesDiscs(outline, present);
}

}  // namespace wheelchair_sim
