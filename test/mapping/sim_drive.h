// The simulator's chair driven along a route of waypoints by wheel torques on /wheel_torques,
// closed over the simulator's ground truth (/sim/ground_truth): a carer pushing the chair in the
// mapping tests (test/mapping, test/slam). Collects the scans received on /scan with the
// ground-truth base_link pose at each scan's stamp, and /sim/collision.
//
// The torque loops close over ROS, so their delay is the test's latency times the simulator's
// speed: the gains keep k delay < pi/2 up to ~0.5 s simulated, ~200 ms of wall latency at speed
// 2.5. Speed: 40 N m per m/s and wheel on ~145 kg (r 0.17 m) is a rate k of ~3.2 /s; yaw:
// 20 N m per rad/s and wheel on ~25 kg m^2 (b 0.275 m) is ~2.6 /s. (150 and 60 at speed 5 were
// ~12 and ~8 /s, unstable beyond ~25 ms of latency: on a loaded machine the chair rocked in
// place for minutes or hit the doorway.)
#pragma once

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <wheelchair_ros/conversions.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace wheelchair_test_drive {

struct Waypoint {
  double x, y;
};

inline double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

// Line following on ground truth: (v, w) wanted to follow segment a→b, and whether b is reached.
struct Command {
  double v = 0, w = 0;
  bool reached = false;
};

inline Command followSegment(const wheelchair_core::Pose2D& p, const Waypoint& a,
                             const Waypoint& b) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const double ux = (b.x - a.x) / len, uy = (b.y - a.y) / len;
  const double along = (p.x - a.x) * ux + (p.y - a.y) * uy;
  Command c;
  if (along >= len - 0.02) {
    c.reached = true;
    return c;
  }
  const double look = std::min(len, along + 0.4);  // pure pursuit on a point 0.4 m ahead
  const double heading_error =
      wrap(std::atan2(a.y + look * uy - p.y, a.x + look * ux - p.x) - p.yaw);
  c.w = std::clamp(2.5 * heading_error, -0.8, 0.8);
  c.v = std::abs(heading_error) > 0.3 ? 0.0 : std::min(0.6, 0.1 + 0.8 * (len - along));
  return c;
}

class SimDrive {
 public:
  /// Follows `route` from where the chair is, then turns to `final_yaw` and brakes.
  SimDrive(std::vector<Waypoint> route, double final_yaw)
      : route_(std::move(route)), final_yaw_(final_yaw) {
    torques_ = nh_.advertise<wheelchair_msgs::WheelTorques>("/wheel_torques", 10);
    truth_sub_ = nh_.subscribe("/sim/ground_truth", 1000, &SimDrive::onTruth, this);
    scan_sub_ = nh_.subscribe("/scan", 100, &SimDrive::onScan, this);
    collision_sub_ = nh_.subscribe<std_msgs::Bool>(
        "/sim/collision", 1, [this](const std_msgs::Bool::ConstPtr& m) { collided_ |= m->data; });
  }

  bool done() const { return finished_; }
  /// [s] simulated time since the first ground-truth pose.
  double simSeconds() const {
    return truth_.empty() ? 0.0 : (truth_.rbegin()->first - first_truth_).toSec();
  }
  bool collided() const { return collided_; }
  /// Scans received over /scan, each with the ground-truth base_link pose at its stamp.
  const std::vector<std::pair<wheelchair_core::LaserScan2D, wheelchair_core::Pose2D>>& scans()
      const {
    return scans_;
  }

 private:
  void onTruth(const nav_msgs::Odometry::ConstPtr& m) {
    const wheelchair_core::Pose2D p = wheelchair_ros::toPose2D(m->pose.pose);
    if (first_truth_.isZero()) first_truth_ = m->header.stamp;
    truth_[m->header.stamp] = p;
    while (truth_.size() > 400) truth_.erase(truth_.begin());
    matchScans();
    if (m->header.stamp < next_control_) return;
    next_control_ = m->header.stamp + ros::Duration(0.02);  // 50 Hz control
    control(p, m->twist.twist.linear.x, m->twist.twist.angular.z);
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& m) {
    if (!finished_) pending_.push_back(m);
    matchScans();
  }

  void matchScans() {
    while (!pending_.empty()) {
      const auto it = truth_.find(pending_.front()->header.stamp);
      if (it == truth_.end()) {
        if (!truth_.empty() && pending_.front()->header.stamp < truth_.begin()->first) {
          pending_.erase(pending_.begin());  // its pose is gone
          continue;
        }
        return;
      }
      scans_.emplace_back(wheelchair_ros::fromLaserScanMsg(*pending_.front()), it->second);
      pending_.erase(pending_.begin());
    }
  }

  void control(const wheelchair_core::Pose2D& p, double v, double w) {
    Command c;
    while (segment_ < route_.size()) {
      const Waypoint from = segment_ == 0 ? start_ : route_[segment_ - 1];
      if (segment_ == 0 && !started_) {
        start_ = {p.x, p.y};
        started_ = true;
        continue;
      }
      c = followSegment(p, from, route_[segment_]);
      if (!c.reached) break;
      ++segment_;
    }
    if (segment_ == route_.size()) {
      const double err = wrap(final_yaw_ - p.yaw);
      c = Command{0.0, std::clamp(2.5 * err, -0.8, 0.8), false};
      finished_ = std::abs(err) < 0.02 && std::abs(w) < 0.05 && std::abs(v) < 0.05;
    }
    // P control of speed and yaw rate through the sum and difference of the wheel torques.
    wheelchair_msgs::WheelTorques t;
    t.header.stamp = ros::Time::now();
    const double common = 40.0 * (c.v - v), diff = 20.0 * (c.w - w);
    t.right = common + diff;
    t.left = common - diff;
    t.brake = finished_;
    torques_.publish(t);
  }

  std::vector<Waypoint> route_;
  double final_yaw_ = 0.0;
  ros::NodeHandle nh_;
  ros::Publisher torques_;
  ros::Subscriber truth_sub_, scan_sub_, collision_sub_;
  std::map<ros::Time, wheelchair_core::Pose2D> truth_;
  std::vector<sensor_msgs::LaserScan::ConstPtr> pending_;
  std::vector<std::pair<wheelchair_core::LaserScan2D, wheelchair_core::Pose2D>> scans_;
  ros::Time next_control_, first_truth_;
  Waypoint start_{0, 0};
  bool started_ = false;
  size_t segment_ = 0;
  bool finished_ = false;
  bool collided_ = false;
};

}  // namespace wheelchair_test_drive
