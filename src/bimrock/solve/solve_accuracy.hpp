#pragma once
/// @file How accurate the solves with a factor of K are: the relative error of K^-1 (K x) for a
/// known x, about cond(K) times the machine precision. Stiff (penalty) interfaces make K
/// ill-conditioned, and the LCP matrix M = N - C K^-1 Phi is then known only to that relative
/// accuracy: a mode of M softer than a small multiple of it cannot be told from a mechanism.
#include <bimrock/assembly/global_system.hpp>  // SparseMatrix
#include <bimrock/solve/spd_solver.hpp>

namespace bimrock {

/// `k_lower`: the lower triangle of the K that `k` solves with.
double solve_accuracy(const SpdSolver& k, const SparseMatrix& k_lower);

}  // namespace bimrock
