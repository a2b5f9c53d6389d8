// The verdict as wheelchair_msgs/SafetyStatus: every reason has its own constant, the rider's
// words and the numbers travel with it, and a repeat of the same verdict is not news.
#include <gtest/gtest.h>

#include <set>

#include "../src/safety_status_msg.h"

using namespace wheelchair_safety;
using wheelchair_msgs::SafetyStatus;

TEST(SafetyStatusMsg, EveryReasonHasItsOwnConstant) {
  const StopReason all[] = {StopReason::kNone,
                            StopReason::kNoData,
                            StopReason::kLocalizationLost,
                            StopReason::kCovarianceTooLarge,
                            StopReason::kLaserSilent,
                            StopReason::kPoseStale,
                            StopReason::kUnexpectedObstacle,
                            StopReason::kDriverFault,
                            StopReason::kUserStop,
                            StopReason::kRearSensorSilent,
                            StopReason::kObstacleBehind};
  std::set<uint8_t> seen;
  for (StopReason r : all) EXPECT_TRUE(seen.insert(statusReason(r)).second);
  EXPECT_EQ(statusReason(StopReason::kNone), SafetyStatus::NONE);
  EXPECT_EQ(statusReason(StopReason::kLaserSilent), SafetyStatus::LASER_SILENT);
  EXPECT_EQ(statusReason(StopReason::kUnexpectedObstacle), SafetyStatus::OBSTACLE);
}

TEST(SafetyStatusMsg, AStopCarriesTheRidersWordsTheDetailAndTheNumbers) {
  SafetyVerdict v;
  v.stop = true;
  v.reason = StopReason::kLaserSilent;
  v.detail = "no laser scan for 0.31 s";
  v.value = 0.31;
  v.limit = 0.3;
  const SafetyStatus s = toSafetyStatus(v, ros::Time(12.5));
  EXPECT_TRUE(s.stop);
  EXPECT_EQ(s.reason, SafetyStatus::LASER_SILENT);
  EXPECT_EQ(s.sentence, "the laser scanner is silent");
  EXPECT_EQ(s.detail, v.detail);
  EXPECT_DOUBLE_EQ(s.value, 0.31);
  EXPECT_DOUBLE_EQ(s.limit, 0.3);
  EXPECT_DOUBLE_EQ(s.header.stamp.toSec(), 12.5);
}

TEST(SafetyStatusMsg, SafeIsNotAStop) {
  const SafetyStatus s = toSafetyStatus(SafetyVerdict(), ros::Time(1.0));
  EXPECT_FALSE(s.stop);
  EXPECT_EQ(s.reason, SafetyStatus::NONE);
}

TEST(SafetyStatusMsg, OnlyAChangedVerdictIsNews) {
  SafetyVerdict v;
  v.stop = true;
  v.reason = StopReason::kLaserSilent;
  v.detail = "no laser scan for 0.31 s";
  const SafetyStatus a = toSafetyStatus(v, ros::Time(1.0));
  EXPECT_TRUE(sameVerdict(a, toSafetyStatus(v, ros::Time(2.0))));  // a later stamp only
  v.detail = "no laser scan for 0.35 s";
  EXPECT_FALSE(sameVerdict(a, toSafetyStatus(v, ros::Time(2.0))));
  EXPECT_FALSE(sameVerdict(a, toSafetyStatus(SafetyVerdict(), ros::Time(2.0))));
}
