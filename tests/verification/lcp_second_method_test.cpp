// Verification: for associated flow the LCP of an increment, M = N - C K^-1 Phi (eqs. 24, 28),
// is symmetric positive semi-definite, and Lemke's solution is checked against two independent
// methods on LCPs taken from a model (not random matrices): the enumeration of all
// complementary bases (exact for small problems; it proves infeasibility for PSD M) and
// projected Gauss-Seidel (which minimizes 1/2 z.Mz + q.z over z >= 0 for symmetric M).
// For PSD M, w = M z + q is the same at every solution, and so is the minimum 1/2 z.Mz + q.z:
// those are compared (z itself may not be unique).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/yield_system.hpp>
#include <bimrock/solve/lcp_enumeration.hpp>
#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/projected_gauss_seidel.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

// The wall of example 2 (3 x 4 bricks of 2 m x 0.5 m, every other row staggered) with
// frictional joints, associated (dilation = friction), under its weight and a pull at A.
Model wall(double friction_deg) {
  CaseSpec c;
  c.file = "wall";
  c.block_materials = {testing::rock(89e9, 0.26, 16e3)};
  JointMaterial j = testing::springs("joint", 395.9e9, 438.8e9);
  JointStrength s;
  s.cohesion = Softening::constant(20e3);
  s.friction = Softening::constant(std::tan(friction_deg * M_PI / 180.0));
  s.dilation = std::tan(friction_deg * M_PI / 180.0);
  s.tensile = Softening::constant(5e3);
  j.strength = s;
  c.joint_materials = {j};
  c.blocks = testing::blocks_of(brick_pattern(3, 4, 2.0, 0.5, Stagger::rows));
  c.default_joint = "joint";
  c.supports.push_back(testing::fixed({0, 0}, {6, 0}));
  return build_model(c);
}

struct ModelLcp {
  LcpProblem problem;
  int rows = 0;
};

// The LCP of one increment from the unloaded state: gravity plus P = `pull` at A = (6, 0.75),
// with the yield points `candidates` (all when empty).
ModelLcp increment_lcp(const Model& m, double pull, std::vector<int> candidates) {
  const auto points = make_yield_points(m);
  if (candidates.empty())
    for (std::size_t p = 0; p < points.size(); ++p)
      candidates.push_back(static_cast<int>(p));
  const std::vector<PlasticState> states(points.size());
  const YieldSystem sys =
      assemble_yield_system(m, points, states, Eigen::VectorXd::Zero(m.n_dofs()), candidates);
  const Eigen::MatrixXd k = full_from_lower(assemble_stiffness_lower(m)).toDense();
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(k);
  Loads loads;
  loads.gravity = Vec2(0, -1);
  loads.points.push_back(
      {find_block_containing(m, Vec2(5.999, 0.75)), Vec2(6.0, 0.75), Vec2(pull, 0.0)});
  const Eigen::VectorXd x = ldlt.solve(assemble_loads(m, loads));
  ModelLcp out;
  out.problem.m =
      Eigen::MatrixXd(sys.n) - Eigen::MatrixXd(sys.c) * ldlt.solve(Eigen::MatrixXd(sys.phi));
  out.problem.q = -sys.f0 - sys.c * x;
  out.rows = sys.size();
  return out;
}

double objective(const LcpProblem& p, const Eigen::VectorXd& z) {
  return 0.5 * z.dot(p.m * z) + p.q.dot(z);
}

TEST(LcpSecondMethod, ModelLcpIsSymmetricPositiveSemiDefinite) {
  const ModelLcp lcp = increment_lcp(wall(30.0), 60e3, {});
  const Eigen::MatrixXd& m = lcp.problem.m;
  EXPECT_LT((m - m.transpose()).norm(), 1e-10 * m.norm());
  const Eigen::VectorXd eig =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (m + m.transpose())).eigenvalues();
  EXPECT_GE(eig.minCoeff(), -1e-9 * eig.cwiseAbs().maxCoeff());
  EXPECT_GT(lcp.rows, 50);
  EXPECT_LT(lcp.problem.q.minCoeff(), 0.0) << "the load makes some joints yield";
}

TEST(LcpSecondMethod, LemkeAgreesWithTheEnumerationOfAllBases) {
  // Six yield points (18 rows) around the loaded half-brick: 2^18 bases, all tried.
  const Model m = wall(30.0);
  const auto points = make_yield_points(m);
  std::vector<int> near_a;
  for (std::size_t p = 0; p < points.size() && near_a.size() < 6; ++p) {
    if (points[p].position.x() >= 4.0 && points[p].position.y() > 0.25 &&
        points[p].position.y() < 1.25)
      near_a.push_back(static_cast<int>(p));
  }
  ASSERT_EQ(near_a.size(), 6u);
  for (double pull : {20e3, 40e3, 60e3, 120e3}) {
    SCOPED_TRACE("P = " + std::to_string(pull));
    const LcpProblem p = increment_lcp(m, pull, near_a).problem;
    const LcpResult lemke = Lemke().solve(p);
    const LcpResult oracle = LcpEnumeration().solve(p);
    ASSERT_EQ(lemke.status, oracle.status)
        << to_string(lemke.status) << " vs " << to_string(oracle.status);
    std::printf("P = %6.0f N: %ld rows, %s, %ld active, %d pivots\n", pull,
                static_cast<long>(p.size()), to_string(lemke.status),
                static_cast<long>((lemke.z.array() > 0.0).count()), lemke.steps);
    if (oracle.status != LcpStatus::solved)
      continue;
    const double scale = p.q.cwiseAbs().maxCoeff();
    EXPECT_LE((lemke.w - oracle.w).cwiseAbs().maxCoeff(), 1e-9 * scale);
    EXPECT_NEAR(objective(p, lemke.z), objective(p, oracle.z),
                1e-9 * std::abs(objective(p, oracle.z)) + 1e-300);
  }
}

TEST(LcpSecondMethod, LemkeAgreesWithProjectedGaussSeidelOnTheWholeModel) {
  // Every yield point of the wall (all rows): too many for the enumeration.
  for (double friction : {20.0, 40.0}) {
    SCOPED_TRACE("friction " + std::to_string(friction));
    const LcpProblem p = increment_lcp(wall(friction), 30e3, {}).problem;
    const LcpResult lemke = Lemke().solve(p);
    ASSERT_EQ(lemke.status, LcpStatus::solved) << to_string(lemke.status);
    PgsOptions o;
    o.tolerance = 1e-12;
    o.max_iterations = 2000000;
    const LcpResult pgs = ProjectedGaussSeidel(o).solve(p);
    ASSERT_EQ(pgs.status, LcpStatus::solved)
        << to_string(pgs.status) << " " << pgs.residuals.worst_relative();
    EXPECT_GT((lemke.z.array() > 0.0).count(), 0) << "a nontrivial solution";
    std::printf("friction %2.0f deg: %ld rows, %ld active, Lemke %d pivots, PGS %d sweeps\n",
                friction, static_cast<long>(p.size()),
                static_cast<long>((lemke.z.array() > 0.0).count()), lemke.steps, pgs.steps);
    const double scale = p.q.cwiseAbs().maxCoeff();
    EXPECT_LE((lemke.w - pgs.w).cwiseAbs().maxCoeff(), 1e-7 * scale);
    EXPECT_NEAR(objective(p, lemke.z), objective(p, pgs.z), 1e-7 * std::abs(objective(p, lemke.z)));
  }
}

}  // namespace
}  // namespace bimrock
