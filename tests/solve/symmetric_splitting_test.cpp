// The splitting method (solve/symmetric_splitting.hpp). Expected answers: planted solutions (q
// built from a chosen complementary z*, w* of a P-matrix M, so the solution is unique), and a
// one-row problem whose iterates are worked by hand.
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/symmetric_splitting.hpp>

#include "solve/random_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// The splitting of (q, B + E), each inner LCP solved by Lemke on the dense B, each proposal
// tried by solving M_AA z_A = -q_A and checking z_A >= 0, w >= 0 (kept in `solution`).
struct Split {
  MatrixXd b, e;
  VectorXd q;
  VectorXd solution{};
  int inner_solves = 0;

  SplittingResult run(const SplittingOptions& options = {}) {
    const SplittingRemainder remainder = [&](const VectorXd& z) { return VectorXd(e * z); };
    const SymmetricLcpSolve solve = [&](const VectorXd& shifted, const VectorXd* /*warm*/,
                                        bool /*after_newton*/) {
      ++inner_solves;
      return Lemke{}.solve({b, shifted});
    };
    const ActiveSetProposal propose = [&](const VectorXd& active) {
      const MatrixXd m = b + e;
      std::vector<Eigen::Index> rows;
      for (Eigen::Index i = 0; i < q.size(); ++i)
        if (active(i) > 0.0)
          rows.push_back(i);
      VectorXd z = VectorXd::Zero(q.size());
      if (!rows.empty()) {
        const auto k = static_cast<Eigen::Index>(rows.size());
        MatrixXd m_aa(k, k);
        VectorXd q_a(k);
        const auto row = [&](Eigen::Index i) { return rows[static_cast<std::size_t>(i)]; };
        for (Eigen::Index i = 0; i < k; ++i) {
          q_a(i) = q(row(i));
          for (Eigen::Index j = 0; j < k; ++j)
            m_aa(i, j) = m(row(i), row(j));
        }
        const VectorXd z_a = m_aa.partialPivLu().solve(-q_a);
        for (Eigen::Index i = 0; i < k; ++i)
          z(row(i)) = z_a(i);
      }
      const VectorXd w = m * z + q;
      const double tol = 1e-10 * (q.cwiseAbs().maxCoeff() + 1.0);
      if (z.minCoeff() < -tol || w.minCoeff() < -tol)
        return ProposalOutcome{.solved = false, .z = z};
      solution = z;
      return ProposalOutcome{.solved = true, .z = {}};
    };
    return solve_by_splitting(q, remainder, solve, propose, VectorXd::Zero(q.size()), nullptr,
                              options);
  }
};

// A planted LCP (q, B + E) of 40 rows: B random symmetric positive definite, E a random matrix
// (made skew-symmetric where `skew`) scaled to `scale` times B's least eigenvalue, and q such
// that z* (every third row active) solves it.
struct PlantedSplit {
  Split split;
  VectorXd z_star;
};
PlantedSplit planted(unsigned seed, double scale, bool skew) {
  std::mt19937 rng(seed);
  const Eigen::Index n = 40;
  PlantedSplit p;
  Split& s = p.split;
  s.b = testing::random_spd(n, rng);
  const double least = Eigen::SelfAdjointEigenSolver<MatrixXd>(s.b).eigenvalues()(0);
  s.e = MatrixXd::Random(n, n);
  if (skew)
    s.e = MatrixXd(s.e - s.e.transpose());
  s.e *= scale * least / s.e.norm();
  p.z_star = VectorXd::Zero(n);
  VectorXd w_star = VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i)
    (i % 3 == 0 ? p.z_star(i) : w_star(i)) = 1.0 + 0.1 * static_cast<double>(i);
  s.q = testing::planted_q(s.b + s.e, p.z_star, w_star);
  return p;
}

TEST(SymmetricSplitting, FindsThePlantedSolutionOfAWeaklyNonSymmetricLcp) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    // E small against B's least eigenvalue: M = B + E stays positive definite (a P-matrix).
    PlantedSplit p = planted(seed, 0.3, false);
    const SplittingResult r = p.split.run();
    ASSERT_TRUE(r.solved) << seed;
    EXPECT_LE((p.split.solution - p.z_star).cwiseAbs().maxCoeff(), 1e-9) << seed;
    EXPECT_GE(r.proposals, 1) << seed;
    EXPECT_LT(r.iterations, SplittingOptions{}.max_iterations) << seed;
  }
}

TEST(SymmetricSplitting, AcceleratesIteratesThatSwapRowsBackAndForth) {
  // One row: B = 1, E = 1.5, q = -1, so M = 2.5 and z* = 0.4. The plain splitting,
  // z_k+1 = max(0, 1 - 1.5 z_k) from 0, gives 1, 0, 1, 0, ...: the active set alternates and is
  // never proposed. Anderson's method on y = 1.5 z, worked by hand: y = 0 gives z = 1 and the
  // image 1.5; y = 1.5 gives z = 0 and the image 0; the residuals 1.5 and -1.5 combine to zero
  // with weights 1/2, so y = 0.75, which gives z = 0.25 > 0 and the image 0.375. The residual
  // differences -3 and 1.125 (one row) leave a one-column least squares problem, gamma = 1/8,
  // so y = 0.375 + 1.5 / 8 = 0.5625 and z = 0.4375 > 0: the set {z > 0} held, and its proposal
  // solves the LCP in the fourth iterate. (Without Newton steps: the one below.)
  Split s{.b = MatrixXd::Constant(1, 1, 1.0),
          .e = MatrixXd::Constant(1, 1, 1.5),
          .q = VectorXd::Constant(1, -1.0)};
  const SplittingResult accelerated = s.run({.newton = false});
  ASSERT_TRUE(accelerated.solved);
  EXPECT_NEAR(s.solution(0), 0.4, 1e-14);
  EXPECT_EQ(accelerated.iterations, 4);
  EXPECT_EQ(accelerated.proposals, 1);

  Split plain = s;
  plain.solution = VectorXd();
  const SplittingResult r =
      plain.run({.anderson_depth = 0, .damped_after = false, .newton = false});
  EXPECT_FALSE(r.solved);
  EXPECT_EQ(r.proposals, 0);
  EXPECT_EQ(r.iterations, SplittingOptions{}.max_iterations);
}

TEST(SymmetricSplitting, DampsTheIteratesWhereTheFirstRunEndsUnsolved) {
  // The same row, the first run plain (no combinations): it ends unsolved after its 40
  // iterates, and the damped run goes on. Three iterates of 1, 0, 1 change the set each time,
  // so the relaxation halves: the iteration's factor -1.5 becomes 1 - 0.5 - 0.75 = -0.25, the
  // iterates settle on z > 0, whose proposal solves the LCP.
  Split s{.b = MatrixXd::Constant(1, 1, 1.0),
          .e = MatrixXd::Constant(1, 1, 1.5),
          .q = VectorXd::Constant(1, -1.0)};
  const SplittingResult r = s.run({.anderson_depth = 0, .newton = false});
  ASSERT_TRUE(r.solved);
  EXPECT_NEAR(s.solution(0), 0.4, 1e-14);
  EXPECT_GT(r.iterations, SplittingOptions{}.max_iterations);
  // The damped run's first two iterates (y = 0, then y = 1.5) are the first run's: taken from
  // it, not solved again.
  EXPECT_EQ(s.inner_solves, r.iterations - 2);
}

TEST(SymmetricSplitting, TakesBackANewtonStepThatDoesNotLowerTheResidual) {
  // The same row, with Newton steps, worked by hand. y = 0 gives z = 1 (residual |1.5 - 0|);
  // y = 1.5 gives z = 0, which changes one row: proposed. Its equations have no row, so
  // z_N = 0, w = -1 < 0: not a solution, and the Newton step goes to y = E z_N = 0, whose inner
  // LCP gives z = 1 again: residual 1.5, not below 0.9 x 1.5. The step is taken back to the
  // accelerated y = 0.75 (z = 0.25), then y = 0.5625 (z = 0.4375) keeps the set {z > 0}, whose
  // proposal solves the LCP: four iterates and the inner LCP of the step taken back.
  Split s{.b = MatrixXd::Constant(1, 1, 1.0),
          .e = MatrixXd::Constant(1, 1, 1.5),
          .q = VectorXd::Constant(1, -1.0)};
  const SplittingResult r = s.run();
  ASSERT_TRUE(r.solved);
  EXPECT_NEAR(s.solution(0), 0.4, 1e-14);
  EXPECT_EQ(r.iterations, 4);
  EXPECT_EQ(r.proposals, 2);
  EXPECT_EQ(s.inner_solves, 5);
}

TEST(SymmetricSplitting, NewtonStepsReachThePlantedSolutionInFewerIterates) {
  // As the first test, with E skew-symmetric and twenty times B's least eigenvalue: M = B + E
  // stays positive definite (z.E z = 0), so z* is the only solution, but the iterates converge
  // slowly, and the proposals' equations, solved on sets that differ from z*'s in a few rows,
  // step nearer it.
  for (unsigned seed = 1; seed <= 5; ++seed) {
    PlantedSplit p = planted(seed, 20.0, true);
    Split& s = p.split;
    const VectorXd& z_star = p.z_star;
    Split without = s;
    const SplittingResult r = s.run();
    const SplittingResult anderson = without.run({.newton = false});
    ASSERT_TRUE(r.solved) << seed;
    ASSERT_TRUE(anderson.solved) << seed;
    EXPECT_LE((s.solution - z_star).cwiseAbs().maxCoeff(), 1e-9) << seed;
    EXPECT_LE((without.solution - z_star).cwiseAbs().maxCoeff(), 1e-9) << seed;
    // 4-6 inner LCPs against 8-13 (seeds 1-5).
    EXPECT_LT(s.inner_solves, without.inner_solves) << seed;
  }
}

TEST(SymmetricSplitting, SaysSoWhereAnInnerLcpHasNoSolution) {
  // B = 0 with q < 0: the first inner LCP (q, B) has none, whatever M is.
  Split s{
      .b = MatrixXd::Zero(2, 2), .e = MatrixXd::Identity(2, 2), .q = VectorXd::Constant(2, -1.0)};
  const SplittingResult r = s.run();
  EXPECT_FALSE(r.solved);
  EXPECT_EQ(r.z.size(), 0);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(s.inner_solves, 1);
}

}  // namespace
}  // namespace bimrock
