// The rectilinear link-distance reference's own tests (oracle/link_polygon_oracle.h): hand-worked
// polygons, and random polyominoes against a second, independent method: a BFS over every lattice
// point of the polygon that expands whole chords (points at k + 1 links are those on an
// axis-parallel segment from a point at k), with membership read straight from the polyomino's
// cell boxes (not from the ring, nor from the reference's point-in-polygon test). The lattice
// holds every Hanan grid point and, once the cells are stretched, many points that are not: the
// two must agree on every distance and on the diameter (which checks that the Hanan grid points
// attain the diameter over the whole polygon). Also: the paper's claim that convex vertices
// attain the diameter, on random polygons.
#include "oracle/link_polygon_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geom/predicates.h"
#include "support/random_shapes.h"
#include "support/sanitized.h"

namespace link_polygon_oracle_test {

using taut::geom::Box;
using taut::geom::Coord;
using taut::geom::Point;
using taut::geom::Ring;
using taut::oracle::LinkPolygonReference;
using Links = std::optional<int>;

std::string ring_str(const Ring& r) {
  std::ostringstream s;
  s << "{";
  for (std::size_t i = 0; i < r.size(); ++i) s << (i ? ", " : "") << "{" << r[i].x << ", " << r[i].y << "}";
  s << "}";
  return s.str();
}

Ring rect_ring(Coord x0, Coord y0, Coord x1, Coord y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Ring reversed(Ring r) {
  std::reverse(r.begin(), r.end());
  return r;
}

// Every edge of length >= 2 gets an extra (collinear) vertex one unit after its start.
Ring with_collinear(const Ring& r) {
  Ring out;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()];
    out.push_back(a);
    const int dx = (b.x > a.x) - (b.x < a.x), dy = (b.y > a.y) - (b.y < a.y);
    if (std::abs(b.x - a.x) + std::abs(b.y - a.y) >= 2) out.push_back({a.x + dx, a.y + dy});
  }
  return out;
}

// A width-1 corridor of unit cells: from cell (0, 0), each run (direction R, U, L or D, length)
// adds `length` cells in that direction.
std::vector<Box> corridor(const std::vector<std::pair<char, int>>& runs) {
  std::vector<Box> cells{{{0, 0}, {1, 1}}};
  Point c{0, 0};
  for (const auto& [dir, len] : runs)
    for (int k = 0; k < len; ++k) {
      c.x += dir == 'R' ? 1 : dir == 'L' ? -1 : 0;
      c.y += dir == 'U' ? 1 : dir == 'D' ? -1 : 0;
      cells.push_back({c, {c.x + 1, c.y + 1}});
    }
  return cells;
}

// The second method: every lattice point of the bounding box of closed boxes, in P when some box
// holds it; a unit step usable when some box holds its midpoint. links(s) by chord expansion.
class Lattice {
 public:
  explicit Lattice(const std::vector<Box>& boxes) : boxes_(boxes) {
    lo_ = hi_ = boxes.at(0).lo;
    for (const Box& b : boxes) {
      lo_ = {std::min(lo_.x, b.lo.x), std::min(lo_.y, b.lo.y)};
      hi_ = {std::max(hi_.x, b.hi.x), std::max(hi_.y, b.hi.y)};
    }
    w_ = hi_.x - lo_.x + 1;
    h_ = hi_.y - lo_.y + 1;
    in_.assign(static_cast<std::size_t>(w_ * h_), 0);
    right_ = up_ = in_;
    for (int i = 0; i < w_; ++i)
      for (int j = 0; j < h_; ++j) {
        const long x2 = 2L * (lo_.x + i), y2 = 2L * (lo_.y + j);
        in_[idx(i, j)] = held(x2, y2);
        right_[idx(i, j)] = i + 1 < w_ && held(x2 + 1, y2);
        up_[idx(i, j)] = j + 1 < h_ && held(x2, y2 + 1);
      }
  }
  bool contains(Point p) const {
    return p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y && in_[idx(p.x - lo_.x, p.y - lo_.y)];
  }
  // links from s to every lattice point (-1: outside P or unreachable)
  std::vector<int> links(Point s) const {
    std::vector<int> d(in_.size(), -1);
    std::vector<std::pair<int, int>> queue{{s.x - lo_.x, s.y - lo_.y}};
    d[idx(queue[0].first, queue[0].second)] = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto [i, j] = queue[head];
      const int k = d[idx(i, j)];
      auto walk = [&](int di, int dj) {
        int a = i, b = j;
        while (true) {
          const bool ok = di > 0 ? right_[idx(a, b)] : di < 0 ? (a > 0 && right_[idx(a - 1, b)])
                        : dj > 0 ? up_[idx(a, b)] : (b > 0 && up_[idx(a, b - 1)]);
          if (!ok) return;
          a += di;
          b += dj;
          if (d[idx(a, b)] < 0) {
            d[idx(a, b)] = k + 1;
            queue.push_back({a, b});
          }
        }
      };
      walk(1, 0), walk(-1, 0), walk(0, 1), walk(0, -1);
    }
    return d;
  }
  Links distance(Point a, Point b) const {
    if (!contains(a) || !contains(b)) return std::nullopt;
    return links(a)[idx(b.x - lo_.x, b.y - lo_.y)];
  }
  int diameter() const {
    int best = 0;
    for (int i = 0; i < w_; ++i)
      for (int j = 0; j < h_; ++j)
        if (in_[idx(i, j)])
          for (int v : links({lo_.x + i, lo_.y + j})) best = std::max(best, v);
    return best;
  }
  Point lo() const { return lo_; }
  Point hi() const { return hi_; }

 private:
  std::size_t idx(int i, int j) const { return static_cast<std::size_t>(i * h_ + j); }
  bool held(long x2, long y2) const {
    for (const Box& b : boxes_)
      if (2L * b.lo.x <= x2 && x2 <= 2L * b.hi.x && 2L * b.lo.y <= y2 && y2 <= 2L * b.hi.y) return true;
    return false;
  }
  std::vector<Box> boxes_;
  Point lo_, hi_;
  int w_ = 0, h_ = 0;
  std::vector<char> in_, right_, up_;
};

// Every check on one polygon given in several equivalent rings: both orientations, with collinear
// vertices.
std::vector<Ring> variants(const Ring& r) { return {r, reversed(r), with_collinear(r), reversed(with_collinear(r))}; }

void expect_diameters(const LinkPolygonReference& ref, int links) {
  const auto d = ref.diameter();
  EXPECT_EQ(d.links, links);
  EXPECT_EQ(ref.distance(d.a, d.b), Links(links));
  EXPECT_EQ(ref.vertex_diameter(), links);
  EXPECT_EQ(ref.convex_vertex_diameter(), links);
}

TEST(LinkPolygonOracle, Rectangle) {
  for (const Ring& r : variants(rect_ring(0, 0, 6, 4))) {
    SCOPED_TRACE(ring_str(r));
    const LinkPolygonReference ref(r);
    EXPECT_EQ(ref.corners().size(), 4u);
    EXPECT_TRUE(ref.contains({0, 0}));
    EXPECT_TRUE(ref.contains({6, 2}));  // on an edge
    EXPECT_TRUE(ref.contains({3, 2}));
    EXPECT_FALSE(ref.contains({7, 2}));
    EXPECT_FALSE(ref.contains({3, -1}));
    EXPECT_EQ(ref.distance({0, 0}, {0, 0}), Links(0));
    EXPECT_EQ(ref.distance({0, 0}, {6, 0}), Links(1));  // along an edge
    EXPECT_EQ(ref.distance({3, 0}, {3, 4}), Links(1));  // across, off the vertex grid
    EXPECT_EQ(ref.distance({0, 0}, {6, 4}), Links(2));
    EXPECT_EQ(ref.distance({1, 1}, {5, 3}), Links(2));
    EXPECT_EQ(ref.distance({2, 2}, {2, 2}), Links(0));
    EXPECT_EQ(ref.distance({0, 0}, {7, 4}), std::nullopt);
    EXPECT_EQ(ref.distance({-1, 2}, {3, 2}), std::nullopt);
    EXPECT_EQ(ref.distance({-1, 2}, {-1, 2}), std::nullopt);  // outside, even to itself
    expect_diameters(ref, 2);
  }
}

TEST(LinkPolygonOracle, LShape) {
  // An L is the union of two rectangles that share the corner square [0,1]^2: from a in the
  // horizontal arm (a.y <= 1) to b in the vertical arm (b.x <= 1) via (b.x, a.y) in that square,
  // two links. So an L has diameter 2, like a rectangle (not 3).
  const Ring l{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
  EXPECT_EQ(LinkPolygonReference(l).convex(), (std::vector<bool>{true, true, true, false, true, true}));
  EXPECT_EQ(LinkPolygonReference(reversed(l)).convex(), (std::vector<bool>{true, true, false, true, true, true}));
  for (const Ring& r : variants(l)) {
    SCOPED_TRACE(ring_str(r));
    const LinkPolygonReference ref(r);
    EXPECT_FALSE(ref.contains({2, 2}));
    EXPECT_TRUE(ref.contains({1, 1}));
    EXPECT_EQ(ref.distance({4, 0}, {0, 4}), Links(2));
    EXPECT_EQ(ref.distance({4, 1}, {1, 4}), Links(2));  // along both inner edges
    EXPECT_EQ(ref.distance({4, 1}, {0, 3}), Links(2));
    EXPECT_EQ(ref.distance({4, 1}, {2, 2}), std::nullopt);
    expect_diameters(ref, 2);
  }
}

TEST(LinkPolygonOracle, UShape) {
  // A U: arms [0,1] x [0,4] and [4,5] x [0,4] on the base [0,5] x [0,1]. The tops of the two arms
  // see each other in no two links (the corners (a.x, b.y), (b.x, a.y) are a and b themselves and
  // the top segment leaves P), and in three through the base. Every point is in an arm or the
  // base, and reaches the base's line with one link: diameter 3.
  const Ring u{{0, 0}, {5, 0}, {5, 4}, {4, 4}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
  for (const Ring& r : variants(u)) {
    SCOPED_TRACE(ring_str(r));
    const LinkPolygonReference ref(r);
    EXPECT_EQ(ref.distance({0, 4}, {5, 4}), Links(3));
    EXPECT_EQ(ref.distance({1, 4}, {4, 4}), Links(3));
    EXPECT_EQ(ref.distance({1, 3}, {4, 2}), Links(3));
    EXPECT_EQ(ref.distance({0, 4}, {5, 0}), Links(2));
    EXPECT_EQ(ref.distance({0, 1}, {5, 1}), Links(1));  // along the base's top
    EXPECT_EQ(ref.distance({2, 2}, {0, 0}), std::nullopt);
    expect_diameters(ref, 3);
  }
}

TEST(LinkPolygonOracle, Comb) {
  // m teeth [2i, 2i+1] x [1, 3] on the base [0, 2m-1] x [0, 1]: as in the U, two tooth tips are 3
  // links apart (down, along the base, up) and never 2; diameter 3.
  for (int m = 2; m <= 5; ++m) {
    std::vector<Box> boxes{{{0, 0}, {2 * m - 1, 1}}};
    for (int i = 0; i < m; ++i) boxes.push_back({{2 * i, 1}, {2 * i + 1, 3}});
    const Ring ring = taut::test::union_ring(boxes);
    SCOPED_TRACE(ring_str(ring));
    EXPECT_EQ(ring.size(), static_cast<std::size_t>(4 * m));
    for (const Ring& r : variants(ring)) {
      const LinkPolygonReference ref(r);
      EXPECT_EQ(ref.distance({0, 3}, {2 * m - 1, 3}), Links(3));
      EXPECT_EQ(ref.distance({1, 3}, {2, 3}), Links(3));
      EXPECT_EQ(ref.distance({0, 3}, {2 * m - 1, 0}), Links(2));
      expect_diameters(ref, 3);
    }
  }
}

// Width-1 corridors whose pieces (maximal straight runs of cells, each turn cell in both pieces
// it joins) meet only their neighbours in the sequence. Every axis-parallel segment in P lies in
// one piece (the corridor has width 1, so a segment across a piece does not leave it), and a link
// meets the next one, so the largest piece index a path has visited grows by at most 1 per link:
// from a point only in piece 1 to a point only in piece m takes >= m links, and m along the
// centre. Two points of pieces i < j are within j - i + 1 links (each link along its own piece,
// the first at a's offset, the one before the last stopping at b's), two points of one piece
// within 2. So the diameter is max(m, 2).
struct CorridorCase {
  std::vector<std::pair<char, int>> runs;
  int pieces;
  Point a, b;  // only in the first and only in the last piece
};

void check_corridor(const CorridorCase& c) {
  const std::vector<Box> cells = corridor(c.runs);
  const Ring ring = taut::test::union_ring(cells);
  SCOPED_TRACE(ring_str(ring));
  const Lattice lattice(cells);
  EXPECT_EQ(lattice.distance(c.a, c.b), Links(c.pieces));
  EXPECT_EQ(lattice.diameter(), std::max(c.pieces, 2));
  for (const Ring& r : variants(ring)) {
    const LinkPolygonReference ref(r);
    EXPECT_EQ(ref.distance(c.a, c.b), Links(c.pieces));
    EXPECT_EQ(ref.distance(c.b, c.a), Links(c.pieces));
    expect_diameters(ref, std::max(c.pieces, 2));
  }
}

TEST(LinkPolygonOracle, Staircase) {
  // k steps: runs R2, U2 repeated k times, 2k pieces (treads and risers 3 cells long with the
  // turn cells; treads 1 apart, so non-neighbouring pieces are disjoint); from the outer corner
  // (0, 0) of the first cell to the outer corner (2k+1, 2k+1) of the last: 2k links, the diameter.
  for (int k = 1; k <= 6; ++k) {
    SCOPED_TRACE("k = " + std::to_string(k));
    CorridorCase c{{}, 2 * k, {0, 0}, {2 * k + 1, 2 * k + 1}};
    for (int i = 0; i < k; ++i) c.runs.insert(c.runs.end(), {{'R', 2}, {'U', 2}});
    check_corridor(c);
  }
}

TEST(LinkPolygonOracle, Spiral) {
  // Runs R8 U8 L8 D6 R6 U4 L4 D2 spiral inwards with a gap of one cell between turns: 8 pieces,
  // from (0, 0) to the inner end's outer corner (2, 4) (cell (2, 4), no other cell near it).
  check_corridor({{{'R', 8}, {'U', 8}, {'L', 8}, {'D', 6}, {'R', 6}, {'U', 4}, {'L', 4}, {'D', 2}}, 8, {0, 0}, {2, 4}});
  // and a shorter one, R6 U6 L6 D4 R4 U2: 6 pieces, to (5, 5), the top corner of cell (4, 4)
  check_corridor({{{'R', 6}, {'U', 6}, {'L', 6}, {'D', 4}, {'R', 4}, {'U', 2}}, 6, {0, 0}, {5, 5}});
}

TEST(LinkPolygonOracle, RejectsBadRings) {
  EXPECT_THROW(LinkPolygonReference(Ring{{0, 0}, {4, 0}, {4, 4}, {1, 3}}), std::invalid_argument);  // sloped
  EXPECT_THROW(LinkPolygonReference(Ring{{0, 0}, {4, 0}, {4, 4}}), std::invalid_argument);
  EXPECT_THROW(LinkPolygonReference(Ring{{0, 0}, {4, 0}, {0, 0}, {0, 4}}), std::invalid_argument);  // back
  // two squares touching at (2, 2) as one ring: not simple
  EXPECT_THROW(LinkPolygonReference(Ring{{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}}),
               std::invalid_argument);
  // a repeated closing vertex and repeated vertices are dropped
  const LinkPolygonReference ref(Ring{{0, 0}, {4, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}});
  EXPECT_EQ(ref.corners().size(), 4u);
  EXPECT_EQ(ref.diameter().links, 2);
}

TEST(LinkPolygonOracle, RandomPolygonGenerator) {
  const unsigned seed = 20240611;
  std::mt19937 rng(seed);
  for (int t = 0; t < 200; ++t) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", polygon " + std::to_string(t));
    const int side = 1 + t % 9, cells = 1 + static_cast<int>(rng() % 40), stretch = 1 + t % 4;
    const Point origin{static_cast<Coord>(rng() % 41) - 20, static_cast<Coord>(rng() % 41) - 20};
    const auto s = taut::test::random_rectilinear_sample(rng, side, cells, stretch, origin);
    EXPECT_LE(s.cells.size(), static_cast<std::size_t>(std::min(cells, side * side)));
    __int128 area = 0;
    for (const Box& b : s.cells) {
      area += 2 * static_cast<__int128>(b.hi.x - b.lo.x) * (b.hi.y - b.lo.y);
      EXPECT_GE(b.lo.x, origin.x);
      EXPECT_LE(b.hi.x, origin.x + side * stretch);
    }
    EXPECT_TRUE(area == taut::geom::twice_area(s.ring)) << ring_str(s.ring);  // counter-clockwise, the union
    const LinkPolygonReference ref(s.ring);                                   // rectilinear and simple
    EXPECT_EQ(ref.corners(), s.ring) << "no collinear vertex";
  }
  std::mt19937 a(7), b(7);
  EXPECT_EQ(taut::test::random_rectilinear_polygon(a, 6, 20, 3, {5, 5}),
            taut::test::random_rectilinear_polygon(b, 6, 20, 3, {5, 5}));
}

// Distances of random lattice pairs (some outside P) and the diameter: the reference against the
// lattice. Unit cells (stretch 1) first, where the lattice is nearly the Hanan grid, then
// stretched ones, where most lattice points are not Hanan grid points.
TEST(LinkPolygonOracle, AgainstLattice) {
  const unsigned seed = 987654321;
  std::mt19937 rng(seed);
  const int polygons = static_cast<int>(taut::test::sanitized_share(240, 8));
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int pairs = 0, stretched = 0;
  for (int t = 0; t < polygons; ++t) {
    const int stretch = t < polygons / 2 ? 1 : uni(2, 3);
    const int side = uni(2, 7);
    const auto s = taut::test::random_rectilinear_sample(rng, side, uni(1, std::min(side * side, 30)), stretch,
                                                         {uni(-5, 5), uni(-5, 5)});
    SCOPED_TRACE("seed " + std::to_string(seed) + ", polygon " + std::to_string(t) + ": " + ring_str(s.ring));
    const LinkPolygonReference ref(s.ring);
    const Lattice lattice(s.cells);
    for (int k = 0; k < 30; ++k) {
      const Point a{uni(lattice.lo().x - 1, lattice.hi().x + 1), uni(lattice.lo().y - 1, lattice.hi().y + 1)};
      const Point b = k % 5 == 0 ? a : Point{uni(lattice.lo().x - 1, lattice.hi().x + 1), uni(lattice.lo().y - 1, lattice.hi().y + 1)};
      ASSERT_EQ(ref.contains(a), lattice.contains(a)) << a.x << "," << a.y;
      ASSERT_EQ(ref.distance(a, b), lattice.distance(a, b)) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
      ++pairs;
    }
    const auto d = ref.diameter();
    ASSERT_EQ(d.links, lattice.diameter());
    EXPECT_EQ(ref.distance(d.a, d.b), Links(d.links));
    EXPECT_EQ(lattice.distance(d.a, d.b), Links(d.links));
    stretched += stretch > 1;
  }
  EXPECT_GT(pairs, 0);
  EXPECT_GT(stretched, 0);
}

TEST(LinkPolygonOracle, ThinPolygonsAgainstLattice) {
  const unsigned seed = 55555;
  std::mt19937 rng(seed);
  const int polygons = static_cast<int>(taut::test::sanitized_share(200, 8));
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  for (int t = 0; t < polygons; ++t) {
    const auto s = taut::test::random_thin_polygon(rng, t % 2 ? 1 : 3);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", polygon " + std::to_string(t) + ": " + ring_str(s.ring));
    const LinkPolygonReference ref(s.ring);
    const Lattice lattice(s.cells);
    for (int k = 0; k < 10; ++k) {
      const Point a{uni(lattice.lo().x, lattice.hi().x), uni(lattice.lo().y, lattice.hi().y)};
      const Point b{uni(lattice.lo().x, lattice.hi().x), uni(lattice.lo().y, lattice.hi().y)};
      ASSERT_EQ(ref.distance(a, b), lattice.distance(a, b)) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
    }
    ASSERT_EQ(ref.diameter().links, lattice.diameter());
  }
}

// The paper (section 4): some pair of convex vertices attains the diameter. Checked, not assumed:
// a failure prints the polygon. Compact polyominoes (random_rectilinear_polygon) and thin ones.
TEST(LinkPolygonOracle, DiameterAtConvexVertices) {
  const unsigned seed = 1486360;
  std::mt19937 rng(seed);
  const int polygons = static_cast<int>(taut::test::sanitized_share(300, 10));
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::map<int, int> histogram;
  for (int t = 0; t < 2 * polygons; ++t) {
    const int side = uni(3, 10);
    const Ring ring = t < polygons ? taut::test::random_rectilinear_polygon(rng, side, uni(side, std::min(side * side, 40)),
                                                                            uni(1, 4), {uni(-100, 100), uni(-100, 100)})
                                   : taut::test::random_thin_polygon(rng, uni(1, 4)).ring;
    SCOPED_TRACE("seed " + std::to_string(seed) + ", polygon " + std::to_string(t) + ": " + ring_str(ring));
    const LinkPolygonReference ref(ring);
    const int dia = ref.diameter().links;
    EXPECT_EQ(ref.vertex_diameter(), dia);
    EXPECT_EQ(ref.convex_vertex_diameter(), dia);
    ++histogram[dia];
  }
  // not vacuous: the polygons reach well beyond rectangles and Ls
  EXPECT_GE(histogram.rbegin()->first, taut::test::kSanitized ? 6 : 10);
  std::ostringstream s;
  for (const auto& [d, n] : histogram) s << " " << d << ":" << n;
  RecordProperty("diameters", s.str());
  std::cout << "diameters (links:polygons):" << s.str() << "\n";
}

}  // namespace link_polygon_oracle_test
