// A topic any node could publish, taken from its one expected publisher only (the base driver's
// rule for /wheel_torques, for the rider's switch, the rider's place choice and the
// supervisor's speed limit): the publisher is named by a parameter (publisherNameProblem
// validates it), a message of any other publisher is refused, counted and reported in the log
// (an error naming the publisher, at most every 5 s per topic).
//
//   ExpectedPublisher guard("/switch", config.switch_publisher);   // "" = this process
//   void onSwitch(const ros::MessageEvent<std_msgs::Empty const>& event) {
//     if (!guard.accept(event.getPublisherName())) return;
//     ...
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

namespace wheelchair_ros {

/// "" if `name` names a publisher: a global graph name ("/switch_keyboard": '/' then
/// segments of letters, digits and '_', each beginning with a letter) or "" (this process, for
/// a nodelet of the chair process); else the problem, naming `key`.
std::string publisherNameProblem(const std::string& key, const std::string& name);

class ExpectedPublisher {
 public:
  /// `expected` "" is this process (ros::this_node::getName() when the first message comes).
  /// Throws std::invalid_argument if publisherNameProblem says so.
  ExpectedPublisher(std::string topic, std::string expected);

  /// True if `publisher` is the expected one; else false: refused, counted, reported.
  bool accept(const std::string& publisher);
  std::uint64_t refused() const { return refused_; }
  /// The expected publisher's name ("" until resolved for this process).
  std::string expected() const;

 private:
  std::string topic_, expected_;
  std::atomic<std::uint64_t> refused_{0};
  std::atomic<double> last_report_{-1e300};
};

}  // namespace wheelchair_ros
