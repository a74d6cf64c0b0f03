// Exact predicates (geom/predicates.h) against an independent reference written with GMP
// rationals: different formulas (parametric solving, quadrant winding numbers), same answers.
#include "geom/predicates.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace taut::geom {
namespace predicates_test {

constexpr Coord L = kMaxCoord;
constexpr std::uint64_t kBaseSeed = 20240611;

// ---------------------------------------------------------------------------------------------
// GMP reference.

mpz_class Z(Coord v) { return mpz_class(static_cast<long>(v)); }
mpz_class Z(std::int64_t v) { return mpz_class(static_cast<long>(v)); }
mpz_class Z(i128 v) {
  const bool neg = v < 0;
  unsigned __int128 u = neg ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
  mpz_class hi(static_cast<unsigned long>(u >> 64)), lo(static_cast<unsigned long>(u));
  mpz_class r = (hi << 64) + lo;
  return neg ? mpz_class(-r) : r;
}

struct QPoint {
  mpq_class x, y;
};
mpz_class cross_ref(Point o, Point a, Point b) {
  return (Z(a.x) - Z(o.x)) * (Z(b.y) - Z(o.y)) - (Z(a.y) - Z(o.y)) * (Z(b.x) - Z(o.x));
}
mpz_class dot_ref(Point o, Point a, Point b) {  // (a - o) . (b - o)
  return (Z(a.x) - Z(o.x)) * (Z(b.x) - Z(o.x)) + (Z(a.y) - Z(o.y)) * (Z(b.y) - Z(o.y));
}
// p = a + lambda (b - a) with lambda in [0, 1].
bool on_segment_ref(Point p, Point a, Point b) {
  if (a == b) return p == a;
  if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x) || p.y < std::min(a.y, b.y) ||
      p.y > std::max(a.y, b.y))
    return false;  // outside the bounding box: cheap exact rejection before GMP
  if (cross_ref(a, b, p) != 0) return false;
  const mpz_class d = dot_ref(a, p, b);
  return d >= 0 && d <= dot_ref(a, b, b);
}

// Solves s.a + u (s.b - s.a) = t.a + v (t.b - t.a) in rationals and classifies the solution set.
SegmentIntersection intersect_ref(Segment s, Segment t) {
  using SI = SegmentIntersection;
  const bool sp = s.a == s.b, tp = t.a == t.b;
  if (sp && tp) return s.a == t.a ? SI::Touch : SI::None;
  if (sp) return on_segment_ref(s.a, t.a, t.b) ? SI::Touch : SI::None;
  if (tp) return on_segment_ref(t.a, s.a, s.b) ? SI::Touch : SI::None;
  const mpz_class rx = Z(s.b.x) - Z(s.a.x), ry = Z(s.b.y) - Z(s.a.y);
  const mpz_class qx = Z(t.b.x) - Z(t.a.x), qy = Z(t.b.y) - Z(t.a.y);
  const mpz_class wx = Z(t.a.x) - Z(s.a.x), wy = Z(t.a.y) - Z(s.a.y);
  const mpz_class den = rx * qy - ry * qx;
  if (den != 0) {
    const mpq_class u(wx * qy - wy * qx, den), v(wx * ry - wy * rx, den);
    mpq_class uu = u, vv = v;
    uu.canonicalize();
    vv.canonicalize();
    if (uu < 0 || uu > 1 || vv < 0 || vv > 1) return SI::None;
    if (uu > 0 && uu < 1 && vv > 0 && vv < 1) return SI::Proper;
    return SI::Touch;
  }
  if (wx * ry - wy * rx != 0) return SI::None;  // parallel, distinct lines
  // Collinear: parameters of t's endpoints along s, intersect [0,1] with [min, max].
  const mpz_class rr = rx * rx + ry * ry;
  mpq_class ua(wx * rx + wy * ry, rr);
  mpq_class ub((Z(t.b.x) - Z(s.a.x)) * rx + (Z(t.b.y) - Z(s.a.y)) * ry, rr);
  ua.canonicalize();
  ub.canonicalize();
  const mpq_class lo = std::max(mpq_class(0), std::min(ua, ub));
  const mpq_class hi = std::min(mpq_class(1), std::max(ua, ub));
  if (lo > hi) return SI::None;
  return lo == hi ? SI::Touch : SI::Overlap;
}

// Winding number by quadrant counting around p (a different method from crossing numbers).
Location locate_ref(Point p, std::span<const Point> ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    if (on_segment_ref(p, ring[i], ring[(i + 1) % n])) return Location::Boundary;
  auto quadrant = [&](Point v) {
    const std::int64_t x = std::int64_t{v.x} - p.x, y = std::int64_t{v.y} - p.y;
    if (x > 0 && y >= 0) return 0;
    if (x <= 0 && y > 0) return 1;
    if (x < 0 && y <= 0) return 2;
    return 3;
  };
  long wind = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    const int d = (quadrant(b) - quadrant(a) + 4) % 4;
    if (d == 1) wind += 1;
    if (d == 3) wind -= 1;
    if (d == 2) wind += cross_ref(p, a, b) > 0 ? 2 : -2;
  }
  return wind != 0 ? Location::Inside : Location::Outside;
}

mpz_class twice_area_ref(std::span<const Point> ring) {
  mpz_class sum = 0;
  const Point o = ring.empty() ? Point{} : ring[0];
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) sum += cross_ref(o, ring[i], ring[i + 1]);
  return sum;  // fan triangulation from vertex 0, not the shoelace formula
}

// ---------------------------------------------------------------------------------------------
// Generators. Each instance mixes scales so coincidences (shared x/y, collinear triples) are
// common both at small coordinates and near the coordinate limit.

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  std::int64_t uniform(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  }
  Coord coord(int mode) {
    switch (mode) {
      case 0: return static_cast<Coord>(uniform(-L, L));               // full range
      case 1: return static_cast<Coord>(uniform(-4, 4));               // coarse small grid
      case 2: return static_cast<Coord>(uniform(-4, 4) * (L / 4));     // coarse huge grid
      case 3: return static_cast<Coord>(L - uniform(0, 3)) * (uniform(0, 1) ? 1 : -1);  // edge
      default: return static_cast<Coord>(uniform(-1000, 1000));
    }
  }
  Point point(int mode) { return {coord(mode), coord(mode)}; }
  Point point() { return point(static_cast<int>(uniform(0, 4))); }
};

// ---------------------------------------------------------------------------------------------

TEST(Predicates, OrientMatchesGmpRandom) {
  for (int i = 0; i < 20000; ++i) {
    Gen g(kBaseSeed + i);
    const int mode = i % 5;
    const Point a = g.point(mode), b = g.point(mode), c = g.point(mode);
    ASSERT_EQ(Z(orient(a, b, c)), cross_ref(a, b, c)) << "seed " << kBaseSeed + i;
    ASSERT_EQ(Z(dot(a, b, a, c)), dot_ref(a, b, c)) << "seed " << kBaseSeed + i;
  }
}

TEST(Predicates, OrientAdversarialNearLimit) {
  // Nearly collinear triples along the diagonal and the extreme corners.
  std::vector<Point> pts = {{-L, -L}, {L, L}, {L - 1, L - 1}, {L - 1, L}, {L, L - 1},
                            {-L, L},  {L, -L}, {0, 0},        {1, 0},      {0, 1},
                            {-L + 1, -L}, {L, L - 2}, {-L, -L + 1}, {1, 1}, {-1, -1}};
  for (Point a : pts)
    for (Point b : pts)
      for (Point c : pts) {
        ASSERT_EQ(Z(orient(a, b, c)), cross_ref(a, b, c));
        ASSERT_EQ(orientation(a, b, c), sgn(cross_ref(a, b, c)));
      }
  EXPECT_EQ(orientation({-L, -L}, {L, L}, {L - 1, L - 1}), 0);
  EXPECT_EQ(orientation({-L, -L}, {L, L}, {L - 1, L}), 1);
  EXPECT_EQ(orientation({-L, -L}, {L, L}, {L, L - 1}), -1);
  // Points one unit off a long line with a non-trivial slope: (-L, -L+1) .. (L, L-2) has
  // slope (2L-3)/(2L); test points p and p +- (0,1) near the middle.
  const Point a{-L, -L + 1}, b{L, L - 2};
  for (std::int64_t x = -5; x <= 5; ++x)
    for (std::int64_t y = -5; y <= 5; ++y) {
      const Point p{static_cast<Coord>(x), static_cast<Coord>(y)};
      ASSERT_EQ(orientation(a, b, p), sgn(cross_ref(a, b, p)));
    }
}

TEST(Predicates, OnSegmentMatchesGmp) {
  int on = 0;
  for (int i = 0; i < 20000; ++i) {
    Gen g(kBaseSeed + 100000 + i);
    const int mode = i % 5;
    const Point a = g.point(mode), b = (i % 17 == 0) ? a : g.point(mode);
    Point p = g.point(mode);
    if (i % 3 == 0 && a != b) {
      // A point on the line through a and b, possibly beyond the ends: a + k * (b - a) / gcd.
      std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
      const std::int64_t gg = std::gcd(dx, dy);
      dx /= gg;
      dy /= gg;
      const std::int64_t k = g.uniform(-2, gg + 2);
      const std::int64_t x = a.x + k * dx, y = a.y + k * dy;
      if (in_range(x) && in_range(y)) p = {static_cast<Coord>(x), static_cast<Coord>(y)};
    }
    if (i % 7 == 0) p = (i % 2) ? a : b;
    const bool ref = on_segment_ref(p, a, b);
    on += ref;
    ASSERT_EQ(on_segment(p, a, b), ref) << "seed " << kBaseSeed + 100000 + i;
  }
  EXPECT_GT(on, 3000);  // the generator really exercises the 'on' branch
}

Segment random_segment(Gen& g, int mode) {
  return {g.point(mode), g.point(mode)};
}

TEST(Predicates, IntersectMatchesGmpRandom) {
  int counts[4] = {0, 0, 0, 0};
  for (int i = 0; i < 40000; ++i) {
    const std::uint64_t seed = kBaseSeed + 200000 + i;
    Gen g(seed);
    const int mode = i % 5;
    Segment s = random_segment(g, mode), t = random_segment(g, mode);
    switch (i % 6) {
      case 1: t.a = s.b; break;                    // share an endpoint
      case 2: t = {s.b, s.a}; break;               // same segment reversed
      case 3: s.b = s.a; break;                    // zero-length s
      case 4: {                                    // t collinear with s (on its line)
        std::int64_t dx = std::int64_t{s.b.x} - s.a.x, dy = std::int64_t{s.b.y} - s.a.y;
        const std::int64_t gg = std::gcd(dx, dy);
        if (gg == 0) break;
        dx /= gg;
        dy /= gg;
        const std::int64_t k1 = g.uniform(-gg, 2 * gg), k2 = g.uniform(-gg, 2 * gg);
        const std::int64_t x1 = s.a.x + k1 * dx, y1 = s.a.y + k1 * dy;
        const std::int64_t x2 = s.a.x + k2 * dx, y2 = s.a.y + k2 * dy;
        if (in_range(x1) && in_range(y1) && in_range(x2) && in_range(y2))
          t = {{static_cast<Coord>(x1), static_cast<Coord>(y1)},
               {static_cast<Coord>(x2), static_cast<Coord>(y2)}};
        break;
      }
      default: break;
    }
    const SegmentIntersection ref = intersect_ref(s, t);
    counts[static_cast<int>(ref)]++;
    ASSERT_EQ(intersect(s, t), ref) << "seed " << seed;
    ASSERT_EQ(intersect(t, s), ref) << "seed " << seed;
    ASSERT_EQ(intersect({s.b, s.a}, t), ref) << "seed " << seed;
  }
  for (int k = 0; k < 4; ++k) EXPECT_GT(counts[k], 1000) << "class " << k;
}

TEST(Predicates, IntersectDegenerateCases) {
  using SI = SegmentIntersection;
  auto check = [](Segment s, Segment t, SI want) {
    EXPECT_EQ(intersect_ref(s, t), want);  // the reference agrees with the hand answer
    EXPECT_EQ(intersect(s, t), want);
    EXPECT_EQ(intersect(t, s), want);
  };
  // Two single points on a vertical line (the old axis-projection bug reported Touch).
  check({{0, 0}, {0, 0}}, {{0, 5}, {0, 5}}, SI::None);
  check({{3, 3}, {3, 3}}, {{3, 3}, {3, 3}}, SI::Touch);
  check({{3, 3}, {3, 3}}, {{0, 0}, {6, 6}}, SI::Touch);   // point inside a segment
  check({{3, 4}, {3, 4}}, {{0, 0}, {6, 6}}, SI::None);
  check({{0, 0}, {0, 4}}, {{0, 4}, {0, 9}}, SI::Touch);   // collinear vertical, end to end
  check({{0, 0}, {0, 4}}, {{0, 3}, {0, 9}}, SI::Overlap);
  check({{0, 0}, {0, 4}}, {{0, 5}, {0, 9}}, SI::None);
  check({{0, 0}, {4, 0}}, {{2, 0}, {2, 3}}, SI::Touch);   // T junction
  check({{0, 0}, {4, 4}}, {{0, 4}, {4, 0}}, SI::Proper);
  check({{0, 0}, {4, 4}}, {{5, 5}, {9, 9}}, SI::None);    // collinear, disjoint
  check({{-L, -L}, {L, L}}, {{-L + 1, -L}, {L, L - 1}}, SI::None);  // parallel, one unit apart
  check({{-L, -L}, {L, L}}, {{-L, -L + 1}, {L, L - 1}}, SI::Proper);  // tiny angle
  check({{-L, -L}, {L, L}}, {{-L, -L + 1}, {L, L - 2}}, SI::Proper);  // tiny angle, crossing
  check({{-L, -L}, {L, L}}, {{L - 1, L - 1}, {L - 1, L - 1}}, SI::Touch);
  check({{-L, -L}, {L, L}}, {{L - 1, L}, {L, L - 1}}, SI::Proper);
  check({{-L, L}, {L, -L}}, {{-L, -L}, {L, L}}, SI::Proper);
}

mpq_class Q(i128 num, i128 den) {
  mpq_class q(Z(num), Z(den));
  q.canonicalize();
  return q;
}

TEST(Predicates, LineIntersectionMatchesGmp) {
  int done = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t seed = kBaseSeed + 300000 + i;
    Gen g(seed);
    const int mode = i % 5;
    Segment s = random_segment(g, mode), t = random_segment(g, mode);
    if (i % 4 == 0) {  // huge segments crossing at tiny angles
      s = {{-L, static_cast<Coord>(-L + g.uniform(0, 3))}, {L, static_cast<Coord>(L - g.uniform(0, 3))}};
      t = {{-L, static_cast<Coord>(-L + g.uniform(0, 3))}, {L, static_cast<Coord>(L - g.uniform(0, 3))}};
    }
    const mpz_class rx = Z(s.b.x) - Z(s.a.x), ry = Z(s.b.y) - Z(s.a.y);
    const mpz_class qx = Z(t.b.x) - Z(t.a.x), qy = Z(t.b.y) - Z(t.a.y);
    const mpz_class den = rx * qy - ry * qx;
    if (den == 0) continue;
    ++done;
    // Reference: Cramer's rule on a1 x + b1 y = c1, a2 x + b2 y = c2 (the lines' equations).
    const mpz_class a1 = ry, b1 = -rx, c1 = ry * Z(s.a.x) - rx * Z(s.a.y);
    const mpz_class a2 = qy, b2 = -qx, c2 = qy * Z(t.a.x) - qx * Z(t.a.y);
    const mpz_class det = a1 * b2 - a2 * b1;
    mpq_class x(c1 * b2 - c2 * b1, det), y(a1 * c2 - a2 * c1, det);
    x.canonicalize();
    y.canonicalize();
    const RationalPoint r = line_intersection(s, t);
    ASSERT_GT(r.den, 0) << "seed " << seed;
    ASSERT_EQ(Q(r.x_num, r.den), x) << "seed " << seed;
    ASSERT_EQ(Q(r.y_num, r.den), y) << "seed " << seed;
    ASSERT_EQ(r.is_integer(), x.get_den() == 1 && y.get_den() == 1) << "seed " << seed;
  }
  EXPECT_GT(done, 10000);
}

// A random simple ring: points sorted by angle around a centre (exact comparator), then
// rejected unless the reference finds no two non-adjacent edges meeting.
bool simple_ref(const Ring& r) {
  const std::size_t n = r.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Segment a{r[i], r[(i + 1) % n]}, b{r[j], r[(j + 1) % n]};
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const SegmentIntersection k = intersect_ref(a, b);
      if (adjacent ? k == SegmentIntersection::Overlap : k != SegmentIntersection::None)
        return false;
    }
  return cross_ref(r[0], r[1], r[2]) != 0 || twice_area_ref(r) != 0;
}

Ring random_ring(Gen& g, int mode, int max_n) {
  for (;;) {
    const int n = static_cast<int>(g.uniform(3, max_n));
    const Point c = g.point(mode);
    Ring r;
    for (int k = 0; k < n; ++k) {
      const Point p = g.point(mode);
      if (p != c) r.push_back(p);
    }
    auto half = [&](Point p) { return p.y > c.y || (p.y == c.y && p.x > c.x) ? 0 : 1; };
    std::sort(r.begin(), r.end(), [&](Point a, Point b) {
      if (half(a) != half(b)) return half(a) < half(b);
      const int o = orientation(c, a, b);
      if (o != 0) return o > 0;
      return a < b;
    });
    // Keep one point per direction from c: the angularly sorted ring is then star-shaped.
    r.erase(std::unique(r.begin(), r.end(),
                        [&](Point a, Point b) { return half(a) == half(b) && orientation(c, a, b) == 0; }),
            r.end());
    if (r.size() >= 3 && simple_ref(r)) {
      if (g.uniform(0, 1)) std::reverse(r.begin(), r.end());
      return r;
    }
  }
}

// Query points that stress the crossing-number rule: vertices, points on the horizontal line
// through vertices, points one unit off, edge points.
std::vector<Point> query_points(Gen& g, const Ring& r, int mode) {
  std::vector<Point> q;
  for (int k = 0; k < 8; ++k) q.push_back(g.point(mode));
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()];
    q.push_back(a);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const std::int64_t x = std::int64_t{a.x} + dx, y = std::int64_t{a.y} + dy;
        if (in_range(x) && in_range(y)) q.push_back({static_cast<Coord>(x), static_cast<Coord>(y)});
      }
    q.push_back({g.point(mode).x, a.y});  // same y as a vertex: the ray hits the vertex
    const std::int64_t mx = (std::int64_t{a.x} + b.x), my = (std::int64_t{a.y} + b.y);
    if (mx % 2 == 0 && my % 2 == 0) q.push_back({static_cast<Coord>(mx / 2), static_cast<Coord>(my / 2)});
  }
  return q;
}

TEST(Predicates, LocateRingMatchesWindingNumber) {
  int where[3] = {0, 0, 0};
  for (int i = 0; i < 500; ++i) {
    const std::uint64_t seed = kBaseSeed + 400000 + i;
    Gen g(seed);
    const int mode = i % 5 == 3 ? 2 : i % 5;  // mode 3 (all near one corner) makes few rings
    const Ring r = random_ring(g, mode, 9);
    for (Point p : query_points(g, r, mode)) {
      const Location ref = locate_ref(p, r);
      where[static_cast<int>(ref)]++;
      ASSERT_EQ(locate(p, std::span<const Point>(r)), ref)
          << "seed " << seed << " p=(" << p.x << "," << p.y << ")";
    }
  }
  for (int k = 0; k < 3; ++k) EXPECT_GT(where[k], 500) << "location " << k;
}

TEST(Predicates, LocateHorizontalEdgesAndVertexOnRay) {
  // A comb with horizontal edges at the query's y and vertices exactly on the ray:
  //   y=2  +--+  +--+
  //        |  |  |  |
  //   y=1  |  +--+  |     queries along y = 1 and y = 2
  //   y=0  +--------+
  const Ring comb = {{0, 0}, {9, 0}, {9, 2}, {6, 2}, {6, 1}, {3, 1}, {3, 2}, {0, 2}};
  for (int x = -1; x <= 10; ++x)
    for (int y = -1; y <= 3; ++y) {
      const Point p{x, y};
      EXPECT_EQ(locate(p, std::span<const Point>(comb)), locate_ref(p, comb)) << x << "," << y;
    }
  EXPECT_EQ(locate({1, 1}, std::span<const Point>(comb)), Location::Inside);
  EXPECT_EQ(locate({4, 1}, std::span<const Point>(comb)), Location::Boundary);
  EXPECT_EQ(locate({4, 2}, std::span<const Point>(comb)), Location::Outside);
  EXPECT_EQ(locate({-1, 2}, std::span<const Point>(comb)), Location::Outside);
  // Repeated and collinear vertices are tolerated.
  const Ring rep = {{0, 0}, {0, 0}, {5, 0}, {10, 0}, {10, 10}, {10, 10}, {0, 10}};
  EXPECT_EQ(locate({5, 5}, std::span<const Point>(rep)), Location::Inside);
  EXPECT_EQ(locate({5, 0}, std::span<const Point>(rep)), Location::Boundary);
  EXPECT_EQ(locate({11, 0}, std::span<const Point>(rep)), Location::Outside);
}

TEST(Predicates, LocatePolygonWithHoles) {
  for (int i = 0; i < 300; ++i) {
    const std::uint64_t seed = kBaseSeed + 500000 + i;
    Gen g(seed);
    const int mode = i % 2 ? 1 : 4;
    Polygon poly;
    poly.outer = random_ring(g, mode, 8);
    const int holes = static_cast<int>(g.uniform(0, 2));
    for (int h = 0; h < holes; ++h) poly.holes.push_back(random_ring(g, mode, 6));
    std::vector<Point> q = query_points(g, poly.outer, mode);
    for (const Ring& h : poly.holes)
      for (Point p : query_points(g, h, mode)) q.push_back(p);
    for (Point p : q) {
      // Reference by the definition: inside the outer ring and outside every hole; boundary
      // of any ring (when not outside the outer ring) is boundary.
      Location ref = locate_ref(p, poly.outer);
      if (ref == Location::Inside) {
        for (const Ring& h : poly.holes) {
          const Location lh = locate_ref(p, h);
          if (lh == Location::Boundary) { ref = Location::Boundary; break; }
          if (lh == Location::Inside) ref = Location::Outside;
        }
      }
      ASSERT_EQ(locate(p, poly), ref) << "seed " << seed << " p=(" << p.x << "," << p.y << ")";
    }
  }
}

TEST(Predicates, TwiceAreaMatchesGmp) {
  for (int i = 0; i < 5000; ++i) {
    const std::uint64_t seed = kBaseSeed + 600000 + i;
    Gen g(seed);
    Ring r;
    const int n = static_cast<int>(g.uniform(0, 12));
    const int mode = i % 5;
    for (int k = 0; k < n; ++k) r.push_back(g.point(mode));
    ASSERT_EQ(Z(twice_area(r)), twice_area_ref(r)) << "seed " << seed;
  }
  // The extreme square: 2 * (2L)^2 = 8 L^2 > 2^63, needs the __int128 accumulator.
  const Ring sq = {{-L, -L}, {L, -L}, {L, L}, {-L, L}};
  EXPECT_EQ(Z(twice_area(sq)), 8 * Z(L) * Z(L));
  Ring rev(sq.rbegin(), sq.rend());
  EXPECT_EQ(Z(twice_area(rev)), -8 * Z(L) * Z(L));
}

// The reference: the nearest point a + lambda (b - a), lambda the projection clamped to [0, 1],
// and its squared distance, all in GMP rationals (no case for the segment's inside).
TEST(Predicates, PointSegmentDistanceMatchesGmp) {
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    Gen g(kBaseSeed + 300000 + i);
    const int mode = i % 5;
    const Point a = g.point(mode), b = (i % 13 == 0) ? a : g.point(mode), p = (i % 11 == 0) ? a : g.point(mode);
    mpq_class lambda = 0;
    const mpz_class len2 = dot_ref(a, b, b);
    if (len2 != 0) {
      lambda = mpq_class(dot_ref(a, p, b), len2);
      lambda.canonicalize();
      inside += lambda > 0 && lambda < 1;
      lambda = std::clamp(lambda, mpq_class(0), mpq_class(1));
    }
    const mpq_class qx = Z(a.x) + lambda * (Z(b.x) - Z(a.x)), qy = Z(a.y) + lambda * (Z(b.y) - Z(a.y));
    const mpq_class ref = (Z(p.x) - qx) * (Z(p.x) - qx) + (Z(p.y) - qy) * (Z(p.y) - qy);
    const SquaredDistance d = point_segment_distance2(p, a, b);
    ASSERT_GT(d.den, 0) << "seed " << kBaseSeed + 300000 + i;
    mpq_class got(Z(d.num), Z(d.den));
    got.canonicalize();
    ASSERT_EQ(got, ref) << "seed " << kBaseSeed + 300000 + i;
  }
  EXPECT_GT(inside, 3000);  // the nearest point inside the segment, not only at its ends
}

}  // namespace predicates_test
}  // namespace taut::geom

// lattice_neighbours against a walk over the multiples of k (half-integers, negatives, the limit).
TEST(Predicates, LatticeNeighboursAreTheNearestMultiples) {
  for (const taut::geom::i64 k : {1, 2, 3, 8, 64}) {
    std::vector<taut::geom::i64> twices;
    for (taut::geom::i64 t = -300; t <= 300; ++t) twices.push_back(t);
    for (const taut::geom::i64 big : {taut::geom::i64{1} << 31, (taut::geom::i64{1} << 31) - 1}) {
      twices.push_back(big);
      twices.push_back(-big);
    }
    for (const taut::geom::i64 twice : twices) {
      const auto [lo, hi] = taut::geom::lattice_neighbours(twice, k);
      SCOPED_TRACE("twice " + std::to_string(twice) + " k " + std::to_string(k));
      EXPECT_EQ(lo % k, 0);
      EXPECT_EQ(hi % k, 0);
      EXPECT_LE(2 * lo, twice);
      EXPECT_GT(2 * (lo + k), twice);  // the greatest below
      EXPECT_GE(2 * hi, twice);
      EXPECT_LT(2 * (hi - k), twice);  // the least above
    }
  }
}
