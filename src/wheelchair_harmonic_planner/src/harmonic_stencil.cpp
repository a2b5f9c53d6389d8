#include "harmonic_stencil.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace wheelchair_harmonic_planner {

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
  s.total.resize(s.cells.size());
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
    s.total[c] = total;
  }
  return s;
}

double earlierSolutionResidual(const ConfigSpace& cs, const std::vector<double>& l, size_t goal,
                               bool use_conductance, double give_up_above) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto& free = cs.freeMask();
  if (l.size() != free.size() || !free[goal] || l[goal] != 0.0) return kInf;
  const long w = cs.width();
  const long offsets[4] = {1, -1, w, -w};
  auto sigma = [&](size_t k) {
    return use_conductance ? cs.conductance(static_cast<int>(k % w), static_cast<int>(k / w)) : 1.0;
  };
  double residual = 0.0;
  for (size_t k = 0; k < free.size(); ++k) {
    if (!free[k]) continue;
    const bool finite = std::isfinite(l[k]);
    double total = 0.0, sum = 0.0;
    for (const long off : offsets) {
      const size_t n = static_cast<size_t>(static_cast<long>(k) + off);
      if (free[n] && std::isfinite(l[n]) != finite) return kInf;  // connectivity changed
      const double edge = 0.5 * (sigma(k) + (free[n] ? sigma(n) : sigma(k)));
      total += edge;
      if (finite && free[n]) sum += edge * std::exp(l[n] - l[k]);
    }
    if (!finite || k == goal) continue;
    residual = std::max(residual, std::abs(sum / total - 1.0));
    if (residual > give_up_above) break;
  }
  return residual;
}

double relativeResidual(const Stencil& s, const std::vector<double>& l, long width,
                        std::vector<double>* a) {
  const long offsets[4] = {1, -1, width, -width};
  double residual = 0.0;
  for (size_t c = 0; c < s.cells.size(); ++c) {
    const size_t k = s.cells[c];
    double sum = 0.0;
    for (int d = 0; d < 4; ++d) {
      const double wt = s.weight[4 * c + d];
      const double coef =
          wt > 0.0 ? wt * std::exp(l[static_cast<size_t>(static_cast<long>(k) + offsets[d])] - l[k])
                   : 0.0;
      if (a) (*a)[4 * c + d] = coef;
      sum += coef;
    }
    residual = std::max(residual, std::abs(sum - 1.0));
  }
  return residual;
}

}  // namespace wheelchair_harmonic_planner
