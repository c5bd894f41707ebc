// The active-set equations on the sparse reduced tangent. Expected numbers come from a second
// method on the same LCP: the dense matrix M = N - C K^-1 Phi formed with a dense LDLT of K,
// solved by a dense LU (one active set) or by Lemke (the whole LCP; M is positive definite, so
// the solution is unique).
#include <algorithm>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/reduced_tangent.hpp>

#include "solve/chain_lcp.hpp"
#include "solve/random_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::ChainLcp;
using testing::dense_solution;
using testing::every;
using testing::make_chain;

// A solution of the tangent's equations against the dense active block's (the second method):
// z, and the undamped w = M z + q, to 1e-9.
void expect_dense_solution(const ChainLcp& chain, const std::vector<Eigen::Index>& active,
                           const ActiveSetEquations::Damping& damping,
                           const ActiveSetEquations::Solution& s) {
  const VectorXd z = dense_solution(chain, active, damping);
  const VectorXd w = chain.m_dense * z + chain.split.q;
  EXPECT_LE((s.z - z).cwiseAbs().maxCoeff(), 1e-9 * z.cwiseAbs().maxCoeff());
  EXPECT_LE((s.w - w).cwiseAbs().maxCoeff(), 1e-9 * w.cwiseAbs().maxCoeff());
}

TEST(ReducedTangent, SolvesTheEquationsOfAnActiveSetAsTheDenseBlockDoes) {
  ChainLcp chain;
  make_chain(40, 7, chain);
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent);
  const std::vector<Eigen::Index> active = every(3, equations.size());  // one or both modes
  const ActiveSetEquations::Solution s = equations.solve(active);
  ASSERT_TRUE(s.regular);
  expect_dense_solution(chain, active, {}, s);
  EXPECT_EQ(equations.factorizations(), 1);
}

TEST(ReducedTangent, TheSolvesOwnWIsTheDenseBlocksFreshOrThroughAnUpdate) {
  // Check::from_solve: w from the tangent's own displacements, not measured with K. It must
  // still be M z + q of the dense second method, for a factorized tangent and for one solved
  // through the kept factor (Woodbury), and say that it was not measured.
  ChainLcp chain;
  make_chain(40, 23, chain);
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent, {64, 64.0});
  const std::vector<Eigen::Index> first = every(3, equations.size());
  std::vector<Eigen::Index> next = first;
  next.erase(std::find(next.begin(), next.end(), 9));        // group 4 leaves
  next.insert(std::find(next.begin(), next.end(), 21), 20);  // group 10 joins
  for (const auto& active : {first, next}) {
    const ActiveSetEquations::Solution s =
        equations.solve(active, {}, ActiveSetEquations::Check::from_solve);
    ASSERT_TRUE(s.regular);
    EXPECT_FALSE(s.measured);
    expect_dense_solution(chain, active, {}, s);
  }
  EXPECT_EQ(equations.factorizations(), 1);
  EXPECT_EQ(equations.updated_factors(), 1);
  EXPECT_TRUE(equations.solve(next).measured);
}

TEST(ReducedTangent, TheDiagonalBoundIsAtLeastTheDiagonalOfM) {
  // M_rr = N_rr - phi_r . K^-1 phi_r: the bound N_rr, against the dense M.
  ChainLcp chain;
  make_chain(20, 29, chain);
  TangentFactor tangent;
  const ReducedTangentEquations equations(chain.split, chain.k, tangent);
  for (Eigen::Index r = 0; r < equations.size(); ++r) {
    EXPECT_GE(equations.diagonal_bound(r), chain.m_dense(r, r));
    EXPECT_GT(chain.m_dense(r, r), 0.0);
  }
}

TEST(ReducedTangent, ATermOutsideThePatternOfKIsAddedWithAPatternOfItsOwn) {
  // The tangent is formed in K's pattern; point 6 couples blocks 5 and 6, which K does not.
  ChainLcp chain;
  make_chain(12, 19, chain, /*uncoupled=*/6);
  ASSERT_EQ(chain.k_lower.coeff(6 * 6, 6 * 5 + 1), 0.0);  // no block 5-6 entry in K
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent);
  const std::vector<Eigen::Index> active = {2, 3, 8, 12, 13, 20};  // points 1, 4, 6, 10
  const ActiveSetEquations::Solution s = equations.solve(active);
  ASSERT_TRUE(s.regular);
  EXPECT_GT(tangent.matrix.nonZeros(), chain.k_lower.nonZeros());
  const VectorXd z = dense_solution(chain, active, {});
  EXPECT_LE((s.z - z).cwiseAbs().maxCoeff(), 1e-9 * z.cwiseAbs().maxCoeff());
}

TEST(ReducedTangent, ReusesTheKeptFactorOnlyForTheSameTangent) {
  // A second LCP (a later candidate round) that starts from the active set the first ended
  // with: no factorization. Another active set of the same pattern: factorized again. Each
  // solution is checked against the dense block, so a stale factor would fail.
  ChainLcp chain;
  make_chain(30, 9, chain);
  TangentFactor tangent;
  const std::vector<Eigen::Index> even = every(2, chain.split.q.size());
  const std::vector<Eigen::Index> odd = every(2, chain.split.q.size(), 1);
  {
    ReducedTangentEquations first(chain.split, chain.k, tangent);
    ASSERT_TRUE(first.solve(odd).regular);
    EXPECT_EQ(first.factorizations(), 1);
  }
  ReducedTangentEquations second(chain.split, chain.k, tangent);
  const ActiveSetEquations::Solution same = second.solve(odd);
  EXPECT_EQ(second.factorizations(), 0);
  EXPECT_EQ(second.reused_factors(), 1);
  const VectorXd z_odd = dense_solution(chain, odd, {});
  EXPECT_LE((same.z - z_odd).cwiseAbs().maxCoeff(), 1e-9 * z_odd.cwiseAbs().maxCoeff());
  const ActiveSetEquations::Solution other = second.solve(even);
  EXPECT_EQ(second.factorizations(), 1);
  const VectorXd z_even = dense_solution(chain, even, {});
  EXPECT_LE((other.z - z_even).cwiseAbs().maxCoeff(), 1e-9 * z_even.cwiseAbs().maxCoeff());
}

TEST(ReducedTangent, UpdatesTheKeptFactorWhereFewRowsChange) {
  // Active sets that differ from the factored one in a few groups (a group dropped, one with
  // another row, one added), then the same rows damped: each solved through the kept factor
  // (Woodbury) and checked against the dense block; a wrong update would fail.
  ChainLcp chain;
  make_chain(40, 13, chain);
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent, {64, 64.0});
  const std::vector<Eigen::Index> first = every(3, equations.size());  // rows 0, 3, 6, ...
  ASSERT_TRUE(equations.solve(first).regular);
  ASSERT_EQ(equations.factorizations(), 1);
  std::vector<Eigen::Index> next = first;
  next.erase(std::find(next.begin(), next.end(), 9));        // group 4 leaves
  next.insert(std::find(next.begin(), next.end(), 12), 13);  // group 6: both modes
  next.insert(std::find(next.begin(), next.end(), 21), 20);  // group 10 joins
  const ActiveSetEquations::Solution s = equations.solve(next);
  ASSERT_TRUE(s.regular);
  EXPECT_EQ(equations.factorizations(), 1);
  EXPECT_EQ(equations.updated_factors(), 1);
  expect_dense_solution(chain, next, {}, s);
  ActiveSetEquations::Damping damping{VectorXd::Zero(static_cast<Eigen::Index>(next.size())),
                                      VectorXd::Constant(equations.size(), 0.1)};
  damping.factor.head(4).setConstant(0.5);
  const ActiveSetEquations::Solution damped = equations.solve(next, damping);
  ASSERT_TRUE(damped.regular);
  EXPECT_EQ(equations.factorizations(), 1);
  EXPECT_EQ(equations.updated_factors(), 2);
  const VectorXd z_damped = dense_solution(chain, next, damping);
  EXPECT_LE((damped.z - z_damped).cwiseAbs().maxCoeff(), 1e-9 * z_damped.cwiseAbs().maxCoeff());
}

// The LCP of a later candidate round: the rows of the groups `groups` of `chain`, numbered
// anew, with the group ids of the chain (the yield points of the analysis); group `moved` (if
// any) with its N block scaled, as hardening would change it. (Scaling its rows of Phi and C
// as well would not change its term of the tangent: Phi_g N_gg^-1 C_g depends on their span
// only.)
struct SubLcp {
  CholmodMatrix c, phi, n;
  SplitLcp split;
  MatrixXd m_dense;
  std::vector<Eigen::Index> rows;  // each row's row in the chain
};

void make_sub(const ChainLcp& chain, const std::vector<Eigen::Index>& groups, SubLcp& out,
              Eigen::Index moved = -1, double scale = 1.0) {
  for (Eigen::Index g : groups)
    for (Eigen::Index r = 2 * g; r < 2 * g + 2; ++r)
      out.rows.push_back(r);
  const auto m = static_cast<Eigen::Index>(out.rows.size());
  const MatrixXd c_full(chain.c);
  const MatrixXd n_full(chain.n);
  MatrixXd c(m, c_full.cols());
  MatrixXd n = MatrixXd::Zero(m, m);
  VectorXd q(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index ri = out.rows[static_cast<std::size_t>(i)];
    const double si = ri / 2 == moved ? scale : 1.0;
    c.row(i) = c_full.row(ri);
    q(i) = chain.split.q(ri);
    for (Eigen::Index j = 0; j < m; ++j) {
      const Eigen::Index rj = out.rows[static_cast<std::size_t>(j)];
      n(i, j) = (rj / 2 == moved ? si : 1.0) * n_full(ri, rj);
    }
  }
  const MatrixXd k = MatrixXd(chain.k_lower).selfadjointView<Eigen::Lower>();
  out.c = c.sparseView();
  out.phi = c.transpose().sparseView();
  out.n = n.sparseView();
  out.m_dense = n - c * k.ldlt().solve(c.transpose());
  out.split = SplitLcp{&chain.k_lower, &out.c, &out.phi, &out.n, q, {}, {}};
  for (Eigen::Index r : out.rows) {
    out.split.group.push_back(r / 2);
    out.split.group_rank.push_back(2);
  }
}

TEST(ReducedTangent, ALaterLcpIsSolvedThroughTheFactorAnEarlierOneKept) {
  // Round 1 has the rows of every point and factorizes an active set; round 2 (other row
  // numbers, some points no longer candidates) asks for an active set that differs from it in
  // a few points: solved through the kept factor, no factorization. If a point's hardening
  // changed between the rounds (its N block differs), its term is not the kept one: still an
  // update, and the solution is right. Every solution is checked against the dense
  // block of its own LCP.
  ChainLcp chain;
  make_chain(40, 21, chain);
  TangentFactor tangent;
  std::vector<Eigen::Index> first;  // chain rows: both modes of every third point
  for (Eigen::Index g = 0; g < 40; g += 3)
    first.insert(first.end(), {2 * g, 2 * g + 1});
  {
    ReducedTangentEquations round1(chain.split, chain.k, tangent, {64, 64.0});
    ASSERT_TRUE(round1.solve(first).regular);
    ASSERT_EQ(round1.factorizations(), 1);
  }
  std::vector<Eigen::Index> groups;  // candidates of round 2: every point but 1, 2, 4 and 5
  for (Eigen::Index g = 0; g < 40; ++g)
    if (g != 1 && g != 2 && g != 4 && g != 5)
      groups.push_back(g);
  for (const double scale : {1.0, 1.5}) {
    SubLcp sub;
    make_sub(chain, groups, sub, /*moved=*/9, scale);
    // Active: the rows of `first` but point 3's, and point 7's first row.
    std::vector<Eigen::Index> active;
    for (std::size_t i = 0; i < sub.rows.size(); ++i) {
      const Eigen::Index r = sub.rows[i];
      if ((std::find(first.begin(), first.end(), r) != first.end() && r / 2 != 3) || r == 14)
        active.push_back(static_cast<Eigen::Index>(i));
    }
    ReducedTangentEquations round2(sub.split, chain.k, tangent, {64, 64.0});
    const ActiveSetEquations::Solution s = round2.solve(active);
    ASSERT_TRUE(s.regular);
    EXPECT_EQ(round2.factorizations(), 0) << scale;
    EXPECT_EQ(round2.updated_factors(), 1) << scale;
    const VectorXd z = dense_solution(sub.m_dense, sub.n, sub.split.q, active, {});
    const VectorXd w = sub.m_dense * z + sub.split.q;
    EXPECT_LE((s.z - z).cwiseAbs().maxCoeff(), 1e-9 * z.cwiseAbs().maxCoeff()) << scale;
    EXPECT_LE((s.w - w).cwiseAbs().maxCoeff(), 1e-9 * w.cwiseAbs().maxCoeff()) << scale;
  }
}

TEST(ReducedTangent, AnUpdateToATangentThatIsNotPositiveDefiniteIsRefused) {
  // With the N block of point 5 a hundredth of its springs' a D a^T, M_rr < 0 on its first row:
  // the tangent of an active set holding it is indefinite (it has as many negative eigenvalues
  // as M_AA). Through an update of a positive definite factor it would still be solved; the
  // inertia of the capacitance must refuse it, and the solve must report the singular block
  // that a fresh factorization reports.
  ChainLcp chain;
  make_chain(20, 17, chain);
  MatrixXd n = MatrixXd(chain.n);
  chain.m_dense.block(10, 10, 2, 2) -= 0.99 * n.block(10, 10, 2, 2);
  n.block(10, 10, 2, 2) *= 0.01;
  chain.n = n.sparseView();
  ASSERT_LT(chain.m_dense(10, 10), 0.0);
  const std::vector<Eigen::Index> first = {0, 4};
  const std::vector<Eigen::Index> next = {0, 4, 10};
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent, {64, 64.0});
  ASSERT_TRUE(equations.solve(first).regular);
  const ActiveSetEquations::Solution s = equations.solve(next);
  EXPECT_FALSE(s.regular);
  EXPECT_EQ(equations.updated_factors(), 0);
  EXPECT_GE(equations.factorizations(), 2);  // the refused update, then a failed factorization
  TangentFactor fresh_factor;
  ReducedTangentEquations fresh(chain.split, chain.k, fresh_factor);
  EXPECT_FALSE(fresh.solve(next).regular);
}

// The solve of an active set's tangent (a preconditioner of the non-symmetric one) is that
// tangent's inverse, from a fresh factor or through an update of the kept one; nothing where the
// tangent is not positive definite (the chain of the test above).
TEST(ReducedTangent, TheTangentSolveIsTheTangentsInverse) {
  ChainLcp chain;
  make_chain(30, 9, chain);
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent, {64, 64.0});
  std::mt19937 rng(4);
  const VectorXd b = testing::random_vector(chain.split.q.size() * 3, rng);
  std::vector<Eigen::Index> active = every(2, chain.split.q.size());
  for (const bool fresh : {true, false}) {
    const std::optional<LinearSolve> solve = equations.tangent_solve(active);
    ASSERT_TRUE(solve.has_value());
    const VectorXd x = dense_tangent(chain, active).ldlt().solve(b);
    EXPECT_LE(((*solve)(b)-x).cwiseAbs().maxCoeff(), 1e-10 * x.cwiseAbs().maxCoeff()) << fresh;
    active.push_back(1);  // one row more: through an update
    std::sort(active.begin(), active.end());
  }
  EXPECT_EQ(equations.factorizations(), 1);
  EXPECT_EQ(equations.updated_factors(), 1);

  ChainLcp indefinite;
  make_chain(20, 17, indefinite);
  MatrixXd n = MatrixXd(indefinite.n);
  n.block(10, 10, 2, 2) *= 0.01;
  indefinite.n = n.sparseView();
  TangentFactor other;
  ReducedTangentEquations at_indefinite(indefinite.split, indefinite.k, other);
  EXPECT_FALSE(at_indefinite.tangent_solve({0, 4, 10}).has_value());
}

TEST(ReducedTangent, SolvesTheDampedEquationsAsTheDenseBlockDoes) {
  // The proximal equations of projected Newton.
  ChainLcp chain;
  make_chain(40, 5, chain);
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent);
  const std::vector<Eigen::Index> active = every(2, equations.size());
  std::mt19937 rng(3);
  ActiveSetEquations::Damping damping{VectorXd::Zero(static_cast<Eigen::Index>(active.size())),
                                      testing::random_vector(equations.size(), rng)};
  for (Eigen::Index i = 0; i < damping.factor.size(); i += 3)
    damping.factor(i) = 0.5;
  const ActiveSetEquations::Solution s = equations.solve(active, damping);
  ASSERT_TRUE(s.regular);
  expect_dense_solution(chain, active, damping, s);  // w undamped
}

TEST(ReducedTangent, ActiveSetOnTheTangentAgreesWithLemkeOnTheDenseMatrix) {
  for (unsigned seed : {1u, 2u, 3u}) {
    ChainLcp chain;
    make_chain(60, seed, chain);
    const LcpResult lemke = Lemke().solve({chain.m_dense, chain.split.q});
    ASSERT_EQ(lemke.status, LcpStatus::solved);
    TangentFactor tangent;
    ReducedTangentEquations equations(chain.split, chain.k, tangent);
    const LcpResult r = ActiveSetLcp().solve(equations);
    ASSERT_EQ(r.status, LcpStatus::solved) << to_string(r.status) << " seed " << seed;
    EXPECT_LE((r.z - lemke.z).cwiseAbs().maxCoeff(), 1e-9 * lemke.z.cwiseAbs().maxCoeff());
    EXPECT_LE(r.residuals.worst_relative(), 1e-9);
    EXPECT_GT(equations.factorizations(), 0);
    // Projected Newton on the tangent from the first iterate on: the same solution.
    ActiveSetOptions newton_at_once;
    newton_at_once.stall_iterations = 0;
    ReducedTangentEquations again(chain.split, chain.k, tangent);
    const LcpResult pn = ActiveSetLcp(newton_at_once).solve(again);
    ASSERT_EQ(pn.status, LcpStatus::solved) << to_string(pn.status) << " seed " << seed;
    EXPECT_LE((pn.z - lemke.z).cwiseAbs().maxCoeff(), 1e-9 * lemke.z.cwiseAbs().maxCoeff());
  }
}

TEST(ReducedTangent, ASingularLocalBlockIsLeftToTheDenseRoute) {
  ChainLcp chain;
  make_chain(5, 11, chain);
  // Both modes of point 2 with proportional gradients: N_gg singular.
  MatrixXd n = MatrixXd(chain.n);
  n.block(4, 4, 2, 2) = MatrixXd::Ones(2, 2);
  chain.n = n.sparseView();
  TangentFactor tangent;
  ReducedTangentEquations equations(chain.split, chain.k, tangent);
  const ActiveSetEquations::Solution s = equations.solve({4, 5});
  EXPECT_FALSE(s.regular);
  EXPECT_EQ(s.ray.size(), 0);
}

// Six springs k_i to the ground, each the only stiffness of its unknown and each with one yield
// mode of gradient a_i (associated, perfectly plastic): C = a k, Phi = C^T, N = a k a. With
// every mode active, M = N - C K^-1 Phi = 0 and the tangent K - Phi N^-1 C = 0: a mechanism, and
// with q < 0 no solution (Farkas: r >= 0, M r = 0, q . r < 0 for every r > 0).
TEST(ReducedTangent, ASingularTangentGivesItsMechanismAndIsLeftAsItWas) {
  const Eigen::Index n = 6;
  const VectorXd k = (VectorXd(n) << 1.0, 2.0, 3.0, 1.5, 2.5, 4.0).finished() * 1e9;
  const VectorXd a = (VectorXd(n) << 1.0, 0.5, 2.0, 1.2, 0.8, 1.5).finished();
  MatrixXd dense_k = k.asDiagonal();
  CholmodMatrix k_lower = dense_k.sparseView();
  CholmodMatrix c = MatrixXd(a.cwiseProduct(k).asDiagonal()).sparseView();
  CholmodMatrix phi = CholmodMatrix(c.transpose());
  CholmodMatrix n_matrix = MatrixXd(a.cwiseProduct(a).cwiseProduct(k).asDiagonal()).sparseView();
  const VectorXd q = -VectorXd::LinSpaced(n, 1.0, 6.0);
  SplitLcp split{&k_lower, &c, &phi, &n_matrix, q, {}, {}};
  for (Eigen::Index r = 0; r < n; ++r) {
    split.group.push_back(r);
    split.group_rank.push_back(1);
  }
  SparseCholesky k_factor;
  k_factor.analyze(k_lower, 6);
  ASSERT_TRUE(k_factor.factorize(k_lower));
  TangentFactor tangent;
  ReducedTangentEquations equations(split, k_factor, tangent);
  const ActiveSetEquations::Solution s = equations.solve(every(1, n));
  EXPECT_FALSE(s.regular);
  ASSERT_EQ(s.ray.size(), n);
  // The certificate, checked here on the dense M (= 0 up to round-off of k).
  EXPECT_GE(s.ray.minCoeff(), 0.0);
  EXPECT_DOUBLE_EQ(s.ray.maxCoeff(), 1.0);
  EXPECT_LT(q.dot(s.ray), 0.0);
  // The kernel search factorizes a shifted tangent: the tangent itself is left as formed,
  // K - Phi N^-1 C = 0 to round-off of k (the smallest shift is 1e-12 k).
  ASSERT_EQ(tangent.matrix.rows(), n);
  for (Eigen::Index j = 0; j < n; ++j)
    EXPECT_LE(std::abs(tangent.matrix.coeff(j, j)), 1e-14 * k(j)) << "unknown " << j;
}

}  // namespace
}  // namespace bimrock
