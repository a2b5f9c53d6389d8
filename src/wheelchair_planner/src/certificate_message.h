// The planner's Certificate as wheelchair_msgs/PlanCertificate (the host's one message
// conversion of a planner type; the shared ones are in wheelchair_ros/conversions.h).
#pragma once

#include <wheelchair_msgs/PlanCertificate.h>
#include <wheelchair_planner/certificate.h>

#include <std_msgs/Header.h>

namespace wheelchair_planner {

wheelchair_msgs::PlanCertificate toPlanCertificateMsg(const Certificate& c,
                                                      const std_msgs::Header& header);

}  // namespace wheelchair_planner
