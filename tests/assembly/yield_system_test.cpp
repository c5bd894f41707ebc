// The yield rows of an increment (eqs. 22-28). Sources: for associated flow the LCP matrix
// N - C K^-1 Phi is symmetric (docs/formulation.md, a consequence of the weighting); C is the
// derivative of the (weighted) yield functions with respect to the unknowns (checked by finite
// differences); Phi lambda is the load that a plastic strain lambda g releases (checked against
// the change of the internal force).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/yield_system.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"

namespace bimrock {
namespace {

Model plastic_assembly(double friction, double dilation, bool blocks_yield) {
  CaseSpec c;
  c.file = "yield";
  c.block_materials = {testing::rock(20e9, 0.25, 2e4)};
  if (blocks_yield) {
    BlockStrength b;
    b.cohesion = 1e6;
    b.friction = std::sin(0.5);
    b.dilation = std::sin(0.5);
    b.planes = 8;
    c.block_materials[0].strength = b;
  }
  JointMaterial j = testing::springs("joint", 5e10, 2e10);
  JointStrength s;
  s.cohesion = Softening::constant(1e5);
  s.friction = Softening::constant(friction);
  s.dilation = dilation;
  j.strength = s;
  c.joint_materials = {j};
  c.blocks = testing::blocks_of(testing::irregular_blocks(2.0, 1.5, 5, 3));
  c.default_joint = "joint";
  c.supports.push_back(testing::fixed({0, 0}, {2, 0}));
  return build_model(c);
}

Eigen::MatrixXd lcp_matrix(const Model& m, const YieldSystem& sys) {
  const Eigen::MatrixXd k = full_from_lower(assemble_stiffness_lower(m)).toDense();
  return Eigen::MatrixXd(sys.n) - Eigen::MatrixXd(sys.c) * k.ldlt().solve(Eigen::MatrixXd(sys.phi));
}

std::vector<int> all_points(const std::vector<YieldPoint>& points) {
  std::vector<int> all(points.size());
  for (std::size_t k = 0; k < all.size(); ++k)
    all[k] = static_cast<int>(k);
  return all;
}

TEST(YieldSystem, AssociatedFlowGivesASymmetricLcpMatrix) {
  const Model m = plastic_assembly(0.6, 0.6, true);
  const auto points = make_yield_points(m);
  const std::vector<PlasticState> states(points.size());
  const Eigen::VectorXd u = Eigen::VectorXd::Random(m.n_dofs()) * 1e-4;
  const YieldSystem sys = assemble_yield_system(m, points, states, u, all_points(points));
  const Eigen::MatrixXd lcp = lcp_matrix(m, sys);
  EXPECT_LT((lcp - lcp.transpose()).norm(), 1e-10 * lcp.norm());
  EXPECT_GT(sys.size(), 20);
}

TEST(YieldSystem, NonAssociatedFlowDoesNot) {
  const Model m = plastic_assembly(0.6, 0.0, false);
  const auto points = make_yield_points(m);
  const std::vector<PlasticState> states(points.size());
  const YieldSystem sys = assemble_yield_system(
      m, points, states, Eigen::VectorXd::Zero(m.n_dofs()), all_points(points));
  const Eigen::MatrixXd lcp = lcp_matrix(m, sys);
  EXPECT_GT((lcp - lcp.transpose()).norm(), 1e-3 * lcp.norm());
}

// The splitting of a non-associated LCP (solve/symmetric_splitting.hpp): with each yield
// gradient turned along the flow, the LCP matrix is symmetric, f0 and Phi are the model's, and
// what C loses is, for a joint's slip rows, the friction term of the normal stress: Mohr-Coulomb
// f = +-tau + sigma_n tan(phi) - c flows along (+-1, tan(psi)), so C - C~ = (tan(phi) -
// tan(psi)) dsigma_n/dU, and dsigma_n/dU is the C row of the point's tension cut-off
// (sigma_n - sigma_t).
TEST(YieldSystem, GradientsAlongTheFlowLeaveASymmetricLcpAndTheFrictionOfTheNormalStress) {
  const double tan_phi = 0.6, tan_psi = 0.1;
  const Model m = plastic_assembly(tan_phi, tan_psi, false);
  const auto points = make_yield_points(m);
  const std::vector<PlasticState> states(points.size());
  const Eigen::VectorXd u = Eigen::VectorXd::Random(m.n_dofs()) * 1e-4;
  const YieldSystem sys = assemble_yield_system(m, points, states, u, all_points(points));
  const YieldSystem along = assemble_yield_system(m, points, states, u, all_points(points),
                                                  FlowRule::gradient_along_flow);
  ASSERT_EQ(along.size(), sys.size());
  const Eigen::MatrixXd lcp = lcp_matrix(m, along);
  EXPECT_LT((lcp - lcp.transpose()).norm(), 1e-10 * lcp.norm());
  EXPECT_TRUE(follows_associated_flow(along));
  EXPECT_FALSE(follows_associated_flow(sys));
  EXPECT_EQ((along.f0 - sys.f0).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(Eigen::MatrixXd(along.phi - sys.phi).cwiseAbs().maxCoeff(), 0.0);
  const Eigen::MatrixXd c = sys.c, c_along = along.c;
  int joint_points = 0;
  for (int r = 0; r < sys.size(); r += 3) {
    ASSERT_TRUE(points[static_cast<std::size_t>(sys.rows[r].point)].is_interface());
    const Eigen::RowVectorXd normal = c.row(r + kOpeningMode);
    for (int slip = 0; slip < 2; ++slip) {
      const Eigen::RowVectorXd lost = c.row(r + slip) - c_along.row(r + slip);
      EXPECT_LT((lost - (tan_phi - tan_psi) * normal).norm(), 1e-12 * normal.norm()) << r;
    }
    EXPECT_EQ((c.row(r + kOpeningMode) - c_along.row(r + kOpeningMode)).norm(), 0.0);
    ++joint_points;
  }
  EXPECT_GT(joint_points, 10);
}

TEST(YieldSystem, CIsTheDerivativeOfTheWeightedYieldFunctions) {
  const Model m = plastic_assembly(0.6, 0.2, true);
  const auto points = make_yield_points(m);
  const std::vector<PlasticState> states(points.size());
  const Eigen::VectorXd u = Eigen::VectorXd::Random(m.n_dofs()) * 1e-4;
  const auto all = all_points(points);
  const YieldSystem sys = assemble_yield_system(m, points, states, u, all);
  const Eigen::MatrixXd c = sys.c;
  for (int dof : {0, 3, 7, 11, 16, 20}) {
    const double h = 1e-7;
    Eigen::VectorXd up = u;
    up(dof) += h;
    const YieldSystem plus = assemble_yield_system(m, points, states, up, all);
    // The yield functions are linear in the stress, hence in u: the difference is exact.
    const Eigen::VectorXd fd = (plus.f0 - sys.f0) / h;
    EXPECT_LT((fd - c.col(dof)).norm(), 1e-6 * std::max(1.0, c.col(dof).norm())) << dof;
  }
}

TEST(YieldSystem, PhiIsTheLoadReleasedByAPlasticMultiplier) {
  // A plastic increment lambda g at one point changes its stress by -D g lambda; the internal
  // force t w E^T dsigma it produces must equal -Phi lambda.
  const Model m = plastic_assembly(0.6, 0.3, true);
  const auto points = make_yield_points(m);
  std::vector<PlasticState> states(points.size());
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(m.n_dofs());
  const YieldSystem sys = assemble_yield_system(m, points, states, u, all_points(points));
  const Eigen::MatrixXd phi = sys.phi;
  for (int r : {0, 1, 2, sys.size() - 1}) {
    const YieldRow row = sys.rows[r];
    const YieldPoint& p = points[row.point];
    const LocalOperator op = local_operator(m, p);
    const Eigen::MatrixXd d = local_stiffness(m, p);
    const Eigen::VectorXd g = sys.flow[r].head(d.rows());
    const Eigen::VectorXd local_force = p.weight * op.e.transpose() * (d * g);
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(m.n_dofs());
    for (int k = 0; k < op.n_blocks(); ++k)
      expected.segment<6>(6 * op.blocks[k]) += local_force.segment<6>(6 * k);
    EXPECT_LT((phi.col(r) - expected).norm(), 1e-12 * expected.norm()) << r;
  }
}

}  // namespace
}  // namespace bimrock
