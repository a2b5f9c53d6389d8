#include "log_cholesky.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace wheelchair_harmonic_planner {

namespace {

using SparseCol = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
constexpr double kNegInf = -std::numeric_limits<double>::infinity();
/// A term e^-40 below a row's accumulated sum is below double's resolution of it: skipped.
constexpr double kNegligible = -40.0;
/// Re-scale a row's accumulator when a term exceeds it by this much (e^300 < DBL_MAX).
constexpr double kRescale = 300.0;

/// The system's lower triangle: A_kk = total conductance, A_kj = -edge (k, j unknowns); log b_k
/// = log of the edge to the goal (u_goal = 1), -inf if none.
SparseCol assemble(const Stencil& s, long width, size_t goal, size_t cells_total,
                   std::vector<double>& log_b) {
  const int n = static_cast<int>(s.cells.size());
  std::vector<int> id(cells_total, -1);
  for (int c = 0; c < n; ++c) id[s.cells[c]] = c;
  const long offsets[4] = {1, -1, width, -width};
  SparseCol a(n, n);
  a.reserve(Eigen::VectorXi::Constant(n, 3));
  log_b.assign(n, kNegInf);
  for (int c = 0; c < n; ++c) {
    a.insert(c, c) = s.total[c];
    for (int d = 0; d < 4; ++d) {
      const double edge = s.weight[4 * c + d] * s.total[c];
      const size_t nb = static_cast<size_t>(static_cast<long>(s.cells[c]) + offsets[d]);
      if (edge <= 0.0) continue;
      if (nb == goal) {
        log_b[c] = std::log(edge);
      } else if (id[nb] > c) {
        a.insert(id[nb], c) = -edge;  // column c, row below the diagonal
      }
    }
  }
  a.makeCompressed();
  return a;
}

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

/// L y = b with unit lower L (column-major, L_ik <= 0), in place on x = log y. Column-oriented:
/// once y_k is final it is scattered into the rows below (one exp per non-zero). |L_ik| <= 1
/// since every Schur complement of a diagonally dominant M-matrix is one.
void forwardLog(const SparseCol& lower, std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  std::vector<double> scale(x), mantissa(n);
  for (int k = 0; k < n; ++k) mantissa[k] = x[k] == kNegInf ? 0.0 : 1.0;
  for (int k = 0; k < n; ++k) {
    x[k] = mantissa[k] > 0.0 ? scale[k] + std::log(mantissa[k]) : kNegInf;
    if (x[k] == kNegInf) continue;
    for (SparseCol::InnerIterator it(lower, k); it; ++it) {
      if (it.value() < 0.0) accumulate(-it.value(), x[k], scale[it.row()], mantissa[it.row()]);
    }
  }
}

/// L^T x = z (log z given in x), in place, backwards: x_k = log(z_k + sum_i (-L_ik) x_i) over
/// column k, scaled by the largest exponent (terms below e^-745 of it underflow to 0).
void backwardLog(const SparseCol& lower, std::vector<double>& x) {
  for (int k = static_cast<int>(x.size()) - 1; k >= 0; --k) {
    double top = x[k];
    for (SparseCol::InnerIterator it(lower, k); it; ++it) top = std::max(top, x[it.row()]);
    if (top == kNegInf) continue;
    double sum = std::exp(x[k] - top);
    for (SparseCol::InnerIterator it(lower, k); it; ++it) {
      if (it.value() < 0.0) sum -= it.value() * std::exp(x[it.row()] - top);
    }
    x[k] = top + std::log(sum);
  }
}

}  // namespace

bool solveLogCholesky(const Stencil& s, long width, size_t goal, std::vector<double>& log_u) {
  const int n = static_cast<int>(s.cells.size());
  if (n == 0) return true;
  std::vector<double> log_b;
  Eigen::SimplicialLDLT<SparseCol, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(
      assemble(s, width, goal, log_u.size(), log_b));
  if (ldlt.info() != Eigen::Success) return false;
  const auto& d = ldlt.vectorD();
  if (!(d.minCoeff() > 0.0)) return false;
  // Factor of P A P^T: x'[perm[i]] = x[i]. L y = P b, z = y / D, L^T x' = z, u = P^T x'.
  const auto& perm = ldlt.permutationP().indices();
  const SparseCol& lower = ldlt.matrixL().nestedExpression();  // strictly lower, unit diagonal
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[perm[i]] = log_b[i];
  forwardLog(lower, x);
  for (int k = 0; k < n; ++k) x[k] -= std::log(d[k]);
  backwardLog(lower, x);
  for (int c = 0; c < n; ++c) log_u[s.cells[c]] = x[perm[c]];
  return true;
}

}  // namespace wheelchair_harmonic_planner
