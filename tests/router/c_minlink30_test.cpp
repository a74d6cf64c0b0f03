// router::CMinLinker in the sets at multiples of 30 degrees (Hershberger & Snoeyink section 6.3;
// CMinLinker::path with a geom::Root3Directions), against references that share only geom's
// types with it and compute in their own Q(sqrt3) (oracle/qroot3.h):
//   - every path is a path of the class in the set's directions: each link runs exactly along an
//     orientation of the set (the unit vectors are written out here), lies in free space
//     (oracle::segment_free in Q(sqrt3)), turns at a blockage vertex only inside one free wedge
//     (the L1 reference's wedges), and its reduced cut word is the sketch's
//     (oracle::HomotopyWords in Q(sqrt3));
//   - it has no more links than the shortest wire of the set with the fewest links
//     (router::Root3StaircaseBuilder, section 6.4) when that wire's exact links are free and in
//     the class (checked here the same way; it is a path of the class then);
//   - an exhaustive search (ThreeLinks below) over the paths of up to three links finds exactly
//     as many links as the path has when it has up to three, and none of three or fewer when it
//     has more. Its first link leaves p along a ray of the set, its last enters q along one, and
//     the middle link lies on a line of a third orientation through a candidate point: p, q, a
//     blockage vertex, a corner of the domain, or a point where a line through p or q meets a
//     blockage edge or a side of the domain. Why that is every minimum-link path up to three
//     links, up to sliding: a two-link path's bend is fixed by its two directions. In a three-link
//     path p X Y q, slide the middle link XY parallel to itself; X moves along p's line, Y along
//     q's, and the path stays free and in its class until the first of: a vertex touches XY
//     (also a pinch, where both blockages lie ahead, so the limit path only touches it); X or Y
//     reaches a blockage edge or a side of the domain on its line (a sloped edge crossing p's
//     line is met by the bend X first, not by the link); X or Y reaches a vertex on its line; X
//     reaches p or Y reaches q (then the path has fewer links). Sliding either way ends at one of
//     these (the domain is bounded), and each leaves XY on a line through a candidate point. The
//     limit path is in the closed free space and its bends, where at a vertex, are judged by the
//     same wedge test as the router's. So the search's count is the minimum up to three links.
//   - the shortest wire of the set (its exact links; section 6.4 claims it has the fewest links
//     among the shortest wires of the class) against the same search restricted to the paths as
//     long as it (the sum of the links' lengths, exact in Q(sqrt3)): up to three links the counts
//     are equal, above it finds none of three or fewer, and it finds no shorter path (on one
//     sketch in four among every path up to three links, else among those it visits). A
//     shortest path slid as above keeps its length (the length is linear in the slide: constant,
//     or the path is already pinned on the side that would shorten it), so the same candidates
//     hold a shortest one with the fewest links. (Mutations: the builder's greedy from one first
//     direction only, or its DP without the credit for a link continuing across a cut, each fail
//     this at once.)
// Sets at other angles (Root3Directions::parse_any, since 2026-12-07: c:0,10, c:0,45,60,
// c:22.5,90,157.5) are judged the same, except that their orientations are the set's own steps
// (tests/geom/root3_test.cpp checks them against the written angles) and, their steps differing
// in length (sqrt2, sqrt(A^2 + B^2)), the search compares lengths as sums of square roots, exactly,
// by its own squaring (ThreeLinks::sign_of; exactly in Q(sqrt3) alone in the 30-degree sets).
// Scenes: the degenerate 9x9 families of the lattice sets' test (sloped triangles, rectangles
// touching at corners and edges, octilinear shapes, T-pinches, slivers) and rectangles that may
// touch; sketches are random walks with loops appended (winding one to three times).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "geom/root3_directions.h"
#include "oracle/homotopy.h"
#include "oracle/l1_oracle.h"
#include "oracle/link_oracle.h"
#include "oracle/qroot3.h"
#include "router/c_minlink.h"
#include "router/root3_staircase.h"
#include "router/tighten.h"
#include "support/sanitized.h"
#include "support/q3_of.h"
#include "support/sketcher.h"
#include "support/taut_check.h"
#include "support/taut_scenes.h"
#include "support/wavefront_hand.h"

namespace taut::test {
namespace c_minlink30_test {

using geom::Point;
using oracle::Q3;
using oracle::Q3Point;

const char* const kSets[] = {"c:0,60,120", "c:30,90,150", "c:0,30,60,90,120,150", "c:0,60", "c:0,90,150",
                             // sets at other angles (Root3Directions::parse_any, since 2026-12-07)
                             "c:0,10", "c:0,45,60", "c:22.5,90,157.5"};

// Twice the unit vector at `deg` degrees (a multiple of 30 below 180), written out here.
Q3Point unit2(int deg) {
  const Q3 r3(0, 1);
  switch (deg) {
    case 0: return {Q3(2), Q3(0)};
    case 30: return {r3, Q3(1)};
    case 60: return {Q3(1), r3};
    case 90: return {Q3(0), Q3(2)};
    case 120: return {Q3(-1), r3};
    case 150: return {-r3, Q3(1)};
    default: throw std::logic_error("unit2: not a multiple of 30 below 180");
  }
}

// The set's orientations as vectors along them: twice the unit vectors written out above for the
// sets at multiples of 30 degrees; for a set at other angles (parse_any) the set's own steps
// (tests/geom/root3_test.cpp checks they lie within 2^-36 radians of the written angles), whose
// lengths differ, so only the first kind has lengths here.
std::vector<Q3Point> units_of(const geom::Root3Directions& set) {
  std::vector<Q3Point> u;
  if (set.mask() != 0) {
    for (const int deg : set.degrees()) u.push_back(unit2(deg));
  } else {
    for (std::size_t k = 0; k < set.steps().size() / 2; ++k) u.push_back(q3of(set.steps()[k]));
  }
  return u;
}

using oracle::cross;
using oracle::dot;
using oracle::minus;

std::string str3(const std::vector<Q3Point>& path) {
  std::string s;
  for (const Q3Point& p : path) s += "(" + p.x.str() + "," + p.y.str() + ")";
  return s;
}

// The point is an integer point: which one.
std::optional<Point> integer_point(const Q3Point& p) {
  if (sgn(p.x.b) != 0 || sgn(p.y.b) != 0 || p.x.a.get_den() != 1 || p.y.a.get_den() != 1) return std::nullopt;
  return Point{static_cast<int>(p.x.a.get_num().get_si()), static_cast<int>(p.y.a.get_num().get_si())};
}

// Angles counter-clockwise from `from`, in [0, 2 pi): is angle(v) <= angle(to)? (the wedge's own
// test, oracle::Wedge::contains, for directions in Q(sqrt3))
int half(const Q3Point& from, const Q3Point& u) {
  const int c = cross(from, u).sign();
  return (c > 0 || (c == 0 && dot(from, u).sign() > 0)) ? 0 : 1;
}
bool wedge_contains(const oracle::Wedge& w, const Q3Point& v) {
  if (w.full) return true;
  const Q3Point from{Q3(w.from_x), Q3(w.from_y)}, to{Q3(w.to_x), Q3(w.to_y)};
  const int hv = half(from, v), ht = half(from, to);
  if (hv != ht) return hv < ht;
  return cross(v, to).sign() >= 0;
}
// A bend at x from direction `in` to direction `out` keeps to one free wedge (x not a vertex:
// free all round).
bool turn_ok(const oracle::L1Reference& ref, const Q3Point& x, const Q3Point& in, const Q3Point& out) {
  const auto v = integer_point(x);
  if (!v) return true;
  const Q3Point back{-in.x, -in.y};
  for (const oracle::Wedge& w : ref.wedges_at(*v))
    if (wedge_contains(w, back) && wedge_contains(w, out)) return true;
  return false;
}

// The path is one of the class in the set's orientations; "" when it is, else what is wrong.
std::string path_problem(const std::vector<Q3Point>& path, const std::vector<Q3Point>& units, const Scene& sc,
                         const oracle::HomotopyWords& h, const oracle::L1Reference& ref, const std::vector<int>* word) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Q3Point d = minus(path[i + 1], path[i]);
    if (d.x.sign() == 0 && d.y.sign() == 0) return "link " + std::to_string(i) + " has no length";
    bool along = false;
    for (const Q3Point& u : units) along = along || cross(u, d).sign() == 0;
    if (!along) return "link " + std::to_string(i) + " is not along the set";
    if (!oracle::segment_free(path[i], path[i + 1], sc.domain, sc.obstacles))
      return "link " + std::to_string(i) + " leaves free space";
    if (i > 0 && !turn_ok(ref, path[i], minus(path[i], path[i - 1]), d))
      return "the turn at bend " + std::to_string(i) + " passes between blockages";
  }
  if (word && h.word(std::span<const Q3Point>(path)) != *word) return "another homotopy class";
  return "";
}

// Reduced concatenation of cut words.
void append(std::vector<int>& w, const std::vector<int>& tail) {
  for (int l : tail) {
    if (!w.empty() && w.back() == -l)
      w.pop_back();
    else
      w.push_back(l);
  }
}

// The exhaustive search of the top of the file, for paths of up to three links: the first link
// on a ray from p, the last on a ray into q, the middle one on a line of a third orientation
// through a blockage vertex, a corner of the domain, p, q, or a point where a line through p or
// q meets a blockage edge or a side of the domain. A segment from p (or into q) along a ray is
// free up to some point and not beyond (a prefix of a free segment is free), found by bisection
// over the candidate bends sorted along the ray.
class ThreeLinks {
 public:
  ThreeLinks(const Judged& j, const std::vector<Q3Point>& units, Point p, Point q)
      : j_(j), p_(oracle::q3(p)), q_(oracle::q3(q)), lengths_(steps_of(units)) {
    units_ = units;
    for (const geom::Polygon& o : j.sc.obstacles) boxes_.push_back(box_of(o.outer));
    std::vector<Q3Point> through{p_, q_};
    auto add_points = [&](const geom::Ring& r) {
      for (Point v : r) through.push_back(oracle::q3(v));
    };
    const geom::Box& D = j.sc.domain;
    const geom::Ring sides{D.lo, {D.hi.x, D.lo.y}, D.hi, {D.lo.x, D.hi.y}};
    add_points(sides);
    std::vector<std::pair<Q3Point, Q3Point>> edges;
    auto add_edges = [&](const geom::Ring& r) {
      for (std::size_t i = 0; i < r.size(); ++i) edges.push_back({oracle::q3(r[i]), oracle::q3(r[(i + 1) % r.size()])});
    };
    add_edges(sides);
    for (const geom::Polygon& o : j.sc.obstacles) {
      add_points(o.outer);
      add_edges(o.outer);
      for (const geom::Ring& r : o.holes) {
        add_points(r);
        add_edges(r);
      }
    }
    // where the lines through p and q meet the edges (closed segments)
    for (const Q3Point& c : {p_, q_})
      for (const Q3Point& u : units_)
        for (const auto& [e0, e1] : edges) {
          const Q3Point ed = minus(e1, e0);
          const Q3 den = cross(u, ed);
          if (den.sign() == 0) continue;  // along the line: its ends are vertices, already in
          const Q3 s = cross(minus(e0, c), u) / den;  // e0 + s ed lies on the line
          if (s < Q3(0) || s > Q3(1)) continue;
          through.push_back({e0.x + s * ed.x, e0.y + s * ed.y});
        }
    // the middle lines, one per (orientation, offset)
    std::set<std::pair<std::size_t, std::string>> seen;
    for (std::size_t o = 0; o < units_.size(); ++o)
      for (const Q3Point& c : through)
        if (seen.insert({o, cross(units_[o], c).str()}).second) middle_.push_back({o, c});
    // the rays from p and into q: (orientation, sign)
    for (std::size_t o = 0; o < units_.size(); ++o)
      for (int sg : {1, -1}) {
        const Q3Point u = sg > 0 ? units_[o] : Q3Point{-units_[o].x, -units_[o].y};
        rays_p_.push_back(reach(o, u, p_));
        rays_q_.push_back(reach(o, u, q_));  // the last link runs against u, into q
      }
  }

  struct Found {
    int fewest = -1;     // the fewest links of a path of the class, -1 when none up to three
    int fewest_at = -1;  // the fewest of one whose length is `shortest`, -1 when none
    bool shorter = false;  // a path of the class shorter than `shortest` was seen
  };
  // The paths from p to q with cut word `word` of 1 to 3 links, in increasing count: the fewest
  // links; given a `shortest` length (the sum of the links' lengths, each exactly along the set),
  // also the fewest links at that length. The slide of the top of the file keeps a shortest
  // path's length (its length is linear in the slide, so it is constant along the slide or the
  // path is already pinned on the side that would shorten it), so the candidates hold a shortest
  // path with the fewest links up to three too. It stops after the count where both are found,
  // unless `every_count` (a shorter path may have more links than the shortest wire: `shorter`
  // then covers every path up to three links; it costs the test twice its time, so it runs on one
  // sketch in four).
  // A path's length, exactly (oracle::SetLengths: a sum of square roots, compared by squaring).
  using Len = oracle::SetLengths::Len;
  bool same(const Len& a, const Len& b) const { return oracle::SetLengths::compare(a, b) == 0; }
  bool less(const Len& a, const Len& b) const { return oracle::SetLengths::compare(a, b) < 0; }
  Found search(const std::vector<int>& word, const std::optional<Len>& shortest, bool every_count = false) const {
    Found f;
    // (with `every_count`, every count up to three is searched for a shorter path)
    auto done = [&] { return f.fewest > 0 && (!shortest || (!every_count && f.fewest_at > 0)); };
    // A candidate of `links` links already known to be a path of the set with its turns in free
    // wedges: judged only when it could change the answer.
    auto take = [&](int links, const std::vector<Q3Point>& path, auto&& free_links) {
      std::optional<Len> len;
      if (shortest) len = length(path);
      const bool at = len && same(*len, *shortest) && f.fewest_at < 0, below = len && less(*len, *shortest) && !f.shorter;
      if (f.fewest > 0 && !at && !below) return;
      if (!free_links() || j_.h.word(std::span<const Q3Point>(path)) != word) return;
      if (f.fewest < 0) f.fewest = links;
      if (at) f.fewest_at = links;
      if (below) f.shorter = true;
    };
    for (const Q3Point& u : units_)
      if (cross(u, minus(q_, p_)).sign() == 0) take(1, {p_, q_}, [&] { return free(p_, q_); });
    if (done()) return f;
    // X = p + a u1 = q + b u2 with a, b > 0, within both reaches
    for (const Ray& r1 : rays_p_)
      for (const Ray& r2 : rays_q_) {
        if (r1.o == r2.o) continue;
        const auto x = meet(p_, r1.u, q_, r2.u);
        if (!x || x->first.sign() <= 0 || x->second.sign() <= 0 || x->first > r1.reach || x->second > r2.reach) continue;
        const Q3Point X = at(p_, r1.u, x->first);
        if (turn_ok(j_.ref, X, r1.u, neg(r2.u))) take(2, {p_, X, q_}, [] { return true; });
      }
    if (done()) return f;
    for (const Ray& r1 : rays_p_)
      for (const Ray& r2 : rays_q_)
        for (const auto& [o, c] : middle_) {
          if (o == r1.o || o == r2.o) continue;
          const auto x = meet(p_, r1.u, c, units_[o]), y = meet(q_, r2.u, c, units_[o]);
          if (!x || !y || x->first.sign() <= 0 || y->first.sign() <= 0 || x->first > r1.reach || y->first > r2.reach) continue;
          const Q3Point X = at(p_, r1.u, x->first), Y = at(q_, r2.u, y->first);
          if (X == Y) continue;
          const Q3Point m = minus(Y, X);
          if (!turn_ok(j_.ref, X, r1.u, m) || !turn_ok(j_.ref, Y, m, neg(r2.u))) continue;
          take(3, {p_, X, Y, q_}, [&] { return free(X, Y); });
        }
    return f;
  }
  Len length(const std::vector<Q3Point>& path) const { return lengths_.length(std::span<const Q3Point>(path)); }

 private:
  struct Ray {
    std::size_t o;
    Q3Point u;
    Q3 reach;  // the segment from the end to end + t u is free for t in [0, reach]
  };
  struct IBox {
    long lx, ly, hx, hy;
  };
  static IBox box_of(const geom::Ring& r) {
    IBox b{r[0].x, r[0].y, r[0].x, r[0].y};
    for (Point v : r) b = {std::min<long>(b.lx, v.x), std::min<long>(b.ly, v.y), std::max<long>(b.hx, v.x), std::max<long>(b.hy, v.y)};
    return b;
  }
  static Q3Point neg(const Q3Point& u) { return {-u.x, -u.y}; }
  static Q3Point at(const Q3Point& c, const Q3Point& u, const Q3& t) { return {c.x + t * u.x, c.y + t * u.y}; }
  // a + s u = b + t v: (s, t); nullopt when parallel
  static std::optional<std::pair<Q3, Q3>> meet(const Q3Point& a, const Q3Point& u, const Q3Point& b, const Q3Point& v) {
    const Q3 den = cross(u, v);
    if (den.sign() == 0) return std::nullopt;
    const Q3Point d = minus(b, a);
    return std::pair<Q3, Q3>{cross(d, v) / den, cross(d, u) / den};
  }
  // oracle::segment_free on the blockages whose boxes meet the segment's (the others cannot meet it)
  bool free(const Q3Point& a, const Q3Point& b) const {
    const Q3 lx = std::min(a.x, b.x), hx = std::max(a.x, b.x), ly = std::min(a.y, b.y), hy = std::max(a.y, b.y);
    std::vector<geom::Polygon> near;
    for (std::size_t k = 0; k < boxes_.size(); ++k) {
      const IBox& bx = boxes_[k];
      if (hx < Q3(bx.lx) || lx > Q3(bx.hx) || hy < Q3(bx.ly) || ly > Q3(bx.hy)) continue;
      near.push_back(j_.sc.obstacles[k]);
    }
    return oracle::segment_free(a, b, j_.sc.domain, near);
  }
  // How far the ray from c along u stays free, up to the last candidate bend on it (the meets
  // with every middle line and every ray from the other end), by bisection.
  Ray reach(std::size_t o, const Q3Point& u, const Q3Point& c) const {
    std::vector<Q3> ts;
    for (const auto& [o2, c2] : middle_)
      if (o2 != o)
        if (const auto x = meet(c, u, c2, units_[o2]); x && x->first.sign() > 0) ts.push_back(x->first);
    for (const Q3Point& e : {p_, q_})
      if (cross(u, minus(e, c)).sign() == 0 && dot(u, minus(e, c)).sign() > 0) ts.push_back(dot(u, minus(e, c)) / dot(u, u));
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    // the last index whose point is reached freely
    std::size_t lo = 0, hi = ts.size();  // ts[0 .. lo) are reached; ts[hi ..) are not
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (free(c, at(c, u, ts[mid]))) lo = mid + 1;
      else hi = mid;
    }
    return {o, u, lo == 0 ? Q3(0) : ts[lo - 1]};
  }

  const Judged& j_;
  Q3Point p_, q_;
  oracle::SetLengths lengths_;
  // the units and their opposites, counter-clockwise (the units run from 0 to below 180 degrees)
  static std::vector<Q3Point> steps_of(const std::vector<Q3Point>& units) {
    std::vector<Q3Point> all = units;
    for (const Q3Point& u : units) all.push_back({-u.x, -u.y});
    return all;
  }
  std::vector<Q3Point> units_;
  std::vector<IBox> boxes_;
  std::vector<std::pair<std::size_t, Q3Point>> middle_;
  std::vector<Ray> rays_p_, rays_q_;
};

struct Totals {
  long long paths = 0, none = 0, links = 0, irrational_bends = 0, sweeps = 0, staircases = 0, staircase_free = 0,
            fewer_than_staircase = 0, searched = 0, searched_more = 0, shortest_searched = 0, shortest_searched_more = 0,
            every_count = 0;
};

// One sketch's taut path in every set, judged as at the top of the file.
void judge_sketch(const Judged& j, const Path& sketch, const Path& taut, const std::string& where, Totals& tot,
                  bool search) {
  const router::CMinLinker cm(j.st.t);
  const router::Root3StaircaseBuilder builder(j.sc.domain, j.sc.obstacles);
  const std::vector<int> word = j.h.word(sketch);
  for (const char* name : kSets) {
    const auto set = geom::Root3Directions::parse_any(name);
    ASSERT_TRUE(set) << name;
    const std::vector<Q3Point> degrees = units_of(*set);
    const std::string at = where + " " + name + " taut " + str(taut);
    router::CMinLinkPath3 c;
    try {
      c = cm.path(taut, *set);
    } catch (const std::exception& e) {
      ADD_FAILURE() << at << ": " << e.what();
      continue;
    }
    if (!c.ok()) {
      ++tot.none;
      if (search) {
        EXPECT_EQ(ThreeLinks(j, degrees, sketch.front(), sketch.back()).search(word, std::nullopt).fewest, -1)
            << at << ": no path (" << c.why << "), but the search finds one";
      }
      continue;
    }
    ++tot.paths;
    tot.sweeps += static_cast<long long>(c.sweeps);
    const int links = static_cast<int>(c.links());
    tot.links += links;
    std::vector<Q3Point> path;
    for (const router::R3Point& x : c.points) path.push_back(q3of(x));
    for (const Q3Point& x : path) tot.irrational_bends += sgn(x.x.b) != 0 || sgn(x.y.b) != 0;
    EXPECT_EQ(path_problem(path, degrees, j.sc, j.h, j.ref, &word), "") << at << " path " << str3(path);
    EXPECT_TRUE(path.front() == oracle::q3(sketch.front()) && path.back() == oracle::q3(sketch.back())) << at;
    // the shortest wire of the set with the fewest links, when its exact links are a path of the class
    const router::Root3Wire sw =
        builder.staircase(taut, *set, [&](Point a, Point b) { return j.st.tight->free(a, b); });
    std::vector<Q3Point> ex;  // the shortest wire's exact links, when they are a path of the class
    if (sw.ok()) {
      ++tot.staircases;
      for (const router::R3Point& x : sw.exact) ex.push_back(q3of(x));
      if (ex.size() >= 2 && path_problem(ex, degrees, j.sc, j.h, j.ref, &word).empty()) {
        ++tot.staircase_free;
        const int sl = static_cast<int>(ex.size()) - 1;
        EXPECT_LE(links, sl) << at << " path " << str3(path) << " staircase " << str3(ex);
        tot.fewer_than_staircase += links < sl;
      } else {
        ex.clear();
      }
    }
    if (search) {
      const ThreeLinks three(j, degrees, sketch.front(), sketch.back());
      const bool lengths = !ex.empty();
      const bool every_count = tot.searched % 4 == 0;  // (one in four: see ThreeLinks::search)
      tot.every_count += every_count && lengths;
      const auto f = three.search(word, lengths ? std::optional<ThreeLinks::Len>(three.length(ex)) : std::nullopt, every_count);
      // up to three links the search's count is the minimum; above, it must find none
      if (links <= 3) {
        ++tot.searched;
        EXPECT_EQ(f.fewest, links) << at << ": the search's fewest (-1: none) against the path " << str3(path);
      } else {
        ++tot.searched_more;
        EXPECT_EQ(f.fewest, -1) << at << ": the search finds " << f.fewest << " links against the path " << str3(path);
      }
      // the same for the shortest wire among the paths as long as it; none is shorter
      if (lengths) {
        const int sl = static_cast<int>(ex.size()) - 1;
        if (sl <= 3) {
          ++tot.shortest_searched;
          EXPECT_EQ(f.fewest_at, sl) << at << ": the search's fewest at the shortest wire's length (-1: none) "
                                     << "against the shortest wire " << str3(ex);
        } else {
          ++tot.shortest_searched_more;
          EXPECT_EQ(f.fewest_at, -1) << at << ": the search finds " << f.fewest_at
                                     << " links at the shortest wire's length against " << str3(ex);
        }
        EXPECT_FALSE(f.shorter) << at << ": the search finds a path shorter than the shortest wire " << str3(ex)
                                << (every_count ? " (every count searched)" : "");
      }
    }
  }
}

TEST(CMinLink30, RandomSketchesAgainstTheReferences) {
  Totals tot;
  long long sketches = 0;
  const long long scenes = for_each_small_scene(
      static_cast<int>(sanitized_share(12, 6)), 9, 131, 7919,
      [&](int seed, int kind, const Judged& j, const Path& pts, std::mt19937_64& rng64) {
        Sketcher sk{j.ref, j.h, pts, rng64};
        for (int t = 0; t < 3; ++t) {
          const auto ts = taut_sketch(sk, *j.st.tight, 2 + static_cast<int>(rng64() % 4), t == 2);
          if (!ts) continue;
          ++sketches;
          const std::string where = "seed " + std::to_string(seed) + " kind " + std::to_string(kind) + " sketch " +
                                    str(ts->sketch);
          judge_sketch(j, ts->sketch, ts->taut.points, where, tot, true);
        }
      });
  std::printf("%lld scenes, %lld sketches: %lld minimum-link paths in the sets (%lld links, "
              "%lld bends off Q, %lld sweeps), %lld with no path; shortest wires %lld, free and in the class %lld, "
              "with more links %lld; exhaustive search on %lld with up to three links, none fewer on %lld with more; on the "
              "shortest wires, %lld with up to three links, none fewer on %lld with more, none shorter up to three links on %lld\n",
              scenes, sketches, tot.paths, tot.links, tot.irrational_bends, tot.sweeps, tot.none, tot.staircases,
              tot.staircase_free, tot.fewer_than_staircase, tot.searched, tot.searched_more, tot.shortest_searched,
              tot.shortest_searched_more, tot.every_count);
  EXPECT_GE(tot.paths, kSanitized ? 50 : 1600);  // 1,716 here
  EXPECT_GE(tot.searched, kSanitized ? 40 : 1250);  // 1,310 here
  EXPECT_GE(tot.searched_more, kSanitized ? 1 : 350);  // 406 here
  EXPECT_GE(tot.shortest_searched, kSanitized ? 40 : 1200);  // 1,289 here
  EXPECT_GE(tot.shortest_searched_more, kSanitized ? 1 : 350);  // 427 here
  EXPECT_GE(tot.every_count, kSanitized ? 10 : 350);  // 410 here
  // the shortest wire's exact links are a path of the class every time (so the bound above is
  // never skipped)
  EXPECT_EQ(tot.staircase_free, tot.staircases);
  EXPECT_GE(tot.staircases, kSanitized ? 50 : 1600);  // 1,716 here
}

// Loops in these sets (CMinLinker::loop), judged as the lattice sets' are (c_minlink_test.cpp):
// closed, every link along the set in free space, every turn (the closing one too) in one free
// wedge, the cyclically reduced cut word the input's up to rotation (freely homotopic). Its lower
// bound and `minimal` are the router's own (it throws below the bound and sets minimal at it), so
// they are not restated here; only the hand cases check minimal counts. No search for loops with
// fewer links here (the lattice sets have one).
struct LoopTotals {
  long long loops = 0, none = 0, minimal = 0, starts = 0;
};

router::CMinLinkLoop3 judge_loop(const Judged& j, const Path& taut, const std::vector<int>& cyclic, const char* name,
                                 const std::string& where, LoopTotals& tot) {
  const auto set = geom::Root3Directions::parse_any(name);
  const router::CMinLinkLoop3 c = router::CMinLinker(j.st.t).loop(taut, *set);
  tot.starts += static_cast<long long>(c.starts);
  std::vector<Q3Point> q;
  for (const router::R3Point& x : c.points) q.push_back(q3of(x));
  const std::string at = where + " " + name + " taut " + str(taut) + " loop " + str3(q) + (c.minimal ? " (minimal)" : "") +
                         " at least " + std::to_string(c.at_least);
  if (!c.ok()) {
    ++tot.none;
    return c;
  }
  ++tot.loops;
  tot.minimal += c.minimal;
  EXPECT_GE(q.size(), 4u) << at;
  if (q.size() < 4) return c;
  EXPECT_TRUE(q.front() == q.back()) << at << ": not closed";
  std::vector<Q3Point> wrapped = q;
  wrapped.push_back(q[1]);  // the closing turn as an interior bend
  EXPECT_EQ(path_problem(wrapped, units_of(*set), j.sc, j.h, j.ref, nullptr), "") << at;
  EXPECT_TRUE(same_up_to_rotation(cyclic_word(j.h.word(std::span<const Q3Point>(q))), cyclic))
      << at << ": another free homotopy class";
  return c;
}

// Round a square: an equilateral triangle in c:0,60,120 and in c:30,90,150 (three links, no
// fewer wind round anything), a parallelogram in c:0,60 (two orientations: an even count).
TEST(CMinLink30Loop, HandCases) {
  const SquareLoop sq = square_loop();
  ASSERT_TRUE(sq.ok());
  const auto& [j, once, l, cyc] = sq;
  LoopTotals tot;
  for (const auto& [name, links] : std::vector<std::pair<const char*, std::size_t>>{
           {"c:0,60,120", 3}, {"c:30,90,150", 3}, {"c:0,30,60,90,120,150", 3}, {"c:0,60", 4}, {"c:0,90,150", 3}}) {
    const router::CMinLinkLoop3 c = judge_loop(*j, l.points, cyc, name, name, tot);
    EXPECT_EQ(c.links(), links) << name;
    EXPECT_TRUE(c.minimal) << name;
  }
  EXPECT_EQ(tot.none, 0);
}

TEST(CMinLink30Loop, RandomLoopsAgainstTheReferences) {
  LoopTotals tot;
  long long taut_loops = 0;
  const long long scenes = for_each_random_loop(
      static_cast<int>(sanitized_share(12, 12)), 4,
      [&](const Judged& j, const Path&, int, const TautLoop& tl, const std::vector<int>& cyc, const std::string& where) {
        ++taut_loops;
        for (const char* name : kSets) judge_loop(j, tl.taut.points, cyc, name, where, tot);
      });
  std::printf("%lld scenes, %lld loops not contractible: %lld loops in the sets (%lld minimal; "
              "%lld starts), %lld with none\n",
              scenes, taut_loops, tot.loops, tot.minimal, tot.starts, tot.none);
  EXPECT_GE(tot.loops, kSanitized ? 10 : 300);  // 336 here
  EXPECT_EQ(tot.none, 0);
}

}  // namespace c_minlink30_test
}  // namespace taut::test
