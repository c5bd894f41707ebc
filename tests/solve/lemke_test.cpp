// Lemke's method. Expected numbers: small LCPs solved by hand (the working is in each test),
// the brute-force enumeration of all complementary bases (an independent oracle, tested in
// lcp_enumeration_test.cpp), planted solutions (q built from a chosen complementary pair), a
// linear program whose optimum is checked by hand through LP duality, and Farkas certificates
// of infeasibility checked directly against M and q.
#include <fstream>

#include <gtest/gtest.h>

#include <bimrock/solve/lcp_enumeration.hpp>
#include <bimrock/solve/lemke.hpp>

#include "solve/random_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

LcpResult lemke(const LcpProblem& p, LemkeOptions options = {}) {
  Lemke solver(std::move(options));
  return solver.solve(p);
}

void expect_solved(const LcpResult& r, double tolerance = 1e-9) {
  ASSERT_EQ(r.status, LcpStatus::solved) << to_string(r.status);
  EXPECT_GE(r.residuals.min_z, 0.0);
  EXPECT_LE(r.residuals.worst_relative(), tolerance);
  EXPECT_TRUE(r.ray.size() == 0);
}

/// r >= 0, M^T r <= 0 and q . r < 0 prove that no z >= 0 gives w = M z + q >= 0, since then
/// r . w = (M^T r) . z + q . r < 0 (Farkas). Checked here, independently of the solver.
void expect_infeasibility_certificate(const LcpProblem& p, const VectorXd& r) {
  ASSERT_EQ(r.size(), p.size());
  EXPECT_NEAR(r.maxCoeff(), 1.0, 1e-12);
  EXPECT_GE(r.minCoeff(), 0.0);
  const VectorXd mtr = p.m.transpose() * r;
  EXPECT_LE(mtr.maxCoeff(), 1e-9 * p.m.cwiseAbs().maxCoeff());
  EXPECT_LT(p.q.dot(r), -1e-3 * p.q.cwiseAbs().maxCoeff());
}

TEST(Lemke, NonnegativeQIsSolvedByZeroWithoutPivots) {
  std::mt19937 rng(1);
  const LcpProblem p{testing::random_matrix(3, 3, rng), VectorXd{{1.0, 0.0, 2.0}}};
  const LcpResult r = lemke(p);
  expect_solved(r, 0.0);
  EXPECT_EQ(r.steps, 0);
  EXPECT_EQ(r.z, VectorXd::Zero(3));
  EXPECT_EQ(r.w, p.q);
}

TEST(Lemke, EmptyProblemIsSolved) {
  const LcpResult r = lemke(LcpProblem{MatrixXd(0, 0), VectorXd(0)});
  EXPECT_EQ(r.status, LcpStatus::solved);
  EXPECT_EQ(r.z.size(), 0);
}

TEST(Lemke, OneByOne) {
  // w = 2 z - 4: z = 0 gives w = -4 < 0, so w = 0 and z = 2.
  const LcpResult r = lemke({MatrixXd{{2.0}}, VectorXd{{-4.0}}});
  expect_solved(r, 1e-15);
  EXPECT_DOUBLE_EQ(r.z(0), 2.0);
  EXPECT_DOUBLE_EQ(r.w(0), 0.0);
}

TEST(Lemke, TwoByTwoWithBothRowsActive) {
  // w = 0: [2 1; 1 2] z = [5; 6] gives z = (4/3, 7/3) by Cramer's rule, both positive.
  const LcpResult r = lemke({MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{-5.0, -6.0}}});
  expect_solved(r, 1e-14);
  EXPECT_NEAR(r.z(0), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(r.z(1), 7.0 / 3.0, 1e-14);
  EXPECT_NEAR(r.w.norm(), 0.0, 1e-14);
}

TEST(Lemke, TwoByTwoWithOneRowActive) {
  // z2 = 0, w1 = 0: 2 z1 - 1 = 0 gives z1 = 1/2 and w2 = z1 + 3 = 7/2 >= 0.
  const LcpResult r = lemke({MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{-1.0, 3.0}}});
  expect_solved(r, 1e-15);
  EXPECT_DOUBLE_EQ(r.z(0), 0.5);
  EXPECT_EQ(r.z(1), 0.0);
  EXPECT_DOUBLE_EQ(r.w(1), 3.5);
}

TEST(Lemke, ZeroMatrixWithNegativeQHasNoSolution) {
  // w = 0 z - 1 = -1 < 0 for every z: no solution; r = 1 is the certificate.
  const LcpProblem p{MatrixXd{{0.0}}, VectorXd{{-1.0}}};
  const LcpResult r = lemke(p);
  EXPECT_EQ(r.status, LcpStatus::no_solution);
  expect_infeasibility_certificate(p, r.ray);
}

TEST(Lemke, SemidefinitePairWithNegativeQHasNoSolution) {
  // w1 + w2 = (z1 - z2 - 1) + (z2 - z1 - 1) = -2 for every z, so w >= 0 is impossible.
  // M = [1 -1; -1 1] is positive semi-definite (eigenvalues 0 and 2): Lemke must end on a ray.
  const LcpProblem p{MatrixXd{{1.0, -1.0}, {-1.0, 1.0}}, VectorXd{{-1.0, -1.0}}};
  const LcpResult r = lemke(p);
  EXPECT_EQ(r.status, LcpStatus::no_solution);
  expect_infeasibility_certificate(p, r.ray);
  EXPECT_NEAR(r.ray(0), 1.0, 1e-12);  // r = (1, 1): M^T r = 0, q . r = -2
  EXPECT_NEAR(r.ray(1), 1.0, 1e-12);
}

TEST(Lemke, StiffnessThatCancelsToRoundOffIsAMechanismNotAHugeMultiplier) {
  // (0.1 + 0.2) - 0.3 is 5.6e-17 in doubles but 0 exactly: row 2 has no stiffness and w2 = -1
  // for every z. Pivoting on the residue would report z2 = 1.8e16 as a "solution".
  const double residue = (0.1 + 0.2) - 0.3;
  ASSERT_GT(residue, 0.0);
  const LcpProblem p{MatrixXd{{1.0, 0.0}, {0.0, residue}}, VectorXd{{-1.0, -1.0}}};
  const LcpResult r = lemke(p);
  EXPECT_EQ(r.status, LcpStatus::no_solution);
  ASSERT_EQ(r.ray.size(), 2);
  EXPECT_EQ(r.ray(0), 0.0);
  EXPECT_EQ(r.ray(1), 1.0);
}

// ---- against the enumeration oracle on problems with exactly one solution ----

enum class Kind { spd, p_matrix };
struct OracleCase {
  Kind kind;
  int n;
};

class LemkeVsEnumeration : public ::testing::TestWithParam<OracleCase> {};

TEST_P(LemkeVsEnumeration, FindsTheUniqueSolution) {
  const auto [kind, n] = GetParam();
  for (unsigned seed = 0; seed < 10; ++seed) {
    std::mt19937 rng(100 * seed + static_cast<unsigned>(n));
    LcpProblem p;
    p.m = kind == Kind::spd ? testing::random_spd(n, rng) : testing::random_p_matrix(n, rng);
    p.q = testing::random_vector(n, rng);
    LcpEnumeration oracle;
    const LcpResult expected = oracle.solve(p);
    ASSERT_EQ(expected.status, LcpStatus::solved);  // P-matrix: always exactly one solution
    const LcpResult r = lemke(p);
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_solved(r, 1e-12);
    EXPECT_LE((r.z - expected.z).cwiseAbs().maxCoeff(), 1e-10 * (1.0 + expected.z.norm()));
    EXPECT_LE(r.steps, 2 * n + 1);
  }
}

std::vector<OracleCase> oracle_cases() {
  std::vector<OracleCase> cases;
  for (Kind kind : {Kind::spd, Kind::p_matrix}) {
    for (int n = 2; n <= 10; ++n)
      cases.push_back({kind, n});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(RandomProblems, LemkeVsEnumeration, ::testing::ValuesIn(oracle_cases()),
                         [](const auto& test) {
                           return std::string(test.param.kind == Kind::spd ? "spd" : "p_matrix") +
                                  "_n" + std::to_string(test.param.n);
                         });

// ---- degenerate problems ----

TEST(Lemke, EqualEntriesOfQAreTiesResolvedLexicographically) {
  // Every q_i equal: the first ratio test ties in every row.
  for (unsigned seed = 0; seed < 5; ++seed) {
    std::mt19937 rng(seed);
    const LcpProblem p{testing::random_spd(6, rng), -VectorXd::Ones(6)};
    const LcpResult expected = LcpEnumeration().solve(p);
    const LcpResult r = lemke(p);
    expect_solved(r, 1e-12);
    EXPECT_LE((r.z - expected.z).cwiseAbs().maxCoeff(), 1e-10);
  }
}

TEST(Lemke, ZeroEntriesOfQAreDegenerateButSolved) {
  std::mt19937 rng(7);
  const LcpProblem p{testing::random_p_matrix(5, rng), VectorXd{{0.0, -1.0, 0.0, -1.0, 0.0}}};
  const LcpResult expected = LcpEnumeration().solve(p);
  const LcpResult r = lemke(p);
  expect_solved(r, 1e-12);
  EXPECT_LE((r.z - expected.z).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(Lemke, DuplicateRowsAndDoublyDegeneratePairs) {
  // M = B^T B with columns 0 and 3 of B equal: rows (and columns) 0 and 3 of M are equal and
  // null(M) = span(e0 - e3). Planted z* = (1, 0, 1/2, 0), w* = 0 (pair 1 has z = w = 0).
  // M is symmetric positive semi-definite, so every solution has the same w = w* = 0, and
  // z - z* lies in null(M): z1 = 0, z2 = 1/2 and z0 + z3 = 1.
  std::mt19937 rng(11);
  MatrixXd b(4, 4);
  b.leftCols(3) = testing::random_matrix(4, 3, rng);
  b.col(3) = b.col(0);
  const MatrixXd m = b.transpose() * b;
  const VectorXd z_star{{1.0, 0.0, 0.5, 0.0}};
  const LcpProblem p{m, testing::planted_q(m, z_star, VectorXd::Zero(4))};
  const LcpResult r = lemke(p);
  expect_solved(r);
  EXPECT_NEAR(r.z(1), 0.0, 1e-12);
  EXPECT_NEAR(r.z(2), 0.5, 1e-12);
  EXPECT_NEAR(r.z(0) + r.z(3), 1.0, 1e-12);
  EXPECT_LE(r.w.cwiseAbs().maxCoeff(), 1e-12 * m.norm());
}

TEST(Lemke, BealesCyclingLinearProgramAsAnLcp) {
  // Beale's (1955) degenerate LP, on which the simplex method with the textbook pivot rule
  // cycles: min -3/4 x1 + 150 x2 - 1/50 x3 + 6 x4 subject to
  //   1/4 x1 - 60 x2 - 1/25 x3 + 9 x4 <= 0,  1/2 x1 - 90 x2 - 1/50 x3 + 3 x4 <= 0,  x3 <= 1.
  // Its optimality conditions are the LCP z = (x, y), M = [0 A^T; -A 0], q = (c, b) (M is
  // positive semi-definite). By hand: x = (1/25, 0, 1, 0) with objective -1/20 is feasible, and
  // y = (0, 3/2, 1/20) is dual feasible (reduced costs 0, 15, 0, 21/2) with -b . y = -1/20, so
  // both are optimal; the positive reduced costs and y2, y3 > 0 make them unique.
  const MatrixXd a{{0.25, -60.0, -0.04, 9.0}, {0.5, -90.0, -0.02, 3.0}, {0.0, 0.0, 1.0, 0.0}};
  const VectorXd c{{-0.75, 150.0, -0.02, 6.0}};
  const VectorXd b{{0.0, 0.0, 1.0}};
  LcpProblem p{MatrixXd::Zero(7, 7), VectorXd(7)};
  p.m.topRightCorner(4, 3) = a.transpose();
  p.m.bottomLeftCorner(3, 4) = -a;
  p.q << c, b;
  const LcpResult r = lemke(p);
  expect_solved(r, 1e-12);
  const VectorXd expected{{1.0 / 25.0, 0.0, 1.0, 0.0, 0.0, 1.5, 1.0 / 20.0}};
  EXPECT_LE((r.z - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(c.dot(r.z.head(4)), -1.0 / 20.0, 1e-14);
}

// ---- singular positive semi-definite M (a mechanism) ----

/// M = A^T A with A = G (I - v v^T), v = (1, ..., 1) / sqrt(n) >= 0, G random 5 x n: rank 5,
/// and M v = 0 up to round-off.
MatrixXd mechanism_matrix(Eigen::Index n, std::mt19937& rng, VectorXd& v) {
  v = VectorXd::Ones(n) / std::sqrt(static_cast<double>(n));
  const MatrixXd a =
      testing::random_matrix(5, n, rng) * (MatrixXd::Identity(n, n) - v * v.transpose());
  return a.transpose() * a;
}

TEST(Lemke, SingularSemidefiniteWithASolution) {
  std::mt19937 rng(21);
  VectorXd v;
  const MatrixXd m = mechanism_matrix(8, rng, v);
  const VectorXd z_star{{1.0, 0.0, 2.0, 0.0, 0.0, 0.5, 0.0, 0.0}};
  const VectorXd w_star{{0.0, 1.0, 0.0, 0.3, 0.0, 0.0, 2.0, 0.0}};
  const LcpProblem p{m, testing::planted_q(m, z_star, w_star)};
  const LcpResult r = lemke(p);
  expect_solved(r);
  // M symmetric semi-definite: w is the same for every solution.
  EXPECT_LE((r.w - w_star).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + m.norm()));
}

TEST(Lemke, SingularSemidefiniteWithoutASolutionEndsOnARay) {
  // q . v = -1 < 0 with v >= 0 and M v = 0: v itself certifies that no solution exists.
  // In doubles M v is only ~1e-16, so the exact LCP of the stored M has a solution with
  // multipliers ~1e16: the solver must recognise the mechanism instead.
  for (unsigned seed = 0; seed < 5; ++seed) {
    std::mt19937 rng(30 + seed);
    VectorXd v;
    LcpProblem p;
    p.m = mechanism_matrix(8, rng, v);
    p.q = testing::random_vector(8, rng);
    p.q -= (p.q.dot(v) + 1.0) * v;
    const LcpResult r = lemke(p);
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_EQ(r.status, LcpStatus::no_solution);
    expect_infeasibility_certificate(p, r.ray);
    EXPECT_EQ(LcpEnumeration().solve(p).status, LcpStatus::no_solution);
  }
}

// ---- scaling ----

TEST(Lemke, BadlyScaledRowsAndColumnsAreSolvedToRelativeAccuracy) {
  // Scaling rows of (M, q) by D leaves z unchanged; scaling columns of M by C maps z to C^-1 z.
  // The spread of the scalings (1e10 overall) stays within 1 / zero_tolerance: entries below
  // zero_tolerance * max|M| are round-off residues by definition (LemkeOptions).
  std::mt19937 rng(41);
  const Eigen::Index n = 8;
  const LcpProblem base{testing::random_spd(n, rng), testing::random_vector(n, rng)};
  const LcpResult expected = LcpEnumeration().solve(base);
  ASSERT_EQ(expected.status, LcpStatus::solved);
  VectorXd d(n), c(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    d(i) = i % 2 == 0 ? 1e5 : 1.0;
    c(i) = i % 3 == 0 ? 1e-5 : 1.0;
  }
  for (int variant = 0; variant < 3; ++variant) {
    const VectorXd row = variant != 1 ? d : VectorXd::Ones(n);
    const VectorXd col = variant != 0 ? c : VectorXd::Ones(n);
    const LcpProblem p{row.asDiagonal() * base.m * col.asDiagonal(), row.cwiseProduct(base.q)};
    const VectorXd z_expected = expected.z.cwiseQuotient(col);
    const LcpResult r = lemke(p);
    SCOPED_TRACE("variant " + std::to_string(variant));
    expect_solved(r, 1e-9);
    // z_i is measured in units of 1 / col_i.
    const double size = expected.z.cwiseAbs().maxCoeff();
    EXPECT_LE((r.z - z_expected).cwiseProduct(col).cwiseAbs().maxCoeff(), 1e-9 * size);
  }
}

// ---- options and limits ----

TEST(Lemke, CoveringVectorDoesNotChangeTheUniqueSolution) {
  std::mt19937 rng(51);
  const LcpProblem p{testing::random_p_matrix(6, rng), testing::random_vector(6, rng)};
  LemkeOptions options;
  options.covering = VectorXd{{1.0, 2.0, 3.0, 0.5, 0.25, 4.0}};
  const LcpResult r = lemke(p, options);
  expect_solved(r, 1e-12);
  EXPECT_LE((r.z - LcpEnumeration().solve(p).z).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(Lemke, PivotBudgetGivesIterationLimitNotASolution) {
  std::mt19937 rng(61);
  const LcpProblem p{testing::random_spd(10, rng), -VectorXd::Ones(10)};
  LemkeOptions options;
  options.max_pivots = 3;
  const LcpResult r = lemke(p, options);
  EXPECT_EQ(r.status, LcpStatus::iteration_limit);
  EXPECT_EQ(r.steps, 3);
  EXPECT_GT(r.residuals.worst_relative(), 1e-3);
}

TEST(Lemke, IsUsableThroughTheSolverInterface) {
  std::unique_ptr<LcpSolver> solver = std::make_unique<Lemke>();
  EXPECT_EQ(solver->name(), "lemke");
  const LcpProblem p{MatrixXd{{2.0}}, VectorXd{{-4.0}}};
  solver->setup(p);
  const VectorXd guess{{1.0}};
  EXPECT_DOUBLE_EQ(solver->solve(p, &guess).z(0), 2.0);
}

}  // namespace
}  // namespace bimrock

namespace bimrock {
namespace {

// ---- LCPs recorded from the analysis (BIMROCK_DEBUG_LCP_DUMP) ----

LcpProblem read_fixture(const std::string& name) {
  std::ifstream in(std::string(BIMROCK_SOURCE_DIR) + "/tests/solve/data/" + name);
  return read_lcp(in);
}

TEST(Lemke, SlidingBlockAtCollapseHasNoSolution) {
  // A block on a plane loaded past its friction limit: rows 0 (slip+ at one end point) and 3
  // (slip+ at the other) sum to an exactly zero row of M (a rigid sliding mechanism: the
  // cancellation leaves residues of 1e-8 beside entries of 4e8) with q_0 + q_3 < 0. The
  // certificate r = e_0 + e_3 is checked here in the measure that matters for a mechanism:
  // relative to the terms of the rows involved, |q| . r, not to the largest |q| of the problem.
  const LcpProblem p = read_fixture("sliding_block_at_collapse.lcp");
  const LcpResult r = lemke(p);
  ASSERT_EQ(r.status, LcpStatus::no_solution) << to_string(r.status);
  ASSERT_EQ(r.ray.size(), p.size());
  EXPECT_GE(r.ray.minCoeff(), 0.0);
  EXPECT_LE((p.m.transpose() * r.ray).maxCoeff(), 1e-9 * p.m.cwiseAbs().maxCoeff());
  EXPECT_LT(p.q.dot(r.ray), -0.5 * p.q.cwiseAbs().dot(r.ray));
}

}  // namespace
}  // namespace bimrock
