#pragma once
/// @file The feasible set of an LCP as a linear program: the polyhedron
/// {z >= 0, w = M z + q >= 0}, with chosen z_i or w_i held at zero, solved by GLPK's simplex.
///
/// A vertex of it with z_i w_i = 0 on every row is a solution of the LCP, and every solution
/// lies in it, so the polyhedron is what a complete method searches (branch_and_bound_lcp.hpp).
/// Where it is empty, Farkas' lemma gives r >= 0 with M^T r <= 0 and q . r < 0: a proof that
/// no z >= 0 makes w >= 0 (in the analysis: no plastic flow along the flow rule's directions
/// brings the stresses of the increment within every yield function).
///
/// The LP is built once, scaled so that max|M| = max|q| = 1 (z in units of max|q| / max|M|),
/// and each solve starts from the last basis: a depth-first search moves between neighbouring
/// nodes. GLPK's own scaling is not used: on the degenerate LCPs of cohesionless joints (rank
/// 6 of 18) it made the simplex call feasible nodes empty, which the same LP unscaled, and the
/// exact rational simplex, found feasible.
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

class LcpPolyhedron {
 public:
  /// What is held at zero on one row.
  enum class Fix : char { none, z, w };
  enum class Status { feasible, empty, failed };
  struct Vertex {
    Status status = Status::failed;
    Eigen::VectorXd z;  ///< for feasible: a vertex, in the problem's own units
    /// For empty: the simplex's phase-one duals at its last basis (one per row, unchecked),
    /// a Farkas certificate of the node up to sign where phase one ended at its optimum.
    Eigen::VectorXd duals;
  };

  explicit LcpPolyhedron(const LcpProblem& problem);
  ~LcpPolyhedron();
  LcpPolyhedron(const LcpPolyhedron&) = delete;
  LcpPolyhedron& operator=(const LcpPolyhedron&) = delete;

  /// A vertex with the rows held as `fix` says (one entry per row), the one of least
  /// sum of z_i + w_i over the free rows (in the scaled units): the objective pulls both of a
  /// pair towards zero. `failed` where the simplex gave up (round-off, or a stall on a
  /// degenerate vertex), or would need more than `max_pivots`.
  [[nodiscard]] Vertex vertex(const std::vector<Fix>& fix,
                              long max_pivots = std::numeric_limits<long>::max());

  /// Simplex pivots of every vertex() so far: each costs about n^2 on this dense LP.
  [[nodiscard]] long pivots() const;

  /// A Farkas certificate that the polyhedron (nothing held) is empty: r >= 0, |r|_inf = 1,
  /// M^T r <= 0, q . r < 0, as the LP found it (the caller checks it with
  /// certifies_infeasibility).
  [[nodiscard]] std::optional<Eigen::VectorXd> certificate() const;

  /// Whether the node with the rows held as `fix` says is empty, checked by a Farkas certificate:
  /// one found for an earlier node where it serves, else one found by an LP of its own: y with y_i
  /// >= 0 where w_i >= 0 (y_i of any sign where w_i is held at zero), (M^T y)_j <= 0 where z_j >= 0
  /// (no condition where z_j is held at zero), and q . y < 0; then y . w = (M^T y) . z + q . y < 0
  /// for every z of the node, where y . w >= 0. The simplex's verdict "empty" alone is no proof: on
  /// the degenerate LCPs of cohesionless joints round-off can make it call a feasible node empty.
  [[nodiscard]] bool certified_empty(const std::vector<Fix>& fix);

  /// Whether `duals` (Vertex::duals of the node `fix`), of either sign, is a Farkas certificate
  /// of the node as certified_empty() checks one: the simplex's own proof, no LP solved.
  [[nodiscard]] bool certified_by_duals(const std::vector<Fix>& fix,
                                        const Eigen::VectorXd& duals) const;

 private:
  /// The least-|y|_1 y of the Farkas system of the node `fix` (see certified_empty()), with
  /// q . y = -1 in the scaled units, as the LP found it, unchecked; none where the LP has none.
  [[nodiscard]] std::optional<Eigen::VectorXd> farkas(const std::vector<Fix>& fix) const;

  /// Whether y is a Farkas certificate of the node `fix` (certified_empty()), in the scaled
  /// units.
  [[nodiscard]] bool certifies(const std::vector<Fix>& fix, const Eigen::VectorXd& y) const;

  struct Lp;
  const LcpProblem& problem_;
  double m_max_ = 1.0;
  double q_max_ = 1.0;
  std::unique_ptr<Lp> lp_;
  std::vector<Eigen::VectorXd> certificates_;  ///< of the nodes certified so far, newest last
};

}  // namespace bimrock
