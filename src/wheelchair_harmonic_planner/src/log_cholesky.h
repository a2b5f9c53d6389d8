// Direct solve of the harmonic boundary problem with the result in log space: internal header.
//
// The unknowns are the stencil's cells; with the unnormalized, symmetric form of the stencil
// (A_kk = total conductance of cell k, A_kj = -edge conductance, b_k = edge to the goal) the
// system A u = b is a symmetric, diagonally dominant M-matrix (a Stieltjes matrix). Its sparse
// LDL^T factors (Eigen's SimplicialLDLT, AMD ordering) have L_kj <= 0 and D > 0, so both
// triangular solves only ever add non-negative terms: no cancellation, every component of u is
// obtained to high *relative* accuracy however small it is. We run those two solves in log
// space (log-sum-exp per row), so u far below the smallest double (e^-5000 down a long
// corridor) keeps full relative precision, exactly like the iterative log-space solvers.
#pragma once

#include "harmonic_stencil.h"

#include <vector>

namespace wheelchair_harmonic_planner {

/// Sets log_u on the stencil's cells (other cells untouched). Returns false if the factorization
/// failed (not expected for a stencil built by buildStencil).
bool solveLogCholesky(const Stencil& s, long width, size_t goal, std::vector<double>& log_u);

}  // namespace wheelchair_harmonic_planner
