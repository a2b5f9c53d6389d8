// One-switch group scanning against the rider's effort it promises and scripted presses.
#include <wheelchair_hmi/places.h>
#include <wheelchair_hmi/switch_scanner.h>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <fstream>

using namespace wheelchair_hmi;
using Kind = ScanOutput::Kind;

namespace {

/// 30 places in 7 rooms of uneven sizes, like a home.
std::vector<Place> homePlaces() {
  const std::vector<std::pair<std::string, int>> rooms = {
      {"hall", 2}, {"kitchen", 6}, {"living", 7}, {"bedroom", 5},
      {"bath", 3}, {"study", 6},   {"balcony", 1}};
  std::vector<Place> places;
  for (const auto& [room, count] : rooms)
    for (int i = 0; i < count; ++i)
      places.push_back({room + "_" + std::to_string(i), room, {1.0 * i, 2.0, 0.0}});
  return places;
}

}  // namespace

TEST(SwitchScanner, ThirtyPlacesTakeAtMostThreePressesAndFewScanSteps) {
  const auto places = homePlaces();
  ASSERT_EQ(places.size(), 30u);
  const ScannerOptions options;
  const ScanEffort effort = measureScanEffort(places, options);
  EXPECT_LE(effort.max_presses, 3);
  EXPECT_LE(effort.mean_steps, 8.0);
  EXPECT_DOUBLE_EQ(effort.linear_mean_steps, 15.5);
  // Independent expectation: rooms sorted by size s_g, a place at room rank g and position i
  // costs (g + 1) room highlights + (i + 1) place highlights (none for a one-place room).
  const SwitchScanner scanner(places, options);
  double expected = 0.0;
  for (size_t g = 0; g < scanner.groupMembers().size(); ++g) {
    const size_t size = scanner.groupMembers()[g].size();
    for (size_t i = 0; i < size; ++i) expected += (g + 1) + (size > 1 ? i + 1 : 0);
  }
  EXPECT_NEAR(effort.mean_steps, expected / 30.0, 1e-12);
}

TEST(SwitchScanner, ScriptedPressesSelectConfirmAndGo) {
  SwitchScanner scanner(homePlaces(), ScannerOptions());
  ScanOutput out = scanner.start(0.0);
  EXPECT_EQ(out.group, "living");  // the largest room is offered first
  out = scanner.tick(2.0);
  EXPECT_EQ(out.group, "kitchen");
  out = scanner.press(2.5);  // choose the kitchen
  ASSERT_EQ(out.kind, Kind::kHighlight);
  EXPECT_EQ(out.place->name, "kitchen_0");
  out = scanner.tick(3.0);  // not yet: interval restarts at the press
  EXPECT_EQ(out.kind, Kind::kNone);
  out = scanner.tick(4.5);
  EXPECT_EQ(out.place->name, "kitchen_1");
  out = scanner.press(5.0);
  ASSERT_EQ(out.kind, Kind::kAskConfirm);
  EXPECT_EQ(out.place->name, "kitchen_1");
  out = scanner.press(6.0);
  ASSERT_EQ(out.kind, Kind::kGo);
  EXPECT_EQ(out.place->name, "kitchen_1");
  EXPECT_EQ(scanner.phase(), SwitchScanner::Phase::kDriving);
  EXPECT_EQ(scanner.tick(100.0).kind, Kind::kNone);  // no scanning while driving
}

TEST(SwitchScanner, AnyPressWhileDrivingStops) {
  SwitchScanner scanner(homePlaces(), ScannerOptions());
  scanner.start(0.0);
  scanner.press(0.1);
  scanner.press(0.2);
  ASSERT_EQ(scanner.press(0.3).kind, Kind::kGo);
  const ScanOutput out = scanner.press(5.0);
  EXPECT_EQ(out.kind, Kind::kStop);
  EXPECT_EQ(scanner.phase(), SwitchScanner::Phase::kGroups);
}

TEST(SwitchScanner, UnconfirmedChoiceIsCancelled) {
  SwitchScanner scanner(homePlaces(), ScannerOptions());
  scanner.start(0.0);
  scanner.press(0.1);
  ASSERT_EQ(scanner.press(0.2).kind, Kind::kAskConfirm);
  EXPECT_EQ(scanner.tick(5.0).kind, Kind::kNone);
  EXPECT_EQ(scanner.tick(8.3).kind, Kind::kCancelled);
  EXPECT_EQ(scanner.phase(), SwitchScanner::Phase::kGroups);
}

TEST(SwitchScanner, IgnoredRoomReturnsToRoomScanning) {
  ScannerOptions options;
  SwitchScanner scanner(homePlaces(), options);
  scanner.start(0.0);
  scanner.press(0.0);  // living room, 7 places
  double now = 0.0;
  for (int i = 0; i < 2 * 7 - 1; ++i) {
    now += options.scan_interval;
    ASSERT_NE(scanner.tick(now).place, nullptr) << i;
  }
  now += options.scan_interval;
  const ScanOutput out = scanner.tick(now);
  EXPECT_EQ(out.place, nullptr);
  EXPECT_EQ(out.group, "living");
  EXPECT_EQ(scanner.phase(), SwitchScanner::Phase::kGroups);
}

TEST(SwitchScanner, OnePlaceRoomGoesStraightToConfirmation) {
  SwitchScanner scanner(homePlaces(), ScannerOptions());
  ScanOutput out = scanner.start(0.0);
  double now = 0.0;
  while (out.group != "balcony") out = scanner.tick(now += 2.0);
  out = scanner.press(now);
  EXPECT_EQ(out.kind, Kind::kAskConfirm);
  EXPECT_EQ(out.place->name, "balcony_0");
}

TEST(Places, LoadsAndRejectsBadFiles) {
  const std::string path = ::testing::TempDir() + "places_test.yaml";
  std::ofstream(path) << "places:\n  - {name: bed, room: bedroom, x: 1.5, y: 2.0, yaw: 1.57}\n"
                         "  - {name: sink, room: kitchen, x: 3, y: 4}\n";
  const auto places = loadPlaces(path);
  ASSERT_EQ(places.size(), 2u);
  EXPECT_EQ(places[0].room, "bedroom");
  EXPECT_DOUBLE_EQ(places[0].pose.yaw, 1.57);
  EXPECT_DOUBLE_EQ(places[1].pose.yaw, 0.0);
  ASSERT_NE(findPlace(places, "sink"), nullptr);
  EXPECT_EQ(findPlace(places, "garage"), nullptr);

  const auto expectError = [&](const std::string& text, const std::string& fragment) {
    std::ofstream(path) << text;
    try {
      loadPlaces(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  };
  expectError("places: []\n", "no 'places'");
  expectError("places:\n  - {room: a, x: 1, y: 2}\n", "missing 'name'");
  expectError("places:\n  - {name: a, x: .nan, y: 2}\n", "not finite");
  expectError("places:\n  - {name: a, x: 1, y: 2}\n  - {name: a, x: 1, y: 2}\n", "duplicate");
  expectError("places: [\n", "bad YAML");
  std::remove(path.c_str());
  EXPECT_THROW(loadPlaces(path), std::runtime_error);
}

TEST(ScannerOptions, KeysAreReadAndUnusableOnesRefused) {
  using wheelchair_core::ConfigError;
  using wheelchair_core::loadConfig;
  using wheelchair_core::YamlParameterSource;
  const auto load = [](const std::string& text) {
    return loadConfig<ScannerOptions>(YamlParameterSource(YAML::Load(text), "hmi.yaml"),
                                      readScannerOptions);
  };
  const ScannerOptions o = load("{scan_interval: 1.0, confirm_timeout: 5, item_cycles: 3}");
  EXPECT_DOUBLE_EQ(o.scan_interval, 1.0);
  EXPECT_DOUBLE_EQ(o.confirm_timeout, 5.0);
  EXPECT_EQ(o.item_cycles, 3);
  EXPECT_EQ(ScannerOptions().validate(), "");
  EXPECT_THROW(load("{scan_interval: 0.0}"), ConfigError);
  EXPECT_THROW(load("{item_cycles: 0}"), ConfigError);
  EXPECT_THROW(load("{scan_intervall: 1.0}"), ConfigError);  // misspelt: refused, not ignored
  ScannerOptions bad;
  bad.confirm_timeout = -1.0;
  EXPECT_THROW(SwitchScanner(homePlaces(), bad), std::invalid_argument);
}
