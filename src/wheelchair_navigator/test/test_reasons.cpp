// The one table of what the rider is told: complete, in the message's order, and in words a
// rider understands (no frames, coordinates or planner jargon).
#include <wheelchair_navigator/reasons.h>

#include <gtest/gtest.h>

#include <cctype>
#include <set>

namespace wheelchair_navigator {
namespace {

/// Words of a developer log that a rider must never hear (the issue's examples).
const char* kJargon[] = {"base_link", "map->",   "tf",         "frame",   "footprint", "search",
                         "expansion", "planner", "hypotheses", "aborted", "cell"};

void expectRiderWords(const std::string& sentence) {
  EXPECT_FALSE(sentence.empty());
  EXPECT_TRUE(std::isupper(static_cast<unsigned char>(sentence[0]))) << sentence;
  EXPECT_EQ(sentence.back(), '.') << sentence;
  EXPECT_LE(sentence.size(), 110u) << "too long to announce: " << sentence;
  for (const char* word : kJargon) EXPECT_EQ(sentence.find(word), std::string::npos) << sentence;
}

TEST(Reasons, TheTableHasEveryReasonInTheMessagesOrderOnce) {
  const auto& table = reasonTable();
  ASSERT_EQ(table.size(), 16u);
  std::set<std::string> names;
  for (size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(static_cast<size_t>(table[i].reason), i);
    EXPECT_TRUE(names.insert(table[i].name).second) << table[i].name;
  }
}

TEST(Reasons, EverySentenceIsOneARiderUnderstands) {
  SentenceContext c;
  c.place = "kitchen door";
  c.where = "living door";
  c.cause = "the laser scanner is silent";
  c.distance = 5.24;
  for (const auto& row : reasonTable()) {
    const std::string sentence = riderSentence(row.reason, c);
    expectRiderWords(sentence);
    EXPECT_EQ(sentence.find('{'), std::string::npos) << "placeholder left: " << sentence;
    EXPECT_EQ(sentence.find("0."), std::string::npos) << "a number: " << sentence;
  }
  for (State s :
       {State::kPlanning, State::kDriving, State::kWaiting, State::kBlocked, State::kStopping})
    for (RouteKind k : {RouteKind::kFirst, RouteKind::kResumed, RouteKind::kAround})
      expectRiderWords(stateSentence(s, c, k));
}

TEST(Reasons, TheIssuesSentencesAndTheirPlaceholders) {
  EXPECT_EQ(riderSentence(Reason::kNotLocalized, {}),
            "I don't know where the chair is yet: set its position first.");
  SentenceContext c;
  c.cause = "the laser scanner is silent";
  EXPECT_EQ(riderSentence(Reason::kSafetyStop, c),
            "Safety stop: the laser scanner is silent. Choose a destination to go on.");
  c.where = "kitchen door";
  EXPECT_EQ(riderSentence(Reason::kBlocked, c),
            "The way is blocked near kitchen door. The chair has stopped: choose a destination "
            "to go on.");
  EXPECT_EQ(riderSentence(Reason::kBlocked, {}),
            "The way is blocked. The chair has stopped: choose a destination to go on.");
  c.place = "bed";
  c.distance = 5.24;
  EXPECT_EQ(stateSentence(State::kDriving, c), "Going to bed: 5.2 m.");
  EXPECT_EQ(stateSentence(State::kDriving, {}), "Going: 0.0 m.");
  EXPECT_EQ(stateSentence(State::kDriving, c, RouteKind::kResumed), "The way is free: going on.");
  EXPECT_EQ(stateSentence(State::kIdle, c), "");
}

TEST(Reasons, RefusalsAreTheGoalsNeverPursued) {
  for (Reason r : {Reason::kNotLocalized, Reason::kInvalidGoal, Reason::kUnknownPlace,
                   Reason::kGoalOutsideMap, Reason::kGoalInObstacle, Reason::kGoalNoRoom})
    EXPECT_TRUE(reasonRow(r).refusal) << toString(r);
  for (Reason r : {Reason::kReached, Reason::kNoRoute, Reason::kBlocked, Reason::kCanceled})
    EXPECT_FALSE(reasonRow(r).refusal) << toString(r);
}

TEST(Reasons, PlaceNamesAreSpokenWithSpaces) {
  EXPECT_EQ(spokenName("kitchen_door"), "kitchen door");
  EXPECT_EQ(spokenName("bed"), "bed");
}

}  // namespace
}  // namespace wheelchair_navigator
