// The plastic analysis on the PETSc backend (src/bimrock/petsc/distributed_factor.hpp): K
// factorized by MUMPS across the processes, regions condensed through their boundary.
//
// Sources of the expected numbers:
// - a region's S against the dense Schur complement K_RR - K_RE K_EE^-1 K_ER computed here with
//   Eigen from the whole K (a second method: elimination of every unknown outside the region);
// - solves with K against K itself: the residual K x - b is round-off;
// - the analysis against the serial one (CHOLMOD, K's factor reordered with zones last): the same
//   collapse bracket and history (a comparison of two routes, as tests/analysis/ makes them), and
//   the wall's collapse against its closed form (wall_collapse_shear(), limit equilibrium of the
//   top row).
// The same binary runs under `mpirun -n 2` (tests/CMakeLists.txt): the answers must not change.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/petsc/distributed_factor.hpp>
#include <bimrock/petsc/owned.hpp>
#include <bimrock/reference/reference_cases.hpp>
#include <bimrock/solve/condensed_stiffness.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

TEST(DistributedFactor, CondensesARegionAsEliminationDoes) {
  const Model model = build_model(abutment_case(100, 25, abutment_collapse_shear()));
  const SparseMatrix lower = assemble_stiffness_lower(model);
  const Eigen::MatrixXd k = Eigen::MatrixXd(full_from_lower(lower));
  const BlockPartition partition = partition_blocks(model);
  Owned<Mat, MatDestroy> distributed;
  *distributed.out() = assemble_distributed_stiffness(model, partition);
  // A region around a block in the middle of the mass, and one at its edge (supported blocks).
  for (int seed : {model.n_blocks() / 2, 0}) {
    std::vector<char> region(static_cast<std::size_t>(model.n_blocks()), 0);
    region[static_cast<std::size_t>(seed)] = 1;
    region = grow_zone(model, region, 40);
    const SparseMatrix s_lower =
        condense_onto_region(model, partition, distributed.get(), lower, region);
    // The same S by eliminating everything outside the region from the dense K.
    std::vector<Eigen::Index> in;
    std::vector<Eigen::Index> out;
    for (Eigen::Index u = 0; u < k.rows(); ++u)
      (region[static_cast<std::size_t>(u / 6)] ? in : out).push_back(u);
    const Eigen::MatrixXd k_rr = k(in, in);
    const Eigen::MatrixXd k_re = k(in, out);
    const Eigen::MatrixXd expected = k_rr - k_re * k(out, out).llt().solve(k_re.transpose());
    const Eigen::MatrixXd s = Eigen::MatrixXd(full_from_lower(s_lower));
    ASSERT_EQ(s.rows(), expected.rows());
    const double error = (s - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
    std::printf("region of %zu unknowns around block %d: S differs by %.2e (relative)\n", in.size(),
                seed, error);
    EXPECT_LT(error, 1e-10);
    // What the rest of the model adds to the boundary's block is a hundred times that tolerance
    // or more (the check could not pass with S = K_RR).
    EXPECT_GT((s - k_rr).cwiseAbs().maxCoeff(), 1e-8 * expected.cwiseAbs().maxCoeff());
  }
  // A region of every block has no boundary: S is K.
  const std::vector<char> all(static_cast<std::size_t>(model.n_blocks()), 1);
  const SparseMatrix whole = condense_onto_region(model, partition, distributed.get(), lower, all);
  EXPECT_EQ((Eigen::MatrixXd(full_from_lower(whole)) - k).cwiseAbs().maxCoeff(), 0.0);
}

TEST(DistributedFactor, SolvesWithKToRoundOff) {
  const Model model = build_model(brick_mass_case(500));
  const SparseMatrix lower = assemble_stiffness_lower(model);
  const SparseMatrix k = full_from_lower(lower);
  const std::unique_ptr<StiffnessFactor> factor =
      distributed_factorization(model)(every_block(model), lower);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(k.rows(), 3);
  const Eigen::MatrixXd x = factor->solver().solve(b);
  const double residual = (k * x - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
  const double round_off =
      1e3 * 1.1e-16 * (k.cwiseAbs() * x.cwiseAbs()).maxCoeff() / b.cwiseAbs().maxCoeff();
  std::printf("residual %.2e (round-off %.2e), factor entries %lld\n", residual, round_off,
              static_cast<long long>(factor->solver().factor_nonzeros()));
  EXPECT_LT(residual, round_off);
  EXPECT_GT(factor->solver().factor_nonzeros(), lower.nonZeros());
  // A single right-hand side takes the same route.
  EXPECT_LT(
      (k * factor->solver().solve(Eigen::VectorXd(b.col(1))) - b.col(1)).cwiseAbs().maxCoeff(),
      round_off * b.cwiseAbs().maxCoeff());
}

// The processes run the same analysis; were they to ask for different solves (a bug), they would
// wait on each other forever in MUMPS. Each solve compares them first: all processes stop with an
// internal error instead (on one process there is nothing to differ).
TEST(DistributedFactor, ProcessesThatAskForDifferentSolvesStopTogether) {
  const Model model = build_model(brick_mass_case(100));
  const SparseMatrix lower = assemble_stiffness_lower(model);
  const std::unique_ptr<StiffnessFactor> factor =
      distributed_factorization(model)(every_block(model), lower);
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const Eigen::VectorXd b = Eigen::VectorXd::Constant(lower.rows(), 1.0 + rank);
  if (ranks == 1)
    EXPECT_NO_THROW((void)factor->solver().solve(b));
  else
    EXPECT_THROW((void)factor->solver().solve(b), std::logic_error);
  // And they go on together where they agree.
  EXPECT_NO_THROW(
      (void)factor->solver().solve(Eigen::VectorXd(Eigen::VectorXd::Ones(lower.rows()))));
}

// Zones condensed from the first LCPs on, so that a small model uses them: inside regions grown
// for them (`region_growth` 3), or, without (0), inside their outermost reserve condensed as a
// region (the serial analysis condenses those zones straight from K).
PlasticTuning zones(double region_growth) {
  PlasticTuning t;
  t.solver.zones = ZoneTuning{.condensed_zone_fraction = 1.0,
                              .least_zone_blocks = 1,
                              .condense_after_blocks = 0,
                              .zone_reserves = 2,
                              .region_growth = region_growth,
                              .region_fraction = 1.0};
  return t;
}

TEST(DistributedFactor, GivesTheSerialAnalysis) {
  const Model model = build_model(abutment_case(100, 25, 1.2 * abutment_collapse_shear()));
  const PlasticResult serial = run_plastic_analysis(model);
  for (const PlasticTuning& route : {PlasticTuning{}, zones(3.0), zones(0.0)}) {
    PlasticTuning tuning = route;
    tuning.stiffness = distributed_factorization(model);
    const PlasticResult distributed = run_plastic_analysis(model, {}, {}, tuning);
    std::printf("%d regions, %d condensations\n", distributed.regions, distributed.condensations);
    if (route.solver.zones.condense_after_blocks == 0) {
      EXPECT_GE(distributed.regions, 2) << "no region was condensed, or only one";
      EXPECT_GE(distributed.condensations, distributed.regions);
    }
    testing::expect_same_analysis(serial, distributed);
  }
}

// Stages that excavate and install bolts: K of what stands is factorized anew by MUMPS at each.
// The monitors after every increment are the serial ones. (Not every block's: after the bench
// is dug out, a loose block of the floor turns freely, its rotation fixed by round-off in either
// analysis.)
TEST(DistributedFactor, GivesTheSerialHistoryThroughExcavationAndBolts) {
  const std::filesystem::path file =
      std::filesystem::path(BIMROCK_SOURCE_DIR) / "examples/tunnel_excavation/bolted.yaml";
  const Case c = read_case_file(file.string());
  const Model model = build_model(c.spec);
  const PlasticResult serial = run_plastic_analysis(model, c.plastic);
  PlasticTuning tuning;
  tuning.stiffness = distributed_factorization(model);
  const PlasticResult distributed = run_plastic_analysis(model, c.plastic, {}, tuning);
  ASSERT_FALSE(serial.collapse || serial.stopped);
  EXPECT_FALSE(distributed.collapse || distributed.stopped);
  EXPECT_EQ(distributed.stiffness_factorizations, serial.stiffness_factorizations);
  EXPECT_GE(serial.stiffness_factorizations, 3) << "the stages no longer excavate and bolt";
  ASSERT_EQ(distributed.history.size(), serial.history.size());
  double largest = 0.0;
  for (const IncrementRecord& r : serial.history)
    for (const Vec2& m : r.monitors)
      largest = std::max(largest, m.norm());
  for (std::size_t i = 0; i < serial.history.size(); ++i) {
    const IncrementRecord& a = serial.history[i];
    const IncrementRecord& b = distributed.history[i];
    EXPECT_EQ(b.stage, a.stage);
    EXPECT_EQ(b.stage_factor, a.stage_factor) << i;
    for (std::size_t m = 0; m < a.monitors.size(); ++m)
      EXPECT_LT((b.monitors[m] - a.monitors[m]).norm(), 1e-7 * largest) << i << " " << m;
  }
}

TEST(DistributedFactor, CarriesTheWallToItsClosedFormCollapse) {
  const double shear = wall_collapse_shear();
  const Model model = build_model(wall_case(300, 10, 1.5 * shear));
  PlasticTuning tuning = zones(3.0);
  tuning.stiffness = distributed_factorization(model);
  const PlasticResult r = run_plastic_analysis(model, {}, {}, tuning);
  ASSERT_TRUE(r.collapse.has_value());
  // The shear stage's factor at collapse is 1 / 1.5 of its load.
  const double carried = 1.5 * r.collapse->carried;
  const double failed = 1.5 * r.collapse->failed;
  std::printf("wall: collapse between %.6f and %.6f of the closed form, %d regions\n", carried,
              failed, r.regions);
  EXPECT_LE(carried, 1.0 + 1e-4);
  EXPECT_GE(failed, 1.0 - 1e-4);
  EXPECT_LT(failed - carried, 2e-4);
}

}  // namespace
}  // namespace bimrock
