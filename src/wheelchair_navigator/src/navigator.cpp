#include <wheelchair_navigator/layer_cut.h>
#include <wheelchair_navigator/navigator.h>

#include <cstdio>
#include <limits>
#include <stdexcept>

namespace wheelchair_navigator {

namespace {

/// [s] an abort of the controller that neither the supervisor nor the localizer explains yet
/// is taken as the controller's own after this long (their statuses come on other topics).
constexpr double kAbortGrace = 0.5;
/// [s] a route handed over during a stop first moves the supervisor's watch onto it; the latch
/// is released once its next scan has been checked against that route.
constexpr double kCorridorSettle = 0.3;
/// [m] beyond the blocked stretch, the part of a new route checked for going through it.
constexpr double kThroughHorizon = 3.0;
/// A way round taken while the chair moves must start where it is and keep within kSmoothTurn
/// [rad] of its heading over its first kSmoothLength [m] (a swerve, no turn back).
constexpr double kSmoothLength = 0.6;
constexpr double kSmoothTurn = 0.5;

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f s", s);
  return text;
}

bool terminal(ControllerPhase phase) {
  return phase == ControllerPhase::kReached || phase == ControllerPhase::kAborted ||
         phase == ControllerPhase::kIdle;
}

}  // namespace

struct Navigator::Drive {
  std::string goal_id;
  Pose2D goal;
  std::string place;
  double started = 0.0;
  double travelled = 0.0;
  std::optional<Pose2D> last_pose;
  int replans = 0, waits = 0, planner_retries = 0, control_retries = 0, back_ups = 0;
  std::vector<std::string> notes;  ///< each retry and its reason, for the result's detail
  // The planner.
  int plan_id = -1;  ///< the request waited for (-1: none)
  Purpose purpose = Purpose::kFirst;
  double plan_asked = 0.0;
  double retry_at = NAN;
  // The route driven.
  int path_id = -1;  ///< -1: no route driven yet
  Route route;
  bool backing_up = false;
  // A route waiting for the supervisor to allow motion.
  std::optional<std::vector<Pose2D>> pending;
  RouteKind pending_kind = RouteKind::kFirst;
  double release_at = NAN, released_at = NAN;
  // Progress.
  double best_remaining = INFINITY, progress_time = 0.0, progress_yaw = 0.0;
  // A controller abort nobody explained yet.
  double abort_at = NAN;
  std::string abort_text;
  std::string controller_text;  ///< the controller's last word on the route driven
  // Something in the way.
  std::vector<Eigen::Vector2d> blocked;
  std::string where, blocked_detail;
  double waiting_since = NAN, blocked_since = NAN, free_since = NAN;
  double last_probe = -INFINITY, last_around = -INFINITY;
  // The end.
  std::optional<DriveResult> result;
  int stop_path_id = -1;
  double stopping_since = NAN;
};

Navigator::Navigator(NavigatorConfig config) : config_(std::move(config)) {
  if (const std::string problem = config_.validate(); !problem.empty())
    throw std::invalid_argument("NavigatorConfig: " + problem);
}

Navigator::~Navigator() = default;

void Navigator::setMap(const wheelchair_core::OccupancyMap& map,
                       const wheelchair_core::Polygon& footprint, double inscribed_radius) {
  auto check = std::make_unique<GoalCheck>(map, footprint, inscribed_radius);
  goal_check_ = std::move(check);
  static_map_ = map;
}

// ---- events ------------------------------------------------------------------------------------

Output Navigator::start(const GoalRequest& goal, double now) {
  out_ = Output();
  if (drive_) {
    if (drive_->result) {
      emit(*drive_->result);  // its stop is still being reported: the result now
    } else {
      // Not stopped: the chair goes on along the old route until the new one is handed over.
      finish(Reason::kReplaced, "replaced by goal '" + goal.id + "'", now);
      if (drive_ && drive_->result) emit(*drive_->result);
    }
    drive_.reset();
  }
  drive_ = std::make_unique<Drive>();
  Drive& d = *drive_;
  d.goal_id = goal.id;
  d.goal = goal.pose;
  d.place = goal.place;
  d.started = now;
  d.last_pose = pose_;

  std::optional<GoalRefusal> refusal;
  if (goal.refused) {
    refusal = GoalRefusal{*goal.refused, goal.refused_detail};
  } else if (!goal.pose.isFinite()) {
    refusal = GoalRefusal{Reason::kInvalidGoal, "the goal pose is not finite"};
  } else if (!localized_) {
    refusal = GoalRefusal{Reason::kNotLocalized, localization_detail_};
  } else if (!pose_) {
    refusal = GoalRefusal{Reason::kNotReady, "no pose of the chair yet"};
  } else if (!goal_check_) {
    refusal = GoalRefusal{Reason::kNotReady, "no map yet"};
  } else {
    refusal = goal_check_->check(goal.pose, config_.goal_min_clearance);
  }
  if (refusal) {
    finish(refusal->reason, refusal->detail, now);
  } else {
    out_.release_safety = true;  // the rider's command: a latched stop is released
    askPlan(Purpose::kFirst, now);
  }
  refreshFeedback();
  return out_;
}

Output Navigator::cancel(const std::string& goal_id, double now) {
  out_ = Output();
  if (drive_ && drive_->goal_id == goal_id && !drive_->result)
    finish(Reason::kCanceled, "canceled by the client", now);
  refreshFeedback();
  return out_;
}

Output Navigator::onPlanAnswer(int plan_id, const PlanAnswer& answer, double now) {
  out_ = Output();
  if (!drive_ || drive_->result || plan_id != drive_->plan_id) return out_;
  Drive& d = *drive_;
  d.plan_id = -1;
  feedback_.last_planning_time = answer.planning_time;
  const bool has_route = answer.success && !answer.path.empty();
  switch (d.purpose) {
    case Purpose::kFirst:
    case Purpose::kRetry:
      if (has_route) {
        drive(answer.path, RouteKind::kFirst, now);
      } else if (answer.unavailable && d.path_id < 0) {
        finish(Reason::kNotReady, answer.detail, now);
      } else if (const auto cut = d.path_id < 0 ? layerCutOfTheWay() : std::nullopt) {
        // Something the map does not have (a person in a doorway) cuts the way: wait for it.
        d.blocked = {*cut};
        d.where = whereIs(d.blocked);
        enterBlocked(
            "no route while something the map does not have cuts the way (" + answer.detail + ")",
            now);
      } else if (d.path_id < 0 && d.planner_retries < config_.max_planner_retries) {
        ++d.planner_retries;
        d.notes.push_back("no route (" + answer.detail + "), asked again");
        d.retry_at = now + config_.retry_delay;
      } else {
        finish(Reason::kNoRoute, answer.detail, now);
      }
      break;
    case Purpose::kStart:
      if (has_route) {
        if (!askAgainIfElsewhere(answer, now)) drive(answer.path, RouteKind::kFirst, now);
      } else if (const auto cut = answer.unavailable ? std::nullopt : layerCutOfTheWay()) {
        d.blocked = {*cut};
        d.where = whereIs(d.blocked);
        enterBlocked(
            "no route while something the map does not have cuts the way (" + answer.detail + ")",
            now);
      } else if (answer.unavailable) {
        enterBlocked(answer.detail, now);
      } else {
        finish(Reason::kNoRoute, answer.detail, now);
      }
      break;
    case Purpose::kResume:
      if (has_route) {
        if (!askAgainIfElsewhere(answer, now)) drive(answer.path, RouteKind::kResumed, now);
      } else {
        enterBlocked("no route: " + answer.detail, now);
      }
      break;
    case Purpose::kAround: {
      if (state() == State::kWaiting && now - d.waiting_since < config_.wait_for_clear) {
        // Asked while driving, answered once the supervisor stopped the chair: a person walks
        // on; the chair waits first (a way round is asked at wait_for_clear if still needed).
        d.last_around = -INFINITY;
        break;
      }
      if (!has_route) {
        enterBlocked("no way around: " + answer.detail, now);
        break;
      }
      // A chair whose route has ended (a back-up driven to its end) stands: any way from here.
      if (state() == State::kDriving && chair_may_move_ && !smoothFromHere(answer.path)) {
        // The planner checked the body's motion onto it from rest (a turn on the spot first);
        // the moving chair would swing its tail wide turning onto it: it stops first, waits
        // (a person walks on), and asks for a way round from where it stands.
        d.notes.push_back("a way round turning away from the moving chair: stopped first");
        enterWaiting(d.blocked, now);
        latest_path_id_ = ++next_path_id_;
        out_.path = PathCommand{latest_path_id_, {}};
        break;
      }
      if (askAgainIfElsewhere(answer, now)) break;
      bool through;
      if (layer_stamp_ >= now - config_.layer_max_age) {  // the planner saw the layer
        through =
            layerObstacleAhead(Route(answer.path), layer_, static_map_,
                               config_.block_length + kThroughHorizon, config_.block_clearance)
                .has_value();
      } else {  // it did not: a route through the stretch the supervisor stopped for
        through =
            distanceToStretch(answer.path, d.blocked, config_.block_length + kThroughHorizon) <
            config_.block_clearance;
      }
      const bool free_now =
          !std::isnan(d.free_since) && now - d.free_since >= config_.clear_confirm;
      if (!through) {
        drive(answer.path, RouteKind::kAround, now);
      } else if (free_now) {
        drive(answer.path, RouteKind::kResumed, now);
      } else {
        enterBlocked("the only route goes through what is in the way", now);
      }
      break;
    }
  }
  refreshFeedback();
  return out_;
}

Output Navigator::onPathStatus(int path_id, ControllerPhase phase, const std::string& text,
                               double now) {
  out_ = Output();
  if (path_id == latest_path_id_ && terminal(phase)) chair_may_move_ = false;
  if (!drive_) return out_;
  Drive& d = *drive_;
  if (d.result) {  // stopping: the controller reports the stop route ended
    if (path_id == d.stop_path_id && terminal(phase)) {
      emit(*d.result);
      drive_.reset();
      setState(State::kIdle);
    }
    refreshFeedback();
    return out_;
  }
  if (path_id != d.path_id || state() != State::kDriving) return out_;
  d.controller_text = text;
  if (phase == ControllerPhase::kReached) {
    if (d.backing_up) {
      d.backing_up = false;
      askPlan(Purpose::kAround, now);
    } else {
      finish(Reason::kReached, "", now);
    }
  } else if (phase == ControllerPhase::kAborted && !safety_.stop && localized_) {
    d.abort_at = now;  // decided in tick(), unless the supervisor or localizer explains it
    d.abort_text = text;
  }
  refreshFeedback();
  return out_;
}

Output Navigator::onSafety(const SafetyInput& safety, double now) {
  out_ = Output();
  safety_ = safety;
  if (!drive_ || drive_->result) {
    refreshFeedback();
    return out_;
  }
  Drive& d = *drive_;
  if (!safety.stop) {
    if (d.pending && !std::isnan(d.released_at)) sendPending(now);
    refreshFeedback();
    return out_;
  }
  d.abort_at = NAN;  // the supervisor explains the controller's abort
  switch (safety.cause) {
    case SafetyCause::kUserStop:
      finish(Reason::kCanceled, "the rider pressed the switch (" + safety.detail + ")", now);
      break;
    case SafetyCause::kLocalization:
      finish(Reason::kLocalizationLost, safety.detail, now);
      break;
    case SafetyCause::kObstacle:
      d.free_since = NAN;
      if (state() == State::kDriving)
        enterWaiting(d.route.stretch(d.route.cursorAlong() + config_.block_start,
                                     d.route.cursorAlong() + config_.block_length),
                     now);
      break;
    case SafetyCause::kNoData:
    case SafetyCause::kOther:
    case SafetyCause::kNone:
      // Before the first route the latch may still be the old one: the route waits for the
      // release (sendPending) and fails after safety_clear_timeout.
      if (state() != State::kPlanning || d.path_id >= 0)
        finish(Reason::kSafetyStop, safety.detail, now, safety.sentence);
      break;
  }
  refreshFeedback();
  return out_;
}

Output Navigator::onLocalization(bool localized, const std::string& detail, double now) {
  out_ = Output();
  localized_ = localized;
  localization_detail_ = detail;
  if (!localized && drive_ && !drive_->result) {
    drive_->abort_at = NAN;
    finish(Reason::kLocalizationLost, detail, now);
  }
  refreshFeedback();
  return out_;
}

Output Navigator::onPose(const Pose2D& pose, double now) {
  out_ = Output();
  if (!pose.isFinite()) return out_;
  pose_ = pose;
  if (drive_) {
    Drive& d = *drive_;
    if (d.last_pose) d.travelled += (pose.position() - d.last_pose->position()).norm();
    d.last_pose = pose;
    if (state() == State::kDriving && !d.route.empty()) {
      const double remaining = d.route.advance(pose);
      feedback_.distance_remaining = remaining;
      if (remaining < d.best_remaining - config_.progress_distance) {
        d.best_remaining = remaining;
        d.progress_time = now;
      }
      if (std::abs(wheelchair_core::angleDifference(pose.yaw, d.progress_yaw)) >
          config_.progress_rotation) {
        d.progress_yaw = pose.yaw;
        d.progress_time = now;
      }
    }
  }
  refreshFeedback();
  return out_;
}

Output Navigator::onObstacleLayer(const wheelchair_core::OccupancyMap& layer, double now) {
  out_ = Output();
  if (layer.width > 0 && layer.resolution > 0.0 &&
      layer.data.size() == static_cast<size_t>(layer.width) * layer.height) {
    layer_ = layer;
    layer_stamp_ = now;
  }
  return out_;
}

Output Navigator::tick(double now) {
  out_ = Output();
  if (!drive_) return out_;
  Drive& d = *drive_;
  if (d.result) {  // stopping
    if (now - d.stopping_since >= config_.stop_timeout) {
      emit(*d.result);
      drive_.reset();
      setState(State::kIdle);
    }
    refreshFeedback();
    return out_;
  }
  if (d.plan_id >= 0 && now - d.plan_asked > config_.planner_timeout) {
    d.plan_id = -1;
    const std::string why = "the planner did not answer within " + seconds(config_.planner_timeout);
    if (state() == State::kWaiting || state() == State::kBlocked)
      enterBlocked(why, now);
    else
      finish(Reason::kNotReady, why, now);
  }
  if (drive_ && !drive_->result) {
    if (!std::isnan(d.retry_at) && now >= d.retry_at) {
      d.retry_at = NAN;
      askPlan(Purpose::kRetry, now);
    }
    if (d.pending) {
      if (std::isnan(d.released_at) && now >= d.release_at && !safety_.stop) {
        sendPending(now);  // released meanwhile (a probe): the supervisor has checked the route
      } else if (std::isnan(d.released_at) && now >= d.release_at) {
        out_.release_safety = true;
        d.released_at = now;
      } else if (!std::isnan(d.released_at) && now - d.released_at > config_.safety_clear_timeout) {
        const Route refused(std::move(*d.pending));
        d.pending.reset();
        if (d.blocked.empty())
          d.blocked = refused.stretch(config_.block_start, config_.block_length);
        const std::string why = "the supervisor did not allow motion within " +
                                seconds(config_.safety_clear_timeout) + " (" + safety_.detail + ")";
        if (safety_.cause == SafetyCause::kObstacle)
          enterBlocked(why, now);
        else if (safety_.cause == SafetyCause::kNoData)
          finish(Reason::kNotReady, why, now);
        else
          finish(Reason::kSafetyStop, why, now, safety_.sentence);
      }
    }
  }
  if (drive_ && !drive_->result && !std::isnan(d.abort_at) && now - d.abort_at >= kAbortGrace)
    controlFailed(d.abort_text, now);
  if (!drive_ || drive_->result) {
    refreshFeedback();
    return out_;
  }
  switch (state()) {
    case State::kDriving:
      if (now - d.progress_time > config_.no_progress_timeout) {
        char text[96];
        std::snprintf(text, sizeof(text), "no progress for %.0f s, %.2f m still to go",
                      now - d.progress_time, feedback_.distance_remaining);
        finish(Reason::kNoProgress,
               std::string(text) + " (controller: " +
                   (d.controller_text.empty() ? "no word" : d.controller_text) + ")",
               now);
      } else if (d.plan_id < 0 && !d.backing_up && now - d.last_around >= config_.replan_period &&
                 d.replans < config_.max_replans) {
        if (const auto obstacle = layerBlockAhead(now)) {
          d.blocked = {*obstacle};
          d.where = whereIs(d.blocked);
          d.last_around = now;
          d.notes.push_back("obstacle layer: something on the route ahead, asked for a way round");
          askPlan(Purpose::kAround, now);
        }
      }
      break;
    case State::kWaiting:
    case State::kBlocked: {
      if (state() == State::kBlocked && now - d.blocked_since >= config_.blocked_timeout) {
        finish(Reason::kBlocked,
               "blocked for " + seconds(now - d.blocked_since) + ": " + d.blocked_detail, now);
        break;
      }
      if (d.path_id < 0 && !d.backing_up) {  // blocked at the start: the first route again
        if (d.plan_id < 0 && now - d.last_around >= config_.replan_period) {
          d.last_around = now;
          askPlan(Purpose::kStart, now);
        }
        break;
      }
      const bool free = wayFree(now);
      if (!free) d.free_since = NAN;
      if (free && std::isnan(d.free_since)) d.free_since = now;
      if (d.pending) break;  // a route waits for the supervisor's release
      if (safety_.stop && safety_.cause == SafetyCause::kObstacle &&
          now - d.last_probe >= config_.probe_period) {
        out_.release_safety = true;  // still there? the supervisor stops again at once if so
        d.last_probe = now;
      }
      const bool resume = !std::isnan(d.free_since) && now - d.free_since >= config_.clear_confirm;
      if (resume && (d.plan_id < 0 || d.purpose == Purpose::kAround)) {
        d.notes.push_back("the way was free again after " + seconds(now - d.waiting_since));
        askPlan(Purpose::kResume, now);  // the same way again (a way around still asked for
        break;                           // is superseded)
      }
      if (d.plan_id >= 0) break;
      if (state() == State::kWaiting && now - d.waiting_since >= config_.wait_for_clear) {
        if (d.replans >= config_.max_replans) {
          enterBlocked("no routes left to ask for (" + std::to_string(d.replans) + ")", now);
        } else if (d.last_around < d.waiting_since) {
          d.last_around = now;
          askPlan(Purpose::kAround, now);
        }
      } else if (state() == State::kBlocked && now - d.last_around >= config_.replan_period &&
                 d.replans < config_.max_replans) {
        d.last_around = now;
        askPlan(Purpose::kAround, now);
      }
      break;
    }
    case State::kIdle:
    case State::kPlanning:
    case State::kStopping:
      break;
  }
  refreshFeedback();
  return out_;
}

// ---- transitions -------------------------------------------------------------------------------

void Navigator::askPlan(Purpose purpose, double now) {
  Drive& d = *drive_;
  d.plan_id = ++next_plan_id_;
  d.purpose = purpose;
  d.plan_asked = now;
  if (purpose != Purpose::kFirst && purpose != Purpose::kStart) ++d.replans;
  out_.plan = PlanRequest{d.plan_id, d.goal};
  if (purpose == Purpose::kFirst || purpose == Purpose::kRetry) setState(State::kPlanning);
}

void Navigator::drive(std::vector<Pose2D> poses, RouteKind kind, double now) {
  Drive& d = *drive_;
  d.pending = std::move(poses);
  d.pending_kind = kind;
  d.released_at = NAN;
  if (!safety_.stop) {
    sendPending(now);
    return;
  }
  // The supervisor still holds its stop (the rider's release at the start is on its way, or
  // it stopped for something in the way): the route goes to it first, so that it watches the
  // new way, and the latch is released once it has checked a scan against it.
  PathCommand corridor{++next_path_id_, *d.pending};
  latest_path_id_ = corridor.id;
  chair_may_move_ = true;  // the controller refuses it while held; counted as moving until it says
  out_.path = corridor;
  d.release_at = now + (safety_.cause == SafetyCause::kObstacle ? kCorridorSettle : 0.0);
}

void Navigator::sendPending(double now) {
  Drive& d = *drive_;
  if (!d.pending) return;
  d.path_id = ++next_path_id_;
  latest_path_id_ = d.path_id;
  chair_may_move_ = true;
  out_.path = PathCommand{d.path_id, *d.pending};
  d.route = Route(std::move(*d.pending));
  d.pending.reset();
  d.best_remaining = d.route.length();
  d.progress_time = now;
  d.progress_yaw = pose_ ? pose_->yaw : 0.0;
  d.abort_at = NAN;
  d.free_since = NAN;
  d.waiting_since = d.blocked_since = NAN;
  feedback_.distance_remaining = d.route.length();
  setState(State::kDriving, d.pending_kind);
}

void Navigator::enterWaiting(std::vector<Eigen::Vector2d> blocked, double now) {
  Drive& d = *drive_;
  ++d.waits;
  d.blocked = std::move(blocked);
  d.where = whereIs(d.blocked);
  d.waiting_since = now;
  d.free_since = NAN;
  d.last_probe = now;
  d.last_around = -INFINITY;
  setState(State::kWaiting);
}

void Navigator::enterBlocked(const std::string& why, double now) {
  Drive& d = *drive_;
  d.blocked_detail = why;
  d.last_around = now;
  if (std::isnan(d.waiting_since)) d.waiting_since = now;
  if (state() != State::kBlocked) {
    d.blocked_since = now;
    d.notes.push_back("blocked: " + why);
  }
  // Stopped by the supervisor, the chair stands still and the old route stays its watch; stopped
  // by what the obstacle layer showed, the chair still drives: stop it.
  if (chair_may_move_ && !safety_.stop) {
    latest_path_id_ = ++next_path_id_;
    out_.path = PathCommand{latest_path_id_, {}};
  }
  setState(State::kBlocked);
  if (back_up_ && pose_ && d.back_ups < config_.max_back_ups) {
    std::vector<Pose2D> reverse = back_up_(BlockedSituation{*pose_, d.goal, d.blocked});
    if (!reverse.empty()) {
      ++d.back_ups;
      d.notes.push_back("backed up");
      d.backing_up = true;
      drive(std::move(reverse), RouteKind::kBackUp, now);
    }
  }
}

void Navigator::controlFailed(const std::string& text, double now) {
  Drive& d = *drive_;
  d.abort_at = NAN;
  if (d.control_retries < config_.max_control_retries && d.replans < config_.max_replans) {
    ++d.control_retries;
    d.notes.push_back("controller: " + text + " (retry " + std::to_string(d.control_retries) +
                      " of " + std::to_string(config_.max_control_retries) + ")");
    askPlan(Purpose::kRetry, now);
  } else {
    finish(Reason::kControlFailed, "controller: " + text, now);
  }
}

void Navigator::finish(Reason reason, const std::string& detail, double now,
                       const std::string& cause) {
  Drive& d = *drive_;
  DriveResult r;
  r.goal_id = d.goal_id;
  r.reason = reason;
  SentenceContext c = context();
  c.cause = cause;
  r.sentence = riderSentence(reason, c);
  r.detail = detail;
  for (const std::string& note : d.notes) r.detail += (r.detail.empty() ? "" : "; ") + note;
  r.refused = reasonRow(reason).refusal;
  r.distance_travelled = d.travelled;
  r.duration = now - d.started;
  r.replans = d.replans;
  r.waits = d.waits;
  d.plan_id = -1;
  d.pending.reset();
  if (reason == Reason::kReplaced) {  // the next goal takes the chair over without a stop
    d.result = r;
    return;
  }
  if (chair_may_move_ && reason != Reason::kReached) {
    d.stop_path_id = ++next_path_id_;
    latest_path_id_ = d.stop_path_id;
    out_.path = PathCommand{d.stop_path_id, {}};
    d.result = r;
    d.stopping_since = now;
    setState(State::kStopping);
    return;
  }
  emit(r);
  drive_.reset();
  setState(State::kIdle);
}

void Navigator::emit(DriveResult result) {
  if (result.reason != Reason::kReplaced) idle_sentence_ = result.sentence;
  out_.results.push_back(std::move(result));
}

// ---- what it says ------------------------------------------------------------------------------

void Navigator::setState(State state, RouteKind kind) {
  // Idle, a screen still shows how the last drive ended.
  const std::string sentence =
      state == State::kIdle ? idle_sentence_ : stateSentence(state, context(), kind);
  if (state != feedback_.state || sentence != feedback_.sentence) out_.feedback_changed = true;
  feedback_.state = state;
  feedback_.sentence = sentence;
}

void Navigator::refreshFeedback() {
  const bool was_active = feedback_.active;
  feedback_.active = drive_ != nullptr;
  if (was_active != feedback_.active) out_.feedback_changed = true;
  if (pose_) {
    feedback_.pose = *pose_;
    feedback_.have_pose = true;
  }
  if (!drive_) {
    feedback_.distance_remaining = NAN;
    return;
  }
  feedback_.goal_id = drive_->goal_id;
  feedback_.place = drive_->place;
  feedback_.goal = drive_->goal;
  feedback_.replans = drive_->replans;
  feedback_.waits = drive_->waits;
}

SentenceContext Navigator::context() const {
  SentenceContext c;
  if (!drive_) return c;
  c.place = spokenName(drive_->place);
  c.where = drive_->where;
  c.distance = drive_->route.length();
  return c;
}

bool Navigator::startsHere(const std::vector<Pose2D>& path, double& off) const {
  off = 0.0;
  if (path.empty() || !pose_) return true;
  off = (path.front().position() - pose_->position()).norm();
  return off <= config_.start_tolerance;
}

bool Navigator::smoothFromHere(const std::vector<Pose2D>& path) const {
  double off = 0.0;
  if (!startsHere(path, off) || !pose_) return false;
  // Its direction over its first kSmoothLength against the chair's heading.
  for (const Pose2D& p : path) {
    const Eigen::Vector2d ahead = p.position() - path.front().position();
    if (ahead.norm() < kSmoothLength) continue;
    const double direction = std::atan2(ahead.y(), ahead.x());
    return std::abs(wheelchair_core::angleDifference(direction, pose_->yaw)) <= kSmoothTurn;
  }
  return true;  // shorter than that: nearly there
}

bool Navigator::askAgainIfElsewhere(const PlanAnswer& answer, double now) {
  Drive& d = *drive_;
  double off = 0.0;
  if (state() != State::kWaiting && state() != State::kBlocked) return false;
  if (startsHere(answer.path, off)) return false;
  if (d.replans >= config_.max_replans) {
    enterBlocked("no routes left to ask for (" + std::to_string(d.replans) + ")", now);
    return true;
  }
  char text[128];
  std::snprintf(text, sizeof(text),
                "a route from %.2f m away from where the chair stopped, asked again from there",
                off);
  d.notes.push_back(text);
  askPlan(d.purpose, now);
  return true;
}

std::optional<Eigen::Vector2d> Navigator::layerCutOfTheWay() const {
  // The last layer, however old: the planner plans on the last one it got.
  if (!drive_ || !goal_check_ || !pose_ || layer_.width <= 0) return std::nullopt;
  return layerCut(goal_check_->configSpace(), static_map_, layer_, *pose_, drive_->goal,
                  config_.layer_corridor);
}

bool Navigator::wayFree(double now) const {
  return !safety_.stop && !layerBlockAhead(now).has_value();
}

std::optional<Eigen::Vector2d> Navigator::layerBlockAhead(double now) const {
  if (!drive_ || layer_stamp_ < now - config_.layer_max_age) return std::nullopt;
  return layerObstacleAhead(drive_->route, layer_, static_map_, config_.layer_lookahead,
                            config_.layer_corridor);
}

std::string Navigator::whereIs(const std::vector<Eigen::Vector2d>& stretch) const {
  if (stretch.empty() || places_.empty()) return "";
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& p : stretch) centre += p;
  centre /= static_cast<double>(stretch.size());
  const NamedPoint* best = nullptr;
  double best_d = config_.where_radius;
  for (const NamedPoint& place : places_) {
    const double dist = (place.point - centre).norm();
    if (dist <= best_d) best_d = dist, best = &place;
  }
  return best ? spokenName(best->name) : "";
}

}  // namespace wheelchair_navigator
