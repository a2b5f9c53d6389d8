#include <gtest/gtest.h>
#include <wheelchair_display/rider_text.h>

#include <regex>

namespace wheelchair_display {
namespace {

DisplayInputs ready() {
  DisplayInputs in;
  in.have_map = true;
  in.have_pose = true;
  in.localization.state = LocalizationView::State::kLocalized;
  in.safety.known = true;
  return in;
}

/// Rider words carry no frame names, no coordinates, no developer vocabulary.
void expectRiderWords(const std::string& text) {
  for (const char* word : {"base_link", "map", "odom", "tf", "frame", "_", "(", "goal", "path"})
    EXPECT_EQ(text.find(word), std::string::npos) << "'" << word << "' in: " << text;
}

}  // namespace

TEST(RiderText, IdentifiersBecomeWords) {
  EXPECT_EQ(riderName("kitchen_door"), "Kitchen door");
  EXPECT_EQ(riderName("tv"), "Tv");
  EXPECT_EQ(riderName(""), "");
  EXPECT_EQ(distanceText(3.24), "3.2 m");
  EXPECT_EQ(distanceText(12.4), "12 m");
  EXPECT_EQ(distanceText(-0.01), "0.0 m");
}

TEST(RiderText, ScanningSaysWhatTheNextPressChooses) {
  DisplayInputs in = ready();
  in.scan.state = ScanView::State::kRooms;
  in.scan.items = {"living_room", "kitchen"};
  in.scan.highlighted = 1;
  EXPECT_EQ(describe(in).prompt, "Press to choose Kitchen.");
  EXPECT_EQ(describe(in).status, "Choose where to go.");
  in.scan.state = ScanView::State::kPlaces;
  in.scan.items = {"sink", "kitchen_door"};
  EXPECT_EQ(describe(in).prompt, "Press to choose Kitchen door.");
  in.scan.state = ScanView::State::kConfirming;
  in.scan.place = "kitchen_door";
  EXPECT_EQ(describe(in).prompt, "Press again to go to Kitchen door.");
}

TEST(RiderText, DrivingSaysWhereToAndHowFarInOneSentence) {
  DisplayInputs in = ready();
  in.drive.phase = DriveView::Phase::kDriving;
  in.drive.destination = "kitchen";
  in.drive.distance = 3.21;
  const Message m = describe(in);
  EXPECT_EQ(m.status, "Driving to Kitchen \u2014 3.2 m to go.");
  EXPECT_EQ(m.prompt, "Press STOP or the switch to stop.");
  expectRiderWords(m.status);
}

TEST(RiderText, ASafetyStopWinsAndUsesTheSupervisorsSentence) {
  DisplayInputs in = ready();
  in.drive.phase = DriveView::Phase::kDriving;
  in.safety.stop = true;
  EXPECT_EQ(describe(in).status, "Stopped.");  // the supervisor gave no sentence
  EXPECT_EQ(describe(in).tone, Message::Tone::kStopped);
  in.safety.sentence = "Stopped: a person is in the way.";
  EXPECT_EQ(describe(in).status, "Stopped: a person is in the way.");
  in.safety.sentence = "stopped by the rider";  // another node's words, made a sentence
  EXPECT_EQ(describe(in).status, "Stopped by the rider.");
}

TEST(RiderText, NotKnowingWhereTheChairIsComesBeforeAnyDrive) {
  DisplayInputs in = ready();
  in.have_pose = false;
  in.localization.state = LocalizationView::State::kUnknown;
  in.drive.phase = DriveView::Phase::kReachable;
  EXPECT_EQ(describe(in).status, "I don't know where the chair is yet.");
  in.have_pose = true;
  in.localization.state = LocalizationView::State::kNotLocalized;
  EXPECT_EQ(describe(in).status, "I am not sure where the chair is.");
  in.localization.sentence = "I am not sure where the chair is: set its position.";
  EXPECT_EQ(describe(in).status, in.localization.sentence);
  EXPECT_FALSE(describe(in).show_go);
}

TEST(RiderText, AHeldUpDriveSaysWhyInTheNavigatorsWordsAndStillHowToStop) {
  DisplayInputs in = ready();
  in.drive.phase = DriveView::Phase::kDriving;
  in.drive.destination = "kitchen";
  in.drive.distance = 3.21;
  in.drive.sentence = "Something is in the way: waiting for it to move.";
  const Message m = describe(in);
  EXPECT_EQ(m.status, "Something is in the way: waiting for it to move.");
  EXPECT_EQ(m.tone, Message::Tone::kAttention);
  EXPECT_EQ(m.prompt, "Press STOP or the switch to stop.");
}

TEST(RiderText, ADriveOnlyTheHmiToldOfIsInTheHmisWordsWithPlacesAsWords) {
  DisplayInputs in = ready();
  in.scan.state = ScanView::State::kDriving;
  in.scan.place = "kitchen_door";
  in.scan.sentence = "Going to kitchen_door. Press to stop.";
  EXPECT_EQ(describe(in).status, "Going to kitchen door. Press to stop.");
  expectRiderWords(describe(in).status);
  EXPECT_EQ(describe(in).prompt, "Press to stop.");
  in.scan.sentence = "";  // an HMI that said nothing yet
  EXPECT_EQ(describe(in).status, "Driving to Kitchen door.");
  EXPECT_EQ(hmiWords("the_bed? ok"), "the bed? ok");
}

TEST(RiderText, EveryOutcomeOfADriveIsToldInRiderWords) {
  DisplayInputs in = ready();
  in.drive.destination = "sofa";
  const std::pair<DriveView::Phase, std::string> outcomes[] = {
      {DriveView::Phase::kArrived, "Arrived at Sofa."},
      {DriveView::Phase::kStoppedByRider, "Stopped: you pressed stop."},
      {DriveView::Phase::kFailed, "Stopped on the way to Sofa."},
      {DriveView::Phase::kRefused, "The chair cannot get to Sofa."},
      {DriveView::Phase::kChecking, "Checking the way to Sofa."}};
  for (const auto& [phase, sentence] : outcomes) {
    in.drive.phase = phase;
    EXPECT_EQ(describe(in).status, sentence);
    expectRiderWords(describe(in).status);
  }
  in.drive.phase = DriveView::Phase::kReachable;
  in.drive.distance = 5.23;
  EXPECT_EQ(describe(in).status, "Sofa is 5.2 m away.");
  EXPECT_TRUE(describe(in).show_go);
  in.drive.destination = "";
  EXPECT_EQ(describe(in).status, "The chosen spot is 5.2 m away.");
}

TEST(RiderText, BeforeTheMapThereIsOnlyWaiting) {
  DisplayInputs in;
  EXPECT_EQ(describe(in).status, "Waiting for the map.");
}

TEST(RiderText, SpokenTextSaysMetresAndPausesAtTheDash) {
  EXPECT_EQ(spokenText("Driving to Kitchen \u2014 3.2 m to go."),
            "Driving to Kitchen, 3.2 metres to go.");
  EXPECT_EQ(spokenText("Sofa is 12 m away."), "Sofa is 12 metres away.");
  EXPECT_EQ(spokenText("Arrived at Sofa."), "Arrived at Sofa.");
}

}  // namespace wheelchair_display
