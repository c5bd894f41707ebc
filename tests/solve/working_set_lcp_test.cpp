// Lemke on a working set of rows. Expected solutions: planted solutions (q built from a chosen
// complementary z*, w*), Lemke on the whole problem (positive definite: the solution is unique),
// and hand-made infeasible problems whose Farkas certificate is known.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/working_set_lcp.hpp>

#include "solve/counting_columns.hpp"
#include "solve/random_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A planted problem with `n` rows, every `stride`-th active.
LcpProblem planted(Eigen::Index n, int stride, unsigned seed, VectorXd& z_star) {
  std::mt19937 rng(seed);
  const MatrixXd m = testing::random_spd(n, rng);
  z_star = VectorXd::Zero(n);
  VectorXd w_star = VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i)
    (i % stride == 0 ? z_star(i) : w_star(i)) = 1.0 + 0.01 * static_cast<double>(i);
  return {m, testing::planted_q(m, z_star, w_star)};
}

TEST(WorkingSetLcp, FindsThePlantedSolutionFromAPartialSetFormingFewColumns) {
  // 300 rows, 15 active; the first working set holds only 5 of them: the rows the solution
  // violates join it round by round, and the columns of rows that never join are not formed.
  VectorXd z_star;
  const LcpProblem p = planted(300, 20, 3, z_star);
  testing::CountingColumns columns(p);
  Lemke lemke;
  const LcpResult r = solve_on_working_set(columns, {0, 20, 40, 60, 80}, lemke);
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_LE((r.z - z_star).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LE(r.residuals.worst_relative(), 1e-9);
  EXPECT_LT(columns.asked.size(), static_cast<std::size_t>(300 / 2));
  std::vector<Eigen::Index> sorted = columns.asked;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "asked twice";
}

TEST(WorkingSetLcp, AgreesWithLemkeOnTheWholeProblem) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 rng(seed);
    const Eigen::Index n = 120;
    const LcpProblem p{testing::random_spd(n, rng), testing::random_vector(n, rng)};
    Lemke lemke;
    const LcpResult whole = lemke.solve(p);
    ASSERT_EQ(whole.status, LcpStatus::solved) << seed;
    DenseLcpColumns columns(p);
    const LcpResult r = solve_on_working_set(columns, {}, lemke);
    ASSERT_EQ(r.status, LcpStatus::solved) << seed;
    EXPECT_LE((r.z - whole.z).cwiseAbs().maxCoeff(), 1e-9 * whole.z.cwiseAbs().maxCoeff()) << seed;
  }
}

TEST(WorkingSetLcp, ANonNegativeQIsSolvedByZeroWithoutAnyColumn) {
  const LcpProblem p{MatrixXd::Identity(3, 3), VectorXd{{0.0, 1.0, 2.0}}};
  testing::CountingColumns columns(p);
  Lemke lemke;
  const LcpResult r = solve_on_working_set(columns, {}, lemke);
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_EQ(r.z.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_TRUE(columns.asked.empty());
}

// [1 -1; -1 1] with q = (-1, -1) has no solution (w_0 + w_1 = -2 for every z; certificate
// r = (1, 1)), embedded in a larger problem whose other rows are comfortably satisfied.
LcpProblem infeasible_pair_in(Eigen::Index n, bool symmetric) {
  MatrixXd m = MatrixXd::Identity(n, n);
  m(0, 1) = m(1, 0) = -1.0;
  VectorXd q = VectorXd::Constant(n, 1.0);
  q(0) = q(1) = -1.0;
  if (symmetric) {
    m(2, 0) = m(0, 2) = -0.1;  // couples an inactive row: (M^T r)_2 = -0.1 <= 0 still
  } else {
    m(2, 0) = 0.5;  // M is not symmetric: M^T r needs rows of M that the columns of W do not give
  }
  return {m, q};
}

TEST(WorkingSetLcp, CertifiesACollapseOnTheWholeProblemWhenMIsSymmetric) {
  const LcpProblem p = infeasible_pair_in(50, true);
  testing::CountingColumns columns(p);
  ASSERT_TRUE(columns.symmetric());
  Lemke lemke;
  const LcpResult r = solve_on_working_set(columns, {}, lemke);
  ASSERT_EQ(r.status, LcpStatus::no_solution);
  ASSERT_EQ(r.ray.size(), 50);
  EXPECT_NEAR(r.ray(0), r.ray(1), 1e-12);  // the certificate (1, 1, 0, ...), normalized
  EXPECT_GT(r.ray(0), 0.0);
  EXPECT_EQ(r.ray.tail(48).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(columns.asked.size(), 2u) << "only the two violated rows' columns are formed";
}

TEST(WorkingSetLcp, LeavesTheCollapseToLemkeOnTheWholeProblemWhenMIsNotSymmetric) {
  // The whole problem has no solution either, but proving it from the sub-LCP's ray needs the
  // rows of M off W, which column-by-column access does not give: the answer is a failure,
  // never no_solution (and never solved).
  const LcpProblem p = infeasible_pair_in(50, false);
  DenseLcpColumns columns(p);
  ASSERT_FALSE(columns.symmetric());
  Lemke lemke;
  const LcpResult r = solve_on_working_set(columns, {}, lemke);
  EXPECT_NE(r.status, LcpStatus::no_solution);
  EXPECT_NE(r.status, LcpStatus::solved);
  EXPECT_EQ(Lemke().solve(p).status, LcpStatus::no_solution) << "the whole problem decides";
}

}  // namespace
}  // namespace bimrock
