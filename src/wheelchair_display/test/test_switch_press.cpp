#include <gtest/gtest.h>
#include <wheelchair_display/switch_press.h>

namespace wheelchair_display {
namespace {

using Phase = DriveView::Phase;
using State = ScanView::State;

ScanView hmi(State state) {
  ScanView s;
  s.state = state;
  s.items = {"kitchen", "study"};
  s.highlighted = 0;
  return s;
}

DriveView drive(Phase phase) {
  DriveView d;
  d.phase = phase;
  return d;
}

}  // namespace

TEST(SwitchPress, WhileTheHmiScansAPressIsTheHmisEvenWithAPointerChoiceWaiting) {
  for (State s : {State::kRooms, State::kPlaces, State::kConfirming})
    for (Phase p : {Phase::kNone, Phase::kChecking, Phase::kReachable, Phase::kRefused,
                    Phase::kArrived, Phase::kStoppedByRider})
      EXPECT_EQ(pressMeaning(hmi(s), drive(p)), PressMeaning::kHmis)
          << "HMI state " << int(s) << ", drive phase " << int(p);
}

TEST(SwitchPress, WhileTheChairDrivesAPressStopsItWhoeverStartedTheDrive) {
  for (State s : {State::kIdle, State::kRooms, State::kPlaces, State::kConfirming, State::kDriving})
    EXPECT_EQ(pressMeaning(hmi(s), drive(Phase::kDriving)), PressMeaning::kStop) << int(s);
  // The HMI's own drive, not known to the display as one (started before it came up).
  EXPECT_EQ(pressMeaning(hmi(State::kDriving), drive(Phase::kNone)), PressMeaning::kStop);
  EXPECT_EQ(pressMeaning(hmi(State::kDriving), drive(Phase::kReachable)), PressMeaning::kStop);
}

TEST(SwitchPress, WithoutAScanningHmiAPressConfirmsOnlyAReachableChoice) {
  const ScanView none;  // no HMI state received: no HMI on this chair
  EXPECT_EQ(pressMeaning(none, drive(Phase::kReachable)), PressMeaning::kConfirm);
  EXPECT_EQ(pressMeaning(hmi(State::kIdle), drive(Phase::kReachable)), PressMeaning::kConfirm);
  for (Phase p : {Phase::kNone, Phase::kChecking, Phase::kRefused, Phase::kArrived,
                  Phase::kStoppedByRider, Phase::kFailed})
    EXPECT_EQ(pressMeaning(none, drive(p)), PressMeaning::kNothing) << int(p);
}

TEST(SwitchPress, ThePressThatOpensARoomsPlacesTakesOverFromThePointer) {
  EXPECT_TRUE(switchTakesOver(hmi(State::kRooms), hmi(State::kPlaces)));
  EXPECT_TRUE(switchTakesOver(hmi(State::kIdle), hmi(State::kConfirming)));
  // Scanning on, a lapse back to the rooms, a drive: no new press on an item.
  EXPECT_FALSE(switchTakesOver(hmi(State::kPlaces), hmi(State::kPlaces)));
  EXPECT_FALSE(switchTakesOver(hmi(State::kPlaces), hmi(State::kConfirming)));
  EXPECT_FALSE(switchTakesOver(hmi(State::kConfirming), hmi(State::kRooms)));
  EXPECT_FALSE(switchTakesOver(hmi(State::kRooms), hmi(State::kRooms)));
  EXPECT_FALSE(switchTakesOver(hmi(State::kConfirming), hmi(State::kDriving)));
}

}  // namespace wheelchair_display
