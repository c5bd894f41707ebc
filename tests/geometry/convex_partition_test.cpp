// The convex partition of the block cutter's non-convex faces. Its pieces are checked here
// independently of CGAL: each convex (no corner turns right) and together of the face's area
// (a 6 x 6 square less two notches of 8: 20), on a face where CGAL's optimal partition itself is
// not convex. (The face the fuzz target found, cutting a rock slope, is tests/app/data/repro/
// partition_not_convex.yaml: its corners are exact intersections of joint traces, which
// rounded to doubles no longer fail.)
#include <cmath>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>

#include <CGAL/Partition_traits_2.h>
#include <CGAL/exceptions.h>
#include <CGAL/partition_2.h>
#include <CGAL/partition_is_valid_2.h>

#include <bimrock/geometry/convex_partition.hpp>

namespace bimrock::cut {
namespace {

double area(const std::vector<Vec2>& p) {
  double twice = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    twice += cross(p[k], p[(k + 1) % p.size()]);
  return 0.5 * twice;
}

// The least turn of a polygon's corners (negative: a reflex corner), as twice the triangle
// area of each corner with its neighbours.
double least_turn(const std::vector<Vec2>& p) {
  double least = INFINITY;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec2& a = p[(k + p.size() - 1) % p.size()];
    least = std::min(least, cross(p[k] - a, p[(k + 1) % p.size()] - a));
  }
  return least;
}

// A cup: its first corner (4, 4) is reflex, and from there CGAL 5.5's optimal partition
// returns a piece that is neither simple nor convex (0 6, 2 4, 2 2, 0 0, 6 0, 4 2).
const std::vector<Vec2> kCup = {{4, 4}, {6, 6}, {0, 6}, {2, 4}, {2, 2}, {0, 0}, {6, 0}, {4, 2}};

std::vector<Point> exact(const std::vector<Vec2>& p) {
  std::vector<Point> out;
  for (const Vec2& v : p)
    out.emplace_back(v.x(), v.y());
  return out;
}

TEST(ConvexPartition, CgalsOptimalPartitionOfThisFaceIsNotConvex) {
  // The guard's reason, and that this face reaches it: if a CGAL release mends its optimal
  // partition, this fails, and convex_pieces() could trust it again (its upstream fix starts
  // the partition at the lowest corner in x, then y, which is never reflex).
  std::vector<Point> corners = exact(kCup);
  using Traits = CGAL::Partition_traits_2<Kernel>;
  std::vector<Traits::Polygon_2> pieces;
  bool convex = true;
  try {  // a debug build of CGAL checks its result and throws
    CGAL::optimal_convex_partition_2(corners.begin(), corners.end(), std::back_inserter(pieces));
    convex = CGAL::convex_partition_is_valid_2(corners.begin(), corners.end(), pieces.begin(),
                                               pieces.end());
  } catch (const CGAL::Failure_exception&) {
    convex = false;
  }
  EXPECT_FALSE(convex);
}

TEST(ConvexPartition, PiecesAreConvexAndMakeUpTheFace) {
  std::vector<Point> corners = exact(kCup);
  for (const int max_optimal : {100, 4}) {  // the optimal partition, or the approximation
    const std::vector<std::vector<std::size_t>> pieces = convex_pieces(corners, max_optimal);
    ASSERT_GE(pieces.size(), 2u);
    double total = 0.0;
    std::vector<int> used(kCup.size(), 0);
    for (const std::vector<std::size_t>& piece : pieces) {
      std::vector<Vec2> p;
      for (const std::size_t k : piece) {
        p.push_back(kCup[k]);
        used[k] = 1;
      }
      EXPECT_GT(least_turn(p), -1e-9) << "a reflex corner in a piece of " << p.size();
      EXPECT_GT(area(p), 0.0);
      total += area(p);
    }
    EXPECT_NEAR(total, 20.0, 1e-12);
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), static_cast<long>(kCup.size()));
  }
}

}  // namespace
}  // namespace bimrock::cut
