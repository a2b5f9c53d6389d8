// The paper's boundary problem (section 2.3, Algorithm 2): Laplace's equation on the free
// C-space with obstacles held at 1 and the goal at 0. We solve for u = 1 - phi (obstacles 0,
// goal 1) and keep it as log u (Wray et al., IROS 2016), so that the exponentially small values
// far down long corridors keep full relative precision and their gradient never underflows.
#pragma once

#include <wheelchair_planner/config_space.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace wheelchair_harmonic_planner {

using wheelchair_planner::ConfigSpace;
using wheelchair_planner::ConfigSpaceChange;
using wheelchair_planner::ConfigSpaceParams;

struct HarmonicSolverParams {
  /// kDirect: sparse LDL^T with log-space triangular solves (log_cholesky.h), then SOR sweeps
  /// only if its residual misses the tolerance; kSor: rescaled SOR.
  enum class Method { kDirect, kSor };
  Method method = Method::kDirect;
  /// Convergence: max over free cells of the relative residual
  /// |sum_j w_ij u_j / sum_j w_ij - u_i| / u_i  (= |Delta log u| of one Jacobi step).
  double tolerance = 1e-5;
  int max_iterations = 20000;   ///< SOR sweeps (SOR, direct's polish)
  double omega = 0.0;           ///< SOR: factor; 0 = estimated from the widest free region
  int sweeps_per_rescale = 8;   ///< SOR: linear sweeps between two re-scalings of the log field
  bool use_conductance = true;  ///< false: plain Laplace (the paper's equation everywhere)
};

/// "direct" or "sor" (the planner's `solver` parameter); throws std::invalid_argument naming
/// the choices otherwise ("multigrid" was removed: it did not converge on large mazes).
HarmonicSolverParams::Method solverMethodFromName(const std::string& name);

struct HarmonicSolution {
  int width = 0;
  int height = 0;
  int goal_ix = -1;
  int goal_iy = -1;
  /// log u per cell: 0 at the goal, -infinity at obstacles and cells not connected to the goal.
  std::vector<double> log_u;
  int iterations = 0;          ///< SOR sweeps; direct: 1 (0 if the warm start already
                               ///< met the tolerance) + polishing SOR sweeps
  bool factor_reused = false;  ///< direct: the factors came from the cache (only the solves ran)
  double residual = std::numeric_limits<double>::infinity();
  double omega = 1.0;
  bool converged = false;
  bool warm_started = false;

  double at(int ix, int iy) const { return log_u[static_cast<size_t>(iy) * width + ix]; }
  bool reachable(int ix, int iy) const;
};

class LogLdlt;

/// The fill-reducing order of a factorization and the free cells it was computed for: the next
/// map with exactly the same free cells (e.g. only the clearance band's conductances changed,
/// or the same map again) reuses it and skips the AMD ordering.
struct FactorOrdering {
  std::vector<uint8_t> free_mask;
  std::vector<int> permutation;  ///< unknown (free cells numbered row by row) at each position
};

/// CPU seconds of the direct solver's map-dependent phases (incl. their page faults): the
/// equation's assembly, CHOLMOD's symbolic analysis (AMD ordering, elimination tree, counts)
/// and the numeric LDL^T factorization.
struct FactorTiming {
  double assemble = 0.0;
  double analyze = 0.0;
  double factorize = 0.0;
};

/// The direct solver's map-dependent part: the ordering and LDL^T factors of the equation of
/// every free cell, which do not depend on the goal (log_cholesky.h). Kept by the caller between
/// solves on the same ConfigSpace object, a new goal then costs two triangular solves instead of
/// a factorization. The cache is tied to the ConfigSpace it was filled for (its address and
/// revision): call reset() whenever that object is replaced or destroyed; after an in-place
/// ConfigSpace::update(), updateHarmonicFactor() adapts the factors to it.
struct HarmonicFactorCache {
  std::shared_ptr<LogLdlt> factor;
  const ConfigSpace* cspace = nullptr;
  int revision = 0;  ///< ConfigSpace::revision() the factors are for
  bool use_conductance = true;
  int factorizations = 0;        ///< factors computed through this cache (for tests and the bench)
  int orderings_reused = 0;      ///< of those, with the previous map's ordering
  int factor_updates = 0;        ///< factors adapted to a C-space update (updateHarmonicFactor)
  size_t updated_columns = 0;    ///< factor columns the last of those recomputed
  double update_cpu_time = 0.0;  ///< CPU seconds of the last of those
  FactorTiming timing;           ///< of the last factorization
  /// Kept across reset(): the last factorization's ordering, for a map with the same free cells.
  std::shared_ptr<const FactorOrdering> ordering;
  std::vector<double> spare;  ///< storage recycled for the next solution's log_u
  void reset() {
    factor.reset();
    cspace = nullptr;
  }
};

/// Solves for the goal cell. `warm_start` (same grid, e.g. the previous solution for this goal
/// on the previous map) is used as the initial guess where it is finite. The goal must be a
/// free cell (checked: throws std::invalid_argument otherwise). `factor_cache` (direct solver
/// only) keeps the factors for the next goal on the same C-space.
HarmonicSolution solveHarmonic(const ConfigSpace& cspace, int goal_ix, int goal_iy,
                               const HarmonicSolverParams& params,
                               const HarmonicSolution* warm_start = nullptr,
                               HarmonicFactorCache* factor_cache = nullptr);

/// After `cspace.update()` returned `change`: the cached factors (for the C-space's previous
/// revision) adapted in place (LogLdlt::update: only the factor columns that depend on a
/// changed row are recomputed), so that the next solve needs no factorization. True if the
/// cache now holds the factors of `cspace`. False if it held none for the previous revision, or
/// the C-space was rebuilt, or a cell is free that was not free in the factored C-space (cells
/// only blocked and freed again relative to it are fine): the cache is then reset (its ordering
/// kept), and the next solve factors afresh.
bool updateHarmonicFactor(const ConfigSpace& cspace, const ConfigSpaceChange& change,
                          const HarmonicSolverParams& params, HarmonicFactorCache& factor_cache);

/// The direct solver's map-dependent work done ahead of any goal: fills `factor_cache` with the
/// factors of `cspace` (nothing to do if it already holds them, or for the iterative solvers,
/// which have no goal-independent part), then solves once for the first free cell so that the
/// solves' buffers exist too. A planner calls it when a map arrives, so that the first goal on
/// that map costs only the solves. False if the factorization failed (the solve then falls back
/// to SOR).
bool prepareHarmonicFactor(const ConfigSpace& cspace, const HarmonicSolverParams& params,
                           HarmonicFactorCache& factor_cache);

/// The paper's method, for comparison: plain Jacobi on phi (obstacles 1, goal 0), linear
/// space, stopping when max |Delta phi| < tolerance. Returns phi per cell.
struct JacobiResult {
  std::vector<double> phi;
  int iterations = 0;  ///< Jacobi sweeps
  bool converged = false;
};
JacobiResult solvePaperJacobi(const ConfigSpace& cspace, int goal_ix, int goal_iy, double tolerance,
                              int max_iterations);

}  // namespace wheelchair_harmonic_planner
