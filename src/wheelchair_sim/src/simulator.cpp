#include <wheelchair_sim/simulator.h>
#include <wheelchair_sim/wheel_torques.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_sim {

namespace wd = wheelchair_description;
namespace core = wheelchair_core;

Simulator::Simulator(const wd::ChairParams& chair, const SimParams& params,
                     std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world)
    : chair_(chair), params_(params), rng_(static_cast<uint64_t>(params.seed)) {
  for (const std::string& problem : {chair_.validate(), params_.validate()})
    if (!problem.empty()) throw std::invalid_argument("simulator: " + problem);
  if (world) contact_.emplace(chair_.footprint, std::move(world));
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
  if ((contact_ && contact_->outlineTouches(pose())) || touchesDisc(pose())) {
    x_ = before;
    x_.tail<2>().setZero();
    collided_ = true;
  }
}

// Each wheel's contact point slips by a random distance whose variance grows with the
// distance it rolled (sigma^2 = slip_noise^2 * r |dpsi|): the body moves as if the wheel had
// turned a little more or less than the encoder says (eq. 10-11 of the two slips).
void Simulator::addSlip(const Eigen::Vector2d& wheel_increment) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector2d slip;
  for (int i = 0; i < 2; ++i) {
    const double rolled = chair_.wheel_radius * std::abs(wheel_increment(i));
    slip(i) = params_.slip_noise * std::sqrt(rolled) * normal(rng_);
  }
  const core::Pose2D p =
      core::integrateArc(pose(), core::bodyMotion(slip(0), slip(1), chair_.half_track));
  const wd::State moved = wd::stateAtAxlePose(p.x, p.y, p.yaw, chair_);
  x_.head<3>() = moved.head<3>();
}

bool Simulator::teleport(const core::Pose2D& pose) {
  if (!pose.isFinite()) return false;
  const core::Pose2D target{pose.x, pose.y, core::normalizeAngle(pose.yaw)};
  if (collides(target)) return false;
  const Eigen::Vector2d wheels = x_.segment<2>(wd::kPsiR);
  x_ = wd::stateAtAxlePose(target.x, target.y, target.yaw, chair_);
  x_.segment<2>(wd::kPsiR) = wheels;
  collided_ = false;
  return true;
}

core::Pose2D Simulator::pose() const {
  const Eigen::Vector3d p = wd::axlePose(x_, chair_);
  return {p.x(), p.y(), core::normalizeAngle(p.z())};
}

core::BodyTwist Simulator::velocity() const {
  return core::bodyTwist({x_(wd::kEtaR), x_(wd::kEtaL)}, chair_.wheelBase());
}

bool Simulator::collides(const core::Pose2D& p) const {
  return (contact_ && contact_->touches(p)) || touchesDisc(p);
}

bool Simulator::touchesDisc(const core::Pose2D& p) const {
  if (obstacles_.all().empty()) return false;
  const std::vector<Disc> present = obstacles_.presentAt(time_);
  if (present.empty()) return false;
  return polygonTouchesDiscs(core::transformPolygon(chair_.footprint, p), present);
}

}  // namespace wheelchair_sim
