#include "safety_status_msg.h"

namespace wheelchair_safety {

using wheelchair_msgs::SafetyStatus;

uint8_t statusReason(StopReason reason) {
  switch (reason) {
    case StopReason::kNone:
      return SafetyStatus::NONE;
    case StopReason::kNoData:
      return SafetyStatus::NO_DATA;
    case StopReason::kLocalizationLost:
      return SafetyStatus::LOCALIZATION_LOST;
    case StopReason::kCovarianceTooLarge:
      return SafetyStatus::COVARIANCE_TOO_LARGE;
    case StopReason::kLaserSilent:
      return SafetyStatus::LASER_SILENT;
    case StopReason::kPoseStale:
      return SafetyStatus::POSE_STALE;
    case StopReason::kUnexpectedObstacle:
      return SafetyStatus::OBSTACLE;
    case StopReason::kDriverFault:
      return SafetyStatus::DRIVER_FAULT;
    case StopReason::kUserStop:
      return SafetyStatus::USER_STOP;
    case StopReason::kRearSensorSilent:
      return SafetyStatus::REAR_SENSOR_SILENT;
    case StopReason::kObstacleBehind:
      return SafetyStatus::OBSTACLE_BEHIND;
  }
  return SafetyStatus::NO_DATA;  // unreachable; never "safe" for an unknown reason
}

SafetyStatus toSafetyStatus(const SafetyVerdict& verdict, const ros::Time& stamp) {
  SafetyStatus status;
  status.header.stamp = stamp;
  status.reason = statusReason(verdict.reason);
  status.stop = verdict.stop;
  status.sentence = describe(verdict.reason);
  status.detail = verdict.detail;
  status.value = verdict.value;
  status.limit = verdict.limit;
  return status;
}

bool sameVerdict(const SafetyStatus& a, const SafetyStatus& b) {
  return a.reason == b.reason && a.stop == b.stop && a.detail == b.detail;
}

}  // namespace wheelchair_safety
