// The primal-dual active-set method. Expected solutions: a hand solution, the enumeration of
// all complementary bases (an independent oracle for small problems, lcp_enumeration_test.cpp),
// planted solutions, and Lemke on larger positive definite problems, whose solution is unique.
// On problems without a solution it must never answer "solved".
#include <algorithm>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/lcp_enumeration.hpp>
#include <bimrock/solve/lemke.hpp>

#include "solve/counting_columns.hpp"
#include "solve/random_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(ActiveSetLcp, TwoByTwoByHand) {
  // [2 1; 1 2] z = (5, 6): z = (4/3, 7/3) (Cramer's rule), both rows active; with q = (-5, 6)
  // only row 0 is: z = (5/2, 0), w_1 = 5/2 + 6 > 0.
  ActiveSetLcp solver;
  LcpResult r = solver.solve({MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{-5.0, -6.0}}});
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_NEAR(r.z(0), 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(r.z(1), 7.0 / 3.0, 1e-12);
  r = solver.solve({MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{-5.0, 6.0}}});
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_NEAR(r.z(0), 2.5, 1e-12);
  EXPECT_EQ(r.z(1), 0.0);
}

class ActiveSetVsOracle : public ::testing::TestWithParam<int> {};

TEST_P(ActiveSetVsOracle, AgreesWithTheEnumerationOnPMatrices) {
  std::mt19937 rng(static_cast<unsigned>(GetParam()));
  const LcpProblem p{testing::random_p_matrix(10, rng), testing::random_vector(10, rng)};
  const LcpResult oracle = LcpEnumeration().solve(p);
  ASSERT_EQ(oracle.status, LcpStatus::solved);
  const LcpResult r = ActiveSetLcp().solve(p);
  if (r.status != LcpStatus::solved)
    GTEST_SKIP() << "no convergence: the caller falls back to Lemke";
  EXPECT_LE((r.z - oracle.z).cwiseAbs().maxCoeff(), 1e-9 * oracle.z.cwiseAbs().maxCoeff());
}

TEST_P(ActiveSetVsOracle, AgreesWithLemkeOnLargePositiveDefiniteProblems) {
  std::mt19937 rng(static_cast<unsigned>(GetParam()));
  const LcpProblem p{testing::random_spd(300, rng), testing::random_vector(300, rng)};
  const LcpResult lemke = Lemke().solve(p);
  ASSERT_EQ(lemke.status, LcpStatus::solved);
  const LcpResult r = ActiveSetLcp().solve(p);
  ASSERT_EQ(r.status, LcpStatus::solved) << to_string(r.status);
  EXPECT_LE((r.z - lemke.z).cwiseAbs().maxCoeff(), 1e-9 * lemke.z.cwiseAbs().maxCoeff());
  EXPECT_LT(r.steps, 20) << "Newton iterations";
}

INSTANTIATE_TEST_SUITE_P(Seeds, ActiveSetVsOracle, ::testing::Range(1, 11));

TEST(ActiveSetLcp, PlantedSolutionIsFoundFromAWarmStart) {
  std::mt19937 rng(7);
  const Eigen::Index n = 200;
  const MatrixXd m = testing::random_spd(n, rng);
  VectorXd z_star = VectorXd::Zero(n), w_star = VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i)
    (i % 3 == 0 ? z_star(i) : w_star(i)) = 1.0 + 0.01 * static_cast<double>(i);
  const LcpProblem p{m, testing::planted_q(m, z_star, w_star)};
  const LcpResult r = ActiveSetLcp().solve(p, &z_star);
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_EQ(r.steps, 1) << "the right active set is confirmed by one solve";
  EXPECT_LE((r.z - z_star).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(ActiveSetLcp, ColumnByColumnFormsOnlyTheActiveColumnsOnce) {
  // A planted solution with 20 active rows out of 400: the same z as the dense solve, and only
  // columns of rows that were active at some iteration are asked for, each once.
  std::mt19937 rng(11);
  const Eigen::Index n = 400;
  const MatrixXd m = testing::random_spd(n, rng);
  VectorXd z_star = VectorXd::Zero(n), w_star = VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i)
    (i % 20 == 0 ? z_star(i) : w_star(i)) = 1.0 + 0.01 * static_cast<double>(i);
  const LcpProblem p{m, testing::planted_q(m, z_star, w_star)};
  testing::CountingColumns columns(p);
  const LcpResult r = ActiveSetLcp().solve(columns);
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_LE((r.z - z_star).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LE(r.residuals.worst_relative(), 1e-9);
  std::vector<Eigen::Index> sorted = columns.asked;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "asked twice";
  EXPECT_LT(columns.asked.size(), static_cast<std::size_t>(n / 4));
  for (Eigen::Index c : columns.asked)
    EXPECT_TRUE(z_star(c) > 0.0 || p.q(c) < 0.0) << "column " << c << " was never active";
}

TEST(ActiveSetLcp, NeverClaimsASolutionThatDoesNotExist) {
  // [1 -1; -1 1], q = (-1, -1): w_0 + w_1 = -2 for every z, no solution (Lemke finds the ray).
  const LcpProblem p{MatrixXd{{1.0, -1.0}, {-1.0, 1.0}}, VectorXd{{-1.0, -1.0}}};
  EXPECT_NE(ActiveSetLcp().solve(p).status, LcpStatus::solved);
  EXPECT_EQ(Lemke().solve(p).status, LcpStatus::no_solution);
  for (unsigned seed = 1; seed <= 20; ++seed) {  // rank-deficient PSD with infeasible q
    std::mt19937 rng(seed);
    const MatrixXd b = testing::random_matrix(8, 3, rng);
    const LcpProblem q{b * b.transpose(), testing::random_vector(8, rng)};
    const LcpResult oracle = LcpEnumeration().solve(q);
    const LcpResult r = ActiveSetLcp().solve(q);
    if (oracle.status == LcpStatus::no_solution) {
      EXPECT_NE(r.status, LcpStatus::solved) << seed;
    }
    if (r.status == LcpStatus::solved) {
      EXPECT_LE(r.residuals.worst_relative(), 1e-9) << seed;
    }
    if (r.status == LcpStatus::no_solution) {  // only with a certificate: the oracle agrees
      EXPECT_EQ(oracle.status, LcpStatus::no_solution) << seed;
    }
  }
}

TEST(ActiveSetLcp, MurtysRuleAfterACycleSolvesWhatTheBlockRuleCannot) {
  // P-matrices (a unique solution, from the enumeration oracle) on which the block rule alone
  // cycles: with the switch to Murty's rule every one of them is solved.
  int cycled = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    std::mt19937 rng(seed);
    const LcpProblem p{testing::random_skewed_positive_definite(4, rng),
                       testing::random_vector(4, rng)};
    const LcpResult oracle = LcpEnumeration().solve(p);
    ASSERT_EQ(oracle.status, LcpStatus::solved) << seed;
    ActiveSetOptions block_only;
    block_only.murty_after_cycle = false;
    if (ActiveSetLcp(block_only).solve(p).status == LcpStatus::solved)
      continue;
    ++cycled;
    const LcpResult r = ActiveSetLcp().solve(p);
    ASSERT_EQ(r.status, LcpStatus::solved) << seed;
    EXPECT_LE((r.z - oracle.z).cwiseAbs().maxCoeff(), 1e-9 * oracle.z.cwiseAbs().maxCoeff())
        << seed;
  }
  EXPECT_GE(cycled, 5) << "the problems must exercise the safeguard";
}

TEST(ActiveSetLcp, ASingularActiveBlockThatIsAMechanismProvesTheCollapse) {
  // [1 -1; -1 1], q = (-1, -1): both rows start active, the block is singular with kernel
  // (1, 1), and M (1, 1) = 0, q . (1, 1) = -2 < 0: Farkas' certificate, found without Lemke.
  const LcpProblem p{MatrixXd{{1.0, -1.0}, {-1.0, 1.0}}, VectorXd{{-1.0, -1.0}}};
  const LcpResult r = ActiveSetLcp().solve(p);
  ASSERT_EQ(r.status, LcpStatus::no_solution);
  ASSERT_EQ(r.ray.size(), 2);
  EXPECT_NEAR(r.ray(0), 1.0, 1e-12);
  EXPECT_NEAR(r.ray(1), 1.0, 1e-12);
}

TEST(ActiveSetLcp, ASingularActiveBlockOfASolvableProblemIsNoProofOfCollapse) {
  // [1 1; 1 1], q = (-1, -1) is solved by z = (1, 0) (w = (0, 0)); the singular block's kernel
  // (1, -1) is no certificate, so the method gives up (Lemke takes over), never no_solution.
  const LcpProblem p{MatrixXd{{1.0, 1.0}, {1.0, 1.0}}, VectorXd{{-1.0, -1.0}}};
  const LcpResult r = ActiveSetLcp().solve(p);
  EXPECT_NE(r.status, LcpStatus::no_solution);
  EXPECT_EQ(LcpEnumeration().solve(p).status, LcpStatus::solved);
}

// Three modes of one point in a two-dimensional stress space: M = A A^T with the rows of A
// (1, 0), (0, 1), (1, 1) has rank 2. With q = (-1, -1, -1) the solution is z = (1, 1, 0),
// w = (0, 0, 1) (by hand).
class ThreeModesOfOnePoint final : public LcpColumns {
 public:
  explicit ThreeModesOfOnePoint(bool grouped) : grouped_(grouped) {
    const MatrixXd a{{1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}};
    p_ = {a * a.transpose(), VectorXd::Constant(3, -1.0)};
  }
  [[nodiscard]] Eigen::Index size() const override { return 3; }
  [[nodiscard]] const VectorXd& q() const override { return p_.q; }
  [[nodiscard]] MatrixXd columns(const std::vector<Eigen::Index>& cols) override {
    return DenseLcpColumns(p_).columns(cols);
  }
  [[nodiscard]] bool symmetric() const override { return true; }
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override { return grouped_ ? 0 : row; }
  [[nodiscard]] int group_rank(Eigen::Index /*row*/) const override { return grouped_ ? 2 : 1; }

 private:
  bool grouped_;
  LcpProblem p_;
};

TEST(ActiveSetLcp, AtMostTheRankOfAGroupIsActiveAtOnce) {
  ThreeModesOfOnePoint ungrouped(false);
  ActiveSetOptions block_only;
  block_only.projected_newton = false;
  EXPECT_NE(ActiveSetLcp(block_only).solve(ungrouped).status, LcpStatus::solved)
      << "all three rows active: a singular block";
  // Projected Newton damps the singular block and gets there all the same, to the accuracy
  // asked of a solution (1e-9 relative: the damped iterates approach it from inside).
  const LcpResult damped = ActiveSetLcp().solve(ungrouped);
  ASSERT_EQ(damped.status, LcpStatus::solved);
  EXPECT_NEAR(damped.z(0), 1.0, 1e-8);
  EXPECT_NEAR(damped.z(1), 1.0, 1e-8);
  EXPECT_NEAR(damped.w(2), 1.0, 1e-8);
  ThreeModesOfOnePoint grouped(true);
  const LcpResult r = ActiveSetLcp().solve(grouped);
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_NEAR(r.z(0), 1.0, 1e-12);
  EXPECT_NEAR(r.z(1), 1.0, 1e-12);
  EXPECT_EQ(r.z(2), 0.0);
  EXPECT_NEAR(r.w(2), 1.0, 1e-12);
}

// Symmetric positive semi-definite LCPs whose rows come in groups of three modes of a point
// with a two-dimensional stress space, as the analysis's: M = P S P^T with P block diagonal
// (three random gradients per point) and S symmetric positive definite, so every group's block
// has rank 2. q = w0 - M z0 with z0, w0 >= 0 is feasible at z0, hence solvable (a convex
// quadratic program bounded below); w = M z + q is the same at every solution.
class GroupedPsdLcp final : public LcpColumns {
 public:
  GroupedPsdLcp(Eigen::Index points, std::mt19937& rng) {
    const Eigen::Index m = 3 * points;
    MatrixXd p = MatrixXd::Zero(m, 2 * points);
    for (Eigen::Index g = 0; g < points; ++g)
      p.block(3 * g, 2 * g, 3, 2) = testing::random_matrix(3, 2, rng);
    const MatrixXd s = testing::random_spd(2 * points, rng);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    VectorXd z0(m), w0(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      z0(i) = unit(rng) < 0.5 ? unit(rng) : 0.0;
      w0(i) = unit(rng) < 0.5 ? unit(rng) : 0.0;
    }
    p_.m = p * s * p.transpose();
    p_.q = w0 - p_.m * z0;
  }
  [[nodiscard]] Eigen::Index size() const override { return p_.size(); }
  [[nodiscard]] const VectorXd& q() const override { return p_.q; }
  [[nodiscard]] MatrixXd columns(const std::vector<Eigen::Index>& cols) override {
    return DenseLcpColumns(p_).columns(cols);
  }
  [[nodiscard]] bool symmetric() const override { return true; }
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override { return row / 3; }
  [[nodiscard]] int group_rank(Eigen::Index /*row*/) const override { return 2; }
  [[nodiscard]] const LcpProblem& dense() const { return p_; }

 private:
  LcpProblem p_;
};

TEST(ActiveSetLcp, ProjectedNewtonSolvesGroupedSemiDefiniteProblemsAsLemkeDoes) {
  // The projected Newton iteration alone (it takes over after the first block-rule iteration):
  // every problem solved, with Lemke's w (unique for symmetric positive semi-definite M).
  ActiveSetOptions newton_at_once;
  newton_at_once.stall_iterations = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    GroupedPsdLcp p(15, rng);
    const LcpResult oracle = Lemke().solve(p.dense());
    ASSERT_EQ(oracle.status, LcpStatus::solved) << seed;
    const LcpResult r = ActiveSetLcp(newton_at_once).solve(p);
    ASSERT_EQ(r.status, LcpStatus::solved) << seed;
    EXPECT_LE(r.residuals.worst_relative(), 1e-9) << seed;
    EXPECT_LE((r.w - oracle.w).cwiseAbs().maxCoeff(), 1e-8 * p.q().cwiseAbs().maxCoeff()) << seed;
  }
}

TEST(ActiveSetLcp, ProjectedNewtonTakesOverWhereTheBlockRuleStalls) {
  // Grouped problems on which the block rule alone does not converge (it cycles, stalls or
  // meets a singular block): the default, which goes on with projected Newton, solves them.
  int rescued = 0;
  for (unsigned seed = 1; seed <= 100; ++seed) {
    std::mt19937 rng(seed);
    GroupedPsdLcp p(15, rng);
    ActiveSetOptions block_only;
    block_only.murty_after_cycle = false;
    block_only.projected_newton = false;
    GroupedPsdLcp copy = p;
    if (ActiveSetLcp(block_only).solve(copy).status == LcpStatus::solved)
      continue;
    const LcpResult oracle = Lemke().solve(p.dense());
    if (oracle.status != LcpStatus::solved)
      continue;  // degenerate pivots: no second method to compare with
    const LcpResult r = ActiveSetLcp().solve(p);
    ASSERT_EQ(r.status, LcpStatus::solved) << seed;
    EXPECT_LE((r.w - oracle.w).cwiseAbs().maxCoeff(), 1e-8 * p.q().cwiseAbs().maxCoeff()) << seed;
    ++rescued;
  }
  EXPECT_GE(rescued, 10) << "the problems must exercise the safeguard";
}

// The active-set equations of a dense symmetric LCP whose solves, asked only for their own w
// (Check::from_solve), report none of the violated rows: a solver that took such a w as a
// result would stop at the first iterate with a wrong answer.
class HidingEquations final : public ActiveSetEquations {
 public:
  explicit HidingEquations(LcpProblem p) : p_(std::move(p)) {}
  [[nodiscard]] Eigen::Index size() const override { return p_.q.size(); }
  [[nodiscard]] const VectorXd& q() const override { return p_.q; }
  [[nodiscard]] bool symmetric() const override { return true; }
  [[nodiscard]] double diagonal_bound(Eigen::Index row) const override { return p_.m(row, row); }
  using ActiveSetEquations::solve;
  Solution solve(const std::vector<Eigen::Index>& active, const Damping& damping,
                 Check check) override {
    const auto k = static_cast<Eigen::Index>(active.size());
    MatrixXd a(k, k);
    VectorXd rhs(k);
    for (Eigen::Index i = 0; i < k; ++i) {
      for (Eigen::Index j = 0; j < k; ++j)
        a(i, j) = p_.m(active[i], active[j]);
      rhs(i) = -p_.q(active[i]);
      if (damping.factor.size() > 0) {
        const double d = damping.factor(i) * p_.m(active[i], active[i]);
        a(i, i) += d;
        rhs(i) += d * damping.center(active[i]);
      }
    }
    Solution out;
    out.z = VectorXd::Zero(size());
    const VectorXd za = a.ldlt().solve(rhs);
    for (Eigen::Index i = 0; i < k; ++i)
      out.z(active[i]) = za(i);
    out.w = p_.m * out.z + p_.q;
    out.w_scale = p_.m.cwiseAbs() * out.z.cwiseAbs() + p_.q.cwiseAbs();
    if (check == Check::from_solve) {
      out.w = out.w.cwiseMax(0.0);
      out.measured = false;
    }
    out.regular = true;
    return out;
  }
  LcpResult result(LcpStatus status, VectorXd z, int steps) override {
    LcpResult r;
    r.status = status;
    r.w = p_.m * z + p_.q;
    r.residuals = measure(z, r.w, VectorXd(p_.m.cwiseAbs() * z.cwiseAbs() + p_.q.cwiseAbs()));
    r.z = std::move(z);
    r.steps = steps;
    return r;
  }

 private:
  LcpProblem p_;
};

TEST(ActiveSetLcp, AWTheSolveDidNotMeasureIsNeverTakenAsTheResult) {
  // Lemke's solution (unique: M positive definite), whether projected Newton takes over at
  // once or after the block rule, from the best iterate as measured.
  for (int stall : {0, 1}) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
      std::mt19937 rng(seed);
      const LcpProblem p{testing::random_spd(60, rng), testing::random_vector(60, rng)};
      const LcpResult lemke = Lemke().solve(p);
      ASSERT_EQ(lemke.status, LcpStatus::solved);
      ActiveSetOptions options;
      options.stall_iterations = stall;
      HidingEquations equations(p);
      const LcpResult r = ActiveSetLcp(options).solve(equations);
      ASSERT_EQ(r.status, LcpStatus::solved) << "seed " << seed << " stall " << stall;
      EXPECT_LE(r.residuals.worst_relative(), 1e-9);
      EXPECT_LE((r.z - lemke.z).cwiseAbs().maxCoeff(), 1e-9 * lemke.z.cwiseAbs().maxCoeff());
    }
  }
}

TEST(ActiveSetLcp, AnInterruptStopsProjectedNewtonAtAMeasuredIterate) {
  // Every iterate of projected Newton shown (interrupt_after 1): the first one shown has z >= 0
  // and its w = M z + q (formed here), and the solve returns it as interrupted. An interrupt
  // that never stops changes nothing: Lemke's solution.
  ActiveSetOptions options;
  options.stall_iterations = 0;
  options.interrupt_after = 1;
  int interrupted = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 rng(seed);
    const LcpProblem p{testing::random_spd(60, rng), testing::random_vector(60, rng)};
    const LcpResult lemke = Lemke().solve(p);
    ASSERT_EQ(lemke.status, LcpStatus::solved);
    int calls = 0;
    VectorXd shown;
    const ActiveSetLcp::Interrupt stop = [&](const LcpResult& iterate) {
      ++calls;
      shown = iterate.z;
      EXPECT_GE(iterate.z.minCoeff(), 0.0);
      const VectorXd w = p.m * iterate.z + p.q;
      EXPECT_LE((iterate.w - w).cwiseAbs().maxCoeff(), 1e-12 * w.cwiseAbs().maxCoeff());
      return true;
    };
    HidingEquations equations(p);
    const LcpResult r = ActiveSetLcp(options).solve(equations, nullptr, &stop);
    if (calls > 0) {
      ++interrupted;
      EXPECT_EQ(calls, 1);
      EXPECT_EQ(r.status, LcpStatus::interrupted);
      EXPECT_EQ(r.z, shown);
    }
    const ActiveSetLcp::Interrupt never = [](const LcpResult&) { return false; };
    HidingEquations again(p);
    const LcpResult solved = ActiveSetLcp(options).solve(again, nullptr, &never);
    ASSERT_EQ(solved.status, LcpStatus::solved) << "seed " << seed;
    EXPECT_LE((solved.z - lemke.z).cwiseAbs().maxCoeff(), 1e-9 * lemke.z.cwiseAbs().maxCoeff());
  }
  EXPECT_GE(interrupted, 1) << "projected Newton never took a step that was not a solution";
}

}  // namespace
}  // namespace bimrock
