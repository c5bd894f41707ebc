// The memory estimate of `bimrock check`: its counts of K's and L's non-zeros against those of
// the stiffness the run assembles and the factor it analyzes (SparseCholesky, on the scalar K in
// blocks of 6), on brick masses and a model cut from a domain. Its bytes are fitted to measured
// peaks (memory_estimate.cpp); here only that they grow with the counts.
#include <gtest/gtest.h>

#include <bimrock/analysis/memory_estimate.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/reference/reference_cases.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {
namespace {

struct Counts {
  std::int64_t stiffness = 0;
  std::int64_t factor = 0;
};

// What the run analyzes: K as assembled, its factor as SparseCholesky orders and sizes it.
Counts of_the_run(const Model& model) {
  const SparseMatrix k = assemble_stiffness_lower(model);
  SparseCholesky cholesky;
  cholesky.analyze(k, 6);
  EXPECT_TRUE(cholesky.factorize(k));
  return {k.nonZeros(), cholesky.factor_nonzeros()};
}

TEST(MemoryEstimate, CountsKAndItsFactorAsTheRunDoes) {
  double last_bytes = 0.0;
  for (const int n : {60, 600, 3000}) {
    const Model model = build_model(brick_mass_case(n));
    const MemoryEstimate e = estimate_memory(model);
    const Counts run = of_the_run(model);
    EXPECT_EQ(e.stiffness_nonzeros, run.stiffness) << n;
    // The run's supernodal factor stores its supernodes whole (relaxed amalgamation pads them
    // with zeros): 1.0-1.4 times the exact count of the same order's factor.
    EXPECT_LE(e.factor_nonzeros, run.factor) << n;
    EXPECT_GE(1.4 * static_cast<double>(e.factor_nonzeros), static_cast<double>(run.factor)) << n;
    EXPECT_GT(e.solve_bytes, last_bytes);
    EXPECT_GE(e.peak_bytes, e.solve_bytes);
    last_bytes = e.solve_bytes;
  }
}

// A chain of blocks: every block couples to its two neighbours only, so no fill at all: L has
// the pattern of K's lower triangle, 21 numbers per diagonal block and 36 per link.
TEST(MemoryEstimate, AChainOfBlocksHasNoFill) {
  CaseSpec spec;
  BlockMaterial rock;
  rock.name = "rock";
  rock.young = 1e10;
  rock.poisson = 0.2;
  spec.block_materials.push_back(rock);
  JointMaterial joint;
  joint.name = "joint";
  joint.normal_stiffness = 1e10;
  joint.shear_stiffness = 1e9;
  spec.joint_materials.push_back(joint);
  spec.default_joint = "joint";
  const int n = 50;
  for (int k = 0; k < n; ++k) {
    const double x = k;
    spec.blocks.push_back(
        {Polygon{{{x, 0}, {x + 1, 0}, {x + 1, 1}, {x, 1}}}, "rock", {0, "block"}});
  }
  const MemoryEstimate e = estimate_memory(build_model(spec));
  EXPECT_EQ(e.stiffness_nonzeros, 21 * n + 36 * (n - 1));
  EXPECT_EQ(e.factor_nonzeros, 21 * n + 36 * (n - 1));
}

}  // namespace
}  // namespace bimrock
