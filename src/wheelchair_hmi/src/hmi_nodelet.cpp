// ROS layer of the one-switch interface: /switch events and named places in, goals, stop
// requests, announcements and rviz markers out. It also tells the rider what became of a
// goal: refused by the planner (with its reason), reached or aborted by the controller, or
// stopped by the safety supervisor; each of those ends the drive and restarts scanning.
// The controller's outcome is read from ~path_status, which names the path it concerns: the end
// of a path older than the rider's latest command (a goal, a stop) is not this drive's end.
#include <wheelchair_hmi/places.h>
#include <wheelchair_hmi/switch_scanner.h>
#include <wheelchair_msgs/GoToPlace.h>
#include <wheelchair_msgs/PlanCertificate.h>

#include <actionlib_msgs/GoalStatus.h>

#include <geometry_msgs/PoseStamped.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>
#include <pluginlib/class_list_macros.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>

namespace wheelchair_hmi {

class HmiNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle nh = getNodeHandle(), pnh = getPrivateNodeHandle();
    std::string places_file;
    if (!pnh.getParam("places_file", places_file)) {
      NODELET_FATAL("~places_file is not set: no destinations to offer");
      return;
    }
    ScannerOptions options;
    pnh.param("scan_interval", options.scan_interval, options.scan_interval);
    pnh.param("confirm_timeout", options.confirm_timeout, options.confirm_timeout);
    pnh.param("item_cycles", options.item_cycles, options.item_cycles);
    pnh.param<std::string>("frame_id", frame_id_, "map");
    try {
      scanner_ = std::make_unique<SwitchScanner>(loadPlaces(places_file), options);
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      return;
    }
    goal_pub_ = nh.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
    stop_pub_ = nh.advertise<std_msgs::Empty>("user_stop", 1);
    announce_pub_ = nh.advertise<std_msgs::String>("hmi/announce", 10, true);
    marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("hmi/markers", 1, true);
    switch_sub_ = nh.subscribe("switch", 10, &HmiNodelet::onSwitch, this);
    go_to_sub_ = nh.subscribe("hmi/go_to", 1, &HmiNodelet::onGoTo, this);
    finished_sub_ = nh.subscribe("hmi/finished", 1, &HmiNodelet::onFinished, this);
    go_to_srv_ = nh.advertiseService("go_to_place", &HmiNodelet::onGoToService, this);
    std::string controller_status, safety_status;
    pnh.param<std::string>("controller_path_status", controller_status, "controller/path_status");
    pnh.param<std::string>("safety_status", safety_status, "safety/status");
    outcome_subs_.push_back(nh.subscribe("move_base_simple/goal", 1, &HmiNodelet::onGoal, this));
    outcome_subs_.push_back(nh.subscribe("plan_certificate", 1, &HmiNodelet::onPlan, this));
    outcome_subs_.push_back(nh.subscribe(controller_status, 5, &HmiNodelet::onController, this));
    outcome_subs_.push_back(nh.subscribe(safety_status, 5, &HmiNodelet::onSafety, this));
    timer_ = nh.createTimer(ros::Duration(0.1), &HmiNodelet::onTimer, this);
    std::lock_guard<std::mutex> lock(mutex_);
    handle(scanner_->start(ros::Time::now().toSec()));
  }

  void onTimer(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    handle(scanner_->tick(ros::Time::now().toSec()));
  }

  void onSwitch(const std_msgs::Empty::ConstPtr&) {
    std::lock_guard<std::mutex> lock(mutex_);
    const ScanOutput out = scanner_->press(ros::Time::now().toSec());
    // The rider's stop is the latest command: what the controller still says about the path
    // it stops (e.g. "tracking" sent just before the stop) does not restart the drive.
    if (out.kind == ScanOutput::Kind::kStop) command_stamp_ = ros::Time::now();
    handle(out);
  }

  void onFinished(const std_msgs::Empty::ConstPtr&) {
    std::lock_guard<std::mutex> lock(mutex_);
    handle(scanner_->finished(ros::Time::now().toSec()));
  }

  /// Any goal (ours, rviz's): the chair is about to drive; a press stops it. The planner's
  /// answer may be processed before or after this (different nodelets, different threads).
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    scanner_->driving(ros::Time::now().toSec());
    goal_stamp_ = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
    command_stamp_ = goal_stamp_;
    goal_pending_ = true;
    if (certificate_ && certificate_->header.stamp >= goal_stamp_) answerGoal();
  }

  void onPlan(const wheelchair_msgs::PlanCertificate::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    certificate_ = msg;
    if (goal_pending_ && msg->header.stamp >= goal_stamp_) answerGoal();
  }

  /// The planner's answer to the goal: a refusal is told to the rider, the chair stays.
  void answerGoal() {
    goal_pending_ = false;
    if (certificate_->success) {
      announce("Route found: " + formatLength(certificate_->length) + ".");
      return;
    }
    // A goal refused during a drive: the chair may still follow the previous path (the host
    // publishes no path for a goal it rejects outright); it stays where it is, as told.
    if (controller_moving_) stop_pub_.publish(std_msgs::Empty());
    endDrive("Cannot go there: " + certificate_->failure_reason + ". The chair stays where it is.");
  }

  /// The controller's state and the path it concerns (stamped by the planner after the goal
  /// came). Ignored when that path is older than the rider's latest command: the previous
  /// drive's "goal_reached" can come after a new goal, before the new path reached the
  /// controller. Otherwise "goal_reached" or "aborted: why" ends the drive, and a moving chair
  /// (a new path, e.g. a replan, while scanning) puts the HMI back to driving: a press stops it.
  void onController(const actionlib_msgs::GoalStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    controller_moving_ = msg->status == actionlib_msgs::GoalStatus::ACTIVE ||
                         msg->status == actionlib_msgs::GoalStatus::PREEMPTING;
    if (msg->goal_id.stamp + ros::Duration(kStampTolerance) < command_stamp_) return;
    if (msg->status == actionlib_msgs::GoalStatus::SUCCEEDED) endDrive("Arrived.");
    if (msg->status == actionlib_msgs::GoalStatus::ABORTED) endDrive("Stopped: " + msg->text + ".");
    if (msg->status == actionlib_msgs::GoalStatus::ACTIVE &&
        scanner_->phase() != SwitchScanner::Phase::kDriving) {
      scanner_->driving(ros::Time::now().toSec());
      announce("The chair is moving (" + msg->text + "). Press to stop.");
    }
  }

  /// The supervisor's verdict: "safe" or "<reason>: <detail>".
  void onSafety(const std_msgs::String::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (msg->data == "safe") last_safety_.clear();
    if (msg->data == "safe" || msg->data == last_safety_) return;
    last_safety_ = msg->data;
    endDrive("Safety stop: " + msg->data + ". Choose a destination to go on.");
  }

  static std::string formatLength(double metres) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f m", metres);
    return text;
  }

  /// While driving: tells the rider why the drive ended and scans rooms again.
  void endDrive(const std::string& why) {
    if (scanner_->phase() != SwitchScanner::Phase::kDriving) return;
    announce(why);
    handle(scanner_->finished(ros::Time::now().toSec()));
  }

  void onGoTo(const std_msgs::String::ConstPtr& msg) {
    wheelchair_msgs::GoToPlace::Request request;
    wheelchair_msgs::GoToPlace::Response response;
    request.name = msg->data;
    onGoToService(request, response);
  }

  bool onGoToService(wheelchair_msgs::GoToPlace::Request& request,
                     wheelchair_msgs::GoToPlace::Response& response) {
    std::lock_guard<std::mutex> lock(mutex_);
    const Place* place = findPlace(scanner_->places(), request.name);
    response.accepted = place != nullptr;
    response.message =
        place ? "Going to " + place->name + "." : "No place called '" + request.name + "'.";
    announce(response.message);
    if (place) publishGoal(*place);
    return true;
  }

  void handle(const ScanOutput& out) {
    if (out.kind == ScanOutput::Kind::kNone) return;
    announce(out.text);
    if (out.kind == ScanOutput::Kind::kGo) publishGoal(*out.place);
    if (out.kind == ScanOutput::Kind::kStop) stop_pub_.publish(std_msgs::Empty());
    publishMarkers(out);
  }

  void announce(const std::string& text) {
    NODELET_INFO("[switch] %s", text.c_str());
    std_msgs::String msg;
    msg.data = text;
    announce_pub_.publish(msg);
  }

  void publishGoal(const Place& place) {
    geometry_msgs::PoseStamped goal;
    goal.header.frame_id = frame_id_;
    goal.header.stamp = ros::Time::now();
    goal.pose.position.x = place.x;
    goal.pose.position.y = place.y;
    goal.pose.orientation.z = std::sin(0.5 * place.yaw);
    goal.pose.orientation.w = std::cos(0.5 * place.yaw);
    goal_pub_.publish(goal);
  }

  /// Every place as a sphere with its name; the highlighted room or place stands out.
  void publishMarkers(const ScanOutput& out) {
    visualization_msgs::MarkerArray array;
    const auto& places = scanner_->places();
    for (size_t i = 0; i < places.size(); ++i) {
      const bool lit = out.place ? out.place == &places[i] : places[i].room == out.group;
      for (int text = 0; text < 2; ++text) {
        visualization_msgs::Marker m;
        m.header.frame_id = frame_id_;
        m.header.stamp = ros::Time::now();
        m.ns = text ? "place_names" : "places";
        m.id = static_cast<int>(i);
        m.type = text ? visualization_msgs::Marker::TEXT_VIEW_FACING
                      : visualization_msgs::Marker::SPHERE;
        m.text = text ? places[i].name : "";
        m.pose.position.x = places[i].x;
        m.pose.position.y = places[i].y;
        m.pose.position.z = text ? 0.5 : 0.1;
        m.pose.orientation.w = 1.0;
        m.scale.x = m.scale.y = m.scale.z = lit ? 0.45 : 0.2;
        m.color.a = 1.0;
        m.color.r = lit ? 1.0f : 0.3f;
        m.color.g = lit ? 0.8f : 0.3f;
        m.color.b = lit ? 0.0f : 0.9f;
        array.markers.push_back(m);
      }
    }
    marker_pub_.publish(array);
  }

  std::mutex mutex_;
  std::unique_ptr<SwitchScanner> scanner_;
  std::string frame_id_;
  ros::Publisher goal_pub_, stop_pub_, announce_pub_, marker_pub_;
  ros::Subscriber switch_sub_, go_to_sub_, finished_sub_;
  std::vector<ros::Subscriber> outcome_subs_;
  bool goal_pending_ = false;
  ros::Time goal_stamp_;
  ros::Time command_stamp_;         ///< the rider's latest command: a goal's stamp, a stop's time
  bool controller_moving_ = false;  ///< the controller's last status, whatever its path
  /// [s] a path stamped this much before the command still counts as its answer: the planner
  /// stamps /plan after the goal came, but a goal from another process (rviz) may carry a clock
  /// a little ahead. An old drive's path is older by that drive's duration (seconds).
  static constexpr double kStampTolerance = 0.1;
  wheelchair_msgs::PlanCertificate::ConstPtr certificate_;
  std::string last_safety_;
  ros::ServiceServer go_to_srv_;
  ros::Timer timer_;
};

}  // namespace wheelchair_hmi

PLUGINLIB_EXPORT_CLASS(wheelchair_hmi::HmiNodelet, nodelet::Nodelet)
