// One tf2 buffer and one /tf listener per process, shared by every nodelet that reads tf.
// In the one-process chair each nodelet used to own a TransformListener: each had its own /tf
// and /tf_static subscriptions, its own spin thread and its own copy of every transform (4x the
// deserialization and thread wake-ups of ~110 /tf messages per second). Sharing them costs
// nothing in behaviour: tf2_ros::Buffer is thread-safe, and lookups only read it.
#pragma once

#include <tf2_ros/buffer.h>

#include <memory>

namespace wheelchair_ros {

/// The process's buffer, filled by one listener with its own spin thread (so blocking lookups
/// with a timeout work). Created on the first call; destroyed with the last holder, i.e. when
/// the last nodelet using it is unloaded. Needs ros::init.
std::shared_ptr<tf2_ros::Buffer> sharedTfBuffer();

}  // namespace wheelchair_ros
