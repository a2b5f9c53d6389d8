// The supervisor's verdict as the typed /safety/status message (wheelchair_msgs/SafetyStatus):
// the reason as the message's enum, the rider's words, the detail and its numbers.
#pragma once

#include <wheelchair_msgs/SafetyStatus.h>
#include <wheelchair_safety/safety_supervisor.h>

#include <ros/time.h>

namespace wheelchair_safety {

/// The message's reason constant for `reason`.
uint8_t statusReason(StopReason reason);

wheelchair_msgs::SafetyStatus toSafetyStatus(const SafetyVerdict& verdict, const ros::Time& stamp);

/// True if `a` and `b` say the same (reason, stop, detail): a new status is published only then.
bool sameVerdict(const wheelchair_msgs::SafetyStatus& a, const wheelchair_msgs::SafetyStatus& b);

}  // namespace wheelchair_safety
