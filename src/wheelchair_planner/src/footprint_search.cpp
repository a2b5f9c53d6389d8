#include <wheelchair_planner/footprint_search.h>

#include "search_attempt.h"

#include <chrono>
#include <string>

namespace wheelchair_planner {

FootprintSearchResult footprintSearch(const FootprintChecker& checker, const Pose2D& start,
                                      const Pose2D& goal, const FootprintSearchParams& params,
                                      const SweepModel& sweep) {
  const auto t0 = std::chrono::steady_clock::now();
  const size_t n = params.attempts.size();
  FootprintSearchResult result;
  size_t expansions = 0, attempts = 0;
  for (size_t i = 0; i < n; ++i) {
    const double used =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (used >= params.time_limit) break;
    result = SearchAttempt(checker, start, goal, params, params.attempts[i], sweep)
                 .run(params.time_limit - used);
    expansions += result.expansions;
    ++attempts;
    // No expansion: refused before searching (outside the map, goal unreachable for the axle
    // disc, start overlapping), which no other setting changes.
    if (result.found || result.expansions == 0) break;
  }
  if (n == 0) result.reason = "footprint search: no attempt configured";
  if (!result.found && attempts > 1)
    result.reason = std::to_string(attempts) + " search settings tried; last: " + result.reason;
  result.expansions = expansions;
  result.time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace wheelchair_planner
