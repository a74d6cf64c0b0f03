#include "router/c_minlink.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "router/minlink.h"
#include "router/tighten.h"

namespace taut::router {

namespace {

using geom::Point;
using i64 = std::int64_t;
using i128 = __int128;

// Integer vectors (differences of coordinates need 32 bits and a sign; products 64).
struct V {
  i64 x, y;
};
V vec(Point from, Point to) { return {i64{to.x} - from.x, i64{to.y} - from.y}; }
i128 cross(V a, V b) { return i128{a.x} * b.y - i128{a.y} * b.x; }
i128 dot(V a, V b) { return i128{a.x} * b.x + i128{a.y} * b.y; }
int sgn(i128 v) { return (v > 0) - (v < 0); }

// The two kinds of direction set, as the algorithm below sees them. A step d of the set, an
// integer vector and their cross and dot products are exact values of `Ex`; points, ray
// parameters and offsets are numbers of the field `Num` (rationals for the lattice sets, Q(sqrt3)
// for the sets at multiples of 30 degrees, whose steps have coordinates in Z[sqrt3]).
struct LatticeKind {
  using Num = Rational;
  using P = RPoint;
  using Dir = Point;
  using Set = geom::LatticeDirections;
  using EV = V;
  using Ex = i128;
  static EV ev(Dir d) { return {d.x, d.y}; }
  static EV ev(V v) { return v; }
  static Ex cross(EV a, EV b) { return router::cross(a, b); }
  static Ex dot(EV a, EV b) { return router::dot(a, b); }
  static int sgn(Ex v) { return router::sgn(v); }
  // Every Ex below is a step (coordinates at most 1) against an integer vector: it fits in 64 bits.
  static Num num(Ex v) { return Num(static_cast<i64>(v)); }
  static Num num(i64 v) { return Num(v); }
  static Num nx(Dir d) { return Num(d.x); }
  static Num ny(Dir d) { return Num(d.y); }
  static Dir neg(Dir d) { return {-d.x, -d.y}; }
  static bool is(const Num& x, std::int32_t v) { return x == v; }
  // An integer vector along the step (so p + d is a point): the step itself here.
  static std::optional<Point> integer(Dir d) { return d; }
};

struct Root3Kind {
  using Num = RationalRoot3;
  using P = R3Point;
  using Dir = geom::Root3Directions::Step;
  using Set = geom::Root3Directions;
  struct EV {
    geom::Root3 x, y;
  };
  struct Ex {
    i128 a = 0, b = 0;  // a + b sqrt3
  };
  static EV ev(Dir d) { return {d.x, d.y}; }
  static EV ev(V v) { return {{v.x, 0}, {v.y, 0}}; }
  static Ex mul(geom::Root3 u, geom::Root3 w) {
    return {i128{u.a} * w.a + 3 * (i128{u.b} * w.b), i128{u.a} * w.b + i128{u.b} * w.a};
  }
  static Ex cross(EV p, EV q) {
    const Ex s = mul(p.x, q.y), t = mul(p.y, q.x);
    return {s.a - t.a, s.b - t.b};
  }
  static Ex dot(EV p, EV q) {
    const Ex s = mul(p.x, q.x), t = mul(p.y, q.y);
    return {s.a + t.a, s.b + t.b};
  }
  static int sgn(Ex v) { return sign_wide<3>(v.a, v.b); }
  // Every Ex below is a step (coordinates at most 2 in Z[sqrt3]; integers up to 2^24 in a set of
  // Root3Directions::parse_any) against an integer vector (below 2^32), or two steps: both parts
  // below 2^57, so they fit in 64 bits.
  static Num num(Ex v) { return Num(Rational(static_cast<i64>(v.a)), Rational(static_cast<i64>(v.b))); }
  // The number is the integer v (its sqrt3 part zero).
  static bool is(const Num& x, std::int32_t v) { return x.b.sign() == 0 && x.a == v; }
  static Num num(i64 v) { return Num(Rational(v)); }
  static Num nx(Dir d) { return Num(d.x); }
  static Num ny(Dir d) { return Num(d.y); }
  static Dir neg(Dir d) { return {-d.x, -d.y}; }
  // The least integer vector along the step when it is a unit of the lattice or a diagonal one
  // (the axis steps (+-2, 0), (0, +-2); (+-1, +-1) in a set of parse_any); nullopt for the
  // others (a step with a sqrt3 part, or a long integer step such as 10 degrees' in c:0,10).
  static std::optional<Point> integer(Dir d) {
    if (d.x.b != 0 || d.y.b != 0) return std::nullopt;
    const i64 g = std::gcd(d.x.a < 0 ? -d.x.a : d.x.a, d.y.a < 0 ? -d.y.a : d.y.a);
    const i64 x = d.x.a / g, y = d.y.a / g;
    if (x < -1 || x > 1 || y < -1 || y > 1) return std::nullopt;
    return Point{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
  }
};

// The largest integer not above v (v >= 0, below 2^63).
i64 floor_of(const Rational& v) {
  using boost::multiprecision::denominator;
  using boost::multiprecision::numerator;
  const auto fl = numerator(v) / denominator(v);
  return static_cast<i64>(fl.convert_to<long long>());
}
i64 floor_of(const RationalRoot3& v) { return v.floor(); }

// The closed interval of lambda in [lo, hi] where c0 + c1 lambda >= 0 for every constraint.
template <class Q>
struct Interval {
  Q lo, hi;
  bool empty = false;
  void at_least_zero(const Q& c0, const Q& c1) {  // c0 + c1 lambda >= 0
    if (empty) return;
    const int s = c1.sign();
    if (s == 0) {
      if (c0.sign() < 0) empty = true;
      return;
    }
    const Q t = -c0 / c1;
    if (s > 0) {
      if (t > lo) lo = t;
    } else if (t < hi) {
      hi = t;
    }
    if (lo > hi) empty = true;
  }
};

// Lifted triangles, named relative to alpha's sleeve: 0 .. K-1 are the sleeve's triangles in
// the lift the sleeve gives them; a larger id is a walk off the sleeve, interned by (the lifted
// triangle it came from, the edge it crossed), so a lifted triangle has one id however it is
// reached (the cover's dual graph is a tree).
class Cover {
 public:
  Cover(const geom::FreeSpaceTriangulation& t, const std::vector<std::int32_t>& sleeve)
      : t_(t), sleeve_(sleeve), k_(static_cast<std::int32_t>(sleeve.size())) {
    next_.assign(sleeve.size(), -1);
    prev_.assign(sleeve.size(), -1);
    for (std::size_t k = 0; k + 1 < sleeve.size(); ++k) {
      next_[k] = shared_edge(sleeve[k], sleeve[k + 1]);
      prev_[k + 1] = shared_edge(sleeve[k + 1], sleeve[k]);
    }
  }
  std::int32_t size() const { return k_; }
  std::int32_t tri(std::int32_t n) const {
    return n < k_ ? sleeve_[static_cast<std::size_t>(n)] : off_[static_cast<std::size_t>(n - k_)].tri;
  }
  // The lifted triangle across edge e of n's triangle, -1 when the edge is constrained.
  std::int32_t move(std::int32_t n, int e) {
    const std::int32_t nb = t_.triangles()[static_cast<std::size_t>(tri(n))].neighbor[static_cast<std::size_t>(e)];
    if (nb < 0) return -1;
    if (n < k_) {
      if (e == next_[static_cast<std::size_t>(n)]) return n + 1;
      if (e == prev_[static_cast<std::size_t>(n)]) return n - 1;
    } else if (e == off_[static_cast<std::size_t>(n - k_)].back) {
      return off_[static_cast<std::size_t>(n - k_)].parent;
    }
    const std::uint64_t key = (static_cast<std::uint64_t>(n) << 2) | static_cast<std::uint64_t>(e);
    const auto it = intern_.find(key);
    if (it != intern_.end()) return it->second;
    off_.push_back(Off{n, nb, shared_edge(nb, tri(n))});
    const std::int32_t id = k_ + static_cast<std::int32_t>(off_.size()) - 1;
    intern_.emplace(key, id);
    return id;
  }

 private:
  int shared_edge(std::int32_t a, std::int32_t b) const {
    const auto& tr = t_.triangles()[static_cast<std::size_t>(a)];
    for (int i = 0; i < 3; ++i)
      if (tr.neighbor[static_cast<std::size_t>(i)] == b) return i;
    throw std::logic_error("CMinLinker: sleeve triangles that are not neighbours");
  }
  struct Off {
    std::int32_t parent, tri;
    int back;  // the edge of tri leading back to parent
  };
  const geom::FreeSpaceTriangulation& t_;
  const std::vector<std::int32_t>& sleeve_;
  std::int32_t k_;
  std::vector<int> next_, prev_;
  std::vector<Off> off_;
  std::unordered_map<std::uint64_t, std::int32_t> intern_;
};

// The algorithm for one kind of set (LatticeKind or Root3Kind).
template <class G>
struct Impl {
  using Q = typename G::Num;
  using RP = typename G::P;
  using Dir = typename G::Dir;
  using EV = typename G::EV;
  using Ex = typename G::Ex;

  static Q num(i64 v) { return G::num(v); }
  static RP rp(Point p) { return {num(p.x), num(p.y)}; }
  static RP add(const RP& a, const Q& t, Dir d) { return {a.x + t * G::nx(d), a.y + t * G::ny(d)}; }
  // cross(d, x): the offset of the line through x in direction d (larger: further left of d)
  static Q off(Dir d, const RP& x) { return G::nx(d) * x.y - G::ny(d) * x.x; }
  static Ex off(Dir d, Point v) { return G::cross(G::ev(d), G::ev(V{v.x, v.y})); }
  static Q qcross(const Q& ax, const Q& ay, const Q& bx, const Q& by) { return ax * by - ay * bx; }
  static bool equal(const RP& a, Point b) { return G::is(a.x, b.x) && G::is(a.y, b.y); }
  // cross and dot of steps and integer vectors, as signs or exact values
  template <class A, class B>
  static Ex cr(A a, B b) {
    return G::cross(G::ev(a), G::ev(b));
  }
  template <class A, class B>
  static int scr(A a, B b) {
    return G::sgn(cr(a, b));
  }
  template <class A, class B>
  static int sdot(A a, B b) {
    return G::sgn(G::dot(G::ev(a), G::ev(b)));
  }
  static Q norm(Dir d) { return G::num(G::dot(G::ev(d), G::ev(d))); }

  // Angles measured counter-clockwise from `from` (an integer vector), in [0, 2 pi): is
  // angle(u) <= angle(v), for a step u and an integer vector v?
  static int half(V from, Dir u) {
    const int c = scr(from, u);
    return (c > 0 || (c == 0 && sdot(from, u) > 0)) ? 0 : 1;
  }
  static int half(V from, V u) {
    const int c = sgn(cross(from, u));
    return (c > 0 || (c == 0 && dot(from, u) > 0)) ? 0 : 1;
  }
  static bool angle_le(V from, Dir u, V v) {
    const int hu = half(from, u), hv = half(from, v);
    if (hu != hv) return hu < hv;
    return scr(u, v) >= 0;
  }

  // A ray's passage through one lifted triangle: its parameters there (point = start + lambda d).
  struct Step {
    std::int32_t node;
    Q in, out;
  };
  // A vertex a ray reaches (passing it or stopping there), from the lifted triangle `node`.
  struct Pass {
    std::int32_t vertex, node;
    Q lam;
  };
  struct Ray {
    std::vector<Step> steps;
    std::vector<Pass> passes;
    Q end;  // where it stops
  };

  // A frontier segment: the part of a maximal ray beyond the frontier's corner.
  struct Seg {
    RP start;  // the corner
    std::int32_t node = 0;  // a lifted triangle holding start
    Dir dir;
    Q len;  // it ends at start + len * dir (len may be 0)
    std::vector<Step> chain;  // the lifted triangles from start to the end
    int qside = 0;  // +1: the component holding q lies left of dir, -1: right
    RP origin;  // where the link along this segment's line starts
    std::int32_t parent = -1;  // the segment origin lies on (-1: origin is p)
  };

  // A sweep's piece: rays in direction d with offsets [lo, hi] through a lifted triangle (chain:
  // the rays start on the segment inside this triangle, so only its d side is swept).
  struct Piece {
    std::int32_t node;
    Q lo, hi;
    bool chain;
    std::int32_t from = -1;  // the lifted triangle it was reached from
  };
  struct Sweep {
    std::size_t seg;
    Dir d;
    std::vector<Piece> pieces;
    std::unordered_multimap<std::int32_t, std::size_t> by_node;
  };

  // A piece of alpha inside a lifted triangle (params: segment index + fraction).
  struct ASeg {
    RP a, b;
    Q pa, pb;
  };

  struct Work {
    const geom::FreeSpaceTriangulation& t;
    Cover& cover;
    std::size_t pieces = 0;
    std::size_t piece_limit;

    Point P(std::int32_t v) const { return t.vertices()[static_cast<std::size_t>(v)]; }
    const geom::FreeTriangle& T(std::int32_t node) const {
      return t.triangles()[static_cast<std::size_t>(cover.tri(node))];
    }
    static int corner(const geom::FreeTriangle& tr, std::int32_t w) {
      for (int i = 0; i < 3; ++i)
        if (tr.v[static_cast<std::size_t>(i)] == w) return i;
      return -1;
    }
    // The closed corner of node's triangle at w holds direction d.
    bool corner_holds(std::int32_t node, std::int32_t w, Dir d) const {
      const auto& tr = T(node);
      const int c = corner(tr, w);
      const Point pw = P(w), b = P(tr.v[static_cast<std::size_t>((c + 1) % 3)]),
                  cc = P(tr.v[static_cast<std::size_t>((c + 2) % 3)]);
      return scr(vec(pw, b), d) >= 0 && scr(d, vec(pw, cc)) >= 0;
    }
    // The lifted triangles of w's free fan that holds `node` (a triangle with corner w).
    std::vector<std::int32_t> fan(std::int32_t node, std::int32_t w) {
      std::vector<std::int32_t> out{node};
      for (int way = 0; way < 2; ++way) {
        std::int32_t cur = node;
        for (std::size_t guard = 0; guard <= t.triangles().size(); ++guard) {
          const int c = corner(T(cur), w);
          // way 0: clockwise, across edge w -> next; way 1: counter-clockwise, across prev -> w
          const int e = way == 0 ? c : (c + 2) % 3;
          const std::int32_t nb = cover.move(cur, e);
          if (nb < 0) break;
          cur = nb;
          out.push_back(cur);
        }
      }
      return out;
    }
    // The fan's sector: counter-clockwise from `start` to `end`, both directions of its constrained
    // boundary edges.
    std::pair<V, V> sector(std::int32_t node, std::int32_t w) {
      V start{}, end{};
      for (int way = 0; way < 2; ++way) {
        std::int32_t cur = node;
        for (std::size_t guard = 0; guard <= t.triangles().size(); ++guard) {
          const auto& tr = T(cur);
          const int c = corner(tr, w);
          const int e = way == 0 ? c : (c + 2) % 3;
          const std::int32_t nb = cover.move(cur, e);
          if (nb < 0) {
            const Point pw = P(w);
            if (way == 0) start = vec(pw, P(tr.v[static_cast<std::size_t>((c + 1) % 3)]));
            else end = vec(pw, P(tr.v[static_cast<std::size_t>((c + 2) % 3)]));
            break;
          }
          cur = nb;
        }
      }
      return {start, end};
    }
    // Walking back along a ray in direction d through w, with q's side `side` (+1: left of d):
    // blockage material lies just behind w on that side, i.e. -d turned a little towards that side
    // is not in the free fan of w that holds `node`.
    bool material_behind(std::int32_t node, std::int32_t w, Dir d, int side) {
      const auto [s, e] = sector(node, w);
      const Dir b = G::neg(d);
      if (!angle_le(s, b, e)) return true;
      // left of d is right of -d: turning -d clockwise (side +1) must not leave past the start
      auto same = [](Dir x, V y) { return scr(x, y) == 0 && sdot(x, y) > 0; };
      return side > 0 ? same(b, s) : same(b, e);
    }
    // A lifted triangle of w's fan (the one holding `node`) whose closed corner holds d; -1 if none.
    std::int32_t fan_toward(std::int32_t node, std::int32_t w, Dir d) {
      for (std::int32_t n : fan(node, w))
        if (corner_holds(n, w, d)) return n;
      return -1;
    }

    // The ray from a (in the closed triangle of `node`) in direction d, until it would leave free
    // space or pass between blockages that touch, or until lambda = *limit.
    Ray walk(const RP& a, std::int32_t node, Dir d, const Q* limit) {
      Ray out;
      std::int32_t cur = node;
      Q lam = num(0);
      for (std::size_t guard = 0;; ++guard) {
        if (guard > 8 * t.triangles().size() + 64) throw std::logic_error("CMinLinker: a ray walk did not end");
        const auto& tr = T(cur);
        std::optional<Q> best;
        std::array<std::optional<Q>, 3> li;
        for (int i = 0; i < 3; ++i) {
          const Point u = P(tr.v[static_cast<std::size_t>(i)]), w = P(tr.v[static_cast<std::size_t>((i + 1) % 3)]);
          const V e = vec(u, w);
          const Ex c = cr(d, e);
          if (G::sgn(c) <= 0) continue;  // d does not leave through this edge
          // a + lambda d on the edge's line: lambda = cross(u - a, e) / cross(d, e)
          li[static_cast<std::size_t>(i)] =
              qcross(num(u.x) - a.x, num(u.y) - a.y, num(e.x), num(e.y)) / G::num(c);
          if (!best || *li[static_cast<std::size_t>(i)] < *best) best = li[static_cast<std::size_t>(i)];
        }
        Q x = *best;
        if (x < lam) x = lam;  // (only on the triangle's boundary, where both are equal)
        if (limit && x >= *limit) {
          out.steps.push_back({cur, lam, *limit});
          out.end = *limit;
          if (x == *limit) {  // a vertex just at the limit is reached too
            const RP X = add(a, x, d);
            for (std::int32_t v : tr.v)
              if (equal(X, P(v))) out.passes.push_back({v, cur, x});
          }
          return out;
        }
        out.steps.push_back({cur, lam, x});
        const RP X = add(a, x, d);
        int vi = -1;
        for (int i = 0; i < 3; ++i)
          if (equal(X, P(tr.v[static_cast<std::size_t>(i)]))) vi = i;
        if (vi < 0) {
          int e = -1;
          for (int i = 0; i < 3; ++i)
            if (li[static_cast<std::size_t>(i)] && *li[static_cast<std::size_t>(i)] == x) e = i;
          const std::int32_t nb = e < 0 ? -1 : cover.move(cur, e);
          if (nb < 0) {
            out.end = x;
            return out;
          }
          cur = nb;
          lam = x;
          continue;
        }
        const std::int32_t w = tr.v[static_cast<std::size_t>(vi)];
        out.passes.push_back({w, cur, x});
        const std::int32_t f = fan_toward(cur, w, d);
        if (f < 0) {
          out.end = x;
          return out;
        }
        cur = f;
        lam = x;
      }
    }

    // Adds every other lifted triangle that holds a piece: the one across an edge the piece runs
    // along, and the fans of its ends that are vertices (the end alone).
    void spread(std::vector<std::pair<std::int32_t, ASeg>>& held) {
      const std::size_t n = held.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::int32_t node = held[k].first;
        const ASeg sg = held[k].second;
        const auto& tr = T(node);
        auto on_line = [&](const RP& x, Point u, Point w) {
          return qcross(num(w.x - u.x), num(w.y - u.y), x.x - num(u.x), x.y - num(u.y)).sign() == 0;
        };
        for (int i = 0; i < 3; ++i) {
          const Point u = P(tr.v[static_cast<std::size_t>(i)]), w = P(tr.v[static_cast<std::size_t>((i + 1) % 3)]);
          if (!on_line(sg.a, u, w) || !on_line(sg.b, u, w)) continue;
          const std::int32_t nb = cover.move(node, i);
          if (nb >= 0) held.push_back({nb, sg});
        }
        for (int end = 0; end < 2; ++end) {
          const RP& x = end == 0 ? sg.a : sg.b;
          const Q& px = end == 0 ? sg.pa : sg.pb;
          for (std::int32_t v : tr.v)
            if (equal(x, P(v)))
              for (std::int32_t f : fan(node, v))
                if (f != node) held.push_back({f, {x, x, px, px}});
        }
      }
    }
    // The pieces of a ray from `start` in direction d (as walk() returned it) in every lifted
    // triangle that holds them (parameters: lambda along the ray).
    std::vector<std::pair<std::int32_t, ASeg>> held(const Ray& r, const RP& start, Dir d) {
      std::vector<std::pair<std::int32_t, ASeg>> out;
      for (const Step& st : r.steps) out.push_back({st.node, {add(start, st.in, d), add(start, st.out, d), st.in, st.out}});
      spread(out);
      return out;
    }

    Seg make_seg(const RP& start, std::int32_t node, Dir dir, int qside, const RP& origin,
                 std::int32_t parent) {
      Seg s;
      s.start = start;
      s.node = node;
      s.dir = dir;
      Ray r = walk(start, node, dir, nullptr);
      s.len = r.end;
      s.chain = std::move(r.steps);
      s.qside = qside;
      s.origin = origin;
      s.parent = parent;
      return s;
    }

    // The rays in direction d from the points of s (the d side of s): a breadth-first search of
    // pieces across the edges the rays leave through.
    Sweep sweep(const Seg& s, std::size_t seg_index, Dir d) {
      Sweep sw;
      sw.seg = seg_index;
      sw.d = d;
      const Q o0 = off(d, s.start);
      const Q cdu = G::num(cr(d, s.dir));
      for (const Step& st : s.chain) {
        Q a = o0 + st.in * cdu, b = o0 + st.out * cdu;
        if (b < a) std::swap(a, b);
        sw.pieces.push_back({st.node, std::move(a), std::move(b), true});
      }
      for (std::size_t k = 0; k < sw.pieces.size(); ++k) {
        if (++pieces > piece_limit) throw std::logic_error("CMinLinker: a sweep passed its piece limit");
        const std::int32_t node = sw.pieces[k].node;
        const auto& tr = T(node);
        for (int i = 0; i < 3; ++i) {
          const Point u = P(tr.v[static_cast<std::size_t>(i)]), w = P(tr.v[static_cast<std::size_t>((i + 1) % 3)]);
          const int c = scr(d, vec(u, w));
          if (c < 0) continue;
          Q ou = G::num(off(d, u)), ow = G::num(off(d, w));
          if (ow < ou) std::swap(ou, ow);
          const Piece& pc = sw.pieces[k];
          if (pc.hi < ou || pc.lo > ow) continue;
          // A ray along the edge (c == 0) lies in the triangle across it as well: it floods round
          // the edge's far vertex from both sides (one of them may be the way on).
          const std::int32_t nb = cover.move(node, i);
          if (nb < 0 || (c == 0 && nb == pc.from)) continue;
          Q lo = pc.lo < ou ? ou : pc.lo, hi = pc.hi > ow ? ow : pc.hi;
          sw.pieces.push_back({nb, std::move(lo), std::move(hi), false, node});
        }
      }
      for (std::size_t k = 0; k < sw.pieces.size(); ++k) sw.by_node.emplace(sw.pieces[k].node, k);
      return sw;
    }

    // Constraints of a piece on a point a + lambda (b - a) (lambda's interval is narrowed).
    static void clip(const Piece& pc, const Seg& s, Dir d, const RP& a, const RP& b, Interval<Q>& iv) {
      const Q oa = off(d, a), ob = off(d, b);
      iv.at_least_zero(oa - pc.lo, ob - oa);
      iv.at_least_zero(pc.hi - oa, oa - ob);
      if (!pc.chain) return;
      // the swept side of the segment's line (or, for a point, ahead of it along d)
      if (s.len.sign() == 0) {
        const Q f0 = (a.x - s.start.x) * G::nx(d) + (a.y - s.start.y) * G::ny(d);
        const Q f1 = (b.x - a.x) * G::nx(d) + (b.y - a.y) * G::ny(d);
        iv.at_least_zero(f0, f1);
      } else {
        const int sg = scr(s.dir, d);
        const Q f0 = qcross(G::nx(s.dir), G::ny(s.dir), a.x - s.start.x, a.y - s.start.y);
        const Q f1 = qcross(G::nx(s.dir), G::ny(s.dir), b.x - a.x, b.y - a.y);
        if (sg > 0) iv.at_least_zero(f0, f1);
        else iv.at_least_zero(-f0, -f1);
      }
    }
  };

  // The point of segment s whose ray in direction d has offset o.
  static RP point_at_offset(const Seg& s, Dir d, const Q& o) {
    if (s.len.sign() == 0) return s.start;
    const Q lam = (o - off(d, s.start)) / G::num(cr(d, s.dir));
    return add(s.start, lam, s.dir);
  }

  // The segment of alpha (0 .. m - 1) that leaves the point at `param` (segment index + fraction).
  static std::size_t alpha_segment(const Q& param, std::size_t m) {
    const auto j = static_cast<std::size_t>(floor_of(param));
    return j >= m ? m - 1 : j;
  }

  // The first point of segment [c, e] on the closed segment [l, r]; its parameter along [c, e].
  static std::optional<Q> first_on(const RP& c, Point e, Point l, Point r) {
    const Q dx = num(e.x) - c.x, dy = num(e.y) - c.y;
    const Q ex = num(i64{r.x} - l.x), ey = num(i64{r.y} - l.y);
    const Q lx = num(l.x) - c.x, ly = num(l.y) - c.y;
    const Q den = qcross(dx, dy, ex, ey);
    const Q zero = num(0), one = num(1);
    if (den.sign() != 0) {
      const Q t = qcross(lx, ly, ex, ey) / den, s = qcross(lx, ly, dx, dy) / den;
      if (t < zero || t > one || s < zero || s > one) return std::nullopt;
      return t;
    }
    if (qcross(lx, ly, dx, dy).sign() != 0 || qcross(lx, ly, ex, ey).sign() != 0) {
      // parallel lines apart, or c off the portal's line
      if (dx.sign() == 0 && dy.sign() == 0) {
        // c alone: on the portal?
        if (qcross(lx, ly, ex, ey).sign() != 0) return std::nullopt;
      } else {
        return std::nullopt;
      }
    }
    // collinear (or c a point on the portal's line): the smallest t in [0, 1] on [l, r]
    const Q dd = dx * dx + dy * dy;
    auto within = [&](const Q& px, const Q& py) {  // point on the portal's segment
      const Q t = (px - num(l.x)) * ex + (py - num(l.y)) * ey, len = ex * ex + ey * ey;
      return t.sign() >= 0 && t <= len;
    };
    if (within(c.x, c.y)) return zero;
    if (dd.sign() == 0) return std::nullopt;
    std::optional<Q> best;
    for (Point x : {l, r}) {
      const Q t = ((num(x.x) - c.x) * dx + (num(x.y) - c.y) * dy) / dd;
      if (t >= zero && t <= one && (!best || t < *best)) best = t;
    }
    return best;
  }

  static CMinLinkPathOf<RP> path(const geom::FreeSpaceTriangulation& tri, std::span<const Point> taut,
                                 const typename G::Set& set, std::size_t max_links);
  static CMinLinkLoopOf<RP> loop(const geom::FreeSpaceTriangulation& tri, std::span<const Point> taut_loop,
                                 const typename G::Set& set, const MinLinkLoop* any_angle, std::size_t max_starts);
};

template <class G>
CMinLinkPathOf<typename G::P> Impl<G>::path(const geom::FreeSpaceTriangulation& tri, std::span<const Point> taut,
                                          const typename G::Set& set, std::size_t max_links) {
  CMinLinkPathOf<RP> result;
  if (taut.empty()) throw std::invalid_argument("CMinLinker: an empty path");
  std::vector<Point> alpha;  // without repeated points
  for (Point x : taut)
    if (alpha.empty() || !(alpha.back() == x)) alpha.push_back(x);
  const Point p = alpha.front(), q = alpha.back();
  if (alpha.size() == 1) {
    result.points = {rp(p)};
    return result;
  }
  const std::size_t m = alpha.size() - 1;  // alpha's segments; params run from 0 to m
  const Tightener tight(tri);
  Sleeve sleeve;
  if (tight.lift(alpha, sleeve) != TightenStatus::Ok) throw std::invalid_argument("CMinLinker: the path does not lift");
  Cover cover(tri, sleeve.triangles);
  const std::int32_t K = cover.size();
  Work wk{tri, cover, 0, 64 * tri.triangles().size() + 4096};

  // Ends: some direction must leave p's free wedge and reach q's.
  {
    const Q one = num(1);
    bool leaves = false, enters = false;
    for (const Dir& d : set.steps()) {
      leaves = leaves || wk.walk(rp(p), 0, d, &one).end.sign() > 0;
      enters = enters || wk.walk(rp(q), K - 1, G::neg(d), &one).end.sign() > 0;
    }
    if (!leaves || !enters) {
      result.why = !leaves ? "no direction of " + set.name() + " leaves the free wedge at the first end"
                           : "no direction of " + set.name() + " enters the free wedge at the last end";
      return result;
    }
  }
  if (m == 1 && set.along(i64{q.x} - p.x, i64{q.y} - p.y)) {
    result.points = {rp(p), rp(q)};
    return result;
  }

  // Alpha's pieces in the lifted triangles that hold them.
  std::unordered_map<std::int32_t, std::vector<ASeg>> bearing;
  {
    std::vector<RP> cp(static_cast<std::size_t>(K) + 1);
    std::vector<Q> cpar(static_cast<std::size_t>(K) + 1);
    cp[0] = rp(p);
    cpar[0] = num(0);
    cp[static_cast<std::size_t>(K)] = rp(q);
    cpar[static_cast<std::size_t>(K)] = num(static_cast<i64>(m));
    std::size_t j = 0;
    RP cur = rp(p);
    auto param = [&](const RP& x, std::size_t seg) {
      const V e = vec(alpha[seg], alpha[seg + 1]);
      const Q t = ((x.x - num(alpha[seg].x)) * num(e.x) + (x.y - num(alpha[seg].y)) * num(e.y)) /
                  num(static_cast<i64>(dot(e, e)));
      return num(static_cast<i64>(seg)) + t;
    };
    for (std::int32_t k = 0; k + 1 < K; ++k) {
      const Portal& pt = sleeve.portals[static_cast<std::size_t>(k)];
      for (;;) {
        if (auto t = first_on(cur, alpha[j + 1], pt.left, pt.right)) {
          cur = {cur.x + *t * (num(alpha[j + 1].x) - cur.x), cur.y + *t * (num(alpha[j + 1].y) - cur.y)};
          break;
        }
        if (equal(cur, alpha[j + 1]) && j + 1 < m) {
          ++j;
          continue;
        }
        throw std::logic_error("CMinLinker: the path does not cross its sleeve's portal");
      }
      cp[static_cast<std::size_t>(k) + 1] = cur;
      cpar[static_cast<std::size_t>(k) + 1] = param(cur, j);
    }
    std::vector<std::pair<std::int32_t, ASeg>> held;
    for (std::int32_t k = 0; k < K; ++k)
      held.push_back({k, {cp[static_cast<std::size_t>(k)], cp[static_cast<std::size_t>(k) + 1],
                          cpar[static_cast<std::size_t>(k)], cpar[static_cast<std::size_t>(k) + 1]}});
    wk.spread(held);
    for (auto& [node, sg] : held) bearing[node].push_back(std::move(sg));
  }

  std::vector<Seg> segs;
  std::vector<std::size_t> frontier;
  Q progress;  // alpha's param of the last exit so far
  std::size_t stalls = 0;  // steps since it last grew
  {
    const V d0 = vec(alpha[0], alpha[1]);
    if (set.along(d0.x, d0.y)) {
      Dir d{};
      for (const Dir& s : set.steps())
        if (scr(s, d0) == 0 && sdot(s, d0) > 0) d = s;
      // the ray along alpha's first edge, beyond its first bend (the blockage there bounds it)
      const Ray r = wk.walk(rp(p), 0, d, nullptr);
      const Q l1 = G::num(G::dot(G::ev(d0), G::ev(d))) / norm(d);
      // the lifted triangle holding alpha[1] on that ray
      std::int32_t node = -1;
      for (const Step& st : r.steps)
        if (st.in <= l1 && l1 <= st.out) node = st.node;
      if (node < 0) throw std::logic_error("CMinLinker: the first edge is not on its ray");
      const int side = scr(d, vec(alpha[1], alpha[2]));
      segs.push_back(wk.make_seg(rp(alpha[1]), node, d, side, rp(p), -1));
      frontier = {0};
      progress = num(1);
    } else {
      const auto [u, v] = set.cone_steps(set.cone(d0.x, d0.y));
      segs.push_back(wk.make_seg(rp(p), 0, u, +1, rp(p), -1));
      segs.push_back(wk.make_seg(rp(p), 0, v, -1, rp(p), -1));
      frontier = {0, 1};
      progress = num(0);
    }
  }

  for (std::size_t links = 1;; ++links) {
    if (links >= max_links) throw std::logic_error("CMinLinker: more than " + std::to_string(max_links) + " links");
    // every sweep of the frontier into the component holding q
    std::vector<Sweep> sweeps;
    for (std::size_t f : frontier)
      for (const Dir& d : set.steps())
        if (scr(segs[f].dir, d) == segs[f].qside) sweeps.push_back(wk.sweep(segs[f], f, d));
    result.sweeps += sweeps.size();
    // alpha's last point in their union
    struct Exit {
      Q param;
      std::size_t sweep = 0;
      std::int32_t node = -1;
      RP at;
    };
    std::optional<Exit> best;
    std::vector<Exit> tied;  // every sweep's exit at best's param
    for (std::size_t k = 0; k < sweeps.size(); ++k) {
      const Sweep& sw = sweeps[k];
      for (const Piece& pc : sw.pieces) {
        const auto it = bearing.find(pc.node);
        if (it == bearing.end()) continue;
        for (const ASeg& as : it->second) {
          Interval<Q> iv{num(0), num(1)};
          Work::clip(pc, segs[sw.seg], sw.d, as.a, as.b, iv);
          if (iv.empty) continue;
          const Q par = as.pa + iv.hi * (as.pb - as.pa);
          if (best && par < best->param) continue;
          Exit ex{par, k, pc.node, {as.a.x + iv.hi * (as.b.x - as.a.x), as.a.y + iv.hi * (as.b.y - as.a.y)}};
          if (!best || par > best->param) tied.clear();
          tied.push_back(ex);
          best = std::move(ex);
        }
      }
    }
    // No progress along alpha is possible only while the frontier turns round a blockage corner
    // that alpha wraps (each turn a direction further; at most once round the set).
    if (!best || best->param < progress || (best->param == progress && ++stalls > 2 * set.steps().size() + 2))
      throw std::logic_error("CMinLinker: a link made no progress along the path");
    if (best->param > progress) stalls = 0;
    progress = best->param;
    const Q qm = num(static_cast<i64>(m));
    if (best->param != qm) {
      // Several sweeps leave alpha at the same point: the ray nearest alpha's way on (on the side
      // alpha takes) bounds what is not yet reached there.
      const std::size_t ja = alpha_segment(best->param, m);
      const V a = vec(alpha[ja], alpha[ja + 1]);
      for (const Exit& ex : tied) {
        const Dir dk = sweeps[ex.sweep].d, db = sweeps[best->sweep].d;
        const int sk = scr(dk, a), sb = scr(db, a);
        if (sk == sb && scr(db, dk) == sb) best = ex;
      }
    }
    const Sweep& sw = sweeps[best->sweep];
    const Dir ds = sw.d;
    const Seg& s0 = segs[sw.seg];
    if (best->param == qm) {
      // q is on a ray of this sweep: the last link; the others along the segments' lines
      std::vector<RP> pts{rp(q), point_at_offset(s0, ds, off(ds, rp(q)))};
      for (std::int32_t i = static_cast<std::int32_t>(sw.seg); i >= 0; i = segs[static_cast<std::size_t>(i)].parent)
        pts.push_back(segs[static_cast<std::size_t>(i)].origin);
      std::reverse(pts.begin(), pts.end());
      std::vector<RP> clean;
      for (RP& x : pts)
        if (clean.empty() || !(clean.back() == x)) clean.push_back(std::move(x));
      if (clean.size() != links + 2)
        throw std::logic_error("CMinLinker: the links read back are not " + std::to_string(links + 1));
      for (std::size_t i = 0; i + 1 < clean.size(); ++i) {
        const Q dx = clean[i + 1].x - clean[i].x, dy = clean[i + 1].y - clean[i].y;
        bool in_set = false;
        for (const Dir& d : set.steps())
          in_set = in_set || (qcross(G::nx(d), G::ny(d), dx, dy).sign() == 0 && (dx * G::nx(d) + dy * G::ny(d)).sign() > 0);
        if (!in_set) throw std::logic_error("CMinLinker: a link outside the direction set");
      }
      result.points = std::move(clean);
      result.pieces = wk.pieces;
      return result;
    }
    // alpha leaves the union at E on the ray s of sweep (ds, s0), into the side `side` of s
    const RP E = best->at;
    const std::size_t j = alpha_segment(best->param, m);
    const int side = scr(ds, vec(alpha[j], alpha[j + 1]));
    if (side == 0) throw std::logic_error("CMinLinker: the path leaves a sweep along its ray");
    const RP X = point_at_offset(s0, ds, off(ds, E));
    const Q muX = ((E.x - X.x) * G::nx(ds) + (E.y - X.y) * G::ny(ds)) / norm(ds);
    const Ray back = wk.walk(E, best->node, G::neg(ds), &muX);
    if (back.end < muX) throw std::logic_error("CMinLinker: a sweep's ray is blocked before its start");
    // Walking back along s from E, the frontier follows s as long as the points just off s on
    // q's side are free and not reached; the first place where that ends (mu: distance from E in
    // steps of ds) is, nearest E:
    //   (a) a vertex with blockage material just behind it on q's side (the tangent case of the
    //       lemma's proof: the frontier is s from there on);
    //   (p) rays parallel to s reaching q's side (the sweep's own, or another segment's in the
    //       same or opposite direction): s from there on;
    //   (c) rays of another direction crossing s from q's side: they cover it; s from there on;
    //   (b) a ray of another direction crossing s into q's side (the first case, or the second half of the
    //       tangent case): the frontier is s and that ray t from the crossing r';
    //   (x) s's start X on s0: s from X.
    std::optional<Q> single = muX;  // (a), (p), (x): the nearest
    std::int32_t node_single = back.steps.back().node;
    auto nearer = [&](const Q& mu, std::int32_t node) {
      if (mu < *single) {
        single = mu;
        node_single = node;
      }
    };
    for (const Pass& ps : back.passes)
      if (ps.lam <= muX && wk.material_behind(ps.node, ps.vertex, ds, side)) {
        nearer(ps.lam, ps.node);
        break;
      }
    for (std::int32_t v : wk.T(best->node).v)
      if (equal(E, wk.P(v)) && wk.material_behind(best->node, v, ds, side)) nearer(num(0), best->node);
    const auto back_held = wk.held(back, E, G::neg(ds));
    std::optional<Q> mub;
    std::vector<std::size_t> at_mub;
    std::int32_t node_b = -1;
    for (std::size_t k = 0; k < sweeps.size(); ++k) {
      const Sweep& o = sweeps[k];
      const int c = scr(o.d, ds);
      // parallel rays: q's side in o's offsets (larger offsets lie left of o.d)
      const int qs = c == 0 ? side * sdot(o.d, ds) : 0;
      const Q oo = c == 0 ? off(o.d, E) : num(0);
      for (const auto& [node, sp] : back_held) {
        // y(mu) = E - mu ds: sp runs from y(sp.pa) to y(sp.pb)
        const auto range = o.by_node.equal_range(node);
        for (auto it = range.first; it != range.second; ++it) {
          const Piece& pc = o.pieces[it->second];
          if (c == 0 && !(pc.lo <= oo && oo <= pc.hi && (qs > 0 ? pc.hi > oo : pc.lo < oo))) continue;
          Interval<Q> iv{num(0), num(1)};
          Work::clip(pc, segs[o.seg], o.d, sp.a, sp.b, iv);
          if (iv.empty) continue;
          const Q mu = sp.pa + iv.lo * (sp.pb - sp.pa);
          if (c == 0 || scr(ds, o.d) != side) {
            nearer(mu, node);  // parallel rays, or rays coming from q's side: they cover it
          } else if (!mub || mu < *mub) {
            mub = mu;
            at_mub = {k};
            node_b = node;
          } else if (mu == *mub && std::find(at_mub.begin(), at_mub.end(), k) == at_mub.end()) {
            at_mub.push_back(k);
          }
        }
      }
    }
    // the ray t of the sweeps at mub (all going into q's side) that turns least from s
    std::optional<std::size_t> tk;
    for (std::size_t k : at_mub)
      if (!tk || scr(sweeps[*tk].d, sweeps[k].d) * side < 0) tk = k;
    std::vector<std::size_t> next;
    if (mub && *mub <= *single) {
      {
        const RP r = add(E, -*mub, ds);
        const Sweep& o = sweeps[*tk];
        Seg t = wk.make_seg(r, node_b, o.d, scr(o.d, ds),
                            point_at_offset(segs[o.seg], o.d, off(o.d, r)), static_cast<std::int32_t>(o.seg));
        if (*mub < *single || t.len.sign() > 0) {  // at a tie, only a ray going on cuts q's side
          segs.push_back(wk.make_seg(r, node_b, ds, side, X, static_cast<std::int32_t>(sw.seg)));
          segs.push_back(std::move(t));
          next = {segs.size() - 2, segs.size() - 1};
        }
      }
    }
    if (next.empty()) {
      const RP r = add(E, -*single, ds);
      segs.push_back(wk.make_seg(r, node_single, ds, side, X, static_cast<std::int32_t>(sw.seg)));
      next = {segs.size() - 1};
    }
    frontier = std::move(next);
  }
}

template <class G>
CMinLinkLoopOf<typename G::P> Impl<G>::loop(const geom::FreeSpaceTriangulation& tri, std::span<const Point> taut_loop,
                                          const typename G::Set& set, const MinLinkLoop* any_angle,
                                          std::size_t max_starts) {
  const std::vector<Point> v = loop_vertices(taut_loop, "CMinLinker::loop");
  const std::size_t n = v.size();
  CMinLinkLoopOf<RP> best;
  {
    const MinLinkLoop any = any_angle ? *any_angle : MinLinker(tri).loop(taut_loop);
    std::size_t lb = std::max<std::size_t>(3, any.minimal ? any.links() : any.at_least);
    if (set.steps().size() == 4) lb = std::max<std::size_t>(4, lb + lb % 2);
    best.at_least = lb;
  }
  // the direction (a step of the set) of the link from a to b
  auto step_of = [&](const RP& a, const RP& b) {
    const Q dx = b.x - a.x, dy = b.y - a.y;
    for (const Dir& d : set.steps())
      if ((dx * G::ny(d) - dy * G::nx(d)).sign() == 0 && (dx * G::nx(d) + dy * G::ny(d)).sign() > 0) return d;
    throw std::logic_error("CMinLinker::loop: a link not along the set");
  };
  // The starts, each a path in the cover whose ends close into a loop of the class:
  //   - an edge (a, b) of the shortest loop along a direction of the set: the path from a once
  //     round to b, whose first link runs along the edge; closed by the edge back to a;
  //   - a vertex v and a direction d of the set strictly within the loop's turn at v: the path
  //     from v - d through v once round to v and on to v + d (locally taut: the blockage at v
  //     lies inside both of its turns there, which contain the loop's), whose first link runs
  //     along d through v; closed by the segment back through v. When the path's last link runs
  //     along the first one's line, the closing segment joins them into one link;
  //   - a vertex v: the path from v once round back to v.
  // A loop wound w times repeats its vertices and edges: each once.
  struct Start {
    std::size_t a;
    int kind;    // 0 an edge from v[a], 1 vertex v[a] with direction d, 2 vertex v[a]
    Point d{0, 0};  // an integer vector along a step (a unit vector: the lattice steps, a 30-degree set's axes,
                    // the diagonals of a set of Root3Directions::parse_any)
  };
  std::vector<Start> starts;
  {
    std::set<std::pair<Point, Point>> seen_edges;
    for (std::size_t a = 0; a < n; ++a) {
      const Point x = v[a], y = v[(a + 1) % n];
      if (set.along(i64{y.x} - x.x, i64{y.y} - x.y) && seen_edges.insert({x, y}).second) starts.push_back({a, 0});
    }
    std::set<std::pair<Point, Point>> seen_dirs;
    for (std::size_t a = 0; a < n; ++a) {
      const Point x = v[a];
      const V u = vec(v[(a + n - 1) % n], x), w = vec(x, v[(a + 1) % n]);
      const int turn = sgn(cross(u, w));
      for (const Dir& step : set.steps()) {
        // only a step along an integer vector, taken as its unit vector (v - d and v + d are points to lift)
        const std::optional<Point> id = G::integer(step);
        if (!id) continue;
        const Point d = *id;
        const V dv{d.x, d.y};
        const int cu = sgn(cross(u, dv)), cw = sgn(cross(dv, w));
        // strictly inside (along u or w the path would not turn at v; the edge starts cover those)
        const bool in_cone = turn * cu > 0 && turn * cw > 0;
        if (in_cone && seen_dirs.insert({x, d}).second) starts.push_back({a, 1, d});
      }
    }
    std::set<Point> seen;
    for (std::size_t a = 0; a < n; ++a)
      if (seen.insert(v[a]).second) starts.push_back({a, 2});
  }
  const std::size_t m = starts.size(), tries = std::max<std::size_t>(1, std::min(m, max_starts));
  std::string why;
  for (std::size_t k = 0; k < tries && (!best.ok() || best.links() > best.at_least); ++k) {
    const Start st = starts[k * m / tries];
    std::vector<Point> round;
    round.reserve(n + 3);
    if (st.kind == 1) round.push_back({v[st.a].x - st.d.x, v[st.a].y - st.d.y});
    for (std::size_t i = 0; i <= n + (st.kind == 0 ? 1 : 0); ++i) round.push_back(v[(st.a + i) % n]);
    if (st.kind == 1) round.push_back({v[st.a].x + st.d.x, v[st.a].y + st.d.y});
    if (st.kind == 1) {
      // v - d and v + d may lie in a blockage or past a pinch: such a start is left out
      Sleeve probe;
      if (Tightener(tri).lift(round, probe) != TightenStatus::Ok) continue;
    }
    CMinLinkPathOf<RP> c = path(tri, round, set, 4096);
    ++best.starts;
    if (!c.ok()) {
      why = c.why;
      continue;
    }
    if (c.points.size() < 2) throw std::logic_error("CMinLinker::loop: a path of no link");
    // Closed: from the path's last point back to its first (along the edge, or through v), or at
    // v. Links along one line (the closing one and its neighbours, or any two that meet there,
    // the same way or back) join into one: the segment between their far ends lies on them, so
    // the loop stays free and in its class.
    std::vector<RP> l(c.points.begin(), c.points.end() - 1);
    if (st.kind != 2) l.push_back(c.points.back());
    for (bool again = true; again && l.size() >= 3;) {
      again = false;
      for (std::size_t i = 0; i < l.size() && l.size() >= 3; ++i) {
        const std::size_t h = (i + l.size() - 1) % l.size(), j = (i + 1) % l.size();
        const Q cr = (l[i].x - l[h].x) * (l[j].y - l[i].y) - (l[i].y - l[h].y) * (l[j].x - l[i].x);
        if (cr.sign() != 0 && !(l[h] == l[i])) continue;
        l.erase(l.begin() + static_cast<std::ptrdiff_t>(i));
        if (l.size() >= 2 && l[(i + l.size() - 1) % l.size()] == l[i % l.size()]) l.erase(l.begin() + static_cast<std::ptrdiff_t>(i % l.size()));
        again = true;
        break;
      }
    }
    if (l.size() < 3) throw std::logic_error("CMinLinker::loop: the loop closed to fewer than three links");
    for (std::size_t i = 0; i < l.size(); ++i) (void)step_of(l[i], l[(i + 1) % l.size()]);
    l.push_back(l.front());
    if (!best.ok() || l.size() < best.points.size()) best.points = std::move(l);
  }
  if (!best.ok()) {
    best.why = "from no vertex or edge of the shortest loop: " + why;
    return best;
  }
  if (best.links() < best.at_least) throw std::logic_error("CMinLinker::loop: fewer links than the lower bound");
  best.minimal = best.links() == best.at_least;
  return best;
}

}  // namespace

CMinLinker::CMinLinker(const geom::FreeSpaceTriangulation& t) : t_(&t) {}

CMinLinkPath CMinLinker::path(std::span<const Point> taut, const geom::LatticeDirections& set,
                              std::size_t max_links) const {
  return Impl<LatticeKind>::path(*t_, taut, set, max_links);
}
CMinLinkPath3 CMinLinker::path(std::span<const Point> taut, const geom::Root3Directions& set,
                               std::size_t max_links) const {
  return Impl<Root3Kind>::path(*t_, taut, set, max_links);
}
CMinLinkLoop CMinLinker::loop(std::span<const Point> taut_loop, const geom::LatticeDirections& set,
                              const MinLinkLoop* any_angle, std::size_t max_starts) const {
  return Impl<LatticeKind>::loop(*t_, taut_loop, set, any_angle, max_starts);
}
CMinLinkLoop3 CMinLinker::loop(std::span<const Point> taut_loop, const geom::Root3Directions& set,
                               const MinLinkLoop* any_angle, std::size_t max_starts) const {
  return Impl<Root3Kind>::loop(*t_, taut_loop, set, any_angle, max_starts);
}

}  // namespace taut::router
