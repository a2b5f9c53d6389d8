// Direct solve of the harmonic boundary problem with the result in log space: internal header.
//
// Goal-independent formulation: A is the unnormalized, symmetric stencil of *every* free cell
// (A_kk = total conductance of cell k incl. its edges to obstacles, A_kj = -edge conductance),
// a symmetric, diagonally dominant M-matrix (a Stieltjes matrix) that depends on the map only.
// For a goal g, w = A^-1 e_g is harmonic at every free cell but g, 0 at obstacles, > 0 on g's
// connected component and exactly 0 elsewhere; so u = w / w_g is the solution of the paper's
// boundary problem (u = 1 at the goal). The LDL^T factors of A are computed once per map and a
// new goal costs two triangular solves. The factors (CHOLMOD's simplicial LDL^T with AMD
// ordering, ~2x faster here than Eigen's SimplicialLDLT, the same factors) have L_kj <= 0
// (|L_kj| <= 1) and D > 0, so both solves only ever add non-negative terms: no cancellation,
// every w_k to high *relative* accuracy however small. We run them on numbers with an extended
// exponent (ScaledValue: a double times 2^(256 b)), so u far below the smallest double (e^-5000
// down a long corridor) keeps full relative precision, and return log u, exactly like the
// iterative log-space solvers; no exp or log per factor non-zero (2.4x faster than a log-sum-exp
// per row), one log per cell at the end. AMD runs once per set of free cells: a later map with
// the same free cells reuses its ordering, one with few changed cells adapts it
// (ordering_update.h), which keeps the factor as local as AMD's.
//
// A map change that only blocks cells and changes conductances (the live obstacle layer over the
// map the factor was made for) keeps the factor's pattern: a blocked cell stays an unknown with
// the equation u = 1 * u (its row and column of A become the identity's), so only the factor
// columns that depend on a changed row of A change: the changed columns and their ancestors in
// the elimination tree. update() recomputes exactly those (left-looking, in CHOLMOD's storage):
// measured on maze1024 for a 1 m^2 obstacle, ~4500 of 554 k columns, 3.4 M multiply-adds (a
// few ms), where CHOLMOD's rank-1 update/downdate of the same change (cholmod_updown, ~2200
// rank-1 terms) took 416 ms, twice a whole numeric factorization (198 ms).
#pragma once

#include <wheelchair_harmonic_planner/harmonic_solver.h>

#include "large_blocks.h"

#include <cholmod.h>

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace wheelchair_harmonic_planner {

/// A non-negative number m * 2^(256 b) with m in [1, 2^256) once normalized (m = 0: zero): the
/// triangular solves' values, far below the smallest double, added without exp or log per term.
struct ScaledValue {
  double m = 0.0;
  long b = std::numeric_limits<long>::min() / 4;
};

class LogLdlt {
 public:
  /// Orders and factors A for every free cell of `cs` (conductance per cell, or 1 everywhere if
  /// !use_conductance). ok() is false if the factorization failed (not expected). `previous`:
  /// an earlier ordering, used instead of AMD if it was made for the same free cells, or
  /// adapted (ordering_update.h) if they differ in few: <= 0.5 % of the cells new, <= 10 %
  /// blocked.
  LogLdlt(const ConfigSpace& cs, bool use_conductance, const FactorOrdering* previous = nullptr);

  ~LogLdlt();
  LogLdlt(const LogLdlt&) = delete;
  LogLdlt& operator=(const LogLdlt&) = delete;

  bool ok() const { return ok_; }
  /// CPU time of the constructor's phases (incl. their page faults).
  const FactorTiming& timing() const { return timing_; }
  /// True if `previous` was used as is.
  bool orderingReused() const { return ordering_reused_; }
  /// True if the ordering was adapted from `previous` (other free cells).
  bool orderingDerived() const { return ordering_derived_; }
  /// The ordering for the next map: this factorization's or, if it was adapted from `previous`,
  /// a copy of `previous` (so that adaptations never accumulate: the next map is compared
  /// with the map of the last fresh AMD ordering).
  std::shared_ptr<const FactorOrdering> ordering(const ConfigSpace& cs) const;
  size_t unknowns() const { return cells_.size(); }
  /// Non-zeros of L including its diagonal (which holds D).
  size_t factorNonZeros() const;

  /// The factor of `cs`'s equation, `cs` being the C-space of the same grid after cells were
  /// blocked or had their conductance changed relative to the one the factor was made for (or
  /// the last update's): `changed` holds every cell whose free state or conductance changed
  /// since (ConfigSpaceChange::cells). Only the columns that depend on a changed row are
  /// recomputed. False, with the factor unchanged, if a cell is free now that was not free in
  /// the C-space of the constructor (its pattern cannot hold it: factor afresh); false with
  /// ok() false if the recomputed factor is not positive definite (not expected).
  bool update(const ConfigSpace& cs, const std::vector<size_t>& changed);
  /// Factor columns the last update() recomputed.
  size_t updatedColumns() const { return updated_columns_; }

  /// log u for the free goal cell on every grid cell of log_u (resized to the grid): 0 at the
  /// goal, -inf at obstacles and at cells not connected to the goal. Returns the convergence
  /// criterion on the result: max over the other connected cells of the relative residual
  /// |sum_j w_kj u_j / sum_j w_kj - u_k| / u_k. Not thread-safe (scratch buffers are reused).
  double solve(size_t goal, std::vector<double>& log_u) const;

 private:
  /// The convergence criterion on the solution in x_ (factor order, u = w / w_g).
  double residual(size_t goal) const;
  /// Column c of A's lower triangle (its diagonal, then its east and north neighbours' entries)
  /// for `cs`: a cell that is not free there has the identity's row.
  void assembleColumn(const ConfigSpace& cs, int c, double* values) const;
  /// A_ab for unknowns a != b that are grid neighbours (0 if not).
  double entry(int a, int b) const;
  /// Left-looking recomputation of factor column j (its rows of L and D_j) from the final
  /// columns before it; false if D_j is not positive.
  bool refactorColumn(long j);

  long width_ = 0;
  bool use_conductance_ = true;
  LargeVector<size_t> cells_;  ///< grid cell of each unknown (row-major order of the free cells)
  LargeVector<int> id_;        ///< unknown of each grid cell, -1 if not free
  /// Lower triangle of A, unknowns in cells_ order, compressed columns (diagonal first).
  LargeVector<int> ap_, ai_;
  LargeVector<double> ax_;
  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;  ///< simplicial LDL^T of P A P^T, column j: D_j, L_.j
  LargeVector<int> inverse_perm_;     ///< position in the factor of each unknown
  bool ok_ = false;
  FactorTiming timing_;
  bool ordering_reused_ = false;
  bool ordering_derived_ = false;
  std::shared_ptr<const FactorOrdering> base_ordering_;  ///< `previous`, if adapted from it
  mutable LargeVector<ScaledValue> x_;                   ///< per-solve scratch, reused
  mutable LargeVector<double> sum_;
  // update()'s scratch (allocated at the first update): a dense column, marks per factor
  // column, the elimination tree and the columns of a row of L.
  LargeVector<double> column_;
  LargeVector<int> mark_;
  LargeVector<int> parent_;
  std::vector<long> row_;
  size_t updated_columns_ = 0;
};

}  // namespace wheelchair_harmonic_planner
