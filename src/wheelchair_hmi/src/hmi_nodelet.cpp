// ROS layer of the one-switch interface: /switch events and named places in, goals, stop
// requests, announcements and rviz markers out. It also tells the rider what became of a
// goal: refused by the planner (with its reason), reached or aborted by the controller, or
// stopped by the safety supervisor (wheelchair_msgs/SafetyStatus); each of those ends the drive
// and restarts scanning. While the rider chooses, a change of the localizer's verdict
// (wheelchair_msgs/LocalizationStatus) is told in the localizer's own words.
// The controller's outcome is read from ~path_status, which names the path it concerns: the end
// of a path older than the rider's latest command (a goal, a stop) is not this drive's end.
#include "hmi_state_publisher.h"

#include <wheelchair_hmi/places.h>
#include <wheelchair_hmi/places_watch.h>
#include <wheelchair_hmi/scan_state.h>
#include <wheelchair_hmi/switch_scanner.h>
#include <wheelchair_msgs/GoToPlace.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/PlanCertificate.h>
#include <wheelchair_msgs/SafetyStatus.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/drive_channel.h>
#include <wheelchair_ros/parameters.h>

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
#include <optional>

namespace wheelchair_hmi {

/// Every private parameter of the nodelet: the scanner's options and its own.
struct HmiNodeletConfig {
  ScannerOptions scanner;
  std::string places_file;  ///< required: the named places of the map
  std::string map_frame = "map";
  std::string controller_path_status = "controller/path_status";
  std::string safety_status = "safety/status";
  std::string localization_status = "localization/status";

  std::string validate() const {
    const std::string scanner_problem = scanner.validate();
    wheelchair_core::ConfigChecks checks;
    checks.check(scanner_problem.empty(), scanner_problem)
        .check(!map_frame.empty(), "map_frame must not be empty");
    return checks.result();
  }
};

void readHmiNodeletConfig(wheelchair_core::ConfigReader& reader, HmiNodeletConfig& config) {
  readScannerOptions(reader, config.scanner);
  reader.require("places_file", config.places_file);
  reader.read("map_frame", config.map_frame);
  reader.renamed("frame_id", "map_frame");
  reader.read("controller_path_status", config.controller_path_status);
  reader.read("safety_status", config.safety_status);
  reader.read("localization_status", config.localization_status);
}

class HmiNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle nh = getNodeHandle();
    const auto config = wheelchair_ros::loadParameters<HmiNodeletConfig>(getPrivateNodeHandle(),
                                                                         readHmiNodeletConfig);
    map_frame_ = config.map_frame;
    try {
      scanner_ = std::make_unique<SwitchScanner>(loadPlaces(config.places_file), config.scanner);
      places_watch_ = std::make_unique<PlacesFileWatch>(config.places_file);
      scanner_options_ = config.scanner;
    } catch (const std::exception& e) {  // no destinations to offer: refuse to start
      NODELET_FATAL("%s", e.what());
      throw wheelchair_core::ConfigError(getPrivateNodeHandle().getNamespace() + ": " + e.what());
    }
    goal_pub_ = nh.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
    stop_pub_ = nh.advertise<std_msgs::Empty>("user_stop", 1);
    announce_pub_ = nh.advertise<std_msgs::String>("hmi/announce", 10, true);
    state_pub_ = std::make_unique<HmiStatePublisher>(nh);
    marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("hmi/markers", 1, true);
    switch_sub_ = nh.subscribe("switch", 10, &HmiNodelet::onSwitch, this);
    go_to_sub_ = nh.subscribe("hmi/go_to", 1, &HmiNodelet::onGoTo, this);
    finished_sub_ = nh.subscribe("hmi/finished", 1, &HmiNodelet::onFinished, this);
    go_to_srv_ = nh.advertiseService("go_to_place", &HmiNodelet::onGoToService, this);
    outcome_subs_.push_back(nh.subscribe("move_base_simple/goal", 1, &HmiNodelet::onGoal, this));
    outcome_subs_.push_back(nh.subscribe("plan_certificate", 1, &HmiNodelet::onPlan, this));
    outcome_subs_.push_back(
        nh.subscribe(config.controller_path_status, 5, &HmiNodelet::onController, this));
    outcome_subs_.push_back(nh.subscribe(config.safety_status, 5, &HmiNodelet::onSafety, this));
    outcome_subs_.push_back(
        nh.subscribe(config.localization_status, 5, &HmiNodelet::onLocalization, this));
    timer_ = nh.createTimer(ros::Duration(0.1), &HmiNodelet::onTimer, this);
    std::lock_guard<std::mutex> lock(mutex_);
    handle(scanner_->start(ros::Time::now().toSec()));
  }

  void onTimer(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    handle(scanner_->tick(ros::Time::now().toSec()));
    if (++ticks_ % 10 == 0) reloadPlaces();
    publishState();
  }

  /// A changed places file (the carer saved a place on the display) is offered from the next
  /// room scan on; a choice or a drive under way is not disturbed.
  void reloadPlaces() {
    std::string problem;
    if (auto places = places_watch_->changed(problem)) pending_places_ = std::move(places);
    if (!problem.empty())
      NODELET_ERROR("[switch] the places file changed but is not used (the old places stay): %s",
                    problem.c_str());
    if (!pending_places_ || scanner_->phase() != SwitchScanner::Phase::kGroups) return;
    try {
      auto scanner = std::make_unique<SwitchScanner>(std::move(*pending_places_), scanner_options_);
      scanner_ = std::move(scanner);
      NODELET_INFO("[switch] places file read again: %zu places", scanner_->places().size());
      handle(scanner_->start(ros::Time::now().toSec()));
    } catch (const std::exception& e) {
      NODELET_ERROR("[switch] the new places are not used (the old places stay): %s", e.what());
    }
    pending_places_.reset();
  }

  /// /hmi/state when what it shows changed (called after every event and every tick).
  void publishState() {
    ScanState state = scanState(*scanner_, ros::Time::now().toSec(), goal_place_);
    state.sentence = last_sentence_;
    state_pub_->publish(state);
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
    goal_place_ = placeAt(scanner_->places(), wheelchair_ros::toPose2D(msg->pose));
    if (certificate_ && certificate_->header.stamp >= goal_stamp_) answerGoal();
    publishState();
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

  /// The supervisor's verdict: a new stop ends the drive, told in the supervisor's words (its
  /// detail goes to the log); the same stop again is not news.
  void onSafety(const wheelchair_msgs::SafetyStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!msg->stop) {
      last_safety_.reset();
      return;
    }
    if (last_safety_ && last_safety_->reason == msg->reason && last_safety_->detail == msg->detail)
      return;
    last_safety_ = *msg;
    if (scanner_->phase() == SwitchScanner::Phase::kDriving)
      NODELET_INFO("[switch] safety stop: %s", msg->detail.c_str());
    endDrive("Safety stop: " + msg->sentence + ". Choose a destination to go on.");
  }

  /// The localizer's verdict: while the rider chooses, a change between localized and not is
  /// told in the localizer's words (a first "localized" is not news). While the chair drives, a
  /// loss stops it and the safety stop is what the rider hears.
  void onLocalization(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool news = localized_ ? *localized_ != msg->localized : !msg->localized;
    localized_ = msg->localized;
    if (!news || scanner_->phase() == SwitchScanner::Phase::kDriving) return;
    announce(!msg->sentence.empty() ? msg->sentence
             : msg->localized       ? "The chair knows where it is."
                                    : "The chair does not know where it is.");
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
    publishState();
  }

  void announce(const std::string& text) {
    NODELET_INFO("[switch] %s", text.c_str());
    std_msgs::String msg;
    msg.data = text;
    announce_pub_.publish(msg);
    last_sentence_ = text;
    publishState();
  }

  /// The rider's destination: their command to go on. It releases a latched stop of the
  /// supervisor and the base driver in this process (the only release there is), then the goal
  /// goes out.
  void publishGoal(const Place& place) {
    if (!wheelchair_ros::releaseStopByRider("hmi: go to " + place.name))
      NODELET_WARN_ONCE(
          "hmi: no supervisor or base driver in this process: a latched stop "
          "cannot be released from here");
    geometry_msgs::PoseStamped goal;
    goal.header.frame_id = map_frame_;
    goal.header.stamp = ros::Time::now();
    goal.pose = wheelchair_ros::toPoseMsg(place.pose);
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
        m.header.frame_id = map_frame_;
        m.header.stamp = ros::Time::now();
        m.ns = text ? "place_names" : "places";
        m.id = static_cast<int>(i);
        m.type = text ? visualization_msgs::Marker::TEXT_VIEW_FACING
                      : visualization_msgs::Marker::SPHERE;
        m.text = text ? places[i].name : "";
        m.pose.position.x = places[i].pose.x;
        m.pose.position.y = places[i].pose.y;
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
  std::unique_ptr<HmiStatePublisher> state_pub_;
  std::unique_ptr<PlacesFileWatch> places_watch_;
  std::optional<std::vector<Place>> pending_places_;  ///< read, waiting for the room scan
  ScannerOptions scanner_options_;
  unsigned ticks_ = 0;
  std::string goal_place_;     ///< the place the chair drives to ("" for a spot)
  std::string last_sentence_;  ///< the last announcement
  std::string map_frame_;
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
  std::optional<wheelchair_msgs::SafetyStatus> last_safety_;  ///< the stop last told
  std::optional<bool> localized_;                             ///< the localizer's last verdict
  ros::ServiceServer go_to_srv_;
  ros::Timer timer_;
};

}  // namespace wheelchair_hmi

PLUGINLIB_EXPORT_CLASS(wheelchair_hmi::HmiNodelet, nodelet::Nodelet)
