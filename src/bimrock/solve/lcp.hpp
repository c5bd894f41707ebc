#pragma once
/// @file The linear complementarity problem of one load increment, as plain data, and what every
/// LCP solver shares: the result, the measured residuals and the solver interface. Find z >= 0 with
/// w = M z + q >= 0 and z . w = 0; in the analysis z is the vector of plastic multipliers lambda, w
/// the slacks nu and M = N - C K^-1 Phi (eqs. 24, 28).
#include <iosfwd>
#include <string>

#include <vector>

#include <Eigen/Core>

namespace bimrock {

/// The LCP (q, M), dense: the form the pivoting methods (Lemke, branch and bound) need, and that
/// of tests and recorded problems. The active-set methods see an increment's M column by column
/// (LcpColumns) or in its sparse parts (ActiveSetEquations) instead, never formed whole.
struct LcpProblem {
  Eigen::MatrixXd m;  ///< n x n; symmetric positive semi-definite for associated flow
  Eigen::VectorXd q;  ///< n
  [[nodiscard]] Eigen::Index size() const { return q.size(); }
};

/// Throws std::invalid_argument unless M is square, q matches it and
/// every entry is finite.
void check_lcp(const LcpProblem& problem);

enum class LcpStatus {
  solved,             ///< z, w satisfy the LCP to the solver's accuracy (see residuals)
  no_solution,        ///< the method proved (or, for some M, concluded) that none exists: collapse
  iteration_limit,    ///< gave up: the pivot or iteration budget ran out
  numerical_failure,  ///< round-off spoiled the result; not a collapse (cut the increment)
  interrupted,        ///< stopped at the caller's request (ActiveSetLcp::Interrupt): no result
};

[[nodiscard]] const char* to_string(LcpStatus status);

/// How well a candidate z satisfies the LCP, measured on the unscaled problem. A z or w with a
/// non-finite entry has infinite relative measures: it fails every check.
/// The relative measures are invariant under positive scaling of the rows and columns of M:
/// row i is compared with the size of the terms that sum to w_i, s_i = |q_i| + sum_j |M_ij z_j|,
/// and z with its largest entry |z|_inf.
struct LcpResiduals {
  // absolute
  double min_z = 0.0;                ///< min_i z_i (>= 0 when feasible)
  double min_w = 0.0;                ///< min_i w_i (>= 0 when feasible)
  double max_complementarity = 0.0;  ///< max_i |z_i w_i|
  // relative
  double z_violation = 0.0;      ///< max_i max(0, -z_i) / |z|_inf
  double w_violation = 0.0;      ///< max_i max(0, -w_i) / s_i
  double complementarity = 0.0;  ///< max_i min(|z_i| / |z|_inf, |w_i| / s_i): one of each pair is 0
  [[nodiscard]] double worst_relative() const;
};

/// Each pair (z_i, w_i) of a point z relative to its scale: z_i / |z|_inf and w_i / s_i, s_i the
/// size of the terms that sum to w_i (as in LcpResiduals): how far a row is from active (w) and
/// from free (z), comparable across rows.
struct RelativePairs {
  Eigen::VectorXd z;
  Eigen::VectorXd w;
};
[[nodiscard]] RelativePairs relative_pairs(const LcpProblem& problem, const Eigen::VectorXd& z);

/// Residuals of z for the problem (w = M z + q computed here).
[[nodiscard]] LcpResiduals measure(const LcpProblem& problem, const Eigen::VectorXd& z);
/// Residuals of z given w = M z + q and the size of the terms that sum to each w_i
/// (s = |M| |z| + |q|, or a bound of it), for an M that is not formed.
[[nodiscard]] LcpResiduals measure(const Eigen::VectorXd& z, const Eigen::VectorXd& w,
                                   const Eigen::VectorXd& s);

struct LcpResult {
  LcpStatus status = LcpStatus::numerical_failure;
  Eigen::VectorXd z;  ///< the multipliers (for a failure: the last iterate, for information)
  Eigen::VectorXd w;  ///< M z + q, computed from the returned z in unscaled form
  int steps = 0;      ///< pivots (Lemke), sweeps (Gauss-Seidel) or bases tried (enumeration)
  LcpResiduals residuals;
  /// For no_solution, when the method finds one: a direction r >= 0, |r|_inf = 1, of unbounded
  /// z (Lemke's secondary ray). For positive semi-definite M it certifies that no solution exists
  /// (M^T r = 0, q . r < 0) and is the mechanism of the collapse. Empty otherwise.
  Eigen::VectorXd ray;
};

/// The result for a given z: w and the residuals computed from the problem.
[[nodiscard]] LcpResult make_lcp_result(const LcpProblem& problem, LcpStatus status,
                                        Eigen::VectorXd z, int steps);

/// Whether r certifies that the LCP has no solution (Farkas): r >= 0, M^T r <= 0 and q . r < 0
/// give r . w = (M^T r) . z + q . r < 0 for every z >= 0, so w >= 0 is impossible. Given
/// mtr = M^T r and mtr_size = |M|^T |r| (the size of the terms each entry sums), each entry is
/// held to a relative tolerance of 1e-8 and, for a column whose entries are all round-off
/// residues of a cancellation (a mechanism), to 1e-10 * m_max * |r|_1 (m_max = max|M_ij|).
[[nodiscard]] bool certifies_infeasibility(const Eigen::VectorXd& q, const Eigen::VectorXd& r,
                                           const Eigen::VectorXd& mtr,
                                           const Eigen::VectorXd& mtr_size, double m_max);

/// The same proof for a part of the polyhedron {z >= 0, w = M z + q >= 0} in which some w_i are
/// held in [0, held_slack] (`held_w`) and some z_j at zero (`held_z`): r_i may take either sign
/// on a held w_i, (M^T r)_j is not bounded on a held z_j, and q . r must stay below
/// -held_slack sum over the held w_i of |r_i| too (then r . w >= that sum, and r . w =
/// (M^T r) . z + q . r < it). With nothing held it is certifies_infeasibility().
[[nodiscard]] bool certifies_empty(const Eigen::VectorXd& q, const Eigen::VectorXd& r,
                                   const Eigen::VectorXd& mtr, const Eigen::VectorXd& mtr_size,
                                   double m_max, const std::vector<char>& held_w,
                                   const std::vector<char>& held_z, double held_slack);

/// A certificate r of LCP(M, q) certifies LCP(M, q - t dq) too, M^T r being the same, as long
/// as q . r stays below certifies_infeasibility's tolerance. For a q that moves with the load,
/// q = q0 + dq at the step taken and q0 at no step, this is the least fraction t of that step
/// from which on (t <= t' <= 1) r certifies the LCP: an upper bound on the collapse load (the
/// step itself, 1, when the load does not drive the mechanism).
[[nodiscard]] double certified_from(const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                                    const Eigen::VectorXd& r);

/// Whether b is a, up to a positive scale of q: the same M, and q_b = s q_a with s > 0 to a
/// relative 1e-12. Such LCPs are one question: z solves LCP(M, q) exactly when s z solves
/// LCP(M, s q), and a certificate of one certifies the other.
[[nodiscard]] bool same_up_to_scale(const LcpProblem& a, const LcpProblem& b);

/// The interface every LCP solver implements, so Lemke, projected Gauss-Seidel and later a
/// sparse or distributed backend sit side by side and are compared on the same problems.
class LcpSolver {
 public:
  virtual ~LcpSolver() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  /// Work that depends only on the structure of M and can serve several solves (a sparse
  /// backend's symbolic analysis). The dense solvers need none.
  virtual void setup(const LcpProblem& /*problem*/) {}
  /// @param warm_start a guess of z (e.g. the previous increment's); solvers may ignore it
  [[nodiscard]] virtual LcpResult solve(const LcpProblem& problem,
                                        const Eigen::VectorXd* warm_start = nullptr) = 0;
};

/// Writes the problem as text with every digit needed to read back the same doubles, so the LCP
/// of a failing increment can be replayed in a test.
void write_lcp(std::ostream& out, const LcpProblem& problem);
/// Reads what write_lcp wrote; throws std::runtime_error on a malformed stream.
[[nodiscard]] LcpProblem read_lcp(std::istream& in);

}  // namespace bimrock
