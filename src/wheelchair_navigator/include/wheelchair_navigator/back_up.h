// The "back up" recovery (issue 24): a drive blocked in a dead end (nothing forward, the way on
// only behind) leaves by reversing along the way it came, then the navigator plans again from
// there (Navigator::setBackUpHook). The way it came is the trail of the chair's own poses while
// it drove forwards: the body has just swept it, so it fits, and the rear guard watches it for
// anyone who stepped in since. BackUpRecovery is the hook: it backs up only where that helps
// (backUpHelps: the trail's end has a route to the goal that the chair's own pose lacks), asked
// of the planner on its own thread while the chair stands blocked. ROS-free.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_navigator/navigator.h>

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace wheelchair_navigator {

struct BackUpConfig {
  double distance = 2.0;      ///< [m] how far back along the trail the recovery reverses
  double min_distance = 0.3;  ///< [m] a shorter trail is no way out: no back-up
  double spacing = 0.05;      ///< [m] between recorded poses
  double max_jump = 0.5;      ///< [m] a longer step (a relocalization) starts a new trail
  double keep = 6.0;          ///< [m] trail kept behind the chair
  /// [m] the first pose taken behind the chair at least this far: the localizer corrects a
  /// standing chair's pose by a few cm sideways, and a nearer pose recorded before that made
  /// the first step sideways (the controller turned in place to it, into a corridor's wall).
  double first_step = 0.5;
};

class BackUpTrail {
 public:
  explicit BackUpTrail(BackUpConfig config = BackUpConfig());

  /// The chair's pose as it moves (a few times a second). Only the stretch driven forwards
  /// since the last reverse step or jump is kept: that is the way back.
  void record(const Pose2D& pose);
  /// The route back: from the chair's pose along the trail, newest to oldest, up to
  /// config.distance, each pose with the heading the chair had there (so the controller drives
  /// it in reverse). Empty if the trail behind is shorter than min_distance.
  std::vector<Pose2D> route(const BlockedSituation& situation) const;
  /// [m] the trail's length behind its newest pose.
  double length() const;
  void clear() { trail_.clear(); }

 private:
  BackUpConfig config_;
  std::deque<Pose2D> trail_;  ///< oldest first
};

/// The rule of the back-up recovery: back out along the trail only when its end (a pose the
/// chair passed, behind it) has a route to the goal and the chair's own pose has none. Where
/// neither has one (the only doorway blocked) backing cannot help: the chair waits; where the
/// chair's pose has one, the navigator drives that (a way round, or the planner's own reverse).
bool backUpHelps(bool route_from_chair, bool route_from_trail_end);

/// The back-up hook (Navigator::setBackUpHook) with its rule. The navigator asks it each time it
/// finds the chair blocked (every replan_period while it stays so): the first ask for a place
/// starts the check (two planner queries on the recovery's own thread, so the caller never
/// waits for the planner); a later ask from the same place and goal gets the trail back if
/// backUpHelps said so. Thread-safe.
class BackUpRecovery {
 public:
  /// A route from `start` (nullopt: the chair's pose as the planner knows it) to `goal`?
  /// Blocking; `detail`: the planner's word.
  using RouteQuery = std::function<bool(const std::optional<Pose2D>& start, const Pose2D& goal,
                                        std::string& detail)>;
  /// Each verdict, for the log.
  using Log = std::function<void(const std::string&)>;

  BackUpRecovery(BackUpConfig config, RouteQuery query, Log log = Log());
  ~BackUpRecovery();
  BackUpRecovery(const BackUpRecovery&) = delete;
  BackUpRecovery& operator=(const BackUpRecovery&) = delete;

  void record(const Pose2D& pose);
  /// The hook: the route back if the check for this place and goal found that backing helps,
  /// else empty (and the check started, if none is running or done for this place).
  std::vector<Pose2D> offer(const BlockedSituation& situation);
  /// Waits until no check is running (tests).
  void waitIdle();

 private:
  struct Check {
    Pose2D chair, goal;
    std::vector<Pose2D> route;  ///< the trail back from where the check was asked
    bool done = false, helps = false;
  };
  bool samePlace(const Check& check, const BlockedSituation& situation) const;
  void run(Check check);

  BackUpTrail trail_;
  RouteQuery query_;
  Log log_;
  std::mutex mutex_;
  std::condition_variable idle_;
  std::optional<Check> check_;  ///< the last check (running or done)
  bool running_ = false, stopping_ = false;
  std::thread worker_;
};

}  // namespace wheelchair_navigator
