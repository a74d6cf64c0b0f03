// The L1 shortest path map (router/spm.h): a vertical decomposition of free space whose
// trapezoid sides carry exact distance staircases, from one wavefront run.
#include "router/spm.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "geom/index.h"
#include "geom/predicates.h"
#include "router/huge_pages.h"
#include "router/wavefront.h"

namespace taut::router {
namespace {

using geom::Point;
using geom::Polygon;
using i64 = std::int64_t;
using i128 = __int128;
constexpr uint32_t kNone = ~0u;

// An exact rational n / d, d > 0: the height where a wall meets a sloped edge.
struct Q {
  i64 n = 0;
  i64 d = 1;
};
inline int cmp(Q a, Q b) {
  if (a.d == b.d) return a.n < b.n ? -1 : (a.n > b.n ? 1 : 0);  // most thresholds are integers
  const i128 l = i128{a.n} * b.d, r = i128{b.n} * a.d;
  return l < r ? -1 : (l > r ? 1 : 0);
}
inline Q qmax(Q a, Q b) { return cmp(a, b) >= 0 ? a : b; }
inline Q qmin(Q a, Q b) { return cmp(a, b) <= 0 ? a : b; }
inline i64 floor_of(Q a) { return a.n >= 0 ? a.n / a.d : -((-a.n + a.d - 1) / a.d); }
inline i64 ceil_of(Q a) { return -floor_of(Q{-a.n, a.d}); }

// The sheared order of points, (x, y) lexicographic, is Point's own operator< (geom/types.h).
inline bool same_dir(Point o, Point a, Point b) {  // o->a and o->b point the same way
  const i64 ax = i64{a.x} - o.x, ay = i64{a.y} - o.y, bx = i64{b.x} - o.x, by = i64{b.y} - o.y;
  return i128{ax} * by - i128{ay} * bx == 0 && i128{ax} * bx + i128{ay} * by > 0;
}

// Where a trapezoid side lies on the wall through a point q: the part below q, above q, both
// (free space joins them through q on that side), or q alone (a wedge narrowing to q).
enum Part : uint8_t { kLower, kUpper, kJoined, kPoint };
inline bool compatible(Part from, Part to) {
  if (from == kPoint || to == kPoint) return false;
  return from == to || from == kJoined || to == kJoined;
}

// A ray on a side: value y + K (up: for y >= t) or -y + K (down: for y <= t), plus the
// horizontal distance from the side inside the trapezoid.
struct Ray {
  i64 K;
  i64 tn;
  uint32_t td;
  uint32_t root;
  Q t() const { return {tn, static_cast<i64>(td)}; }
  void set_t(Q q) {
    tn = q.n;
    td = static_cast<uint32_t>(q.d);
  }
};

struct Root {
  Point p;
  i64 d;
  uint32_t source;
  uint32_t wedge;  // index into vertex_wedges(p); kNone for a source
};

struct Edge {
  uint32_t l, r;  // point ids, l lex-before r
  bool free_above;
};

struct Trap {
  uint32_t L, R;      // the points whose walls bound it
  uint32_t bot, top;  // edges
  uint32_t lo[3];     // left staircase: up [lo0, lo1), down [lo1, lo2)
  uint32_t ro[3];     // right staircase
  // The same geometry as points, copied here so a query's exact test reads one record.
  Point pl, pr, b0, b1, t0, t1;
};

struct SideRange {
  Q lo, hi;
};

struct WallSide {
  uint32_t trap;
  Part part;
  Point wedge_lo;  // a point in the direction of the ring edge that starts q's wedge (ccw)
  bool has_wedge;
};

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
// float boxes (half the memory of double ones, so fewer cache misses per query), rounded
// outward; the exact test decides.
using BPoint = bg::model::point<float, 2, bg::cs::cartesian>;
using BBox = bg::model::box<BPoint>;
using TrapValue = std::pair<BBox, uint32_t>;
// Its nodes live in an arena on huge pages (router/huge_pages.h).
using TrapTree = bgi::rtree<TrapValue, bgi::rstar<16>, bgi::indexable<TrapValue>, bgi::equal_to<TrapValue>,
                            std::pmr::polymorphic_allocator<TrapValue>>;
// What queries read at random places goes on huge pages.
template <class T>
using HugeVector = std::vector<T, detail::HugePageAllocator<T>>;

}  // namespace

struct L1Map::Impl {
  geom::Box domain;
  L1Wavefront wf;
  std::vector<Point> P;            // decomposition points, lex order
  std::vector<uint32_t> src_at;    // per point: the least source index there, or kNone
  std::vector<Edge> edges;
  HugeVector<Trap> traps;
  HugeVector<Ray> rays;
  HugeVector<Root> roots;
  std::vector<uint32_t> root_begin;  // per point: its roots [begin, next)
  std::vector<Point> root_lo;        // build only: per root, the ring neighbour its wedge starts at
  detail::HugePageResource tree_pages;  // declared before the tree: it outlives it
  std::pmr::monotonic_buffer_resource tree_arena{&tree_pages};
  // Trapezoids of positive width, and those of width 0 (between points on a common vertical: half
  // of them on axis-parallel layouts), which only queries on such a vertical can be in.
  std::optional<TrapTree> tree, zero_tree;
  Stats st;

  Impl(const geom::Box& dom, std::span<const Polygon> obstacles, std::span<const Point> sources)
      : domain(dom), wf(dom, obstacles) {
    wf.run(sources, {}, WavefrontStop::Never);
    build_points_and_edges(sources);
    std::vector<SideRange> left, right;
    std::vector<uint32_t> close_begin, open_begin;
    std::vector<WallSide> closing, opening;
    sweep(left, right, close_begin, closing, open_begin, opening);
    make_roots();
    pass(true, left, right, close_begin, closing, open_begin, opening);
    pass(false, left, right, close_begin, closing, open_begin, opening);
    build_tree(left, right);
    root_lo = {};
    rays.shrink_to_fit();  // grown by doubling: up to half of it was slack
    traps.shrink_to_fit();
    roots.shrink_to_fit();
    st.vertices = static_cast<i64>(P.size());
    st.trapezoids = static_cast<i64>(traps.size());
    st.rays = static_cast<i64>(rays.size());
    st.roots = static_cast<i64>(roots.size());
  }

  uint32_t point_id(Point p) const {
    auto it = std::lower_bound(P.begin(), P.end(), p);
    return it != P.end() && *it == p ? static_cast<uint32_t>(it - P.begin()) : kNone;
  }
  bool in_domain(Point q) const {
    return q.x >= domain.lo.x && q.x <= domain.hi.x && q.y >= domain.lo.y && q.y <= domain.hi.y;
  }

  // ------------------------------------------------------------------------------------------
  // Points: every ring vertex (frame included) and every free source; edges: the ring edges,
  // split at sources lying inside them, each knowing which side is free.
  void build_points_and_edges(std::span<const Point> sources) {
    const std::span<const Polygon> polys = wf.frame_obstacles();
    std::vector<Point> raw;
    for (const Polygon& p : polys) {
      raw.insert(raw.end(), p.outer.begin(), p.outer.end());
      for (const auto& h : p.holes) raw.insert(raw.end(), h.begin(), h.end());
    }
    const std::size_t nring = raw.size();
    std::sort(raw.begin(), raw.end());
    raw.erase(std::unique(raw.begin(), raw.end()), raw.end());
    std::vector<Point> ring_pts = raw;  // sorted: vertex lookup
    auto is_vertex = [&](Point p) { return std::binary_search(ring_pts.begin(), ring_pts.end(), p); };
    std::vector<std::pair<Point, uint32_t>> free_src;  // free sources, first index per point
    for (std::size_t i = 0; i < sources.size(); ++i)
      if (wf.is_free(sources[i])) free_src.push_back({sources[i], static_cast<uint32_t>(i)});
    for (const auto& [p, i] : free_src) raw.push_back(p);
    std::sort(raw.begin(), raw.end());
    raw.erase(std::unique(raw.begin(), raw.end()), raw.end());
    P = std::move(raw);
    src_at.assign(P.size(), kNone);
    for (const auto& [p, i] : free_src) {
      uint32_t& s = src_at[point_id(p)];
      s = std::min(s, i);
    }
    // Sources inside an edge: found on an R-tree of the edges (only when there are any).
    auto key = [](Point a, Point b) {
      if (b < a) std::swap(a, b);
      return std::pair<Point, Point>{a, b};
    };
    std::vector<std::pair<std::pair<Point, Point>, Point>> on_edge;
    {
      std::vector<Point> loose;
      for (const auto& [p, i] : free_src)
        if (!is_vertex(p)) loose.push_back(p);
      if (!loose.empty()) {
        geom::ObstacleIndex index(polys);
        for (Point p : loose)
          for (uint32_t e : index.edges_in_box(geom::Box{p, p})) {
            const geom::Segment& s = index.edge(e);
            if (geom::orientation(s.a, s.b, p) == 0) on_edge.push_back({key(s.a, s.b), p});
          }
      }
    }
    std::sort(on_edge.begin(), on_edge.end());  // by edge, then by point
    edges.reserve(nring + on_edge.size());
    std::vector<Point> chain;
    auto add_ring = [&](const geom::Ring& ring) {
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Point a = ring[i], b = ring[(i + 1) % n];
        if (a == b) continue;
        chain.assign({a});
        if (!on_edge.empty()) {
          const auto k = key(a, b);
          auto it = std::lower_bound(on_edge.begin(), on_edge.end(), k,
                                     [](const auto& x, const auto& kk) { return x.first < kk; });
          std::vector<Point> mid;
          for (; it != on_edge.end() && it->first == k; ++it)
            if (it->second != a && it->second != b) mid.push_back(it->second);
          std::sort(mid.begin(), mid.end());
          mid.erase(std::unique(mid.begin(), mid.end()), mid.end());
          if (b < a) std::reverse(mid.begin(), mid.end());
          chain.insert(chain.end(), mid.begin(), mid.end());
        }
        chain.push_back(b);
        for (std::size_t j = 0; j + 1 < chain.size(); ++j) {
          const uint32_t u = point_id(chain[j]), w = point_id(chain[j + 1]);
          // The obstacle lies left of the ring's direction: above an edge running left to
          // right, below one running right to left.
          const bool free_above = chain[j + 1] < chain[j];
          edges.push_back(P[u] < P[w] ? Edge{u, w, free_above} : Edge{w, u, free_above});
        }
      }
    };
    for (const Polygon& p : polys) {
      add_ring(p.outer);
      for (const auto& h : p.holes) add_ring(h);
    }
  }

  // y of edge e on the wall through point q (sheared: a vertical edge meets it at q's height).
  Q y_at(uint32_t e, uint32_t q) const {
    const Point a = P[edges[e].l], b = P[edges[e].r], p = P[q];
    if (a.x == b.x) return {p.y, 1};
    const i64 dx = i64{b.x} - a.x;
    return {i64{a.y} * dx + (i64{b.y} - a.y) * (i64{p.x} - a.x), dx};
  }

  // ------------------------------------------------------------------------------------------
  // The vertical decomposition by a plane sweep in the sheared order (x, y) (wavefront.cpp's
  // sweep_rays(): no two points share X there, no edge is vertical, edges only meet at their
  // ends, so the edges crossing the sweep line are those with left end < q < right end).
  // A gap between consecutive edges is free when its bottom edge has free space above it and it
  // has a top edge; its open trapezoid closes at the next point in the gap.
  void sweep(std::vector<SideRange>& left, std::vector<SideRange>& right,
             std::vector<uint32_t>& close_begin, std::vector<WallSide>& closing,
             std::vector<uint32_t>& open_begin, std::vector<WallSide>& opening) {
    const uint32_t n = static_cast<uint32_t>(P.size()), m = static_cast<uint32_t>(edges.size());
    std::vector<uint32_t> sb(n + 1, 0), eb(n + 1, 0);
    for (const Edge& e : edges) {
      ++sb[e.l + 1];
      ++eb[e.r + 1];
    }
    for (uint32_t v = 0; v < n; ++v) {
      sb[v + 1] += sb[v];
      eb[v + 1] += eb[v];
    }
    std::vector<uint32_t> slist(m), elist(m);
    {
      std::vector<uint32_t> fs(sb.begin(), sb.end() - 1), fe(eb.begin(), eb.end() - 1);
      for (uint32_t e = 0; e < m; ++e) {
        slist[fs[edges[e].l]++] = e;
        elist[fe[edges[e].r]++] = e;
      }
    }
    struct Key {
      Point q;
    };
    struct Below {
      using is_transparent = void;
      const Impl* s;
      bool operator()(uint32_t e, uint32_t f) const {
        if (e == f) return false;
        const Point le = s->P[s->edges[e].l], re = s->P[s->edges[e].r];
        const Point lf = s->P[s->edges[f].l], rf = s->P[s->edges[f].r];
        if (s->edges[e].l == s->edges[f].l) return geom::orientation(le, re, rf) > 0;
        if (lf < le) return geom::orientation(lf, rf, le) < 0;
        return geom::orientation(le, re, lf) > 0;
      }
      bool operator()(uint32_t e, const Key& k) const {
        return geom::orientation(s->P[s->edges[e].l], s->P[s->edges[e].r], k.q) > 0;
      }
      bool operator()(const Key& k, uint32_t e) const {
        return geom::orientation(s->P[s->edges[e].l], s->P[s->edges[e].r], k.q) < 0;
      }
    };
    std::set<uint32_t, Below> active(Below{this});
    std::vector<std::set<uint32_t, Below>::iterator> where(m, active.end());
    std::vector<uint32_t> gap(m, kNone);  // trapezoid open above edge e
    close_begin.assign(n + 1, 0);
    open_begin.assign(n + 1, 0);
    std::vector<uint32_t> E, S;
    auto other = [&](uint32_t e, uint32_t q) { return P[edges[e].l == q ? edges[e].r : edges[e].l]; };
    for (uint32_t q = 0; q < n; ++q) {
      close_begin[q] = static_cast<uint32_t>(closing.size());
      open_begin[q] = static_cast<uint32_t>(opening.size());
      E.assign(elist.begin() + eb[q], elist.begin() + eb[q + 1]);
      S.assign(slist.begin() + sb[q], slist.begin() + sb[q + 1]);
      const Below below{this};
      std::sort(E.begin(), E.end(), below);
      std::sort(S.begin(), S.end(), below);
      uint32_t B = kNone, A = kNone;
      if (!E.empty()) {
        auto lo = where[E.front()], hi = where[E.back()];
        if (lo != active.begin()) B = *std::prev(lo);
        if (std::next(hi) != active.end()) A = *std::next(hi);
      } else {
        auto it = active.lower_bound(Key{P[q]});
        if (it != active.end()) {
          if (geom::orientation(P[edges[*it].l], P[edges[*it].r], P[q]) == 0)
            throw std::logic_error("spm: a decomposition point lies inside an edge");
          A = *it;
        }
        if (it != active.begin()) B = *std::prev(it);
      }
      const Q yq{P[q].y, 1};
      const Q yB = B != kNone ? y_at(B, q) : yq, yA = A != kNone ? y_at(A, q) : yq;
      // Wedges of q (for roots): lower part and joined sides: ccw from the lowest edge on the
      // left (else the highest on the right); upper part: ccw from the highest on the right
      // (else the lowest on the left).
      const bool has_lower_w = !E.empty() || !S.empty(), has_upper_w = has_lower_w;
      const Point lower_w = !E.empty() ? other(E.front(), q) : (!S.empty() ? other(S.back(), q) : P[q]);
      const Point upper_w = !S.empty() ? other(S.back(), q) : (!E.empty() ? other(E.front(), q) : P[q]);
      auto close = [&](uint32_t bottom, Part part, Q lo, Q hi, Point w, bool hw) {
        const uint32_t t = gap[bottom];
        gap[bottom] = kNone;
        if (t == kNone) return;
        traps[t].R = q;
        right[t] = {lo, hi};
        closing.push_back({t, part, w, hw});
      };
      if (E.empty()) {
        if (B != kNone) close(B, kJoined, yB, yA, lower_w, has_lower_w);
      } else {
        if (B != kNone) close(B, kLower, yB, yq, lower_w, has_lower_w);
        for (std::size_t i = 0; i + 1 < E.size(); ++i) close(E[i], kPoint, yq, yq, other(E[i + 1], q), true);
        close(E.back(), kUpper, yq, yA, upper_w, has_upper_w);
      }
      for (uint32_t e : E) {
        active.erase(where[e]);
        where[e] = active.end();
      }
      for (uint32_t e : S) where[e] = active.insert(e).first;
      auto open = [&](uint32_t bottom, uint32_t top, Part part, Q lo, Q hi, Point w, bool hw) {
        if (!edges[bottom].free_above || top == kNone) return;
        const uint32_t t = static_cast<uint32_t>(traps.size());
        traps.push_back(Trap{q, kNone, bottom, top, {0, 0, 0}, {0, 0, 0}, {}, {}, {}, {}, {}, {}});
        left.push_back({lo, hi});
        right.push_back({});
        gap[bottom] = t;
        opening.push_back({t, part, w, hw});
      };
      if (S.empty()) {
        if (B != kNone) open(B, A, kJoined, yB, yA, lower_w, has_lower_w);
      } else {
        if (B != kNone) open(B, S.front(), kLower, yB, yq, lower_w, has_lower_w);
        for (std::size_t i = 0; i + 1 < S.size(); ++i) open(S[i], S[i + 1], kPoint, yq, yq, other(S[i], q), true);
        open(S.back(), A, kUpper, yq, yA, upper_w, has_upper_w);
      }
    }
    close_begin[n] = static_cast<uint32_t>(closing.size());
    open_begin[n] = static_cast<uint32_t>(opening.size());
    for (Trap& t : traps) {
      if (t.R == kNone) throw std::logic_error("spm: a trapezoid never closed");
      t.pl = P[t.L];
      t.pr = P[t.R];
      t.b0 = P[edges[t.bot].l];
      t.b1 = P[edges[t.bot].r];
      t.t0 = P[edges[t.top].l];
      t.t1 = P[edges[t.top].r];
    }
  }

  // ------------------------------------------------------------------------------------------
  void make_roots() {
    root_begin.assign(P.size() + 1, 0);
    for (uint32_t q = 0; q < P.size(); ++q) {
      root_begin[q] = static_cast<uint32_t>(roots.size());
      if (src_at[q] != kNone) {
        roots.push_back({P[q], 0, src_at[q], kNone});
        root_lo.push_back(P[q]);
        continue;
      }
      const auto w = wf.vertex_wedges(P[q]);
      for (uint32_t k = 0; k < w.size(); ++k)
        if (w[k].distance) {
          roots.push_back({P[q], *w[k].distance, static_cast<uint32_t>(w[k].source.value_or(kNone)), k});
          root_lo.push_back(w[k].lo);
        }
    }
    root_begin[P.size()] = static_cast<uint32_t>(roots.size());
  }
  // The root of point q for a side whose wedge starts at direction (q -> w); kNone if q's wedge
  // there was not reached.
  uint32_t root_for(uint32_t q, const WallSide& s) const {
    const uint32_t b = root_begin[q], e = root_begin[q + 1];
    if (b == e) return kNone;
    if (roots[b].wedge == kNone) return b;  // a source: every side
    if (!s.has_wedge) return kNone;
    for (uint32_t r = b; r < e; ++r)
      if (same_dir(P[q], root_lo[r], s.wedge_lo)) return r;
    return kNone;
  }

  // Ray order: value (K), then the larger root distance, then the root id.
  bool key_less(const Ray& a, const Ray& b) const {
    if (a.K != b.K) return a.K < b.K;
    const i64 da = roots[a.root].d, db = roots[b.root].d;
    if (da != db) return da > db;
    return a.root < b.root;
  }

  // Append the staircases of ups and downs to rays; returns the three offsets.
  void staircase(std::vector<Ray>& ups, std::vector<Ray>& downs, uint32_t out[3]) {
    auto push = [&](const Ray& r) {
      if (rays.size() >= std::numeric_limits<uint32_t>::max()) throw std::length_error("the shortest path map needs more than 2^32 rays");
      rays.push_back(r);
    };
    out[0] = static_cast<uint32_t>(rays.size());
    std::sort(ups.begin(), ups.end(), [&](const Ray& a, const Ray& b) {
      const int c = cmp(a.t(), b.t());
      return c != 0 ? c < 0 : key_less(a, b);
    });
    const Ray* best = nullptr;
    for (const Ray& r : ups)
      if (!best || key_less(r, *best)) {
        push(r);
        best = &r;
      }
    out[1] = static_cast<uint32_t>(rays.size());
    std::sort(downs.begin(), downs.end(), [&](const Ray& a, const Ray& b) {
      const int c = cmp(a.t(), b.t());
      return c != 0 ? c > 0 : key_less(a, b);
    });
    best = nullptr;
    for (const Ray& r : downs)
      if (!best || key_less(r, *best)) {
        push(r);
        best = &r;
      }
    out[2] = static_cast<uint32_t>(rays.size());
  }

  // One family of rays: left to right (l2r: each trapezoid's left side gets the rays of the
  // walls before it) or right to left.
  void pass(bool l2r, const std::vector<SideRange>& left, const std::vector<SideRange>& right,
            const std::vector<uint32_t>& close_begin, const std::vector<WallSide>& closing,
            const std::vector<uint32_t>& open_begin, const std::vector<WallSide>& opening) {
    const uint32_t n = static_cast<uint32_t>(P.size());
    struct In {
      Ray r;
      bool up;
      Part part;
    };
    std::vector<In> in;
    std::vector<Ray> ups, downs;
    for (uint32_t step = 0; step < n; ++step) {
      const uint32_t q = l2r ? step : n - 1 - step;
      const WallSide* src = l2r ? closing.data() + close_begin[q] : opening.data() + open_begin[q];
      const WallSide* src_end = l2r ? closing.data() + close_begin[q + 1] : opening.data() + open_begin[q + 1];
      const WallSide* dst = l2r ? opening.data() + open_begin[q] : closing.data() + close_begin[q];
      const WallSide* dst_end = l2r ? opening.data() + open_begin[q + 1] : closing.data() + close_begin[q + 1];
      if (dst == dst_end) continue;
      in.clear();
      for (const WallSide* s = src; s != src_end; ++s) {
        if (s->part == kPoint) continue;
        const Trap& t = traps[s->trap];
        const uint32_t* o = l2r ? t.lo : t.ro;
        const SideRange& at = l2r ? right[s->trap] : left[s->trap];  // the side on this wall
        const i64 w = i64{P[t.R].x} - P[t.L].x;
        for (uint32_t i = o[0]; i < o[2]; ++i) {
          Ray r = rays[i];
          const bool up = i < o[1];
          r.K += w;
          if (up) {
            if (cmp(r.t(), at.hi) > 0) continue;
            r.set_t(qmax(r.t(), at.lo));
          } else {
            if (cmp(r.t(), at.lo) < 0) continue;
            r.set_t(qmin(r.t(), at.hi));
          }
          in.push_back({r, up, s->part});
        }
      }
      for (const WallSide* d = dst; d != dst_end; ++d) {
        const SideRange& at = l2r ? left[d->trap] : right[d->trap];
        ups.clear();
        downs.clear();
        for (const In& x : in) {
          if (!compatible(x.part, d->part)) continue;
          Ray r = x.r;
          if (x.up) {
            if (cmp(r.t(), at.hi) > 0) continue;
            r.set_t(qmax(r.t(), at.lo));
            ups.push_back(r);
          } else {
            if (cmp(r.t(), at.lo) < 0) continue;
            r.set_t(qmin(r.t(), at.hi));
            downs.push_back(r);
          }
        }
        const uint32_t root = root_for(q, *d);
        if (root != kNone) {
          const i64 y = P[q].y, dr = roots[root].d;
          ups.push_back({dr - y, y, 1, root});
          downs.push_back({dr + y, y, 1, root});
        }
        Trap& t = traps[d->trap];
        staircase(ups, downs, l2r ? t.lo : t.ro);
      }
    }
  }

  // The float nearest to v on each side (v an integer below 2^31 in magnitude).
  static float down(i64 v) {
    float f = static_cast<float>(v);
    while (static_cast<i64>(f) > v) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
  }
  static float up(i64 v) {
    float f = static_cast<float>(v);
    while (static_cast<i64>(f) < v) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  }

  void build_tree(const std::vector<SideRange>& left, const std::vector<SideRange>& right) {
    std::vector<std::pair<BBox, uint32_t>> boxes, zero_boxes;
    boxes.reserve(traps.size());
    for (uint32_t i = 0; i < traps.size(); ++i) {
      const Trap& t = traps[i];
      const i64 y0 = std::min(floor_of(left[i].lo), floor_of(right[i].lo));
      const i64 y1 = std::max(ceil_of(left[i].hi), ceil_of(right[i].hi));
      (t.pl.x == t.pr.x ? zero_boxes : boxes)
          .push_back({BBox(BPoint(down(P[t.L].x), down(y0)), BPoint(up(P[t.R].x), up(y1))), i});
    }
    const std::pmr::polymorphic_allocator<TrapValue> alloc(&tree_arena);
    tree.emplace(boxes.begin(), boxes.end(), bgi::rstar<16>(), bgi::indexable<TrapValue>(),
                 bgi::equal_to<TrapValue>(), alloc);
    zero_tree.emplace(zero_boxes.begin(), zero_boxes.end(), bgi::rstar<16>(), bgi::indexable<TrapValue>(),
                      bgi::equal_to<TrapValue>(), alloc);
  }

  // The trapezoid whose closure holds q (q not a decomposition point); kNone if none (q is not
  // free). The trapezoids partition free space (open across walls, closed along blockage
  // edges, which have free space on one side only), so at most one holds q: look among those
  // of positive width first, then among those of width 0.
  uint32_t find(Point q) const {
    const uint32_t t = find_in(*tree, q);
    return t != kNone ? t : find_in(*zero_tree, q);
  }
  uint32_t find_in(const TrapTree& rt, Point q) const {
    const BPoint bp(down(q.x), down(q.y)), bq(up(q.x), up(q.y));
    // The first box holding q whose trapezoid holds q exactly: the query iterator stops there
    // (no further nodes visited), unlike an output-iterator query that walks every candidate.
    for (auto it = rt.qbegin(bgi::intersects(BBox(bp, bq))); it != rt.qend(); ++it) {
      const Trap& t = traps[it->second];
      if (t.pl < q && q < t.pr && geom::orientation(t.b0, t.b1, q) >= 0 && geom::orientation(t.t0, t.t1, q) <= 0)
        return it->second;
    }
    return kNone;
  }

  // Best ray at q inside trapezoid i: (value, root).
  std::optional<std::pair<i64, uint32_t>> evaluate(uint32_t i, Point q) const {
    const Trap& t = traps[i];
    std::optional<Ray> best;
    i64 best_v = 0;
    auto consider = [&](const Ray& r, i64 v) {
      Ray c = r;
      c.K = v;
      if (!best || key_less(c, *best)) {
        best = c;
        best_v = v;
      }
    };
    const Q y{q.y, 1};
    for (int side = 0; side < 2; ++side) {
      const uint32_t* o = side == 0 ? t.lo : t.ro;
      const i64 dx = side == 0 ? i64{q.x} - t.pl.x : i64{t.pr.x} - q.x;
      // up: thresholds ascending; the last with t <= y
      auto ub = std::upper_bound(rays.begin() + o[0], rays.begin() + o[1], y,
                                 [](const Q& yy, const Ray& r) { return cmp(yy, r.t()) < 0; });
      if (ub != rays.begin() + o[0]) {
        const Ray& r = *std::prev(ub);
        consider(r, r.K + q.y + dx);
      }
      // down: thresholds descending; the last with t >= y
      auto db = std::upper_bound(rays.begin() + o[1], rays.begin() + o[2], y,
                                 [](const Q& yy, const Ray& r) { return cmp(yy, r.t()) > 0; });
      if (db != rays.begin() + o[1]) {
        const Ray& r = *std::prev(db);
        consider(r, r.K - q.y + dx);
      }
    }
    if (!best) return std::nullopt;
    return std::pair<i64, uint32_t>{best_v, best->root};
  }

  // The best root at q: (distance, root id); nullopt if not free or unreached.
  std::optional<std::pair<i64, uint32_t>> best_root(Point q) const {
    if (!in_domain(q)) return std::nullopt;
    // A decomposition point is never strictly between the walls of a trapezoid holding it, so
    // find() misses it: look it up only then (most queries are not vertices).
    const uint32_t t = find(q);
    if (t != kNone) return evaluate(t, q);
    const uint32_t v = point_id(q);
    if (v == kNone) return std::nullopt;
    std::optional<std::pair<i64, uint32_t>> out;
    for (uint32_t r = root_begin[v]; r < root_begin[v + 1]; ++r)
      if (!out || roots[r].d < out->first) out = {roots[r].d, r};
    return out;
  }

  // ------------------------------------------------------------------------------------------
  // Cells. Inside trapezoid i the distance is the least of its four staircases' rays. Between
  // consecutive thresholds (a horizontal band) each staircase has one active ray, a linear
  // function with gradient (+-1, +-1); so the band splits into at most four convex pieces, cut
  // by horizontal, vertical and diagonal bisectors (the gradients always differ, so ties are
  // lines, never areas: L1's tied areas were already settled in the staircases, by key_less).
  struct Cand {
    int gx, gy;   // gradient
    i64 c;        // value = gx x + gy y + c
    uint32_t root;
  };
  // Keep the part of convex polygon `poly` where a x + b y + c <= 0.
  static void clip(std::vector<RPoint>& poly, const Rational& a, const Rational& b, const Rational& c) {
    const std::size_t n = poly.size();
    if (n == 0) return;
    std::vector<Rational> s(n);
    bool all_in = true, all_out = true;
    for (std::size_t i = 0; i < n; ++i) {
      s[i] = a * poly[i].x + b * poly[i].y + c;
      all_in = all_in && s[i] <= 0;
      all_out = all_out && s[i] > 0;
    }
    if (all_in) return;
    if (all_out) {
      poly.clear();
      return;
    }
    std::vector<RPoint> out;
    out.reserve(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
      const RPoint& p = poly[i];
      const RPoint& q = poly[(i + 1) % n];
      const Rational &sp = s[i], &sq = s[(i + 1) % n];
      if (sp <= 0) out.push_back(p);
      if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
        const Rational f = sp / (sp - sq);
        out.push_back({p.x + (q.x - p.x) * f, p.y + (q.y - p.y) * f});
      }
    }
    poly.clear();
    for (RPoint& v : out)
      if (poly.empty() || !(poly.back() == v)) poly.push_back(std::move(v));
    while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
  }
  static bool has_area(const std::vector<RPoint>& poly) { return poly.size() >= 3 && twice_signed_area(poly) > 0; }

  void trapezoid_pieces(uint32_t i, bool by_root, std::vector<L1Map::Piece>& out) const {
    const Trap& t = traps[i];
    if (t.pl.x == t.pr.x) return;  // width 0: no area
    auto y_q = [](Point a, Point b, i64 x) {  // y of segment ab (not vertical) at x, exact
      return Q{i64{a.y} * (i64{b.x} - x) + i64{b.y} * (x - a.x), i64{b.x} - a.x};
    };
    auto rq = [](Q q) { return Rational(q.n, q.d); };
    const Q bl = y_q(t.b0, t.b1, t.pl.x), br = y_q(t.b0, t.b1, t.pr.x);
    const Q tl = y_q(t.t0, t.t1, t.pl.x), tr = y_q(t.t0, t.t1, t.pr.x);
    std::vector<RPoint> poly{{Rational(t.pl.x), rq(bl)},
                             {Rational(t.pr.x), rq(br)},
                             {Rational(t.pr.x), rq(tr)},
                             {Rational(t.pl.x), rq(tl)}};
    if (poly[1] == poly[2]) poly.erase(poly.begin() + 2);
    if (poly[0] == poly.back()) poly.pop_back();
    // The four staircases: ranges and the part of each ray's value that is fixed.
    struct Stair {
      uint32_t b, e;
      bool up;
      int gx;
      i64 c0;  // value = ray.K + gx x + (up ? y : -y) + c0
    };
    const Stair st4[4] = {{t.lo[0], t.lo[1], true, 1, -i64{t.pl.x}},
                          {t.lo[1], t.lo[2], false, 1, -i64{t.pl.x}},
                          {t.ro[0], t.ro[1], true, -1, i64{t.pr.x}},
                          {t.ro[1], t.ro[2], false, -1, i64{t.pr.x}}};
    auto emit = [&](std::vector<RPoint>&& ring, uint32_t root) {
      if (!has_area(ring)) return;
      const Root& r = roots[root];
      out.push_back({std::move(ring), r.source, r.p, r.d});
    };
    // Every ray of the trapezoid from one source: one piece (BySource), no bands needed.
    uint32_t any = kNone;
    bool one_source = true, one_root = true;
    for (const Stair& s : st4)
      for (uint32_t k = s.b; k < s.e; ++k) {
        const uint32_t r = rays[k].root;
        if (any == kNone) any = r;
        one_root = one_root && r == any;
        one_source = one_source && roots[r].source == roots[any].source;
      }
    if (any == kNone) return;  // no ray: walled in (a reached trapezoid is reached everywhere)
    if (one_root || (!by_root && one_source)) {
      emit(std::move(poly), any);
      return;
    }
    const Q ylo = qmin(bl, br), yhi = qmax(tl, tr);
    // Band limits: the trapezoid's lowest and highest y, and the thresholds strictly between.
    std::vector<Q> lim{ylo};
    for (const Stair& s : st4)
      for (uint32_t k = s.b; k < s.e; ++k)
        if (cmp(rays[k].t(), ylo) > 0 && cmp(rays[k].t(), yhi) < 0) lim.push_back(rays[k].t());
    std::sort(lim.begin() + 1, lim.end(), [](Q a, Q b) { return cmp(a, b) < 0; });
    lim.erase(std::unique(lim.begin(), lim.end(), [](Q a, Q b) { return cmp(a, b) == 0; }), lim.end());
    lim.push_back(yhi);
    // Active ray of each staircase in the band (a, b): up: the last with t <= a; down: the
    // last (thresholds descending) with t >= b. Bands rise, so each staircase is walked once:
    // an up staircase's cursor only moves on, a down staircase's only back.
    uint32_t cursor[4];
    for (int s = 0; s < 4; ++s) cursor[s] = st4[s].up ? st4[s].b : st4[s].e;
    auto active = [&](int si, Q a, Q b) -> uint32_t {
      const Stair& s = st4[si];
      uint32_t& c = cursor[si];
      if (s.up) {
        while (c < s.e && cmp(rays[c].t(), a) <= 0) ++c;  // [s.b, c): t <= a
        return c > s.b ? c - 1 : kNone;
      }
      while (c > s.b && cmp(rays[c - 1].t(), b) < 0) --c;  // [s.b, c): t >= b
      return c > s.b ? c - 1 : kNone;
    };
    // Bands, merged while their active rays stay the same. Consecutive bands that are one
    // root's (ByRoot) or one source's (BySource) become one slab: fewer, larger pieces.
    struct Run {
      Q ya, yb;
      uint32_t root = kNone;
    } run;
    auto flush = [&] {
      if (run.root == kNone) return;
      std::vector<RPoint> slab = poly;
      if (cmp(run.ya, ylo) > 0) clip(slab, 0, -1, rq(run.ya));  // y >= ya
      if (cmp(run.yb, yhi) < 0) clip(slab, 0, 1, -rq(run.yb));  // y <= yb
      emit(std::move(slab), run.root);
      run.root = kNone;
    };
    // Band i is (lim[i], lim[i + 1]); the active rays of every band, in one walk.
    const std::size_t nb = lim.size() - 1;
    std::vector<std::array<uint32_t, 4>> acts(nb);
    for (std::size_t i = 0; i < nb; ++i)
      for (int s = 0; s < 4; ++s) acts[i][s] = active(s, lim[i], lim[i + 1]);
    std::size_t band = 0;
    while (band < nb) {
      const std::array<uint32_t, 4> act = acts[band];
      std::size_t end = band + 1;
      while (end < nb && acts[end] == act) ++end;
      const Q ya = lim[band], yb = lim[end];
      band = end;
      std::vector<Cand> cands;
      for (int s = 0; s < 4; ++s)
        if (act[s] != kNone) {
          const Ray& r = rays[act[s]];
          cands.push_back({st4[s].gx, st4[s].up ? 1 : -1, r.K + st4[s].c0, r.root});
        }
      if (cands.empty()) throw std::logic_error("spm: a band of a reached trapezoid has no ray");
      // A candidate no lower than another at every corner of the band's bounding box
      // [xl, xr] x [ya, yb] is no lower anywhere in the band (their difference is linear): it
      // wins nowhere with area, so it is dropped. Exact in __int128, scaled by the thresholds'
      // denominators. (Two candidates never dominate each other: their gradients differ.)
      if (cands.size() > 1) {
        auto diff_at = [&](const Cand& j, const Cand& i, i64 x, Q y) {  // sign of f_j - f_i at (x, y)
          const i128 v = i128{j.gx - i.gx} * x * y.d + i128{j.gy - i.gy} * y.n + (i128{j.c} - i.c) * y.d;
          return v < 0 ? -1 : (v > 0 ? 1 : 0);
        };
        std::vector<Cand> kept;
        for (std::size_t i = 0; i < cands.size(); ++i) {
          bool dominated = false;
          for (std::size_t j = 0; j < cands.size() && !dominated; ++j)
            dominated = j != i && diff_at(cands[j], cands[i], t.pl.x, ya) <= 0 && diff_at(cands[j], cands[i], t.pr.x, ya) <= 0 &&
                        diff_at(cands[j], cands[i], t.pl.x, yb) <= 0 && diff_at(cands[j], cands[i], t.pr.x, yb) <= 0;
          if (!dominated) kept.push_back(cands[i]);
        }
        cands = std::move(kept);
      }
      bool uniform = true;
      for (const Cand& c : cands)
        uniform = uniform && (by_root ? c.root == cands[0].root : roots[c.root].source == roots[cands[0].root].source);
      if (uniform) {
        const bool joins = run.root != kNone && (by_root ? run.root == cands[0].root
                                                         : roots[run.root].source == roots[cands[0].root].source);
        if (joins) {
          run.yb = yb;
        } else {
          flush();
          run = {ya, yb, cands[0].root};
        }
        continue;
      }
      flush();
      std::vector<RPoint> b = poly;
      if (cmp(ya, ylo) > 0) clip(b, 0, -1, rq(ya));   // y >= ya
      if (cmp(yb, yhi) < 0) clip(b, 0, 1, -rq(yb));   // y <= yb
      if (!has_area(b)) continue;
      for (std::size_t a = 0; a < cands.size(); ++a) {
        std::vector<RPoint> p = b;
        for (std::size_t o = 0; o < cands.size() && p.size() >= 3; ++o) {
          if (o == a) continue;
          const Cand &x = cands[a], &y = cands[o];
          clip(p, x.gx - y.gx, x.gy - y.gy, Rational(x.c) - y.c);
        }
        emit(std::move(p), cands[a].root);
      }
    }
    flush();
  }

  bool is_free(Point q) const {
    if (!in_domain(q)) return false;
    if (find(q) != kNone) return true;
    const uint32_t v = point_id(q);
    return v != kNone && (src_at[v] != kNone || !wf.vertex_wedges(q).empty());
  }
};

L1Map::L1Map(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources)
    : impl_(std::make_unique<Impl>(domain, obstacles, sources)) {}
L1Map::~L1Map() = default;
L1Map::L1Map(L1Map&&) noexcept = default;
L1Map& L1Map::operator=(L1Map&&) noexcept = default;

bool L1Map::is_free(Point q) const { return impl_->is_free(q); }

std::optional<L1Map::Answer> L1Map::locate(Point q) const {
  const auto b = impl_->best_root(q);
  if (!b) return std::nullopt;
  const Root& r = impl_->roots[b->second];
  return Answer{b->first, r.source, r.p, b->second};
}

std::vector<Point> L1Map::path(Point q) const {
  const auto a = locate(q);
  return a ? path(q, *a) : std::vector<Point>{};
}

std::vector<Point> L1Map::path(Point q, const Answer& a) const {
  if (a.root_id >= impl_->roots.size()) return {};
  const Root& r = impl_->roots[a.root_id];
  std::vector<Point> out;
  if (r.wedge == kNone)
    out.push_back(r.p);
  else
    out = impl_->wf.wedge_path(r.p, r.wedge);
  if (out.empty() || out.back() != q) out.push_back(q);
  return out;
}

std::vector<L1Map::Trapezoid> L1Map::trapezoids() const {
  const Impl& m = *impl_;
  std::vector<Trapezoid> out;
  out.reserve(m.traps.size());
  for (const Trap& t : m.traps)
    out.push_back({m.P[t.L], m.P[t.R], {m.P[m.edges[t.bot].l], m.P[m.edges[t.bot].r]},
                   {m.P[m.edges[t.top].l], m.P[m.edges[t.top].r]}});
  return out;
}

Rational twice_signed_area(const std::vector<RPoint>& ring) {
  Rational a2 = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const RPoint &p = ring[i], &q = ring[(i + 1) % n];
    a2 += p.x * q.y - q.x * p.y;
  }
  return a2;
}

std::vector<L1Map::Piece> L1Map::pieces(Detail detail) const {
  std::vector<Piece> out;
  for (uint32_t i = 0; i < impl_->traps.size(); ++i) impl_->trapezoid_pieces(i, detail == Detail::ByRoot, out);
  return out;
}

const L1Map::Stats& L1Map::stats() const { return impl_->st; }

std::size_t L1Map::memory_bytes() const {
  const Impl& m = *impl_;
  return m.wf.memory_bytes() + m.P.capacity() * sizeof(Point) + m.src_at.capacity() * sizeof(uint32_t) +
         m.edges.capacity() * sizeof(Edge) + m.traps.capacity() * sizeof(Trap) + m.rays.capacity() * sizeof(Ray) +
         m.roots.capacity() * sizeof(Root) + m.root_begin.capacity() * sizeof(uint32_t) +
         m.tree_pages.bytes();  // the R-tree's arena
}

}  // namespace taut::router
