// Reverse tracking (README, "Reverse"): the output point behind the axle, P_r = P - L_r h, gives
// zero dynamics that are stable when the chair backs up, where the paper's P_l = P + L h (eq. 18)
// leaves the heading unstable; the tracker follows straight and curved reverse pieces on the
// dynamic model, stops at every cusp, and keeps the comfort limits across it.
#include <wheelchair_controller/linearization.h>
#include <wheelchair_controller/outer_law.h>
#include <wheelchair_controller_test/closed_loop_simulation.h>
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;
using wheelchair_core::Pose2D;

namespace {

wd::ChairParams chair() { return wd::test::shippedChair(); }

wc::PlantConfig mismatchedPlant() { return wc::heavierRiderPlant(chair()); }

bool entered(const wc::ClosedLoopResult& r, wc::TrackerState state) {
  return std::any_of(r.trace.begin(), r.trace.end(),
                     [&](const wc::TraceSample& s) { return s.state == state; });
}

/// Largest heading deviation [rad] of the true chair from `heading` while reversing.
double reverseHeadingDeviation(const wc::ClosedLoopResult& r, double heading) {
  double worst = 0.0;
  for (const wc::TraceSample& s : r.trace)
    if (s.state == wc::TrackerState::kReversing)
      worst = std::max(worst, std::abs(std::remainder(s.pose.z() - heading, 2.0 * M_PI)));
  return worst;
}

/// The chair driven by the linearizing law alone (eqs. 18-21 with output offset ell, the outer
/// law, tau = f1 u + f2) on the model, its output referenced to move backwards along -h0 at
/// `speed` from where it stands: returns the heading after `seconds`.
double headingAfterBackingUp(double ell, double speed, double heading_error, double seconds) {
  const wd::ChairParams p = chair();
  wd::State x = wd::stateAtAxlePose(0.0, 0.0, heading_error, p);
  const Eigen::Vector2d h0(1.0, 0.0);
  const Eigen::Vector2d y0 = wc::outputPoint(x.head<5>(), p, ell);
  const wc::OuterGains gains = wc::gainsFromNaturalFrequency(2.5, 1.0);
  const double dt = 0.001;
  for (double t = 0.0; t < seconds; t += dt) {
    wc::OutputReference ref;
    ref.position = y0 - speed * t * h0;
    ref.velocity = -speed * h0;
    const Eigen::Vector2d eta = x.tail<2>();
    const Eigen::Vector2d y = wc::outputPoint(x.head<5>(), p, ell);
    const Eigen::Vector2d v =
        wc::outerLaw(ref, y, wc::outputVelocity(x.head<5>(), eta, p, ell), gains, 0.5);
    const Eigen::Vector2d u = wc::linearizingInput(x.head<5>(), eta, v, p, ell);
    x = wd::integrateRK4(x, wc::computedTorque(x.head<5>(), eta, u, p), dt, p);
  }
  return x(wd::kTheta);
}

}  // namespace

TEST(ReverseLinearization, DecouplingBehindTheAxleIsInvertibleWithTheMirroredDeterminant) {
  const wd::ChairParams p = chair();
  const double c = p.wheel_radius / (2.0 * p.half_track), lr = 0.15;
  wd::Vector5 q = wd::stateAtAxlePose(0.4, -1.0, 2.3, p).head<5>();
  EXPECT_NEAR(wc::decouplingMatrix(q, p, -lr).determinant(), 2.0 * p.half_track * lr * c * c,
              1e-12);
  // The output really lies L_r behind the axle P: P_c + (d - L_r) h.
  const Eigen::Vector2d axle(0.4, -1.0), h(std::cos(2.3), std::sin(2.3));
  EXPECT_NEAR((wc::outputPoint(q, p, -lr) - (axle - lr * h)).norm(), 0.0, 1e-12);
}

TEST(ReverseLinearization, ZeroDynamicsAreStableBehindTheAxleAndUnstableAheadWhenBackingUp) {
  // Output held on a reference moving at V along phi = 0, the chair facing pi + e (backing up):
  // theta_dot = (1/ell) n(theta) . y_dot_ref, so de/dt = -(V/ell) sin(e) ~ -(V/ell) e... with
  // the sign of ell: decays for ell < 0 (P_r), grows for ell > 0 (P_l).
  const Eigen::Vector2d y_dot(0.3, 0.0);
  const double e = 0.05, L = 0.15;
  const double behind = wc::zeroDynamicsHeadingRate(M_PI + e, y_dot, -L);
  const double ahead = wc::zeroDynamicsHeadingRate(M_PI + e, y_dot, L);
  EXPECT_LT(behind * e, 0.0) << "P_r: the heading error shrinks";
  EXPECT_GT(ahead * e, 0.0) << "P_l: the heading error grows";
  EXPECT_NEAR(behind, -0.3 / L * std::sin(e), 1e-12);
  // Driving forwards it is the other way round (the paper's case).
  EXPECT_LT(wc::zeroDynamicsHeadingRate(e, y_dot, L) * e, 0.0);
}

TEST(ReverseLinearization, OnTheDynamicModelThePaperPointTurnsTheChairAroundWhileBackingUp) {
  // The same linearizing law on the full model: backing up 0.3 m/s for 6 s from a 0.1 rad
  // heading error. With P_r behind the axle the heading settles (bounded zero dynamics); with
  // the paper's P_l ahead the output is tracked too, but the chair swings round to face its
  // motion (the unstable internal dynamics: it ends up driving forwards).
  const double with_pr = headingAfterBackingUp(-0.15, 0.3, 0.1, 6.0);
  const double with_pl = headingAfterBackingUp(0.15, 0.3, 0.1, 6.0);
  EXPECT_LT(std::abs(std::remainder(with_pr, 2.0 * M_PI)), 0.01) << with_pr;
  EXPECT_GT(std::abs(std::remainder(with_pl, 2.0 * M_PI)), 2.5) << with_pl;
}

TEST(ReverseTracking, BacksUpAStraightLineWithTheHeadingHeld) {
  const std::vector<Pose2D> path = wc::PathBuilder({0.0, 0.0, 0.0}).reverse().straight(2.0).poses();
  const wc::ClosedLoopResult r =
      wc::simulateClosedLoop(path, path.front(), chair(), wc::TrackerConfig{}, mismatchedPlant());
  ASSERT_EQ(r.final_state, wc::TrackerState::kGoalReached) << r.reason;
  EXPECT_TRUE(entered(r, wc::TrackerState::kReversing));
  EXPECT_FALSE(entered(r, wc::TrackerState::kAligning)) << "no turn before backing up";
  EXPECT_LT(reverseHeadingDeviation(r, 0.0), 0.02);
  EXPECT_LT(r.final_position_error, 0.02);
  EXPECT_LT(std::abs(r.final_heading_error), 0.05);
  EXPECT_LE(r.max_speed, 0.3 * 1.02);
  EXPECT_LT(r.body_deviation_max, 0.02);
  EXPECT_LT(r.mse_cm2, 0.5);
}

TEST(ReverseTracking, BacksUpAQuarterTurnWithTheBodyOnThePath) {
  // Backing out of a doorway: 0.5 m straight back, then a quarter turn of radius 1 m backwards.
  const std::vector<Pose2D> path = wc::PathBuilder({1.0, 2.0, M_PI / 2})
                                       .reverse()
                                       .straight(0.5)
                                       .arc(1.0, -M_PI / 2)
                                       .straight(0.5)
                                       .poses();
  const wc::ClosedLoopResult r =
      wc::simulateClosedLoop(path, path.front(), chair(), wc::TrackerConfig{}, mismatchedPlant());
  ASSERT_EQ(r.final_state, wc::TrackerState::kGoalReached) << r.reason;
  EXPECT_LT(r.body_deviation_max, 0.03);
  EXPECT_LT(r.final_position_error, 0.03);
  EXPECT_LT(std::abs(r.final_heading_error), 0.05);
  EXPECT_LE(r.max_speed, 0.3 * 1.02);
  EXPECT_LE(r.max_accel, 0.5);
  EXPECT_LE(r.max_jerk, 1.0);
  RecordProperty("mse_cm2", std::to_string(r.mse_cm2));
}

TEST(ReverseTracking, StopsAtTheCuspAndKeepsTheComfortLimitsAcrossIt) {
  // Three-point turn: forward left, back right (the tail swings), forward left again.
  const std::vector<Pose2D> path = wc::threePointTurnPath();
  ASSERT_EQ(wheelchair_core::cuspCount(path), 2u);
  const wc::ClosedLoopResult r =
      wc::simulateClosedLoop(path, path.front(), chair(), wc::TrackerConfig{}, mismatchedPlant());
  ASSERT_EQ(r.final_state, wc::TrackerState::kGoalReached) << r.reason;
  EXPECT_LE(r.max_accel, 0.5) << "at t=" << r.max_accel_time;
  EXPECT_LE(r.max_jerk, 1.0) << "at t=" << r.max_jerk_time;
  EXPECT_LT(r.body_deviation_max, 0.03);
  EXPECT_LT(r.final_position_error, 0.03);
  // Direction changes only at rest: between a forward and a reverse sample the chair stood.
  int changes = 0;
  wc::TrackerState last = wc::TrackerState::kIdle;
  for (size_t i = 0; i < r.trace.size(); ++i) {
    const wc::TrackerState s = r.trace[i].state;
    if ((s == wc::TrackerState::kTracking || s == wc::TrackerState::kReversing) && s != last &&
        (last == wc::TrackerState::kTracking || last == wc::TrackerState::kReversing)) {
      ++changes;
      ASSERT_GT(i, 1u);
      const Eigen::Vector3d& a = r.trace[i - 1].pose;
      const Eigen::Vector3d& b = r.trace[i].pose;
      EXPECT_LT((b - a).head<2>().norm() / (r.trace[i].t - r.trace[i - 1].t), 0.02)
          << "moving when the direction changed at t=" << r.trace[i].t;
    }
    if (s == wc::TrackerState::kTracking || s == wc::TrackerState::kReversing) last = s;
  }
  EXPECT_EQ(changes, 2);
}

TEST(ReverseTracking, ANewPathTheOtherWayWhileMovingBrakesFirst) {
  // Driving forwards at speed, the chair gets a path that backs up: it brakes to rest within
  // the comfort limits before the reverse piece starts.
  const wd::ChairParams model = chair();
  wc::PathTracker tracker(model, wc::TrackerConfig{});
  const wc::PlantConfig plant = mismatchedPlant();
  wd::State x = wd::stateAtAxlePose(0.0, 0.0, 0.0, plant.chair);
  ASSERT_TRUE(tracker.setPath(wc::PathBuilder({0.0, 0.0, 0.0}).straight(6.0).poses()).empty());
  const double dt = 0.02;
  bool switched = false;
  double min_speed_after_switch = 1e9, speed_at_switch = 0.0;
  for (double t = 0.0; t < 30.0; t += dt) {
    const Eigen::Vector3d pose = wd::axlePose(x, plant.chair);
    const double speed = wd::bodyVelocity(x.tail<2>(), plant.chair)(0);
    if (!switched && speed > 0.4) {
      switched = true;
      speed_at_switch = speed;
      const std::vector<Pose2D> back =
          wc::PathBuilder({pose.x(), pose.y(), pose.z()}).reverse().straight(1.0).poses();
      ASSERT_TRUE(tracker.setPath(back).empty());
    }
    const wc::TrackerOutput out =
        tracker.update(t, wc::PoseMeasurement{t, {pose.x(), pose.y(), pose.z()}}, {t, x.tail<2>()});
    if (switched) {
      if (out.state == wc::TrackerState::kReversing) {
        ASSERT_LT(min_speed_after_switch, 0.02) << "reversed without stopping first";
      } else {
        min_speed_after_switch = std::min(min_speed_after_switch, std::abs(speed));
      }
    }
    if (out.state == wc::TrackerState::kGoalReached || out.state == wc::TrackerState::kAborted) {
      EXPECT_EQ(out.state, wc::TrackerState::kGoalReached) << tracker.reason();
      break;
    }
    Eigen::Vector2d tau =
        out.command.torque - wc::rollingResistanceTorque(x.tail<2>(), plant.chair);
    if (out.command.brake) {
      x.tail<2>().setZero();
      continue;
    }
    for (int i = 0; i < 20; ++i) x = wd::integrateRK4(x, tau, dt / 20, plant.chair);
  }
  EXPECT_TRUE(switched);
  EXPECT_GT(speed_at_switch, 0.4);
  EXPECT_EQ(tracker.state(), wc::TrackerState::kGoalReached) << tracker.reason();
}
