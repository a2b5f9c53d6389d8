// The safety supervisor's speed limit (/safety/speed_limit, PathTracker::setSpeedLimit): the
// governor slows the reference to it without a stop, and the chair speeds up again when it is
// lifted.
#include <wheelchair_controller/path_tracker.h>
#include <wheelchair_controller_test/axle_pose.h>
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;

namespace {

/// An 8 m straight at 50 Hz on the model itself; `limits`: time [s] -> speed limit from then
/// on. Returns the axle speed [m/s] at every step, and the tracker's last output.
std::vector<double> drive(const std::map<double, double>& limits, wc::TrackerOutput* last) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  tracker.setPath(wc::PathBuilder({0.0, 0.0, 0.0}).straight(8.0).poses());
  wd::State x = wd::stateAtAxlePose(0.0, 0.0, 0.0, p);
  std::vector<double> speeds;
  const double dt = 0.02;
  for (int k = 0; k < 2500; ++k) {
    const double t = k * dt;
    const auto limit = limits.upper_bound(t);
    if (limit != limits.begin()) tracker.setSpeedLimit(std::prev(limit)->second);
    *last = tracker.update(t, wc::PoseMeasurement{t, wc::axlePose2D(x, p)}, {t, x.tail<2>()});
    speeds.push_back(wd::bodyVelocity(x.tail<2>(), p)(0));
    if (last->state == wc::TrackerState::kGoalReached) break;
    if (last->command.brake)
      x.tail<2>().setZero();
    else
      for (int i = 0; i < 20; ++i) x = wd::integrateRK4(x, last->command.torque, 1e-3, p);
  }
  return speeds;
}

double maxBetween(const std::vector<double>& v, double from, double to) {
  double m = 0.0;
  for (size_t k = static_cast<size_t>(from / 0.02); k < v.size() && k * 0.02 < to; ++k)
    m = std::max(m, v[k]);
  return m;
}

}  // namespace

TEST(SpeedLimit, TheChairSlowsToTheLimitWithoutAStopAndGoesOnWhenItIsLifted) {
  wc::TrackerOutput free_run, limited;
  const auto free_speeds = drive({}, &free_run);
  ASSERT_EQ(free_run.state, wc::TrackerState::kGoalReached);
  EXPECT_GT(maxBetween(free_speeds, 3.0, 6.0), 0.7) << "cruises near 0.8 m/s unlimited";

  const auto speeds = drive({{3.0, 0.3}, {9.0, INFINITY}}, &limited);
  EXPECT_LT(maxBetween(speeds, 5.0, 9.0), 0.3 + 0.03) << "at most the limit, 2 s after it came";
  EXPECT_GT(maxBetween(speeds, 5.0, 9.0), 0.25) << "and still driving";
  EXPECT_EQ(limited.state, wc::TrackerState::kGoalReached) << limited.reason;
  EXPECT_GT(speeds.size(), free_speeds.size()) << "later than unlimited";
}

TEST(SpeedLimit, ALimitOfZeroHoldsTheChairWithoutAbortingAndNaNCountsAsZero) {
  wc::TrackerOutput last;
  const auto speeds = drive({{2.0, NAN}}, &last);
  // The reference stands still; only P_l is controlled, so the body may creep about it.
  EXPECT_LT(maxBetween(speeds, 20.0, 50.0), 0.05)
      << "held near rest; " << wc::toString(last.state) << ", rate " << last.reference_rate;
  EXPECT_EQ(last.reference_rate, 0.0);
  EXPECT_NE(last.state, wc::TrackerState::kAborted) << last.reason;
}
