#include <wheelchair_ros/expected_publisher.h>

#include <ros/ros.h>

#include <cctype>
#include <stdexcept>

namespace wheelchair_ros {

namespace {
constexpr double kReportPeriod = 5.0;  // [s of wall time] between reports of one topic

bool validSegment(const std::string& segment) {
  if (segment.empty() || !std::isalpha(static_cast<unsigned char>(segment[0]))) return false;
  for (char c : segment)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}
}  // namespace

std::string publisherNameProblem(const std::string& key, const std::string& name) {
  if (name.empty()) return "";
  if (name[0] != '/')
    return key + " '" + name + "' must be a global node name such as /switch_keyboard";
  std::size_t begin = 1;
  while (true) {
    const std::size_t end = name.find('/', begin);
    if (!validSegment(name.substr(begin, end == std::string::npos ? end : end - begin)))
      return key + " '" + name + "' is not a valid node name";
    if (end == std::string::npos) return "";
    begin = end + 1;
  }
}

ExpectedPublisher::ExpectedPublisher(std::string topic, std::string expected)
    : topic_(std::move(topic)), expected_(std::move(expected)) {
  const std::string problem = publisherNameProblem("the publisher of " + topic_, expected_);
  if (!problem.empty()) throw std::invalid_argument(problem);
}

std::string ExpectedPublisher::expected() const {
  return expected_.empty() ? ros::this_node::getName() : expected_;
}

bool ExpectedPublisher::accept(const std::string& publisher) {
  if (publisher == expected()) return true;
  ++refused_;
  const double now = ros::WallTime::now().toSec();
  if (now - last_report_.load() >= kReportPeriod) {
    last_report_ = now;
    ROS_ERROR("%s from %s refused: only %s may publish it (%llu refused so far)", topic_.c_str(),
              publisher.c_str(), expected().c_str(),
              static_cast<unsigned long long>(refused_.load()));
  }
  return false;
}

}  // namespace wheelchair_ros
