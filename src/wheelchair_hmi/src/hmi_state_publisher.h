// Publishes the HMI's scanning state (scan_state.h) as wheelchair_msgs/HmiState on /hmi/state,
// latched, whenever what it shows changes (the time left alone is no change: a display counts
// it down from the step's start).
#pragma once

#include <wheelchair_hmi/scan_state.h>

#include <ros/ros.h>

#include <optional>

namespace wheelchair_hmi {

class HmiStatePublisher {
 public:
  explicit HmiStatePublisher(ros::NodeHandle& nh);
  /// Publishes `state` unless it shows what the last one showed.
  void publish(const ScanState& state);

 private:
  ros::Publisher pub_;
  std::optional<ScanState> last_;
};

}  // namespace wheelchair_hmi
