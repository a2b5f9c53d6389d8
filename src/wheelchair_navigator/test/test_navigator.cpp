// The navigator's state machine, event by event, against what the issue asks of a drive: one
// result per goal, refusals with the rider's sentence, waiting for something in the way and
// going on the same way when it leaves, a way around it, blocked with where, cancel and every
// failure through a controlled stop, bounded retries each with its reason, no progress.
#include <wheelchair_navigator/navigator.h>

#include "test_world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_navigator {
namespace {

using wheelchair_navigator_test::chairFootprint;
using wheelchair_navigator_test::kHalfWidth;
using wheelchair_navigator_test::straight;
using wheelchair_navigator_test::testRoom;

const Pose2D kStart{1.5, 2.5, 0.0};
const Pose2D kGoal{5.5, 2.5, 0.0};

SafetyInput clear() { return SafetyInput(); }
SafetyInput stopFor(SafetyCause cause, const std::string& sentence = "something is in the way") {
  SafetyInput s;
  s.stop = true;
  s.cause = cause;
  s.sentence = sentence;
  s.detail = "detail for the log";
  return s;
}

/// A navigator in the test room, localized at kStart, the supervisor clear, with one named place.
class NavigatorTest : public ::testing::Test {
 protected:
  explicit NavigatorTest(NavigatorConfig config = NavigatorConfig()) : nav(config) {
    nav.setMap(testRoom(), chairFootprint(), kHalfWidth);
    nav.setPlaces({{"kitchen_door", {4.0, 3.0}}, {"sofa", {9.0, 4.5}}});
    nav.onLocalization(true, "", t);
    nav.onSafety(clear(), t);
    nav.onPose(kStart, t);
  }

  GoalRequest goal(const std::string& id = "g1", Pose2D pose = kGoal,
                   const std::string& place = "") {
    GoalRequest g;
    g.id = id;
    g.pose = pose;
    g.place = place;
    return g;
  }

  /// Starts a drive and answers its first route with a straight line: returns the path id.
  int startDriving(const std::string& id = "g1") {
    const Output started = nav.start(goal(id, kGoal, "kitchen_door"), t);
    EXPECT_TRUE(started.plan.has_value());
    const Output driving = nav.onPlanAnswer(started.plan->id, route(), t);
    EXPECT_TRUE(driving.path.has_value());
    EXPECT_EQ(nav.state(), State::kDriving);
    return driving.path->id;
  }

  static PlanAnswer route(std::vector<Pose2D> poses = straight(1.5, 2.5, 5.5, 2.5)) {
    PlanAnswer a;
    a.success = true;
    a.path = std::move(poses);
    a.planning_time = 0.02;
    return a;
  }
  static PlanAnswer noRoute(const std::string& why = "start and goal are not connected") {
    PlanAnswer a;
    a.detail = why;
    return a;
  }

  /// Ticks every 0.1 s until `until`, collecting every output.
  std::vector<Output> runUntil(double until) {
    std::vector<Output> outs;
    while (t < until - 1e-9) {
      t += 0.1;
      outs.push_back(nav.tick(t));
    }
    return outs;
  }
  static std::vector<DriveResult> resultsOf(const std::vector<Output>& outs) {
    std::vector<DriveResult> r;
    for (const auto& o : outs) r.insert(r.end(), o.results.begin(), o.results.end());
    return r;
  }
  /// The last planner request among `outs` (earlier ones are superseded).
  static const PlanRequest* planOf(const std::vector<Output>& outs) {
    for (auto o = outs.rbegin(); o != outs.rend(); ++o)
      if (o->plan) return &*o->plan;
    return nullptr;
  }
  /// Ticks every 0.1 s until `until`, answering every planner request with `answer` at once.
  std::vector<Output> runAnswering(double until, const PlanAnswer& answer) {
    std::vector<Output> outs;
    while (t < until - 1e-9) {
      t += 0.1;
      outs.push_back(nav.tick(t));
      if (outs.back().plan) outs.push_back(nav.onPlanAnswer(outs.back().plan->id, answer, t));
    }
    return outs;
  }
  static int releasesOf(const std::vector<Output>& outs) {
    int n = 0;
    for (const auto& o : outs) n += o.release_safety;
    return n;
  }

  double t = 100.0;
  Navigator nav;
};

TEST_F(NavigatorTest, RefusesAGoalWhileNotLocalizedWithTheRiderSentence) {
  nav.onLocalization(false, "uninitialized: no initial pose", t);
  const Output out = nav.start(goal(), t);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].reason, Reason::kNotLocalized);
  EXPECT_EQ(out.results[0].sentence,
            "I don't know where the chair is yet: set its position first.");
  EXPECT_EQ(out.results[0].detail, "uninitialized: no initial pose");
  EXPECT_TRUE(out.results[0].refused);
  EXPECT_FALSE(out.plan) << "planned from a guess";
  EXPECT_FALSE(out.path);
  EXPECT_FALSE(out.release_safety) << "a refused goal is no command to move";
  EXPECT_FALSE(nav.active());
}

TEST_F(NavigatorTest, RefusesGoalsInAWallOutsideTheMapAndWhereTheBodyDoesNotFit) {
  const struct {
    Pose2D pose;
    Reason reason;
  } cases[] = {{{7.5, 1.5, 0.0}, Reason::kGoalInObstacle},
               {{0.05, 2.5, 0.0}, Reason::kGoalInObstacle},
               {{-2.0, -3.0, 0.0}, Reason::kGoalOutsideMap},
               {{2.2, 5.5, M_PI / 2}, Reason::kGoalNoRoom},
               {{7.5, 2.2, 0.0}, Reason::kGoalNoRoom}};
  for (const auto& c : cases) {
    const Output out = nav.start(goal("g", c.pose), t);
    ASSERT_EQ(out.results.size(), 1u);
    EXPECT_EQ(out.results[0].reason, c.reason) << out.results[0].detail;
    EXPECT_TRUE(out.results[0].refused);
    EXPECT_FALSE(out.plan);
  }
  EXPECT_TRUE(nav.start(goal("free", {5.0, 3.0, 0.0}), t).plan) << "a free goal is planned";
}

TEST_F(NavigatorTest, RefusesWhatTheRosSideFoundWrongAndANonFiniteGoal) {
  GoalRequest g = goal();
  g.refused = Reason::kUnknownPlace;
  g.refused_detail = "no place called 'attic'";
  Output out = nav.start(g, t);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].reason, Reason::kUnknownPlace);
  EXPECT_EQ(out.results[0].detail, "no place called 'attic'");
  out = nav.start(goal("nan", {NAN, 1.0, 0.0}), t);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].reason, Reason::kInvalidGoal);
}

TEST_F(NavigatorTest, WithoutAMapAGoalIsNotReady) {
  Navigator fresh;
  fresh.onLocalization(true, "", t);
  fresh.onPose(kStart, t);
  const Output out = fresh.start(goal(), t);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].reason, Reason::kNotReady);
}

TEST_F(NavigatorTest, AcceptedGoalReleasesTheLatchPlansDrivesAndArrivesWithOneResult) {
  const Output started = nav.start(goal("g1", kGoal, "kitchen_door"), t);
  EXPECT_TRUE(started.release_safety) << "the rider's command releases the supervisor's latch";
  ASSERT_TRUE(started.plan);
  EXPECT_EQ(started.plan->goal.x, kGoal.x);
  EXPECT_EQ(nav.state(), State::kPlanning);
  EXPECT_EQ(nav.feedback().sentence, "Finding a way to kitchen door.");
  const Output driving = nav.onPlanAnswer(started.plan->id, route(), t);
  ASSERT_TRUE(driving.path);
  EXPECT_EQ(driving.path->poses.size(), straight(1.5, 2.5, 5.5, 2.5).size());
  EXPECT_EQ(nav.feedback().sentence, "Going to kitchen door: 4.0 m.");
  EXPECT_NEAR(nav.feedback().distance_remaining, 4.0, 1e-9);
  nav.onPose({3.5, 2.52, 0.0}, t + 5);
  EXPECT_NEAR(nav.feedback().distance_remaining, 2.0, 0.03);
  nav.onPathStatus(driving.path->id, ControllerPhase::kActive, "tracking", t + 5);
  const Output reached =
      nav.onPathStatus(driving.path->id, ControllerPhase::kReached, "goal_reached", t + 10);
  ASSERT_EQ(reached.results.size(), 1u);
  EXPECT_EQ(reached.results[0].reason, Reason::kReached);
  EXPECT_EQ(reached.results[0].goal_id, "g1");
  EXPECT_EQ(reached.results[0].sentence, "Arrived.");
  EXPECT_FALSE(reached.path) << "an arrival is no stop";
  EXPECT_NEAR(reached.results[0].distance_travelled, 2.0, 0.03);
  EXPECT_FALSE(nav.active());
  EXPECT_EQ(nav.state(), State::kIdle);
  EXPECT_EQ(nav.feedback().sentence, "Arrived.") << "a screen shows how the drive ended";
  EXPECT_TRUE(reached.feedback_changed);
  // Nothing that comes later is a second result.
  std::vector<Output> later;
  later.push_back(nav.onPathStatus(driving.path->id, ControllerPhase::kAborted, "x", t + 11));
  later.push_back(nav.onSafety(stopFor(SafetyCause::kOther), t + 11));
  later.push_back(nav.onLocalization(false, "lost", t + 11));
  t += 11;
  for (const auto& o : runUntil(t + 60)) later.push_back(o);
  EXPECT_TRUE(resultsOf(later).empty());
}

TEST_F(NavigatorTest, StatusesOfAnotherRouteAreNotThisDrivesEnd) {
  const int path = startDriving();
  EXPECT_TRUE(
      nav.onPathStatus(path - 1, ControllerPhase::kReached, "goal_reached", t).results.empty());
  EXPECT_TRUE(
      nav.onPathStatus(path + 7, ControllerPhase::kReached, "goal_reached", t).results.empty());
  EXPECT_EQ(nav.state(), State::kDriving);
}

TEST_F(NavigatorTest, NoRouteIsAskedAgainOnceThenEndsWithTheRidersSentenceAndThePlannersWhy) {
  const Output started = nav.start(goal(), t);
  Output out = nav.onPlanAnswer(started.plan->id, noRoute(), t);
  EXPECT_TRUE(out.results.empty());
  const auto outs = runUntil(t + 1.5);
  const PlanRequest* again = planOf(outs);
  ASSERT_NE(again, nullptr) << "no second request";
  out = nav.onPlanAnswer(again->id, noRoute(), t);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].reason, Reason::kNoRoute);
  EXPECT_EQ(out.results[0].sentence,
            "There is no way there that the chair fits through. The chair stays where it is.");
  EXPECT_NE(out.results[0].detail.find("start and goal are not connected"), std::string::npos);
  EXPECT_FALSE(out.path) << "the chair never moved for it: nothing to stop";
}

TEST_F(NavigatorTest, SomethingInTheWayWaitsThenGoesOnTheSameWayWhenItHasGone) {
  const int path = startDriving();
  nav.onPose({2.5, 2.5, 0.0}, t);
  const Output stop = nav.onSafety(stopFor(SafetyCause::kObstacle), t);
  EXPECT_EQ(nav.state(), State::kWaiting);
  EXPECT_EQ(nav.feedback().sentence, "Something is in the way: waiting for it to move.");
  EXPECT_TRUE(stop.feedback_changed);
  EXPECT_FALSE(stop.path) << "the supervisor stops the chair; its watch stays on the route";
  EXPECT_TRUE(stop.results.empty());
  nav.onPathStatus(path, ControllerPhase::kAborted, "aborted: safety stop", t + 1);
  // Still there: the supervisor is asked every probe_period and stops again each time.
  auto outs = runUntil(t + 3.25);
  EXPECT_EQ(releasesOf(outs), 3);
  EXPECT_EQ(planOf(outs), nullptr);
  // Gone: the supervisor stays clear; after clear_confirm the same way again.
  nav.onSafety(clear(), t);
  const double gone = t;
  outs = runUntil(gone + 0.95);
  EXPECT_EQ(planOf(outs), nullptr) << "went on before the way stayed free for clear_confirm";
  outs = runUntil(gone + 1.25);
  const PlanRequest* resume = planOf(outs);
  ASSERT_NE(resume, nullptr);
  const Output driving = nav.onPlanAnswer(resume->id, route(straight(2.5, 2.5, 5.5, 2.5)), t);
  ASSERT_TRUE(driving.path) << "the supervisor is clear: the route goes at once";
  EXPECT_EQ(nav.state(), State::kDriving);
  EXPECT_EQ(nav.feedback().sentence, "The way is free: going on.");
  const Output reached = nav.onPathStatus(driving.path->id, ControllerPhase::kReached, "", t);
  ASSERT_EQ(reached.results.size(), 1u);
  EXPECT_EQ(reached.results[0].reason, Reason::kReached);
  EXPECT_EQ(reached.results[0].waits, 1);
  EXPECT_EQ(reached.results[0].replans, 1);
}

TEST_F(NavigatorTest, AfterWaitingBrieflyItDrivesAWayAroundOnceTheSupervisorWatchesIt) {
  startDriving();
  nav.onPose({2.5, 2.5, 0.0}, t);
  nav.onSafety(stopFor(SafetyCause::kObstacle), t);
  const double stopped = t;
  auto outs = runUntil(stopped + nav.config().wait_for_clear - 0.05);
  EXPECT_EQ(planOf(outs), nullptr) << "asked for a way round before wait_for_clear";
  outs = runUntil(stopped + nav.config().wait_for_clear + 0.15);
  const PlanRequest* around = planOf(outs);
  ASSERT_NE(around, nullptr);
  // A way round the far side of the room: nowhere near the stretch 0.5-1.5 m ahead.
  std::vector<Pose2D> way = straight(2.5, 2.5, 2.5, 4.2);
  const auto rest = straight(2.5, 4.2, 5.5, 2.5);
  way.insert(way.end(), rest.begin() + 1, rest.end());
  const Output first = nav.onPlanAnswer(around->id, route(way), t);
  // The supervisor still holds its stop: the route goes to it first, then its latch is released.
  ASSERT_TRUE(first.path);
  EXPECT_FALSE(first.release_safety);
  outs = runUntil(t + 0.45);
  EXPECT_EQ(releasesOf(outs), 1);
  const Output go = nav.onSafety(clear(), t);
  ASSERT_TRUE(go.path);
  EXPECT_NE(go.path->id, first.path->id) << "the controller needs a route after the hold ended";
  EXPECT_EQ(go.path->poses.size(), way.size());
  EXPECT_EQ(nav.state(), State::kDriving);
  EXPECT_EQ(nav.feedback().sentence.rfind("Going another way to kitchen door: ", 0), 0u);
  EXPECT_EQ(nav.feedback().replans, 1);
}

class BlockedTest : public NavigatorTest {
 protected:
  /// Drives, is stopped by something in the way at (2.5, 2.5), and the only route the planner
  /// has goes straight through it.
  void blockedThroughTheOnlyRoute(bool expect_no_route = true) {
    const int path = startDriving();
    nav.onPose({2.5, 2.5, 0.0}, t);
    nav.onSafety(stopFor(SafetyCause::kObstacle), t);
    nav.onPathStatus(path, ControllerPhase::kAborted, "aborted: safety stop (supervisor)", t);
    stopped = t;
    const auto outs = runUntil(stopped + nav.config().wait_for_clear + 0.15);
    const PlanRequest* around = planOf(outs);
    ASSERT_NE(around, nullptr);
    const Output blocked = nav.onPlanAnswer(around->id, route(straight(2.5, 2.5, 5.5, 2.5)), t);
    if (expect_no_route) EXPECT_FALSE(blocked.path) << "drove into it again";
    EXPECT_TRUE(blocked.results.empty());
  }
  double stopped = 0.0;
};

TEST_F(BlockedTest, TheOnlyRouteThroughItTellsTheRiderWhereAndWaits) {
  blockedThroughTheOnlyRoute();
  EXPECT_EQ(nav.state(), State::kBlocked);
  EXPECT_EQ(nav.feedback().sentence,
            "The way is blocked near kitchen door: the chair waits until it is free.");
  // It asks for a way round again every replan_period and ends after blocked_timeout.
  const auto outs =
      runAnswering(t + nav.config().blocked_timeout + 0.2, route(straight(2.5, 2.5, 5.5, 2.5)));
  int asked = 0;
  for (const auto& o : outs) asked += o.plan.has_value();
  EXPECT_EQ(asked, nav.config().max_replans - 1) << "asked every replan_period up to max_replans";
  const auto results = resultsOf(outs);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].reason, Reason::kBlocked);
  EXPECT_EQ(results[0].sentence,
            "The way is blocked near kitchen door. The chair has stopped: choose a destination "
            "to go on.");
  EXPECT_NE(results[0].detail.find("the only route goes through"), std::string::npos);
}

TEST_F(BlockedTest, NoWayAroundFromThePlannerIsBlockedToo) {
  startDriving();
  nav.onPose({2.5, 2.5, 0.0}, t);
  nav.onSafety(stopFor(SafetyCause::kObstacle), t);
  const auto outs = runUntil(t + nav.config().wait_for_clear + 0.15);
  ASSERT_NE(planOf(outs), nullptr);
  nav.onPlanAnswer(planOf(outs)->id, noRoute("the doorway is blocked"), t);
  EXPECT_EQ(nav.state(), State::kBlocked);
}

TEST_F(BlockedTest, WhenItHasGoneTheChairGoesOnWithoutANewCommand) {
  blockedThroughTheOnlyRoute();
  auto outs = runAnswering(t + 10.0, route(straight(2.5, 2.5, 5.5, 2.5)));
  EXPECT_GE(releasesOf(outs), 9) << "not asking the supervisor whether the way is free";
  EXPECT_EQ(nav.state(), State::kBlocked);
  nav.onSafety(clear(), t);
  outs = runUntil(t + 1.25);
  const PlanRequest* resume = planOf(outs);
  ASSERT_NE(resume, nullptr);
  const Output go = nav.onPlanAnswer(resume->id, route(straight(2.5, 2.5, 5.5, 2.5)), t);
  ASSERT_TRUE(go.path);
  EXPECT_EQ(nav.feedback().sentence, "The way is free: going on.");
  const Output reached = nav.onPathStatus(go.path->id, ControllerPhase::kReached, "", t);
  ASSERT_EQ(reached.results.size(), 1u);
  EXPECT_EQ(reached.results[0].reason, Reason::kReached);
}

TEST_F(BlockedTest, NoPathTheNavigatorSendsIsItsOwnRecoveryMotion) {
  // No rotation on the spot, no motion of its own: every route is the planner's, or a stop.
  startDriving();
  nav.onPose({2.5, 2.5, 0.0}, t);
  std::vector<Output> outs{nav.onSafety(stopFor(SafetyCause::kObstacle), t)};
  for (int round = 0; round < 6; ++round) {
    for (const auto& o : runUntil(t + 6.0)) outs.push_back(o);
    if (const PlanRequest* p = planOf(outs)) {
      outs.push_back(nav.onPlanAnswer(p->id, route(straight(2.5, 2.5, 5.5, 2.5)), t));
      outs.erase(std::remove_if(outs.begin(), outs.end(), [](const Output& o) { return o.plan; }),
                 outs.end());
    }
  }
  for (const auto& o : outs)
    if (o.path) EXPECT_TRUE(o.path->poses.empty() || o.path->poses.size() == 61u);
}

TEST_F(BlockedTest, ABackUpHookIsAskedWhenBlockedAndAWayAroundAfterItsRoute) {
  int asked = 0;
  nav.setBackUpHook([&](const BlockedSituation& s) {
    ++asked;
    EXPECT_FALSE(s.blocked.empty());
    return straight(s.chair.x, s.chair.y, s.chair.x - 0.5, s.chair.y);  // reverse 0.5 m
  });
  blockedThroughTheOnlyRoute(false);
  EXPECT_EQ(asked, 1);
  const auto outs = runUntil(t + 0.4);  // its route waits for the supervisor's release
  EXPECT_EQ(releasesOf(outs), 1);
  const Output back = nav.onSafety(clear(), t);
  ASSERT_TRUE(back.path);
  const Output after = nav.onPathStatus(back.path->id, ControllerPhase::kReached, "", t + 3);
  EXPECT_TRUE(after.plan) << "no way around asked after backing up";
  EXPECT_TRUE(after.results.empty());
}

TEST_F(NavigatorTest, CancelStopsTheChairThenReportsCanceledOnce) {
  startDriving();
  const Output cancel = nav.cancel("g1", t);
  ASSERT_TRUE(cancel.path);
  EXPECT_TRUE(cancel.path->poses.empty()) << "no controlled stop asked of the controller";
  EXPECT_TRUE(cancel.results.empty()) << "the result comes when the chair has stopped";
  EXPECT_EQ(nav.state(), State::kStopping);
  EXPECT_TRUE(nav.cancel("g1", t).results.empty());
  EXPECT_TRUE(nav.onPathStatus(cancel.path->id, ControllerPhase::kStopping, "stopping", t + 0.5)
                  .results.empty());
  const Output done =
      nav.onPathStatus(cancel.path->id, ControllerPhase::kAborted, "aborted: empty path", t + 1);
  ASSERT_EQ(done.results.size(), 1u);
  EXPECT_EQ(done.results[0].reason, Reason::kCanceled);
  EXPECT_EQ(done.results[0].sentence, "Stopped, as you asked.");
  EXPECT_FALSE(nav.active());
}

TEST_F(NavigatorTest, ACancelOfAnotherGoalChangesNothing) {
  startDriving();
  EXPECT_FALSE(nav.cancel("other", t).path);
  EXPECT_EQ(nav.state(), State::kDriving);
}

TEST_F(NavigatorTest, WithoutTheControllersWordTheResultComesAfterStopTimeout) {
  startDriving();
  nav.cancel("g1", t);
  auto outs = runUntil(t + nav.config().stop_timeout - 0.2);
  EXPECT_TRUE(resultsOf(outs).empty());
  outs = runUntil(t + 0.4);
  ASSERT_EQ(resultsOf(outs).size(), 1u);
  EXPECT_EQ(resultsOf(outs)[0].reason, Reason::kCanceled);
}

TEST_F(NavigatorTest, ASafetyStopEndsTheDriveWithTheSupervisorsCause) {
  const int path = startDriving();
  const Output stop = nav.onSafety(stopFor(SafetyCause::kOther, "the laser scanner is silent"), t);
  ASSERT_TRUE(stop.path);
  EXPECT_TRUE(stop.path->poses.empty());
  nav.onPathStatus(path, ControllerPhase::kAborted, "aborted: safety stop (supervisor)", t + 1);
  const Output done = nav.onPathStatus(stop.path->id, ControllerPhase::kAborted, "", t + 1);
  ASSERT_EQ(done.results.size(), 1u);
  EXPECT_EQ(done.results[0].reason, Reason::kSafetyStop);
  EXPECT_EQ(done.results[0].sentence,
            "Safety stop: the laser scanner is silent. Choose a destination to go on.");
  EXPECT_EQ(done.results[0].detail, "detail for the log");
}

TEST_F(NavigatorTest, TheRidersSwitchWhileDrivingEndsItAsCanceled) {
  startDriving();
  const Output stop = nav.onSafety(stopFor(SafetyCause::kUserStop, "stopped by the rider"), t);
  ASSERT_TRUE(stop.path);
  const Output done = nav.onPathStatus(stop.path->id, ControllerPhase::kAborted, "", t + 1);
  ASSERT_EQ(done.results.size(), 1u);
  EXPECT_EQ(done.results[0].reason, Reason::kCanceled);
}

TEST_F(NavigatorTest, LosingLocalizationEndsTheDriveWithItsOwnReasonOnce) {
  const int path = startDriving();
  std::vector<Output> outs;
  outs.push_back(nav.onLocalization(false, "misfit: 35 % of echoes fit", t));
  // The supervisor and the controller say the same: no second result, no other reason.
  outs.push_back(nav.onSafety(stopFor(SafetyCause::kLocalization, "the chair does not know"), t));
  outs.push_back(nav.onPathStatus(path, ControllerPhase::kAborted, "localization lost", t + 1));
  outs.push_back(nav.onPathStatus(outs[0].path->id, ControllerPhase::kAborted, "", t + 1));
  const auto results = resultsOf(outs);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].reason, Reason::kLocalizationLost);
  EXPECT_EQ(results[0].detail, "misfit: 35 % of echoes fit");
}

TEST_F(NavigatorTest, NoProgressForTheTimeoutEndsTheDrive) {
  startDriving();
  auto outs = runUntil(t + nav.config().no_progress_timeout - 1.0);
  EXPECT_TRUE(resultsOf(outs).empty());
  outs = runUntil(t + 1.2);
  ASSERT_TRUE(outs.back().path || std::any_of(outs.begin(), outs.end(),
                                              [](const Output& o) { return o.path.has_value(); }));
  outs = runUntil(t + nav.config().stop_timeout + 0.2);
  ASSERT_EQ(resultsOf(outs).size(), 1u);
  EXPECT_EQ(resultsOf(outs)[0].reason, Reason::kNoProgress);
  EXPECT_EQ(resultsOf(outs)[0].sentence, "The chair was not getting any closer, so it stopped.");
}

TEST_F(NavigatorTest, TurningOnTheSpotAndGettingCloserAreProgress) {
  startDriving();
  const double timeout = nav.config().no_progress_timeout;
  const double t0 = t;
  runUntil(t0 + 0.8 * timeout);
  nav.onPose({kStart.x, kStart.y, 0.5}, t);  // the start rotation
  runUntil(t0 + 1.6 * timeout);
  nav.onPose({kStart.x + 0.5, kStart.y, 0.5}, t);  // closer
  const auto outs = runUntil(t0 + 2.4 * timeout);
  EXPECT_TRUE(resultsOf(outs).empty());
  EXPECT_EQ(nav.state(), State::kDriving);
}

TEST_F(NavigatorTest, TheControllerGivingUpIsRetriedTwiceEachWithItsReasonThenEnds) {
  int path = startDriving();
  for (int retry = 1; retry <= 2; ++retry) {
    nav.onPathStatus(path, ControllerPhase::kAborted, "tracking error 1.02 m", t);
    const auto outs = runUntil(t + 0.6);
    const PlanRequest* again = planOf(outs);
    ASSERT_NE(again, nullptr) << "retry " << retry;
    const Output go = nav.onPlanAnswer(again->id, route(), t);
    ASSERT_TRUE(go.path);
    path = go.path->id;
  }
  nav.onPathStatus(path, ControllerPhase::kAborted, "tracking error 1.02 m", t);
  const auto outs = runUntil(t + 0.6);
  EXPECT_EQ(planOf(outs), nullptr) << "more retries than max_control_retries";
  const auto results = resultsOf(outs);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].reason, Reason::kControlFailed);
  EXPECT_EQ(results[0].sentence, "The chair could not follow its route and stopped.");
  EXPECT_NE(results[0].detail.find("retry 1 of 2"), std::string::npos) << results[0].detail;
  EXPECT_NE(results[0].detail.find("retry 2 of 2"), std::string::npos) << results[0].detail;
}

TEST_F(NavigatorTest, AnAbortTheSupervisorExplainsIsNoControllerRetry) {
  const int path = startDriving();
  nav.onPathStatus(path, ControllerPhase::kAborted, "safety stop (supervisor)", t);
  const Output stop = nav.onSafety(stopFor(SafetyCause::kOther, "the motor controller"), t + 0.1);
  const auto outs = runUntil(t + 1.0);
  EXPECT_EQ(planOf(outs), nullptr) << "retried a stop the supervisor made";
  ASSERT_EQ(stop.results.size(), 1u) << "the controller had already stopped: the result at once";
  EXPECT_EQ(stop.results[0].reason, Reason::kSafetyStop);
}

TEST_F(NavigatorTest, ANewGoalReplacesTheDriveWithoutStoppingTheChair) {
  startDriving("g1");
  const Output out = nav.start(goal("g2", {6.0, 3.5, 0.0}), t);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].goal_id, "g1");
  EXPECT_EQ(out.results[0].reason, Reason::kReplaced);
  EXPECT_FALSE(out.path) << "stopped between two destinations";
  ASSERT_TRUE(out.plan);
  EXPECT_EQ(nav.feedback().goal_id, "g2");
}

TEST_F(NavigatorTest, ARefusedNewGoalStopsTheChairDrivingTheOldOne) {
  startDriving("g1");
  const Output out = nav.start(goal("g2", {7.5, 1.5, 0.0}), t);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].reason, Reason::kReplaced);
  ASSERT_TRUE(out.path);
  EXPECT_TRUE(out.path->poses.empty());
  const Output done = nav.onPathStatus(out.path->id, ControllerPhase::kAborted, "", t + 1);
  ASSERT_EQ(done.results.size(), 1u);
  EXPECT_EQ(done.results[0].reason, Reason::kGoalInObstacle);
}

TEST_F(NavigatorTest, TheFirstRouteWaitsForTheSupervisorsRelease) {
  nav.onSafety(stopFor(SafetyCause::kUserStop, "stopped by the rider"), t);
  const Output started = nav.start(goal(), t);
  EXPECT_TRUE(started.release_safety);
  const Output answer = nav.onPlanAnswer(started.plan->id, route(), t);
  ASSERT_TRUE(answer.path);  // to the supervisor first; the controller refuses it while held
  EXPECT_TRUE(answer.results.empty());
  nav.tick(t + 0.1);
  const Output go = nav.onSafety(clear(), t + 0.2);
  ASSERT_TRUE(go.path);
  EXPECT_NE(go.path->id, answer.path->id);
  EXPECT_EQ(nav.state(), State::kDriving);
}

TEST_F(NavigatorTest, ALatchThatDoesNotClearEndsTheDriveWithItsCause) {
  nav.onSafety(stopFor(SafetyCause::kOther, "the motor controller reports a fault"), t);
  const Output started = nav.start(goal(), t);
  nav.onPlanAnswer(started.plan->id, route(), t);
  const auto outs = runUntil(t + nav.config().safety_clear_timeout + nav.config().stop_timeout + 1);
  const auto results = resultsOf(outs);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].reason, Reason::kSafetyStop);
  EXPECT_EQ(results[0].sentence,
            "Safety stop: the motor controller reports a fault. Choose a destination to go on.");
}

TEST_F(NavigatorTest, APlannerThatNeverAnswersIsNotReady) {
  nav.start(goal(), t);
  const auto outs = runUntil(t + nav.config().planner_timeout + 0.2);
  const auto results = resultsOf(outs);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].reason, Reason::kNotReady);
}

TEST_F(NavigatorTest, AnObstacleTheLayerShowsOnTheRouteAheadAsksForAWayAround) {
  startDriving();
  wheelchair_core::OccupancyMap layer = testRoom();
  int ix, iy;
  ASSERT_TRUE(layer.worldToCell(3.5, 2.5, ix, iy));
  layer.at(ix, iy) = wheelchair_core::kOccupied;  // a person 2 m ahead, not in the map
  nav.onObstacleLayer(layer, t);
  auto outs = runUntil(t + 0.15);
  const PlanRequest* around = planOf(outs);
  ASSERT_NE(around, nullptr);
  EXPECT_EQ(nav.state(), State::kDriving) << "the chair drives on while the planner answers";
  // The planner did not go round it: the chair stops and the rider is told.
  nav.onObstacleLayer(layer, t);
  const Output blocked = nav.onPlanAnswer(around->id, route(), t);
  ASSERT_TRUE(blocked.path);
  EXPECT_TRUE(blocked.path->poses.empty());
  EXPECT_EQ(nav.state(), State::kBlocked);
  // Gone from the layer: free again, on its way.
  layer.at(ix, iy) = wheelchair_core::kFree;
  std::vector<Output> after;
  for (int i = 0; i < 15; ++i) {
    t += 0.1;
    nav.onObstacleLayer(layer, t);
    after.push_back(nav.tick(t));
  }
  EXPECT_NE(planOf(after), nullptr) << "did not go on once the layer was clear";
}

TEST_F(NavigatorTest, ARouteTheLayerShowsClearIsAWayAroundEvenCloseToTheOldRoute) {
  startDriving();
  wheelchair_core::OccupancyMap layer = testRoom();
  int ix, iy;
  ASSERT_TRUE(layer.worldToCell(3.5, 2.5, ix, iy));
  layer.at(ix, iy) = wheelchair_core::kOccupied;
  nav.onObstacleLayer(layer, t);
  const auto outs = runUntil(t + 0.15);
  ASSERT_NE(planOf(outs), nullptr);
  const int id = planOf(outs)->id;
  // Round the person with 0.5 m to spare: within 0.3 m of the old route just ahead of the chair.
  std::vector<Pose2D> way = straight(1.5, 2.5, 3.5, 3.0);
  const auto rest = straight(3.5, 3.0, 5.5, 2.5);
  way.insert(way.end(), rest.begin() + 1, rest.end());
  nav.onObstacleLayer(layer, t);
  const Output go = nav.onPlanAnswer(id, route(way), t);
  ASSERT_TRUE(go.path);
  EXPECT_EQ(go.path->poses.size(), way.size());
  EXPECT_EQ(nav.state(), State::kDriving);
}

TEST_F(NavigatorTest, AWayRoundAnsweredOnceStoppedWaitsForThePersonToWalkOnFirst) {
  startDriving();
  wheelchair_core::OccupancyMap layer = testRoom();
  int ix, iy;
  ASSERT_TRUE(layer.worldToCell(3.5, 2.5, ix, iy));
  layer.at(ix, iy) = wheelchair_core::kOccupied;  // a person 2 m ahead
  nav.onObstacleLayer(layer, t);
  auto outs = runUntil(t + 0.15);
  const PlanRequest* asked = planOf(outs);
  ASSERT_NE(asked, nullptr);
  const int early = asked->id;
  // The supervisor stops the chair before the planner answers.
  nav.onPose({2.5, 2.5, 0.0}, t);
  nav.onSafety(stopFor(SafetyCause::kObstacle), t);
  const double stopped = t;
  std::vector<Pose2D> way = straight(2.5, 2.5, 2.5, 4.2);
  const auto rest = straight(2.5, 4.2, 5.5, 2.5);
  way.insert(way.end(), rest.begin() + 1, rest.end());
  const Output answer = nav.onPlanAnswer(early, route(way), t + 0.5);
  EXPECT_FALSE(answer.path) << "went round a person who walks on after half a second";
  EXPECT_EQ(nav.state(), State::kWaiting);
  outs = runUntil(stopped + nav.config().wait_for_clear - 0.05);
  EXPECT_EQ(planOf(outs), nullptr);
  outs = runUntil(stopped + nav.config().wait_for_clear + 0.15);
  ASSERT_NE(planOf(outs), nullptr) << "still there at wait_for_clear: a way round is asked";
}

TEST_F(NavigatorTest, AWayRoundFromWhereTheChairWasBeforeItStoppedIsAskedAgainFromWhereItIs) {
  startDriving();
  nav.onPose({2.5, 2.5, 0.0}, t);
  nav.onSafety(stopFor(SafetyCause::kObstacle), t);
  auto outs = runUntil(t + nav.config().wait_for_clear + 0.15);
  const PlanRequest* around = planOf(outs);
  ASSERT_NE(around, nullptr);
  // Planned from 0.4 m behind where the chair came to rest (it was still braking).
  std::vector<Pose2D> way = straight(2.1, 2.5, 2.1, 4.2);
  const auto rest = straight(2.1, 4.2, 5.5, 2.5);
  way.insert(way.end(), rest.begin() + 1, rest.end());
  const Output stale = nav.onPlanAnswer(around->id, route(way), t);
  EXPECT_FALSE(stale.path) << "the turn onto it from here is not what the planner checked";
  ASSERT_TRUE(stale.plan) << "not asked again from where the chair stands";
  EXPECT_EQ(nav.state(), State::kWaiting);
  std::vector<Pose2D> here = straight(2.5, 2.5, 2.5, 4.2);
  const auto on = straight(2.5, 4.2, 5.5, 2.5);
  here.insert(here.end(), on.begin() + 1, on.end());
  const Output fresh = nav.onPlanAnswer(stale.plan->id, route(here), t);
  ASSERT_TRUE(fresh.path);
  EXPECT_EQ(fresh.path->poses.size(), here.size());
  EXPECT_EQ(nav.feedback().replans, 2);
}

TEST_F(NavigatorTest, AWayRoundTurningAwayFromTheMovingChairStopsItFirstThenAsksFromThere) {
  startDriving();
  wheelchair_core::OccupancyMap layer = testRoom();
  int ix, iy;
  ASSERT_TRUE(layer.worldToCell(3.5, 2.5, ix, iy));
  layer.at(ix, iy) = wheelchair_core::kOccupied;
  nav.onObstacleLayer(layer, t);
  auto outs = runUntil(t + 0.15);
  ASSERT_NE(planOf(outs), nullptr);
  const int id = planOf(outs)->id;
  nav.onPose({2.0, 2.5, 0.0}, t);  // driving east at the first pose of the answer
  // Round the far side: a turn to the north at once, which the moving chair cannot drive.
  std::vector<Pose2D> way = straight(2.0, 2.5, 2.0, 4.2);
  const auto rest = straight(2.0, 4.2, 5.5, 2.5);
  way.insert(way.end(), rest.begin() + 1, rest.end());
  nav.onObstacleLayer(layer, t);
  const Output answer = nav.onPlanAnswer(id, route(way), t);
  ASSERT_TRUE(answer.path);
  EXPECT_TRUE(answer.path->poses.empty()) << "the moving chair turned sharply onto it";
  EXPECT_EQ(nav.state(), State::kWaiting);
  EXPECT_EQ(nav.feedback().sentence, "Something is in the way: waiting for it to move.");
  // Still there after wait_for_clear: a way round from where the chair stands, driven.
  nav.onPose({2.2, 2.5, 0.0}, t);
  outs.clear();
  for (int i = 0; i < 60 && !planOf(outs); ++i) {
    t += 0.1;
    nav.onObstacleLayer(layer, t);
    outs = {nav.tick(t)};
  }
  ASSERT_NE(planOf(outs), nullptr);
  std::vector<Pose2D> here = straight(2.2, 2.5, 2.2, 4.2);
  const auto on = straight(2.2, 4.2, 5.5, 2.5);
  here.insert(here.end(), on.begin() + 1, on.end());
  nav.onObstacleLayer(layer, t);
  const Output go = nav.onPlanAnswer(planOf(outs)->id, route(here), t);
  ASSERT_TRUE(go.path);
  EXPECT_EQ(go.path->poses.size(), here.size());
  EXPECT_EQ(nav.state(), State::kDriving);
}

TEST_F(NavigatorTest, ARouteForTheSupervisorThatClearedMeanwhileGoesWithoutAnotherRelease) {
  startDriving();
  nav.onPose({2.5, 2.5, 0.0}, t);
  nav.onSafety(stopFor(SafetyCause::kObstacle), t);
  auto outs = runUntil(t + nav.config().wait_for_clear + 0.15);
  const PlanRequest* around = planOf(outs);
  ASSERT_NE(around, nullptr);
  std::vector<Pose2D> way = straight(2.5, 2.5, 2.5, 4.2);
  const auto rest = straight(2.5, 4.2, 5.5, 2.5);
  way.insert(way.end(), rest.begin() + 1, rest.end());
  const Output corridor = nav.onPlanAnswer(around->id, route(way), t);
  ASSERT_TRUE(corridor.path);       // to the supervisor first, while it still holds its stop
  nav.onSafety(clear(), t + 0.05);  // a probe's release cleared it before the navigator's own
  outs = runUntil(t + 0.45);
  const Output* sent = nullptr;
  for (const auto& o : outs)
    if (o.path) sent = &o;
  ASSERT_NE(sent, nullptr) << "the route waited for a clear status that had already come";
  EXPECT_EQ(sent->path->poses.size(), way.size());
  EXPECT_EQ(nav.state(), State::kDriving);
}

class BlockedAtTheStartTest : public NavigatorTest {
 protected:
  /// A row of obstacles across the room at x = 4 that the map does not have, in the layer.
  void rowAcrossTheRoom() {
    wheelchair_core::OccupancyMap layer = testRoom();
    layer.data.assign(layer.data.size(), wheelchair_core::kUnknown);
    for (int iy = 0; iy < layer.height; ++iy) {
      int ix, unused;
      double x, y;
      layer.worldToCell(4.0, 0.0, ix, unused);
      layer.cellToWorld(ix, iy, x, y);
      if (y > 0.1 && y < 5.0) layer.at(ix, iy) = wheelchair_core::kOccupied;
    }
    nav.onObstacleLayer(layer, t);
  }
};

TEST_F(BlockedAtTheStartTest, NoRouteWhileTheLayerCutsTheWayIsWaitedForAndTheRiderTold) {
  rowAcrossTheRoom();
  const Output started = nav.start(goal("g1", kGoal, "kitchen_door"), t);
  ASSERT_TRUE(started.plan);
  const Output answer = nav.onPlanAnswer(started.plan->id, noRoute(), t);
  EXPECT_TRUE(answer.results.empty()) << "refused at once";
  EXPECT_EQ(nav.state(), State::kBlocked);
  EXPECT_EQ(nav.feedback().sentence,
            "The way is blocked near kitchen door: the chair waits until it is free.");
  // Asked again every replan_period; free again: the first route, driven.
  auto outs = runAnswering(t + nav.config().replan_period - 0.05, noRoute());
  EXPECT_EQ(planOf(outs), nullptr);
  outs = runUntil(t + 0.15);
  const PlanRequest* again = planOf(outs);
  ASSERT_NE(again, nullptr);
  const Output go = nav.onPlanAnswer(again->id, route(), t);
  ASSERT_TRUE(go.path);
  EXPECT_EQ(nav.state(), State::kDriving);
  EXPECT_EQ(nav.feedback().sentence, "Going to kitchen door: 4.0 m.");
}

TEST_F(BlockedAtTheStartTest, StillCutAfterBlockedTimeoutTheDriveEndsBlockedWithWhere) {
  rowAcrossTheRoom();
  const Output started = nav.start(goal("g1", kGoal, "kitchen_door"), t);
  nav.onPlanAnswer(started.plan->id, noRoute(), t);
  const auto outs = runAnswering(t + nav.config().blocked_timeout + 0.2, noRoute());
  const auto results = resultsOf(outs);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].reason, Reason::kBlocked);
  EXPECT_EQ(results[0].sentence,
            "The way is blocked near kitchen door. The chair has stopped: choose a destination to "
            "go on.");
  EXPECT_NE(results[0].detail.find("cuts the way"), std::string::npos) << results[0].detail;
}

TEST_F(BlockedAtTheStartTest, NoRouteWithoutTheLayerCuttingTheWayIsStillNoRoute) {
  const Output started = nav.start(goal("g1", kGoal, "kitchen_door"), t);
  nav.onPlanAnswer(started.plan->id, noRoute(), t);
  const auto outs = runAnswering(t + nav.config().retry_delay + 0.3, noRoute());
  const auto results = resultsOf(outs);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].reason, Reason::kNoRoute);
}

}  // namespace
}  // namespace wheelchair_navigator
