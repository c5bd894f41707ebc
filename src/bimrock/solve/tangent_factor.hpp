#pragma once
/// @file The factor of the reduced tangent kept from one LCP to the next (reduced_tangent.hpp),
/// and the solves of another tangent through it. A tangent that differs from the kept one in
/// the terms of a few groups, S_new = S_kept - P D P^T, is solved by the Woodbury identity, one
/// back-solve per column of P, where a factorization costs as much as K's.
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {

using SparseColumn = Eigen::SparseVector<double, Eigen::ColMajor, std::int64_t>;

/// One group's part of a reduced tangent, Phi_g N_gg^-1 C_g: the columns of Phi of its active
/// rows and their (damped) N_gg. A kept factor is described by its terms, so that a later LCP,
/// whose rows are numbered otherwise, can tell how its own tangent differs from it.
struct TangentTerm {
  Eigen::Index group = 0;  ///< SplitLcp::group: the same yield point in every LCP
  std::vector<int> modes;  ///< each active row's place among the rows of its group
  std::vector<SparseColumn> phi;
  Eigen::MatrixXd n_local;
};

/// The factor of the reduced tangent, kept from one LCP to the next: its symbolic analysis
/// serves every active set, and its numeric factor the next LCPs whose tangents are the same
/// or differ from it in a few groups (each candidate round starts from the active set the
/// last one ended with, each increment from the last increment's).
struct TangentFactor {
  SparseCholesky cholesky;
  /// The last tangent formed (lower triangle): K's pattern, its values overwritten each time.
  CholmodMatrix matrix;
  /// The tangent `cholesky` holds the factor of, as K minus these terms (empty: none).
  std::optional<std::vector<TangentTerm>> terms;
  /// S^-1 phi of the rows updates used, by group and mode (with the phi they were solved
  /// for), kept while the factor is: the rows an update changes are much the same from one
  /// active-set iteration to the next.
  struct Column {
    SparseColumn phi;
    Eigen::VectorXd solved;
  };
  std::map<std::pair<Eigen::Index, int>, Column> columns;
};

/// How much the tangent of a solve may differ from the one whose factor is kept and still be
/// solved through it (a low-rank update) instead of factorized: rows whose terms differ, and
/// back-solves for the columns not kept from earlier updates. Negative: chosen from the
/// factor's memory and its cost against a back-solve's.
struct TangentUpdateLimits {
  Eigen::Index rows = -1;
  double new_columns = -1.0;
};

/// A tangent S_new solved through the kept factor of S_kept (an empty P: the same tangent).
/// S_new = S_kept - P D P^T, P = [Phi of the new terms | Phi of the old terms] (n x r), D =
/// diag(N_new^-1, -N_old^-1); so S_new^-1 b = y + Y Cap^-1 P^T y with y = S_kept^-1 b,
/// Y = S_kept^-1 P and the capacitance Cap = D^-1 - P^T Y = V diag(lambda) V^T.
struct TangentUpdate {
  CholmodMatrix p;
  std::vector<const Eigen::VectorXd*> y;  ///< S_kept^-1 P, in TangentFactor::columns or `own`
  std::vector<Eigen::VectorXd> own;
  Eigen::MatrixXd vectors;
  Eigen::VectorXd inverse_values;
};

/// The solve of the tangent K minus `terms` through the kept factor of another one when they
/// differ in few groups, or nothing if they differ in too many, the back-solves would cost too
/// much, or the new one is not positive definite. The columns S_kept^-1 P it solves are kept in
/// tangent.columns for later updates.
[[nodiscard]] std::optional<TangentUpdate> update_from_kept(TangentFactor& tangent,
                                                            const std::vector<TangentTerm>& terms,
                                                            TangentUpdateLimits limits);

/// S^-1 rhs with the kept factor, through `update` if not null.
[[nodiscard]] Eigen::VectorXd solve_tangent(const TangentFactor& tangent,
                                            const Eigen::VectorXd& rhs,
                                            const TangentUpdate* update);

}  // namespace bimrock
