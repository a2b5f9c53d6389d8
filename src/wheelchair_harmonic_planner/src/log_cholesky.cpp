#include "log_cholesky.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wheelchair_harmonic_planner {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();
/// A term e^-40 below a row's accumulated sum is below double's resolution of it: skipped.
constexpr double kNegligible = -40.0;
/// Re-scale a row's accumulator when a term exceeds it by this much (e^300 < DBL_MAX).
constexpr double kRescale = 300.0;

/// Adds c * exp(x) (c > 0) to the row accumulator mantissa * exp(scale), which keeps
/// mantissa >= 1 so that a term below e^kNegligible of it is negligible (c <= 1 below).
void accumulate(double c, double x, double& scale, double& mantissa) {
  const double e = x - scale;
  if (mantissa == 0.0 || e > kRescale) {
    const double top = mantissa == 0.0 ? x + std::log(c) : std::max(scale, x + std::log(c));
    mantissa = (mantissa == 0.0 ? 0.0 : mantissa * std::exp(scale - top)) + c * std::exp(x - top);
    scale = top;
  } else if (e > kNegligible) {
    mantissa += c * std::exp(e);
  }
}

}  // namespace

LogLdlt::LogLdlt(const ConfigSpace& cs, bool use_conductance) : width_(cs.width()) {
  cholmod_start(&common_);
  const auto& free = cs.freeMask();
  id_.assign(free.size(), -1);
  for (size_t k = 0; k < free.size(); ++k) {
    if (!free[k]) continue;
    id_[k] = static_cast<int>(cells_.size());
    cells_.push_back(k);
  }
  const int n = static_cast<int>(cells_.size());
  if (n == 0) return;
  auto sigma = [&](size_t k) {
    return use_conductance
               ? cs.conductance(static_cast<int>(k % width_), static_cast<int>(k / width_))
               : 1.0;
  };
  // Column c of the lower triangle: the diagonal, then the east (c + 1) and north neighbours
  // (unknowns are numbered row by row, so both have larger numbers): rows already sorted.
  ap_.resize(n + 1);
  ai_.resize(3 * static_cast<size_t>(n));
  ax_.resize(3 * static_cast<size_t>(n));
  int nz = 0;
  const long offsets[4] = {1, width_, -1, -width_};
  for (int c = 0; c < n; ++c) {
    const size_t k = cells_[c];
    ap_[c] = nz;
    const int diag = nz++;
    double total = 0.0;
    for (int d = 0; d < 4; ++d) {
      const size_t nb = static_cast<size_t>(static_cast<long>(k) + offsets[d]);
      const bool neighbour_free = id_[nb] >= 0;
      const double edge = 0.5 * (sigma(k) + (neighbour_free ? sigma(nb) : sigma(k)));
      total += edge;
      if (neighbour_free && d < 2) {
        ai_[nz] = id_[nb];
        ax_[nz++] = -edge;
      }
    }
    ai_[diag] = c;
    ax_[diag] = total;
  }
  ap_[n] = nz;
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<size_t>(n);
  a.nzmax = static_cast<size_t>(nz);
  a.p = ap_.data();
  a.i = ai_.data();
  a.x = ax_.data();
  a.stype = -1;  // symmetric, lower triangle stored
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  common_.nmethods = 1;  // AMD only (METIS/NESDIS give more fill on these grids and cost more)
  common_.method[0].ordering = CHOLMOD_AMD;
  common_.postorder = 1;
  common_.supernodal = CHOLMOD_SIMPLICIAL;
  common_.final_ll = 0;  // keep LDL^T
  factor_ = cholmod_analyze(&a, &common_);
  if (!factor_ || common_.status != CHOLMOD_OK) return;
  cholmod_factorize(&a, factor_, &common_);
  if (common_.status != CHOLMOD_OK || factor_->minor != static_cast<size_t>(n)) return;
  const int* lp = static_cast<const int*>(factor_->p);
  const double* lx = static_cast<const double*>(factor_->x);
  ok_ = true;
  for (int j = 0; j < n; ++j) ok_ = ok_ && lx[lp[j]] > 0.0;  // D > 0
}

LogLdlt::~LogLdlt() {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

size_t LogLdlt::factorNonZeros() const {
  if (!factor_) return 0;
  const int* lnz = static_cast<const int*>(factor_->nz);
  size_t total = 0;
  for (size_t j = 0; j < factor_->n; ++j) total += static_cast<size_t>(lnz[j]);
  return total;
}

double LogLdlt::solve(size_t goal, std::vector<double>& log_u) const {
  log_u.assign(id_.size(), kNegInf);
  if (id_[goal] < 0) return std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(cells_.size());
  // Factor of P A P^T (row k of it is row perm[k] of A). L y = P e_g, z = y / D, L^T x' = z,
  // w[perm[k]] = x'[k]. Column j of the factor: its diagonal entry (D_j) first, then L_.j.
  const int* perm = static_cast<const int*>(factor_->Perm);
  const int* lp = static_cast<const int*>(factor_->p);
  const int* li = static_cast<const int*>(factor_->i);
  const int* lnz = static_cast<const int*>(factor_->nz);
  const double* lx = static_cast<const double*>(factor_->x);
  x_.assign(n, kNegInf);
  scale_.assign(n, kNegInf);
  mantissa_.assign(n, 0.0);
  int first = 0;
  while (perm[first] != id_[goal]) ++first;
  scale_[first] = 0.0;
  mantissa_[first] = 1.0;
  // Forward, column-oriented: once y_k is final it is scattered into the rows below (one exp
  // per non-zero); only the elimination-tree ancestors of the goal become non-zero.
  for (int k = first; k < n; ++k) {
    if (mantissa_[k] == 0.0) continue;
    const double y = scale_[k] + std::log(mantissa_[k]);
    x_[k] = y - std::log(lx[lp[k]]);  // z = y / D
    for (int p = lp[k] + 1; p < lp[k] + lnz[k]; ++p) {
      if (lx[p] < 0.0) accumulate(-lx[p], y, scale_[li[p]], mantissa_[li[p]]);
    }
  }
  // Backward: x_k = log(z_k + sum_i (-L_ik) x_i) over column k in one pass, the sum kept
  // relative to the largest exponent seen so far (re-scaled when a larger one comes); terms
  // e^-40 below it are negligible (|L_ik| <= 1) and skip their exp.
  for (int k = n - 1; k >= 0; --k) {
    double top = x_[k];
    double sum = top == kNegInf ? 0.0 : 1.0;
    for (int p = lp[k] + 1; p < lp[k] + lnz[k]; ++p) {
      const double xi = x_[li[p]];
      if (xi == kNegInf || !(lx[p] < 0.0)) continue;
      if (xi > top) {
        sum = (sum == 0.0 ? 0.0 : sum * std::exp(top - xi)) - lx[p];
        top = xi;
      } else if (xi - top > kNegligible) {
        sum -= lx[p] * std::exp(xi - top);
      }
    }
    if (sum > 0.0) x_[k] = top + std::log(sum);
  }
  const double log_wg = x_[first];
  for (int k = 0; k < n; ++k) {
    if (x_[k] != kNegInf) log_u[cells_[perm[k]]] = x_[k] - log_wg;
  }
  log_u[goal] = 0.0;
  return residual(log_u, goal);
}
double LogLdlt::residual(const std::vector<double>& log_u, size_t goal) const {
  // sum_j w_kj exp(l_j - l_k) / total_k per unknown k, from the lower triangle of A (each edge
  // once, added to both of its rows); 0 for edges to obstacles (u = 0).
  std::vector<double>& sum = scale_;
  sum.assign(cells_.size(), 0.0);
  const int n = static_cast<int>(cells_.size());
  for (int c = 0; c < n; ++c) {
    const double lc = log_u[cells_[c]];
    if (lc == kNegInf) continue;
    const double total_c = ax_[ap_[c]];  // the diagonal comes first
    for (int p = ap_[c] + 1; p < ap_[c + 1]; ++p) {
      const int r = ai_[p];
      const double lr = log_u[cells_[r]];
      // u_r / u_c: between edge / total and total / edge (maximum principle), no overflow.
      const double ratio = std::exp(lr - lc);
      sum[c] -= ax_[p] / total_c * ratio;
      sum[r] -= ax_[p] / ax_[ap_[r]] / ratio;
    }
  }
  double worst = 0.0;
  for (int c = 0; c < n; ++c) {
    if (cells_[c] != goal && log_u[cells_[c]] != kNegInf) {
      worst = std::max(worst, std::abs(sum[c] - 1.0));
    }
  }
  return worst;
}

}  // namespace wheelchair_harmonic_planner
