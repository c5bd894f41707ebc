// The nodes of the LCP's polyhedron that branch and bound prunes as empty, and the Farkas
// certificates that prove them so. Each node's emptiness and each certificate are worked by hand
// on LCP(M, q) with M = [[2, 1], [1, -1]], q = (2, -2): w1 = 2 z1 + z2 + 2, w2 = z1 - z2 - 2.
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
