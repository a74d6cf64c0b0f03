// normalize_polygon(): canonical form; io/movingai: the .map reader and its diagnostics.
#include "geom/normalize.h"

#include <gtest/gtest.h>

#include "support/run.h"
#include "support/sanitized.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "geom/predicates.h"
#include "io/movingai.h"

namespace normalize_test {

using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Ring;

TEST(NormalizePolygon, HandWritten) {
  //  (0,4) +-----+ (4,4)     written clockwise, with a repeat and two collinear vertices
  //        |     |
  //  (0,0) +--+--+ (4,0)
  Polygon p{{{4, 4}, {4, 0}, {2, 0}, {2, 0}, {0, 0}, {0, 2}, {0, 4}}, {}};
  const Polygon n = taut::geom::normalize_polygon(p);
  EXPECT_EQ(n.outer, (Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  // A hole written counter-clockwise becomes clockwise, starting at its smallest vertex.
  Polygon h{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{3, 3}, {6, 3}, {6, 6}, {3, 6}}, {{7, 7}, {8, 7}, {8, 8}}}};
  const Polygon nh = taut::geom::normalize_polygon(h);
  EXPECT_EQ(nh.holes[0], (Ring{{3, 3}, {3, 6}, {6, 6}, {6, 3}}));
  EXPECT_EQ(nh.holes[1], (Ring{{7, 7}, {8, 8}, {8, 7}}));
}

// Rotating, reversing, repeating vertices and adding collinear points never changes the
// canonical form; the form starts at the minimum, is counter-clockwise, has no straight vertex.
TEST(NormalizePolygon, RandomEquivalentWritings) {
  const unsigned base = 20240601;
  for (unsigned it = 0; it < 400; ++it) {
    const unsigned seed = base + it;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    // Star polygon around (0,0) with even coordinates (so midpoints are integer).
    const int k = 3 + static_cast<int>(rng() % 10);
    std::vector<double> ang;
    for (int i = 0; i < k; ++i) ang.push_back(std::uniform_real_distribution<double>(0, 6.283)(rng));
    std::sort(ang.begin(), ang.end());
    Ring r;
    for (double a : ang) {
      const double rad = 20 + static_cast<int>(rng() % 200);
      const Point p{2 * static_cast<int>(std::lround(rad * std::cos(a))), 2 * static_cast<int>(std::lround(rad * std::sin(a)))};
      if (r.empty() || r.back() != p) r.push_back(p);
    }
    if (r.size() < 3 || taut::geom::twice_area(r) <= 0) continue;
    const Polygon ref = taut::geom::normalize_polygon({r, {}});
    ASSERT_GE(ref.outer.size(), 3u);
    EXPECT_EQ(ref.outer.front(), *std::min_element(ref.outer.begin(), ref.outer.end()));
    EXPECT_GT(taut::geom::twice_area(ref.outer), 0);
    EXPECT_EQ(taut::geom::twice_area(ref.outer), taut::geom::twice_area(r));
    for (std::size_t i = 0; i < ref.outer.size(); ++i) {
      const std::size_t n = ref.outer.size();
      EXPECT_NE(taut::geom::orient(ref.outer[(i + n - 1) % n], ref.outer[i], ref.outer[(i + 1) % n]), 0);
    }
    Ring w;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point a = r[i], b = r[(i + 1) % r.size()];
      w.push_back(a);
      if (rng() % 2) w.push_back(a);
      if (rng() % 2) w.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
    }
    std::rotate(w.begin(), w.begin() + static_cast<long>(rng() % w.size()), w.end());
    if (rng() % 2) std::reverse(w.begin(), w.end());
    EXPECT_EQ(taut::geom::normalize_polygon({w, {}}), ref);
  }
}

TEST(MovingAi, ParsesRunsAndBoundary) {
  // Row 0 is the top: cells (c, r) -> [c*s, (c+1)*s] x [(H-1-r)*s, (H-r)*s].
  const std::string text = "type octile\nheight 2\nwidth 4\nmap\n@@.T\r\n.G@S\n";
  const auto r = taut::io::parse_movingai_map(text, "t.map", 10);
  ASSERT_TRUE(r.layout) << (r.diagnostics.empty() ? "" : taut::format(r.diagnostics[0]));
  const auto& L = *r.layout;
  ASSERT_TRUE(L.boundary);
  EXPECT_EQ(L.boundary->box, (taut::geom::Box{{0, 0}, {40, 20}}));
  ASSERT_EQ(L.blockages.size(), 3u);
  EXPECT_EQ(L.blockages[0].id, "r0c0");
  EXPECT_EQ(L.blockages[0].shapes[0].rect, (taut::geom::Box{{0, 10}, {20, 20}}));
  EXPECT_EQ(L.blockages[1].id, "r0c3");
  EXPECT_EQ(L.blockages[1].shapes[0].rect, (taut::geom::Box{{30, 10}, {40, 20}}));
  EXPECT_EQ(L.blockages[2].id, "r1c2");
  EXPECT_EQ(L.blockages[2].shapes[0].rect, (taut::geom::Box{{20, 0}, {30, 10}}));
  EXPECT_EQ(L.blockages[2].line, 6);
}

TEST(MovingAi, MalformedFilesGiveDiagnostics) {
  struct Case {
    std::string text, code;
    int line;
  };
  const std::vector<Case> cases = {
      {"", "IO-0091", 0},
      {"type octile\nheight 2\nwidth x\nmap\n..\n..\n", "IO-0091", 3},
      {"type octile\nheight 2\nmap\n..\n..\n", "IO-0091", 3},
      {"type octile\nheight 2\nwidth 2\nfoo\nmap\n", "IO-0091", 4},
      {"height 2\nwidth 2\nmap\n..\n..\n", "IO-0091", 3},
      {"type octile\nheight 3\nwidth 2\nmap\n..\n..\n", "IO-0092", 6},
      {"type octile\nheight 2\nwidth 2\nmap\n..\n...\n", "IO-0092", 6},
      {"type octile\nheight 2\nwidth 2\nmap\n..\n..\nxx\n", "IO-0094", 7},
      {"type octile\nheight 2\nwidth 200000000\nmap\n", "IO-0093", 4},
      {"type octile\nheight -1\nwidth 2\nmap\n", "IO-0091", 2},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const auto r = taut::io::parse_movingai_map(c.text, "bad.map", 10);
    EXPECT_FALSE(r.layout);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].code, c.code);
    EXPECT_EQ(r.diagnostics[0].line, c.line);
    EXPECT_EQ(r.diagnostics[0].file, "bad.map");
  }
  const auto missing = taut::io::load_movingai_map("/nonexistent/x.map");
  ASSERT_EQ(missing.diagnostics.size(), 1u);
  EXPECT_EQ(missing.diagnostics[0].code, "IO-0090");
}

TEST(MovingAi, LoadsSharedArena) {
  TAUT_REQUIRE_SHARED_DATA();
  const auto r = taut::io::load_movingai_map(std::string(TAUT_SHARED_DATA) + "/movingai/arena.map", 10);
  ASSERT_TRUE(r.layout);
  EXPECT_EQ(r.layout->boundary->box, (taut::geom::Box{{0, 0}, {490, 490}}));
  EXPECT_FALSE(r.layout->blockages.empty());
}

// square_grown + normalize_obstacles against the definition of the Minkowski sum with the
// square [-r, r]^2: a lattice point whose square (closed) meets some input polygon (the point
// itself inside, a polygon vertex inside the square, or a square side crossing a polygon edge)
// must be covered, never missed; a covered point outside the sum may only come from the union's
// outward rounding of sloped crossings (normalize.h: within 2 DBU), so its square grown by 2
// must meet a polygon. Checked with geom's locate() and intersect() on random polygons
// (rectangles, triangles, a ring with a hole) and r in 0..4.
TEST(SquareGrown, CoversTheMinkowskiSum) {
  using taut::geom::Point;
  using taut::geom::Polygon;
  long long points = 0, covered = 0, rounded = 0;
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    std::mt19937_64 rng(seed);
    auto r_ = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
    std::vector<Polygon> polys;
    for (int k = r_(1, 3); k-- > 0;) {
      const int x = r_(5, 25), y = r_(5, 25);
      switch (r_(0, 2)) {
        case 0: polys.push_back(Polygon{{{x, y}, {x + r_(1, 6), y}, {x + r_(1, 6), y + r_(1, 6)}, {x, y + r_(1, 6)}}, {}}); break;
        case 1: polys.push_back(Polygon{{{x, y}, {x + r_(2, 7), y + r_(-3, 3)}, {x + r_(-2, 3), y + r_(2, 7)}}, {}}); break;
        default: polys.push_back(Polygon{{{x, y}, {x + 8, y}, {x + 8, y + 8}, {x, y + 8}}, {{{x + 2, y + 2}, {x + 2, y + 6}, {x + 6, y + 6}, {x + 6, y + 2}}}});
      }
    }
    for (Polygon& p : polys) p = taut::geom::normalize_polygon(p);  // counter-clockwise outer rings
    bool valid = true;
    for (const Polygon& p : polys) valid = valid && taut::geom::twice_area(p.outer) > 0;
    if (!valid) continue;
    const int r = r_(0, 4);
    const taut::geom::Box dom{{-10, -10}, {50, 50}};
    const auto grown = taut::geom::normalize_obstacles(taut::geom::square_grown(polys, r), dom);
    for (int x = -5; x <= 45; ++x)
      for (int y = -5; y <= 45; ++y) {
        const Point q{x, y};
        auto meets = [&](int rr) {  // the square of half-side rr around q meets a polygon
          const std::vector<Point> sq{{x - rr, y - rr}, {x + rr, y - rr}, {x + rr, y + rr}, {x - rr, y + rr}};
          for (const Polygon& p : polys) {
            if (taut::geom::locate(q, p) != taut::geom::Location::Outside) return true;
            std::vector<const taut::geom::Ring*> rings{&p.outer};
            for (const auto& h : p.holes) rings.push_back(&h);
            for (const auto* ring : rings)
              for (std::size_t i = 0; i < ring->size(); ++i) {
                const Point a = (*ring)[i], b = (*ring)[(i + 1) % ring->size()];
                if (std::abs(a.x - x) <= rr && std::abs(a.y - y) <= rr) return true;
                for (int s = 0; s < 4; ++s)
                  if (taut::geom::intersect({sq[static_cast<std::size_t>(s)], sq[static_cast<std::size_t>((s + 1) % 4)]},
                                            {a, b}) != taut::geom::SegmentIntersection::None)
                    return true;
              }
          }
          return false;
        };
        const bool want = meets(r);
        bool got = false;
        for (const Polygon& o : grown.obstacles) got = got || taut::geom::locate(q, o) != taut::geom::Location::Outside;
        if (want) {
          ASSERT_TRUE(got) << "seed " << seed << " r " << r << " point " << x << "," << y << " not covered";
        }
        if (got && !want) {
          ASSERT_TRUE(meets(r + 2)) << "seed " << seed << " r " << r << " point " << x << "," << y << " covered too far out";
          ++rounded;
        }
        ++points;
        covered += got;
      }
  }
  std::printf("%lld lattice points, %lld covered (%lld by the union's outward rounding)\n", points, covered, rounded);
  EXPECT_LT(rounded * 100, covered);
}

// Winding number of ring r around q, all coordinates times 4 (q off the ring): Sunday's rule.
int winding4(const Ring& r, Point q4) {
  int w = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a{r[i].x * 4, r[i].y * 4}, b{r[(i + 1) % r.size()].x * 4, r[(i + 1) % r.size()].y * 4};
    const std::int64_t o = (std::int64_t{b.x} - a.x) * (std::int64_t{q4.y} - a.y) - (std::int64_t{b.y} - a.y) * (std::int64_t{q4.x} - a.x);
    if (a.y <= q4.y && q4.y < b.y && o > 0) ++w;
    if (b.y <= q4.y && q4.y < a.y && o < 0) --w;
  }
  return w;
}
bool on_ring4(const Ring& r, Point q4) {
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a{r[i].x * 4, r[i].y * 4}, b{r[(i + 1) % r.size()].x * 4, r[(i + 1) % r.size()].y * 4};
    if (taut::geom::on_segment(q4, a, b)) return true;
  }
  return false;
}

// cut_beyond(): the components of random unions of rectangles, triangles (sloped edges) and
// rings with holes, cut against random boxes (sides through vertices and edges, boxes inside,
// across and beside the shapes): every ring keeps its winding number at every point of the box
// off both rings (points at quarter units, so on sloped edges too), the union in the box is the
// same polygon for polygon (normalize_obstacles with the box as its domain), nothing is moved or
// added, and the runs beyond the sides are in fact cut.
TEST(CutBeyond, KeepsEverythingInTheBox) {
  long long boxes = 0, cut_vertices = 0, dropped = 0, points = 0, inside_points = 0;
  const auto seeds = static_cast<std::uint64_t>(taut::test::sanitized_share(1500, 5));
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed * 7919);
    auto r_ = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
    std::vector<Polygon> in;
    for (int k = r_(2, 9); k-- > 0;) {
      const int x = r_(0, 30), y = r_(0, 30);
      switch (r_(0, 3)) {
        case 0: case 1: in.push_back(Polygon{{{x, y}, {x + r_(1, 12), y}, {x + r_(1, 12), y + r_(1, 12)}, {x, y + r_(1, 12)}}, {}}); break;
        case 2: in.push_back(Polygon{{{x, y}, {x + r_(2, 9), y + r_(-3, 3)}, {x + r_(-2, 3), y + r_(2, 9)}}, {}}); break;
        default: in.push_back(Polygon{{{x, y}, {x + 10, y}, {x + 10, y + 10}, {x, y + 10}}, {{{x + 2, y + 2}, {x + 2, y + 8}, {x + 8, y + 8}, {x + 8, y + 2}}}});
      }
    }
    for (Polygon& p : in) p = taut::geom::normalize_polygon(p);
    bool valid = true;
    for (const Polygon& p : in) valid = valid && taut::geom::twice_area(p.outer) > 0;
    if (!valid) continue;
    const std::vector<Polygon> comps = taut::geom::normalize_obstacles(in, taut::geom::Box{{-100, -100}, {100, 100}}).obstacles;
    for (int t = 0; t < 4; ++t) {
      const int x0 = r_(-4, 36), y0 = r_(-4, 36);
      const taut::geom::Box d{{x0, y0}, {x0 + r_(0, 20), y0 + r_(0, 20)}};
      ++boxes;
      std::vector<Polygon> cut;
      for (const Polygon& p : comps) {
        std::optional<Polygon> c = p;
        if (!taut::geom::cut_beyond(*c, d)) {
          EXPECT_EQ(*c, p) << "a polygon beyond a side is left as it was";
          c.reset();
        }
        std::vector<const Ring*> before{&p.outer}, after;
        for (const Ring& h : p.holes) before.push_back(&h);
        if (c) {
          after.push_back(&c->outer);
          for (const Ring& h : c->holes) after.push_back(&h);
          for (const Ring* r : after)  // no vertex moved or added
            for (Point v : *r) {
              bool found = false;
              for (const Ring* b : before) found = found || std::find(b->begin(), b->end(), v) != b->end();
              ASSERT_TRUE(found) << "vertex (" << v.x << ", " << v.y << ") is new";
            }
          std::size_t nb = 0, na = 0;
          for (const Ring* r : before) nb += r->size();
          for (const Ring* r : after) na += r->size();
          cut_vertices += static_cast<long long>(nb - na);
          cut.push_back(*c);
        } else {
          ++dropped;
        }
        // winding at every point of d at quarter units, off the rings: the sum over the rings
        for (int qx = 4 * d.lo.x; qx <= 4 * d.hi.x; ++qx)
          for (int qy = 4 * d.lo.y; qy <= 4 * d.hi.y; ++qy) {
            // lattice points, and points a quarter and three quarters off them (never on an
            // axis-parallel edge)
            const int mx = ((qx % 4) + 4) % 4, my = ((qy % 4) + 4) % 4;
            if (!(mx == 0 && my == 0) && !(mx == 1 && my == 3)) continue;
            const Point q{qx, qy};
            bool on = false;
            for (const Ring* r : before) on = on || on_ring4(*r, q);
            for (const Ring* r : after) on = on || on_ring4(*r, q);
            if (on) continue;
            int wb = 0, wa = 0;
            for (const Ring* r : before) wb += winding4(*r, q);
            for (const Ring* r : after) wa += winding4(*r, q);
            ASSERT_EQ(wa, wb) << "at (" << qx / 4.0 << ", " << qy / 4.0 << ")";
            ++points;
            inside_points += wb != 0;
          }
      }
      EXPECT_EQ(taut::geom::normalize_obstacles(cut, d).obstacles, taut::geom::normalize_obstacles(comps, d).obstacles);
    }
  }
  std::printf("%lld boxes: %lld vertices cut, %lld polygons beyond a side; %lld points compared, %lld inside\n", boxes,
              cut_vertices, dropped, points, inside_points);
  EXPECT_GT(boxes, taut::test::sanitized_share(4000, 5));
  EXPECT_GT(cut_vertices, taut::test::sanitized_share(5000, 5));
  EXPECT_GT(dropped, taut::test::sanitized_share(500, 5));
  EXPECT_GT(inside_points, taut::test::sanitized_share(100000, 5));
}

}  // namespace normalize_test
