#include "hmi_state_publisher.h"

#include <wheelchair_msgs/HmiState.h>

namespace wheelchair_hmi {

using Msg = wheelchair_msgs::HmiState;
static_assert(int(ScanState::Kind::kIdle) == Msg::IDLE &&
                  int(ScanState::Kind::kRooms) == Msg::SCANNING_ROOMS &&
                  int(ScanState::Kind::kPlaces) == Msg::SCANNING_PLACES &&
                  int(ScanState::Kind::kConfirming) == Msg::CONFIRMING &&
                  int(ScanState::Kind::kDriving) == Msg::DRIVING,
              "ScanState::Kind follows wheelchair_msgs/HmiState's constants");

HmiStatePublisher::HmiStatePublisher(ros::NodeHandle& nh)
    : pub_(nh.advertise<wheelchair_msgs::HmiState>("hmi/state", 1, true)) {}

void HmiStatePublisher::publish(const ScanState& state) {
  if (last_ && last_->sameShown(state)) return;
  last_ = state;
  wheelchair_msgs::HmiState msg;
  msg.header.stamp = ros::Time::now();
  msg.state = static_cast<uint8_t>(state.state);
  msg.items = state.items;
  msg.highlighted = state.highlighted;
  msg.room = state.room;
  msg.place = state.place;
  msg.time_left = state.time_left;
  msg.step_time = state.step_time;
  msg.sentence = state.sentence;
  pub_.publish(msg);
}

}  // namespace wheelchair_hmi
