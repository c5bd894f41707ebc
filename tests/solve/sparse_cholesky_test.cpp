// The sparse Cholesky factor (CHOLMOD) on the kind of matrix the analysis builds: 6 unknowns
// per block, each block coupled to its neighbours on a grid. The solution must have a residual
// at round-off, and a matrix that is not positive definite must be refused whatever factor
// CHOLMOD picks: a small one is simplicial (LDL' by default, which would not fail), a large
// one supernodal.
#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <bimrock/solve/schur_solver.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

#include "solve/random_lcp.hpp"

namespace bimrock {
namespace {

// The lower triangle of a side x side grid of blocks, each coupled to the next in x and in y
// by a random positive definite 12 x 12 block, plus the identity: positive definite.
CholmodMatrix grid(int side, unsigned seed) {
  std::mt19937 rng(seed);
  const int n = 6 * side * side;
  std::vector<Eigen::Triplet<double, std::int64_t>> entries;
  auto couple = [&](int a, int b) {
    const Eigen::MatrixXd k = testing::random_spd(12, rng);
    const int at[2] = {6 * a, 6 * b};
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) {
        const int row = at[i / 6] + i % 6;
        const int col = at[j / 6] + j % 6;
        if (row >= col)
          entries.emplace_back(row, col, k(i, j));
      }
  };
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      if (x + 1 < side)
        couple(y * side + x, y * side + x + 1);
      if (y + 1 < side)
        couple(y * side + x, (y + 1) * side + x);
    }
  for (int i = 0; i < n; ++i)
    entries.emplace_back(i, i, 1.0);
  CholmodMatrix lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}

TEST(SparseCholesky, SolvesToRoundOffWithEitherKindOfFactor) {
  for (int side : {2, 30}) {
    const CholmodMatrix lower = grid(side, 5);
    SparseCholesky k;
    k.analyze(lower, 6);
    ASSERT_TRUE(k.factorize(lower));
    EXPECT_EQ(k.supernodal(), side == 30) << side;
    std::mt19937 rng(2);
    const Eigen::VectorXd b = testing::random_vector(lower.rows(), rng);
    const Eigen::VectorXd x = k.solve(b);
    const Eigen::VectorXd residual = lower.selfadjointView<Eigen::Lower>() * x - b;
    EXPECT_LE(residual.norm(), 1e-12 * lower.norm() * x.norm()) << side << " blocks a side";
    // Three right-hand sides at once, each solved as alone; the work counted.
    const Eigen::MatrixXd b3 = testing::random_matrix(lower.rows(), 3, rng);
    const Eigen::MatrixXd x3 = k.solve(b3);
    for (Eigen::Index c = 0; c < 3; ++c)
      EXPECT_LE((x3.col(c) - k.solve(Eigen::VectorXd(b3.col(c)))).norm(), 1e-12 * x3.norm());
    EXPECT_EQ(k.work().factorizations, 1);
    EXPECT_EQ(k.work().solved_columns, 1 + 3 + 3);
  }
}

TEST(SparseCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  for (int side : {2, 30}) {
    CholmodMatrix lower = grid(side, 7);
    const std::int64_t last = lower.rows() - 1;
    lower.coeffRef(last, last) = -1.0;  // a negative diagonal entry: not positive definite
    SparseCholesky k;
    k.analyze(lower, 6);
    EXPECT_FALSE(k.factorize(lower)) << side << " blocks a side";
    EXPECT_GE(k.failed_column(), 0);
    EXPECT_FALSE(k.factorized());
  }
}

// A matrix of another pattern than the analyzed one is refused from the first factorization on,
// whatever factor CHOLMOD picked (its own routines would factorize it into a wrong factor).
TEST(SparseCholesky, RefusesAPatternOtherThanTheAnalyzedOne) {
  for (int side : {2, 20}) {
    const CholmodMatrix lower = grid(side, 5);
    SparseCholesky k;
    k.analyze(lower, 6);
    CholmodMatrix other = lower;
    other.coeffRef(lower.rows() - 1, 0) = 1e-3;  // an entry the analyzed pattern lacks
    other.makeCompressed();
    EXPECT_THROW((void)k.factorize(other), std::logic_error) << side << " blocks a side";
    CholmodMatrix moved = lower;  // as many entries, one of them elsewhere
    moved.coeffRef(lower.rows() - 1, 0) = 1e-3;
    moved.prune([&](std::int64_t row, std::int64_t col, double) {
      return !(row == lower.rows() - 1 && col == lower.rows() - 1);
    });
    moved.makeCompressed();
    ASSERT_EQ(moved.nonZeros(), lower.nonZeros());
    EXPECT_THROW((void)k.factorize(moved), std::logic_error) << side << " blocks a side";
    EXPECT_TRUE(k.factorize(lower)) << side << " blocks a side";
  }
}

// One analysis, many factorizations: from the second on, the matrix is put in the factor's
// order by the class itself (CHOLMOD is told the order is natural), which must give the same
// factor. Each factor's solution is checked by its residual (K x = b), for K's own order and
// for a zone ordered last (then also its Schur complement against the dense one); a matrix
// that is not positive definite is still refused at its own column, and one of another
// pattern is refused outright.
TEST(SparseCholesky, RefactorizesOnePatternWithNewValues) {
  constexpr int kSide = 20;
  std::vector<char> last(kSide * kSide, 0);
  for (int y = 7; y < 13; ++y)
    for (int x = 8; x < 12; ++x)
      last[y * kSide + x] = 1;
  for (const bool zone_last : {false, true}) {
    SparseCholesky chol;
    // Analyzed with values that no factorization uses: the first factorization must read its
    // own (analyze_last() keeps the matrix permuted into its order for it).
    const CholmodMatrix first = grid(kSide, 7);
    if (zone_last)
      chol.analyze_last(first, 6, last);
    else
      chol.analyze(first, 6);
    ASSERT_TRUE(chol.supernodal());
    std::mt19937 rng(3);
    for (unsigned seed : {1U, 2U, 3U, 4U}) {
      const CholmodMatrix lower = grid(kSide, seed);
      ASSERT_TRUE(chol.factorize(lower)) << seed;
      const Eigen::VectorXd b = testing::random_vector(lower.rows(), rng);
      const Eigen::VectorXd x = chol.solve(b);
      const Eigen::VectorXd residual = lower.selfadjointView<Eigen::Lower>() * x - b;
      EXPECT_LE(residual.norm(), 1e-12 * lower.norm() * x.norm())
          << "seed " << seed << (zone_last ? ", zone last" : ", K's order");
    }
    if (zone_last) {  // the factor of the last values, read as a Schur complement
      const CholmodMatrix lower = grid(kSide, 4);
      const Eigen::MatrixXd k = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
      const Eigen::MatrixXd s =
          Eigen::MatrixXd(chol.schur_complement(lower)).selfadjointView<Eigen::Lower>();
      const std::vector<std::int64_t> p = chol.trailing_unknowns();
      std::vector<std::int64_t> e;
      for (std::int64_t i = 0; i < lower.rows(); ++i)
        if (!last[static_cast<std::size_t>(i / 6)])
          e.push_back(i);
      const Eigen::MatrixXd expected =
          Eigen::MatrixXd(k(p, p)) -
          k(p, e) * Eigen::MatrixXd(k(e, e)).llt().solve(Eigen::MatrixXd(k(e, p)));
      EXPECT_LE((s - expected).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
    }
    CholmodMatrix indefinite = grid(kSide, 5);
    const std::int64_t column = 6 * (10 * kSide + 10) + 2;  // inside the zone
    indefinite.coeffRef(column, column) = -1.0;
    EXPECT_FALSE(chol.factorize(indefinite));
    EXPECT_EQ(chol.failed_column(), column);
    CholmodMatrix other = grid(kSide, 5);
    other.coeffRef(6 * 40 + 5, 0) = 1e-3;  // an entry the analyzed pattern lacks
    other.makeCompressed();
    EXPECT_THROW((void)chol.factorize(other), std::logic_error);
  }
}

// The Schur complement onto the blocks ordered last, read from the factor, against the dense
// K_PP - K_PE K_EE^-1 K_EP (a second method: Eigen's dense Cholesky of K_EE). Zones: a patch
// inside the grid (coupled to the rest on all sides), a corner, scattered blocks, every block.
TEST(SparseCholesky, SchurComplementOfTheBlocksOrderedLastIsTheDenseOne) {
  constexpr int kSide = 12;
  const CholmodMatrix lower = grid(kSide, 7);
  const Eigen::MatrixXd k = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const auto patch = [](int x, int y) { return x >= 4 && x < 8 && y >= 3 && y < 9; };
  const auto corner = [](int x, int y) { return x < 3 && y < 3; };
  const auto scattered = [](int x, int y) { return (x * 7 + y * 3) % 5 == 0; };
  const auto every = [](int, int) { return true; };
  const std::function<bool(int, int)> zones[] = {patch, corner, scattered, every};
  for (const auto& in_zone : zones) {
    std::vector<char> last(kSide * kSide, 0);
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x)
        last[y * kSide + x] = in_zone(x, y) ? 1 : 0;
    SparseCholesky chol;
    chol.analyze_last(lower, 6, last);
    ASSERT_TRUE(chol.factorize(lower));
    const Eigen::MatrixXd s =
        Eigen::MatrixXd(chol.schur_complement(lower)).selfadjointView<Eigen::Lower>();
    const std::vector<std::int64_t>& p = chol.trailing_unknowns();
    std::vector<std::int64_t> e;
    for (std::int64_t i = 0; i < lower.rows(); ++i)
      if (!last[static_cast<std::size_t>(i / 6)])
        e.push_back(i);
    ASSERT_EQ(static_cast<std::size_t>(s.rows()), p.size());
    ASSERT_EQ(p.size() + e.size(), static_cast<std::size_t>(lower.rows()));
    const Eigen::MatrixXd k_pp = k(p, p);
    Eigen::MatrixXd expected = k_pp;
    if (!e.empty())
      expected -= k(p, e) * Eigen::MatrixXd(k(e, e)).llt().solve(Eigen::MatrixXd(k(e, p)));
    EXPECT_LE((s - expected).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
    // Each block's six unknowns stay together and in order (the block_size of S's analysis).
    for (std::size_t i = 0; i < p.size(); ++i)
      EXPECT_EQ(p[i] % 6, static_cast<std::int64_t>(i % 6));
  }
}

// Levels of a side x side grid of blocks: 2 on the patch [x0, x1) x [y0, y1), 1 on one ring of
// blocks around it, 0 on the rest.
std::vector<char> patch_and_ring(int side, int x0, int x1, int y0, int y1) {
  std::vector<char> levels(static_cast<std::size_t>(side * side), 0);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const bool inner = x >= x0 && x < x1 && y >= y0 && y < y1;
      const bool ring = x >= x0 - 1 && x < x1 + 1 && y >= y0 - 1 && y < y1 + 1;
      levels[static_cast<std::size_t>(y * side + x)] = inner ? 2 : ring ? 1 : 0;
    }
  return levels;
}

// The Schur complement of dense K onto the unknowns p (in that order): K_pp - K_pe K_ee^-1 K_ep,
// e the unknowns of blocks below `level`.
Eigen::MatrixXd dense_schur(const Eigen::MatrixXd& k, const std::vector<char>& levels, int level,
                            const std::vector<std::int64_t>& p) {
  std::vector<std::int64_t> e;
  for (std::int64_t i = 0; i < k.rows(); ++i)
    if (levels[static_cast<std::size_t>(i / 6)] < level)
      e.push_back(i);
  EXPECT_EQ(p.size() + e.size(), static_cast<std::size_t>(k.rows())) << level;
  return Eigen::MatrixXd(k(p, p)) -
         k(p, e) * Eigen::MatrixXd(k(e, e)).llt().solve(Eigen::MatrixXd(k(e, p)));
}

// Nested zones in one order: the Schur complement onto each is read from the same factor.
TEST(SparseCholesky, SchurComplementOfEachNestedZoneIsTheDenseOne) {
  constexpr int kSide = 12;
  const CholmodMatrix lower = grid(kSide, 11);
  const Eigen::MatrixXd k = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  std::vector<char> levels = patch_and_ring(kSide, 5, 8, 4, 7);
  SparseCholesky chol;
  chol.analyze_last(lower, 6, levels);
  ASSERT_TRUE(chol.factorize(lower));
  ASSERT_EQ(chol.levels(), 2);
  for (int level : {1, 2}) {
    const Eigen::MatrixXd s =
        Eigen::MatrixXd(chol.schur_complement(lower, level)).selfadjointView<Eigen::Lower>();
    const Eigen::MatrixXd expected = dense_schur(k, levels, level, chol.trailing_unknowns(level));
    EXPECT_LE((s - expected).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff()) << level;
  }
  // A patch next to blocks two levels lower is no nesting.
  levels.assign(levels.size(), 0);
  levels[5 * kSide + 5] = 2;
  EXPECT_THROW(chol.analyze_last(lower, 6, levels), std::logic_error);
}

// S x = b through the trailing block of the factor S was read from (SchurSolver): the solution
// of the dense Schur complement (formed from K as in the test above), for each nested zone, one
// right-hand side and several.
TEST(SchurSolver, SolvesWithEachNestedZonesSchurComplementAsTheDenseOne) {
  constexpr int kSide = 12;
  const CholmodMatrix lower = grid(kSide, 13);
  const Eigen::MatrixXd k = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const std::vector<char> levels = patch_and_ring(kSide, 4, 8, 5, 9);
  SparseCholesky chol;
  chol.analyze_last(lower, 6, levels);
  ASSERT_TRUE(chol.factorize(lower));
  for (int level : {1, 2}) {
    const std::vector<std::int64_t> p = chol.trailing_unknowns(level);
    const Eigen::MatrixXd s = dense_schur(k, levels, level, p);
    const SchurSolver solver(chol, level);
    ASSERT_EQ(solver.rows(), static_cast<std::int64_t>(p.size()));
    EXPECT_GT(solver.factor_nonzeros(), 0);
    EXPECT_LT(solver.factor_nonzeros(), chol.factor_nonzeros());
    Eigen::MatrixXd b(s.rows(), 3);
    for (Eigen::Index i = 0; i < b.rows(); ++i)
      for (Eigen::Index j = 0; j < b.cols(); ++j)
        b(i, j) = std::sin(0.37 * static_cast<double>(i) + static_cast<double>(j)) + 0.1;
    const Eigen::MatrixXd expected = s.llt().solve(b);
    const Eigen::MatrixXd x = solver.solve(b);
    EXPECT_LE((x - expected).norm(), 1e-10 * expected.norm()) << level;
    const Eigen::VectorXd one = solver.solve(Eigen::VectorXd(b.col(1)));
    EXPECT_LE((one - expected.col(1)).norm(), 1e-10 * expected.col(1).norm()) << level;
    EXPECT_EQ(solver.work().solved_columns, 4);
  }
  EXPECT_THROW(SchurSolver(chol, 3), std::logic_error);
}

// A load on the blocks ordered last is solved forward on the trailing part of L only; the
// displacements must still be K^-1 b everywhere (checked against a dense solve of K), and a
// load outside them takes the whole solve.
TEST(SparseCholesky, LoadOnTheBlocksOrderedLastIsSolvedExactly) {
  constexpr int kSide = 12;
  const CholmodMatrix lower = grid(kSide, 7);
  const Eigen::MatrixXd k = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const Eigen::LLT<Eigen::MatrixXd> dense(k);
  std::vector<char> last(kSide * kSide, 0);
  for (int y = 3; y < 9; ++y)
    for (int x = 4; x < 8; ++x)
      last[y * kSide + x] = 1;
  SparseCholesky chol;
  chol.analyze_last(lower, 6, last);
  ASSERT_TRUE(chol.factorize(lower));
  for (const bool inside : {true, false}) {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(lower.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i)
      if (last[static_cast<std::size_t>(i / 6)] == (inside ? 1 : 0) && i % 5 != 0)
        b(i) = std::sin(0.37 * static_cast<double>(i)) + 0.1;
    const Eigen::VectorXd expected = dense.solve(b);
    const Eigen::VectorXd x = chol.solve(b);
    EXPECT_LE((x - expected).norm(), 1e-10 * expected.norm()) << (inside ? "inside" : "outside");
  }
}

}  // namespace
}  // namespace bimrock
