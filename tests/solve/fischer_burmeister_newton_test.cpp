// The semismooth Newton method on the sparse parts of a non-symmetric LCP. Expected numbers come
// from a second method on the same LCP: the dense M = N - C K^-1 Phi (a dense LDLT of K) solved
// by Lemke; M is positive definite here, a P-matrix, so the solution is unique.
#include <gtest/gtest.h>

#include <bimrock/solve/fischer_burmeister_newton.hpp>
#include <bimrock/solve/lemke.hpp>

#include "solve/chain_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::ChainLcp;
using testing::make_nonassociated_chain;

VectorXd lemke_solution(const ChainLcp& chain) {
  Lemke lemke;
  const LcpResult r = lemke.solve(LcpProblem{chain.m_dense, chain.split.q});
  EXPECT_EQ(r.status, LcpStatus::solved);
  return r.z;
}

TEST(FischerBurmeisterNewton, FindsLemkesSolutionFromNoPlasticFlow) {
  for (const unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    ChainLcp chain;
    make_nonassociated_chain(30, seed, chain);
    const VectorXd expected = lemke_solution(chain);
    ASSERT_GT((expected.array() > 0.0).count(), 5) << seed;  // some rows active, not all
    ASSERT_LT((expected.array() > 0.0).count(), expected.size()) << seed;
    const LcpResult r =
        fischer_burmeister_newton(chain.split, chain.k, VectorXd::Zero(expected.size()));
    ASSERT_EQ(r.status, LcpStatus::solved) << seed;
    EXPECT_LE(r.residuals.worst_relative(), 1e-9) << seed;
    EXPECT_LE((r.z - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.cwiseAbs().maxCoeff())
        << seed;
    // w is measured, not the method's own.
    const VectorXd w = chain.m_dense * r.z + chain.split.q;
    EXPECT_LE((r.w - w).cwiseAbs().maxCoeff(), 1e-9 * chain.split.q.cwiseAbs().maxCoeff()) << seed;
    EXPECT_GT(r.steps, 0);
  }
}

TEST(FischerBurmeisterNewton, ConvergesFromAFarStartAndStopsAtOnceAtTheSolution) {
  ChainLcp chain;
  make_nonassociated_chain(20, 7, chain);
  const VectorXd expected = lemke_solution(chain);
  // Far: every multiplier 100 times the solution's largest (negative entries are projected).
  const VectorXd far = VectorXd::Constant(expected.size(), 100.0 * expected.maxCoeff());
  const LcpResult r = fischer_burmeister_newton(chain.split, chain.k, far);
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_LE((r.z - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.cwiseAbs().maxCoeff());
  const LcpResult again = fischer_burmeister_newton(chain.split, chain.k, r.z);
  ASSERT_EQ(again.status, LcpStatus::solved);
  EXPECT_EQ(again.steps, 0);
}

TEST(FischerBurmeisterNewton, AnUnfinishedSolveSaysSoAndKeepsItsMultipliersNonNegative) {
  ChainLcp chain;
  make_nonassociated_chain(30, 3, chain);
  const LcpResult r = fischer_burmeister_newton(
      chain.split, chain.k, VectorXd::Zero(chain.split.q.size()), {.max_iterations = 1});
  EXPECT_EQ(r.status, LcpStatus::iteration_limit);
  EXPECT_GE(r.z.minCoeff(), 0.0);
  EXPECT_GT(r.residuals.worst_relative(), 1e-9);
}

}  // namespace
}  // namespace bimrock
