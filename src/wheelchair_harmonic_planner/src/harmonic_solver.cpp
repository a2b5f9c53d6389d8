#include <wheelchair_harmonic_planner/harmonic_solver.h>

#include "harmonic_stencil.h"
#include "log_cholesky.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>

namespace wheelchair_harmonic_planner {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

/// Optimal SOR factor for the slowest mode of a disc of the widest free radius R [cells]:
/// Jacobi spectral radius rho = 1 - lambda / 4 with lambda = (2.405 / R)^2.
double estimateOmega(const ConfigSpace& cs) {
  const double hard = cs.params().inscribed_radius + cs.params().min_clearance;
  double r_max = 1.0;
  for (int iy = 0; iy < cs.height(); ++iy)
    for (int ix = 0; ix < cs.width(); ++ix)
      if (cs.isFree(ix, iy))
        r_max = std::max(r_max, (cs.obstacleDistance(ix, iy) - hard) / cs.resolution() + 1.0);
  const double rho = std::max(0.0, 1.0 - std::pow(2.405 / r_max, 2) / 4.0);
  return std::min(1.95, 2.0 / (1.0 + std::sqrt(1.0 - rho * rho)));
}

/// One SOR sweep on v (forward or backward); v may not drop below half its old value.
void sorSweep(const Stencil& s, const std::vector<double>& a, long w, double omega, bool forward,
              std::vector<double>& v) {
  const long n = static_cast<long>(s.cells.size());
  for (long i = 0; i < n; ++i) {
    const size_t c = static_cast<size_t>(forward ? i : n - 1 - i);
    const size_t k = s.cells[c];
    const double* ac = &a[4 * c];
    const double gs = ac[0] * v[k + 1] + ac[1] * v[k - 1] + ac[2] * v[k + w] + ac[3] * v[k - w];
    v[k] = std::max(0.5 * v[k], (1.0 - omega) * v[k] + omega * gs);
  }
}

}  // namespace

HarmonicSolverParams::Method solverMethodFromName(const std::string& name) {
  using Method = HarmonicSolverParams::Method;
  if (name == "direct") return Method::kDirect;
  if (name == "sor") return Method::kSor;
  if (name == "multigrid") {
    throw std::invalid_argument(
        "harmonic solver 'multigrid' was removed (it did not converge on large mazes): use "
        "'direct' (the default) or 'sor'");
  }
  throw std::invalid_argument("harmonic solver must be 'direct' or 'sor', not '" + name + "'");
}

bool HarmonicSolution::reachable(int ix, int iy) const {
  return ix >= 0 && iy >= 0 && ix < width && iy < height && std::isfinite(at(ix, iy));
}

namespace {

/// Initial guess: warm start where available, else exponential decay with the BFS distance at
/// the rate pi / width of a corridor whose mean wall distance matches the free space's.
void initialGuess(const ConfigSpace& cs, const Stencil& stencil, const std::vector<int>& dist,
                  const HarmonicSolution* warm, HarmonicSolution& sol) {
  const long w = cs.width();
  double mean_wall = 1.0;
  {
    const double hard = cs.params().inscribed_radius + cs.params().min_clearance;
    double sum = 0.0;
    for (const size_t k : stencil.cells)
      sum += (cs.obstacleDistance(static_cast<int>(k % w), static_cast<int>(k / w)) - hard) /
                 cs.resolution() +
             0.5;
    mean_wall = stencil.cells.empty() ? 1.0 : std::max(0.5, sum / stencil.cells.size());
  }
  const double decay = M_PI / (4.0 * mean_wall);
  sol.log_u.assign(dist.size(), kNegInf);
  sol.log_u[cs.index(sol.goal_ix, sol.goal_iy)] = 0.0;
  for (const size_t k : stencil.cells) {
    const double guess = warm ? warm->log_u[k] : kNegInf;
    sol.log_u[k] = std::isfinite(guess) ? guess : -decay * dist[k];
  }
}

/// Symmetric SOR on the rescaled equation, rescaling every params.sweeps_per_rescale sweeps.
/// `coarse_phase`: start with single log-space Gauss-Seidel steps (for a guess far off).
void solveSor(const ConfigSpace& cs, const Stencil& stencil, const HarmonicSolverParams& params,
              bool coarse_phase, HarmonicSolution& sol) {
  const long w = cs.width();
  sol.omega = params.omega > 0.0 ? params.omega : estimateOmega(cs);
  std::vector<double> a(4 * stencil.cells.size());
  std::vector<double> v(sol.log_u.size(), 0.0);
  v[cs.index(sol.goal_ix, sol.goal_iy)] = 1.0;
  const int max_iter = sol.iterations + std::max(1, params.max_iterations);
  while (true) {
    sol.residual = relativeResidual(stencil, sol.log_u, w, &a);
    if (sol.residual < params.tolerance) {
      sol.converged = true;
      break;
    }
    if (sol.iterations >= max_iter) break;
    for (const size_t k : stencil.cells) v[k] = 1.0;
    // While the guess is far off, take single Gauss-Seidel steps (a log-space iteration);
    // then SOR sweeps between re-scalings, alternating direction (symmetric SOR).
    const int sweeps = coarse_phase ? 1 : std::max(1, params.sweeps_per_rescale);
    const double omega = coarse_phase ? 1.0 : sol.omega;
    for (int s = 0; s < sweeps && sol.iterations < max_iter; ++s, ++sol.iterations) {
      sorSweep(stencil, a, w, omega, (sol.iterations % 2) == 0, v);
    }
    double change = 0.0;
    for (const size_t k : stencil.cells) {
      const double dl = std::log(v[k]);
      sol.log_u[k] += dl;
      change = std::max(change, std::abs(dl));
    }
    if (coarse_phase && change < 0.5) coarse_phase = false;
  }
}

/// The goal-independent factors: from the cache when it holds them for this C-space, else
/// computed (and stored in the cache, if any).
std::shared_ptr<const LogLdlt> directFactor(const ConfigSpace& cs,
                                            const HarmonicSolverParams& params,
                                            HarmonicFactorCache* cache, bool& reused) {
  reused = cache && cache->factor && cache->cspace == &cs && cache->revision == cs.revision() &&
           cache->use_conductance == params.use_conductance;
  if (reused) return cache->factor;
  auto factor = std::make_shared<LogLdlt>(cs, params.use_conductance,
                                          cache ? cache->ordering.get() : nullptr);
  if (cache) {
    if (!factor->orderingReused()) cache->ordering = factor->ordering(cs);
    cache->orderings_reused += factor->orderingReused() ? 1 : 0;
    cache->factor = factor;
    cache->cspace = &cs;
    cache->revision = cs.revision();
    cache->use_conductance = params.use_conductance;
    cache->timing = factor->timing();
    ++cache->factorizations;
  }
  return factor;
}

/// Warm start (same goal, maybe a changed map): taken as is if it still meets the tolerance,
/// else a direct solve; SOR from the guess if the factorization failed (not expected).
void solveDirect(const ConfigSpace& cs, const Stencil& stencil, const HarmonicSolverParams& params,
                 HarmonicFactorCache* cache, HarmonicSolution& sol) {
  sol.residual = relativeResidual(stencil, sol.log_u, cs.width(), nullptr);
  if (sol.warm_started && sol.residual < params.tolerance) {
    sol.converged = true;
    return;
  }
  const auto factor = directFactor(cs, params, cache, sol.factor_reused);
  if (factor->ok()) {
    sol.residual = factor->solve(cs.index(sol.goal_ix, sol.goal_iy), sol.log_u);
    sol.iterations = 1;
  }
  solveSor(cs, stencil, params, !factor->ok() && !sol.warm_started, sol);
}

}  // namespace

bool updateHarmonicFactor(const ConfigSpace& cs, const ConfigSpaceChange& change,
                          const HarmonicSolverParams& params, HarmonicFactorCache& cache) {
  if (params.method != HarmonicSolverParams::Method::kDirect) return false;
  if (!cache.factor || cache.cspace != &cs || cache.use_conductance != params.use_conductance) {
    cache.reset();
    return false;
  }
  if (cache.revision == cs.revision()) return true;  // nothing changed
  const std::clock_t cpu0 = std::clock();
  const bool updated = !change.rebuilt && cache.revision + 1 == cs.revision() &&
                       cache.factor->update(cs, change.cells);
  if (!updated) {
    cache.reset();
    return false;
  }
  cache.revision = cs.revision();
  ++cache.factor_updates;
  cache.updated_columns = cache.factor->updatedColumns();
  cache.update_cpu_time = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return true;
}

bool prepareHarmonicFactor(const ConfigSpace& cs, const HarmonicSolverParams& params,
                           HarmonicFactorCache& factor_cache) {
  if (params.method != HarmonicSolverParams::Method::kDirect) return true;
  bool reused = false;
  const auto factor = directFactor(cs, params, &factor_cache, reused);
  if (!factor->ok() || reused) return factor->ok();
  // A dry solve (for the first free cell): the solves' scratch and the field's storage (the
  // cache's spare) are then in place for the first goal; fresh pages cost ~4 ms per MB here.
  const auto& free = cs.freeMask();
  const auto first = std::find(free.begin(), free.end(), uint8_t{1});
  if (first != free.end()) factor->solve(first - free.begin(), factor_cache.spare);
  return true;
}

HarmonicSolution solveHarmonic(const ConfigSpace& cs, int goal_ix, int goal_iy,
                               const HarmonicSolverParams& params,
                               const HarmonicSolution* warm_start,
                               HarmonicFactorCache* factor_cache) {
  if (!cs.isFree(goal_ix, goal_iy)) {
    throw std::invalid_argument("solveHarmonic: goal cell is not free");
  }
  HarmonicSolution sol;
  sol.width = cs.width();
  sol.height = cs.height();
  sol.goal_ix = goal_ix;
  sol.goal_iy = goal_iy;
  const size_t goal = cs.index(goal_ix, goal_iy);
  sol.warm_started = warm_start != nullptr && warm_start->width == sol.width &&
                     warm_start->height == sol.height && warm_start->goal_ix == goal_ix &&
                     warm_start->goal_iy == goal_iy;
  const bool direct = params.method == HarmonicSolverParams::Method::kDirect;
  if (direct && sol.warm_started) {
    // The earlier solution for this goal (the map changed): kept as is if it still meets the
    // tolerance on this map, checked without building the stencil; else factored as below.
    const double earlier = earlierSolutionResidual(cs, warm_start->log_u, goal,
                                                   params.use_conductance, params.tolerance);
    if (earlier < params.tolerance) {
      sol.log_u = warm_start->log_u;
      for (size_t k = 0; k < sol.log_u.size(); ++k)
        if (!cs.freeMask()[k]) sol.log_u[k] = kNegInf;
      sol.residual = earlier;
      sol.converged = true;
      return sol;
    }
  }
  if (direct) {
    // Direct: the factors (cached per map) and two log-space solves; the residual is checked
    // on the result and SOR polishes below only if it missed the tolerance.
    const auto factor = directFactor(cs, params, factor_cache, sol.factor_reused);
    if (factor->ok()) {
      if (factor_cache) sol.log_u.swap(factor_cache->spare);
      sol.residual = factor->solve(goal, sol.log_u);
      sol.iterations = 1;
      sol.converged = sol.residual < params.tolerance;
      if (sol.converged) return sol;
    }
  }
  const std::vector<int> dist = reachableDistances(cs, goal);
  const Stencil stencil = buildStencil(cs, dist, goal, params.use_conductance);
  if (direct && sol.iterations == 1) {  // polish the direct solution
    solveSor(cs, stencil, params, false, sol);
    return sol;
  }
  initialGuess(cs, stencil, dist, sol.warm_started ? warm_start : nullptr, sol);
  if (direct) {
    solveDirect(cs, stencil, params, factor_cache, sol);
  } else {
    solveSor(cs, stencil, params, !sol.warm_started, sol);
  }
  return sol;
}

JacobiResult solvePaperJacobi(const ConfigSpace& cs, int goal_ix, int goal_iy, double tolerance,
                              int max_iterations) {
  JacobiResult r;
  const size_t n = static_cast<size_t>(cs.width()) * cs.height();
  const long w = cs.width();
  r.phi.assign(n, 1.0);
  const size_t goal = cs.index(goal_ix, goal_iy);
  r.phi[goal] = 0.0;
  std::vector<double> next = r.phi;
  std::vector<size_t> cells;
  for (size_t k = 0; k < n; ++k)
    if (cs.freeMask()[k] && k != goal) cells.push_back(k);
  while (r.iterations < max_iterations) {
    double change = 0.0;
    for (const size_t k : cells) {
      // Paper, Algorithm 2: each free cell becomes the average of its four neighbours.
      next[k] = 0.25 * (r.phi[k + 1] + r.phi[k - 1] + r.phi[k + w] + r.phi[k - w]);
      change = std::max(change, std::abs(next[k] - r.phi[k]));
    }
    r.phi.swap(next);
    ++r.iterations;
    if (change < tolerance) {
      r.converged = true;
      break;
    }
  }
  return r;
}

}  // namespace wheelchair_harmonic_planner
