// The one-publisher rule of ExpectedPublisher: the names a parameter may give, and that only
// the expected publisher's messages are accepted.
#include <wheelchair_ros/expected_publisher.h>

#include <gtest/gtest.h>

#include <stdexcept>

namespace wheelchair_ros {
namespace {

TEST(ExpectedPublisher, GlobalNodeNamesAndThisProcessAreValid) {
  EXPECT_EQ(publisherNameProblem("switch_publisher", "/switch_keyboard"), "");
  EXPECT_EQ(publisherNameProblem("switch_publisher", "/chair/switch_2"), "");
  EXPECT_EQ(publisherNameProblem("speed_limit_publisher", ""), "");  // this process
}

TEST(ExpectedPublisher, OtherNamesAreRefusedNamingTheKey) {
  for (const char* bad : {"switch_keyboard", "/", "//a", "/a/", "/a b", "/1a", "/a-b", "~a"}) {
    const std::string problem = publisherNameProblem("switch_publisher", bad);
    EXPECT_NE(problem.find("switch_publisher"), std::string::npos) << bad << ": " << problem;
  }
  EXPECT_THROW(ExpectedPublisher("/switch", "switch_keyboard"), std::invalid_argument);
}

TEST(ExpectedPublisher, OnlyTheExpectedPublisherIsAccepted) {
  ExpectedPublisher guard("/switch", "/switch_keyboard");
  EXPECT_TRUE(guard.accept("/switch_keyboard"));
  EXPECT_FALSE(guard.accept("/intruder"));
  EXPECT_FALSE(guard.accept("/switch_keyboard2"));
  EXPECT_FALSE(guard.accept(""));
  EXPECT_TRUE(guard.accept("/switch_keyboard"));
  EXPECT_EQ(guard.refused(), 3u);
}

}  // namespace
}  // namespace wheelchair_ros
