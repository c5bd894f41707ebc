// The active-set equations of a non-symmetric LCP (non-associated flow) on the sparse reduced
// tangent, factorized by LU. Expected numbers come from a second method on the same LCP: the
// dense matrix M = N - C K^-1 Phi formed with a dense LDLT of K, solved by a dense LU (one
// active set) or by Lemke (the whole LCP: M is positive definite, a P-matrix, so the solution
// is unique). GMRES on the tangent is checked against the same dense LU.
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/unsymmetric_tangent.hpp>

#include "solve/chain_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::ChainLcp;
using testing::dense_solution;
using testing::dense_tangent;
using testing::every;
using testing::make_nonassociated_chain;

TEST(UnsymmetricTangent, SolvesTheEquationsOfAnActiveSetAsTheDenseBlockDoes) {
  ChainLcp chain;
  make_nonassociated_chain(40, 5, chain);
  UnsymmetricTangentEquations equations(chain.split, chain.k);
  for (const Eigen::Index step : {1, 2, 3}) {
    const std::vector<Eigen::Index> active = every(step, equations.size());
    const ActiveSetEquations::Solution s = equations.solve(active);
    ASSERT_TRUE(s.regular);
    const VectorXd z = dense_solution(chain, active, {});
    const VectorXd w = chain.m_dense * z + chain.split.q;
    EXPECT_LE((s.z - z).cwiseAbs().maxCoeff(), 1e-9 * z.cwiseAbs().maxCoeff()) << step;
    EXPECT_LE((s.w - w).cwiseAbs().maxCoeff(), 1e-9 * chain.split.q.cwiseAbs().maxCoeff()) << step;
  }
  EXPECT_EQ(equations.factorizations(), 3);
}

TEST(UnsymmetricTangent, TheActiveSetMethodOnItFindsLemkesSolution) {
  for (const unsigned seed : {1u, 2u, 3u, 4u}) {
    ChainLcp chain;
    make_nonassociated_chain(30, seed, chain);
    UnsymmetricTangentEquations equations(chain.split, chain.k);
    ActiveSetLcp solver;
    const LcpResult r = solver.solve(equations);
    ASSERT_EQ(r.status, LcpStatus::solved) << seed;
    Lemke lemke;
    const LcpResult second = lemke.solve(LcpProblem{chain.m_dense, chain.split.q});
    ASSERT_EQ(second.status, LcpStatus::solved);
    EXPECT_LE((r.z - second.z).cwiseAbs().maxCoeff(), 1e-8 * second.z.cwiseAbs().maxCoeff())
        << seed;
    EXPECT_GT(equations.factorizations(), 0);
  }
}

// With a preconditioner (here the symmetric part of the tangent, factorized densely: a
// symmetric tangent near it, as the associated form's is in the analysis), the equations are
// solved by GMRES without an LU, to the dense block's answer.
TEST(UnsymmetricTangent, SolvesByGmresWithASymmetricTangentNearIt) {
  ChainLcp chain;
  make_nonassociated_chain(40, 5, chain);
  std::vector<std::vector<Eigen::Index>> asked;
  UnsymmetricTangentEquations::Preconditioner near =
      [&](const std::vector<Eigen::Index>& active) -> std::optional<LinearSolve> {
    asked.push_back(active);
    const MatrixXd t = dense_tangent(chain, active);
    const Eigen::LDLT<MatrixXd> symmetric_part(0.5 * (t + t.transpose()));
    return [symmetric_part](const VectorXd& b) { return VectorXd(symmetric_part.solve(b)); };
  };
  UnsymmetricTangentEquations equations(chain.split, chain.k, near);
  for (const Eigen::Index step : {1, 2, 3}) {
    const std::vector<Eigen::Index> active = every(step, equations.size());
    const ActiveSetEquations::Solution s = equations.solve(active);
    ASSERT_TRUE(s.regular);
    const VectorXd z = dense_solution(chain, active, {});
    EXPECT_LE((s.z - z).cwiseAbs().maxCoeff(), 1e-9 * z.cwiseAbs().maxCoeff()) << step;
    EXPECT_EQ(asked.back(), active);
  }
  EXPECT_EQ(equations.factorizations(), 0);
  EXPECT_EQ(equations.iterative_solves(), 3);
}

// A preconditioner that makes GMRES look converged on a wrong answer (it maps every residual
// to zero), or none for the rows asked: the result is measured, and the LU solves it.
TEST(UnsymmetricTangent, TheLuSolvesWhereGmresMissesTheEquations) {
  ChainLcp chain;
  make_nonassociated_chain(40, 5, chain);
  const std::vector<Eigen::Index> active = every(2, chain.split.q.size());
  const VectorXd z = dense_solution(chain, active, {});
  const UnsymmetricTangentEquations::Preconditioner zero =
      [](const std::vector<Eigen::Index>&) -> std::optional<LinearSolve> {
    return [](const VectorXd& b) { return VectorXd(VectorXd::Zero(b.size())); };
  };
  const UnsymmetricTangentEquations::Preconditioner none =
      [](const std::vector<Eigen::Index>&) -> std::optional<LinearSolve> { return std::nullopt; };
  for (const auto& preconditioner : {zero, none}) {
    UnsymmetricTangentEquations equations(chain.split, chain.k, preconditioner);
    const ActiveSetEquations::Solution s =
        equations.solve(active, {}, ActiveSetEquations::Check::from_solve);
    ASSERT_TRUE(s.regular);
    EXPECT_LE((s.z - z).cwiseAbs().maxCoeff(), 1e-8 * z.cwiseAbs().maxCoeff());
    EXPECT_EQ(equations.factorizations(), 1);
    EXPECT_EQ(equations.iterative_solves(), 0);
  }
}

TEST(UnsymmetricTangent, ASingularLocalBlockIsLeftToTheDenseRoute) {
  ChainLcp chain;
  make_nonassociated_chain(10, 9, chain);
  // Both modes of point 0 with their local block made singular (its rows equal).
  chain.n.coeffRef(1, 0) = chain.n.coeff(0, 0);
  chain.n.coeffRef(1, 1) = chain.n.coeff(0, 1);
  UnsymmetricTangentEquations equations(chain.split, chain.k);
  EXPECT_FALSE(equations.solve({0, 1}).regular);
}

}  // namespace
}  // namespace bimrock
