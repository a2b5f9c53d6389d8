// What the HMI publishes on /hmi/state (wheelchair_msgs/HmiState), read from the scanner along
// a scripted ride: each field against what the rider was shown at that moment.
#include <wheelchair_hmi/scan_state.h>

#include <gtest/gtest.h>

using namespace wheelchair_hmi;
using Kind = ScanState::Kind;
using Strings = std::vector<std::string>;

namespace {

/// The kitchen has the most places, so it is offered first; hall and bedroom keep file order.
std::vector<Place> places() {
  return {{"front_door", "hall", {1.0, 1.0, 0.0}},
          {"sink", "kitchen", {4.0, 2.0, 1.5708}},
          {"table", "kitchen", {5.0, 3.0, 3.1416}},
          {"fridge", "kitchen", {6.0, 2.5, 0.0}},
          {"bed", "bedroom", {8.0, 6.0, 0.0}}};
}

}  // namespace

TEST(ScanState, RoomScanningListsTheRoomsWithTheHighlightAndItsTimeLeft) {
  SwitchScanner scanner(places(), ScannerOptions());  // 2 s steps
  scanner.start(10.0);
  ScanState s = scanState(scanner, 10.5, "");
  EXPECT_EQ(s.state, Kind::kRooms);
  EXPECT_EQ(s.items, (Strings{"kitchen", "hall", "bedroom"}));
  EXPECT_EQ(s.highlighted, 0);
  EXPECT_EQ(s.room, "kitchen");
  EXPECT_EQ(s.place, "");
  EXPECT_DOUBLE_EQ(s.step_time, 2.0);
  EXPECT_DOUBLE_EQ(s.time_left, 1.5);
  scanner.tick(12.0);
  s = scanState(scanner, 12.25, "");
  EXPECT_EQ(s.highlighted, 1);
  EXPECT_EQ(s.room, "hall");
  EXPECT_DOUBLE_EQ(s.time_left, 1.75);
}

TEST(ScanState, PlaceScanningConfirmingAndDrivingNameThePlace) {
  SwitchScanner scanner(places(), ScannerOptions());
  scanner.start(0.0);
  scanner.press(0.5);  // the kitchen: its places in file order, the first highlighted
  ScanState s = scanState(scanner, 1.0, "");
  EXPECT_EQ(s.state, Kind::kPlaces);
  EXPECT_EQ(s.items, (Strings{"sink", "table", "fridge"}));
  EXPECT_EQ(s.highlighted, 0);
  EXPECT_EQ(s.room, "kitchen");
  EXPECT_EQ(s.place, "sink");
  EXPECT_DOUBLE_EQ(s.time_left, 1.5);  // the step restarts at the press
  scanner.tick(2.5);
  s = scanState(scanner, 2.5, "");
  EXPECT_EQ(s.highlighted, 1);
  EXPECT_EQ(s.place, "table");

  scanner.press(3.0);  // the table, to confirm within 8 s
  s = scanState(scanner, 5.0, "");
  EXPECT_EQ(s.state, Kind::kConfirming);
  EXPECT_EQ(s.items, (Strings{"table"}));
  EXPECT_EQ(s.highlighted, 0);
  EXPECT_EQ(s.room, "kitchen");
  EXPECT_EQ(s.place, "table");
  EXPECT_DOUBLE_EQ(s.step_time, 8.0);
  EXPECT_DOUBLE_EQ(s.time_left, 6.0);
  EXPECT_DOUBLE_EQ(scanState(scanner, 30.0, "").time_left, 0.0);  // overdue: none, not negative

  scanner.press(4.0);  // confirmed: the chair drives to the table
  s = scanState(scanner, 4.5, "table");
  EXPECT_EQ(s.state, Kind::kDriving);
  EXPECT_EQ(s.items, (Strings{"table"}));
  EXPECT_EQ(s.place, "table");
  EXPECT_DOUBLE_EQ(s.time_left, 0.0);
}

TEST(ScanState, AGoalFromElsewhereDrivesToNoNamedPlace) {
  SwitchScanner scanner(places(), ScannerOptions());
  scanner.start(0.0);
  scanner.driving(1.0);
  const ScanState s = scanState(scanner, 1.5, "");
  EXPECT_EQ(s.state, Kind::kDriving);
  EXPECT_TRUE(s.items.empty());
  EXPECT_EQ(s.place, "");
  EXPECT_EQ(s.highlighted, -1);
}

TEST(ScanState, OnlyTheTimeLeftIsNoChangeToShow) {
  SwitchScanner scanner(places(), ScannerOptions());
  scanner.start(0.0);
  const ScanState a = scanState(scanner, 0.1, "");
  EXPECT_TRUE(a.sameShown(scanState(scanner, 1.9, "")));
  ScanState told = a;
  told.sentence = "Kitchen?";
  EXPECT_FALSE(a.sameShown(told));
  scanner.tick(2.0);
  EXPECT_FALSE(a.sameShown(scanState(scanner, 2.0, "")));
}

TEST(ScanState, AGoalIsNamedByThePlaceAtItsPose) {
  const auto all = places();
  EXPECT_EQ(placeAt(all, {5.004, 2.997, 3.1416}), "table");
  EXPECT_EQ(placeAt(all, {5.05, 3.0, 3.1416}), "");  // 5 cm away: a spot, not the table
  EXPECT_EQ(placeAt(all, {5.0, 3.0, 2.9}), "");      // another heading
  EXPECT_EQ(placeAt(all, {5.0, 3.0, -3.1416}), "table");
}
