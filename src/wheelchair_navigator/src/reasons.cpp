#include <wheelchair_navigator/reasons.h>

#include <cstdio>
#include <stdexcept>

namespace wheelchair_navigator {

namespace {

/// Replaces every "{key}" of `text` by `value`.
std::string substitute(std::string text, const std::string& key, const std::string& value) {
  const std::string placeholder = "{" + key + "}";
  for (size_t at = text.find(placeholder); at != std::string::npos;
       at = text.find(placeholder, at + value.size()))
    text.replace(at, placeholder.size(), value);
  return text;
}

std::string fillAll(const char* text, const SentenceContext& c) {
  char distance[32];
  std::snprintf(distance, sizeof(distance), "%.1f m", c.distance);
  std::string out = substitute(text, "to", c.place.empty() ? "" : " to " + c.place);
  out = substitute(out, "where", c.where.empty() ? "" : " near " + c.where);
  out = substitute(out, "cause", c.cause.empty() ? "the supervisor stopped the chair" : c.cause);
  return substitute(out, "distance", distance);
}

}  // namespace

const std::vector<ReasonRow>& reasonTable() {
  static const std::vector<ReasonRow> table{
      {Reason::kReached, "reached", "Arrived.", false},
      {Reason::kCanceled, "canceled", "Stopped, as you asked.", false},
      {Reason::kReplaced, "replaced", "Going to the new destination instead.", false},
      {Reason::kNotLocalized, "not_localized",
       "I don't know where the chair is yet: set its position first.", true},
      {Reason::kInvalidGoal, "invalid_goal", "That destination cannot be used: choose another one.",
       true},
      {Reason::kUnknownPlace, "unknown_place", "I don't know that place: choose another one.",
       true},
      {Reason::kGoalOutsideMap, "goal_outside_map",
       "That destination is outside the map: choose another one.", true},
      {Reason::kGoalInObstacle, "goal_in_obstacle",
       "That destination is inside a wall or furniture: choose another one.", true},
      {Reason::kGoalNoRoom, "goal_no_room",
       "The chair does not fit at that destination: choose another one.", true},
      {Reason::kNoRoute, "no_route",
       "There is no way there that the chair fits through. The chair stays where it is.", false},
      {Reason::kBlocked, "blocked",
       "The way is blocked{where}. The chair has stopped: choose a destination to go on.", false},
      {Reason::kSafetyStop, "safety_stop", "Safety stop: {cause}. Choose a destination to go on.",
       false},
      {Reason::kLocalizationLost, "localization_lost",
       "The chair lost track of where it is and stopped: set its position again.", false},
      {Reason::kNoProgress, "no_progress", "The chair was not getting any closer, so it stopped.",
       false},
      {Reason::kControlFailed, "control_failed",
       "The chair could not follow its route and stopped.", false},
      {Reason::kNotReady, "not_ready",
       "The chair is not ready to drive yet: try again in a moment.", false},
  };
  return table;
}

const ReasonRow& reasonRow(Reason reason) {
  const auto& table = reasonTable();
  const size_t i = static_cast<size_t>(reason);
  if (i >= table.size() || table[i].reason != reason)
    throw std::logic_error("reason table out of order");
  return table[i];
}

const char* toString(Reason reason) { return reasonRow(reason).name; }

const char* toString(State state) {
  switch (state) {
    case State::kIdle:
      return "idle";
    case State::kPlanning:
      return "planning";
    case State::kDriving:
      return "driving";
    case State::kWaiting:
      return "waiting";
    case State::kBlocked:
      return "blocked";
    case State::kStopping:
      return "stopping";
  }
  return "unknown";
}

std::string riderSentence(Reason reason, const SentenceContext& context) {
  return fillAll(reasonRow(reason).sentence, context);
}

std::string stateSentence(State state, const SentenceContext& context, RouteKind kind) {
  switch (state) {
    case State::kIdle:
      return "";
    case State::kPlanning:
      return fillAll("Finding a way{to}.", context);
    case State::kDriving:
      if (kind == RouteKind::kResumed) return "The way is free: going on.";
      if (kind == RouteKind::kAround) return fillAll("Going another way{to}: {distance}.", context);
      if (kind == RouteKind::kBackUp) return "Backing out of the way we came.";
      return fillAll("Going{to}: {distance}.", context);
    case State::kWaiting:
      return "Something is in the way: waiting for it to move.";
    case State::kBlocked:
      return fillAll("The way is blocked{where}: the chair waits until it is free.", context);
    case State::kStopping:
      return "Stopping.";
  }
  return "";
}

std::string spokenName(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (c == '_') c = ' ';
  return out;
}

}  // namespace wheelchair_navigator
