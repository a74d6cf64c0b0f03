// Tests for geom/triangulation.h: hand-drawn cases, error codes, and thousands of random
// layouts checked against brute force written here (exact winding numbers, point-in-triangle
// over all triangles, Euler counts), not against the code under test.
#include "geom/triangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace taut::geom {
namespace triangulation_test {

using i64 = std::int64_t;
using i128 = __int128;

// ---- independent reference geometry (i64 coordinates so that scaled points fit) ------------

struct P64 {
  i64 x, y;
};
i128 orient128(P64 a, P64 b, P64 c) {
  return i128{b.x - a.x} * (c.y - a.y) - i128{b.y - a.y} * (c.x - a.x);
}
P64 scaled(Point p, i64 s) { return {p.x * s, p.y * s}; }
bool on_seg(P64 p, P64 a, P64 b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y) && orient128(a, b, p) == 0;
}

// Winding number of ring around p (p not on the ring); exact. Works for weakly simple rings.
int winding(P64 p, const Ring& ring, i64 s) {
  int w = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P64 a = scaled(ring[i], s), b = scaled(ring[(i + 1) % ring.size()], s);
    if (a.y <= p.y) {
      if (b.y > p.y && orient128(a, b, p) > 0) ++w;
    } else if (b.y <= p.y && orient128(a, b, p) < 0) {
      --w;
    }
  }
  return w;
}
// -1 strictly outside, 0 on the boundary, 1 strictly inside the polygon with holes. Points and
// the polygon are compared at scale s (the point is already scaled).
int where(P64 p, const Polygon& poly, i64 s) {
  i64 lx = INT64_MAX, ly = INT64_MAX, hx = INT64_MIN, hy = INT64_MIN;  // bounding box first
  for (Point q : poly.outer) {
    lx = std::min<i64>(lx, q.x * s), hx = std::max<i64>(hx, q.x * s);
    ly = std::min<i64>(ly, q.y * s), hy = std::max<i64>(hy, q.y * s);
  }
  if (p.x < lx || p.x > hx || p.y < ly || p.y > hy) return -1;
  auto on_ring = [&](const Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i)
      if (on_seg(p, scaled(r[i], s), scaled(r[(i + 1) % r.size()], s))) return true;
    return false;
  };
  if (on_ring(poly.outer)) return 0;
  for (const Ring& h : poly.holes)
    if (on_ring(h)) return 0;
  if (winding(p, poly.outer, s) == 0) return -1;
  for (const Ring& h : poly.holes)
    if (winding(p, h, s) != 0) return -1;
  return 1;
}
i128 shoelace(const Ring& r) {
  i128 a = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point p = r[i], q = r[(i + 1) % r.size()];
    a += i128{p.x} * q.y - i128{q.x} * p.y;
  }
  return a;
}

// ---- builders --------------------------------------------------------------------------------

Polygon rect(Coord x0, Coord y0, Coord x1, Coord y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}
Ring cw_rect(Coord x0, Coord y0, Coord x1, Coord y1) {
  return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
}

// ---- the brute-force verifier ------------------------------------------------------------------

struct VerifyOptions {
  int random_points = 40;
  bool brute_edges = true;  // O(triangles * obstacle edges) checks
};

void verify(const Box& dom, const std::vector<Polygon>& obs, const FreeSpaceTriangulation& t,
            std::mt19937_64& rng, VerifyOptions opt = {}) {
  ASSERT_TRUE(t.ok()) << (t.diagnostics().empty() ? "" : format(t.diagnostics()[0]));
  const std::vector<std::string> problems = t.check();
  ASSERT_TRUE(problems.empty()) << problems.size() << " problems, first: " << problems[0];
  const auto& vs = t.vertices();
  const auto& ts = t.triangles();

  // Vertices are exactly the distinct input points.
  std::vector<Point> expect = {dom.lo, {dom.hi.x, dom.lo.y}, dom.hi, {dom.lo.x, dom.hi.y}};
  for (const Polygon& p : obs) {
    expect.insert(expect.end(), p.outer.begin(), p.outer.end());
    for (const Ring& h : p.holes) expect.insert(expect.end(), h.begin(), h.end());
  }
  std::sort(expect.begin(), expect.end());
  expect.erase(std::unique(expect.begin(), expect.end()), expect.end());
  ASSERT_EQ(vs, expect);

  // Area adds up exactly.
  i128 free2 = i128{2} * (i128{dom.hi.x} - dom.lo.x) * (i128{dom.hi.y} - dom.lo.y);
  for (const Polygon& p : obs) {
    free2 -= shoelace(p.outer);
    for (const Ring& h : p.holes) free2 -= shoelace(h);
  }
  i128 sum = 0;
  for (const FreeTriangle& tr : ts) {
    const i128 o = orient128(scaled(vs[tr.v[0]], 1), scaled(vs[tr.v[1]], 1), scaled(vs[tr.v[2]], 1));
    ASSERT_GT(o, 0);
    sum += o;
  }
  ASSERT_TRUE(sum == free2) << "free area " << static_cast<double>(sum) << " expected "
                            << static_cast<double>(free2);

  auto on_domain_side = [&](Point a, Point b) {
    return (a.x == b.x && (a.x == dom.lo.x || a.x == dom.hi.x)) ||
           (a.y == b.y && (a.y == dom.lo.y || a.y == dom.hi.y));
  };
  // Every obstacle edge with its owner, for the brute-force edge checks.
  struct OwnedEdge {
    P64 u, w;
    std::size_t owner;
  };
  std::vector<OwnedEdge> all_edges;
  for (std::size_t k = 0; k < obs.size(); ++k)
    for (std::size_t r = 0; r <= obs[k].holes.size(); ++r) {
      const Ring& ring = r == 0 ? obs[k].outer : obs[k].holes[r - 1];
      for (std::size_t i = 0; i < ring.size(); ++i)
        all_edges.push_back({scaled(ring[i], 1), scaled(ring[(i + 1) % ring.size()], 1), k});
    }
  // On an edge of obstacle k (k = SIZE_MAX: of any obstacle).
  auto on_obstacle_edge = [&](std::size_t k, Point a, Point b) {
    const P64 pa = scaled(a, 1), pb = scaled(b, 1);
    for (const OwnedEdge& e : all_edges)
      if ((k == SIZE_MAX || e.owner == k) && on_seg(pa, e.u, e.w) && on_seg(pb, e.u, e.w))
        return true;
    return false;
  };
  if (opt.brute_edges) {
    for (std::size_t ti = 0; ti < ts.size(); ++ti) {
      const FreeTriangle& tr = ts[ti];
      SCOPED_TRACE(ti);  // triangle index
      // The centroid (scaled by 3) is strictly inside the domain and outside every obstacle:
      // the triangle lies in free space (its edges never cross constraints).
      const P64 c{i64{vs[tr.v[0]].x} + vs[tr.v[1]].x + vs[tr.v[2]].x,
                  i64{vs[tr.v[0]].y} + vs[tr.v[1]].y + vs[tr.v[2]].y};
      ASSERT_TRUE(c.x > 3 * i64{dom.lo.x} && c.x < 3 * i64{dom.hi.x} && c.y > 3 * i64{dom.lo.y} &&
                  c.y < 3 * i64{dom.hi.y});
      for (const Polygon& p : obs) ASSERT_EQ(where(c, p, 3), -1);
      for (int k = 0; k < 3; ++k) {
        const Point a = vs[tr.v[k]], b = vs[tr.v[(k + 1) % 3]];
        const std::int32_t con = tr.constraint[k];
        if (con == kDomainEdge) {
          ASSERT_TRUE(on_domain_side(a, b));
          ASSERT_EQ(tr.neighbor[k], -1);
        } else if (con >= 0) {
          ASSERT_LT(static_cast<std::size_t>(con), obs.size());
          ASSERT_TRUE(on_obstacle_edge(static_cast<std::size_t>(con), a, b));
          ASSERT_EQ(tr.neighbor[k], -1);
        } else {
          ASSERT_EQ(con, kUnconstrained);
          ASSERT_FALSE(on_domain_side(a, b));
          ASSERT_FALSE(on_obstacle_edge(SIZE_MAX, a, b));
          const std::int32_t n = tr.neighbor[k];
          ASSERT_TRUE(n >= 0 && static_cast<std::size_t>(n) < ts.size());
          bool back = false;
          for (int j = 0; j < 3; ++j)
            back = back || (ts[n].v[j] == tr.v[(k + 1) % 3] && ts[n].v[(j + 1) % 3] == tr.v[k] &&
                            ts[n].neighbor[j] == static_cast<std::int32_t>(ti));
          ASSERT_TRUE(back);
        }
      }
    }
  }

  // Point location against brute force: the smallest free triangle index containing p.
  std::vector<Point> queries;
  std::uniform_int_distribution<int> pick(0, 2);
  for (int q = 0; q < opt.random_points; ++q) {
    const int kind = pick(rng);
    if (kind == 0 || ts.empty()) {
      queries.push_back(vs[std::uniform_int_distribution<std::size_t>(0, vs.size() - 1)(rng)]);
    } else if (kind == 1) {  // an integer point on a triangle edge
      const FreeTriangle& tr = ts[std::uniform_int_distribution<std::size_t>(0, ts.size() - 1)(rng)];
      const int k = pick(rng);
      const Point a = vs[tr.v[k]], b = vs[tr.v[(k + 1) % 3]];
      const i64 g = std::gcd(std::abs(i64{b.x} - a.x), std::abs(i64{b.y} - a.y));
      const i64 j = std::uniform_int_distribution<i64>(0, g)(rng);
      queries.push_back({static_cast<Coord>(a.x + (i64{b.x} - a.x) / g * j),
                         static_cast<Coord>(a.y + (i64{b.y} - a.y) / g * j)});
    } else {  // anywhere in the domain, or a little beyond it
      const i64 mx = std::max<i64>(2, (i64{dom.hi.x} - dom.lo.x) / 8);
      const i64 my = std::max<i64>(2, (i64{dom.hi.y} - dom.lo.y) / 8);
      const i64 x = std::uniform_int_distribution<i64>(std::max<i64>(-kMaxCoord, dom.lo.x - mx),
                                                       std::min<i64>(kMaxCoord, dom.hi.x + mx))(rng);
      const i64 y = std::uniform_int_distribution<i64>(std::max<i64>(-kMaxCoord, dom.lo.y - my),
                                                       std::min<i64>(kMaxCoord, dom.hi.y + my))(rng);
      queries.push_back({static_cast<Coord>(x), static_cast<Coord>(y)});
    }
  }
  for (const Point p : queries) {
    SCOPED_TRACE("query (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    std::int32_t brute = -1;
    int strictly_inside = 0;
    for (std::size_t ti = 0; ti < ts.size(); ++ti) {
      const P64 a = scaled(vs[ts[ti].v[0]], 1), b = scaled(vs[ts[ti].v[1]], 1),
                c = scaled(vs[ts[ti].v[2]], 1), q = scaled(p, 1);
      const i128 o1 = orient128(a, b, q), o2 = orient128(b, c, q), o3 = orient128(c, a, q);
      if (o1 >= 0 && o2 >= 0 && o3 >= 0 && brute < 0) brute = static_cast<std::int32_t>(ti);
      if (o1 > 0 && o2 > 0 && o3 > 0) ++strictly_inside;
    }
    ASSERT_LE(strictly_inside, 1);  // interiors are disjoint
    const std::optional<std::int32_t> got = t.locate(p);
    if (brute < 0)
      ASSERT_FALSE(got.has_value()) << "located in " << *got;
    else
      ASSERT_EQ(got, std::optional<std::int32_t>(brute));
    if (!ts.empty()) {
      const auto hint = std::uniform_int_distribution<std::int32_t>(
          0, static_cast<std::int32_t>(ts.size()) - 1)(rng);
      ASSERT_EQ(t.locate(p, hint), got);
    }
    const bool in_dom = dom.lo.x <= p.x && p.x <= dom.hi.x && dom.lo.y <= p.y && p.y <= dom.hi.y;
    const bool strictly_in_dom =
        dom.lo.x < p.x && p.x < dom.hi.x && dom.lo.y < p.y && p.y < dom.hi.y;
    int inside_obstacle = 0, touching_obstacle = 0;
    for (const Polygon& poly : obs) {
      const int w = where(scaled(p, 1), poly, 1);
      inside_obstacle += w == 1;
      touching_obstacle += w == 0;
    }
    if (!in_dom || inside_obstacle > 0) {
      ASSERT_FALSE(got.has_value());
    }
    if (strictly_in_dom && inside_obstacle == 0 && touching_obstacle == 0) {
      ASSERT_TRUE(got.has_value());
    }
  }
}

FreeSpaceTriangulation run(const Box& dom, const std::vector<Polygon>& obs) {
  return triangulate_free_space(dom, obs);
}

// For a free region that is a polygon with h holes and n vertices, all on its boundary:
// triangles = n + 2h - 2 (Euler). Independent of the triangulation.
std::size_t euler_triangles(std::size_t n, std::size_t h) { return n + 2 * h - 2; }

// ---- hand-made cases ---------------------------------------------------------------------------

TEST(Triangulation, EmptyDomain) {
  std::mt19937_64 rng(1);
  const Box dom{{0, 0}, {10, 6}};
  const auto t = run(dom, {});
  verify(dom, {}, t, rng);
  EXPECT_EQ(t.triangles().size(), 2u);
  EXPECT_TRUE(t.locate({0, 0}).has_value());
  EXPECT_TRUE(t.locate({10, 6}).has_value());
  EXPECT_FALSE(t.locate({11, 6}).has_value());
  EXPECT_FALSE(t.locate({-1, 0}).has_value());
}

TEST(Triangulation, DefaultAndMovedFrom) {
  FreeSpaceTriangulation a;
  EXPECT_TRUE(a.ok());
  EXPECT_TRUE(a.triangles().empty());
  EXPECT_FALSE(a.locate({0, 0}).has_value());
  EXPECT_TRUE(a.check().empty());
  FreeSpaceTriangulation b = run({{0, 0}, {4, 4}}, {});
  FreeSpaceTriangulation c = std::move(b);
  EXPECT_EQ(c.triangles().size(), 2u);
  EXPECT_TRUE(c.locate({1, 1}).has_value());
}

//   +-----------+
//   |   +---+   |     one square in the middle: 8 vertices, 1 hole -> 8 triangles
//   |   |###|   |
//   |   +---+   |
//   +-----------+
TEST(Triangulation, OneSquare) {
  std::mt19937_64 rng(2);
  const Box dom{{0, 0}, {12, 12}};
  const std::vector<Polygon> obs = {rect(4, 4, 8, 8)};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {200, true});
  EXPECT_EQ(t.triangles().size(), euler_triangles(8, 1));
  EXPECT_FALSE(t.locate({6, 6}).has_value());  // interior of the obstacle
  ASSERT_TRUE(t.locate({4, 6}).has_value());   // on its boundary: a free triangle
  EXPECT_TRUE(t.locate({4, 4}).has_value());
  int obstacle_edges = 0;
  for (const auto& tr : t.triangles())
    for (int k = 0; k < 3; ++k) obstacle_edges += tr.constraint[k] == 0;
  EXPECT_EQ(obstacle_edges, 4);
}

//   +-------------------+
//   | +---------------+ |
//   | |###############| |   obstacle 0: a frame (outer ring + hole)
//   | |##+---------+##| |   obstacle 1: a square inside the hole
//   | |##|  +---+  |##| |
//   | |##|  |###|  |##| |
//   | |##|  +---+  |##| |
//   | |##+---------+##| |
//   | +---------------+ |
//   +-------------------+
TEST(Triangulation, HoleContainingObstacle) {
  std::mt19937_64 rng(3);
  const Box dom{{0, 0}, {20, 20}};
  Polygon frame = rect(2, 2, 18, 18);
  frame.holes.push_back(cw_rect(5, 5, 15, 15));
  const std::vector<Polygon> obs = {frame, rect(8, 8, 12, 12)};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {300, true});
  // Two free regions: the ring between domain and frame (8 vertices, 1 hole -> 8), and the
  // hole minus the square (8 vertices, 1 hole -> 8).
  EXPECT_EQ(t.triangles().size(), 16u);
  EXPECT_FALSE(t.locate({3, 10}).has_value());
  EXPECT_TRUE(t.locate({6, 10}).has_value());
  EXPECT_FALSE(t.locate({10, 10}).has_value());
}

//   +=====+-----+=====+
//   |#####|     |#####|   obstacles along the domain boundary, one filling a corner, one
//   |#####|     +=====+   spanning a whole side; edges shared with the boundary
//   +-----+           |
//   +=================+
TEST(Triangulation, ObstaclesAlongDomainBoundary) {
  std::mt19937_64 rng(4);
  const Box dom{{0, 0}, {30, 20}};
  const std::vector<Polygon> obs = {rect(0, 12, 10, 20), rect(20, 15, 30, 20), rect(0, 0, 30, 4),
                                    {{{12, 20}, {14, 17}, {16, 20}}, {}}};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {400, true});
  EXPECT_FALSE(t.locate({0, 0}).has_value());   // corner covered by an obstacle
  EXPECT_FALSE(t.locate({15, 0}).has_value());  // domain boundary covered by an obstacle
  EXPECT_FALSE(t.locate({5, 20}).has_value());
  EXPECT_TRUE(t.locate({15, 4}).has_value());   // obstacle boundary facing free space
  EXPECT_TRUE(t.locate({12, 20}).has_value());  // triangle touching the top side
  EXPECT_FALSE(t.locate({14, 19}).has_value());
  EXPECT_TRUE(t.locate({17, 20}).has_value());
}

// The whole domain is one obstacle: no free triangle at all.
TEST(Triangulation, ObstacleFillsDomain) {
  std::mt19937_64 rng(5);
  const Box dom{{-5, -5}, {5, 5}};
  const std::vector<Polygon> obs = {rect(-5, -5, 5, 5)};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {100, true});
  EXPECT_TRUE(t.triangles().empty());
  EXPECT_FALSE(t.locate({-5, -5}).has_value());
}

//   +-------------+
//   |      +--+   |   one ring pinched at (4,4): two lobes touching at a vertex;
//   |      |##|   |   a second obstacle with a triangular hole touching its outer corner
//   |   +--+--+   |
//   |   |##|      |
//   |   +--+      |
//   +-------------+
TEST(Triangulation, PinchedRings) {
  std::mt19937_64 rng(6);
  const Box dom{{0, 0}, {20, 12}};
  Polygon eight{{{2, 2}, {4, 2}, {4, 4}, {6, 4}, {6, 6}, {4, 6}, {4, 4}, {2, 4}}, {}};
  Polygon with_hole = rect(10, 2, 16, 8);
  with_hole.holes.push_back({{10, 2}, {11, 5}, {13, 3}});  // CW, touches the corner (10,2)
  Polygon at_boundary{{{17, 0}, {18, 2}, {19, 0}, {20, 3}, {18, 4}}, {}};  // a W on the boundary
  const std::vector<Polygon> obs = {eight, with_hole, at_boundary};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {400, true});
  EXPECT_TRUE(t.locate({4, 4}).has_value());  // the pinch vertex borders free space
  EXPECT_FALSE(t.locate({3, 3}).has_value());
  EXPECT_FALSE(t.locate({5, 5}).has_value());
  EXPECT_TRUE(t.locate({11, 4}).has_value());  // inside the hole
  EXPECT_TRUE(t.locate({10, 2}).has_value());
}

// A union that pinches twice on the same ring, and a ring that touches the domain boundary
// at single vertices only.
TEST(Triangulation, DoublePinchAndBoundaryTouch) {
  std::mt19937_64 rng(7);
  const Box dom{{0, 0}, {16, 16}};
  // Three squares in a diagonal chain as one ring, touching at (4,4) and (8,8).
  Polygon chain{{{0, 0}, {4, 0}, {4, 4}, {8, 4}, {8, 8}, {12, 8}, {12, 12}, {8, 12}, {8, 8},
                 {4, 8}, {4, 4}, {0, 4}},
                {}};
  Polygon diamond{{{14, 0}, {16, 2}, {14, 4}, {12, 2}}, {}};  // touches bottom at one vertex
  const std::vector<Polygon> obs = {chain, diamond};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {400, true});
  EXPECT_TRUE(t.locate({8, 8}).has_value());
  EXPECT_TRUE(t.locate({14, 0}).has_value());
  EXPECT_TRUE(t.locate({16, 2}).has_value());
  EXPECT_FALSE(t.locate({0, 0}).has_value());
}

// Beyond the contract but tolerated: obstacles touching at a point (a triangle's apex on the
// middle of a rectangle's edge, two rectangles sharing a corner).
//            +---+
//            |###|      +------+
//       +----X---+      |######|
//       |####|          +--X---+   X: the touching points
//       +----+            /##\     (triangle)
//                        +----+
TEST(Triangulation, TouchingAtPointsTolerated) {
  std::mt19937_64 rng(10);
  const Box dom{{0, 0}, {30, 20}};
  const std::vector<Polygon> obs = {rect(2, 10, 6, 14), rect(6, 14, 9, 18), rect(14, 10, 22, 14),
                                    {{{15, 4}, {21, 4}, {18, 10}}, {}}};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {400, true});
  EXPECT_TRUE(t.locate({6, 14}).has_value());
  EXPECT_TRUE(t.locate({18, 10}).has_value());
}

// Many vertices on one horizontal line (y = 5), with obstacles above and below it, and on the
// domain's bottom side (y = 0).
TEST(Triangulation, ManyVerticesOnOneLine) {
  std::mt19937_64 rng(8);
  const Box dom{{0, 0}, {200, 10}};
  std::vector<Polygon> obs;
  for (Coord x = 1; x + 3 < 200; x += 8) {
    obs.push_back(rect(x, 5, x + 2, 7));                     // bottoms on y = 5
    obs.push_back({{{x + 4, 3}, {x + 6, 3}, {x + 5, 5}}, {}});  // apex on y = 5
    obs.push_back(rect(x, 0, x + 1, 2));                     // on the domain's bottom
  }
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {1000, true});
}

// Coordinates at the limits of the range.
TEST(Triangulation, ExtremeCoordinates) {
  std::mt19937_64 rng(9);
  const Coord m = kMaxCoord;
  const Box dom{{-m, -m}, {m, m}};
  const std::vector<Polygon> obs = {rect(-m, -m, -m + 1, m), rect(-3, -m, 5, 7),
                                    {{{m - 2, m - 1}, {m, m - 1}, {m, m}}, {}},
                                    {{{0, m}, {1, m - 1}, {2, m}}, {}}};
  const auto t = run(dom, obs);
  verify(dom, obs, t, rng, {500, true});
}

// ---- errors ------------------------------------------------------------------------------------

std::string first_code(const FreeSpaceTriangulation& t) {
  EXPECT_FALSE(t.ok());
  EXPECT_TRUE(t.triangles().empty());
  EXPECT_FALSE(t.locate({1, 1}).has_value());
  return t.diagnostics().empty() ? "" : t.diagnostics()[0].code;
}

TEST(TriangulationErrors, Domain) {
  EXPECT_EQ(first_code(run({{0, 0}, {0, 5}}, {})), "GEOM-0040");
  EXPECT_EQ(first_code(run({{0, 5}, {5, 0}}, {})), "GEOM-0040");
  EXPECT_EQ(first_code(run({{0, 0}, {kMaxCoord + 1, 5}}, {})), "GEOM-0040");
  EXPECT_EQ(first_code(run({{0, 0}, {10, 10}}, {rect(0, 0, kMaxCoord + 1, 5)})), "GEOM-0040");
}

TEST(TriangulationErrors, Rings) {
  const Box dom{{0, 0}, {10, 10}};
  EXPECT_EQ(first_code(run(dom, {Polygon{{{1, 1}, {2, 2}}, {}}})), "GEOM-0041");
  EXPECT_EQ(first_code(run(dom, {Polygon{cw_rect(1, 1, 3, 3), {}}})), "GEOM-0041");
  Polygon ccw_hole = rect(1, 1, 8, 8);
  ccw_hole.holes.push_back(rect(2, 2, 3, 3).outer);
  EXPECT_EQ(first_code(run(dom, {ccw_hole})), "GEOM-0041");
  EXPECT_EQ(first_code(run(dom, {Polygon{{{1, 1}, {2, 2}, {3, 3}}, {}}})), "GEOM-0041");
  EXPECT_EQ(first_code(run(dom, {rect(5, 5, 11, 6)})), "GEOM-0042");
  EXPECT_EQ(first_code(run(dom, {rect(-1, 5, 2, 6)})), "GEOM-0042");
}

TEST(TriangulationErrors, Contradictions) {
  const Box dom{{0, 0}, {20, 20}};
  // A plus sign: edges cross.
  EXPECT_EQ(first_code(run(dom, {rect(2, 8, 18, 12), rect(8, 2, 12, 18)})), "GEOM-0043");
  // Overlapping squares whose crossings are at integer points still create vertices.
  EXPECT_EQ(first_code(run(dom, {rect(2, 2, 10, 10), rect(6, 6, 14, 14)})), "GEOM-0043");
  // Nested without a hole.
  EXPECT_EQ(first_code(run(dom, {rect(2, 2, 18, 18), rect(6, 6, 10, 10)})), "GEOM-0044");
  EXPECT_EQ(first_code(run(dom, {rect(6, 6, 10, 10), rect(2, 2, 18, 18)})), "GEOM-0044");
  // Two squares sharing an edge.
  EXPECT_EQ(first_code(run(dom, {rect(2, 2, 6, 6), rect(6, 2, 10, 6)})), "GEOM-0044");
  // Identical squares.
  EXPECT_EQ(first_code(run(dom, {rect(2, 2, 6, 6), rect(2, 2, 6, 6)})), "GEOM-0044");
  // A zero-width spike sticking out of a square.
  EXPECT_EQ(first_code(run(dom, {Polygon{{{2, 2}, {6, 2}, {6, 6}, {2, 6}, {2, 4}, {1, 4}, {2, 4}},
                                         {}}})),
            "GEOM-0044");
  // A hole overlapping its outer ring along an edge.
  Polygon bad = rect(2, 2, 10, 10);
  bad.holes.push_back(cw_rect(2, 4, 6, 8));
  EXPECT_EQ(first_code(run(dom, {bad})), "GEOM-0044");
  // A hole outside its outer ring.
  Polygon outside = rect(2, 2, 6, 6);
  outside.holes.push_back(cw_rect(10, 10, 12, 12));
  EXPECT_EQ(first_code(run(dom, {outside})), "GEOM-0044");
  // A hole inside another hole.
  Polygon nested = rect(2, 2, 10, 10);
  nested.holes = {cw_rect(3, 3, 9, 9), cw_rect(5, 5, 7, 7)};
  EXPECT_EQ(first_code(run(dom, {nested})), "GEOM-0044");
  // The same hole twice: every face is labelled consistently, only the area gives it away.
  Polygon twice = rect(2, 2, 10, 10);
  twice.holes = {cw_rect(4, 4, 6, 6), cw_rect(4, 4, 6, 6)};
  EXPECT_EQ(first_code(run(dom, {twice})), "GEOM-0045");
}

// ---- random layouts ----------------------------------------------------------------------------

// Fewer instances in Debug (sanitizers) so the file stays well under a minute there.
#ifdef NDEBUG
constexpr int kGridInstances = 3000, kRectangleInstances = 400;
#else
constexpr int kGridInstances = 1000, kRectangleInstances = 150;
#endif

// Cells of a coarse grid each hold at most one obstacle inside [x0, x0+S-1] x [y0, y0+S-1], so
// obstacles in different cells are disjoint; the outermost cells reach the domain boundary.
constexpr Coord kCell = 8;

Coord pick_coord(std::mt19937_64& rng, Coord lo, Coord hi) {  // biased to the extremes
  const int r = std::uniform_int_distribution<int>(0, 5)(rng);
  if (r == 0) return lo;
  if (r == 1) return hi;
  return std::uniform_int_distribution<Coord>(lo, hi)(rng);
}

bool convex_hull(std::vector<Point> pts, Ring& out) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return false;
  std::vector<Point> h(2 * pts.size());
  std::size_t k = 0;
  auto cross = [](Point o, Point a, Point b) {
    return orient128(scaled(o, 1), scaled(a, 1), scaled(b, 1));
  };
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i - 1]) <= 0) --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  if (h.size() < 3) return false;
  out = h;
  return true;
}

// A star-shaped polygon around the cell centre c: points sorted by angle, each angular gap
// below pi (so c is strictly inside and the ring is simple).
bool star(std::mt19937_64& rng, Point c, Coord x0, Coord y0, Ring& out) {
  std::vector<Point> pts;
  const int n = std::uniform_int_distribution<int>(3, 9)(rng);
  for (int i = 0; i < n; ++i) {
    const Point p{std::uniform_int_distribution<Coord>(x0, x0 + kCell - 1)(rng),
                  std::uniform_int_distribution<Coord>(y0, y0 + kCell - 1)(rng)};
    if (p != c) pts.push_back(p);
  }
  auto half = [&](Point p) { return (p.y < c.y || (p.y == c.y && p.x < c.x)) ? 1 : 0; };
  auto cr = [&](Point a, Point b) { return orient128(scaled(c, 1), scaled(a, 1), scaled(b, 1)); };
  std::sort(pts.begin(), pts.end(), [&](Point a, Point b) {
    if (half(a) != half(b)) return half(a) < half(b);
    return cr(a, b) > 0;
  });
  std::vector<Point> uniq;  // one point per direction
  for (Point p : pts)
    if (uniq.empty() || half(uniq.back()) != half(p) || cr(uniq.back(), p) != 0) uniq.push_back(p);
  if (uniq.size() >= 2 && half(uniq.front()) == half(uniq.back()) && cr(uniq.back(), uniq.front()) == 0)
    uniq.pop_back();
  if (uniq.size() < 3) return false;
  for (std::size_t i = 0; i < uniq.size(); ++i)
    if (cr(uniq[i], uniq[(i + 1) % uniq.size()]) <= 0) return false;
  out = uniq;
  return true;
}

void random_layout(std::mt19937_64& rng, int grid, Box& dom, std::vector<Polygon>& obs) {
  obs.clear();
  const Coord size = grid * kCell;
  dom = {{0, 0}, {size - 1, size - 1}};
  for (int cx = 0; cx < grid; ++cx) {
    for (int cy = 0; cy < grid; ++cy) {
      const Coord x0 = cx * kCell, y0 = cy * kCell, x1 = x0 + kCell - 1, y1 = y0 + kCell - 1;
      const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
      if (kind <= 1) continue;
      if (kind <= 3) {  // rectangle
        Coord a = pick_coord(rng, x0, x1), b = pick_coord(rng, x0, x1);
        Coord c = pick_coord(rng, y0, y1), d = pick_coord(rng, y0, y1);
        if (a == b || c == d) continue;
        obs.push_back(rect(std::min(a, b), std::min(c, d), std::max(a, b), std::max(c, d)));
      } else if (kind == 4) {  // frame with a hole, maybe a square inside the hole
        const Coord w = std::uniform_int_distribution<Coord>(3, kCell - 1)(rng);
        const Coord ox = pick_coord(rng, x0, x1 - w), oy = pick_coord(rng, y0, y1 - w);
        Polygon f = rect(ox, oy, ox + w, oy + w);
        f.holes.push_back(cw_rect(ox + 1, oy + 1, ox + w - 1, oy + w - 1));
        obs.push_back(f);
        if (w >= 5 && rng() % 2) obs.push_back(rect(ox + 2, oy + 2, ox + w - 2, oy + w - 2));
      } else if (kind == 5) {  // figure eight: two lobes pinched at one vertex
        const Coord xm = std::uniform_int_distribution<Coord>(x0 + 1, x1 - 1)(rng);
        const Coord ym = std::uniform_int_distribution<Coord>(y0 + 1, y1 - 1)(rng);
        const Coord xa = pick_coord(rng, x0, xm - 1), xb = pick_coord(rng, xm + 1, x1);
        const Coord ya = pick_coord(rng, y0, ym - 1), yb = pick_coord(rng, ym + 1, y1);
        if (rng() % 2)
          obs.push_back({{{xa, ya}, {xm, ya}, {xm, ym}, {xb, ym}, {xb, yb}, {xm, yb}, {xm, ym}, {xa, ym}},
                         {}});
        else  // the other diagonal
          obs.push_back({{{xm, ya}, {xb, ya}, {xb, ym}, {xm, ym}, {xm, yb}, {xa, yb}, {xa, ym}, {xm, ym}},
                         {}});
      } else if (kind == 6) {  // square with a triangular hole pinched at a corner
        const Coord ox = pick_coord(rng, x0, x1 - 4), oy = pick_coord(rng, y0, y1 - 4);
        const Coord w = std::uniform_int_distribution<Coord>(4, std::min(x1 - ox, y1 - oy))(rng);
        Polygon p = rect(ox, oy, ox + w, oy + w);
        p.holes.push_back({{ox, oy}, {ox + 1, oy + w - 1}, {ox + w - 1, oy + 1}});
        obs.push_back(p);
      } else if (kind == 7) {  // convex polygon
        std::vector<Point> pts;
        const int n = std::uniform_int_distribution<int>(3, 10)(rng);
        for (int i = 0; i < n; ++i) pts.push_back({pick_coord(rng, x0, x1), pick_coord(rng, y0, y1)});
        Ring r;
        if (convex_hull(pts, r)) obs.push_back({r, {}});
      } else {  // star-shaped polygon
        Ring r;
        if (star(rng, {x0 + kCell / 2, y0 + kCell / 2}, x0, y0, r)) obs.push_back({r, {}});
      }
    }
  }
}

// An affine map that keeps every incidence: scale by f, shift by (dx, dy).
void transform(Box& dom, std::vector<Polygon>& obs, Coord f, Coord dx, Coord dy) {
  auto m = [&](Point& p) { p = {p.x * f + dx, p.y * f + dy}; };
  m(dom.lo);
  m(dom.hi);
  for (Polygon& p : obs) {
    for (Point& q : p.outer) m(q);
    for (Ring& h : p.holes)
      for (Point& q : h) m(q);
  }
}

TEST(TriangulationRandom, GridLayouts) {
  constexpr std::uint64_t kBaseSeed = 20240601;
  int instances = 0;
  std::size_t triangles = 0;
  for (int i = 0; i < kGridInstances; ++i) {
    const std::uint64_t seed = kBaseSeed + i;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    Box dom;
    std::vector<Polygon> obs;
    random_layout(rng, std::uniform_int_distribution<int>(1, 5)(rng), dom, obs);
    switch (i % 4) {  // shift/scale to negative and extreme coordinates
      case 1: transform(dom, obs, 1, -20, -7); break;
      case 2: transform(dom, obs, 1 << 20, -(1 << 29), 12345); break;
      case 3: transform(dom, obs, 3, -kMaxCoord, kMaxCoord - 3 * dom.hi.y); break;
      default: break;
    }
    const auto t = run(dom, obs);
    verify(dom, obs, t, rng);
    if (HasFatalFailure()) return;
    ++instances;
    triangles += t.triangles().size();
  }
  std::cout << instances << " instances, " << triangles << " free triangles\n";
}

// Disjoint rectangles only, on a finer grid (more vertices per instance, shared x and y).
TEST(TriangulationRandom, DisjointRectangles) {
  constexpr std::uint64_t kBaseSeed = 777000;
  for (int i = 0; i < kRectangleInstances; ++i) {
    const std::uint64_t seed = kBaseSeed + i;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const int grid = std::uniform_int_distribution<int>(2, 12)(rng);
    const Box dom{{0, 0}, {grid * 4 - 1, grid * 4 - 1}};
    std::vector<Polygon> obs;
    for (int cx = 0; cx < grid; ++cx)
      for (int cy = 0; cy < grid; ++cy) {
        if (rng() % 3 == 0) continue;
        const Coord a = pick_coord(rng, cx * 4, cx * 4 + 3), b = pick_coord(rng, cx * 4, cx * 4 + 3);
        const Coord c = pick_coord(rng, cy * 4, cy * 4 + 3), d = pick_coord(rng, cy * 4, cy * 4 + 3);
        if (a != b && c != d)
          obs.push_back(rect(std::min(a, b), std::min(c, d), std::max(a, b), std::max(c, d)));
      }
    const auto t = run(dom, obs);
    verify(dom, obs, t, rng, {60, grid <= 8});
    if (HasFatalFailure()) return;
  }
}

// ---- scale ---------------------------------------------------------------------------------------

// n obstacle vertices as n/4 disjoint random rectangles, one per cell of a square grid.
void rectangles(std::size_t n, std::uint64_t seed, Box& dom, std::vector<Polygon>& obs) {
  std::mt19937_64 rng(seed);
  const std::size_t count = n / 4;
  const Coord grid = static_cast<Coord>(std::ceil(std::sqrt(static_cast<double>(count))));
  constexpr Coord kS = 64;
  dom = {{0, 0}, {grid * kS, grid * kS}};
  obs.clear();
  for (Coord cx = 0; cx < grid && obs.size() < count; ++cx)
    for (Coord cy = 0; cy < grid && obs.size() < count; ++cy) {
      std::uniform_int_distribution<Coord> u(1, kS - 2);
      Coord a = u(rng), b = u(rng), c = u(rng), d = u(rng);
      if (a == b) ++b;
      if (c == d) ++d;
      obs.push_back(rect(cx * kS + std::min(a, b), cy * kS + std::min(c, d), cx * kS + std::max(a, b),
                         cy * kS + std::max(c, d)));
    }
}

TEST(TriangulationScale, TenThousandVertices) {
  Box dom;
  std::vector<Polygon> obs;
  rectangles(10000, 99, dom, obs);
  const auto t = run(dom, obs);
  ASSERT_TRUE(t.ok());
  const auto problems = t.check();
  ASSERT_TRUE(problems.empty()) << problems[0];
  // One free region with every rectangle as a hole: Euler gives the exact count.
  EXPECT_EQ(t.triangles().size(), euler_triangles(4 + 4 * obs.size(), obs.size()));
}

// Timing, run by hand in a Release build: --gtest_also_run_disabled_tests.
TEST(TriangulationScale, DISABLED_Timing) {
  for (std::size_t n : {std::size_t{10000}, std::size_t{100000}, std::size_t{1000000}}) {
    Box dom;
    std::vector<Polygon> obs;
    rectangles(n, 7, dom, obs);
    const auto t0 = std::chrono::steady_clock::now();
    const auto t = run(dom, obs);
    const auto t1 = std::chrono::steady_clock::now();
    ASSERT_TRUE(t.ok());
    const auto problems = t.check();
    const auto t2 = std::chrono::steady_clock::now();
    ASSERT_TRUE(problems.empty()) << problems[0];
    std::mt19937_64 rng(1);
    std::uniform_int_distribution<Coord> ux(dom.lo.x, dom.hi.x);
    constexpr int kQueries = 100000;
    int found = 0;
    for (int q = 0; q < kQueries; ++q) found += t.locate({ux(rng), ux(rng)}).has_value();
    const auto t3 = std::chrono::steady_clock::now();
    std::optional<std::int32_t> hint;
    for (int q = 0; q < kQueries; ++q) {  // a random walk of nearby queries
      const Coord x = static_cast<Coord>(dom.hi.x / 2 + q % 200), y = static_cast<Coord>(dom.hi.y / 2 + q / 200 % 200);
      auto r = hint ? t.locate({x, y}, *hint) : t.locate({x, y});
      if (r) hint = r;
    }
    const auto t4 = std::chrono::steady_clock::now();
    auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    std::cout << n << " obstacle vertices: triangulate " << ms(t0, t1) << " ms, check "
              << ms(t1, t2) << " ms, " << t.triangles().size() << " free triangles; " << kQueries
              << " random locates " << ms(t2, t3) << " ms (" << found << " free), " << kQueries
              << " hinted locates " << ms(t3, t4) << " ms\n";
  }
}

}  // namespace triangulation_test
}  // namespace taut::geom
