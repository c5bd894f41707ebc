// Domain validation and measures. Areas are closed forms (rectangles and a diamond whose
// diagonals are 2: area 2); every bad polygon must be named the way a case file names it.
#include <gtest/gtest.h>

#include <bimrock/geometry/domain.hpp>
#include <bimrock/geometry/geometry_error.hpp>

#include "support/rectangle.hpp"

namespace bimrock {
namespace {

using testing::rectangle;

// An L: the square [0,10]^2 less its top-right quarter [5,10]^2 (area 100 - 25 = 75).
Polygon l_shape() {
  return {{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}};
}

std::string item_of(const Domain& d) {
  try {
    validate(d);
  } catch (const GeometryError& e) {
    return e.item();
  }
  return "valid";
}

TEST(Domain, AreaIsOutlineLessHoles) {
  const Domain d{l_shape(), {{{{2, 1}, {3, 2}, {2, 3}, {1, 2}}}}, {}};
  EXPECT_EQ(item_of(d), "valid");
  EXPECT_DOUBLE_EQ(area(d), 73.0);
}

TEST(Domain, ZoneContainingPicksTheFirstListed) {
  Domain d{rectangle(0, 0, 4, 2),
           {},
           {{"weak", rectangle(-1, -1, 2, 3)}, {"strong", rectangle(1, -1, 5, 3)}}};
  EXPECT_EQ(zone_containing(d, {0.5, 1.0}), 0);
  EXPECT_EQ(zone_containing(d, {1.5, 1.0}), 0);  // in both: the first wins
  EXPECT_EQ(zone_containing(d, {3.0, 1.0}), 1);
  EXPECT_EQ(zone_containing(d, {9.0, 1.0}), -1);
}

struct BadDomain {
  const char* name;
  Domain domain;
  const char* item;
  const char* words;  // part of the message
};

class BadDomains : public ::testing::TestWithParam<BadDomain> {};

TEST_P(BadDomains, AreNamedWithTheItem) {
  try {
    validate(GetParam().domain);
    FAIL() << "accepted";
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.item(), GetParam().item);
    EXPECT_NE(std::string(e.what()).find(GetParam().words), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Validation, BadDomains,
    ::testing::Values(
        BadDomain{"bow_tie",
                  {{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}, {}, {}},
                  "domain.outline",
                  "intersects itself"},
        BadDomain{
            "collinear", {{{{0, 0}, {1, 0}, {2, 0}}}, {}, {}}, "domain.outline", "folds back"},
        BadDomain{"clockwise",
                  {{{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}, {}, {}},
                  "domain.outline",
                  "clockwise"},
        BadDomain{"two_vertices", {{{{0, 0}, {1, 0}}}, {}, {}}, "domain.outline", "3 vertices"},
        BadDomain{"repeated_vertex",
                  {{{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}, {}, {}},
                  "domain.outline",
                  "repeats"},
        BadDomain{
            "spike", {{{{0, 0}, {2, 0}, {1, 0}, {1, 1}}}, {}, {}}, "domain.outline", "folds back"},
        BadDomain{"hole_outside",
                  {rectangle(0, 0, 10, 10), {rectangle(1, 1, 2, 2), rectangle(11, 1, 12, 2)}, {}},
                  "domain.holes[1]",
                  "outside"},
        BadDomain{"hole_crossing",
                  {rectangle(0, 0, 10, 10), {rectangle(8, 1, 12, 2)}, {}},
                  "domain.holes[0]",
                  "crosses the domain outline"},
        BadDomain{"hole_in_the_notch",
                  {l_shape(), {rectangle(6, 6, 7, 7)}, {}},
                  "domain.holes[0]",
                  "outside"},
        BadDomain{"holes_overlap",
                  {rectangle(0, 0, 10, 10), {rectangle(1, 1, 3, 3), rectangle(2, 2, 4, 4)}, {}},
                  "domain.holes[1]",
                  "overlaps domain.holes[0]"},
        BadDomain{"hole_in_hole",
                  {rectangle(0, 0, 10, 10), {rectangle(1, 1, 5, 5), rectangle(2, 2, 3, 3)}, {}},
                  "domain.holes[1]",
                  "overlaps domain.holes[0]"},
        BadDomain{"holes_touch",
                  {rectangle(0, 0, 10, 10), {rectangle(1, 1, 3, 3), rectangle(3, 1, 4, 3)}, {}},
                  "domain.holes[1]",
                  "touches"},
        BadDomain{"bad_zone",
                  {rectangle(0, 0, 10, 10),
                   {},
                   {{"a", rectangle(0, 0, 1, 1)}, {"b", {{{0, 0}, {1, 0}}}}}},
                  "domain.zones[1]",
                  "3 vertices"}),
    [](const auto& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace bimrock
