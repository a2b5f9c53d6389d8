#include <wheelchair_harmonic_planner/harmonic_solver.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

namespace wheelchair_harmonic_planner {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

/// Free cells connected to the goal (4-neighbourhood), with their breadth-first distance.
std::vector<int> reachableDistances(const ConfigSpace& cs, size_t goal) {
  std::vector<int> dist(static_cast<size_t>(cs.width()) * cs.height(), -1);
  const auto& free = cs.freeMask();
  const long w = cs.width();
  std::deque<size_t> queue{goal};
  dist[goal] = 0;
  while (!queue.empty()) {
    const size_t k = queue.front();
    queue.pop_front();
    for (const long off : {1L, -1L, w, -w}) {
      const size_t n = static_cast<size_t>(static_cast<long>(k) + off);
      if (free[n] && dist[n] < 0) {
        dist[n] = dist[k] + 1;
        queue.push_back(n);
      }
    }
  }
  return dist;
}

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

/// The discrete operator: for free cell k, u_k = sum_j w_kj u_j / sum_j w_kj over its four
/// neighbours; edge conductance w_kj = (sigma_k + sigma_j) / 2 (sigma_j := sigma_k for
/// obstacles, whose u is 0). With sigma = 1 this is the paper's four-neighbour average.
struct Stencil {
  std::vector<size_t> cells;    ///< free cells connected to the goal, goal excluded
  std::vector<double> weight;   ///< 4 normalized weights per listed cell (E, W, N, S)
  std::vector<uint8_t> active;  ///< 1 for cells whose log u is finite (incl. goal)
};

Stencil buildStencil(const ConfigSpace& cs, const std::vector<int>& dist, size_t goal,
                     bool use_conductance) {
  Stencil s;
  const long w = cs.width();
  const long offsets[4] = {1, -1, w, -w};
  s.active.assign(dist.size(), 0);
  for (size_t k = 0; k < dist.size(); ++k) {
    if (dist[k] < 0) continue;
    s.active[k] = 1;
    if (k == goal) continue;
    s.cells.push_back(k);
  }
  auto sigma = [&](size_t k) {
    return use_conductance ? cs.conductance(static_cast<int>(k % w), static_cast<int>(k / w)) : 1.0;
  };
  s.weight.resize(4 * s.cells.size());
  for (size_t c = 0; c < s.cells.size(); ++c) {
    const size_t k = s.cells[c];
    double total = 0.0;
    for (int d = 0; d < 4; ++d) {
      const size_t n = static_cast<size_t>(static_cast<long>(k) + offsets[d]);
      const double edge = 0.5 * (sigma(k) + (s.active[n] ? sigma(n) : sigma(k)));
      s.weight[4 * c + d] = s.active[n] ? edge : 0.0;
      total += edge;
    }
    for (int d = 0; d < 4; ++d) s.weight[4 * c + d] /= total;
  }
  return s;
}

/// Scaled coefficients a_kj = w_kj exp(l_j - l_k) for v = u / exp(l); returns the max relative
/// residual |sum_j a_kj - 1| of the current log field.
double scaleCoefficients(const Stencil& s, const std::vector<double>& l, long w,
                         std::vector<double>& a) {
  const long offsets[4] = {1, -1, w, -w};
  double residual = 0.0;
  for (size_t c = 0; c < s.cells.size(); ++c) {
    const size_t k = s.cells[c];
    double sum = 0.0;
    for (int d = 0; d < 4; ++d) {
      const double wt = s.weight[4 * c + d];
      const double coef =
          wt > 0.0 ? wt * std::exp(l[static_cast<size_t>(static_cast<long>(k) + offsets[d])] - l[k])
                   : 0.0;
      a[4 * c + d] = coef;
      sum += coef;
    }
    residual = std::max(residual, std::abs(sum - 1.0));
  }
  return residual;
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

bool HarmonicSolution::reachable(int ix, int iy) const {
  return ix >= 0 && iy >= 0 && ix < width && iy < height && std::isfinite(at(ix, iy));
}

HarmonicSolution solveHarmonic(const ConfigSpace& cs, int goal_ix, int goal_iy,
                               const HarmonicSolverParams& params,
                               const HarmonicSolution* warm_start) {
  if (!cs.isFree(goal_ix, goal_iy)) {
    throw std::invalid_argument("solveHarmonic: goal cell is not free");
  }
  HarmonicSolution sol;
  sol.width = cs.width();
  sol.height = cs.height();
  sol.goal_ix = goal_ix;
  sol.goal_iy = goal_iy;
  const long w = cs.width();
  const size_t goal = cs.index(goal_ix, goal_iy);
  const std::vector<int> dist = reachableDistances(cs, goal);
  const Stencil stencil = buildStencil(cs, dist, goal, params.use_conductance);

  // Initial guess: warm start where available, else exponential decay with the BFS distance at
  // the rate pi / width of a corridor whose mean wall distance matches the free space's.
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
  const bool warm = warm_start != nullptr && warm_start->width == sol.width &&
                    warm_start->height == sol.height && warm_start->goal_ix == goal_ix &&
                    warm_start->goal_iy == goal_iy;
  sol.warm_started = warm;
  sol.log_u.assign(dist.size(), kNegInf);
  sol.log_u[goal] = 0.0;
  for (const size_t k : stencil.cells) {
    const double guess = warm ? warm_start->log_u[k] : kNegInf;
    sol.log_u[k] = std::isfinite(guess) ? guess : -decay * dist[k];
  }

  sol.omega = params.omega > 0.0 ? params.omega : estimateOmega(cs);
  std::vector<double> a(4 * stencil.cells.size());
  std::vector<double> v(dist.size(), 0.0);
  v[goal] = 1.0;
  const int max_iter = std::max(1, params.max_iterations);
  bool coarse_phase = !warm;
  while (true) {
    sol.residual = scaleCoefficients(stencil, sol.log_u, w, a);
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
