// Polygon measures and checks. Expected numbers are closed forms (shoelace areas and centroids
// of triangles and rectangles worked by hand).
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

}  // namespace
}  // namespace bimrock
