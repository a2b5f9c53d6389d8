#include "reeds_shepp.h"

#include <wheelchair_core/kinematics.h>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace wheelchair_planner {

namespace {

/// The pose after `d` metres on an arc of curvature `kappa` (d < 0: in reverse).
Pose2D along(const Pose2D& p, double kappa, double d) {
  return wheelchair_core::integrateArc(p, {d, kappa * d});
}

}  // namespace

ReedsSheppShot reedsSheppShot(const Pose2D& from, const Pose2D& to, double radius, double step) {
  namespace ob = ompl::base;
  auto space = std::make_shared<ob::ReedsSheppStateSpace>(radius);
  ob::ScopedState<ob::SE2StateSpace> a(space), b(space);
  a->setXY(from.x, from.y);
  a->setYaw(from.yaw);
  b->setXY(to.x, to.y);
  b->setYaw(to.yaw);
  const ob::ReedsSheppStateSpace::ReedsSheppPath path = space->reedsShepp(a.get(), b.get());
  ReedsSheppShot shot;
  shot.poses.push_back(from);
  shot.shortest_run = std::numeric_limits<double>::infinity();
  double run = 0.0;
  int last_sign = 0;
  for (int i = 0; i < 5; ++i) {
    // Segment lengths are in units of the radius, negative in reverse (OMPL's convention).
    const double d = path.length_[i] * radius;
    if (path.type_[i] == ob::ReedsSheppStateSpace::RS_NOP || std::abs(d) < 1e-9) continue;
    const double kappa = path.type_[i] == ob::ReedsSheppStateSpace::RS_LEFT    ? 1.0 / radius
                         : path.type_[i] == ob::ReedsSheppStateSpace::RS_RIGHT ? -1.0 / radius
                                                                               : 0.0;
    const int sign = d > 0.0 ? 1 : -1;
    if (last_sign == 0) {
      shot.first_reverse = sign < 0;
    } else if (sign != last_sign) {
      ++shot.cusps;
      shot.shortest_run = std::min(shot.shortest_run, run);
      run = 0.0;
    }
    last_sign = sign;
    run += std::abs(d);
    shot.length += std::abs(d);
    if (sign < 0) shot.reversed += std::abs(d);
    const Pose2D start = shot.poses.back();
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(d) / step)));
    for (int k = 1; k <= n; ++k) shot.poses.push_back(along(start, kappa, d * k / n));
  }
  shot.shortest_run = std::min(shot.shortest_run, run);
  shot.poses.back().yaw = to.yaw;  // exact, not the integrated heading
  return shot;
}

}  // namespace wheelchair_planner
