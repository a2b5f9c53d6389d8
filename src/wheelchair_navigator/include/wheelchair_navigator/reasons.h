// Everything the navigator tells the rider, in one table: why a drive ended (one Reason per
// outcome, the same numbers as wheelchair_msgs/NavigateResult) and what the chair is doing now
// (one sentence per State, as wheelchair_msgs/NavigatorState). Sentences are short and name no
// frames or coordinates; the technical cause goes to the log and the result's `detail`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_navigator {

/// Why a drive ended. Values are wheelchair_msgs/NavigateResult's constants.
enum class Reason : uint8_t {
  kReached = 0,
  kCanceled = 1,
  kReplaced = 2,
  kNotLocalized = 3,
  kInvalidGoal = 4,
  kUnknownPlace = 5,
  kGoalOutsideMap = 6,
  kGoalInObstacle = 7,
  kGoalNoRoom = 8,
  kNoRoute = 9,
  kBlocked = 10,
  kSafetyStop = 11,
  kLocalizationLost = 12,
  kNoProgress = 13,
  kControlFailed = 14,
  kNotReady = 15,
};

/// What the navigator is doing. Values are wheelchair_msgs/NavigatorState's constants.
enum class State : uint8_t {
  kIdle = 0,
  kPlanning = 1,
  kDriving = 2,
  kWaiting = 3,
  kBlocked = 4,
  kStopping = 5,
};

/// One row of the table: the reason, its name for logs, the rider's sentence (with the
/// placeholders of SentenceContext), and whether it is a refusal (the goal was never pursued:
/// the chair did not move for it).
struct ReasonRow {
  Reason reason;
  const char* name;
  const char* sentence;
  bool refusal;
};

/// The table, in Reason order.
const std::vector<ReasonRow>& reasonTable();
const ReasonRow& reasonRow(Reason reason);
const char* toString(Reason reason);
const char* toString(State state);

/// What fills a sentence's placeholders: {place} the destination ("kitchen door", or "there"),
/// {where} where the way is blocked (" near the kitchen door", or ""), {cause} the safety
/// supervisor's words for its stop ("the laser scanner is silent"), {distance} "5.2 m".
struct SentenceContext {
  std::string place;
  std::string where;
  std::string cause;
  double distance = 0.0;
};

/// The rider's sentence for a drive that ended with `reason`.
std::string riderSentence(Reason reason, const SentenceContext& context);

/// Which route the chair drives: the first one, the same way again after a wait, or
/// another way round something in the way.
enum class RouteKind { kFirst, kResumed, kAround, kBackUp };

/// The rider's sentence while in `state` (kDriving: on a route of `kind`).
std::string stateSentence(State state, const SentenceContext& context,
                          RouteKind kind = RouteKind::kFirst);

/// A place's name as the rider hears it: "kitchen_door" -> "kitchen door".
std::string spokenName(const std::string& name);

}  // namespace wheelchair_navigator
