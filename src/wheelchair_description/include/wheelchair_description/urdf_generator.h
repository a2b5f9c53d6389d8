// The chair's URDF, generated from its parameters so that the robot model and the chair file
// (config/chair.yaml) can never disagree. ROS-free: plain text.
#pragma once

#include <wheelchair_description/chair_params.h>

#include <string>

namespace wheelchair_description {

/// Names of the URDF's frames and moving joints (REP-105; DESIGN.md).
constexpr const char* kBaseFootprintFrame = "base_footprint";
constexpr const char* kBaseLinkFrame = "base_link";
constexpr const char* kLaserFrame = "laser";
constexpr const char* kRearLaserFrame = "rear_laser";
constexpr const char* kLeftWheelJoint = "left_wheel_joint";
constexpr const char* kRightWheelJoint = "right_wheel_joint";

/// Plain URDF (no xacro) of the front-wheel-drive power chair described by `params`:
/// base_footprint on the floor below P; base_link at the drive axle centre P (height r);
/// left/right drive wheels on continuous joints about +y (positive angle rolls forward, as
/// psi_l/psi_r of the model); two fixed rear casters; the body + rider link at P_c carrying
/// M_T and I_T; the laser at the chair file's mount. Shapes are boxes and cylinders.
/// Throws std::invalid_argument if `params` is not valid (ChairParams::validate).
std::string chairUrdf(const ChairParams& params);

}  // namespace wheelchair_description
