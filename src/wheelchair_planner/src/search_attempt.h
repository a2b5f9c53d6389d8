// One weighted A* run of the footprint search with one setting (internal header of
// footprint_search.cpp): the lattice, the start's in-place rotations, the motion primitives,
// the candidates that join the goal, and the reason when nothing is found.
#pragma once

#include <wheelchair_planner/footprint_search.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace wheelchair_planner {

class SearchAttempt {
 public:
  /// All references must outlive the attempt.
  SearchAttempt(const FootprintChecker& checker, const Pose2D& start, const Pose2D& goal,
                const FootprintSearchParams& params, const FootprintSearchParams::Attempt& attempt,
                const SweepModel& sweep);

  /// Searches for at most `time_limit` seconds (and params.attempt_expansions expansions).
  FootprintSearchResult run(double time_limit);

 private:
  struct Node {
    Pose2D pose;
    double g = 0.0;
    int parent = -1;
    double kappa = 0.0;
    bool rotation = false;  ///< reached from the parent by an in-place rotation (start only)
  };

  /// The cells, the heuristic field and the clearance rule; false with the reason if the search
  /// cannot start (outside the map, goal unreachable for the axle disc, start overlapping).
  bool prepare(std::string& reason);
  /// The start node and the headings reachable from it by rotating in place either way.
  void seedStart();
  /// A goal-region arrival: true (and `result` filled) if the final rotation and the whole
  /// executed sweep of the path to it keep the required clearance.
  bool acceptCandidate(int idx, FootprintSearchResult& result);
  /// The motion primitives from node `idx` (a copy of it in `node`).
  void expand(int idx, const Node& node);
  /// Why nothing was found, after `expansions` in `seconds`; `limit` names a limit reached.
  std::string failureReason(size_t expansions, double seconds, const std::string& limit) const;

  /// Clearance of a pose if it keeps what the rule requires there, else the blocking contact.
  bool poseOk(const Pose2D& p, bool start_rotation, FootprintContact& c) const;
  double heuristic(const Pose2D& p) const;
  int64_t key(const Pose2D& p) const;
  /// Cost per metre for a primitive whose smallest footprint clearance is `c`.
  double penalty(double c) const;
  void push(const Node& n);
  /// The start position, the primitives' poses (every 5 cm) up to node `idx`, and the goal.
  std::vector<Pose2D> pathTo(int idx) const;

  const FootprintChecker& checker_;
  const ConfigSpace& cs_;
  const Pose2D start_, goal_;
  const FootprintSearchParams& params_;
  const FootprintSearchParams::Attempt attempt_;
  const SweepModel& sweep_;
  std::vector<double> h_;  ///< geodesic distance to the goal per cell [m]
  ClearanceRule rule_;
  double bin_angle_ = 0.0;
  std::vector<double> curvatures_;

  std::vector<Node> nodes_;
  std::unordered_map<int64_t, double> best_g_;
  std::unordered_map<int64_t, bool> expanded_;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open_;

  // Where the search came closest to the goal, and what blocked it there (for the reason).
  double closest_ = std::numeric_limits<double>::infinity();
  Pose2D closest_pose_;
  FootprintContact closest_block_;
  int candidates_ = 0;
  std::string last_candidate_reason_;
};

}  // namespace wheelchair_planner
