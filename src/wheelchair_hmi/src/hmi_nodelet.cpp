// ROS layer of the one-switch interface: /switch events and named places in, drives, stop
// requests, announcements and rviz markers out. A chosen place becomes a goal of the
// navigator's `navigate` action (wheelchair_msgs/NavigateAction); what the navigator says about
// it (its feedback's sentence: the route, waiting, blocked) and how it ended (its result's
// sentence) is told to the rider, and the result ends the drive and restarts scanning. A drive
// someone else started (rviz, a script: the navigator's ~state shows it active) puts the HMI to
// driving too, so that a press stops it. While the rider chooses, a change of the localizer's
// verdict (wheelchair_msgs/LocalizationStatus) is told in the localizer's own words.
#include "hmi_state_publisher.h"

#include <wheelchair_core/callback_cpu.h>
#include <wheelchair_hmi/places.h>
#include <wheelchair_hmi/places_watch.h>
#include <wheelchair_hmi/scan_state.h>
#include <wheelchair_hmi/switch_scanner.h>
#include <wheelchair_msgs/GoToPlace.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/NavigateAction.h>
#include <wheelchair_msgs/NavigatorState.h>
#include <wheelchair_msgs/SafetyStatus.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/drive_channel.h>
#include <wheelchair_ros/expected_publisher.h>
#include <wheelchair_ros/parameters.h>

#include <actionlib/client/simple_action_client.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>
#include <mutex>
#include <optional>

namespace wheelchair_hmi {

using NavigateClient = actionlib::SimpleActionClient<wheelchair_msgs::NavigateAction>;
using wheelchair_msgs::NavigatorState;

/// Every private parameter of the nodelet: the scanner's options and its own.
struct HmiNodeletConfig {
  ScannerOptions scanner;
  std::string places_file;  ///< required: the named places of the map
  std::string map_frame = "map";
  std::string navigator_action = "navigate";
  std::string navigator_state = "navigator/state";
  std::string localization_status = "localization/status";
  /// The one node whose /switch presses and /hmi/go_to choices are the rider's (a choice
  /// releases a latched stop and drives): any other publisher is refused and reported.
  std::string switch_publisher = "/switch_keyboard";
  std::string go_to_publisher = "/display";
  /// The one node whose go_to_place calls are the rider's: they release a latched stop. Any
  /// other caller (a script, rosservice, a misconfigured node) gets a drive like an rviz goal
  /// when nothing is stopped, but never a release: with a stop latched it is refused, reported.
  std::string go_to_caller = "/display";

  std::string validate() const {
    const std::string scanner_problem = scanner.validate();
    const std::string switch_problem =
        wheelchair_ros::publisherNameProblem("switch_publisher", switch_publisher);
    const std::string go_to_problem =
        wheelchair_ros::publisherNameProblem("go_to_publisher", go_to_publisher);
    const std::string caller_problem =
        wheelchair_ros::publisherNameProblem("go_to_caller", go_to_caller);
    wheelchair_core::ConfigChecks checks;
    checks.check(scanner_problem.empty(), scanner_problem)
        .check(switch_problem.empty(), switch_problem)
        .check(go_to_problem.empty(), go_to_problem)
        .check(caller_problem.empty(), caller_problem)
        .check(!map_frame.empty(), "map_frame must not be empty")
        .check(!navigator_action.empty(), "navigator_action must name the navigator's action");
    return checks.result();
  }
};

void readHmiNodeletConfig(wheelchair_core::ConfigReader& reader, HmiNodeletConfig& config) {
  readScannerOptions(reader, config.scanner);
  reader.require("places_file", config.places_file);
  reader.read("map_frame", config.map_frame);
  reader.renamed("frame_id", "map_frame");
  reader.renamed("controller_path_status", "navigator_action");  // the navigator owns drives
  reader.renamed("safety_status", "navigator_action");
  reader.read("navigator_action", config.navigator_action);
  reader.read("navigator_state", config.navigator_state);
  reader.read("localization_status", config.localization_status);
  reader.read("switch_publisher", config.switch_publisher);
  reader.read("go_to_publisher", config.go_to_publisher);
  reader.read("go_to_caller", config.go_to_caller);
}

class HmiNodelet : public nodelet::Nodelet {
 private:
  /// What to do with the navigator once mutex_ is released (its client takes locks of its own,
  /// and calls back into this nodelet from other threads).
  struct ClientCommand {
    std::optional<wheelchair_msgs::NavigateGoal> goal;
    bool cancel = false;
    bool release = true;  ///< the goal is the rider's command: it releases a latched stop
  };

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
    client_ = std::make_unique<NavigateClient>(nh, config.navigator_action, false);
    stop_pub_ = nh.advertise<std_msgs::Empty>("user_stop", 1);
    announce_pub_ = nh.advertise<std_msgs::String>("hmi/announce", 10, true);
    state_pub_ = std::make_unique<HmiStatePublisher>(nh);
    marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("hmi/markers", 1, true);
    switch_guard_ = std::make_unique<wheelchair_ros::ExpectedPublisher>(nh.resolveName("switch"),
                                                                        config.switch_publisher);
    go_to_guard_ = std::make_unique<wheelchair_ros::ExpectedPublisher>(nh.resolveName("hmi/go_to"),
                                                                       config.go_to_publisher);
    switch_sub_ = nh.subscribe("switch", 10, &HmiNodelet::onSwitch, this);
    go_to_sub_ = nh.subscribe("hmi/go_to", 1, &HmiNodelet::onGoTo, this);
    finished_sub_ = nh.subscribe("hmi/finished", 1, &HmiNodelet::onFinished, this);
    go_to_caller_ = config.go_to_caller;
    go_to_srv_ = nh.advertiseService("go_to_place", &HmiNodelet::onGoToPlaceCall, this);
    safety_sub_ = nh.subscribe("safety/status", 1, &HmiNodelet::onSafety, this);
    state_sub_ = nh.subscribe(config.navigator_state, 5, &HmiNodelet::onNavigatorState, this);
    localization_sub_ =
        nh.subscribe(config.localization_status, 5, &HmiNodelet::onLocalization, this);
    timer_ = nh.createTimer(ros::Duration(0.1), &HmiNodelet::onTimer, this);
    ClientCommand command;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      command = handle(scanner_->start(ros::Time::now().toSec()));
    }
    perform(command);
  }

  void onTimer(const ros::TimerEvent&) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    ClientCommand command;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      command = handle(scanner_->tick(ros::Time::now().toSec()));
      if (waiting_goal_ && !command.goal && !command.cancel) {
        if (client_->isServerConnected()) {
          command.goal = waiting_goal_;
          command.release = waiting_release_;
        } else if ((ros::WallTime::now() - waiting_since_).toSec() > kConnectTimeout) {
          NODELET_WARN("[switch] the navigator's action server is not connected");
          waiting_goal_.reset();
          endDrive("The chair did not answer: try again in a moment.");
        }
      }
      if (++ticks_ % 10 == 0) reloadPlaces();
      publishState();
    }
    perform(command);
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
      handle(scanner_->start(ros::Time::now().toSec()));  // a room scan: no goal, no stop
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

  /// A press of the rider's switch (its one publisher only: another node's press could choose a
  /// destination, which releases a stop and drives).
  void onSwitch(const ros::MessageEvent<std_msgs::Empty const>& event) {
    if (!switch_guard_->accept(event.getPublisherName())) return;
    ClientCommand command;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      command = handle(scanner_->press(ros::Time::now().toSec()));
    }
    perform(command);
  }

  void onFinished(const std_msgs::Empty::ConstPtr&) {
    ClientCommand command;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      command = handle(scanner_->finished(ros::Time::now().toSec()));
    }
    perform(command);
  }

  /// A place chosen by name (its one publisher only, as the switch).
  void onGoTo(const ros::MessageEvent<std_msgs::String const>& event) {
    if (!go_to_guard_->accept(event.getPublisherName())) return;
    wheelchair_msgs::GoToPlace::Request request;
    wheelchair_msgs::GoToPlace::Response response;
    request.name = event.getMessage()->data;
    onGoToService(request, response);
  }

  /// The go_to_place service: the rider's (go_to_caller's) call releases a latched stop; any
  /// other caller's is a goal like rviz's, which never releases a stop (with a stop in effect
  /// it moves nothing and is reported). The caller's name is its own word (ROS 1 has no
  /// authentication): this guards against mistakes of nodes inside the chair's trust domain.
  bool onGoToPlaceCall(ros::ServiceEvent<wheelchair_msgs::GoToPlace::Request,
                                         wheelchair_msgs::GoToPlace::Response>& event) {
    const std::string caller = event.getCallerName();
    const std::string rider = go_to_caller_.empty() ? ros::this_node::getName() : go_to_caller_;
    if (caller == rider) return onGoToService(event.getRequest(), event.getResponse());
    bool stopped;
    unsigned long long count;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopped = safety_stop_;
      count = ++foreign_go_to_;
    }
    if (stopped)
      NODELET_ERROR(
          "go_to_place from %s refused to release the stop: only %s (the rider's "
          "display) may (%llu foreign calls so far)",
          caller.c_str(), rider.c_str(), count);
    else
      NODELET_WARN("go_to_place from %s (not the rider's display %s): a goal, no release",
                   caller.c_str(), rider.c_str());
    return onGoToService(event.getRequest(), event.getResponse(), false);
  }

  /// The supervisor's verdict (for the report of a foreign go_to_place only: the release is
  /// the channel's, and a spoofed status releases nothing).
  void onSafety(const wheelchair_msgs::SafetyStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    safety_stop_ = msg->stop;
  }

  bool onGoToService(const wheelchair_msgs::GoToPlace::Request& request,
                     wheelchair_msgs::GoToPlace::Response& response, bool rider = true) {
    ClientCommand command;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const Place* place = findPlace(scanner_->places(), request.name);
      response.accepted = place != nullptr;
      response.message =
          place ? "Going to " + place->name + "." : "No place called '" + request.name + "'.";
      announce(response.message);
      if (place) {
        scanner_->driving(ros::Time::now().toSec());
        goal_place_ = place->name;
        command.goal = goalFor(*place);
        command.release = rider;
        publishState();
      }
    }
    perform(command);
    return true;
  }

  // ---- the navigator -------------------------------------------------------------------------

  /// Sends or cancels the rider's goal (mutex_ not held). A goal the navigator cannot take yet
  /// (its server not seen yet, e.g. just after start-up) waits up to kConnectTimeout; waiting
  /// here would block this nodelet's callbacks, the client's among them.
  void perform(const ClientCommand& command) {
    if (command.cancel) client_->cancelGoal();
    if (!command.goal) return;
    if (!client_->isServerConnected()) {
      std::lock_guard<std::mutex> lock(mutex_);
      waiting_goal_ = command.goal;
      waiting_release_ = command.release;
      waiting_since_ = ros::WallTime::now();
      return;
    }
    int goal;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      goal = ++goal_count_;
      own_goal_ = goal;
      waiting_goal_.reset();
      told_.clear();
    }
    // The rider's destination is their command to go on: it releases a latched stop of the
    // supervisor and the base driver in this process (the only release there is).
    if (command.release && !wheelchair_ros::releaseStopByRider("hmi: go to " + command.goal->place))
      NODELET_WARN_ONCE(
          "hmi: no supervisor or base driver in this process: a latched stop "
          "cannot be released from here");
    client_->sendGoal(
        *command.goal,
        [this, goal](const actionlib::SimpleClientGoalState& state,
                     const wheelchair_msgs::NavigateResultConstPtr& result) {
          onDone(goal, state, result);
        },
        NavigateClient::SimpleActiveCallback(),
        [this, goal](const wheelchair_msgs::NavigateFeedbackConstPtr& feedback) {
          onFeedback(goal, feedback->state);
        });
  }

  wheelchair_msgs::NavigateGoal goalFor(const Place& place) const {
    wheelchair_msgs::NavigateGoal goal;
    goal.place = place.name;
    goal.target_pose.header.frame_id = map_frame_;
    goal.target_pose.header.stamp = ros::Time::now();
    goal.target_pose.pose = wheelchair_ros::toPoseMsg(place.pose);
    return goal;
  }

  /// The navigator's words about the rider's drive: what it does now.
  void onFeedback(int goal, const NavigatorState& state) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (goal != own_goal_) return;
    tell(state);
  }

  /// How the rider's drive ended (exactly once per goal): told in the navigator's sentence,
  /// then scanning restarts. A goal replaced by someone else's: that drive goes on.
  void onDone(int goal, const actionlib::SimpleClientGoalState& state,
              const wheelchair_msgs::NavigateResultConstPtr& result) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (goal != own_goal_) return;
    own_goal_ = 0;
    if (result && result->reason == wheelchair_msgs::NavigateResult::REPLACED) return;
    if (result && !result->sentence.empty()) {
      NODELET_INFO("[switch] drive ended (%s): %s", state.toString().c_str(),
                   result->detail.c_str());
      endDrive(result->sentence);
    } else {
      endDrive("The chair did not answer: try again in a moment.");
    }
  }

  /// The navigator's state: someone else's drive (rviz, a script) makes the HMI a stop button
  /// and is told like the rider's own; its end (the state's sentence is then its result's)
  /// restarts scanning.
  void onNavigatorState(const NavigatorState::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool was_active = navigator_active_;
    navigator_active_ = msg->active;
    if (own_goal_ != 0) return;  // the rider's drive: told from its feedback and result
    if (msg->active) {
      const std::string place =
          !msg->place.empty()
              ? msg->place
              : placeAt(scanner_->places(), wheelchair_ros::toPose2D(msg->goal.pose));
      const bool new_place = place != goal_place_;
      goal_place_ = place;
      if (scanner_->phase() != SwitchScanner::Phase::kDriving) {
        scanner_->driving(ros::Time::now().toSec());
        told_.clear();
        announce("The chair is moving. Press to stop.");
      } else if (new_place) {
        publishState();
      }
      tell(*msg);
    } else if (was_active) {
      endDrive(msg->sentence.empty() ? "The chair has stopped." : msg->sentence);
    }
  }

  /// Tells a new sentence of the navigator once (not the ones of planning and stopping, which
  /// the rider does not need to hear).
  void tell(const NavigatorState& state) {
    if (state.state == NavigatorState::STOPPING || state.sentence.empty()) return;
    if (state.sentence == told_) return;
    told_ = state.sentence;
    announce(state.sentence);
  }

  /// The localizer's verdict: while the rider chooses, a change between localized and not is
  /// told in the localizer's words (a first "localized" is not news). While the chair drives,
  /// the navigator says what a loss means for the drive.
  void onLocalization(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool news = localized_ ? *localized_ != msg->localized : !msg->localized;
    localized_ = msg->localized;
    if (!news || scanner_->phase() == SwitchScanner::Phase::kDriving) return;
    announce(!msg->sentence.empty() ? msg->sentence
             : msg->localized       ? "The chair knows where it is."
                                    : "The chair does not know where it is.");
  }

  /// While driving: tells the rider why the drive ended and scans rooms again.
  void endDrive(const std::string& why) {
    if (scanner_->phase() != SwitchScanner::Phase::kDriving) return;
    announce(why);
    handle(scanner_->finished(ros::Time::now().toSec()));
  }

  /// What the scanner wants (mutex_ held): announcements, markers, a stop; a goal or a cancel
  /// for the navigator comes back to be performed once the lock is released.
  ClientCommand handle(const ScanOutput& out) {
    ClientCommand command;
    if (out.kind == ScanOutput::Kind::kNone) return command;
    announce(out.text);
    if (out.kind == ScanOutput::Kind::kGo) {
      goal_place_ = out.place->name;
      command.goal = goalFor(*out.place);
    }
    if (out.kind == ScanOutput::Kind::kStop) {
      waiting_goal_.reset();
      // The supervisor and the controller stop at once; the navigator ends the drive (the
      // rider's own goal, or anyone's: it ends a drive the supervisor stopped for the rider).
      stop_pub_.publish(std_msgs::Empty());
      command.cancel = own_goal_ != 0;
      own_goal_ = 0;
    }
    publishMarkers(out);
    publishState();
    return command;
  }

  void announce(const std::string& text) {
    NODELET_INFO("[switch] %s", text.c_str());
    std_msgs::String msg;
    msg.data = text;
    announce_pub_.publish(msg);
    last_sentence_ = text;
    publishState();
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
  std::unique_ptr<NavigateClient> client_;
  std::string map_frame_;
  ros::Publisher stop_pub_, announce_pub_, marker_pub_;
  ros::Subscriber switch_sub_, go_to_sub_, finished_sub_, state_sub_, localization_sub_;
  std::unique_ptr<wheelchair_ros::ExpectedPublisher> switch_guard_, go_to_guard_;
  std::optional<wheelchair_msgs::NavigateGoal> waiting_goal_;  ///< for the server to be seen
  bool waiting_release_ = true;
  ros::WallTime waiting_since_;
  static constexpr double kConnectTimeout = 5.0;  ///< [s] wall
  int goal_count_ = 0;
  int own_goal_ = 0;               ///< the rider's goal in flight (0: none)
  bool navigator_active_ = false;  ///< the navigator's last state: a drive in progress
  std::string told_;               ///< the navigator's sentence last told
  std::optional<bool> localized_;  ///< the localizer's last verdict
  std::unique_ptr<HmiStatePublisher> state_pub_;
  std::unique_ptr<PlacesFileWatch> places_watch_;
  std::optional<std::vector<Place>> pending_places_;  ///< read, waiting for the room scan
  ScannerOptions scanner_options_;
  unsigned ticks_ = 0;
  std::string goal_place_;     ///< the place the chair drives to ("" for a spot)
  std::string last_sentence_;  ///< the last announcement
  ros::ServiceServer go_to_srv_;
  ros::Subscriber safety_sub_;
  std::string go_to_caller_;
  bool safety_stop_ = false;  ///< the supervisor's last verdict (mutex_)
  unsigned long long foreign_go_to_ = 0;
  ros::Timer timer_;
};

}  // namespace wheelchair_hmi

PLUGINLIB_EXPORT_CLASS(wheelchair_hmi::HmiNodelet, nodelet::Nodelet)
