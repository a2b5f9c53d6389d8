#include <wheelchair_planner/footprint_search.h>

#include "geodesic_distance.h"
#include "search_attempt.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <sstream>
#include <string>

namespace wheelchair_planner {

namespace {

/// What was tried, in words: the settings, the motions allowed, the budget and how it ended.
std::string summary(const FootprintSearchParams& params, size_t settings, size_t expansions,
                    double seconds, bool budget_spent, bool time_spent) {
  std::ostringstream os;
  os.precision(3);
  os << "no footprint-feasible path (" << settings << " lattice setting"
     << (settings == 1 ? "" : "s") << ", ";
  if (params.reverse) {
    os << "forwards and in reverse with at most " << params.max_cusps << " cusps and "
       << params.max_reverse_length << " m reversed";
  } else {
    os << "forwards only";
  }
  os << "; " << expansions << " expansions in " << seconds << " s: ";
  if (!budget_spent)
    os << "every pose the lattice reaches was tried";
  else if (time_spent)
    os << "the time budget of " << params.time_limit << " s is spent";
  else
    os << "the budget of " << params.max_expansions << " expansions is spent";
  os << ")";
  return os.str();
}

}  // namespace

FootprintSearchResult footprintSearch(const FootprintChecker& checker, const Pose2D& start,
                                      const Pose2D& goal, const FootprintSearchParams& params,
                                      const SweepModel& sweep) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const auto deadline = t0 + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(params.time_limit));
  FootprintSearchResult result;
  if (params.attempts.empty()) {
    result.reason = "footprint search: no attempt configured";
    return result;
  }
  std::vector<std::unique_ptr<SearchAttempt>> runs;
  HeuristicFields fields;  // one field per direction, not one per run
  for (const FootprintSearchParams::Attempt& a : params.attempts)
    runs.push_back(std::make_unique<SearchAttempt>(checker, start, goal, params, a, sweep, fields));
  // Each run tries to join the trees of the runs searching the other way.
  for (const auto& run : runs) {
    std::vector<const SearchAttempt*> partners;
    for (const auto& other : runs)
      if (other->backward() != run->backward()) partners.push_back(other.get());
    run->setPartners(std::move(partners));
  }
  const auto spent = [&] {
    size_t n = 0;
    for (const auto& r : runs) n += r->expansions();
    return n;
  };
  const size_t budget = static_cast<size_t>(std::max(0, params.max_expansions));
  const SearchAttempt* found = nullptr;
  bool progress = true;
  // Round after round, each setting that can go on gets a slice, in order (the least greedy
  // first: where it succeeds its paths keep more clearance), until one finds a path. From the
  // second round on, the forward and backward runs also try to join their trees.
  bool first_round = true;
  while (!found && progress && Clock::now() < deadline && spent() < budget) {
    progress = false;
    if (!first_round)
      for (const auto& run : runs) run->startMeeting();
    for (const auto& run : runs) {
      if (run->status() != SearchAttempt::Status::kRunning) continue;
      if (!first_round && run->oneSlice()) continue;
      const size_t left = budget - std::min(budget, spent());
      if (left == 0 || Clock::now() >= deadline) break;
      const size_t slice = std::min(left, static_cast<size_t>(params.attempt_expansions));
      const SearchAttempt::Status status = run->advance(slice, deadline);
      progress = true;
      if (status == SearchAttempt::Status::kFound) {
        found = run.get();
        break;
      }
      // Refused before searching (outside the map, goal unreachable for the axle disc, start
      // overlapping): no other setting changes that.
      if (status == SearchAttempt::Status::kRefused) {
        result = run->result();
        result.time = std::chrono::duration<double>(Clock::now() - t0).count();
        return result;
      }
    }
    first_round = false;
  }
  result.time = std::chrono::duration<double>(Clock::now() - t0).count();
  result.expansions = spent();
  if (found) {
    const size_t expansions = result.expansions;
    const double time = result.time;
    result = found->result();
    result.expansions = expansions;
    result.time = time;
    return result;
  }
  // Nothing fits: say what was tried, how far the best setting came and what blocked it there,
  // and the narrowest passage on the way.
  // (A backward run's approach is to the start: not what the rider asked about.)
  const SearchAttempt* best = runs.front().get();
  for (const auto& run : runs)
    if (!run->backward() && (best->backward() || run->closestApproach() < best->closestApproach()))
      best = run.get();
  bool budget_spent = false;
  for (const auto& run : runs)
    budget_spent =
        budget_spent || (run->status() == SearchAttempt::Status::kRunning && !run->oneSlice());
  std::ostringstream os;
  os.precision(3);
  os << summary(params, runs.size(), result.expansions, result.time, budget_spent,
                Clock::now() >= deadline)
     << ": " << best->failureReason();
  double x = 0.0, y = 0.0;
  int sx, sy, gx, gy;
  const ConfigSpace& cs = checker.configSpace();
  const double passage =
      cs.worldToCell(start.x, start.y, sx, sy) && cs.worldToCell(goal.x, goal.y, gx, gy)
          ? narrowestPassage(cs, sx, sy, gx, gy, x, y)
          : 0.0;
  if (passage > 0.0)
    os << "; the narrowest passage on the way is " << passage << " m wide at (" << x << ", " << y
       << ")";
  result.reason = os.str();
  return result;
}

}  // namespace wheelchair_planner
