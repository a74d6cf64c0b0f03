// ObstacleIndex (geom/index.h): ray shooting and box queries against a brute-force scan of
// every edge computed with GMP rationals.
#include "geom/index.h"
#include "support/sanitized.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>
#include <tuple>
#include <vector>

namespace taut::geom {
namespace index_test {

constexpr Coord L = kMaxCoord;
constexpr std::uint64_t kBaseSeed = 77001;

mpz_class Z(std::int64_t v) { return mpz_class(static_cast<long>(v)); }

// ---------------------------------------------------------------------------------------------
// Brute-force reference.

using Key = std::tuple<std::uint32_t, std::int32_t, std::uint32_t>;  // polygon, ring, vertex

struct RefHit {
  bool hit = false;
  mpq_class t;
  std::vector<Key> edges;
};

bool on_segment_ref(Point p, Point a, Point b) {
  if (a == b) return p == a;
  if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x) || p.y < std::min(a.y, b.y) ||
      p.y > std::max(a.y, b.y))
    return false;  // outside the bounding box: cheap exact rejection before GMP
  const mpz_class cr = (Z(b.x) - a.x) * (Z(p.y) - a.y) - (Z(b.y) - a.y) * (Z(p.x) - a.x);
  if (cr != 0) return false;
  const mpz_class d = (Z(p.x) - a.x) * (Z(b.x) - a.x) + (Z(p.y) - a.y) * (Z(b.y) - a.y);
  return d >= 0 && d <= (Z(b.x) - a.x) * (Z(b.x) - a.x) + (Z(b.y) - a.y) * (Z(b.y) - a.y);
}

// The set {t >= 0 : p + t d on [a, b]} is empty or an interval; its minimum, by Cramer's rule.
bool ray_edge_ref(Point p, Point d, Point a, Point b, mpq_class& t) {
  // Cheap exact rejections first (__int128 signs): both ends strictly on one side of the ray's
  // line, or both strictly behind the start.
  auto side = [&](Point q) {
    const __int128 c = __int128{d.x} * (__int128{q.y} - p.y) - __int128{d.y} * (__int128{q.x} - p.x);
    return (c > 0) - (c < 0);
  };
  auto ahead = [&](Point q) { return __int128{d.x} * (__int128{q.x} - p.x) + __int128{d.y} * (__int128{q.y} - p.y); };
  if (side(a) * side(b) > 0 || (ahead(a) < 0 && ahead(b) < 0)) return false;
  const mpz_class ex = Z(b.x) - a.x, ey = Z(b.y) - a.y, wx = Z(a.x) - p.x, wy = Z(a.y) - p.y;
  // t d - u e = w  ->  [d.x -e.x; d.y -e.y] [t u]^T = w
  const mpz_class det = Z(d.x) * (-ey) - (-ex) * Z(d.y);
  if (det != 0) {
    mpq_class tt(wx * (-ey) - (-ex) * wy, det), uu(Z(d.x) * wy - Z(d.y) * wx, det);
    tt.canonicalize();
    uu.canonicalize();
    if (tt < 0 || uu < 0 || uu > 1) return false;
    t = tt;
    return true;
  }
  if (wx * d.y - wy * d.x != 0) return false;
  const mpz_class dd = Z(d.x) * d.x + Z(d.y) * d.y;
  mpq_class ta(wx * d.x + wy * d.y, dd), tb((Z(b.x) - p.x) * d.x + (Z(b.y) - p.y) * d.y, dd);
  ta.canonicalize();
  tb.canonicalize();
  if (std::max(ta, tb) < 0) return false;
  t = std::max(mpq_class(0), std::min(ta, tb));
  return true;
}

template <class F>
void for_each_edge(const std::vector<Polygon>& obs, F f) {
  for (std::uint32_t k = 0; k < obs.size(); ++k) {
    auto ring = [&](const Ring& r, std::int32_t id) {
      for (std::uint32_t i = 0; i < r.size(); ++i)
        if (r[i] != r[(i + 1) % r.size()]) f(Key{k, id, i}, r[i], r[(i + 1) % r.size()]);
    };
    ring(obs[k].outer, -1);
    for (std::int32_t h = 0; h < static_cast<std::int32_t>(obs[k].holes.size()); ++h)
      ring(obs[k].holes[h], h);
  }
}

RefHit shoot_ref(const std::vector<Polygon>& obs, Point p, Direction dir, bool ignore_start) {
  RefHit r;
  const Point d = step(dir);
  for_each_edge(obs, [&](Key key, Point a, Point b) {
    if (ignore_start && on_segment_ref(p, a, b)) return;
    mpq_class t;
    if (!ray_edge_ref(p, d, a, b, t)) return;
    if (r.hit && t > r.t) return;
    if (!r.hit || t < r.t) {
      r.hit = true;
      r.t = t;
      r.edges.clear();
    }
    if (t == r.t) r.edges.push_back(key);
  });
  std::sort(r.edges.begin(), r.edges.end());
  return r;
}

// Closed segment meets closed box: an endpoint inside, or the segment meets a side (sides are
// tested as point sets with rational parameters).
bool seg_side_ref(Point a, Point b, Point c, Point e) {
  // Does [a,b] meet [c,e]?  Parametrize both; handle degenerate/collinear by sampling ends.
  if (on_segment_ref(a, c, e) || on_segment_ref(b, c, e) || on_segment_ref(c, a, b) ||
      on_segment_ref(e, a, b))
    return true;
  const mpz_class rx = Z(b.x) - a.x, ry = Z(b.y) - a.y, qx = Z(e.x) - c.x, qy = Z(e.y) - c.y;
  const mpz_class den = rx * qy - ry * qx;
  if (den == 0) return false;
  const mpz_class wx = Z(c.x) - a.x, wy = Z(c.y) - a.y;
  mpq_class u(wx * qy - wy * qx, den), v(wx * ry - wy * rx, den);
  u.canonicalize();
  v.canonicalize();
  return u >= 0 && u <= 1 && v >= 0 && v <= 1;
}
bool meets_box_ref(Point a, Point b, const Box& x) {
  if (std::max(a.x, b.x) < x.lo.x || std::min(a.x, b.x) > x.hi.x || std::max(a.y, b.y) < x.lo.y ||
      std::min(a.y, b.y) > x.hi.y)
    return false;  // bounding boxes apart
  auto inside = [&](Point p) { return x.lo.x <= p.x && p.x <= x.hi.x && x.lo.y <= p.y && p.y <= x.hi.y; };
  if (inside(a) || inside(b)) return true;
  const Point c[4] = {x.lo, {x.hi.x, x.lo.y}, x.hi, {x.lo.x, x.hi.y}};
  for (int i = 0; i < 4; ++i)
    if (seg_side_ref(a, b, c[i], c[(i + 1) % 4])) return true;
  return false;
}

// ---------------------------------------------------------------------------------------------
// Layouts.

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  std::int64_t uniform(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  }
};

// Coordinates on a coarse grid (cells of `scale` DBU) so that rays from grid points run along
// edges and through vertices, in all 8 directions; `scale` large puts them near the limit.
struct Layout {
  std::vector<Polygon> obstacles;
  std::vector<Point> queries;
};

Layout random_layout(Gen& g, int grid, std::int64_t scale, std::int64_t offset) {
  auto P = [&](std::int64_t i, std::int64_t j) {
    return Point{static_cast<Coord>(offset + i * scale), static_cast<Coord>(offset + j * scale)};
  };
  Layout lay;
  const int n = static_cast<int>(g.uniform(1, 6));
  for (int k = 0; k < n; ++k) {
    Polygon poly;
    switch (g.uniform(0, 2)) {
      case 0: {  // rectangle, maybe with a repeated vertex and a collinear vertex
        const std::int64_t x0 = g.uniform(0, grid - 1), y0 = g.uniform(0, grid - 1);
        const std::int64_t x1 = g.uniform(x0 + 1, grid), y1 = g.uniform(y0 + 1, grid);
        poly.outer = {P(x0, y0), P(x1, y0), P(x1, y1), P(x0, y1)};
        if (g.uniform(0, 3) == 0) poly.outer.insert(poly.outer.begin() + 1, P(x0, y0));
        if (g.uniform(0, 3) == 0 && x1 - x0 >= 2) poly.outer.insert(poly.outer.begin() + 1, P(x0 + 1, y0));
        break;
      }
      case 1: {  // diamond (diagonal edges)
        const std::int64_t cx = g.uniform(1, grid - 1), cy = g.uniform(1, grid - 1);
        const std::int64_t r = g.uniform(1, std::min({cx, cy, grid - cx, grid - cy}));
        poly.outer = {P(cx - r, cy), P(cx, cy - r), P(cx + r, cy), P(cx, cy + r)};
        break;
      }
      default: {  // arbitrary ring on the grid (may self-intersect: the index does not care)
        const int m = static_cast<int>(g.uniform(3, 6));
        for (int i = 0; i < m; ++i) poly.outer.push_back(P(g.uniform(0, grid), g.uniform(0, grid)));
        if (g.uniform(0, 2) == 0) {
          Ring h;
          for (int i = 0; i < 3; ++i) h.push_back(P(g.uniform(0, grid), g.uniform(0, grid)));
          poly.holes.push_back(h);
        }
      }
    }
    lay.obstacles.push_back(poly);
  }
  for (int k = 0; k < 12; ++k) lay.queries.push_back(P(g.uniform(-1, grid + 1), g.uniform(-1, grid + 1)));
  for (const Polygon& poly : lay.obstacles)
    for (Point v : poly.outer) lay.queries.push_back(v);
  return lay;
}

void check_layout(const Layout& lay, std::uint64_t seed, int* hits) {
  const ObstacleIndex index(lay.obstacles);
  for (Point p : lay.queries)
    for (Direction dir : kAllDirections)
      for (bool ignore : {false, true}) {
        const RefHit ref = shoot_ref(lay.obstacles, p, dir, ignore);
        const RayHit got = index.shoot(p, dir, RayOptions{ignore});
        auto where = [&] {  // built only when an assertion fails
          return "seed " + std::to_string(seed) + " p=(" + std::to_string(p.x) + "," +
                 std::to_string(p.y) + ") dir " + std::to_string(static_cast<int>(dir)) +
                 " ignore " + std::to_string(ignore);
        };
        ASSERT_EQ(got.hit(), ref.hit) << where();
        if (!ref.hit) continue;
        ++*hits;
        ASSERT_GT(got.t.den, 0) << where();
        mpq_class t(Z(got.t.num), Z(got.t.den));
        t.canonicalize();
        ASSERT_EQ(t, ref.t) << where();
        std::vector<Key> keys;
        for (std::uint32_t id : got.edges) {
          const EdgeRef& e = index.edge_ref(id);
          keys.emplace_back(e.polygon, e.ring, e.vertex);
          const Ring& r = e.ring < 0 ? lay.obstacles[e.polygon].outer : lay.obstacles[e.polygon].holes[e.ring];
          ASSERT_EQ(index.edge(id).a, r[e.vertex]) << where();
        }
        std::sort(keys.begin(), keys.end());
        ASSERT_EQ(keys, ref.edges) << where();
      }
}

TEST(ObstacleIndex, RaysMatchBruteForceOnCoarseGrids) {
  int hits = 0;
  // Under the sanitizers an eighth of the layouts (support/sanitized.h).
  const int layouts = static_cast<int>(taut::test::sanitized_share(250, 4));
  for (int i = 0; i < layouts; ++i) {
    const std::uint64_t seed = kBaseSeed + i;
    Gen g(seed);
    const int grid = static_cast<int>(g.uniform(2, 10));
    Layout lay;
    switch (i % 3) {
      case 0: lay = random_layout(g, grid, 1, 0); break;
      case 1: lay = random_layout(g, grid, (2 * std::int64_t{L}) / grid, -L); break;  // to the limit
      default: lay = random_layout(g, grid, g.uniform(1, 1000), g.uniform(-1000, 1000)); break;
    }
    check_layout(lay, seed, &hits);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(hits, taut::test::sanitized_share(10000, 4));
}

TEST(ObstacleIndex, RaysMatchBruteForceFullRange) {
  // Arbitrary coordinates: diagonal rays hit at rational parameters.
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    const std::uint64_t seed = kBaseSeed + 100000 + i;
    Gen g(seed);
    Layout lay;
    const int n = static_cast<int>(g.uniform(1, 8));
    for (int k = 0; k < n; ++k) {
      Polygon poly;
      for (int v = 0; v < 4; ++v)
        poly.outer.push_back({static_cast<Coord>(g.uniform(-L, L)), static_cast<Coord>(g.uniform(-L, L))});
      lay.obstacles.push_back(poly);
    }
    for (int k = 0; k < 10; ++k)
      lay.queries.push_back({static_cast<Coord>(g.uniform(-L, L)), static_cast<Coord>(g.uniform(-L, L))});
    lay.queries.push_back({L, L});
    lay.queries.push_back({-L, -L});
    check_layout(lay, seed, &hits);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(hits, 3000);
}

TEST(ObstacleIndex, HandMadeSemantics) {
  //  y
  //  4  +-----+
  //     |     |        square A = [2,6] x [0,4]
  //  0  +-----+
  //     2     6
  const std::vector<Polygon> obs = {{{{2, 0}, {6, 0}, {6, 4}, {2, 4}}, {}}};
  const ObstacleIndex index(obs);
  EXPECT_EQ(index.edge_count(), 4u);
  // E from (0,2): hits the left edge (vertex 3: (2,4)->(2,0)) at t = 2.
  RayHit h = index.shoot({0, 2}, Direction::E);
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t.num, 2);
  EXPECT_EQ(h.t.den, 1);
  ASSERT_EQ(h.edges.size(), 1u);
  EXPECT_EQ(index.edge_ref(h.edges[0]).vertex, 3u);
  // E along the bottom edge from (0,0): the collinear bottom edge and the left edge, at t = 2.
  h = index.shoot({0, 0}, Direction::E);
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t.num, 2);
  EXPECT_EQ(h.edges.size(), 2u);
  // NE from (0,-2) passes exactly through the vertex (2,0): both edges at t = 2.
  h = index.shoot({0, -2}, Direction::NE);
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t.num, 2);
  EXPECT_EQ(h.edges.size(), 2u);
  // A start point on an edge hits it at t = 0, unless ignored.
  h = index.shoot({4, 0}, Direction::S);
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t.num, 0);
  h = index.shoot({4, 0}, Direction::S, RayOptions{true});
  EXPECT_FALSE(h.hit());
  h = index.shoot({4, 0}, Direction::N, RayOptions{true});
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t.num, 4);
  // Diagonal rational hit: from (0,1) NE the ray y = x + 1 meets x = 2 at t = 2; from (1,0)
  // NW it meets x = 2? no (moves left): nothing.
  EXPECT_FALSE(index.shoot({1, 0}, Direction::NW).hit());
  const std::vector<Polygon> slanted = {{{{0, 10}, {3, 0}, {5, 10}}, {}}};
  const ObstacleIndex s(slanted);
  // From (0,0) NE: y = x meets edge (0,10)-(3,0) [10x + 3y = 30] at x = 30/13.
  h = s.shoot({0, 0}, Direction::NE);
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t.num, 30);
  EXPECT_EQ(h.t.den, 13);
  // Empty index.
  const ObstacleIndex empty(std::span<const Polygon>{});
  EXPECT_FALSE(empty.shoot({0, 0}, Direction::E).hit());
  EXPECT_TRUE(empty.edges_in_box({{0, 0}, {1, 1}}).empty());
}

TEST(ObstacleIndex, BoxQueryMatchesBruteForce) {
  int found = 0;
  for (int i = 0; i < 800; ++i) {
    const std::uint64_t seed = kBaseSeed + 200000 + i;
    Gen g(seed);
    const int grid = static_cast<int>(g.uniform(2, 10));
    const std::int64_t scale = i % 2 ? 1 : (2 * std::int64_t{L}) / grid, offset = i % 2 ? 0 : -L;
    const Layout lay = random_layout(g, grid, scale, offset);
    const ObstacleIndex index(lay.obstacles);
    // (an index answers its first 16 such queries by reading every edge, the rest by its R-tree:
    // 24 queries check both)
    for (int q = 0; q < 24; ++q) {
      auto c = [&] { return static_cast<Coord>(offset + g.uniform(-1, grid + 1) * scale / (q % 2 + 1)); };
      Coord x0 = c(), x1 = c(), y0 = c(), y1 = c();
      const Box box{{std::min(x0, x1), std::min(y0, y1)}, {std::max(x0, x1), std::max(y0, y1)}};
      std::vector<Key> want;
      for_each_edge(lay.obstacles, [&](Key k, Point a, Point b) {
        if (meets_box_ref(a, b, box)) want.push_back(k);
      });
      std::vector<Key> got;
      for (std::uint32_t id : index.edges_in_box(box)) {
        const EdgeRef& e = index.edge_ref(id);
        got.emplace_back(e.polygon, e.ring, e.vertex);
      }
      std::sort(want.begin(), want.end());
      std::sort(got.begin(), got.end());
      found += static_cast<int>(want.size());
      ASSERT_EQ(got, want) << "seed " << seed << " box " << box.lo.x << "," << box.lo.y << " "
                           << box.hi.x << "," << box.hi.y;
    }
  }
  EXPECT_GT(found, 12000);
}

TEST(ObstacleIndex, ManyEdgesIsFast) {
  // 40000 unit-ish squares on a 200x200 lattice; 20000 rays. Checks a sample against the
  // brute force and reports the time per ray (no assertion on time: machines differ).
  std::vector<Polygon> obs;
  Gen g(kBaseSeed + 300000);
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j) {
      if (g.uniform(0, 2) == 0) continue;
      const Coord x = i * 100, y = j * 100, w = static_cast<Coord>(g.uniform(10, 90));
      obs.push_back({{{x, y}, {x + w, y}, {x + w, y + w}, {x, y + w}}, {}});
    }
  const auto t0 = std::chrono::steady_clock::now();
  const ObstacleIndex index(obs);
  const auto t1 = std::chrono::steady_clock::now();
  std::int64_t total_hits = 0;
#ifdef NDEBUG
  const int rays = 20000;
#else
  const int rays = 2000;
#endif
  std::vector<Point> starts;
  for (int k = 0; k < rays; ++k)
    starts.push_back({static_cast<Coord>(g.uniform(-100, 20100)), static_cast<Coord>(g.uniform(-100, 20100))});
  std::vector<RayHit> got(rays);
  const auto t1b = std::chrono::steady_clock::now();
  for (int k = 0; k < rays; ++k) {
    got[k] = index.shoot(starts[k], kAllDirections[k % 8]);
    total_hits += got[k].hit();
  }
  const auto t2 = std::chrono::steady_clock::now();
  for (int k = 0; k < rays; k += 1000) {
    const RefHit ref = shoot_ref(obs, starts[k], kAllDirections[k % 8], false);
    ASSERT_EQ(got[k].hit(), ref.hit) << k;
    if (ref.hit) {
      ASSERT_EQ(got[k].edges.size(), ref.edges.size()) << k;
      mpq_class t(Z(got[k].t.num), Z(got[k].t.den));
      t.canonicalize();
      ASSERT_EQ(t, ref.t) << k;
    }
  }
  const double build_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  const double ray_us = std::chrono::duration<double, std::micro>(t2 - t1b).count() / rays;
  std::printf("[ index ] %zu edges: build %.1f ms, %.2f us per ray (%lld hits)\n",
              index.edge_count(), build_ms, ray_us, static_cast<long long>(total_hits));
  EXPECT_GT(total_hits, rays / 2);
}

}  // namespace index_test
}  // namespace taut::geom
