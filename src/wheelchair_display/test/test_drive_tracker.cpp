#include <gtest/gtest.h>
#include <wheelchair_display/drive_tracker.h>

namespace wheelchair_display {
namespace {

using Phase = DriveView::Phase;
using wheelchair_core::Pose2D;

std::vector<Pose2D> lShape() { return {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}}; }

}  // namespace

TEST(RemainingLength, IsMeasuredAlongTheRouteFromTheNearestPoint) {
  EXPECT_NEAR(remainingLength(lShape(), {0, 0}), 7.0, 1e-9);
  EXPECT_NEAR(remainingLength(lShape(), {1, 0.2}), 6.0, 1e-9);
  EXPECT_NEAR(remainingLength(lShape(), {4.1, 1}), 2.0, 1e-9);
  EXPECT_NEAR(remainingLength(lShape(), {4, 3}), 0.0, 1e-9);
  EXPECT_NEAR(remainingLength({{1, 1, 0}}, {4, 5}), 5.0, 1e-9);
}

TEST(RemainingLength, KeepsMovingForwardOnARouteThatPassesTheChairTwice) {
  // Out 2 m and back past the start: from the hint, the chair on the way back is near the end.
  const std::vector<Pose2D> there_and_back = {{0, 0, 0}, {2, 0, 0}, {2, 0.1, 0}, {-1, 0.1, 0}};
  size_t segment = 2;
  EXPECT_NEAR(remainingLength(there_and_back, {0, 0.05}, &segment), 1.0, 1e-9);
  EXPECT_EQ(segment, 2u);
}

TEST(DriveTracker, AChoiceIsCheckedThenConfirmedThenDrivenToItsEnd) {
  DriveTracker drive(30.0);
  const Pose2D goal{4, 3, 1.57};
  drive.check("kitchen", goal, 0.0);
  EXPECT_EQ(drive.view().phase, Phase::kChecking);
  drive.checked(goal, true, 7.0, "", 0.5);
  EXPECT_EQ(drive.view().phase, Phase::kReachable);
  EXPECT_DOUBLE_EQ(drive.view().distance, 7.0);
  drive.goal("kitchen", goal, 1.0);
  drive.route(lShape(), 1.1);
  drive.progress({4, 1});
  EXPECT_EQ(drive.view().phase, Phase::kDriving);
  EXPECT_NEAR(drive.view().distance, 2.0, 1e-9);
  drive.arrived(9.0);
  EXPECT_EQ(drive.view().phase, Phase::kArrived);
  EXPECT_TRUE(drive.routePoses().empty());
  drive.tick(38.9);
  EXPECT_EQ(drive.view().phase, Phase::kArrived);  // the outcome stays for a while
  drive.tick(39.1);
  EXPECT_EQ(drive.view().phase, Phase::kNone);
}

TEST(DriveTracker, AnAnswerToAnOlderChoiceIsIgnored) {
  DriveTracker drive(30.0);
  drive.check("sofa", {1, 1, 0}, 0.0);
  drive.check("bed", {2, 9, 0}, 0.2);
  drive.checked({1, 1, 0}, false, 0.0, "", 0.3);
  EXPECT_EQ(drive.view().phase, Phase::kChecking);
  EXPECT_EQ(drive.view().destination, "bed");
  drive.checked({2, 9, 0}, false, 0.0, "", 0.4);
  EXPECT_EQ(drive.view().phase, Phase::kRefused);
}

TEST(DriveTracker, AnEmptyRouteIsARefusalAndTheRidersStopEndsTheDrive) {
  DriveTracker drive(30.0);
  drive.goal("sofa", {1, 1, 0}, 0.0);
  drive.route({}, 0.1);
  EXPECT_EQ(drive.view().phase, Phase::kRefused);
  drive.goal("sofa", {1, 1, 0}, 1.0);
  drive.route(lShape(), 1.1);
  drive.riderStopped(2.0);
  EXPECT_EQ(drive.view().phase, Phase::kStoppedByRider);
  drive.arrived(3.0);  // a late end of the stopped drive changes nothing
  EXPECT_EQ(drive.view().phase, Phase::kStoppedByRider);
}

TEST(DriveTracker, AStopBeforeConfirmingWithdrawsTheChoice) {
  DriveTracker drive(30.0);
  drive.check("sofa", {1, 1, 0}, 0.0);
  drive.checked({1, 1, 0}, true, 3.0, "", 0.1);
  drive.riderStopped(0.5);
  EXPECT_EQ(drive.view().phase, Phase::kNone);
  EXPECT_FALSE(drive.goalPose().has_value());
}

TEST(DriveTracker, AnEndCloseToTheGoalIsAnArrivalAndFarFromItAFailure) {
  DriveTracker drive(30.0);
  drive.goal("bed", {4, 3, 0}, 0.0);
  drive.route(lShape(), 0.1);
  drive.progress({4.0, 2.9});
  drive.ended(5.0, 0.15);
  EXPECT_EQ(drive.view().phase, Phase::kArrived);
  drive.goal("bed", {4, 3, 0}, 6.0);
  drive.route(lShape(), 6.1);
  drive.progress({2.0, 0.0});
  drive.ended(7.0, 0.15);
  EXPECT_EQ(drive.view().phase, Phase::kFailed);
}

TEST(DriveTracker, TheOwnersSentenceIsKeptWithTheOutcome) {
  DriveTracker drive(30.0);
  drive.goal("bed", {2, 9, 0}, 0.0);
  drive.failed(1.0, "Stopped: the doorway is blocked.");
  EXPECT_EQ(drive.view().phase, Phase::kFailed);
  EXPECT_EQ(drive.view().sentence, "Stopped: the doorway is blocked.");
}

TEST(DriveTracker, AnEndFarFromTheGoalKeepsTheNavigatorsReasonAndAnArrivalItsOwnWords) {
  DriveTracker drive(30.0);
  drive.goal("bed", {4, 3, 0}, 0.0);
  drive.route(lShape(), 0.1);
  drive.progress({2.0, 0.0});
  drive.ended(1.0, 0.15,
              "Safety stop: the chair's computer paused. Choose a destination to go on.");
  EXPECT_EQ(drive.view().phase, Phase::kFailed);
  EXPECT_EQ(drive.view().sentence,
            "Safety stop: the chair's computer paused. Choose a destination to go on.");
  drive.goal("bed", {4, 3, 0}, 2.0);
  drive.progress({4.0, 2.95});
  drive.ended(3.0, 0.15, "Arrived.");
  EXPECT_EQ(drive.view().phase, Phase::kArrived);
  EXPECT_EQ(drive.view().sentence, "");  // "Arrived at Bed." names the place
}

TEST(DriveTracker, AHeldUpDriveSaysWhyUntilItDrivesOnAndOnlyWhileDriving) {
  DriveTracker drive(30.0);
  drive.heldUp("Something is in the way: waiting for it to move.");
  EXPECT_EQ(drive.view().sentence, "");  // no drive: nothing to hold up
  drive.goal("bed", {4, 3, 0}, 0.0);
  drive.heldUp("Something is in the way: waiting for it to move.");
  EXPECT_EQ(drive.view().phase, Phase::kDriving);
  EXPECT_EQ(drive.view().sentence, "Something is in the way: waiting for it to move.");
  drive.heldUp("");
  EXPECT_EQ(drive.view().sentence, "");
  drive.heldUp("The way is blocked: the chair waits until it is free.");
  drive.riderStopped(1.0);
  EXPECT_EQ(drive.view().phase, Phase::kStoppedByRider);
  EXPECT_EQ(drive.view().sentence, "");
}

}  // namespace wheelchair_display
