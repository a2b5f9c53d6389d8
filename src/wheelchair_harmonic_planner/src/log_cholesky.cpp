#include "log_cholesky.h"

#include "large_blocks.h"
#include "ordering_update.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>

namespace wheelchair_harmonic_planner {

namespace {

/// Process CPU time [s] (the phases' profile).
double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

constexpr double kNegInf = -std::numeric_limits<double>::infinity();
/// Block exponent of the solves' scaled numbers: value = m * 2^(kChunk * b).
constexpr int kChunk = 256;
constexpr double kTwoChunk = 0x1p256;
constexpr double kTwoMinusChunk = 0x1p-256;
/// 2^(-kChunk * d) for a block-exponent gap d = 0..3; a term 4 or more blocks (>= 2^-768) below
/// the running sum is below double's resolution of it (|L_ij| <= 1) and is dropped.
constexpr double kDown[5] = {1.0, 0x1p-256, 0x1p-512, 0x1p-768, 0.0};

double down(long gap) { return kDown[gap < 4 ? gap : 4]; }

/// Brings m into [1, 2^kChunk) by whole blocks (m > 0).
void normalize(ScaledValue& v) {
  while (v.m >= kTwoChunk) {
    v.m *= kTwoMinusChunk;
    ++v.b;
  }
  while (v.m < 1.0) {
    v.m *= kTwoChunk;
    --v.b;
  }
}

/// acc += c * 2^(kChunk * b) (c >= 0), the sum kept at the larger block exponent.
void accumulate(double c, long b, ScaledValue& acc) {
  if (b <= acc.b) {
    acc.m += c * down(acc.b - b);
  } else {
    acc.m = acc.m * down(b - acc.b) + c;
    acc.b = b;
  }
}

}  // namespace

LogLdlt::LogLdlt(const ConfigSpace& cs, bool use_conductance, const FactorOrdering* previous)
    : width_(cs.width()), use_conductance_(use_conductance) {
  double t0 = cpuSeconds();
  recycleLargeCholmodBlocks();
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
  // Column c of the lower triangle: the diagonal, then the east (c + 1) and north neighbours
  // (unknowns are numbered row by row, so both have larger numbers): rows already sorted.
  ap_.resize(n + 1);
  ai_.resize(3 * static_cast<size_t>(n));
  ax_.resize(3 * static_cast<size_t>(n));
  int nz = 0;
  for (int c = 0; c < n; ++c) {
    const size_t k = cells_[c];
    ap_[c] = nz;
    ai_[nz++] = c;
    for (const long offset : {1L, width_}) {
      const int nb = id_[static_cast<size_t>(static_cast<long>(k) + offset)];
      if (nb >= 0) ai_[nz++] = nb;
    }
  }
  ap_[n] = nz;
  for (int c = 0; c < n; ++c) assembleColumn(cs, c, &ax_[ap_[c]]);
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
  // AMD (METIS/NESDIS give more fill on these grids and cost more; a geometric nested
  // dissection too, and its fill joins distant cells: ordering_update.h), or the previous map's
  // ordering (AMD and postorder, so already postordered) if its free cells are the same, or
  // adapted to the new free cells if few changed.
  ordering_reused_ = previous && previous->free_mask == free &&
                     previous->permutation.size() == static_cast<size_t>(n);
  const auto lap = [&t0](double& phase) {
    const double t = cpuSeconds();
    phase = t - t0;
    t0 = t;
  };
  lap(timing_.assemble);
  LargeVector<int> derived;
  if (previous && !ordering_reused_) {
    derived = deriveOrdering(*previous, free, cells_, id_, width_, static_cast<size_t>(n) / 200,
                             static_cast<size_t>(n) / 10);
  }
  ordering_derived_ = !derived.empty();
  if (ordering_derived_) base_ordering_ = std::make_shared<const FactorOrdering>(*previous);
  common_.nmethods = 1;
  common_.method[0].ordering = ordering_reused_ || ordering_derived_ ? CHOLMOD_GIVEN : CHOLMOD_AMD;
  common_.postorder = ordering_reused_ ? 0 : 1;
  common_.supernodal = CHOLMOD_SIMPLICIAL;
  common_.final_ll = 0;  // keep LDL^T
  int* given = ordering_reused_    ? const_cast<int*>(previous->permutation.data())
               : ordering_derived_ ? derived.data()
                                   : nullptr;
  factor_ =
      given ? cholmod_analyze_p(&a, given, nullptr, 0, &common_) : cholmod_analyze(&a, &common_);
  lap(timing_.analyze);
  if (!factor_ || common_.status != CHOLMOD_OK) return;
  cholmod_factorize(&a, factor_, &common_);
  lap(timing_.factorize);
  if (common_.status != CHOLMOD_OK || factor_->minor != static_cast<size_t>(n)) return;
  const int* lp = static_cast<const int*>(factor_->p);
  const double* lx = static_cast<const double*>(factor_->x);
  const int* perm = static_cast<const int*>(factor_->Perm);
  inverse_perm_.resize(n);
  ok_ = true;
  for (int j = 0; j < n; ++j) {
    ok_ = ok_ && lx[lp[j]] > 0.0;  // D > 0
    inverse_perm_[perm[j]] = j;
  }
}

void LogLdlt::assembleColumn(const ConfigSpace& cs, int c, double* values) const {
  const size_t k = cells_[c];
  const auto& free = cs.freeMask();
  const auto sigma = [&](size_t cell) {
    return use_conductance_
               ? cs.conductance(static_cast<int>(cell % width_), static_cast<int>(cell / width_))
               : 1.0;
  };
  const long offsets[4] = {1, width_, -1, -width_};
  int out = 1;
  if (!free[k]) {  // blocked since the factorization: u = 0 there, decoupled from its neighbours
    values[0] = 1.0;
    for (int d = 0; d < 2; ++d)
      if (id_[static_cast<size_t>(static_cast<long>(k) + offsets[d])] >= 0) values[out++] = 0.0;
    return;
  }
  double total = 0.0;
  for (int d = 0; d < 4; ++d) {
    const size_t nb = static_cast<size_t>(static_cast<long>(k) + offsets[d]);
    const bool neighbour_free = free[nb] != 0;
    const double edge = 0.5 * (sigma(k) + (neighbour_free ? sigma(nb) : sigma(k)));
    total += edge;
    if (d < 2 && id_[nb] >= 0) values[out++] = neighbour_free ? -edge : 0.0;
  }
  values[0] = total;
}

double LogLdlt::entry(int a, int b) const {
  const int lo = std::min(a, b), hi = std::max(a, b);
  for (int p = ap_[lo] + 1; p < ap_[lo + 1]; ++p)
    if (ai_[p] == hi) return ax_[p];
  return 0.0;
}

bool LogLdlt::update(const ConfigSpace& cs, const std::vector<size_t>& changed) {
  updated_columns_ = 0;
  if (!ok_ || cs.width() != width_ || cs.freeMask().size() != id_.size()) return false;
  const auto& free = cs.freeMask();
  for (const size_t k : changed)
    if (free[k] && id_[k] < 0) return false;  // newly free: not in the factor's pattern
  const long n = static_cast<long>(cells_.size());
  const int* lp = static_cast<const int*>(factor_->p);
  const int* li = static_cast<const int*>(factor_->i);
  const int* lnz = static_cast<const int*>(factor_->nz);
  if (parent_.empty()) {
    column_.assign(n, 0.0);
    mark_.assign(n, -1);
    parent_.resize(n);
    for (long j = 0; j < n; ++j) parent_[j] = lnz[j] > 1 ? li[lp[j] + 1] : -1;  // rows sorted
  }
  // The columns of A whose values change: the changed cells' and their neighbours'.
  std::vector<int> touched;
  for (const size_t k : changed) {
    for (const long offset : {0L, 1L, -1L, width_, -width_}) {
      const int u = id_[static_cast<size_t>(static_cast<long>(k) + offset)];
      if (u >= 0) touched.push_back(u);
    }
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  std::vector<long> rows;  // factor positions of the unknowns whose row of A changed
  double values[3];
  for (const int c : touched) {
    const int count = ap_[c + 1] - ap_[c];
    assembleColumn(cs, c, values);
    for (int q = 0; q < count; ++q) {
      double& a = ax_[ap_[c] + q];
      if (a == values[q]) continue;
      a = values[q];
      rows.push_back(inverse_perm_[c]);
      if (q > 0) rows.push_back(inverse_perm_[ai_[ap_[c] + q]]);
    }
  }
  // The factor columns that depend on them: their ancestors in the elimination tree.
  std::vector<long> columns;
  for (long j : rows) {
    for (; j >= 0 && mark_[j] != -2; j = parent_[j]) {
      mark_[j] = -2;
      columns.push_back(j);
    }
  }
  for (const long j : columns) mark_[j] = -1;
  std::sort(columns.begin(), columns.end());
  for (const long j : columns) {
    if (!refactorColumn(j)) {
      ok_ = false;
      return false;
    }
  }
  updated_columns_ = columns.size();
  return true;
}

bool LogLdlt::refactorColumn(long j) {
  const int* perm = static_cast<const int*>(factor_->Perm);
  const int* lp = static_cast<const int*>(factor_->p);
  const int* li = static_cast<const int*>(factor_->i);
  const int* lnz = static_cast<const int*>(factor_->nz);
  double* lx = static_cast<double*>(factor_->x);
  const int u = perm[j];
  const size_t k = cells_[u];
  // Column j of P A P^T from row j down, and the pattern of row j of L: the elimination-tree
  // paths from the rows above j of that column up to j.
  column_[j] = ax_[ap_[u]];
  row_.clear();
  for (const long offset : {1L, -1L, width_, -width_}) {
    const int v = id_[static_cast<size_t>(static_cast<long>(k) + offset)];
    if (v < 0) continue;
    long p = inverse_perm_[v];
    if (p > j) {
      column_[p] = entry(u, v);
      continue;
    }
    for (; p >= 0 && p < j && mark_[p] != j; p = parent_[p]) {
      mark_[p] = static_cast<int>(j);
      row_.push_back(p);
    }
  }
  // Left-looking: subtract L_.d D_d L_jd, from row j down, for every column d of row j.
  bool found = true;
  for (const long d : row_) {
    mark_[d] = -1;
    const int* begin = li + lp[d] + 1;
    const int* end = li + lp[d] + lnz[d];
    const int* at = std::lower_bound(begin, end, static_cast<int>(j));
    if (at == end || *at != j) {
      found = false;  // not in the symbolic pattern: not expected
      continue;
    }
    const long q = at - li;
    const double f = lx[q] * lx[lp[d]];
    for (long r = q; r < lp[d] + lnz[d]; ++r) column_[li[r]] -= lx[r] * f;  // from row j: D_j too
  }
  const double dj = column_[j];
  column_[j] = 0.0;
  lx[lp[j]] = dj;
  for (long r = lp[j] + 1; r < lp[j] + lnz[j]; ++r) {
    lx[r] = column_[li[r]] / dj;
    column_[li[r]] = 0.0;
  }
  return found && dj > 0.0;
}

LogLdlt::~LogLdlt() {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

std::shared_ptr<const FactorOrdering> LogLdlt::ordering(const ConfigSpace& cs) const {
  if (!ok_) return nullptr;
  if (ordering_derived_) return base_ordering_;
  auto o = std::make_shared<FactorOrdering>();
  o->free_mask = cs.freeMask();
  const int* perm = static_cast<const int*>(factor_->Perm);
  o->permutation.assign(perm, perm + factor_->n);
  return o;
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
  const long n = static_cast<long>(cells_.size());
  // Factor of P A P^T (row k of it is row perm[k] of A). L y = P e_g, z = y / D, L^T x' = z,
  // w[perm[k]] = x'[k]. Column j of the factor: its diagonal entry (D_j) first, then L_.j.
  // Every value is a ScaledValue m * 2^(256 b): the sums only add non-negative terms, so this
  // is exact to double's relative precision at any magnitude, with no exp or log per term.
  const int* perm = static_cast<const int*>(factor_->Perm);
  const int* lp = static_cast<const int*>(factor_->p);
  const int* li = static_cast<const int*>(factor_->i);
  const int* lnz = static_cast<const int*>(factor_->nz);
  const double* lx = static_cast<const double*>(factor_->x);
  x_.assign(n, ScaledValue{});
  const long first = inverse_perm_[id_[goal]];
  x_[first].m = 1.0;
  x_[first].b = 0;
  // Forward, column-oriented: once y_k is final it is scattered into the rows below; only the
  // elimination-tree ancestors of the goal become non-zero. x_ holds y, then z = y / D.
  for (long k = first; k < n; ++k) {
    ScaledValue& y = x_[k];
    if (y.m == 0.0) continue;
    normalize(y);
    for (int p = lp[k] + 1; p < lp[k] + lnz[k]; ++p) {
      if (lx[p] < 0.0) accumulate(-lx[p] * y.m, y.b, x_[li[p]]);
    }
    y.m /= lx[lp[k]];
    normalize(y);
  }
  // Backward: x_k = z_k + sum_i (-L_ik) x_i over column k (rows i > k, already final).
  for (long k = n - 1; k >= 0; --k) {
    ScaledValue acc = x_[k];
    for (int p = lp[k] + 1; p < lp[k] + lnz[k]; ++p) {
      const ScaledValue& xi = x_[li[p]];
      if (xi.m != 0.0 && lx[p] < 0.0) accumulate(-lx[p] * xi.m, xi.b, acc);
    }
    if (acc.m != 0.0) normalize(acc);
    x_[k] = acc;
  }
  // u = w / w_g, in the grid's cell order for the residual, and its log for the descent.
  const ScaledValue wg = x_[first];
  for (long k = 0; k < n; ++k) {
    ScaledValue& xk = x_[k];
    if (xk.m == 0.0) continue;
    xk.m /= wg.m;
    xk.b -= wg.b;
    normalize(xk);
    log_u[cells_[perm[k]]] = std::log(xk.m) + kChunk * M_LN2 * static_cast<double>(xk.b);
  }
  log_u[goal] = 0.0;
  return residual(goal);
}

double LogLdlt::residual(size_t goal) const {
  // sum_j w_kj u_j / (total_k u_k) per unknown k, from the lower triangle of A (each edge once,
  // added to both of its rows); 0 for edges to obstacles (u = 0). Evaluated on the scaled
  // values: the log taken above changes log u by < 1e-15 relative.
  const auto u = [this](int c) -> const ScaledValue& { return x_[inverse_perm_[c]]; };
  LargeVector<double>& sum = sum_;
  sum.assign(cells_.size(), 0.0);
  const int n = static_cast<int>(cells_.size());
  for (int c = 0; c < n; ++c) {
    const ScaledValue& uc = u(c);
    if (uc.m == 0.0) continue;
    const double total_c = ax_[ap_[c]];  // the diagonal comes first
    for (int p = ap_[c] + 1; p < ap_[c + 1]; ++p) {
      if (ax_[p] == 0.0) continue;  // an edge to a cell blocked since the factorization
      const int r = ai_[p];
      // u_r / u_c: between edge / total and total / edge (maximum principle), no overflow.
      const ScaledValue& ur = u(r);
      const long gap = ur.b - uc.b;
      const double q = ur.m / uc.m;
      const double ratio = gap == 0 ? q : std::ldexp(q, kChunk * static_cast<int>(gap));
      sum[c] -= ax_[p] / total_c * ratio;
      sum[r] -= ax_[p] / ax_[ap_[r]] / ratio;
    }
  }
  double worst = 0.0;
  for (int c = 0; c < n; ++c) {
    if (cells_[c] != goal && u(c).m != 0.0) worst = std::max(worst, std::abs(sum[c] - 1.0));
  }
  return worst;
}

}  // namespace wheelchair_harmonic_planner
