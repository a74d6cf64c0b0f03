#include "router/root3_staircase.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include "router/tighten.h"

namespace taut::router {

namespace {

using geom::Point;
using geom::Root3;
using i64 = std::int64_t;
using R3 = RationalRoot3;
using Step = geom::Root3Directions::Step;
using FPoint = std::array<R3, 2>;  // frame coordinates (U, V)

R3Point exact_point(Point p) { return {R3(Rational(p.x)), R3(Rational(p.y))}; }

// The frame of a piece from a to b in the cone (s1, s2): (U, V) = (cross(p - a, s2), cross(s1,
// p - a)), D = cross(s1, s2) > 0, so p = a + (U s1 + V s2) / D.
struct Frame {
  Point a;
  Step s1, s2;
  R3 d;
  // (U, V) of an integer point, in Z[sqrt3] (|coefficients| < 2^34; < 2^57 with the integer
  // steps of Root3Directions::parse_any, up to 2^24)
  std::array<Root3, 2> of_int(Point p) const {
    const i64 dx = i64{p.x} - a.x, dy = i64{p.y} - a.y;
    return {geom::Root3Directions::cross(dx, dy, s2), geom::Root3Directions::cross(s1, dx, dy)};
  }
  FPoint of(Point p) const {
    const std::array<Root3, 2> f = of_int(p);
    return {R3(f[0]), R3(f[1])};
  }
  R3Point at(const FPoint& f) const {
    const R3 x = R3(Rational(a.x)) + (f[0] * R3(s1.x) + f[1] * R3(s2.x)) / d;
    const R3 y = R3(Rational(a.y)) + (f[0] * R3(s1.y) + f[1] * R3(s2.y)) / d;
    return {x, y};
  }
};

// A blockage edge (or a domain side) clipped to the piece's box, its ends in the frame, and on
// which side of the taut piece it lies (+1 above, larger V; -1 below).
struct Wall {
  FPoint c0, c1;
  int side = 0;
};

class PieceSolver {
 public:
  PieceSolver(const Frame& fr, std::span<const Point> alpha, const FPoint& lim) : lim_(lim) {
    for (const Point p : alpha) {
      const FPoint f = fr.of(p);
      a_[0].push_back(f[0]);
      a_[1].push_back(f[1]);
    }
  }

  // Clips the frame segment p q to the box and classifies it; false when nothing of it is inside.
  // `inside`: both ends are in the box (nothing to clip).
  bool add(const FPoint& p, const FPoint& q, bool inside) {
    if (inside) {
      Wall w{p, q, 0};
      w.side = side_of(w, q[0] - p[0], q[1] - p[1]);
      walls_.push_back(std::move(w));
      return true;
    }
    R3 t0(Rational(0)), t1(Rational(1));
    for (int k = 0; k < 2; ++k) {
      const R3 dq = q[k] - p[k];
      if (dq.sign() == 0) {
        if (p[k].sign() < 0 || p[k] > lim_[k]) return false;
        continue;
      }
      R3 ta = (R3() - p[k]) / dq, tb = (lim_[k] - p[k]) / dq;
      if (tb < ta) std::swap(ta, tb);
      if (t0 < ta) t0 = ta;
      if (tb < t1) t1 = tb;
    }
    if (t1 < t0) return false;
    Wall w;
    for (int k = 0; k < 2; ++k) {
      w.c0[k] = p[k] + t0 * (q[k] - p[k]);
      w.c1[k] = p[k] + t1 * (q[k] - p[k]);
    }
    w.side = side_of(w, q[0] - p[0], q[1] - p[1]);
    walls_.push_back(std::move(w));
    return true;
  }

  // The greedy staircase leaving 0 along s[first]: its frame points, or nullopt (stuck, or more
  // than cap runs).
  // `over`: set when it stopped at the cap.
  std::optional<std::vector<FPoint>> greedy(int first, std::size_t cap, bool& over) const {
    std::vector<FPoint> pts{{R3(), R3()}};
    FPoint pos{R3(), R3()};
    for (int k = first;; k = 1 - k) {
      R3 r = reach(k, pos);
      if (r <= pos[k]) return std::nullopt;
      pos[k] = std::move(r);
      pts.push_back(pos);
      if (pts.size() > cap + 1) {
        over = true;
        return std::nullopt;
      }
      if (pos[0] == lim_[0] && pos[1] == lim_[1]) return pts;
    }
  }

 private:
  // Sign of (point - alpha) in V at the point's U (0 <= X <= U(b)).
  int side_of_point(const R3& X, const R3& Y) const {
    std::size_t lo = 0, hi = a_[0].size() - 1;  // a_[0][lo] <= X, answer in [lo, hi)
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if (a_[0][mid] <= X) lo = mid;
      else hi = mid;
    }
    const R3 du = a_[0][lo + 1] - a_[0][lo], dv = a_[1][lo + 1] - a_[1][lo];
    return ((Y - a_[1][lo]) * du - (X - a_[0][lo]) * dv).sign();
  }

  // Walls do not cross alpha (it is free), so any point off alpha decides: the clipped ends, then
  // alpha's vertices between them; a wall along alpha lies on its obstacle's side (the left of
  // the edge; the frame keeps orientation, D > 0). (du, dv): the edge's direction in the frame.
  int side_of(const Wall& w, const R3& du, const R3& dv) const {
    for (const FPoint* c : {&w.c0, &w.c1})
      if (const int s = side_of_point((*c)[0], (*c)[1]); s != 0) return s;
    if (du.sign() != 0) {
      const bool c0_first = w.c0[0] < w.c1[0];
      const R3& lo = c0_first ? w.c0[0] : w.c1[0];
      const R3& hi = c0_first ? w.c1[0] : w.c0[0];
      for (std::size_t j = 0; j < a_[0].size(); ++j) {
        if (!(lo < a_[0][j]) || !(a_[0][j] < hi)) continue;
        // the wall's V at U = a_[0][j] against a_[1][j]
        const R3 v = w.c0[1] + (a_[0][j] - w.c0[0]) * (w.c1[1] - w.c0[1]) / (w.c1[0] - w.c0[0]);
        if (const int s = (v - a_[1][j]).sign(); s != 0) return s;
      }
    }
    const bool with_alpha = du.sign() > 0 || (du.sign() == 0 && dv.sign() > 0);
    return with_alpha ? 1 : -1;
  }

  // How far a run along coordinate k from pos may go because of w: the least coordinate k over
  // the closure of w's points whose other coordinate exceeds pos's (lim when there are none).
  R3 wall_reach(const Wall& w, int k, const FPoint& pos) const {
    const int o = 1 - k;
    const bool in0 = w.c0[o] > pos[o], in1 = w.c1[o] > pos[o];
    if (!in0 && !in1) return lim_[k];
    R3 e0 = w.c0[k], e1 = w.c1[k];
    if (!in0 || !in1) {  // the point where coordinate o is pos[o]
      const R3 x = w.c0[k] + (pos[o] - w.c0[o]) * (w.c1[k] - w.c0[k]) / (w.c1[o] - w.c0[o]);
      (in0 ? e1 : e0) = x;
    }
    R3 m = e0 < e1 ? e0 : e1;
    return m < lim_[k] ? m : lim_[k];
  }

  // The farthest coordinate k a run along s[k] from pos reaches: a run along s1 (U) is stopped by
  // walls below alpha that rise above pos's V, one along s2 by walls above alpha that reach right
  // of pos's U.
  R3 reach(int k, const FPoint& pos) const {
    const int want = k == 0 ? -1 : 1;
    R3 best = lim_[k];
    for (const Wall& w : walls_)
      if (w.side == want) {
        R3 r = wall_reach(w, k, pos);
        if (r < best) best = std::move(r);
      }
    return best;
  }

  FPoint lim_;
  std::array<std::vector<R3>, 2> a_;  // alpha's vertices: U and V (both strictly increasing)
  std::vector<Wall> walls_;
};

// One candidate wire of a piece: its exact points and the steps (indices into set.steps()) of its
// first and last links.
struct Candidate {
  std::vector<R3Point> pts;
  std::size_t first = 0, last = 0;
  int links() const { return static_cast<int>(pts.size()) - 1; }
};

std::int64_t nearest(const R3& v) { return (v + R3(Rational(1) / 2)).floor(); }

}  // namespace

Root3StaircaseBuilder::Root3StaircaseBuilder(const geom::Box& domain, std::span<const geom::Polygon> obstacles)
    : domain_(domain), index_(obstacles) {
  // the domain's sides, the outside on their left (clockwise round the domain)
  const Point c[4] = {{domain.lo.x, domain.lo.y}, {domain.lo.x, domain.hi.y}, {domain.hi.x, domain.hi.y},
                      {domain.hi.x, domain.lo.y}};
  for (int i = 0; i < 4; ++i) sides_.push_back({c[i], c[(i + 1) % 4]});
}

Root3Wire Root3StaircaseBuilder::staircase(std::span<const Point> taut, const geom::Root3Directions& set,
                                           const std::function<bool(Point, Point)>& free) const {
  Root3Wire out;
  if (taut.empty()) {
    out.why = "an empty wire";
    return out;
  }
  const std::vector<Step>& steps = set.steps();
  const std::vector<std::size_t> cuts = tangent_cuts(taut, set);
  std::vector<std::vector<Candidate>> pieces;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const std::span<const Point> alpha = taut.subspan(cuts[c], cuts[c + 1] - cuts[c] + 1);
    const Point a = alpha.front(), b = alpha.back();
    const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
    std::vector<Candidate> cands;
    if (const int along = alpha.size() == 2 ? set.step_along(dx, dy) : -1; along >= 0) {  // a segment along a direction of the set
      const auto s = static_cast<std::size_t>(along);
      cands.push_back({{exact_point(a), exact_point(b)}, s, s});
      pieces.push_back(std::move(cands));
      continue;
    }
    const int cone = set.cone(i64{alpha[1].x} - a.x, i64{alpha[1].y} - a.y);
    const std::size_t i1 = static_cast<std::size_t>(cone), i2 = (i1 + 1) % steps.size();
    Frame fr{a, steps[i1], steps[i2], R3()};
    fr.d = R3(steps[i1].x * steps[i2].y - steps[i1].y * steps[i2].x);
    const FPoint lim = fr.of(b);
    PieceSolver solver(fr, alpha, lim);
    // the walls: every edge whose box meets the box of the piece's parallelogram, within the
    // domain (a wide cone's parallelogram reaches out of it, past the int32 range near the
    // coordinate limit: clamped, as the lattice sets' frame_box does; every indexed edge lies in
    // the domain)
    i64 x0 = b.x, y0 = b.y, x1 = b.x, y1 = b.y;
    for (const FPoint& f : {FPoint{R3(), R3()}, FPoint{lim[0], R3()}, FPoint{R3(), lim[1]}, lim}) {
      const R3Point p = fr.at(f);
      const i64 fx = p.x.floor(), fy = p.y.floor();
      x0 = std::min(x0, fx), y0 = std::min(y0, fy), x1 = std::max(x1, fx + 1), y1 = std::max(y1, fy + 1);
    }
    auto into = [](i64 v, i64 lo, i64 hi) { return static_cast<geom::Coord>(std::clamp(v, lo, hi)); };
    const geom::Box box{{into(x0, domain_.lo.x, domain_.hi.x), into(y0, domain_.lo.y, domain_.hi.y)},
                        {into(x1, domain_.lo.x, domain_.hi.x), into(y1, domain_.lo.y, domain_.hi.y)}};
    // (an edge with both ends beyond one side of the frame's box misses it: decided in Z[sqrt3]
    // before the rationals)
    const std::array<Root3, 2> lim_int = fr.of_int(b);
    auto add = [&](const geom::Segment& e) {
      const std::array<Root3, 2> p = fr.of_int(e.a), q = fr.of_int(e.b);
      bool inside = true;
      for (int k = 0; k < 2; ++k) {
        const int p0 = p[k].sign(), q0 = q[k].sign();
        const bool p1 = p[k] > lim_int[k], q1 = q[k] > lim_int[k];
        if ((p0 < 0 && q0 < 0) || (p1 && q1)) return;
        inside = inside && p0 >= 0 && q0 >= 0 && !p1 && !q1;
      }
      solver.add({R3(p[0]), R3(p[1])}, {R3(q[0]), R3(q[1])}, inside);
    };
    for (const std::uint32_t id : index_.edges_in_box(box)) add(index_.edge(id));
    for (const geom::Segment& e : sides_) add(e);
    const std::size_t cap = max_runs_per_piece;
    bool capped = false;
    for (int f = 0; f < 2; ++f) {
      bool over = false;
      const std::optional<std::vector<FPoint>> g = solver.greedy(f, cap, over);
      capped = capped || over;
      if (!g) continue;
      Candidate cand;
      for (const FPoint& p : *g) cand.pts.push_back(fr.at(p));
      cand.pts.front() = exact_point(a);  // (equal already; exactly the ends)
      cand.pts.back() = exact_point(b);
      const int runs = static_cast<int>(g->size()) - 1;
      cand.first = f == 0 ? i1 : i2;
      cand.last = ((runs % 2 == 1) == (f == 0)) ? i1 : i2;
      cands.push_back(std::move(cand));
    }
    if (cands.empty()) {
      out.why = "no staircase in the set's directions " + set.name() + " between " + std::to_string(a.x) + "," +
                std::to_string(a.y) + " and " + std::to_string(b.x) + "," + std::to_string(b.y) +
                (capped ? " with fewer than " + std::to_string(cap + 1) +
                              " links: a blockage edge at an angle outside the set pinches the wire there (H&S 6: a "
                              "shortest wire in the set may then need infinitely many links)"
                        : " from either first direction (the greedy got stuck; not expected of a taut wire: please "
                          "report the layout)");
      return out;
    }
    pieces.push_back(std::move(cands));
  }
  if (pieces.empty()) {  // one point
    out.points = {taut.front(), taut.front()};
    out.exact = {exact_point(taut[0])};
    return out;
  }
  // DP over the pieces: the fewest links, a link continuing across a cut (the same step on both
  // sides of it: one line through the cut point) counted once
  const std::size_t m = pieces.size();
  std::vector<std::vector<int>> best(m), from(m);
  for (std::size_t i = 0; i < m; ++i) {
    best[i].assign(pieces[i].size(), std::numeric_limits<int>::max());
    from[i].assign(pieces[i].size(), -1);
    for (std::size_t c = 0; c < pieces[i].size(); ++c) {
      if (i == 0) {
        best[i][c] = pieces[i][c].links();
        continue;
      }
      for (std::size_t p = 0; p < pieces[i - 1].size(); ++p) {
        const int v = best[i - 1][p] + pieces[i][c].links() - (pieces[i - 1][p].last == pieces[i][c].first ? 1 : 0);
        if (v < best[i][c]) {
          best[i][c] = v;
          from[i][c] = static_cast<int>(p);
        }
      }
    }
  }
  std::vector<std::size_t> pick(m);
  pick[m - 1] = static_cast<std::size_t>(std::min_element(best[m - 1].begin(), best[m - 1].end()) - best[m - 1].begin());
  for (std::size_t i = m - 1; i > 0; --i) pick[i - 1] = static_cast<std::size_t>(from[i][pick[i]]);
  // The exact wire, and the same with the cut points inside a link kept (`split`): those are
  // integer points (blockage corners the taut wire wraps), which a rounded link through them
  // could cut; the split form is rounded when the merged one has no free rounding.
  std::vector<R3Point> split;
  for (std::size_t i = 0; i < m; ++i) {
    const Candidate& c = pieces[i][pick[i]];
    if (i == 0) {
      out.exact = split = c.pts;
      continue;
    }
    if (pieces[i - 1][pick[i - 1]].last == c.first) out.exact.pop_back();  // the joint is inside one link
    out.exact.insert(out.exact.end(), c.pts.begin() + 1, c.pts.end());
    split.insert(split.end(), c.pts.begin() + 1, c.pts.end());
  }
  if (!round_wire(out.exact, set, free, out) && (split.size() == out.exact.size() || !round_wire(split, set, free, out)))
    out.why = "rounded to integer vertices, every wire near the exact one in " + set.name() +
              " leaves free space (the sixteen integer points round each of its vertices tried)";
  if (out.ok() && out.points.size() == 1) out.points.push_back(out.points[0]);
  return out;
}

bool Root3StaircaseBuilder::round_wire(const std::vector<R3Point>& exact, const geom::Root3Directions& set,
                                       const std::function<bool(Point, Point)>& free, Root3Wire& out) {
  // Rounding: the nearest integer points, else the DP over the floor/ceiling points (above).
  out.moved = 0;
  const std::size_t n = exact.size();
  std::vector<std::vector<Point>> cand(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point near{static_cast<geom::Coord>(nearest(exact[i].x)), static_cast<geom::Coord>(nearest(exact[i].y))};
    cand[i].push_back(near);
    if (i == 0 || i + 1 == n) continue;  // the ends are integer points
    const i64 fx = exact[i].x.floor(), fy = exact[i].y.floor();
    for (const i64 x : {fx - 1, fx, fx + 1, fx + 2})
      for (const i64 y : {fy - 1, fy, fy + 1, fy + 2}) {
        const Point q{static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)};
        if (q == near) continue;
        cand[i].push_back(q);
      }
  }
  auto step_ok = [&](Point p, Point q) {
    return p == q || (set.fits(i64{q.x} - p.x, i64{q.y} - p.y) && free(p, q));
  };
  bool nearest_ok = true;
  for (std::size_t i = 1; i < n && nearest_ok; ++i) nearest_ok = step_ok(cand[i - 1][0], cand[i][0]);
  std::vector<std::size_t> choice(n, 0);
  if (!nearest_ok) {
    constexpr int kNone = std::numeric_limits<int>::max();
    std::vector<std::vector<int>> cost(n), prev(n);
    cost[0] = {0};
    prev[0] = {-1};
    for (std::size_t i = 1; i < n; ++i) {
      cost[i].assign(cand[i].size(), kNone);
      prev[i].assign(cand[i].size(), -1);
      for (std::size_t c = 0; c < cand[i].size(); ++c)
        for (std::size_t p = 0; p < cand[i - 1].size(); ++p) {
          if (cost[i - 1][p] == kNone) continue;
          const int v = cost[i - 1][p] + (c == 0 ? 0 : 1);
          if (v < cost[i][c] && step_ok(cand[i - 1][p], cand[i][c])) {
            cost[i][c] = v;
            prev[i][c] = static_cast<int>(p);
          }
        }
    }
    if (cost[n - 1][0] == kNone) return false;
    for (std::size_t i = n - 1; i > 0; --i) choice[i - 1] = static_cast<std::size_t>(prev[i][choice[i]]);
    out.moved = cost[n - 1][0];
  }
  out.points.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const Point q = cand[i][choice[i]];
    if (out.points.empty() || out.points.back() != q) out.points.push_back(q);
  }
  return true;
}

}  // namespace taut::router
