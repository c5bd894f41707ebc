// The nodes of the LCP's polyhedron that branch and bound prunes as empty, and the Farkas
// certificates that prove them so. Each node's emptiness and each certificate are worked by hand
// on LCP(M, q) with M = [[2, 1], [1, -1]], q = (2, -2): w1 = 2 z1 + z2 + 2, w2 = z1 - z2 - 2; the
// simplex's own duals are checked against Farkas' lemma on random LCPs as well.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/solve/lcp.hpp>
#include <bimrock/solve/lcp_polyhedron.hpp>

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using Fix = LcpPolyhedron::Fix;

const LcpProblem kTwoRowLcp{MatrixXd{{2.0, 1.0}, {1.0, -1.0}}, VectorXd{{2.0, -2.0}}};

TEST(LcpPolyhedron, AFeasibleNodeHasNoCertificate) {
  // z = (2, 0) gives w = (6, 0): the root is not empty, nor is the node z2 = 0.
  LcpPolyhedron polyhedron(kTwoRowLcp);
  EXPECT_EQ(polyhedron.vertex({Fix::none, Fix::none}).status, LcpPolyhedron::Status::feasible);
  EXPECT_FALSE(polyhedron.certified_empty({Fix::none, Fix::none}));
  EXPECT_FALSE(polyhedron.certified_empty({Fix::none, Fix::z}));
}

TEST(LcpPolyhedron, AnEmptyNodeIsCertifiedWithTheRowsItHolds) {
  LcpPolyhedron polyhedron(kTwoRowLcp);
  // z1 = 0: w2 = -z2 - 2 < 0. y = (0, 1): M^T y = (1, -1), the first entry on a column held
  // at zero; q . y = -2.
  EXPECT_EQ(polyhedron.vertex({Fix::z, Fix::none}).status, LcpPolyhedron::Status::empty);
  EXPECT_TRUE(polyhedron.certified_empty({Fix::z, Fix::none}));
  // w1 = 0: 2 z1 + z2 = -2 has no z >= 0. y = (-1, 0), negative on the row held: M^T y =
  // (-2, -1), q . y = -2.
  EXPECT_EQ(polyhedron.vertex({Fix::w, Fix::none}).status, LcpPolyhedron::Status::empty);
  EXPECT_TRUE(polyhedron.certified_empty({Fix::w, Fix::none}));
}

// Whether y or -y proves the node `fix` of `problem` empty (Farkas' lemma, certifies_empty()).
bool either_sign_certifies(const LcpProblem& problem, const std::vector<Fix>& fix,
                           const VectorXd& y) {
  std::vector<char> held_w;
  std::vector<char> held_z;
  for (const Fix f : fix) {
    held_w.push_back(f == Fix::w);
    held_z.push_back(f == Fix::z);
  }
  const double m_max = problem.m.cwiseAbs().maxCoeff();
  if (y.size() != problem.size())
    return false;
  for (const double sign : {1.0, -1.0}) {
    const VectorXd r = sign * y;
    if (certifies_empty(problem.q, r, problem.m.transpose() * r,
                        problem.m.cwiseAbs().transpose() * r.cwiseAbs(), m_max, held_w, held_z,
                        0.0))
      return true;
  }
  return false;
}

TEST(LcpPolyhedron, AnEmptyVertexCarriesItsCertificateInItsDuals) {
  // The two empty nodes above: the simplex's final basis already holds their proofs.
  LcpPolyhedron polyhedron(kTwoRowLcp);
  for (const std::vector<Fix>& fix : {std::vector<Fix>{Fix::z, Fix::none}, {Fix::w, Fix::none}}) {
    const LcpPolyhedron::Vertex v = polyhedron.vertex(fix);
    ASSERT_EQ(v.status, LcpPolyhedron::Status::empty);
    EXPECT_TRUE(either_sign_certifies(kTwoRowLcp, fix, v.duals));
  }
  // The empty nodes of random LCPs of 6 rows, each row free, held at z = 0 or at w = 0.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int empty = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const LcpProblem p{MatrixXd::NullaryExpr(6, 6, [&] { return u(rng); }),
                       VectorXd::NullaryExpr(6, [&] { return u(rng); })};
    LcpPolyhedron node_lps(p);
    for (int code = 0; code < 729; code += 7) {  // a spread of the 3^6 ways to hold the rows
      std::vector<Fix> fix;
      for (int i = 0, c = code; i < 6; ++i, c /= 3)
        fix.push_back(static_cast<Fix>(c % 3));
      const LcpPolyhedron::Vertex v = node_lps.vertex(fix);
      if (v.status != LcpPolyhedron::Status::empty)
        continue;
      ++empty;
      EXPECT_TRUE(either_sign_certifies(p, fix, v.duals)) << "trial " << trial << " code " << code;
    }
  }
  EXPECT_GE(empty, 100);  // the test sees many empty nodes
}

TEST(CertifiesEmpty, HoldsEachConditionOnlyWhereTheNodeDoes) {
  const std::vector<char> none{0, 0};
  const std::vector<char> first{1, 0};
  const auto check = [](const VectorXd& y, const std::vector<char>& held_w,
                        const std::vector<char>& held_z, double slack) {
    return certifies_empty(kTwoRowLcp.q, y, kTwoRowLcp.m.transpose() * y,
                           kTwoRowLcp.m.cwiseAbs().transpose() * y.cwiseAbs(), 2.0, held_w, held_z,
                           slack);
  };
  // y = (0, 1): M^T y = (1, -1) proves the node z1 = 0 empty, not the root (z1 free).
  EXPECT_TRUE(check(VectorXd{{0.0, 1.0}}, none, first, 0.0));
  EXPECT_FALSE(check(VectorXd{{0.0, 1.0}}, none, none, 0.0));
  // y = (-1, 0) proves the node w1 = 0 empty, not the root (y must be >= 0 on free rows).
  EXPECT_TRUE(check(VectorXd{{-1.0, 0.0}}, first, none, 0.0));
  EXPECT_FALSE(check(VectorXd{{-1.0, 0.0}}, none, none, 0.0));
  // Held in [0, s] instead of at 0: w1 = 2 z1 + z2 + 2 <= s stays impossible below s = 2.
  EXPECT_TRUE(check(VectorXd{{-1.0, 0.0}}, first, none, 1.9));
  EXPECT_FALSE(check(VectorXd{{-1.0, 0.0}}, first, none, 2.1));
}

}  // namespace
}  // namespace bimrock
