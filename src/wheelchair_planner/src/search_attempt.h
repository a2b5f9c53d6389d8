// One weighted A* run of the footprint search with one lattice setting (internal header of
// footprint_search.cpp): the lattice, the start's in-place rotations, the forward and reverse
// motion primitives with their cusps, the candidates that join the goal, and the reason when
// nothing is found. A run can be advanced in slices (footprint_search.cpp shares one budget
// among the settings).
#pragma once

#include <wheelchair_planner/footprint_search.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace wheelchair_planner {

/// The heuristic fields of one search, shared by its runs: every forward run's is the geodesic
/// distance to the goal, every backward run's to the start (the same axle disc), computed once
/// by the first run of each direction that starts (footprint_search.cpp).
struct HeuristicFields {
  std::vector<double> to_goal, to_start;  ///< empty until computed
};

class SearchAttempt {
 public:
  /// All references must outlive the attempt.
  SearchAttempt(const FootprintChecker& checker, const Pose2D& start, const Pose2D& goal,
                const FootprintSearchParams& params, const FootprintSearchParams::Attempt& attempt,
                const SweepModel& sweep, HeuristicFields& fields);

  enum class Status {
    kRunning,    ///< open nodes left: may be advanced further
    kFound,      ///< `result()` holds the path
    kExhausted,  ///< every pose the lattice reaches was expanded (or too many candidates failed)
    kRefused,    ///< could not start (outside the map, goal unreachable, start overlapping)
  };

  /// Expands at most `expansions` more nodes, stopping early at `deadline` (steady clock).
  Status advance(size_t expansions, std::chrono::steady_clock::time_point deadline);

  Status status() const { return status_; }
  size_t expansions() const { return expansions_; }
  /// The found path (status kFound); otherwise `reason` says why nothing was found so far.
  const FootprintSearchResult& result() const { return result_; }
  /// Why nothing was found so far (closest approach, what blocked it, the last failed sweep).
  std::string failureReason() const;
  /// How close the run came to the goal [m of geodesic distance] (for the summary).
  double closestApproach() const { return closest_ / attempt_.heuristic_weight; }
  /// The run searches from the goal to the start (FootprintSearchParams::Attempt::backward).
  bool backward() const { return attempt_.backward; }
  /// The run gets the first round's slice only (FootprintSearchParams::Attempt::one_slice).
  bool oneSlice() const { return attempt_.one_slice; }
  /// Runs of the other direction whose trees this run tries to join at each expansion (a
  /// bidirectional search: the way out of a side room backwards and the way along the hallway
  /// to the goal are each found quickly, together by neither alone). All must outlive this.
  void setPartners(std::vector<const SearchAttempt*> partners) { partners_ = std::move(partners); }
  /// Joins are tried only once this is set (footprint_search.cpp: after every run's first
  /// slice, so that a forward path found alone is preferred to a joined one).
  void startMeeting() { meeting_ = true; }

 private:
  struct Node {
    Pose2D pose;
    double g = 0.0;
    int parent = -1;
    double kappa = 0.0;
    bool rotation = false;  ///< reached from the parent by an in-place rotation (start only)
    bool moved = false;     ///< reached by a primitive (not the start or a start rotation)
    bool reverse = false;   ///< that primitive runs in reverse in the search's own direction
    int cusps = 0;          ///< direction changes on the way here
    double reversed = 0.0;  ///< [m] that the chair will drive in reverse on the way here
  };

  /// The cells, the heuristic field and the clearance rule; false with the reason if the search
  /// cannot start (outside the map, goal unreachable for the axle disc, start overlapping).
  bool prepare(std::string& reason);
  /// The start node and the headings reachable from it by rotating in place either way.
  void seedStart();
  /// A goal-region arrival: true (and `result_` filled) if the final rotation and the whole
  /// executed sweep of the path to it keep the required clearance.
  bool acceptCandidate(int idx);
  /// The motion primitives from node `idx` (a copy of it in `node`).
  void expand(int idx, const Node& node);
  /// Joins node `idx` to a node of a partner run at about the same pose and heading by a short
  /// straight piece along the motion; true (and `result_` filled) if the joined path keeps the
  /// limits on cusps and reversing and its whole executed sweep passes.
  bool tryMeet(int idx, const Node& node);
  /// Cell and heading bin of a pose, without the direction (where two runs may meet).
  int64_t cellKey(const Pose2D& p) const;
  /// Analytic expansion: the Reeds-Shepp path from node `idx` to the goal pose; true (and
  /// `result_` filled) if it keeps the clearance, the limits on cusps and reversing, and the
  /// whole executed sweep passes.
  bool tryAnalytic(int idx, const Node& node);
  /// True (and `result_` filled) if the executed sweep of `path` (from the search's start to
  /// its goal: drivenPath) keeps the clearance; else its reason is kept for the failure message.
  bool acceptPath(std::vector<Pose2D> path);
  /// The plan the chair drives for a path of this run: a backward run's path reversed (the
  /// chair's start first, the goal with its heading last); a forward run's as it is.
  std::vector<Pose2D> drivenPath(std::vector<Pose2D> path) const;
  /// A primitive of this run that runs `reverse` in the search's direction is driven in
  /// reverse by the chair.
  bool drivenInReverse(bool reverse) const { return reverse != attempt_.backward; }

  /// Clearance of a pose if it keeps what the rule requires there, else the blocking contact.
  bool poseOk(const Pose2D& p, bool start_rotation, FootprintContact& c) const;
  double heuristic(const Pose2D& p) const;
  int64_t key(const Pose2D& p, bool reverse) const;
  /// Cost per metre for a primitive whose smallest footprint clearance is `c`.
  double penalty(double c) const;
  /// A node at least as cheap as `g` has reached the state of `p` (arriving `reverse`): push()
  /// would refuse one of cost `g` there.
  bool reachedAsCheaply(const Pose2D& p, bool reverse, double g) const;
  void push(const Node& n);
  /// The start position, the primitives' poses (every 5 cm) up to node `idx`, and the goal
  /// (unless `with_goal` is false).
  std::vector<Pose2D> pathTo(int idx, bool with_goal = true) const;

  const FootprintChecker& checker_;
  const ConfigSpace& cs_;
  /// Where the search begins and ends: the chair's start and goal, swapped in a backward run.
  const Pose2D start_, goal_;
  const Pose2D chair_start_, chair_goal_;  ///< the plan's own start and goal
  const FootprintSearchParams& params_;
  const FootprintSearchParams::Attempt attempt_;
  const SweepModel& sweep_;
  HeuristicFields& fields_;
  const std::vector<double>* h_ = nullptr;  ///< geodesic distance to goal_ per cell [m]
  ClearanceRule rule_;
  double bin_angle_ = 0.0;
  std::vector<double> curvatures_;

  Status status_ = Status::kRunning;
  bool started_ = false;
  size_t expansions_ = 0;
  FootprintSearchResult result_;
  std::vector<Node> nodes_;
  std::unordered_map<int64_t, double> best_g_;
  std::unordered_map<int64_t, bool> expanded_;
  std::unordered_map<int64_t, std::vector<int>> by_cell_;  ///< nodes per cellKey
  std::vector<const SearchAttempt*> partners_;
  int meet_tries_ = 0;  ///< joined paths whose sweep was checked
  bool meeting_ = false;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open_;

  // Where the search came closest to the goal, and what blocked it there (for the reason).
  double closest_ = std::numeric_limits<double>::infinity();
  Pose2D closest_pose_;
  FootprintContact closest_block_;
  int candidates_ = 0;
  double analytic_best_ = std::numeric_limits<double>::infinity();  ///< nearest node tried [m]
  size_t analytic_last_ = 0;  ///< expansion count at the last analytic try
  std::string last_candidate_reason_;
};

}  // namespace wheelchair_planner
