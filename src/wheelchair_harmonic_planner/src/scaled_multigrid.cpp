#include <wheelchair_harmonic_planner/scaled_multigrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wheelchair_harmonic_planner {

namespace {

size_t coarseIndex(int x, int y, int coarse_width) {
  return static_cast<size_t>((y + 1) / 2) * coarse_width + (x + 1) / 2;
}

}  // namespace

ScaledMultigrid::ScaledMultigrid(int width, int height, std::vector<uint8_t> unknown,
                                 std::vector<double> weight, size_t goal,
                                 const MultigridParams& params)
    : params_(params), goal_(goal) {
  const size_t n = static_cast<size_t>(width) * height;
  if (width < 3 || height < 3 || unknown.size() != n || weight.size() != 4 * n || goal >= n) {
    throw std::invalid_argument("ScaledMultigrid: grid, weights and goal do not match");
  }
  Level fine;
  fine.w = width;
  fine.h = height;
  fine.unknown = std::move(unknown);
  for (auto* a : {&fine.sE, &fine.sW, &fine.sN, &fine.sS, &fine.diag}) a->assign(n, 0.0);
  for (size_t k = 0; k < n; ++k) {
    if (!fine.unknown[k]) continue;
    fine.diag[k] = 1.0;
    const size_t nb[4] = {k + 1, k - 1, k + width, k - width};
    double* s[4] = {&fine.sE[k], &fine.sW[k], &fine.sN[k], &fine.sS[k]};
    for (int d = 0; d < 4; ++d) {
      // Couplings to the goal (v = 1 there) become the right-hand side.
      if (nb[d] == goal) to_goal_.push_back({k, weight[4 * k + d]});
      *s[d] = fine.unknown[nb[d]] ? weight[4 * k + d] : 0.0;
    }
  }
  levels_.push_back(std::move(fine));
  while (true) {
    Level& f = levels_.back();
    const long count = std::count(f.unknown.begin(), f.unknown.end(), uint8_t{1});
    if (count <= params_.coarsest_unknowns || f.w < 6 || f.h < 6) break;
    Level c = aggregate(f);
    levels_.push_back(std::move(c));
  }
  for (Level& lv : levels_) {
    const size_t m = static_cast<size_t>(lv.w) * lv.h;
    for (auto* a : {&lv.cE, &lv.cW, &lv.cN, &lv.cS, &lv.l, &lv.t, &lv.v, &lv.f, &lv.r}) {
      a->assign(m, 0.0);
    }
  }
}

ScaledMultigrid::Level ScaledMultigrid::aggregate(Level& f) {
  Level c;
  c.w = (f.w - 1) / 2 + 2;  // fine x -> coarse (x + 1) / 2 keeps the outer ring empty
  c.h = (f.h - 1) / 2 + 2;
  const size_t m = static_cast<size_t>(c.w) * c.h;
  c.unknown.assign(m, 0);
  for (auto* a : {&c.sE, &c.sW, &c.sN, &c.sS, &c.diag}) a->assign(m, 0.0);
  f.agg.assign(f.unknown.size(), 0);
  const long w = f.w;
  for (int cy = 1; cy < c.h - 1; ++cy) {
    for (int cx = 1; cx < c.w - 1; ++cx) {
      // Children 0 = (2X-1, 2Y-1), 1 = its east, 2 = its north, 3 = north-east. Only the largest
      // set of them connected inside the block is aggregated; the others get no coarse
      // correction (the smoother handles them).
      size_t child[4];
      int comp[4];
      for (int i = 0; i < 4; ++i) {
        const int x = 2 * cx - 1 + (i & 1), y = 2 * cy - 1 + (i >> 1);
        const bool inside = x < f.w - 1 && y < f.h - 1;
        child[i] = inside ? static_cast<size_t>(y) * w + x : 0;
        comp[i] = inside && f.unknown[child[i]] ? i : -1;
      }
      const int links[4][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}};
      for (int pass = 0; pass < 2; ++pass) {
        for (const auto& e : links) {
          const int a = e[0], b = e[1];
          if (comp[a] < 0 || comp[b] < 0) continue;
          const bool linked = (b == a + 1 ? f.sE[child[a]] : f.sN[child[a]]) > 0.0;
          if (linked) comp[a] = comp[b] = std::min(comp[a], comp[b]);
        }
      }
      int best = -1, best_size = 0;
      for (int i = 0; i < 4; ++i) {
        const int size = static_cast<int>(std::count(comp, comp + 4, i));
        if (size > best_size) best = i, best_size = size;
      }
      if (best < 0) continue;
      c.unknown[static_cast<size_t>(cy) * c.w + cx] = 1;
      for (int i = 0; i < 4; ++i)
        if (comp[i] == best) f.agg[child[i]] = 1;
    }
  }
  // Galerkin R A P with P piecewise constant over the aggregates and R = P^T: couplings that
  // cross a block edge become coarse couplings, those inside a block cancel against the
  // diagonal, those to cells without coarse correction drop out.
  for (int y = 1; y < f.h - 1; ++y) {
    for (int x = 1; x < f.w - 1; ++x) {
      const size_t k = static_cast<size_t>(y) * w + x;
      if (!f.agg[k]) continue;
      const size_t kc = coarseIndex(x, y, c.w);
      const bool right = (x & 1) == 0, top = (y & 1) == 0;  // position inside the block
      const double e = f.agg[k + 1] ? f.sE[k] : 0.0, wv = f.agg[k - 1] ? f.sW[k] : 0.0;
      const double nv = f.agg[k + w] ? f.sN[k] : 0.0, sv = f.agg[k - w] ? f.sS[k] : 0.0;
      c.diag[kc] += f.diag[k];
      (right ? c.sE[kc] : c.diag[kc]) += right ? e : -e;
      (right ? c.diag[kc] : c.sW[kc]) += right ? -wv : wv;
      (top ? c.sN[kc] : c.diag[kc]) += top ? nv : -nv;
      (top ? c.diag[kc] : c.sS[kc]) += top ? -sv : sv;
    }
  }
  return c;
}

void ScaledMultigrid::scaleLevel(Level& lv) const {
  // The coefficient of each edge and of its reverse share one exponential.
  const long w = lv.w;
  for (size_t k = static_cast<size_t>(w); k + w < lv.unknown.size(); ++k) {
    if (!lv.unknown[k]) continue;
    if (lv.sE[k] > 0.0 || lv.sW[k + 1] > 0.0) {
      const double e = std::exp(lv.l[k + 1] - lv.l[k]);
      lv.cE[k] = lv.sE[k] * e;
      lv.cW[k + 1] = lv.sW[k + 1] / e;
    }
    if (lv.sN[k] > 0.0 || lv.sS[k + w] > 0.0) {
      const double e = std::exp(lv.l[k + w] - lv.l[k]);
      lv.cN[k] = lv.sN[k] * e;
      lv.cS[k + w] = lv.sS[k + w] / e;
    }
  }
}

double ScaledMultigrid::rescale(const std::vector<double>& log_u) {
  Level& fine = levels_.front();
  const size_t n = fine.unknown.size();
  for (size_t k = 0; k < n; ++k) {
    fine.l[k] = fine.unknown[k] || k == goal_ ? log_u[k] : 0.0;
    fine.v[k] = fine.unknown[k] ? 1.0 : 0.0;
    fine.f[k] = 0.0;
    fine.cE[k] = fine.cW[k] = fine.cN[k] = fine.cS[k] = 0.0;
  }
  scaleLevel(fine);
  for (const auto& [k, wt] : to_goal_) fine.f[k] = wt * std::exp(fine.l[goal_] - fine.l[k]);
  double res = 0.0;
  for (size_t k = 0; k < n; ++k) {
    if (!fine.unknown[k]) continue;
    const double sum = fine.cE[k] + fine.cW[k] + fine.cN[k] + fine.cS[k] + fine.f[k];
    res = std::max(res, std::abs(sum - 1.0));
  }
  // Coarse scaling: log of the mean of exp(l) over each aggregate (its u-space average).
  for (size_t li = 1; li < levels_.size(); ++li) {
    Level& f = levels_[li - 1];
    Level& c = levels_[li];
    std::fill(c.l.begin(), c.l.end(), -std::numeric_limits<double>::infinity());
    for (int y = 1; y < f.h - 1; ++y)
      for (int x = 1; x < f.w - 1; ++x) {
        const size_t k = static_cast<size_t>(y) * f.w + x;
        if (f.agg[k]) c.l[coarseIndex(x, y, c.w)] = std::max(c.l[coarseIndex(x, y, c.w)], f.l[k]);
      }
    std::vector<double> sum(c.l.size(), 0.0), count(c.l.size(), 0.0);
    for (int y = 1; y < f.h - 1; ++y)
      for (int x = 1; x < f.w - 1; ++x) {
        const size_t k = static_cast<size_t>(y) * f.w + x;
        if (!f.agg[k]) continue;
        const size_t kc = coarseIndex(x, y, c.w);
        f.t[k] = std::exp(f.l[k] - c.l[kc]);
        sum[kc] += f.t[k];
        count[kc] += 1.0;
      }
    for (size_t kc = 0; kc < c.l.size(); ++kc) {
      if (!c.unknown[kc]) {
        c.l[kc] = 0.0;
        continue;
      }
      const double shift = std::log(sum[kc] / count[kc]);
      c.l[kc] += shift;
      sum[kc] = std::exp(-shift);
    }
    for (int y = 1; y < f.h - 1; ++y)
      for (int x = 1; x < f.w - 1; ++x) {
        const size_t k = static_cast<size_t>(y) * f.w + x;
        if (f.agg[k]) f.t[k] *= sum[coarseIndex(x, y, c.w)];
      }
    scaleLevel(c);
  }
  return res;
}

void ScaledMultigrid::smooth(Level& lv, int sweeps) const {
  const long w = lv.w;
  for (int s = 0; s < sweeps; ++s) {
    for (int color = 0; color < 2; ++color) {
      for (int y = 1; y < lv.h - 1; ++y) {
        const size_t row = static_cast<size_t>(y) * w;
        for (int x = 1 + ((y + 1 + color) & 1); x < lv.w - 1; x += 2) {
          const size_t k = row + x;
          if (!lv.unknown[k]) continue;
          lv.v[k] = (lv.f[k] + lv.cE[k] * lv.v[k + 1] + lv.cW[k] * lv.v[k - 1] +
                     lv.cN[k] * lv.v[k + w] + lv.cS[k] * lv.v[k - w]) /
                    lv.diag[k];
        }
      }
    }
  }
}

void ScaledMultigrid::residual(Level& lv) const {
  const long w = lv.w;
  const size_t n = lv.unknown.size();
  for (size_t k = static_cast<size_t>(w); k + w < n; ++k) {
    lv.r[k] = lv.unknown[k]
                  ? lv.f[k] + lv.cE[k] * lv.v[k + 1] + lv.cW[k] * lv.v[k - 1] +
                        lv.cN[k] * lv.v[k + w] + lv.cS[k] * lv.v[k - w] - lv.diag[k] * lv.v[k]
                  : 0.0;
  }
}

void ScaledMultigrid::cycle(size_t li) {
  Level& f = levels_[li];
  if (li + 1 == levels_.size()) {
    smooth(f, params_.coarsest_sweeps);
    return;
  }
  smooth(f, params_.pre_smooth);
  residual(f);
  Level& c = levels_[li + 1];
  // Restriction and prolongation in the scaled variables: R = D_c^-1 P^T D, P = D^-1 P D_c
  // with D = exp(l), i.e. piecewise constant in u.
  std::fill(c.f.begin(), c.f.end(), 0.0);
  std::fill(c.v.begin(), c.v.end(), 0.0);
  for (int y = 1; y < f.h - 1; ++y)
    for (int x = 1; x < f.w - 1; ++x) {
      const size_t k = static_cast<size_t>(y) * f.w + x;
      if (f.agg[k]) c.f[coarseIndex(x, y, c.w)] += f.t[k] * f.r[k];
    }
  for (int g = 0; g < std::max(1, params_.cycle_index); ++g) cycle(li + 1);
  const double scale = params_.correction_scale;
  for (int y = 1; y < f.h - 1; ++y)
    for (int x = 1; x < f.w - 1; ++x) {
      const size_t k = static_cast<size_t>(y) * f.w + x;
      if (f.agg[k]) f.v[k] += scale * c.v[coarseIndex(x, y, c.w)] / f.t[k];
    }
  smooth(f, params_.post_smooth);
}

void ScaledMultigrid::vcycle() { cycle(0); }

double ScaledMultigrid::correct(std::vector<double>& log_u) const {
  const Level& fine = levels_.front();
  double change = 0.0;
  for (size_t k = 0; k < fine.unknown.size(); ++k) {
    if (!fine.unknown[k]) continue;
    // Far from the solution a cycle can overshoot (v <= 0 or huge): the step in log u is
    // bounded and the next rescaled cycle continues from there.
    const double dl = std::clamp(std::log(std::max(fine.v[k], 1e-30)), -params_.max_log_step,
                                 params_.max_log_step);
    log_u[k] += dl;
    change = std::max(change, std::abs(dl));
  }
  return change;
}

}  // namespace wheelchair_harmonic_planner
