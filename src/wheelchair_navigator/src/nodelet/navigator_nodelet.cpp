// ROS layer of the navigator: two action servers (`move_base`, move_base_msgs/MoveBaseAction,
// for rviz and scripts; `navigate`, wheelchair_msgs/NavigateAction, a pose or a named place,
// with the rider's reasons) and /move_base_simple/goal, all driving the one ROS-free Navigator.
// It asks the planner host (~planner_service) for routes on a worker thread, hands routes to
// the controller on /plan (each stamped uniquely: the controller's ~path_status names the
// route by that stamp), and feeds the core the supervisor's /safety/status, the localizer's
// /localization/status, tf map -> base_link, /map and the obstacle layer /obstacles.
// Goal handles are only touched by one dispatcher thread, never inside a server's callback (so
// the two servers' locks and the core's are never taken in opposite orders).
#include <wheelchair_description/chair_file.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_hmi/places.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/MakePlan.h>
#include <wheelchair_msgs/NavigateAction.h>
#include <wheelchair_msgs/NavigatorState.h>
#include <wheelchair_msgs/SafetyStatus.h>
#include <wheelchair_navigator/back_up.h>
#include <wheelchair_navigator/navigator.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/drive_channel.h>
#include <wheelchair_ros/parameters.h>
#include <wheelchair_ros/shared_tf.h>

#include "navigator_parameters.h"

#include <actionlib/server/action_server.h>
#include <actionlib_msgs/GoalStatus.h>
#include <geometry_msgs/PoseStamped.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <pluginlib/class_list_macros.hpp>

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace wheelchair_navigator {

namespace {

using MoveBaseServer = actionlib::ActionServer<move_base_msgs::MoveBaseAction>;
using NavigateServer = actionlib::ActionServer<wheelchair_msgs::NavigateAction>;
using wheelchair_msgs::NavigateResult;
using wheelchair_msgs::NavigatorState;

// The core's enums are the messages' numbers.
static_assert(static_cast<int>(Reason::kReached) == NavigateResult::REACHED);
static_assert(static_cast<int>(Reason::kBlocked) == NavigateResult::BLOCKED);
static_assert(static_cast<int>(Reason::kNotReady) == NavigateResult::NOT_READY);
static_assert(static_cast<int>(State::kBlocked) == NavigatorState::BLOCKED);
static_assert(static_cast<int>(State::kStopping) == NavigatorState::STOPPING);

SafetyCause causeOf(const wheelchair_msgs::SafetyStatus& s) {
  using wheelchair_msgs::SafetyStatus;
  switch (s.reason) {
    case SafetyStatus::NONE:
      return SafetyCause::kNone;
    case SafetyStatus::NO_DATA:
      return SafetyCause::kNoData;
    case SafetyStatus::OBSTACLE:
      return SafetyCause::kObstacle;
    case SafetyStatus::USER_STOP:
      return SafetyCause::kUserStop;
    case SafetyStatus::LOCALIZATION_LOST:
      return SafetyCause::kLocalization;
    default:
      return SafetyCause::kOther;
  }
}

ControllerPhase phaseOf(uint8_t status) {
  using actionlib_msgs::GoalStatus;
  switch (status) {
    case GoalStatus::ACTIVE:
      return ControllerPhase::kActive;
    case GoalStatus::PREEMPTING:
      return ControllerPhase::kStopping;
    case GoalStatus::SUCCEEDED:
      return ControllerPhase::kReached;
    case GoalStatus::ABORTED:
      return ControllerPhase::kAborted;
    default:
      return ControllerPhase::kIdle;
  }
}

}  // namespace

class NavigatorNodelet : public nodelet::Nodelet {
 public:
  ~NavigatorNodelet() override {
    {
      std::lock_guard<std::mutex> lock(plan_mutex_);
      std::lock_guard<std::mutex> lock2(effects_mutex_);
      shutdown_ = true;
    }
    plan_cv_.notify_all();
    effects_cv_.notify_all();
    if (planner_thread_.joinable()) planner_thread_.join();
    if (dispatcher_.joinable()) dispatcher_.join();
  }

 private:
  /// What happens to a client's goal handle, applied by the dispatcher thread in order.
  struct Effect {
    enum class Kind { kAccept, kResult, kFeedback };
    Kind kind = Kind::kAccept;
    std::string goal_id;
    DriveResult result;
    NavigatorState state;

    static Effect accept(const std::string& id) { return {Kind::kAccept, id, {}, {}}; }
    static Effect resultOf(const DriveResult& r) { return {Kind::kResult, r.goal_id, r, {}}; }
    static Effect feedback(const std::string& id, const NavigatorState& s) {
      Effect e;
      e.kind = Kind::kFeedback;
      e.goal_id = id;
      e.state = s;
      return e;
    }
  };
  /// A goal of either server.
  struct Handle {
    std::optional<MoveBaseServer::GoalHandle> move_base;
    std::optional<NavigateServer::GoalHandle> navigate;
  };

  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    params_ = wheelchair_ros::loadParameters<NavigatorParameters>(getPrivateNodeHandle(),
                                                                  readNavigatorParameters);
    try {
      chair_ = wheelchair_description::loadChairParams(
          wheelchair_description::resolveChairFile(params_.chair_file));
      if (!params_.places_file.empty()) places_ = wheelchair_hmi::loadPlaces(params_.places_file);
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw wheelchair_core::ConfigError(getPrivateNodeHandle().getNamespace() + ": " + e.what());
    }
    navigator_ = std::make_unique<Navigator>(params_.navigator);
    std::vector<NamedPoint> named;
    for (const auto& p : places_) named.push_back({p.name, p.pose.position()});
    navigator_->setPlaces(named);
    // Issue 24: blocked in a dead end, back out along the way the chair came, only where the
    // trail's end has a route the chair's pose lacks (back_up.h, BackUpRecovery).
    back_up_ = std::make_unique<BackUpRecovery>(
        BackUpConfig(),
        [this](const auto& start, const Pose2D& goal, std::string& detail) {
          return routeExists(start, goal, detail);
        },
        [this](const std::string& verdict) { NODELET_INFO("navigator: %s", verdict.c_str()); });
    navigator_->setBackUpHook([this](const BlockedSituation& s) { return back_up_->offer(s); });
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();  // one /tf listener per process

    path_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, true);
    state_pub_ = nh.advertise<NavigatorState>("navigator/state", 5, true);
    simple_goal_pub_ = nh.advertise<move_base_msgs::MoveBaseActionGoal>("move_base/goal", 1);
    planner_ = nh.serviceClient<wheelchair_msgs::MakePlan>(params_.planner_service);
    back_up_planner_ = nh.serviceClient<wheelchair_msgs::MakePlan>(params_.planner_service);
    planner_thread_ = std::thread(&NavigatorNodelet::plannerLoop, this);
    dispatcher_ = std::thread(&NavigatorNodelet::dispatchLoop, this);

    subs_.push_back(nh.subscribe("map", 1, &NavigatorNodelet::onMap, this));
    subs_.push_back(nh.subscribe("obstacles", 1, &NavigatorNodelet::onObstacles, this));
    subs_.push_back(
        nh.subscribe("localization/status", 5, &NavigatorNodelet::onLocalization, this));
    subs_.push_back(nh.subscribe("safety/status", 5, &NavigatorNodelet::onSafety, this));
    subs_.push_back(
        nh.subscribe(params_.controller_path_status, 10, &NavigatorNodelet::onPathStatus, this));
    subs_.push_back(
        nh.subscribe("move_base_simple/goal", 1, &NavigatorNodelet::onSimpleGoal, this));
    move_base_ = std::make_unique<MoveBaseServer>(
        nh, "move_base", [this](MoveBaseServer::GoalHandle gh) { onMoveBaseGoal(gh); },
        [this](MoveBaseServer::GoalHandle gh) { onCancel(gh.getGoalID().id); }, false);
    navigate_ = std::make_unique<NavigateServer>(
        nh, "navigate", [this](NavigateServer::GoalHandle gh) { onNavigateGoal(gh); },
        [this](NavigateServer::GoalHandle gh) { onCancel(gh.getGoalID().id); }, false);
    move_base_->start();
    navigate_->start();
    timer_ = nh.createTimer(ros::Duration(1.0 / params_.rate), &NavigatorNodelet::onTimer, this);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      publishState();
    }
    NODELET_INFO("navigator: actions move_base and navigate, %zu named places, planner %s",
                 places_.size(), params_.planner_service.c_str());
  }

  // ---- goals -----------------------------------------------------------------------------------

  /// rviz's 2D Nav Goal: a goal of our own move_base server (move_base does the same).
  void onSimpleGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
    move_base_msgs::MoveBaseActionGoal goal;
    goal.header.stamp = ros::Time::now();
    goal.goal.target_pose = *msg;  // an empty goal id: the server makes one
    simple_goal_pub_.publish(goal);
  }

  void onMoveBaseGoal(MoveBaseServer::GoalHandle gh) {
    const std::string id = gh.getGoalID().id;
    {
      std::lock_guard<std::mutex> lock(effects_mutex_);
      handles_[id].move_base = gh;
    }
    startGoal(poseRequest(id, gh.getGoal()->target_pose));
  }

  void onNavigateGoal(NavigateServer::GoalHandle gh) {
    const std::string id = gh.getGoalID().id;
    {
      std::lock_guard<std::mutex> lock(effects_mutex_);
      handles_[id].navigate = gh;
    }
    const auto goal = gh.getGoal();
    startGoal(goal->place.empty() ? poseRequest(id, goal->target_pose)
                                  : placeRequest(id, goal->place));
  }

  GoalRequest poseRequest(const std::string& id, const geometry_msgs::PoseStamped& pose) {
    GoalRequest r;
    r.id = id;
    r.pose = wheelchair_ros::toPose2D(pose.pose);
    if (!pose.header.frame_id.empty() && pose.header.frame_id != params_.map_frame) {
      r.refused = Reason::kInvalidGoal;
      r.refused_detail =
          "goal in frame '" + pose.header.frame_id + "', expected '" + params_.map_frame + "'";
    } else if (!wheelchair_ros::isNormalized(pose.pose.orientation)) {
      r.refused = Reason::kInvalidGoal;
      r.refused_detail = "the goal's orientation is not a unit quaternion";
    }
    return r;
  }

  GoalRequest placeRequest(const std::string& id, const std::string& name) {
    GoalRequest r;
    r.id = id;
    r.place = name;
    const wheelchair_hmi::Place* place = wheelchair_hmi::findPlace(places_, name);
    if (place) {
      r.pose = place->pose;
    } else {
      r.refused = Reason::kUnknownPlace;
      r.refused_detail =
          places_.empty() ? "no places_file: no named places" : "no place called '" + name + "'";
    }
    return r;
  }

  void startGoal(const GoalRequest& request) {
    std::lock_guard<std::mutex> lock(mutex_);
    const Output out = navigator_->start(request, ros::Time::now().toSec());
    handle(out);  // the replaced drive's result first
    // Accepted unless refused at once (a refusal is set by its result, still pending).
    bool refused = false;
    for (const auto& r : out.results) refused |= r.goal_id == request.id && r.refused;
    if (!refused) queue(Effect::accept(request.id));
  }

  void onCancel(const std::string& goal_id) {
    std::lock_guard<std::mutex> lock(mutex_);
    handle(navigator_->cancel(goal_id, ros::Time::now().toSec()));
  }

  // ---- what the chair says ---------------------------------------------------------------------

  /// Any node can publish /map: a grid fromOccupancyGrid refuses (a 4000 x 4000 one beyond
  /// max_map_cells, a broken one) is refused here with its reason; its throw outside the try
  /// aborted the whole chair process. The navigator keeps its last good map.
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    try {
      const wheelchair_core::OccupancyMap map = wheelchair_ros::fromOccupancyGrid(*msg);
      std::lock_guard<std::mutex> lock(mutex_);
      navigator_->setMap(map, chair_.footprint, chair_.inscribedRadius());
    } catch (const std::exception& e) {
      NODELET_ERROR("navigator: map refused, keeping the last good one: %s", e.what());
    }
  }

  /// The live layer, as unchecked as /map: a broken one is refused, the last one kept.
  void onObstacles(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    wheelchair_core::OccupancyMap layer;
    try {
      layer = wheelchair_ros::fromOccupancyGrid(*msg);
    } catch (const std::exception& e) {
      NODELET_ERROR("navigator: obstacle layer refused: %s", e.what());
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    handle(navigator_->onObstacleLayer(layer, ros::Time::now().toSec()));
  }

  void onLocalization(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    handle(navigator_->onLocalization(msg->localized,
                                      msg->detail.empty() ? msg->sentence : msg->detail,
                                      ros::Time::now().toSec()));
  }

  void onSafety(const wheelchair_msgs::SafetyStatus::ConstPtr& msg) {
    SafetyInput s;
    s.stop = msg->stop;
    s.cause = causeOf(*msg);
    s.sentence = msg->sentence;
    s.detail = msg->detail;
    std::lock_guard<std::mutex> lock(mutex_);
    last_safety_cause_ = s.stop ? s.cause : SafetyCause::kNone;
    handle(navigator_->onSafety(s, ros::Time::now().toSec()));
  }

  void onPathStatus(const actionlib_msgs::GoalStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto id = path_ids_.find(msg->goal_id.stamp);
    if (id == path_ids_.end()) return;  // a route of someone else (a test, the planner host)
    handle(navigator_->onPathStatus(id->second, phaseOf(msg->status), msg->text,
                                    ros::Time::now().toSec()));
  }

  void onTimer(const ros::TimerEvent&) {
    std::optional<wheelchair_core::Pose2D> pose;
    try {
      pose = wheelchair_ros::toPose2D(
          tf_buffer_->lookupTransform(params_.map_frame, params_.base_frame, ros::Time(0))
              .transform);
    } catch (const tf2::TransformException&) {
    }
    std::lock_guard<std::mutex> lock(mutex_);
    const double now = ros::Time::now().toSec();
    if (pose) back_up_->record(*pose);
    if (pose) handle(navigator_->onPose(*pose, now));
    handle(navigator_->tick(now));
    // A screen's distance to go: a few times a second while driving.
    if (navigator_->active() && now - last_state_publish_ >= 0.5) publishState();
  }

  // ---- what the navigator does -----------------------------------------------------------------

  /// Carries out an Output (mutex_ held): routes, the latch release, planner requests, the
  /// results and feedback for the dispatcher.
  void handle(const Output& out) {
    if (out.path) publishPath(*out.path);
    if (out.release_safety) releaseSafetyLatch();
    if (out.plan) {
      std::lock_guard<std::mutex> lock(plan_mutex_);
      plan_request_ = *out.plan;  // a newer request supersedes one not yet sent
      plan_cv_.notify_one();
    }
    for (const DriveResult& r : out.results) {
      NODELET_INFO("navigator: goal %s %s: %s [%s]", r.goal_id.c_str(), toString(r.reason),
                   r.sentence.c_str(), r.detail.c_str());
      queue(Effect::resultOf(r));
    }
    if (out.feedback_changed) {
      const Feedback& f = navigator_->feedback();
      if (!f.sentence.empty()) NODELET_INFO("navigator: %s", f.sentence.c_str());
      publishState();
    }
  }

  /// The navigator, carrying on a drive, may release only an obstacle stop (something was in
  /// the way: the supervisor stops again at its next check if it still is). Every other latched
  /// stop (the rider's own stop, a sensor or driver fault, a lost position) waits for the
  /// rider's own command: the HMI releases it in this process when the rider chooses a
  /// destination (wheelchair_ros::releaseStopByRider). A goal from another node never does.
  void releaseSafetyLatch() {
    if (last_safety_cause_ != SafetyCause::kObstacle) return;
    wheelchair_ros::releaseStopByRider("navigator: checking the way again");
  }

  void publishPath(const PathCommand& command) {
    ros::Time stamp = ros::Time::now();
    if (stamp <= last_path_stamp_) stamp = last_path_stamp_ + ros::Duration(0, 1000);
    last_path_stamp_ = stamp;
    path_ids_[stamp] = command.id;
    while (path_ids_.size() > 64) path_ids_.erase(path_ids_.begin());
    path_pub_.publish(wheelchair_ros::toPathMsg(command.poses, params_.map_frame, stamp));
  }

  void publishState() {
    const Feedback& f = navigator_->feedback();
    NavigatorState s;
    s.header.stamp = ros::Time::now();
    s.header.frame_id = params_.map_frame;
    s.state = static_cast<uint8_t>(f.state);
    s.active = f.active;
    s.goal_id = f.goal_id;
    s.place = f.place;
    s.goal.header = s.header;
    s.goal.pose = wheelchair_ros::toPoseMsg(f.goal);
    s.pose.header = s.header;
    s.pose.pose = wheelchair_ros::toPoseMsg(f.pose);
    s.distance_remaining = f.distance_remaining;
    s.sentence = f.sentence;
    s.replans = f.replans;
    s.waits = f.waits;
    s.last_planning_time = f.last_planning_time;
    state_pub_.publish(s);
    last_state_publish_ = s.header.stamp.toSec();
    if (f.active) queue(Effect::feedback(f.goal_id, s));
  }

  // ---- the planner -----------------------------------------------------------------------------

  void plannerLoop() {
    std::unique_lock<std::mutex> lock(plan_mutex_);
    while (true) {
      plan_cv_.wait(lock, [this] { return shutdown_ || plan_request_.has_value(); });
      if (shutdown_) return;
      const PlanRequest request = *plan_request_;
      plan_request_.reset();
      lock.unlock();
      const PlanAnswer answer = askPlanner(request);
      {
        std::lock_guard<std::mutex> core(mutex_);
        handle(navigator_->onPlanAnswer(request.id, answer, ros::Time::now().toSec()));
      }
      lock.lock();
    }
  }

  /// The planner's question from `start` (nullopt: from tf map -> base_link, as the planner
  /// host knows it) to `goal`, in the map frame.
  wheelchair_msgs::MakePlan planQuestion(const std::optional<Pose2D>& start,
                                         const Pose2D& goal) const {
    wheelchair_msgs::MakePlan srv;
    srv.request.use_start = start.has_value();
    srv.request.goal.header.frame_id = params_.map_frame;
    srv.request.goal.header.stamp = ros::Time::now();
    srv.request.goal.pose = wheelchair_ros::toPoseMsg(goal);
    if (start) {
      srv.request.start.header = srv.request.goal.header;
      srv.request.start.pose = wheelchair_ros::toPoseMsg(*start);
    }
    return srv;
  }

  PlanAnswer askPlanner(const PlanRequest& request) {
    wheelchair_msgs::MakePlan srv = planQuestion(std::nullopt, request.goal);
    PlanAnswer answer;
    const ros::WallTime started = ros::WallTime::now();
    if (!planner_.exists() && !planner_.waitForExistence(ros::Duration(2.0))) {
      answer.unavailable = true;
      answer.detail = "the planner's service " + planner_.getService() + " is not available";
    } else if (!planner_.call(srv)) {
      answer.unavailable = true;
      answer.detail = "the call of " + planner_.getService() + " failed";
    } else {
      answer.success = srv.response.success;
      answer.detail = srv.response.reason;
      if (answer.success) answer.path = wheelchair_ros::fromPathMsg(srv.response.plan);
    }
    answer.planning_time = (ros::WallTime::now() - started).toSec();
    return answer;
  }

  /// The back-up check's question (its own thread and client): a route from `start` (nullopt:
  /// tf's pose of the chair) to `goal` on the planner's map and obstacle layer?
  bool routeExists(const std::optional<Pose2D>& start, const Pose2D& goal, std::string& detail) {
    wheelchair_msgs::MakePlan srv = planQuestion(start, goal);
    if (!back_up_planner_.call(srv)) {
      detail = "the call of " + back_up_planner_.getService() + " failed";
      return false;
    }
    detail = srv.response.reason;
    return srv.response.success && !srv.response.plan.poses.empty();
  }

  // ---- goal handles (the dispatcher thread only)
  // -------------------------------------------------

  void queue(Effect effect) {
    std::lock_guard<std::mutex> lock(effects_mutex_);
    effects_.push_back(std::move(effect));
    effects_cv_.notify_one();
  }

  void dispatchLoop() {
    std::unique_lock<std::mutex> lock(effects_mutex_);
    while (true) {
      effects_cv_.wait(lock, [this] { return shutdown_ || !effects_.empty(); });
      if (shutdown_) return;
      const Effect effect = std::move(effects_.front());
      effects_.pop_front();
      auto found = handles_.find(effect.goal_id);
      if (found == handles_.end()) continue;
      Handle handle = found->second;
      if (effect.kind == Effect::Kind::kResult) handles_.erase(found);
      lock.unlock();
      apply(handle, effect);
      lock.lock();
    }
  }

  void apply(Handle& handle, const Effect& effect) {
    try {
      if (handle.move_base) apply(*handle.move_base, effect, moveBaseResult(effect));
      if (handle.navigate) apply(*handle.navigate, effect, navigateResult(effect));
    } catch (const std::exception& e) {  // a goal handle the server has dropped
      NODELET_WARN("navigator: goal %s: %s", effect.goal_id.c_str(), e.what());
    }
  }

  static move_base_msgs::MoveBaseResult moveBaseResult(const Effect&) { return {}; }
  static NavigateResult navigateResult(const Effect& effect) {
    NavigateResult r;
    r.reason = static_cast<uint8_t>(effect.result.reason);
    r.sentence = effect.result.sentence;
    r.detail = effect.result.detail;
    r.distance_travelled = effect.result.distance_travelled;
    r.duration = effect.result.duration;
    r.replans = effect.result.replans;
    r.waits = effect.result.waits;
    return r;
  }

  template <typename GoalHandle, typename Result>
  void apply(GoalHandle& gh, const Effect& effect, const Result& result) {
    using actionlib_msgs::GoalStatus;
    const uint8_t status = gh.getGoalStatus().status;
    switch (effect.kind) {
      case Effect::Kind::kAccept:
        if (status == GoalStatus::PENDING || status == GoalStatus::RECALLING) gh.setAccepted();
        break;
      case Effect::Kind::kFeedback:
        if (status == GoalStatus::ACTIVE) publishFeedback(gh, effect.state);
        break;
      case Effect::Kind::kResult: {
        const DriveResult& r = effect.result;
        if (r.refused && (status == GoalStatus::PENDING || status == GoalStatus::RECALLING)) {
          gh.setRejected(result, r.sentence);
        } else if (r.reason == Reason::kReached) {
          gh.setSucceeded(result, r.sentence);
        } else if (r.reason == Reason::kCanceled || r.reason == Reason::kReplaced) {
          gh.setCanceled(result, r.sentence);
        } else {
          gh.setAborted(result, r.sentence);
        }
        break;
      }
    }
  }

  static void publishFeedback(MoveBaseServer::GoalHandle& gh, const NavigatorState& s) {
    move_base_msgs::MoveBaseFeedback feedback;
    feedback.base_position = s.pose;
    gh.publishFeedback(feedback);
  }
  static void publishFeedback(NavigateServer::GoalHandle& gh, const NavigatorState& s) {
    wheelchair_msgs::NavigateFeedback feedback;
    feedback.state = s;
    gh.publishFeedback(feedback);
  }

  NavigatorParameters params_;
  wheelchair_description::ChairParams chair_;
  std::vector<wheelchair_hmi::Place> places_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;

  std::mutex mutex_;  ///< the core and what it publishes
  std::unique_ptr<Navigator> navigator_;
  ros::Time last_path_stamp_;
  std::map<ros::Time, int> path_ids_;  ///< route stamp -> the core's route id
  double last_state_publish_ = 0.0;

  std::mutex plan_mutex_;
  std::condition_variable plan_cv_;
  std::optional<PlanRequest> plan_request_;
  std::thread planner_thread_;
  ros::ServiceClient planner_;
  ros::ServiceClient back_up_planner_;  ///< the back-up check's (its own thread)
  std::unique_ptr<BackUpRecovery> back_up_;

  std::mutex effects_mutex_;
  std::condition_variable effects_cv_;
  std::deque<Effect> effects_;
  std::map<std::string, Handle> handles_;
  std::thread dispatcher_;
  bool shutdown_ = false;

  std::unique_ptr<MoveBaseServer> move_base_;
  std::unique_ptr<NavigateServer> navigate_;
  ros::Publisher path_pub_, state_pub_, simple_goal_pub_;
  SafetyCause last_safety_cause_ = SafetyCause::kNone;
  std::vector<ros::Subscriber> subs_;
  ros::Timer timer_;
};

}  // namespace wheelchair_navigator

PLUGINLIB_EXPORT_CLASS(wheelchair_navigator::NavigatorNodelet, nodelet::Nodelet)
