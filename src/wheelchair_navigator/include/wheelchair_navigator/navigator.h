// The navigator: one owner of every drive, from the goal to exactly one result (move_base's
// and nav2 bt_navigator's role, as a plain state machine). ROS-free; time is injected (seconds,
// any epoch) and every event returns what the ROS side must do (Output).
//
//   start(goal) -- refused (not localized, goal outside the map / in furniture / no room) -->
//   result
//       | release the supervisor's latch (the rider's command), ask the planner
//   PLANNING -- route --> DRIVING (the route to the controller once the supervisor allows motion)
//       | no route, and the obstacle layer cuts a way the static map has (layer_cut.h): BLOCKED
//       | no route otherwise: one retry, then result NO_ROUTE
//   DRIVING -- controller reached --> result REACHED
//       | the obstacle layer has something on the route ahead: a way round is asked, taken on
//       | the move only if it swerves from where the chair is (no turn back: the tail swings
//       | wide); otherwise the chair stops for it
//       | supervisor stops for an obstacle
//       v
//   WAITING -- the way free again for clear_confirm (asked every probe_period) --> same way
//       | after wait_for_clear (a person walks on first): a way around (the planner sees the
//       | obstacle layer), driven only if it starts where the chair stands (else asked again)
//       | that way goes through the same stretch, or none --> BLOCKED (the rider is told where)
//   BLOCKED -- the way free again --> DRIVING;  a way around found --> DRIVING
//       | blocked at the start: the first route asked again every replan_period
//       | blocked_timeout --> result BLOCKED
//   Anything else ends the drive with its reason (safety stop with its cause, localization lost,
//   no progress, controller gave up after max_control_retries, cancel, a newer goal), through
//   STOPPING: an empty route to the controller, the result once it reports the chair stopped.
// There is no rotation on the spot as a recovery. A back-up recovery (issue 24, reversing) can
// be plugged in with setBackUpHook: it is asked for a reverse route when the chair is blocked.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_navigator/goal_check.h>
#include <wheelchair_navigator/navigator_config.h>
#include <wheelchair_navigator/reasons.h>
#include <wheelchair_navigator/route.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wheelchair_navigator {

/// The supervisor's verdict as the navigator needs it (from wheelchair_msgs/SafetyStatus).
enum class SafetyCause { kNone, kNoData, kObstacle, kUserStop, kLocalization, kOther };
struct SafetyInput {
  bool stop = false;
  SafetyCause cause = SafetyCause::kNone;
  std::string sentence;  ///< the supervisor's words for the rider ("the laser scanner is silent")
  std::string detail;    ///< for the log
};

/// The controller's state for one route (its ~path_status, actionlib_msgs/GoalStatus).
enum class ControllerPhase { kIdle, kActive, kStopping, kReached, kAborted };

/// A goal as a client gave it. `refused`: a problem the ROS side found first (another frame,
/// not a unit quaternion, an unknown place), with its detail.
struct GoalRequest {
  std::string id;  ///< the client's goal id: every result names it
  Pose2D pose;
  std::string place;  ///< the named place, "" for a pose
  std::optional<Reason> refused;
  std::string refused_detail;
};

/// Ask the planner for a route from the chair's current pose to `goal`.
struct PlanRequest {
  int id = 0;
  Pose2D goal;
};
/// The planner's answer to a PlanRequest.
struct PlanAnswer {
  bool success = false;
  std::vector<Pose2D> path;
  std::string detail;          ///< the planner's reason on failure
  double planning_time = 0.0;  ///< [s] wall time of the request
  bool unavailable = false;    ///< the planner could not be asked (not running)
};
/// Hand a route to the controller (and the supervisor): `poses` empty = stop the chair. Each
/// route has its own id; the controller's statuses name it.
struct PathCommand {
  int id = 0;
  std::vector<Pose2D> poses;
};

/// How a drive ended: exactly one per goal.
struct DriveResult {
  std::string goal_id;
  Reason reason = Reason::kReached;
  std::string sentence;             ///< for the rider
  std::string detail;               ///< for the log: the cause, the retries and their reasons
  bool refused = false;             ///< never pursued (reasonRow(reason).refusal)
  double distance_travelled = 0.0;  ///< [m]
  double duration = 0.0;            ///< [s]
  int replans = 0;
  int waits = 0;
};

/// What a screen shows and the action's feedback carries.
struct Feedback {
  State state = State::kIdle;
  bool active = false;
  std::string goal_id;
  std::string place;
  Pose2D goal;
  Pose2D pose;
  bool have_pose = false;
  double distance_remaining = NAN;  ///< [m] along the route
  std::string sentence;             ///< what the rider is told now; idle: how the last drive ended
  int replans = 0;
  int waits = 0;
  double last_planning_time = NAN;  ///< [s]
};

/// What the ROS side must do after an event.
struct Output {
  std::optional<PlanRequest> plan;
  std::optional<PathCommand> path;
  bool release_safety = false;  ///< the rider's command releases the supervisor's latch
  std::vector<DriveResult> results;
  bool feedback_changed = false;  ///< state or sentence changed: publish it now
};

/// A named place, to say where the way is blocked.
struct NamedPoint {
  std::string name;
  Eigen::Vector2d point;
};

/// The back-up hook (issue 24): asked when the chair is blocked and no way forward exists.
/// Returns a route to drive (reverse poses; empty: no back-up here). Once the chair has driven
/// it, the navigator asks for a way around again.
struct BlockedSituation {
  Pose2D chair;
  Pose2D goal;
  std::vector<Eigen::Vector2d> blocked;  ///< the stretch of the route that is blocked
};
using BackUpHook = std::function<std::vector<Pose2D>(const BlockedSituation&)>;

class Navigator {
 public:
  explicit Navigator(NavigatorConfig config = NavigatorConfig());
  ~Navigator();

  /// The static map, the chair's footprint and half width for the goal check. Throws
  /// std::invalid_argument on a map it cannot use (the previous one is then kept).
  void setMap(const wheelchair_core::OccupancyMap& map, const wheelchair_core::Polygon& footprint,
              double inscribed_radius);
  void setPlaces(std::vector<NamedPoint> places) { places_ = std::move(places); }
  void setBackUpHook(BackUpHook hook) { back_up_ = std::move(hook); }

  /// A new goal; a drive in progress ends with REPLACED (the chair goes on towards the new one).
  Output start(const GoalRequest& goal, double now);
  /// The client cancels `goal_id` (ignored if it is not the current drive).
  Output cancel(const std::string& goal_id, double now);
  Output onPlanAnswer(int plan_id, const PlanAnswer& answer, double now);
  Output onPathStatus(int path_id, ControllerPhase phase, const std::string& text, double now);
  Output onSafety(const SafetyInput& safety, double now);
  Output onLocalization(bool localized, const std::string& detail, double now);
  Output onPose(const Pose2D& pose, double now);
  /// The obstacle layer (/obstacles): cells >= 50 that the static map does not have.
  Output onObstacleLayer(const wheelchair_core::OccupancyMap& layer, double now);
  /// Timeouts, probes, retries: call a few times a second.
  Output tick(double now);

  const Feedback& feedback() const { return feedback_; }
  State state() const { return feedback_.state; }
  bool active() const { return drive_ != nullptr; }
  const NavigatorConfig& config() const { return config_; }

 private:
  struct Drive;
  /// kStart: the first route again, the way blocked at the start by the obstacle layer.
  enum class Purpose { kFirst, kResume, kAround, kRetry, kStart };

  void askPlan(Purpose purpose, double now);
  void drive(std::vector<Pose2D> poses, RouteKind kind, double now);
  void sendPending(double now);
  void enterWaiting(std::vector<Eigen::Vector2d> blocked, double now);
  void enterBlocked(const std::string& why, double now);
  void finish(Reason reason, const std::string& detail, double now, const std::string& cause = "");
  void emit(DriveResult result);
  void controlFailed(const std::string& text, double now);
  void setState(State state, RouteKind kind = RouteKind::kFirst);
  void refreshFeedback();
  bool wayFree(double now) const;
  /// The route starts where the chair stands (start_tolerance); `off`: how far off it does [m].
  bool startsHere(const std::vector<Pose2D>& path, double& off) const;
  /// Where the obstacle layer cuts the way from the chair to the goal (layer_cut.h).
  std::optional<Eigen::Vector2d> layerCutOfTheWay() const;
  /// A route for a chair that stands, planned from elsewhere: asked again. True if it was.
  bool askAgainIfElsewhere(const PlanAnswer& answer, double now);
  /// The route starts where the moving chair is and swerves, no turn back (kSmoothTurn).
  bool smoothFromHere(const std::vector<Pose2D>& path) const;
  std::optional<Eigen::Vector2d> layerBlockAhead(double now) const;
  std::string whereIs(const std::vector<Eigen::Vector2d>& stretch) const;
  SentenceContext context() const;

  NavigatorConfig config_;
  std::unique_ptr<GoalCheck> goal_check_;
  wheelchair_core::OccupancyMap static_map_;
  std::vector<NamedPoint> places_;
  BackUpHook back_up_;

  // What the navigator knows of the rest of the chair.
  bool localized_ = false;
  std::string localization_detail_ = "no localization status yet";
  SafetyInput safety_;  ///< no status yet counts as no stop: the controller enforces its own
  std::optional<Pose2D> pose_;
  wheelchair_core::OccupancyMap layer_;
  double layer_stamp_ = -INFINITY;

  // Routes and the controller.
  int next_plan_id_ = 0;
  int next_path_id_ = 0;
  int latest_path_id_ = -1;      ///< the last route (or stop) handed to the controller
  bool chair_may_move_ = false;  ///< a route was handed over and not yet reported ended

  std::unique_ptr<Drive> drive_;
  std::string idle_sentence_;  ///< the last result's sentence, shown while idle
  Output out_;
  Feedback feedback_;
};

}  // namespace wheelchair_navigator
