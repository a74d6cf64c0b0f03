#include "router/minlink.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace taut::router {

namespace {

using geom::Point;
using Z = boost::multiprecision::mpz_int;

struct ZVec {
  Z x, y;
};
ZVec zvec(Point a, Point b) { return {Z(b.x) - a.x, Z(b.y) - a.y}; }  // b - a
Z cross(const ZVec& a, const ZVec& b) { return a.x * b.y - a.y * b.x; }
Z dot(const ZVec& a, const ZVec& b) { return a.x * b.x + a.y * b.y; }
int sgn(const Z& z) { return z.sign(); }
int sgn(const Rational& q) { return q.sign(); }

RPoint rp(Point p) { return {Rational(p.x), Rational(p.y)}; }
Rational rcross(const Rational& ax, const Rational& ay, const Rational& bx, const Rational& by) { return ax * by - ay * bx; }
// orientation of c relative to the directed line a -> b, for rational points
int orient(const RPoint& a, const RPoint& b, const RPoint& c) {
  return sgn(rcross(b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y));
}

// The smallest integer vector with the direction of a rational one.
ZVec integer_direction(const Rational& dx, const Rational& dy) {
  using boost::multiprecision::denominator;
  using boost::multiprecision::numerator;
  const Z l = boost::multiprecision::lcm(denominator(dx), denominator(dy));
  Z x = numerator(dx) * (l / denominator(dx)), y = numerator(dy) * (l / denominator(dy));
  const Z g = boost::multiprecision::gcd(x, y);
  if (g != 0) {
    x /= g;
    y /= g;
  }
  return {x, y};
}

// Angles measured counter-clockwise from `from`, in [0, 2 pi): is angle(u) <= angle(v)?
int half(const ZVec& from, const ZVec& u) {
  const int c = sgn(cross(from, u));
  return (c > 0 || (c == 0 && sgn(dot(from, u)) > 0)) ? 0 : 1;
}
bool angle_le(const ZVec& from, const ZVec& u, const ZVec& v) {
  const int hu = half(from, u), hv = half(from, v);
  if (hu != hv) return hu < hv;
  return sgn(cross(u, v)) >= 0;
}
ZVec neg(const ZVec& v) { return {-v.x, -v.y}; }

// A free fan at a vertex: the closed counter-clockwise sector from `start` to `end` (directions
// of its bounding edges), and its triangles in that order.
struct Fan {
  ZVec start, end;
  std::vector<std::int32_t> tris;
  bool contains(const ZVec& d) const { return angle_le(start, d, end); }
  // The open half-plane of directions counter-clockwise from d to -d lies inside the fan.
  bool holds_half_ccw_of(const ZVec& d) const {
    const ZVec m = neg(d);
    return contains(d) && contains(m) && angle_le(start, d, m);
  }
};

int corner(const geom::FreeTriangle& tr, std::int32_t w) {
  for (int i = 0; i < 3; ++i)
    if (tr.v[static_cast<std::size_t>(i)] == w) return i;
  throw std::logic_error("MinLinker: triangle without the vertex");
}

}  // namespace

struct MinLinker::Sweep {
  const MinLinker& m;
  const geom::FreeSpaceTriangulation& t;
  const std::vector<Point>& verts;
  std::span<const Point> alpha;
  std::vector<std::int32_t> ids;  // triangulation vertex of each inner vertex of alpha
  std::map<std::size_t, std::vector<std::int32_t>> chain_cands;  // by chain segment / vertex

  Point P(std::int32_t v) const { return verts[static_cast<std::size_t>(v)]; }
  const geom::FreeTriangle& T(std::int32_t i) const { return t.triangles()[static_cast<std::size_t>(i)]; }

  // The free fan at w that holds triangle `tri` (which has w as a corner).
  Fan fan(std::int32_t w, std::int32_t tri) const {
    const Point pw = P(w);
    // back (clockwise) to the fan's first triangle: across edge w -> A
    std::int32_t cur = tri;
    for (std::size_t guard = 0;; ++guard) {
      const auto& tr = T(cur);
      const int i = corner(tr, w);
      const std::int32_t nb = tr.neighbor[static_cast<std::size_t>(i)];
      if (nb < 0 || tr.constraint[static_cast<std::size_t>(i)] != geom::kUnconstrained) break;
      cur = nb;
      if (cur == tri || guard > t.triangles().size()) throw std::logic_error("MinLinker: a vertex with a full free fan");
    }
    Fan f;
    {
      const auto& tr = T(cur);
      const int i = corner(tr, w);
      f.start = zvec(pw, P(tr.v[static_cast<std::size_t>((i + 1) % 3)]));
    }
    for (;;) {
      f.tris.push_back(cur);
      const auto& tr = T(cur);
      const int i = corner(tr, w);
      const std::size_t e = static_cast<std::size_t>((i + 2) % 3);  // edge B -> w
      if (tr.neighbor[e] < 0 || tr.constraint[e] != geom::kUnconstrained) {
        f.end = zvec(pw, P(tr.v[e]));
        break;
      }
      cur = tr.neighbor[e];
    }
    return f;
  }

  std::vector<Fan> fans(std::int32_t w) const {
    std::vector<Fan> out;
    for (std::int32_t k = m.fan_start_[static_cast<std::size_t>(w)]; k < m.fan_start_[static_cast<std::size_t>(w) + 1]; ++k) {
      const std::int32_t tri = m.fan_[static_cast<std::size_t>(k)];
      bool seen = false;
      for (const Fan& f : out) seen = seen || std::find(f.tris.begin(), f.tris.end(), tri) != f.tris.end();
      if (!seen) out.push_back(fan(w, tri));
    }
    return out;
  }

  void add_neighbours(std::int32_t w, std::vector<std::int32_t>& out) const {
    for (std::int32_t k = m.fan_start_[static_cast<std::size_t>(w)]; k < m.fan_start_[static_cast<std::size_t>(w) + 1]; ++k)
      for (std::int32_t v : T(m.fan_[static_cast<std::size_t>(k)]).v) out.push_back(v);
  }

  // A walk from vertex c0 along direction d through the triangles. Ray mode (end < 0): until
  // the ray would leave free space, or passes a vertex whose obstacle reaches into the open half
  // plane on side sigma of d (a graze on the swept side). Segment mode: to vertex `end`, which
  // must be reached through free space. Collects the ends of the edges crossed and the vertices
  // passed with their fan neighbours.
  struct Walk {
    Rational S;                      // where the ray stopped: c0 + S d
    std::vector<std::int32_t> cands;
  };
  Walk walk(std::int32_t c0, const ZVec& d, int sigma, std::int32_t end) const {
    const Point pc = P(c0);
    Walk out;
    auto param = [&](Point x) {  // the parameter of a point on the ray's line
      const ZVec v = zvec(pc, x);
      return Rational(dot(v, d)) / Rational(dot(d, d));
    };
    auto side = [&](std::int32_t v) { return sgn(cross(d, zvec(pc, P(v)))); };
    // at a vertex
    std::int32_t w = c0, tri = -1;
    Rational s = 0;
    bool start = true;
    // in a triangle, entered through the edge (x, y)
    std::int32_t in_tri = -1, ex = -1, ey = -1;
    // Out of triangle tr through its edge e = (x, y): on into the neighbour (true), or the ray
    // stops there at a constrained edge (false, out.S set).
    auto leave = [&](const geom::FreeTriangle& tr, std::size_t e, std::int32_t x, std::int32_t y) {
      const ZVec xy = zvec(P(x), P(y));
      s = Rational(cross(zvec(pc, P(x)), xy)) / Rational(cross(d, xy));
      if (tr.neighbor[e] < 0 || tr.constraint[e] != geom::kUnconstrained) {
        if (end >= 0) throw std::logic_error("MinLinker: a chain segment leaves free space");
        out.S = s;
        return false;
      }
      out.cands.push_back(x);
      out.cands.push_back(y);
      in_tri = tr.neighbor[e];
      ex = x;
      ey = y;
      w = -1;
      return true;
    };
    for (std::size_t guard = 0; guard < 8 * t.triangles().size() + 16; ++guard) {
      if (w >= 0) {
        if (!start) {
          out.cands.push_back(w);
          add_neighbours(w, out.cands);
          if (w == end) {
            out.S = s;
            return out;
          }
        }
        // the fan the walk is in; at the start, the one holding d
        std::optional<Fan> f;
        if (tri >= 0) {
          f = fan(w, tri);
        } else {
          for (Fan& g : fans(w))
            if (g.contains(d)) f = std::move(g);
        }
        const bool go = f && f->contains(d) &&
                        (end >= 0 || start || f->holds_half_ccw_of(sigma > 0 ? d : neg(d)));
        if (!go) {
          if (end >= 0) throw std::logic_error("MinLinker: a chain segment leaves free space");
          out.S = s;
          return out;
        }
        start = false;
        bool moved = false;
        for (std::int32_t ti : f->tris) {
          const auto& tr = T(ti);
          const int i = corner(tr, w);
          const std::int32_t a = tr.v[static_cast<std::size_t>((i + 1) % 3)], b = tr.v[static_cast<std::size_t>((i + 2) % 3)];
          const ZVec va = zvec(P(w), P(a)), vb = zvec(P(w), P(b));
          const int ca = sgn(cross(va, d)), cb = sgn(cross(d, vb));
          if (ca < 0 || cb < 0) continue;
          if (ca == 0 && sgn(dot(va, d)) > 0) {
            s = param(P(a));
            w = a;
            tri = ti;
            moved = true;
            break;
          }
          if (cb == 0 && sgn(dot(vb, d)) > 0) {
            s = param(P(b));
            w = b;
            tri = ti;
            moved = true;
            break;
          }
          if (ca == 0 || cb == 0) continue;
          // strictly inside the corner: out through the edge a -> b
          if (!leave(tr, static_cast<std::size_t>((i + 1) % 3), a, b)) return out;
          moved = true;
          break;
        }
        if (!moved) throw std::logic_error("MinLinker: no triangle of the fan holds the direction");
        continue;
      }
      // inside in_tri, entered through (ex, ey)
      const auto& tr = T(in_tri);
      std::int32_t c = -1;
      for (std::int32_t v : tr.v)
        if (v != ex && v != ey) c = v;
      const int sc = side(c);
      if (sc == 0) {
        s = param(P(c));
        w = c;
        tri = in_tri;
        continue;
      }
      const std::int32_t z = side(ex) == -sc ? ex : ey;
      if (side(z) != -sc) throw std::logic_error("MinLinker: the walk lost the line");
      std::size_t e = 3;
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int32_t u = tr.v[k], v = tr.v[(k + 1) % 3];
        if ((u == c && v == z) || (u == z && v == c)) e = k;
      }
      if (!leave(tr, e, c, z)) return out;
    }
    throw std::logic_error("MinLinker: the walk does not end");
  }

  // Candidates from the chain alpha[j..jm]: its segments' walks and its vertices' neighbours.
  const std::vector<std::int32_t>& segment_cands(std::size_t i) {
    auto it = chain_cands.find(i);
    if (it != chain_cands.end()) return it->second;
    std::vector<std::int32_t> c;
    add_neighbours(ids[i], c);
    if (i + 1 < alpha.size() && ids[i + 1] >= 0) {
      Walk wk = walk(ids[i], zvec(alpha[i], alpha[i + 1]), 1, ids[i + 1]);
      c.insert(c.end(), wk.cands.begin(), wk.cands.end());
    }
    return chain_cands.emplace(i, std::move(c)).first->second;
  }

  // The sweep's tangent point seen from a: the first chain vertex after j whose successor lies
  // strictly on side sigma of a -> it (or jm).
  std::size_t tangent(const RPoint& a, std::size_t j, std::size_t jm, int sigma) const {
    for (std::size_t i = j + 1; i < jm; ++i)
      if (sigma * orient(a, rp(alpha[i]), rp(alpha[i + 1])) > 0) return i;
    return jm;
  }
};

std::vector<Point> loop_vertices(std::span<const Point> loop, const char* who) {
  if (loop.size() < 2 || loop.front() != loop.back())
    throw std::invalid_argument(std::string(who) + ": the loop is not closed");
  std::vector<Point> v;
  for (std::size_t i = 0; i + 1 < loop.size(); ++i)
    if (v.empty() || v.back() != loop[i]) v.push_back(loop[i]);
  while (v.size() > 1 && v.back() == v.front()) v.pop_back();
  if (v.size() < 3) throw std::invalid_argument(std::string(who) + ": a loop of fewer than three vertices");
  return v;
}

MinLinker::MinLinker(const geom::FreeSpaceTriangulation& t) : t_(&t) {
  geom::VertexFans f = geom::vertex_fans(t);
  fan_start_ = std::move(f.start);
  fan_ = std::move(f.triangles);
}

MinLinkPath MinLinker::path(std::span<const geom::Point> taut) const {
  MinLinkPath out;
  if (taut.empty()) return out;
  const std::size_t k = taut.size() - 1;
  if (k == 0) {
    out.points = {rp(taut[0])};
    return out;
  }
  out.points.push_back(rp(taut[0]));
  if (k == 1) {
    out.points.push_back(rp(taut[1]));
    return out;
  }
  Sweep sw{*this, *t_, t_->vertices(), taut, std::vector<std::int32_t>(taut.size(), -1), {}};
  std::vector<int> label(taut.size(), 0);
  for (std::size_t i = 1; i < k; ++i) {
    const auto it = std::lower_bound(sw.verts.begin(), sw.verts.end(), taut[i]);
    if (it == sw.verts.end() || *it != taut[i])
      throw std::invalid_argument("MinLinker: a bend of the path is not a triangulation vertex");
    sw.ids[i] = static_cast<std::int32_t>(it - sw.verts.begin());
    label[i] = sgn(cross(zvec(taut[i - 1], taut[i]), zvec(taut[i], taut[i + 1])));
    if (label[i] == 0) throw std::invalid_argument("MinLinker: the path does not turn at a bend");
  }
  auto chain_end = [&](std::size_t j) {
    std::size_t jm = j;
    while (jm + 1 < k && label[jm + 1] == label[j]) ++jm;
    return jm;
  };

  std::size_t j = 1, jm = chain_end(1);
  ZVec d = zvec(taut[0], taut[1]);
  for (std::size_t guard = 0; guard < 4 * taut.size() + 8; ++guard) {
    const int sigma = label[j];
    const Point c0 = taut[j], up = taut[jm], tp = taut[jm + 1];
    const RPoint rc0 = rp(c0);
    auto at = [&](const Rational& s) { return RPoint{rc0.x + s * Rational(d.x), rc0.y + s * Rational(d.y)}; };
    const ZVec next_dir = zvec(up, tp);
    // The link runs along the next inflection edge u' -> t': the end (t' = q, true), or the
    // next chain starts at t'.
    auto on_to_next_inflection_edge = [&] {
      if (jm + 1 == k) {
        out.points.push_back(rp(tp));
        return true;
      }
      j = jm + 1;
      jm = chain_end(j);
      d = next_dir;
      return false;
    };

    // Case 1 at once: the chain is the single vertex u' and the link bends there (or already
    // runs along the next inflection edge).
    if (j == jm) {
      if (!(sgn(cross(d, next_dir)) == 0 && sgn(dot(d, next_dir)) > 0)) out.points.push_back(rc0);
      if (on_to_next_inflection_edge()) return out;
      continue;
    }

    const Sweep::Walk ray = sw.walk(sw.ids[j], d, sigma, -1);
    const Rational& S = ray.S;

    // the events: (s, kind, chain index, new direction); kind 0 = case 1, 1 = blocker, 2 = end
    struct Event {
      Rational s;
      int kind;
      std::size_t c;
      ZVec dir;
    };
    std::optional<Event> best;
    auto offer = [&](Event e) {
      if (!best || e.s < best->s || (e.s == best->s && e.kind < best->kind)) best = std::move(e);
    };

    // case 1: the tangent becomes the line of the next inflection edge
    {
      const Z den = cross(d, next_dir);
      if (sgn(den) != 0) {
        const Rational s1 = Rational(cross(zvec(c0, up), next_dir)) / Rational(den);
        if (s1 >= 0 && s1 <= S) {
          const RPoint a1 = at(s1);
          const Rational along = (Rational(up.x) - a1.x) * Rational(next_dir.x) + (Rational(up.y) - a1.y) * Rational(next_dir.y);
          if (along > 0 && sw.tangent(a1, j, jm, sigma) == jm) offer({s1, 0, jm, next_dir});
        }
      }
    }
    // case 3: a vertex b met by the sweeping segment
    std::vector<std::int32_t> cands = ray.cands;
    for (std::size_t i = j; i <= jm; ++i) {
      const auto& c = sw.segment_cands(i);
      cands.insert(cands.end(), c.begin(), c.end());
    }
    std::sort(cands.begin(), cands.end());
    cands.erase(std::unique(cands.begin(), cands.end()), cands.end());
    for (std::int32_t bv : cands) {
      // (a vertex of the chain itself can block: a later turn of a chain that winds)
      const Point b = sw.P(bv);
      std::optional<std::vector<Fan>> b_fans;  // made when a tangent through b is found
      for (std::size_t i = j + 1; i <= jm; ++i) {
        const ZVec e = zvec(b, taut[i]);
        if (sgn(e.x) == 0 && sgn(e.y) == 0) continue;
        // a tangent from b: the chain's neighbours of c_i on side sigma (the next one strictly)
        if (i < jm && sigma * sgn(cross(e, zvec(b, taut[i + 1]))) <= 0) continue;
        if (sigma * sgn(cross(e, zvec(b, taut[i - 1]))) < 0) continue;
        const Z den = cross(d, e);
        if (sgn(den) == 0) continue;
        const Rational s = Rational(cross(zvec(c0, b), e)) / Rational(den);
        if (s < 0 || s > S) continue;
        if (best && s > best->s) continue;
        // b strictly between a and c_i: a = b + ta e with ta < 0
        const RPoint a = at(s);
        const Rational ta = e.x != 0 ? (a.x - Rational(b.x)) / Rational(e.x) : (a.y - Rational(b.y)) / Rational(e.y);
        if (ta >= 0) continue;
        // b's obstacle reaches into the unswept side (side -sigma of the segment)
        bool blocks = true;
        if (!b_fans) b_fans = sw.fans(bv);
        for (const Fan& f : *b_fans)
          if (f.contains(neg(e)) && f.contains(e) && f.holds_half_ccw_of(sigma > 0 ? neg(e) : e)) blocks = false;
        if (!blocks) continue;
        if (sw.tangent(a, j, jm, sigma) != i) continue;
        offer({s, 1, i, e});
      }
    }
    // case 2: the end of the extension
    {
      const RPoint v = at(S);
      const std::size_t i = sw.tangent(v, j, jm, sigma);
      const Point ci = taut[i];
      offer({S, 2, i, integer_direction(Rational(ci.x) - v.x, Rational(ci.y) - v.y)});
    }

    const RPoint bend = at(best->s);
    out.points.push_back(bend);
    if (best->kind == 0) {
      if (on_to_next_inflection_edge()) return out;
    } else {
      if (sgn(best->dir.x) == 0 && sgn(best->dir.y) == 0) throw std::logic_error("MinLinker: a zero link");
      j = best->c;
      d = best->dir;
    }
  }
  throw std::logic_error("MinLinker: the sweep does not end");
}

MinLinkLoop MinLinker::loop(std::span<const geom::Point> taut_loop, std::size_t max_starts) const {
  const std::vector<Point> v = loop_vertices(taut_loop, "MinLinker::loop");
  const std::size_t n = v.size();
  std::vector<int> label(n);
  for (std::size_t i = 0; i < n; ++i) {
    label[i] = sgn(cross(zvec(v[(i + n - 1) % n], v[i]), zvec(v[i], v[(i + 1) % n])));
    if (label[i] == 0) throw std::invalid_argument("MinLinker::loop: the loop does not turn at a vertex");
  }
  // From edge (v[a], v[a+1]): the path v[a], v[a+1], ..., v[a+n] = v[a], v[a+n+1] = v[a+1].
  auto from_edge = [&](std::size_t a) {
    std::vector<Point> p;
    p.reserve(n + 2);
    for (std::size_t i = 0; i <= n + 1; ++i) p.push_back(v[(a + i) % n]);
    MinLinkPath m = path(p);
    // m: v[a], the bends, v[a+1]; its first and last links lie on the edge's line, one link of
    // the loop (from the last bend on through v[a] and v[a+1] to the first bend)
    if (m.points.size() < 5) throw std::logic_error("MinLinker::loop: a loop of fewer than three links");
    MinLinkLoop l;
    l.points.assign(m.points.begin() + 1, m.points.end() - 1);
    l.points.push_back(l.points.front());
    return l;
  };
  MinLinkLoop best;
  for (std::size_t a = 0; a < n; ++a)
    if (label[a] != label[(a + 1) % n]) {
      best = from_edge(a);
      best.minimal = true;
      best.inflection = true;
      best.starts = 1;
      best.at_least = best.links();
      return best;
    }
  // Convex: the lower bound from the winding numbers round the blockages met by the loop's fans
  // (each blockage's once: the number is the same at every point inside it).
  {
    std::vector<char> seen;
    const auto& tris = t_->triangles();
    const auto& P = t_->vertices();
    std::size_t w_max = 0;
    for (const Point x : v) {
      const auto it = std::lower_bound(P.begin(), P.end(), x);
      if (it == P.end() || *it != x) throw std::invalid_argument("MinLinker::loop: a vertex is not a triangulation vertex");
      const std::size_t id = static_cast<std::size_t>(it - P.begin());
      for (std::int32_t f = fan_start_[id]; f < fan_start_[id + 1]; ++f) {
        const geom::FreeTriangle& tr = tris[static_cast<std::size_t>(fan_[static_cast<std::size_t>(f)])];
        for (std::size_t e = 0; e < 3; ++e) {
          const std::int32_t ob = tr.constraint[e];
          if (ob == geom::kUnconstrained || ob == geom::kDomainEdge || ob < 0) continue;
          if (static_cast<std::size_t>(ob) >= seen.size()) seen.resize(static_cast<std::size_t>(ob) + 1, 0);
          if (seen[static_cast<std::size_t>(ob)]) continue;
          seen[static_cast<std::size_t>(ob)] = 1;
          // the point just inside the blockage from the edge's middle m: m + eps n, n the edge's
          // right normal (the free triangle is on its left); the ray from it along n, in doubled
          // coordinates so that m is an integer point
          const Point a = P[static_cast<std::size_t>(tr.v[e])], b = P[static_cast<std::size_t>(tr.v[(e + 1) % 3])];
          const ZVec nn{Z(b.y) - a.y, Z(a.x) - b.x};
          const Z mx = Z(a.x) + b.x, my = Z(a.y) + b.y;
          auto side = [&](Point x) { return sgn(cross(nn, ZVec{2 * Z(x.x) - mx, 2 * Z(x.y) - my})) >= 0 ? 1 : -1; };
          long wind = 0;
          for (std::size_t i = 0; i < n; ++i) {
            const Point x = v[i], y = v[(i + 1) % n];
            const int sx = side(x), sy = side(y);
            if (sx == sy) continue;
            // where the edge meets the ray's line: m + t n with t = cross(x - m, y - x) / cross(n, y - x)
            const ZVec xy = zvec(x, y);
            const Z num = cross(ZVec{2 * Z(x.x) - mx, 2 * Z(x.y) - my}, xy), den = cross(nn, xy);
            if (sgn(num) * sgn(den) <= 0) continue;  // behind the point, or through m itself
            wind += sgn(den);
          }
          w_max = std::max<std::size_t>(w_max, static_cast<std::size_t>(wind < 0 ? -wind : wind));
        }
      }
    }
    best.at_least = std::max<std::size_t>(3, 2 * w_max + 1);
  }
  // The distinct edges (a loop wound w times repeats each of its edges w times), up to max_starts
  // of them spread evenly round the loop.
  std::vector<std::size_t> distinct;
  {
    std::set<std::pair<Point, Point>> seen;
    for (std::size_t a = 0; a < n; ++a)
      if (seen.insert({v[a], v[(a + 1) % n]}).second) distinct.push_back(a);
  }
  const std::size_t m = distinct.size(), tries = std::max<std::size_t>(1, std::min(m, max_starts));
  std::size_t runs = 0;
  const std::size_t at_least = best.at_least;
  for (std::size_t k = 0; k < tries && (best.points.empty() || best.links() > at_least); ++k) {
    MinLinkLoop l = from_edge(distinct[k * m / tries]);
    ++runs;
    if (best.points.empty() || l.links() < best.links()) best = std::move(l);
  }
  best.at_least = at_least;
  best.starts = runs;
  if (best.links() < best.at_least) throw std::logic_error("MinLinker::loop: fewer links than the winding allows");
  best.minimal = best.links() == best.at_least;
  return best;
}

}  // namespace taut::router
