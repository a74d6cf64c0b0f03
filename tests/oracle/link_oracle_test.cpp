// The minimum-link references' own tests (tests/oracle/link_oracle.h): the rational free check
// on hand-worked segments, touching, along edges and through pinches.
#include "oracle/link_oracle.h"

#include <gtest/gtest.h>

#include "support/wavefront_hand.h"

namespace taut::test {
namespace link_oracle_test {

oracle::QPoint qp(long x, long y) { return {mpq_class(x), mpq_class(y)}; }

TEST(LinkOracle, SegmentFree) {
  const Scene sc = normalized({{0, 0}, {12, 12}}, {rect(4, 4, 8, 8)});
  auto free = [&](oracle::QPoint a, oracle::QPoint b) { return oracle::segment_free(a, b, sc.domain, sc.obstacles); };
  EXPECT_TRUE(free(qp(0, 2), qp(12, 2)));
  EXPECT_FALSE(free(qp(0, 6), qp(12, 6)));                          // through the square
  EXPECT_TRUE(free(qp(0, 4), qp(12, 4)));                           // along its bottom edge
  EXPECT_FALSE(free(qp(2, 2), qp(10, 10)));                          // the diagonal crosses it
  EXPECT_FALSE(free(oracle::QPoint{mpq_class(9, 2), 0}, qp(9, 12)));  // steep, through
  EXPECT_FALSE(free(qp(12, 0), oracle::QPoint{mpq_class(15, 2), mpq_class(9, 2)}));  // ends inside (7.5,4.5)
}

TEST(LinkOracle, SegmentFreeTouchingAndPinches) {
  // touching a corner from outside is free; entering at a corner is not
  const Scene sq = normalized({{0, 0}, {12, 12}}, {rect(4, 4, 8, 8)});
  EXPECT_FALSE(oracle::segment_free(qp(2, 10), qp(10, 2), sq.domain, sq.obstacles));  // through (6,6)
  EXPECT_TRUE(oracle::segment_free(qp(0, 8), qp(8, 0), sq.domain, sq.obstacles));      // touches the corner (4,4)
  EXPECT_TRUE(oracle::segment_free(qp(0, 12), qp(4, 8), sq.domain, sq.obstacles));     // ends on a corner
  // a triangle's tip touching a rectangle's bottom edge from below (a T-shaped pinch at (5,5)):
  // running along that edge through the tip slips between them
  const Scene t = normalized({{0, 0}, {12, 12}}, {rect(1, 5, 11, 10), geom::Polygon{{{3, 1}, {7, 1}, {5, 5}}, {}}});
  EXPECT_FALSE(oracle::segment_free(qp(2, 5), qp(8, 5), t.domain, t.obstacles));
  EXPECT_TRUE(oracle::segment_free(qp(2, 5), qp(5, 5), t.domain, t.obstacles));  // up to the pinch
  // two squares touching at a corner: straight through the pinch point is not free, grazing it
  // with both squares on one side is
  const Scene two = normalized({{0, 0}, {12, 12}}, {rect(2, 2, 6, 6), rect(6, 6, 10, 10)});
  EXPECT_FALSE(oracle::segment_free(qp(2, 10), qp(10, 2), two.domain, two.obstacles));
  EXPECT_FALSE(oracle::segment_free(qp(0, 0), qp(12, 12), two.domain, two.obstacles));  // through both
  EXPECT_TRUE(oracle::segment_free(qp(6, 0), qp(6, 6), two.domain, two.obstacles));              // up to the pinch
}

}  // namespace link_oracle_test
}  // namespace taut::test
