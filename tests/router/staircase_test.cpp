// router/staircase: polygonal shortest paths turned into rectilinear / octilinear staircases.
//
// The reference is independent of the code under test: the L1 oracle (tests/oracle/l1_oracle.h)
// judges every unit step of the integer lattice (allowed segment) and every lattice point
// (which free wedges hold the arrival and departure directions), and a 0-1 BFS over ALL
// lattice points of a link's rectangle (parallelogram for octilinear) counts the fewest bends
// of a monotone lattice staircase per (first, last) direction. On layouts with coordinates
// <= 60 the builder's per-link tables must equal it exactly (this is what checks that the
// sparse candidate coordinates and the A* pruning lose nothing), and the bends of the whole
// output must equal a DP over the reference tables with the oracle's wedges at the joints
// (so the builder's bounded per-link searches lose nothing either). Inputs: oracle shortest
// paths between random free points and obstacle vertices, free straight segments, and
// two-link paths through obstacle vertices (pinches first). Every output is checked by
// L1Reference::check_path (free, length) and for shape (rectilinear/octilinear, integer,
// ends, bends only); a builder with a 3-step budget (depth-first fallback) must stay legal.
// Larger layouts check validity and length only. Seeds are in every failure message.
#include "router/staircase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "geom/directions.h"
#include "geom/normalize.h"
#include "geom/predicates.h"
#include "geom/validate.h"
#include "oracle/l1_oracle.h"
#include "support/sanitized.h"

namespace staircase_test {

using taut::geom::Box;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Ring;
using taut::oracle::L1Reference;
using taut::oracle::Wedge;
using taut::router::count_bends;
using taut::router::LinkTable;
using taut::router::StaircaseBuilder;
using taut::router::StaircaseStyle;
using i64 = std::int64_t;

constexpr int kInf = 1 << 29;

std::string str(Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }
std::string str(const std::vector<Point>& ps) {
  std::string s;
  for (const Point p : ps) s += str(p) + " ";
  return s;
}
std::string describe(const Box& d, const std::vector<Polygon>& obs) {
  std::ostringstream os;
  os << "domain " << str(d.lo) << str(d.hi);
  for (const Polygon& p : obs) {
    os << " | ";
    for (const Point v : p.outer) os << str(v);
    for (const Ring& h : p.holes) {
      os << " hole ";
      for (const Point v : h) os << str(v);
    }
  }
  return os.str();
}

i64 l1(Point a, Point b) { return std::abs(i64{a.x} - b.x) + std::abs(i64{a.y} - b.y); }
i64 l1_length(const std::vector<Point>& p) {
  i64 s = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) s += l1(p[i], p[i + 1]);
  return s;
}
// Octilinear length as (a, b): a + b * sqrt(2).
std::pair<i64, i64> oct_length(const std::vector<Point>& p) {
  i64 a = 0, b = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const i64 dx = std::abs(i64{p[i].x} - p[i + 1].x), dy = std::abs(i64{p[i].y} - p[i + 1].y);
    a += std::max(dx, dy) - std::min(dx, dy);
    b += std::min(dx, dy);
  }
  return {a, b};
}

// ---------------------------------------------------------------------------------------------
// Brute-force reference on the unit lattice (see the file comment).
class LatticeRef {
 public:
  explicit LatticeRef(const L1Reference& ref) : ref_(ref) {}

  const std::vector<Wedge>& wedges(Point p) {
    auto it = wedges_.find(p);
    if (it == wedges_.end()) it = wedges_.emplace(p, ref_.wedges_at(p)).first;
    return it->second;
  }
  // Index of the oracle wedge at p holding direction d, -1 if none.
  int wedge_index(Point p, Point d) {
    const auto& ws = wedges(p);
    for (std::size_t i = 0; i < ws.size(); ++i)
      if (ws[i].contains(d.x, d.y)) return static_cast<int>(i);
    return -1;
  }
  bool pass(Point p, Point back, Point fwd) {
    for (const Wedge& w : wedges(p))
      if (w.contains(back.x, back.y) && w.contains(fwd.x, fwd.y)) return true;
    return false;
  }
  bool step(Point p, Point q) {
    const auto key = std::make_pair(p, q);
    auto it = steps_.find(key);
    if (it == steps_.end()) it = steps_.emplace(key, ref_.visible(p, q)).first;
    return it->second;
  }

  struct Link {
    std::array<Point, 2> d{};
    std::array<std::array<int, 2>, 2> bends{{{-1, -1}, {-1, -1}}};
    std::array<int, 2> ws{-1, -1};
    std::array<std::array<int, 2>, 2> we{{{-1, -1}, {-1, -1}}};
  };

  // Fewest bends per (first, last) direction of a monotone lattice staircase a -> b using unit
  // steps d1, d2 (the directions the builder reports).
  Link link(Point a, Point b, std::array<Point, 2> d) {
    Link r;
    r.d = d;
    if (d[0] == d[1]) {  // straight
      if (ref_.visible(a, b)) {
        const int w0 = wedge_index(a, d[0]), w1 = wedge_index(b, {-d[0].x, -d[0].y});
        for (int f = 0; f < 2; ++f) {
          r.ws[f] = w0;
          for (int l = 0; l < 2; ++l) r.bends[f][l] = 0, r.we[f][l] = w1;
        }
      }
      return r;
    }
    // b = a + U d1 + V d2.
    const i64 det = i64{d[0].x} * d[1].y - i64{d[0].y} * d[1].x;
    const i64 rx = i64{b.x} - a.x, ry = i64{b.y} - a.y;
    const i64 U = (rx * d[1].y - ry * d[1].x) / det, V = (i64{d[0].x} * ry - i64{d[0].y} * rx) / det;
    EXPECT_GT(U, 0);
    EXPECT_GT(V, 0);
    auto at = [&](i64 u, i64 v) {
      return Point{static_cast<int>(a.x + u * d[0].x + v * d[1].x),
                   static_cast<int>(a.y + u * d[0].y + v * d[1].y)};
    };
    const std::array<i64, 2> lim{U, V};
    auto idx = [&](i64 u, i64 v, int k) { return static_cast<std::size_t>(((u * (V + 1)) + v) * 2 + k); };
    for (int f = 0; f < 2; ++f) {
      r.ws[f] = wedge_index(a, d[f]);
      if (r.ws[f] < 0) continue;
      std::vector<int> dist(static_cast<std::size_t>((U + 1) * (V + 1) * 2), kInf);
      struct S {
        i64 u, v;
        int k, c;
      };
      std::deque<S> dq;
      dist[idx(0, 0, f)] = 0;
      dq.push_back({0, 0, f, 0});
      std::array<int, 2> arr{kInf, kInf};
      while (!dq.empty()) {
        const S s = dq.front();
        dq.pop_front();
        if (dist[idx(s.u, s.v, s.k)] != s.c) continue;
        const i64 nu = s.u + (s.k == 0), nv = s.v + (s.k == 1);
        if (nu > U || nv > V) continue;
        const Point p = at(s.u, s.v), q = at(nu, nv);
        if (!step(p, q)) continue;
        const Point back{-d[s.k].x, -d[s.k].y};
        if (q == b) {
          if (s.c < arr[s.k]) {
            arr[s.k] = s.c;
            r.we[f][s.k] = wedge_index(b, back);
          }
          continue;
        }
        for (const int k2 : {s.k, 1 - s.k}) {
          if ((k2 == 0 ? nu : nv) >= lim[k2]) continue;
          if (!pass(q, back, d[k2])) continue;
          const int nc = s.c + (k2 != s.k);
          int& dd = dist[idx(nu, nv, k2)];
          if (nc >= dd) continue;
          dd = nc;
          if (nc == s.c) dq.push_front({nu, nv, k2, nc});
          else dq.push_back({nu, nv, k2, nc});
        }
      }
      for (int l = 0; l < 2; ++l) r.bends[f][l] = arr[l] < kInf ? arr[l] : -1;
    }
    return r;
  }

 private:
  const L1Reference& ref_;
  std::map<Point, std::vector<Wedge>> wedges_;
  std::map<std::pair<Point, Point>, bool> steps_;
};

// Fewest bends over the whole path from per-link reference tables (joints: one wedge, a bend
// when the directions differ); -1 when some link has no staircase.
int reference_total(LatticeRef& lr, const std::vector<LatticeRef::Link>& links) {
  std::array<int, 4> dp{kInf, kInf, kInf, kInf};
  for (std::size_t i = 0; i < links.size(); ++i) {
    std::array<int, 4> nd{kInf, kInf, kInf, kInf};
    const auto& s = links[i];
    for (int f = 0; f < 2; ++f)
      for (int l = 0; l < 2; ++l) {
        if (s.bends[f][l] < 0) continue;
        if (i == 0) {
          nd[f * 2 + l] = s.bends[f][l];
          continue;
        }
        const auto& p = links[i - 1];
        for (int o = 0; o < 4; ++o) {
          if (dp[o] >= kInf || p.we[o / 2][o % 2] != s.ws[f]) continue;
          const int joint = p.d[o % 2] == s.d[f] ? 0 : 1;
          nd[f * 2 + l] = std::min(nd[f * 2 + l], dp[o] + joint + s.bends[f][l]);
        }
      }
    dp = nd;
  }
  (void)lr;
  const int best = *std::min_element(dp.begin(), dp.end());
  return best >= kInf ? -1 : best;
}

bool axis_parallel(Point a, Point b) { return a.x == b.x || a.y == b.y; }
bool octilinear_dir(Point a, Point b) {
  return a.x == b.x || a.y == b.y || std::abs(i64{a.x} - b.x) == std::abs(i64{a.y} - b.y);
}

// Shape and validity of an output for input polyline `in`.
void check_output(const L1Reference& ref, const std::vector<Point>& in,
                  const std::vector<Point>& out, StaircaseStyle style) {
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.front(), in.front());
  EXPECT_EQ(out.back(), in.back());
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    ASSERT_NE(out[i], out[i + 1]) << str(out);
    if (style == StaircaseStyle::Rectilinear)
      ASSERT_TRUE(axis_parallel(out[i], out[i + 1])) << str(out);
    else
      ASSERT_TRUE(octilinear_dir(out[i], out[i + 1])) << str(out);
  }
  // Bends only: no two consecutive segments in the same direction.
  EXPECT_EQ(count_bends(out), std::max(0, static_cast<int>(out.size()) - 2));
  const auto len = ref.check_path(out);
  ASSERT_TRUE(len.has_value()) << "not free: " << str(out);
  if (style == StaircaseStyle::Rectilinear)
    EXPECT_EQ(*len, l1_length(in));
  else
    EXPECT_EQ(oct_length(out), oct_length(in));
}

std::array<Point, 2> expected_dirs(Point a, Point b, StaircaseStyle style) {
  const int sx = (b.x > a.x) - (b.x < a.x), sy = (b.y > a.y) - (b.y < a.y);
  const i64 ax = std::abs(i64{b.x} - a.x), ay = std::abs(i64{b.y} - a.y);
  if (style == StaircaseStyle::Rectilinear) {
    if (sx == 0 || sy == 0) return {Point{sx, sy}, Point{sx, sy}};
    return {Point{sx, 0}, Point{0, sy}};
  }
  if (sx == 0 || sy == 0 || ax == ay) return {Point{sx, sy}, Point{sx, sy}};
  if (ax > ay) return {Point{sx, 0}, Point{sx, sy}};
  return {Point{0, sy}, Point{sx, sy}};
}

// ---------------------------------------------------------------------------------------------
// Random layouts: rectangles and small triangles / quadrilaterals with vertices on a grid of
// step g (touching corners and collinear edges are frequent), normalized.

std::vector<Polygon> random_layout(std::mt19937& rng, const Box& dom, int g, int nrect, int npoly) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const int gw = (dom.hi.x - dom.lo.x) / g, gh = (dom.hi.y - dom.lo.y) / g;
  std::vector<Polygon> out;
  for (int i = 0; i < nrect; ++i) {
    const int x0 = uni(0, gw - 1), y0 = uni(0, gh - 1);
    const int x1 = std::min(gw, x0 + uni(1, std::max(1, gw / 4))),
              y1 = std::min(gh, y0 + uni(1, std::max(1, gh / 4)));
    const Point lo{dom.lo.x + g * x0, dom.lo.y + g * y0}, hi{dom.lo.x + g * x1, dom.lo.y + g * y1};
    out.push_back({{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, {}});
  }
  for (int i = 0; i < npoly; ++i) {
    const int cx = uni(0, gw), cy = uni(0, gh), n = uni(3, 4), r = uni(1, 4);
    std::vector<std::pair<double, Point>> vs;
    for (int k = 0; k < n; ++k) {
      const int x = std::clamp(cx + uni(-r, r), 0, gw), y = std::clamp(cy + uni(-r, r), 0, gh);
      vs.push_back({0.0, Point{dom.lo.x + g * x, dom.lo.y + g * y}});
    }
    double mx = 0, my = 0;
    for (const auto& v : vs) mx += v.second.x, my += v.second.y;
    mx /= n, my /= n;
    for (auto& v : vs) v.first = std::atan2(v.second.y - my, v.second.x - mx);
    std::sort(vs.begin(), vs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    Polygon p;
    for (const auto& v : vs) p.outer.push_back(v.second);
    if (taut::geom::twice_area(p.outer) == 0 || !taut::geom::validate_polygon(p).empty()) continue;
    out.push_back(p);
  }
  return out;
}

struct Counters {
  int layouts = 0, paths = 0, links = 0, tables = 0, none = 0, unverified_none = 0;
  int bends = 0, paths_with_bends = 0;
  int tiny_found = 0, tiny_greedy = 0;  // with a 3-step search budget (fallback exercised)
  int pinch_joints = 0;                 // joints of input paths at points with >= 2 wedges
};

// One layout: paths between random free points and obstacle vertices (oracle shortest paths,
// and free straight segments), both styles. `brute`: compare with the lattice reference.
void run_layout(unsigned seed, const Box& dom, const std::vector<Polygon>& input, int npoints,
                bool brute, Counters& c) {
  const auto nr = taut::geom::normalize_obstacles(input, dom);
  const L1Reference ref(nr.domain, nr.obstacles);
  ASSERT_TRUE(ref.problems().empty()) << "seed " << seed;
  const StaircaseBuilder sb(nr.domain, nr.obstacles);
  const StaircaseBuilder tiny(nr.domain, nr.obstacles, {.max_work_per_search = 3});
  LatticeRef lr(ref);
  std::mt19937 rng(seed * 7919u + 13u);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<Point> pts;
  for (int tries = 0; tries < 20 * npoints && static_cast<int>(pts.size()) < npoints; ++tries) {
    const Point p{uni(nr.domain.lo.x, nr.domain.hi.x), uni(nr.domain.lo.y, nr.domain.hi.y)};
    if (ref.is_free(p)) pts.push_back(p);
  }
  for (const Polygon& p : nr.obstacles)
    if (uni(0, 1) == 0) pts.push_back(p.outer[rng() % p.outer.size()]);
  ++c.layouts;
  std::vector<std::vector<Point>> paths;
  for (std::size_t i = 0; i + 1 < pts.size(); i += 2) {
    if (auto p = ref.path(pts[i], pts[i + 1]); p && p->size() >= 2) paths.push_back(*p);
    if (ref.visible(pts[i], pts[(i + 3) % pts.size()]))
      paths.push_back({pts[i], pts[(i + 3) % pts.size()]});
  }
  // Two-link paths through an obstacle vertex (pinches first), legal but not necessarily
  // shortest: every joint case, including joints that must keep to one wedge of a pinch.
  std::vector<Point> verts, pinches;
  for (const Polygon& p : nr.obstacles) {
    for (const Point v : p.outer) (ref.wedges_at(v).size() >= 2 ? pinches : verts).push_back(v);
    for (const Ring& h : p.holes)
      for (const Point v : h) (ref.wedges_at(v).size() >= 2 ? pinches : verts).push_back(v);
  }
  for (int k = 0; k < npoints && (!verts.empty() || !pinches.empty()); ++k) {
    const auto& from = !pinches.empty() && (k % 2 == 0 || verts.empty()) ? pinches : verts;
    const Point v = from[rng() % from.size()];
    for (int tries = 0; tries < 20; ++tries) {
      const Point s{uni(nr.domain.lo.x, nr.domain.hi.x), uni(nr.domain.lo.y, nr.domain.hi.y)};
      const Point t{uni(nr.domain.lo.x, nr.domain.hi.x), uni(nr.domain.lo.y, nr.domain.hi.y)};
      const std::vector<Point> via{s, v, t};
      if (s != v && t != v && ref.check_path(via)) {
        paths.push_back(via);
        break;
      }
    }
  }
  for (const auto& path : paths) {
    for (const StaircaseStyle style : {StaircaseStyle::Rectilinear, StaircaseStyle::Octilinear}) {
      const bool rect = style == StaircaseStyle::Rectilinear;
      SCOPED_TRACE("seed " + std::to_string(seed) + (rect ? " rectilinear" : " octilinear") +
                   " path " + str(path) + "\n" + describe(nr.domain, nr.obstacles));
      ++c.paths;
      c.links += static_cast<int>(path.size()) - 1;
      for (std::size_t i = 1; i + 1 < path.size(); ++i) c.pinch_joints += ref.wedges_at(path[i]).size() >= 2;
      const auto out = sb.staircase(path, style);
      if (out) {
        check_output(ref, path, *out, style);
        if (::testing::Test::HasFatalFailure()) return;
        c.bends += count_bends(*out);
        c.paths_with_bends += count_bends(*out) > 0;
      } else {
        ++c.none;
      }
      // Starved of budget: whatever comes back (mostly from the fallback) must still be legal.
      taut::router::StaircaseStats st;
      if (const auto t = tiny.staircase(path, style, &st)) {
        ++c.tiny_found;
        check_output(ref, path, *t, style);
        if (::testing::Test::HasFatalFailure()) return;
        if (out) {
          EXPECT_GE(count_bends(*t), count_bends(*out));
        }
      }
      c.tiny_greedy += static_cast<int>(st.greedy_links);
      if (!brute) {
        c.unverified_none += !out;
        continue;
      }
      std::vector<LatticeRef::Link> links;
      for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        const LinkTable t = sb.link_table(path[i], path[i + 1], style);
        ASSERT_TRUE(t.complete);
        ASSERT_EQ(t.dirs, expected_dirs(path[i], path[i + 1], style));
        links.push_back(lr.link(path[i], path[i + 1], t.dirs));
        ++c.tables;
        ASSERT_EQ(t.bends, links.back().bends)
            << "link " << str(path[i]) << " -> " << str(path[i + 1]) << ": builder [["
            << t.bends[0][0] << "," << t.bends[0][1] << "],[" << t.bends[1][0] << ","
            << t.bends[1][1] << "]] reference [[" << links.back().bends[0][0] << ","
            << links.back().bends[0][1] << "],[" << links.back().bends[1][0] << ","
            << links.back().bends[1][1] << "]]";
      }
      const int total = reference_total(lr, links);
      ASSERT_EQ(out.has_value(), total >= 0) << "reference total " << total;
      if (out) {
        ASSERT_EQ(count_bends(*out), total) << str(*out);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Hand-made cases.

std::vector<Point> rect(Point a, Point b) {
  const Box r{{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
  return {r.lo, {r.hi.x, r.lo.y}, r.hi, {r.lo.x, r.hi.y}};
}

struct Scene {
  taut::geom::NormalizedObstacles nr;
  L1Reference ref;
  StaircaseBuilder sb;
  Scene(const Box& dom, const std::vector<Polygon>& in)
      : nr(taut::geom::normalize_obstacles(in, dom)), ref(nr.domain, nr.obstacles),
        sb(nr.domain, nr.obstacles) {}
};

TEST(Staircase, CountBends) {
  EXPECT_EQ(count_bends(std::vector<Point>{}), 0);
  EXPECT_EQ(count_bends(std::vector<Point>{{0, 0}}), 0);
  EXPECT_EQ(count_bends(std::vector<Point>{{0, 0}, {3, 0}, {5, 0}}), 0);
  EXPECT_EQ(count_bends(std::vector<Point>{{0, 0}, {3, 0}, {3, 0}, {3, 4}, {5, 4}}), 2);
  EXPECT_EQ(count_bends(std::vector<Point>{{0, 0}, {3, 0}, {1, 0}}), 1);  // U-turn: once
  EXPECT_EQ(count_bends(std::vector<Point>{{0, 0}, {2, 2}, {4, 4}, {6, 4}}), 1);
}

TEST(Staircase, EmptyDomainLShape) {
  Scene s({{0, 0}, {10, 10}}, {});
  const std::vector<Point> in{{0, 0}, {5, 3}};
  const auto out = s.sb.rectilinear(in);
  ASSERT_TRUE(out);
  EXPECT_EQ(count_bends(*out), 1);
  check_output(s.ref, in, *out, StaircaseStyle::Rectilinear);
  const auto oct = s.sb.octilinear(in);
  ASSERT_TRUE(oct);
  EXPECT_EQ(oct->size(), 3u);  // E then NE (or NE then E): one 45 degree bend
  check_output(s.ref, in, *oct, StaircaseStyle::Octilinear);
  // Straight and collinear inputs stay one segment.
  const std::vector<Point> straight{{1, 1}, {4, 1}, {8, 1}};
  EXPECT_EQ(s.sb.rectilinear(straight), (std::vector<Point>{{1, 1}, {8, 1}}));
  const std::vector<Point> diag{{1, 1}, {4, 4}};
  EXPECT_EQ(s.sb.octilinear(diag), (std::vector<Point>{{1, 1}, {4, 4}}));
  EXPECT_EQ(s.sb.rectilinear(std::vector<Point>{{2, 2}}), (std::vector<Point>{{2, 2}}));
  EXPECT_FALSE(s.sb.rectilinear(std::vector<Point>{}));
  EXPECT_FALSE(s.sb.rectilinear(std::vector<Point>{{11, 2}, {3, 3}}));  // outside the domain
}

TEST(Staircase, BothLShapesBlockedGivesZ) {
  //  (0,10)+----+            a = (0,0), b = (10,10): the corner (0,10) and the corner (10,0)
  //        |////|      b     are blocked, so the fewest bends is 2 (a Z through the middle).
  //        +----+
  //                  +----+
  //         a        |////|
  //                  +----+ (10,0)
  Scene s({{0, 0}, {10, 10}}, {{rect({0, 6}, {4, 10}), {}}, {rect({6, 0}, {10, 4}), {}}});
  const std::vector<Point> in{{0, 0}, {10, 10}};
  ASSERT_EQ(s.ref.check_path(in), 20);
  const auto out = s.sb.rectilinear(in);
  ASSERT_TRUE(out);
  EXPECT_EQ(count_bends(*out), 2) << str(*out);
  check_output(s.ref, in, *out, StaircaseStyle::Rectilinear);
  const LinkTable t = s.sb.link_table({0, 0}, {10, 10}, StaircaseStyle::Rectilinear);
  // E, N, E and N, E, N need 2; leaving east and arriving north (E, N, E, N) needs 3.
  EXPECT_EQ(t.bends[0][0], 2);
  EXPECT_EQ(t.bends[1][1], 2);
  EXPECT_EQ(t.bends[0][1], 3);
  EXPECT_EQ(t.bends[1][0], 3);
}

TEST(Staircase, NoIntegerStaircaseBetweenSlopedTriangles) {
  // The segment (0,0)->(3,1) runs between two disjoint triangles; every lattice staircase
  // (one unit vertical step at x = 0, 1, 2 or 3) enters one of them: no integer answer.
  const std::vector<Polygon> in{{{{-1, 0}, {2, 1}, {-1, 1}}, {}}, {{{1, 0}, {4, 0}, {4, 1}}, {}}};
  Scene s({{-3, -3}, {6, 4}}, in);
  const std::vector<Point> path{{0, 0}, {3, 1}};
  ASSERT_EQ(s.ref.check_path(path), 4);
  EXPECT_FALSE(s.sb.rectilinear(path));
  const LinkTable t = s.sb.link_table({0, 0}, {3, 1}, StaircaseStyle::Rectilinear);
  EXPECT_TRUE(t.complete);
  EXPECT_EQ(t.bends, (std::array<std::array<int, 2>, 2>{{{-1, -1}, {-1, -1}}}));
  LatticeRef lr(s.ref);
  EXPECT_EQ(lr.link({0, 0}, {3, 1}, t.dirs).bends, t.bends);
  // Octilinear (E and NE) fits: (0,0) -> (1,0) east along the lower triangle's base line,
  // NE to (2,1) between the two sloped edges (vertex to vertex), east to (3,1).
  const LinkTable o = s.sb.link_table({0, 0}, {3, 1}, StaircaseStyle::Octilinear);
  EXPECT_EQ(o.bends, (std::array<std::array<int, 2>, 2>{{{2, -1}, {-1, -1}}}));
  EXPECT_EQ(lr.link({0, 0}, {3, 1}, o.dirs).bends, o.bends);
  EXPECT_EQ(s.sb.octilinear(path), (std::vector<Point>{{0, 0}, {1, 0}, {2, 1}, {3, 1}}));
}

TEST(Staircase, NeverSwitchesWedgeAtAPinch) {
  // Squares [0,2]^2 and [2,4]^2 touch at (2,2): two free wedges there (NW and SE).
  Scene s({{0, 0}, {4, 4}}, {{rect({0, 0}, {2, 2}), {}}, {rect({2, 2}, {4, 4}), {}}});
  // Through the pinch from one wedge into the other: not a legal path, no answer.
  const std::vector<Point> bad{{1, 3}, {2, 2}, {3, 1}};
  ASSERT_FALSE(s.ref.check_path(bad));
  EXPECT_FALSE(s.sb.rectilinear(bad));
  EXPECT_FALSE(s.sb.octilinear(bad));
  // Into the pinch and back out in the same wedge is fine.
  const std::vector<Point> ok{{0, 3}, {2, 2}, {1, 4}};
  ASSERT_TRUE(s.ref.check_path(ok));
  const auto out = s.sb.rectilinear(ok);
  ASSERT_TRUE(out);
  check_output(s.ref, ok, *out, StaircaseStyle::Rectilinear);
  // A start point inside an obstacle is refused.
  EXPECT_FALSE(s.sb.rectilinear(std::vector<Point>{{1, 1}, {1, 3}}));
  EXPECT_FALSE(s.sb.is_free({1, 1}));
  EXPECT_TRUE(s.sb.is_free({2, 2}));
  EXPECT_TRUE(s.sb.is_free({0, 4}));
}

TEST(Staircase, JointsChooseDirectionsToSaveBends) {
  // Two links, each an L at best: (0,0)->(5,2)->(10,4). Arriving at (5,2) moving east and
  // leaving east joins without a bend: N, E, N = 2 bends in all (not 3).
  Scene s({{0, 0}, {10, 10}}, {});
  const std::vector<Point> in{{0, 0}, {5, 2}, {10, 4}};
  const auto out = s.sb.rectilinear(in);
  ASSERT_TRUE(out);
  EXPECT_EQ(count_bends(*out), 2) << str(*out);
  check_output(s.ref, in, *out, StaircaseStyle::Rectilinear);
  const auto oct = s.sb.octilinear(in);
  ASSERT_TRUE(oct);
  EXPECT_EQ(count_bends(*oct), 2) << str(*oct);
  check_output(s.ref, in, *oct, StaircaseStyle::Octilinear);
}

TEST(Staircase, FlushWithTheDomainSideIsNotFree) {
  // An obstacle lying flush on the bottom side: the stretch under it is not free, so the
  // staircase from (0,0) to (6,3) must go up first.
  Scene s({{0, 0}, {6, 6}}, {{rect({2, 0}, {4, 1}), {}}});
  const std::vector<Point> in{{0, 0}, {6, 3}};
  ASSERT_TRUE(s.ref.check_path(in));
  const auto out = s.sb.rectilinear(in);
  ASSERT_TRUE(out);
  check_output(s.ref, in, *out, StaircaseStyle::Rectilinear);
  EXPECT_EQ(count_bends(*out), 1) << str(*out);  // N then E... then N? (0,0)-(0,3)-(6,3)
  EXPECT_EQ((*out)[1], (Point{0, 3}));
}

TEST(Staircase, HugeCoordinates) {
  // The Z scene scaled by 2^26 and shifted to negative coordinates near -2^30.
  const int k = 1 << 26, off = -(1 << 30) + 1;
  auto P = [&](int x, int y) { return Point{off + x * k, off + y * k}; };
  Scene s({P(0, 0), P(10, 10)}, {{rect(P(0, 6), P(4, 10)), {}}, {rect(P(6, 0), P(10, 4)), {}}});
  const std::vector<Point> in{P(0, 0), P(10, 10)};
  const auto out = s.sb.rectilinear(in);
  ASSERT_TRUE(out);
  EXPECT_EQ(count_bends(*out), 2);
  check_output(s.ref, in, *out, StaircaseStyle::Rectilinear);
  const auto oct = s.sb.octilinear(in);
  ASSERT_TRUE(oct);
  check_output(s.ref, in, *oct, StaircaseStyle::Octilinear);
  // A sloped obstacle far out: a triangle hugging the diagonal.
  Scene t({P(0, 0), P(15, 15)}, {{{P(1, 0), P(15, 0), P(15, 14)}, {}}, {{P(0, 2), P(13, 15), P(0, 15)}, {}}});
  const std::vector<Point> diag{P(0, 0), P(15, 15)};
  ASSERT_TRUE(t.ref.check_path(diag));
  const auto o2 = t.sb.rectilinear(diag);
  ASSERT_TRUE(o2);
  check_output(t.ref, diag, *o2, StaircaseStyle::Rectilinear);
}

// A lattice set's wide cone at the coordinate limit: in c:0,45 a piece going up (between NE and
// W) from near the domain's bottom-right corner to near its top-right one. Its frame box reaches
// x = 3M, past the int32 range (frame_box keeps the R-tree query inside the domain); the
// staircase has three links (the west side is a wall the W run stops at), every point free, in
// the set, of the set's length.
TEST(Staircase, WideConeAtTheCoordinateLimit) {
  const int M = taut::geom::kMaxCoord;
  // a square above the NE diagonal, outside the region between the staircase and the segment
  Scene s({{-M, -M}, {M, M}}, {{rect({-M / 2 - 10, M / 2 - 10}, {-M / 2 + 10, M / 2 + 10}), {}}});
  const std::vector<Point> taut{{M - 1, -M + 1}, {M - 3, M - 1}};
  ASSERT_TRUE(s.ref.check_path(taut));
  const auto set = *taut::geom::LatticeDirections::parse("c:0,45");
  const std::vector<std::size_t> cuts{0, 1};
  const auto out = s.sb.staircase_in_class(taut, cuts, set);
  ASSERT_TRUE(out);
  // three links either way round: W, NE, W or (as built) NE one step to the east side, W, NE
  ASSERT_EQ(out->size(), 4u);
  EXPECT_EQ(out->front(), taut.front());
  EXPECT_EQ(out->back(), taut.back());
  for (std::size_t i = 1; i < out->size(); ++i)
    EXPECT_TRUE(set.along(std::int64_t{(*out)[i].x} - (*out)[i - 1].x, std::int64_t{(*out)[i].y} - (*out)[i - 1].y));
  EXPECT_TRUE(s.ref.check_path(*out));
  EXPECT_EQ(set.length2(*out), set.length2(taut));
}

// The first failure of the lattice-set test (seed 1, kind 0, c:45,90): a piece along the domain's
// bottom side, from (3,0) to (1,0), lies between N and SW; its SW-first staircase leaves the
// domain at once, and the N-first one is stopped by the sloped edge above (at y = 1.5 over x = 3):
// N, SW, N, SW with three bends, the exhaustive search's count. Without the domain's sides as
// walls the SW run went to y = -1 and no wire was found.
TEST(Staircase, LatticeSetPieceAlongTheDomainSide) {
  Scene s({{0, 0}, {9, 9}}, {{{{0, 1}, {6, 2}, {8, 8}, {6, 7}, {7, 9}, {3, 6}, {1, 4}, {1, 3}}, {}}});
  const std::vector<Point> taut{{3, 0}, {1, 0}};
  const std::vector<std::size_t> cuts{0, 1};
  const auto out = s.sb.staircase_in_class(taut, cuts, *taut::geom::LatticeDirections::parse("c:45,90"));
  ASSERT_TRUE(out);
  EXPECT_EQ(*out, (std::vector<Point>{{3, 0}, {3, 1}, {2, 0}, {2, 1}, {1, 0}}));
  EXPECT_TRUE(s.ref.check_path(*out));
}

// ---------------------------------------------------------------------------------------------
// Random layouts against the lattice reference.

TEST(Staircase, RandomSmallLayoutsMatchLatticeReference) {
  const auto t0 = std::chrono::steady_clock::now();
  Counters c;
  const unsigned base = 51000;
  // Under the sanitizers an eighth of the layouts (support/sanitized.h); the thresholds scale with them.
  const auto share = [](std::int64_t n) { return taut::test::sanitized_share(n, 4); };
  for (unsigned it = 0; it < share(300); ++it) {
    const unsigned seed = base + it;
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const int g = uni(1, 3);
    const Box dom{{0, 0}, {g * uni(4, 30 / g), g * uni(4, 30 / g)}};
    const auto in = random_layout(rng, dom, g, uni(0, 6), uni(0, 5));
    run_layout(seed, dom, in, 8, true, c);
    if (::testing::Test::HasFatalFailure()) return;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("small: %d layouts, %d path runs (both styles), %d links, %d link tables vs "
              "reference, %d joints at pinches, %d runs without integer staircase, %d bends in %d "
              "runs; tiny budget: %d found, %d fallback links; %.2f s\n",
              c.layouts, c.paths, c.links, c.tables, c.pinch_joints, c.none, c.bends,
              c.paths_with_bends, c.tiny_found, c.tiny_greedy, secs);
  EXPECT_GT(c.tables, share(3000));
  EXPECT_GT(c.tiny_greedy, share(100));
}

// Longer lines (coordinates up to 60, more shapes): fewer instances, same exact comparison.
TEST(Staircase, RandomMediumLayoutsMatchLatticeReference) {
  const auto t0 = std::chrono::steady_clock::now();
  Counters c;
  const unsigned base = 63000;
  for (unsigned it = 0; it < 40; ++it) {
    const unsigned seed = base + it;
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const int g = uni(1, 4);
    const Box dom{{0, 0}, {g * uni(30 / g, 60 / g), g * uni(30 / g, 60 / g)}};
    const auto in = random_layout(rng, dom, g, uni(4, 14), uni(2, 10));
    run_layout(seed, dom, in, 10, true, c);
    if (::testing::Test::HasFatalFailure()) return;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("medium: %d layouts, %d path runs (both styles), %d links, %d link tables vs "
              "reference, %d joints at pinches, %d runs without integer staircase, %d bends; "
              "%.2f s\n",
              c.layouts, c.paths, c.links, c.tables, c.pinch_joints, c.none, c.bends, secs);
  EXPECT_GT(c.tables, 1000);
}

// Checkerboards with holes: squares touching at corners everywhere, so shortest paths run
// through pinch points and the joints must keep to one wedge.
TEST(Staircase, PinchRichLayoutsMatchLatticeReference) {
  Counters c;
  for (unsigned it = 0; it < 60; ++it) {
    const unsigned seed = 88000 + it;
    std::mt19937 rng(seed);
    const int g = 2 + static_cast<int>(rng() % 2), n = 6 + static_cast<int>(rng() % 4);
    const Box dom{{0, 0}, {g * n, g * n}};
    std::vector<Polygon> in;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if ((i + j) % 2 == 0 && rng() % 100 < 55)
          in.push_back({rect({g * i, g * j}, {g * i + g, g * j + g}), {}});
    run_layout(seed, dom, in, 10, true, c);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf("pinch-rich: %d layouts, %d path runs, %d links, %d joints at pinches, %d runs "
              "without integer staircase\n",
              c.layouts, c.paths, c.links, c.pinch_joints, c.none);
  EXPECT_GT(c.pinch_joints, 100);
}

TEST(Staircase, RandomLargerLayoutsAreValid) {
  const auto t0 = std::chrono::steady_clock::now();
  Counters c;
  const unsigned base = 77000;
  for (unsigned it = 0; it < 12; ++it) {
    const unsigned seed = base + it;
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const int g = uni(0, 1) ? 1 : 10;
    const Box dom{{-200, -100}, {400, 500}};
    const auto in = random_layout(rng, dom, g, uni(10, 30), uni(5, 20));
    run_layout(seed, dom, in, 16, false, c);
    if (::testing::Test::HasFatalFailure()) return;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("larger: %d layouts, %d path runs (both styles), %d links, %d runs without "
              "integer staircase, %d bends, %.2f s\n",
              c.layouts, c.paths, c.links, c.none, c.bends, secs);
  EXPECT_GT(c.paths, 100);
}

}  // namespace staircase_test
