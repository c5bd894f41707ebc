// Polygon measures and checks. Expected numbers are closed forms (shoelace areas and centroids
// of triangles and rectangles worked by hand).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock {
namespace {

TEST(Polygon, AreaAndCentroidOfATriangle) {
  const Polygon p{{{0, 0}, {3, 0}, {0, 6}}};
  EXPECT_DOUBLE_EQ(signed_area(p), 9.0);
  EXPECT_NEAR(centroid(p).x(), 1.0, 1e-15);
  EXPECT_NEAR(centroid(p).y(), 2.0, 1e-15);
}

TEST(Polygon, CentroidFarFromTheOriginKeepsItsDigits) {
  const double x0 = 1e6;
  const Polygon p{{{x0, x0}, {x0 + 0.2, x0}, {x0 + 0.2, x0 + 0.1}, {x0, x0 + 0.1}}};
  EXPECT_NEAR(centroid(p).x() - x0, 0.1, 1e-9);
  EXPECT_NEAR(centroid(p).y() - x0, 0.05, 1e-9);
  EXPECT_NEAR(signed_area(p), 0.02, 1e-9);
}

TEST(Polygon, OutwardNormalsOfACounterClockwiseSquare) {
  const Polygon p{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  EXPECT_TRUE(outward_normal(p, 0).isApprox(Vec2(0, -1)));
  EXPECT_TRUE(outward_normal(p, 1).isApprox(Vec2(1, 0)));
  EXPECT_TRUE(outward_normal(p, 2).isApprox(Vec2(0, 1)));
  EXPECT_TRUE(outward_normal(p, 3).isApprox(Vec2(-1, 0)));
}

TEST(Polygon, ContainsPointsInsideAndOnTheBoundaryOnly) {
  const Polygon p{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  EXPECT_TRUE(contains(p, {0.5, 0.5}, 1e-12));
  EXPECT_TRUE(contains(p, {1.0, 0.5}, 1e-12));
  EXPECT_FALSE(contains(p, {1.0 + 1e-9, 0.5}, 1e-12));
}

struct DefectCase {
  const char* name;
  Polygon polygon;
  PolygonDefect defect;
  std::size_t vertex;
};

class PolygonDefects : public ::testing::TestWithParam<DefectCase> {};

TEST_P(PolygonDefects, AreNamedWithTheOffendingVertex) {
  const PolygonCheck c = check_convex_polygon(GetParam().polygon, 1e-9);
  EXPECT_EQ(c.defect, GetParam().defect);
  EXPECT_EQ(c.vertex, GetParam().vertex);
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

INSTANTIATE_TEST_SUITE_P(
    Checks, PolygonDefects,
    ::testing::Values(
        DefectCase{"valid", {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, PolygonDefect::none, 0},
        DefectCase{"collinear_vertex_allowed",
                   {{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}}},
                   PolygonDefect::none,
                   0},
        DefectCase{"two_vertices", {{{0, 0}, {1, 0}}}, PolygonDefect::too_few_vertices, 0},
        DefectCase{"nan", {{{0, 0}, {1, kNaN}, {1, 1}}}, PolygonDefect::not_finite, 1},
        DefectCase{
            "duplicate", {{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}, PolygonDefect::duplicate_vertex, 2},
        DefectCase{"zero_area", {{{0, 0}, {1, 0}, {2, 0}}}, PolygonDefect::zero_area, 0},
        DefectCase{"clockwise", {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}, PolygonDefect::clockwise, 0},
        DefectCase{
            "reflex", {{{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}}, PolygonDefect::non_convex, 2},
        DefectCase{
            "star", {{{0, 0}, {2, 1}, {0, 2}, {1, 0}, {2, 2}}}, PolygonDefect::non_convex, 0}),
    [](const auto& p) { return std::string(p.param.name); });

// The first vertex within tol of an earlier one, by its definition: every pair.
std::size_t first_duplicate_by_all_pairs(const std::vector<Vec2>& v, double tol) {
  for (std::size_t m = 1; m < v.size(); ++m) {
    for (std::size_t k = 0; k < m; ++k) {
      if ((v[k] - v[m]).norm() <= tol)
        return m;
    }
  }
  return v.size();
}

// Points on a lattice of spacing about tol, jittered (or not: repeated points): many pairs just
// within and just beyond tol, and many points per cell of the fast search, which must agree with
// every pair. Also tol = 0 and a tol far below the points' spacing (its coarser cells).
TEST(Polygon, FirstDuplicateVertexAgreesWithAllPairs) {
  std::mt19937 random(7);
  int found = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double tol = trial % 10 == 0   ? 0.0
                       : trial % 10 == 5 ? 1e-14
                                         : std::pow(10.0, -(trial % 7));
    const double spacing = (tol > 1e-10 ? tol : 1e-3) * (0.5 + 0.01 * (trial % 150));
    const int side = 5 + trial % 40;
    const double amount = trial % 3 == 0 ? 0.0 : 0.3;
    std::uniform_int_distribution<int> cell(0, side);
    std::uniform_real_distribution<double> jitter(-amount, amount);
    std::vector<Vec2> v(static_cast<std::size_t>(40 + trial * 5));
    for (Vec2& p : v) {
      p = {1e3 + spacing * (cell(random) + jitter(random)),
           -2e3 + spacing * (cell(random) + jitter(random))};
    }
    const std::size_t expected = first_duplicate_by_all_pairs(v, tol);
    found += expected < v.size() ? 1 : 0;
    EXPECT_EQ(first_duplicate_vertex(v, tol), expected) << "trial " << trial << ", tol " << tol;
  }
  EXPECT_GT(found, 100);  // the trials do test duplicates, and some test their absence
  EXPECT_LT(found, 200);
}

TEST(Polygon, FirstDuplicateVertexOfIdenticalOrFewVertices) {
  EXPECT_EQ(first_duplicate_vertex(std::vector<Vec2>(1000, Vec2(3, 4)), 0.0), 1u);
  std::vector<Vec2> repeated(100000, Vec2(1, 1));  // tol 0: the coarse cells, all in one
  repeated[0] = {0, 0};
  EXPECT_EQ(first_duplicate_vertex(repeated, 0.0), 2u);
  EXPECT_EQ(first_duplicate_vertex(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}}, 0.5), 3u);
  EXPECT_EQ(first_duplicate_vertex(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}, {1, 0.4}}, 0.5), 3u);
}

// A block of 1e5 vertices (a circle of radius 100 m, vertices 6.3 mm apart) is a valid block,
// checked in O(n log n) (it took all pairs, 5e9 of them, before); a vertex moved to within the
// tolerance of another is named.
TEST(Polygon, ABlockOf100000VerticesIsChecked) {
  const std::size_t n = 100000;
  Polygon p;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(n);
    p.vertices.push_back({5e5 + 100.0 * std::cos(a), 4e6 + 100.0 * std::sin(a)});
  }
  const double tol = model_tolerance(bbox_of(p));
  EXPECT_EQ(check_convex_polygon(p, tol).defect, PolygonDefect::none);

  p.vertices[77777] = p.vertices[12345] + Vec2(0.6 * tol, -0.6 * tol);  // 0.85 tol away
  const PolygonCheck c = check_convex_polygon(p, tol);
  EXPECT_EQ(c.defect, PolygonDefect::duplicate_vertex);
  EXPECT_EQ(c.vertex, 77777u);
  p.vertices[77777] = p.vertices[12345] + Vec2(0.8 * tol, -0.8 * tol);  // 1.13 tol away
  EXPECT_NE(check_convex_polygon(p, tol).defect, PolygonDefect::duplicate_vertex);
}

}  // namespace
}  // namespace bimrock
