// CHOLMOD's large blocks, recycled (factor_memory.hpp): a freed large block serves the next
// request of about its size with its pages kept, what a block held survives realloc, a reused
// block given by calloc is zero, and factors computed in recycled memory are right (the residual
// of a solve with a factor of a second analysis, computed independently with the matrix).
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Sparse>

#include <SuiteSparse_config.h>

#include <bimrock/solve/factor_memory.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {
namespace {

constexpr std::size_t kLarge = kLargeFactorBlock;

TEST(FactorMemory, AFreedLargeBlockServesTheNextOfAboutItsSize) {
  release_kept_factor_memory();
  const FactorMemoryStats before = factor_memory_stats();
  void* a = factor_malloc(3 * kLarge);
  ASSERT_NE(a, nullptr);
  std::memset(a, 7, 3 * kLarge);
  factor_free(a);
  EXPECT_EQ(factor_memory_stats().kept_bytes, static_cast<std::int64_t>(3 * kLarge));
  // 20% larger: the kept block, grown.
  void* b = factor_malloc(3 * kLarge + 3 * kLarge / 5);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(factor_memory_stats().reused, before.reused + 1);
  EXPECT_EQ(factor_memory_stats().kept_bytes, 0);
  // More than twice as large as anything kept: a new mapping.
  factor_free(b);
  void* c = factor_malloc(8 * kLarge);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(factor_memory_stats().mapped, before.mapped + 2);
  factor_free(c);
  release_kept_factor_memory();
  EXPECT_EQ(factor_memory_stats().kept_bytes, 0);
}

TEST(FactorMemory, CallocOfAReusedBlockIsZero) {
  release_kept_factor_memory();
  const std::size_t n = 2 * kLarge / sizeof(double);
  auto* dirty = static_cast<double*>(factor_malloc(n * sizeof(double)));
  ASSERT_NE(dirty, nullptr);
  for (std::size_t i = 0; i < n; ++i)
    dirty[i] = 1.0 + static_cast<double>(i);
  factor_free(dirty);
  const std::int64_t reused = factor_memory_stats().reused;
  // Larger than the kept block: its pages hold old values, the grown tail is fresh.
  const std::size_t m = n + n / 4;
  auto* clean = static_cast<double*>(factor_calloc(m, sizeof(double)));
  ASSERT_NE(clean, nullptr);
  EXPECT_EQ(factor_memory_stats().reused, reused + 1);
  std::size_t nonzero = 0;
  for (std::size_t i = 0; i < m; ++i)
    nonzero += clean[i] != 0.0;
  EXPECT_EQ(nonzero, 0u);
  factor_free(clean);
  release_kept_factor_memory();
}

TEST(FactorMemory, ReallocKeepsWhatTheBlockHeld) {
  release_kept_factor_memory();
  // A small block (glibc's) grown into a large one, then grown and shrunk as a large one.
  const std::size_t small = 1000;
  auto* p = static_cast<unsigned char*>(factor_malloc(small));
  ASSERT_NE(p, nullptr);
  for (std::size_t i = 0; i < small; ++i)
    p[i] = static_cast<unsigned char>(i % 251);
  for (std::size_t bytes : {2 * kLarge, 5 * kLarge, kLarge + 1}) {
    p = static_cast<unsigned char*>(factor_realloc(p, bytes));
    ASSERT_NE(p, nullptr) << bytes;
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < small; ++i)
      wrong += p[i] != static_cast<unsigned char>(i % 251);
    EXPECT_EQ(wrong, 0u) << bytes;
  }
  factor_free(p);
  release_kept_factor_memory();
}

TEST(FactorMemory, KeepsAtMostItsLimitAndUnmapsTheSmallestFirst) {
  release_kept_factor_memory();
  std::vector<void*> blocks;
  for (int k = 0; k <= kKeptFactorBlocks; ++k)
    blocks.push_back(factor_malloc((2 + static_cast<std::size_t>(k)) * kLarge));
  for (void* b : blocks)
    factor_free(b);
  // The smallest (2 kLarge) went; the others stay, 3 + 4 + ... kLarge.
  std::int64_t expected = 0;
  for (int k = 1; k <= kKeptFactorBlocks; ++k)
    expected += static_cast<std::int64_t>((2 + static_cast<std::size_t>(k)) * kLarge);
  EXPECT_EQ(factor_memory_stats().kept_bytes, expected);
  release_kept_factor_memory();
}

TEST(FactorMemory, OffItLeavesNewBlocksToGlibcAndStillFreesItsOwn) {
  release_kept_factor_memory();
  void* recycled = factor_malloc(2 * kLarge);  // mapped here, freed while recycling is off
  recycle_factor_memory(false);
  const FactorMemoryStats before = factor_memory_stats();
  void* glibcs = factor_malloc(2 * kLarge);
  ASSERT_NE(glibcs, nullptr);
  std::memset(glibcs, 1, 2 * kLarge);
  factor_free(glibcs);
  recycled = factor_realloc(recycled, 3 * kLarge);
  ASSERT_NE(recycled, nullptr);
  factor_free(recycled);
  EXPECT_EQ(factor_memory_stats().mapped, before.mapped);
  EXPECT_EQ(factor_memory_stats().kept_bytes, 0);
  recycle_factor_memory(true);
  factor_free(factor_malloc(2 * kLarge));
  EXPECT_EQ(factor_memory_stats().kept_bytes, static_cast<std::int64_t>(2 * kLarge));
  release_kept_factor_memory();
}

// A grid of nodes with 6 unknowns each, every unknown coupled to all of its neighbours' by
// -1/6 (K's pattern) and 4.5 on the diagonal: strictly diagonally dominant, so positive
// definite, and large enough (side 60: 21 600 unknowns) that its factor's values are a large
// block.
CholmodMatrix laplacian(int side) {
  const int n = 6 * side * side;
  std::vector<Eigen::Triplet<double, std::int64_t>> entries;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const int node = y * side + x;
      for (int d = 0; d < 6; ++d) {
        const int i = 6 * node + d;
        entries.emplace_back(i, i, 4.5);
        for (int e = 0; e < 6; ++e) {
          if (x + 1 < side)
            entries.emplace_back(6 * (node + 1) + e, i, -1.0 / 6.0);
          if (y + 1 < side)
            entries.emplace_back(6 * (node + side) + e, i, -1.0 / 6.0);
        }
      }
    }
  CholmodMatrix lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}

// The allocator is a setting of the process: a factorization does not install it (a library
// user's other SuiteSparse code keeps malloc), an explicit call does. (ctest runs each test in a
// process of its own, so no earlier test has installed it.)
TEST(FactorMemory, OnlyAnExplicitCallInstallsIt) {
  const CholmodMatrix lower = laplacian(60);
  const FactorMemoryStats before = factor_memory_stats();
  {
    SparseCholesky k;
    k.analyze(lower, 6);
    ASSERT_TRUE(k.factorize(lower));
    ASSERT_GE(8 * k.factor_nonzeros(), static_cast<std::int64_t>(kLarge));
  }
  EXPECT_EQ(factor_memory_stats().mapped, before.mapped);
  EXPECT_TRUE(SuiteSparse_config.malloc_func != &factor_malloc);
  install_factor_memory();
  EXPECT_TRUE(SuiteSparse_config.malloc_func == &factor_malloc);
  EXPECT_TRUE(SuiteSparse_config.free_func == &factor_free);
}

TEST(FactorMemory, AFactorInRecycledMemorySolvesToRoundOff) {
  install_factor_memory();
  release_kept_factor_memory();
  const int side = 60;
  const CholmodMatrix lower = laplacian(side);
  const CholmodMatrix full =
      CholmodMatrix(lower.selfadjointView<Eigen::Lower>());  // the matrix, for residuals
  SparseCholesky k;
  k.analyze(lower, 6);
  ASSERT_TRUE(k.factorize(lower));
  ASSERT_GE(8 * k.factor_nonzeros(), static_cast<std::int64_t>(kLarge));
  const std::int64_t reused = factor_memory_stats().reused;
  // Analyzed again with a band of blocks last (a zone): the first factor's blocks serve it.
  std::vector<char> level(static_cast<std::size_t>(side * side), 0);
  for (int node = 0; node < side * side; ++node)
    level[static_cast<std::size_t>(node)] = node % side < side / 4 ? 1 : 0;
  k.analyze_last(lower, 6, level);
  ASSERT_TRUE(k.factorize(lower));
  EXPECT_GT(factor_memory_stats().reused, reused);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd b(lower.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i)
    b(i) = u(rng);
  const Eigen::VectorXd x = k.solve(b);
  EXPECT_LT((full * x - b).norm(), 1e-12 * b.norm());
}

}  // namespace
}  // namespace bimrock
