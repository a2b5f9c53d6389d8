#include <gtest/gtest.h>
#include <wheelchair_display/speech.h>

namespace wheelchair_display {

TEST(Speech, TheSettingsBecomeEspeakNgArguments) {
  SpeechSettings s;
  s.voice = "en-gb";
  s.volume = 140;
  s.rate = 130;
  EXPECT_EQ(espeakArguments(s),
            (std::vector<std::string>{"-v", "en-gb", "-a", "140", "-s", "130", "--stdin"}));
  const auto to_file = espeakArguments(s, "/tmp/x.wav");
  EXPECT_EQ(to_file.back(), "/tmp/x.wav");
  EXPECT_EQ(to_file[to_file.size() - 2], "-w");
}

TEST(Speech, ExpectedDurationFollowsWordsAndRate) {
  EXPECT_NEAR(expectedSpeechSeconds("Stopped: something is in the way.", 150), 2.4, 1e-9);
  EXPECT_EQ(expectedSpeechSeconds("", 150), 0.0);
}

TEST(Announcer, SaysEachNewStatusOnce) {
  Announcer a(false);
  EXPECT_EQ(a.onStatus("Choose where to go."), "Choose where to go.");
  EXPECT_EQ(a.onStatus("Choose where to go."), "");
  EXPECT_EQ(a.onStatus("Arrived at Sofa."), "Arrived at Sofa.");
}

TEST(Announcer, AuditoryScanningSaysEachHighlightedItem) {
  Announcer a(true);
  ScanView scan;
  scan.state = ScanView::State::kRooms;
  scan.items = {"living_room", "kitchen"};
  scan.highlighted = 0;
  EXPECT_EQ(a.onScan(scan), "Living room?");
  EXPECT_EQ(a.onScan(scan), "");  // same highlight, next tick
  scan.highlighted = 1;
  EXPECT_EQ(a.onScan(scan), "Kitchen?");
  scan.state = ScanView::State::kConfirming;
  scan.place = "sink";
  EXPECT_EQ(a.onScan(scan), "Go to Sink?");
}

TEST(Announcer, WithoutAuditoryScanningHighlightsAreSilent) {
  Announcer a(false);
  ScanView scan;
  scan.state = ScanView::State::kPlaces;
  scan.items = {"sink"};
  scan.highlighted = 0;
  EXPECT_EQ(a.onScan(scan), "");
}

}  // namespace wheelchair_display
