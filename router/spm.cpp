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
#include <type_traits>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "geom/index.h"
#include "geom/normalize.h"
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

// Keep the part of convex polygon `poly` (points of an exact field N: Rational, RationalRoot2)
// where a x + b y + c <= 0: Sutherland-Hodgman against one line, exact.
// N: the points' coordinate type; the coefficients convert to it.
template <class Pt, class N = std::remove_cvref_t<decltype(Pt::x)>>
void clip_convex(std::vector<Pt>& poly, const std::type_identity_t<N>& a, const std::type_identity_t<N>& b,
                 const std::type_identity_t<N>& c) {
  const std::size_t n = poly.size();
  if (n == 0) return;
  std::vector<N> v(n);
  std::vector<int> sg(n);
  bool all_in = true, all_out = true;
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = a * poly[i].x + b * poly[i].y + c;
    sg[i] = v[i].sign();
    all_in = all_in && sg[i] <= 0;
    all_out = all_out && sg[i] > 0;
  }
  if (all_in) return;
  if (all_out) {
    poly.clear();
    return;
  }
  std::vector<Pt> out;
  out.reserve(n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const Pt& p = poly[i];
    const Pt& q = poly[(i + 1) % n];
    const int sp = sg[i], sq = sg[(i + 1) % n];
    if (sp <= 0) out.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const N f = v[i] / (v[i] - v[(i + 1) % n]);
      out.push_back({p.x + (q.x - p.x) * f, p.y + (q.y - p.y) * f});
    }
  }
  poly.clear();
  for (Pt& w : out)
    if (poly.empty() || !(poly.back() == w)) poly.push_back(std::move(w));
  while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
}

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

// Values: i64 for L1; geom::Root2 for the octilinear map's frames, whose x and y steps weigh 1
// and sqrt2 (or sqrt2 and 1). scale(d, w): d steps of weight w.
inline i64 scale(i64 d, i64 w) { return d * w; }
inline geom::Root2 scale(i64 d, geom::Root2 w) { return {d * w.a, d * w.b}; }

// A ray on a side: value wy y + K (up: for y >= t) or -wy y + K (down: for y <= t), plus wx
// times the horizontal distance from the side inside the trapezoid.
template <class V>
struct RayT {
  V K;
  i64 tn;
  uint32_t td;
  uint32_t root;
  Q t() const { return {tn, static_cast<i64>(td)}; }
  void set_t(Q q) {
    tn = q.n;
    td = static_cast<uint32_t>(q.d);
  }
};

template <class V>
struct RootT {
  Point p;
  V d;
  uint32_t source;
  uint32_t wedge;  // index into vertex_wedges(p); kNone for a source
};

struct Edge {
  uint32_t l, r;  // point ids, l lex-before r
  bool free_above;
  uint32_t src = kNone;  // an edge of a shape source: its source index (distance 0 along it)
};

// A "flat" ray: the horizontal front of a vertical edge of a shape source. Value K (plus wx
// times the horizontal distance from the side inside the trapezoid) for every y in [lo, hi]:
// each such point is reached straight across from the edge.
template <class V>
struct FlatT {
  V K;
  Q lo, hi;
  uint32_t src;
};
// The root of an answer that comes from a shape source's side (a front or a flat ray): no
// vertex; the answer names the foot point on the shape, which sees the query straight.
constexpr uint32_t kFootRoot = L1Map::kFootRoot;

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

// What queries read at random places goes on huge pages.
template <class T>
using HugeVector = std::vector<T, detail::HugePageAllocator<T>>;

// The sweep's ordered set of edges, kept for every point of the sweep at once: a treap made
// persistent by node copying (Driscoll, Sarnak, Sleator & Tarjan, "Making data structures
// persistent", 1989; Sarnak & Tarjan's planar point location, 1986). Version v is the set after
// the sweep has passed point v. Each node has one spare child pointer stamped with the version
// from which it replaces one of the two children; a node changed a second time is copied, and
// its parent is pointed at the copy (which may use the parent's spare, or copy it in turn).
// Nodes made during the current version are changed in place. A treap (priorities: a hash of
// the edge id) changes O(1) pointers per insert or erase in expectation, so the versions cost
// O(1) nodes each in expectation (measured: 3.1 nodes per edge), and a query reads O(log n)
// nodes with high probability over the priorities (measured: 11 on average at 10^6 vertices).
class PersistentEdges {
 public:
  struct Node {
    Point l, r;             // the edge's ends, for a query's test without another lookup
    uint32_t edge;
    uint32_t child[2];
    uint32_t spare_ver;     // kNone, or the version (low 31 bits) and side (top bit) of `spare`
    uint32_t spare;
  };

  // Start version v (versions increase by one, from 0).
  void begin_version(uint32_t v) {
    ver_ = v;
    first_of_ver_ = static_cast<uint32_t>(nodes_.size());
  }
  // End it: the current set is version v's.
  void end_version() { roots_.push_back(root_); }

  template <class Less>
  void insert(uint32_t edge, Point l, Point r, const Less& less) {
    nodes_.push_back(Node{l, r, edge, {kNone, kNone}, kNone, kNone});
    root_ = insert_at(root_, static_cast<uint32_t>(nodes_.size() - 1), less);
  }
  template <class Less>
  void erase(uint32_t edge, const Less& less) { root_ = erase_at(root_, edge, less); }

  // The highest edge of version v that q is above (strictly: `strict`) or on; kNone if none.
  uint32_t below(uint32_t v, Point q, bool strict) const {
    uint32_t x = roots_[v], best = kNone;
    while (x != kNone) {
      const Node& n = nodes_[x];
      const int o = geom::orientation(n.l, n.r, q);
      if (o > 0 || (o == 0 && !strict)) {
        best = n.edge;
        x = child(n, 1, v);
      } else {
        x = child(n, 0, v);
      }
    }
    return best;
  }
  // Renumbers the nodes in depth-first order from the roots of the versions in turn (every
  // pointer followed, spare ones too), so a node's subtree tends to follow it in memory: a query
  // reads each node once, top down, and most of them are then near the one before.
  void compact() {
    const uint32_t n = static_cast<uint32_t>(nodes_.size());
    std::vector<uint32_t> id(n, kNone), stack;
    uint32_t next = 0;
    for (const uint32_t r : roots_) {
      if (r == kNone || id[r] != kNone) continue;
      stack.push_back(r);
      while (!stack.empty()) {
        const uint32_t x = stack.back();
        stack.pop_back();
        if (id[x] != kNone) continue;
        id[x] = next++;
        const Node& nd = nodes_[x];
        for (const uint32_t c : {nd.spare, nd.child[1], nd.child[0]})  // left child first
          if (c != kNone && id[c] == kNone) stack.push_back(c);
      }
    }
    HugeVector<Node> out(next);
    for (uint32_t x = 0; x < n; ++x) {
      if (id[x] == kNone) continue;  // unreachable from every version (replaced in its own)
      Node nd = nodes_[x];
      for (uint32_t& c : nd.child)
        if (c != kNone) c = id[c];
      if (nd.spare != kNone) nd.spare = id[nd.spare];
      out[id[x]] = nd;
    }
    nodes_ = std::move(out);
    for (uint32_t& r : roots_)
      if (r != kNone) r = id[r];
    roots_.shrink_to_fit();
  }
  std::size_t bytes() const { return nodes_.capacity() * sizeof(Node) + roots_.capacity() * sizeof(uint32_t); }
  std::size_t nodes() const { return nodes_.size(); }

 private:
  static constexpr uint32_t kSide = 1u << 31;
  static uint32_t child(const Node& n, int side, uint32_t v) {
    if (n.spare_ver != kNone && (n.spare_ver & ~kSide) <= v && static_cast<int>(n.spare_ver >> 31) == side)
      return n.spare;
    return n.child[side];
  }
  uint32_t latest(uint32_t x, int side) const { return child(nodes_[x], side, ver_); }
  static uint64_t priority(uint32_t edge) {  // splitmix64: a fixed, well-mixed order
    uint64_t z = edge + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  bool higher(uint32_t a, uint32_t b) const {
    const uint64_t pa = priority(nodes_[a].edge), pb = priority(nodes_[b].edge);
    return pa != pb ? pa > pb : nodes_[a].edge > nodes_[b].edge;
  }
  // Points x's child `side` at y in the current version; returns the node that is x now (x, or
  // its copy, which the caller must link in place of x).
  uint32_t set_child(uint32_t x, int side, uint32_t y) {
    if (latest(x, side) == y) return x;
    Node& n = nodes_[x];
    if (x >= first_of_ver_) {
      n.child[side] = y;
      return x;
    }
    const uint32_t tag = ver_ | (side ? kSide : 0);
    if (n.spare_ver == kNone || n.spare_ver == tag) {
      n.spare_ver = tag;
      n.spare = y;
      return x;
    }
    Node c = n;
    c.child[0] = latest(x, 0);
    c.child[1] = latest(x, 1);
    c.child[side] = y;
    c.spare_ver = kNone;
    c.spare = kNone;
    nodes_.push_back(c);
    return static_cast<uint32_t>(nodes_.size() - 1);
  }
  template <class Less>
  uint32_t insert_at(uint32_t x, uint32_t n, const Less& less) {
    if (x == kNone) return n;
    const int side = less(nodes_[n].edge, nodes_[x].edge) ? 0 : 1;
    const uint32_t c = insert_at(latest(x, side), n, less);
    x = set_child(x, side, c);
    if (!higher(c, x)) return x;
    // Rotate c above x.
    x = set_child(x, side, latest(c, 1 - side));
    return set_child(c, 1 - side, x);
  }
  template <class Less>
  uint32_t erase_at(uint32_t x, uint32_t edge, const Less& less) {
    if (x == kNone) throw std::logic_error("spm: an edge to erase is not in the persistent set");
    if (nodes_[x].edge == edge) return join(latest(x, 0), latest(x, 1));
    const int side = less(edge, nodes_[x].edge) ? 0 : 1;
    return set_child(x, side, erase_at(latest(x, side), edge, less));
  }
  uint32_t join(uint32_t a, uint32_t b) {  // every edge of a below every edge of b
    if (a == kNone) return b;
    if (b == kNone) return a;
    if (higher(a, b)) return set_child(a, 1, join(latest(a, 1), b));
    return set_child(b, 0, join(a, latest(b, 0)));
  }

  HugeVector<Node> nodes_;
  std::vector<uint32_t> roots_;  // per version
  uint32_t root_ = kNone;
  uint32_t ver_ = 0, first_of_ver_ = 0;
};

// What a decomposition needs of a point's free wedges (in its own coordinates).
template <class V>
struct WedgeIn {
  Point lo;              // a point in the direction the wedge starts at (ccw)
  std::optional<V> d;    // distance, when reached
  uint32_t source;       // the source it was reached from
};

// The decomposition and its staircases, for one metric: V the value type, wx and wy the
// weights of a horizontal and a vertical step (1 and 1 for L1).
template <class V>
struct Decomp {
  using Ray = RayT<V>;
  using Root = RootT<V>;
  using Flat = FlatT<V>;
  geom::Box domain;  // queries outside it are not free (the octilinear frames: a bounding box)
  V wx, wy;
  HugeVector<Point> P;             // decomposition points, lex order (queries search it)
  std::vector<uint32_t> src_at;    // per point: the least source index there, or kNone
  std::vector<Edge> edges;
  HugeVector<Trap> traps;
  HugeVector<Ray> rays;
  HugeVector<Root> roots;
  std::vector<uint32_t> root_begin;  // per point: its roots [begin, next)
  std::vector<Point> root_lo;        // build only: per root, the ring neighbour its wedge starts at
  std::vector<bool> vertex_free;     // per point: a source, or an obstacle vertex with a free wedge
  // Shape sources (maps built with them only): per trapezoid, the flat rays of its left side
  // [f[0], f[1]) and of its right side [f[2], f[3]) in `flats`.
  bool has_shapes = false;
  std::vector<Flat> flats;
  std::vector<std::array<uint32_t, 4>> trap_flats;
  // Point location from the sweep itself: the edges crossing the sweep line after each point
  // (PersistentEdges), and per edge the trapezoids above it in sweep order.
  PersistentEdges pset;
  HugeVector<uint32_t> above_begin, above;
  // Where a query's x falls among the points: x_first[b] is the first point with x >= x_lo +
  // b * x_step (buckets of equal width, about two points each on average).
  HugeVector<uint32_t> x_first;
  i64 x_lo = 0, x_step = 1;
  // The fast path: a uniform grid over the domain; cell c lists the trapezoids whose bounding
  // box meets it, [cell_begin[c], cell_begin[c + 1]) of cell_traps, and is `complete` when no
  // trapezoid meeting it was left out (those spanning more than kGridSpan cells are).
  // Tuned on bench_spm (10^5 and 10^6 vertices, every generated kind): with one cell per
  // trapezoid, lists of up to 16 and trapezoids listed in up to 64 cells, 1-4 % of queries on
  // rects, polygons and maze layouts and 12 % on degenerate ones go on to the persistent search
  // (half a cell per trapezoid and lists of 12: 20 %).
  static constexpr i64 kGridSpan = 64;       // most cells a trapezoid is listed in
  static constexpr uint32_t kGridList = 16;  // longest list a query scans
  i64 gx0 = 0, gy0 = 0, gsx = 1, gsy = 1, gnx = 0, gny = 0;
  HugeVector<uint32_t> cell_begin, cell_traps;
  std::vector<bool> cell_complete;
  L1Map::Stats st;

  // polys: the wavefront's frame obstacles; free_src: the free sources (point, index); wedges(p):
  // the free wedges of ring vertex p, in vertex_wedges() order.
  template <class Wedges>
  // poly_src (empty, or one per polygon): the source index of a polygon that is a shape source
  // (its edges are at distance 0), else kNone.
  Decomp(const geom::Box& dom, std::span<const Polygon> polys, std::span<const std::pair<Point, uint32_t>> free_src,
         const Wedges& wedges, V wx_, V wy_, bool grid, double box_area = 1.0, std::span<const uint32_t> poly_src = {})
      : domain(dom), wx(wx_), wy(wy_) {
    build_points_and_edges(polys, free_src, poly_src);
    std::vector<SideRange> left, right;
    std::vector<uint32_t> close_begin, open_begin;
    std::vector<WallSide> closing, opening;
    sweep(left, right, close_begin, closing, open_begin, opening);
    make_roots(wedges);
    pass(true, left, right, close_begin, closing, open_begin, opening);
    pass(false, left, right, close_begin, closing, open_begin, opening);
    if (grid) build_grid(left, right, box_area);
    root_lo = {};
    rays.shrink_to_fit();  // grown by doubling: up to half of it was slack
    traps.shrink_to_fit();
    roots.shrink_to_fit();
    st.vertices = static_cast<i64>(P.size());
    st.trapezoids = static_cast<i64>(traps.size());
    st.rays = static_cast<i64>(rays.size());
    st.roots = static_cast<i64>(roots.size());
    st.location_nodes = static_cast<i64>(pset.nodes());
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
  void build_points_and_edges(std::span<const Polygon> polys, std::span<const std::pair<Point, uint32_t>> free_src,
                              std::span<const uint32_t> poly_src) {
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
    for (const auto& [p, i] : free_src) raw.push_back(p);
    std::sort(raw.begin(), raw.end());
    raw.erase(std::unique(raw.begin(), raw.end()), raw.end());
    P.assign(raw.begin(), raw.end());
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
    uint32_t ring_src = kNone;
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
          edges.push_back(P[u] < P[w] ? Edge{u, w, free_above, ring_src} : Edge{w, u, free_above, ring_src});
        }
      }
    };
    for (std::size_t i = 0; i < polys.size(); ++i) {
      const Polygon& p = polys[i];
      ring_src = poly_src.empty() ? kNone : poly_src[i];
      has_shapes = has_shapes || ring_src != kNone;
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
      struct is_transparent {};  // (a type: GCC calls an unused typedef in a template unused)
      const Decomp* s;
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
    std::vector<typename std::set<uint32_t, Below>::iterator> where(m, active.end());
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
      pset.begin_version(q);
      for (uint32_t e : E) {
        active.erase(where[e]);
        where[e] = active.end();
        pset.erase(e, below);
      }
      for (uint32_t e : S) {
        where[e] = active.insert(e).first;
        pset.insert(e, P[edges[e].l], P[edges[e].r], below);
      }
      pset.end_version();
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
    pset.compact();
    // x buckets (P is sorted by x first).
    x_lo = P.front().x;
    const i64 span = i64{P.back().x} - x_lo + 1;
    const i64 nb = std::max<i64>(1, static_cast<i64>(P.size() / 2));
    x_step = std::max<i64>(1, (span + nb - 1) / nb);
    const std::size_t buckets = static_cast<std::size_t>((span + x_step - 1) / x_step);
    x_first.assign(buckets + 1, 0);
    for (std::size_t bb = 0, i = 0; bb <= buckets; ++bb) {
      const i64 start = x_lo + static_cast<i64>(bb) * x_step;
      while (i < P.size() && P[i].x < start) ++i;
      x_first[bb] = static_cast<uint32_t>(i);
    }
    above_begin.assign(m + 1, 0);
    for (const Trap& t : traps) ++above_begin[t.bot + 1];
    for (uint32_t e = 0; e < m; ++e) above_begin[e + 1] += above_begin[e];
    above.resize(traps.size());
    {
      std::vector<uint32_t> fill(above_begin.begin(), above_begin.end() - 1);
      for (uint32_t t = 0; t < traps.size(); ++t) above[fill[traps[t].bot]++] = t;  // L ascending
    }
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
  template <class Wedges>
  void make_roots(const Wedges& wedges) {
    root_begin.assign(P.size() + 1, 0);
    vertex_free.assign(P.size(), false);
    for (uint32_t q = 0; q < P.size(); ++q) {
      root_begin[q] = static_cast<uint32_t>(roots.size());
      if (src_at[q] != kNone) {
        roots.push_back({P[q], V{}, src_at[q], kNone});
        root_lo.push_back(P[q]);
        vertex_free[q] = true;
        continue;
      }
      const std::vector<WedgeIn<V>> w = wedges(P[q]);
      vertex_free[q] = !w.empty();
      for (uint32_t k = 0; k < w.size(); ++k)
        if (w[k].d) {
          roots.push_back({P[q], *w[k].d, w[k].source, k});
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
    const V &da = roots[a.root].d, &db = roots[b.root].d;
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
    struct FlatIn {
      Flat f;
      Part part;
    };
    std::vector<In> in;
    std::vector<FlatIn> fin;
    std::vector<Ray> ups, downs;
    std::vector<Flat> fout;
    // Shape sources: the vertical edges whose free side faces this pass's new sides: left to
    // right, an edge with free space on its right (free below, in the sheared order) starts
    // flats at its upper end r; right to left, one with free space on its left at its lower end.
    std::vector<std::vector<uint32_t>> vertical_at;
    if (has_shapes) {
      vertical_at.resize(n);
      if (trap_flats.size() != traps.size()) trap_flats.assign(traps.size(), {0, 0, 0, 0});
      for (uint32_t e = 0; e < edges.size(); ++e) {
        const Edge& ed = edges[e];
        if (ed.src == kNone || P[ed.l].x != P[ed.r].x || ed.free_above == l2r) continue;
        vertical_at[l2r ? ed.r : ed.l].push_back(e);
      }
    }
    auto clip = [](Flat& f, const SideRange& at) {
      f.lo = qmax(f.lo, at.lo);
      f.hi = qmin(f.hi, at.hi);
      return cmp(f.lo, f.hi) <= 0;
    };
    for (uint32_t step = 0; step < n; ++step) {
      const uint32_t q = l2r ? step : n - 1 - step;
      const WallSide* src = l2r ? closing.data() + close_begin[q] : opening.data() + open_begin[q];
      const WallSide* src_end = l2r ? closing.data() + close_begin[q + 1] : opening.data() + open_begin[q + 1];
      const WallSide* dst = l2r ? opening.data() + open_begin[q] : closing.data() + close_begin[q];
      const WallSide* dst_end = l2r ? opening.data() + open_begin[q + 1] : closing.data() + close_begin[q + 1];
      if (dst == dst_end) continue;
      in.clear();
      fin.clear();
      for (const WallSide* s = src; s != src_end; ++s) {
        if (s->part == kPoint) continue;
        const Trap& t = traps[s->trap];
        const uint32_t* o = l2r ? t.lo : t.ro;
        const SideRange& at = l2r ? right[s->trap] : left[s->trap];  // the side on this wall
        const i64 w = i64{P[t.R].x} - P[t.L].x;
        for (uint32_t i = o[0]; i < o[2]; ++i) {
          Ray r = rays[i];
          const bool up = i < o[1];
          r.K += scale(w, wx);
          if (up) {
            if (cmp(r.t(), at.hi) > 0) continue;
            r.set_t(qmax(r.t(), at.lo));
          } else {
            if (cmp(r.t(), at.lo) < 0) continue;
            r.set_t(qmin(r.t(), at.hi));
          }
          in.push_back({r, up, s->part});
        }
        if (!has_shapes) continue;
        const auto& tf = trap_flats[s->trap];
        for (uint32_t i = tf[l2r ? 0 : 2]; i < tf[l2r ? 1 : 3]; ++i) {
          Flat f = flats[i];
          f.K += scale(w, wx);
          if (clip(f, at)) fin.push_back({f, s->part});
        }
        // A trapezoid on a shape's horizontal or 45-degree edge: its front (the distance
        // straight down to its bottom edge, or up to its top) goes on past this wall as the
        // rays of the edge's point on the wall (distance 0, a root of its own).
        for (const bool bottom : {true, false}) {
          const Edge& e = edges[bottom ? t.bot : t.top];
          if (e.src == kNone || P[e.l].x == P[e.r].x) continue;
          const i64 y = floor_of(bottom ? at.lo : at.hi);  // an integer: the edge is at 0 or 45 degrees
          const uint32_t root = static_cast<uint32_t>(roots.size());
          roots.push_back({Point{P[q].x, static_cast<geom::Coord>(y)}, V{}, e.src, kNone});
          if (bottom)
            in.push_back({Ray{V{} - scale(y, wy), y, 1, root}, true, s->part});
          else
            in.push_back({Ray{V{} + scale(y, wy), y, 1, root}, false, s->part});
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
          const i64 y = P[q].y;
          const V dr = roots[root].d;
          ups.push_back({dr - scale(y, wy), y, 1, root});
          downs.push_back({dr + scale(y, wy), y, 1, root});
        }
        Trap& t = traps[d->trap];
        staircase(ups, downs, l2r ? t.lo : t.ro);
        if (!has_shapes) continue;
        fout.clear();
        for (const FlatIn& x : fin) {
          if (!compatible(x.part, d->part)) continue;
          Flat f = x.f;
          if (clip(f, at)) fout.push_back(f);
        }
        // A shape's vertical edge ending here, its free side towards this side: every point of
        // it is at distance 0, and the side's points level with it are reached straight across.
        const Part facing = l2r ? kLower : kUpper;
        if (d->part == facing || d->part == kJoined)
          for (const uint32_t e : vertical_at[q]) {
            Flat f{V{}, Q{P[edges[e].l].y, 1}, Q{P[edges[e].r].y, 1}, edges[e].src};
            if (clip(f, at)) fout.push_back(f);
          }
        // Keep a flat unless another covers its whole range for no more.
        auto& tf = trap_flats[d->trap];
        if (flats.size() + fout.size() >= std::numeric_limits<uint32_t>::max())
          throw std::length_error("the shortest path map needs more than 2^32 flat rays");
        tf[l2r ? 0 : 2] = static_cast<uint32_t>(flats.size());
        for (std::size_t a = 0; a < fout.size(); ++a) {
          bool covered = false;
          for (std::size_t b = 0; b < fout.size() && !covered; ++b)
            covered = b != a && !(fout[a].K < fout[b].K) && cmp(fout[b].lo, fout[a].lo) <= 0 &&
                      cmp(fout[a].hi, fout[b].hi) <= 0 && (fout[b].K < fout[a].K || b < a);
          if (!covered) flats.push_back(fout[a]);
        }
        tf[l2r ? 1 : 3] = static_cast<uint32_t>(flats.size());
      }
    }
  }

  // The grid: about one cell per trapezoid, cells shaped like the domain. Each trapezoid's
  // box (exact integer bounds of its closure: x between its walls, y from the floor of its
  // lowest corner height to the ceiling of its highest) is listed in every cell it meets.
  void build_grid(const std::vector<SideRange>& left, const std::vector<SideRange>& right, double box_area) {
    const i64 w = i64{domain.hi.x} - domain.lo.x + 1, h = i64{domain.hi.y} - domain.lo.y + 1;
    // About one cell per trapezoid of the domain's own area: `domain` may be a bounding box
    // `box_area` times larger (the octilinear frames' parallelograms), whose cells outside hold
    // nothing.
    const double cells = std::max<double>(1.0, static_cast<double>(traps.size()) * box_area);
    const double aspect = static_cast<double>(w) / static_cast<double>(h);
    gnx = std::clamp<i64>(static_cast<i64>(std::sqrt(cells * aspect)), 1, w);
    gny = std::clamp<i64>(static_cast<i64>(cells / static_cast<double>(gnx)), 1, h);
    gsx = (w + gnx - 1) / gnx;
    gsy = (h + gny - 1) / gny;
    gnx = (w + gsx - 1) / gsx;
    gny = (h + gsy - 1) / gsy;
    gx0 = domain.lo.x;
    gy0 = domain.lo.y;
    const std::size_t ncell = static_cast<std::size_t>(gnx * gny);
    struct Span {
      i64 cx0, cx1, cy0, cy1;
    };
    auto span = [&](uint32_t i) {
      const Trap& t = traps[i];
      const i64 y0 = std::max<i64>(domain.lo.y, std::min(floor_of(left[i].lo), floor_of(right[i].lo)));
      const i64 y1 = std::min<i64>(domain.hi.y, std::max(ceil_of(left[i].hi), ceil_of(right[i].hi)));
      // (trapezoids lie in the domain; the clamps only guard the indices)
      auto cx = [&](i64 x) { return std::clamp<i64>((x - gx0) / gsx, 0, gnx - 1); };
      auto cy = [&](i64 y) { return std::clamp<i64>((y - gy0) / gsy, 0, gny - 1); };
      return Span{cx(t.pl.x), cx(t.pr.x), cy(y0), cy(y1)};
    };
    auto listed = [](const Span& sp) { return (sp.cx1 - sp.cx0 + 1) * (sp.cy1 - sp.cy0 + 1) <= kGridSpan; };
    // Trapezoids left out are counted per cell with a 2-D difference array.
    std::vector<int64_t> missing(static_cast<std::size_t>((gnx + 1) * (gny + 1)), 0);
    auto at = [&](i64 cx, i64 cy) -> int64_t& { return missing[static_cast<std::size_t>(cy * (gnx + 1) + cx)]; };
    cell_begin.assign(ncell + 1, 0);
    for (uint32_t i = 0; i < traps.size(); ++i) {
      const Span sp = span(i);
      if (!listed(sp)) {
        ++at(sp.cx0, sp.cy0);
        --at(sp.cx1 + 1, sp.cy0);
        --at(sp.cx0, sp.cy1 + 1);
        ++at(sp.cx1 + 1, sp.cy1 + 1);
        continue;
      }
      for (i64 cy = sp.cy0; cy <= sp.cy1; ++cy)
        for (i64 cx = sp.cx0; cx <= sp.cx1; ++cx) ++cell_begin[static_cast<std::size_t>(cy * gnx + cx) + 1];
    }
    for (std::size_t c = 0; c < ncell; ++c) cell_begin[c + 1] += cell_begin[c];
    cell_traps.resize(cell_begin[ncell]);
    {
      std::vector<uint32_t> fill(cell_begin.begin(), cell_begin.end() - 1);
      for (uint32_t i = 0; i < traps.size(); ++i) {
        const Span sp = span(i);
        if (!listed(sp)) continue;
        for (i64 cy = sp.cy0; cy <= sp.cy1; ++cy)
          for (i64 cx = sp.cx0; cx <= sp.cx1; ++cx) cell_traps[fill[static_cast<std::size_t>(cy * gnx + cx)]++] = i;
      }
    }
    cell_complete.assign(ncell, false);
    for (i64 cy = 0; cy < gny; ++cy)
      for (i64 cx = 0; cx < gnx; ++cx) {
        if (cx > 0) at(cx, cy) += at(cx - 1, cy);
        if (cy > 0) at(cx, cy) += at(cx, cy - 1);
        if (cx > 0 && cy > 0) at(cx, cy) -= at(cx - 1, cy - 1);
        cell_complete[static_cast<std::size_t>(cy * gnx + cx)] = at(cx, cy) == 0;
      }
  }

  static bool holds(const Trap& t, Point q) {
    return t.pl < q && q < t.pr && geom::orientation(t.b0, t.b1, q) >= 0 && geom::orientation(t.t0, t.t1, q) <= 0;
  }
  // The trapezoid whose closure holds q (q not a decomposition point); kNone if none (q is not
  // free). The trapezoids partition free space (open across walls, closed along blockage
  // edges, which have free space on one side only), so at most one holds q. The edges crossing
  // the sweep line when it reaches q are version k of the persistent set, k the last point
  // before q (found in q's x bucket); the trapezoid holding q lies above the highest of them
  // that q is on or above, or, when q is on that edge and its free side is below, above the
  // highest that q is strictly above. Per edge the trapezoids above it are in sweep order: the
  // one open at k is the last that opened at or before k. First, though, q's grid cell: when
  // its list is short and complete, it holds the answer (kNone included).
  uint32_t find(Point q) const {
    if (gnx > 0 && q.x >= gx0 && q.y >= gy0 && q.x <= domain.hi.x && q.y <= domain.hi.y) {
      const std::size_t c = static_cast<std::size_t>(((i64{q.y} - gy0) / gsy) * gnx + (i64{q.x} - gx0) / gsx);
      const uint32_t b = cell_begin[c], e = cell_begin[c + 1];
      if (e - b <= kGridList) {
        for (uint32_t i = b; i < e; ++i)
          if (holds(traps[cell_traps[i]], q)) return cell_traps[i];
        if (cell_complete[c]) return kNone;
      }
    }
    return find_persistent(q);
  }
  uint32_t find_persistent(Point q) const {
    if (q.x < x_lo) return kNone;
    const std::size_t b = static_cast<std::size_t>((i64{q.x} - x_lo) / x_step);
    if (b + 1 >= x_first.size()) return kNone;
    const auto it = std::upper_bound(P.begin() + x_first[b], P.begin() + x_first[b + 1], q);
    if (it == P.begin()) return kNone;
    const uint32_t k = static_cast<uint32_t>(it - P.begin() - 1);
    auto trap_above = [&](uint32_t e) -> uint32_t {
      if (e == kNone) return kNone;
      const auto lo = above.begin() + above_begin[e], hi = above.begin() + above_begin[e + 1];
      const auto j = std::upper_bound(lo, hi, k, [&](uint32_t kk, uint32_t t) { return kk < traps[t].L; });
      if (j == lo) return kNone;
      const uint32_t t = *std::prev(j);
      return holds(traps[t], q) ? t : kNone;
    };
    const uint32_t e = pset.below(k, q, false);
    const uint32_t t = trap_above(e);
    if (t != kNone || e == kNone) return t;
    if (geom::orientation(P[edges[e].l], P[edges[e].r], q) != 0) return kNone;
    return trap_above(pset.below(k, q, true));
  }

  // The shape sides trapezoid i sees straight, as linear candidates (value gx x + gy y + c, root
  // kFootRoot): the fronts of its bottom and top edges when they are a shape's horizontal or
  // 45-degree sides (over all of it: f(c, -, -, false)), then the flats of its left and right
  // sides (for y in [lo, hi]: f(c, lo, hi, true)). L1 maps only (V = i64).
  template <class F>
  void side_candidates(uint32_t i, F&& f) const {
    if (!has_shapes) return;
    const Trap& t = traps[i];
    for (const bool bottom : {true, false}) {
      const Edge& e = edges[bottom ? t.bot : t.top];
      const Point a = P[e.l], b = P[e.r];
      if (e.src == kNone || a.x == b.x) continue;
      const int sl = static_cast<int>((i64{b.y} - a.y) / (i64{b.x} - a.x));  // 0 or +-1
      // bottom: y - (a.y + sl (x - a.x)); top: the opposite
      const int sg = bottom ? 1 : -1;
      f(Cand{-sg * sl, sg, sg * (i64{sl} * a.x - a.y), kFootRoot, e.src, {a, b}}, Q{}, Q{}, false);
    }
    const auto& tf = trap_flats[i];
    for (int side = 0; side < 2; ++side)
      for (uint32_t k = tf[2 * side]; k < tf[2 * side + 1]; ++k) {
        const Flat& fl = flats[k];
        const i64 x0 = side == 0 ? i64{t.pl.x} - fl.K : i64{t.pr.x} + fl.K;  // the vertical side's x
        const Point s0{static_cast<geom::Coord>(x0), static_cast<geom::Coord>(floor_of(fl.lo))};
        const Point s1{static_cast<geom::Coord>(x0), static_cast<geom::Coord>(ceil_of(fl.hi))};
        // side 0: K + (x - pl.x) = x - x0; side 1: x0 - x
        f(Cand{side == 0 ? 1 : -1, 0, side == 0 ? -x0 : x0, kFootRoot, fl.src, {s0, s1}}, fl.lo, fl.hi, true);
      }
  }

  // The answer at a point: its value and root, or (root kFootRoot) the foot on a shape source
  // that sees it straight and that source.
  struct Best {
    V value;
    uint32_t root;
    Point foot{};
    uint32_t src = kNone;
  };
  // Best ray at q inside trapezoid i.
  std::optional<Best> evaluate(uint32_t i, Point q) const {
    const Trap& t = traps[i];
    std::optional<Ray> best;
    V best_v{};
    auto consider = [&](const Ray& r, V v) {
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
      const V dx = scale(side == 0 ? i64{q.x} - t.pl.x : i64{t.pr.x} - q.x, wx), y_up = scale(q.y, wy);
      // up: thresholds ascending; the last with t <= y
      auto ub = std::upper_bound(rays.begin() + o[0], rays.begin() + o[1], y,
                                 [](const Q& yy, const Ray& r) { return cmp(yy, r.t()) < 0; });
      if (ub != rays.begin() + o[0]) {
        const Ray& r = *std::prev(ub);
        consider(r, r.K + y_up + dx);
      }
      // down: thresholds descending; the last with t >= y
      auto db = std::upper_bound(rays.begin() + o[1], rays.begin() + o[2], y,
                                 [](const Q& yy, const Ray& r) { return cmp(yy, r.t()) > 0; });
      if (db != rays.begin() + o[1]) {
        const Ray& r = *std::prev(db);
        consider(r, r.K - y_up + dx);
      }
    }
    std::optional<Best> out;
    if (best) out = Best{best_v, best->root};
    if constexpr (std::is_same_v<V, i64>) {
      if (!has_shapes) return out;
      // A foot on a shape wins only when strictly nearer: on a tie a root (distance >= 0,
      // preferred by the larger distance) sees q straight as well.
      auto foot = [&](i64 v, Point f, uint32_t src) {
        if (!out || v < out->value) out = Best{v, kFootRoot, f, src};
      };
      // A vertical side bounds only trapezoids of width 0: q on it, or not.
      for (const uint32_t e : {t.bot, t.top}) {
        const Point a = P[edges[e].l], b = P[edges[e].r];
        if (edges[e].src != kNone && a.x == b.x && q.x == a.x && a.y <= q.y && q.y <= b.y) foot(0, q, edges[e].src);
      }
      // The fronts and flats: the foot lies straight down or up (a front), or across (a flat).
      side_candidates(i, [&](const Cand& c, Q lo, Q hi, bool ranged) {
        if (ranged && (cmp(lo, y) > 0 || cmp(y, hi) > 0)) return;
        const i64 v = c.gx * i64{q.x} + c.gy * i64{q.y} + c.c;
        const Point f = c.gy != 0 ? Point{q.x, static_cast<geom::Coord>(q.y - c.gy * v)}
                                  : Point{static_cast<geom::Coord>(q.x - c.gx * v), q.y};
        foot(v, f, c.src);
      });
    }
    return out;
  }

  // The best root at q; nullopt if not free or unreached.
  std::optional<Best> best_root(Point q) const {
    if (!in_domain(q)) return std::nullopt;
    // A decomposition point is never strictly between the walls of a trapezoid holding it, so
    // find() misses it: look it up only then (most queries are not vertices).
    const uint32_t t = find(q);
    if (t != kNone) return evaluate(t, q);
    const uint32_t v = point_id(q);
    if (v == kNone) return std::nullopt;
    std::optional<Best> out;
    for (uint32_t r = root_begin[v]; r < root_begin[v + 1]; ++r)
      if (!out || roots[r].d < out->value) out = Best{roots[r].d, r};
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
    uint32_t root;     // kFootRoot: a shape's front or flat, from src, straight out of seg
    uint32_t src;
    geom::Segment seg;
  };
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
    // Shape sources: the fronts of the trapezoid's bottom and top edges (all of it), and the
    // flats of its two sides (each over its range of y): linear values as well.
    std::vector<Cand> fronts;
    struct FlatCand {
      Cand c;
      Q lo, hi;
    };
    std::vector<FlatCand> flat_cands;
    side_candidates(i, [&](const Cand& c, Q lo, Q hi, bool ranged) {
      if (ranged)
        flat_cands.push_back({c, lo, hi});
      else
        fronts.push_back(c);
    });
    auto source_of = [&](const Cand& c) { return c.root == kFootRoot ? c.src : roots[c.root].source; };
    auto same = [&](const Cand& a, const Cand& b) {  // ByRoot: one root (or one straight front)
      return by_root ? a.root == b.root && (a.root != kFootRoot || (a.seg == b.seg && a.gx == b.gx && a.gy == b.gy))
                     : source_of(a) == source_of(b);
    };
    auto emit = [&](std::vector<RPoint>&& ring, const Cand& c) {
      if (!has_area(ring)) return;
      if (c.root == kFootRoot) {
        out.push_back({std::move(ring), c.src, c.seg.a, 0, c.seg});
        return;
      }
      const Root& r = roots[c.root];
      out.push_back({std::move(ring), r.source, r.p, r.d, std::nullopt});
    };
    // Every ray of the trapezoid from one source: one piece (BySource), no bands needed.
    std::optional<Cand> any;
    bool one_source = true, one_root = fronts.empty() && flat_cands.empty();
    auto see = [&](const Cand& c) {
      if (!any) any = c;
      one_root = one_root && c.root == any->root;
      one_source = one_source && source_of(c) == source_of(*any);
    };
    for (const Stair& s : st4)
      for (uint32_t k = s.b; k < s.e; ++k) see({0, 0, 0, rays[k].root, kNone, {}});
    for (const Cand& c : fronts) see(c);
    for (const FlatCand& f : flat_cands) see(f.c);
    if (!any) return;  // no ray: walled in (a reached trapezoid is reached everywhere)
    if (one_root || (!by_root && one_source)) {
      emit(std::move(poly), *any);
      return;
    }
    const Q ylo = qmin(bl, br), yhi = qmax(tl, tr);
    // Band limits: the trapezoid's lowest and highest y, and the thresholds strictly between.
    std::vector<Q> lim{ylo};
    for (const Stair& s : st4)
      for (uint32_t k = s.b; k < s.e; ++k)
        if (cmp(rays[k].t(), ylo) > 0 && cmp(rays[k].t(), yhi) < 0) lim.push_back(rays[k].t());
    for (const FlatCand& f : flat_cands)
      for (const Q y : {f.lo, f.hi})
        if (cmp(y, ylo) > 0 && cmp(y, yhi) < 0) lim.push_back(y);
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
      std::optional<Cand> c;
    } run;
    auto flush = [&] {
      if (!run.c) return;
      std::vector<RPoint> slab = poly;
      if (cmp(run.ya, ylo) > 0) clip_convex(slab, 0, -1, rq(run.ya));  // y >= ya
      if (cmp(run.yb, yhi) < 0) clip_convex(slab, 0, 1, -rq(run.yb));  // y <= yb
      emit(std::move(slab), *run.c);
      run.c.reset();
    };
    // Band i is (lim[i], lim[i + 1]); the active rays (and flats) of every band, in one walk.
    const std::size_t nb = lim.size() - 1;
    std::vector<std::array<uint32_t, 6>> acts(nb);
    for (std::size_t i = 0; i < nb; ++i) {
      for (int s = 0; s < 4; ++s) acts[i][s] = active(s, lim[i], lim[i + 1]);
      for (int side = 0; side < 2; ++side) {  // the least flat of each side covering the band
        uint32_t bestf = kNone;
        for (uint32_t k = 0; k < flat_cands.size(); ++k) {
          const FlatCand& f = flat_cands[k];
          if ((f.c.gx == 1) != (side == 0) || cmp(f.lo, lim[i]) > 0 || cmp(lim[i + 1], f.hi) > 0) continue;
          if (bestf == kNone || f.c.c < flat_cands[bestf].c.c) bestf = k;  // one side: one gradient
        }
        acts[i][4 + side] = bestf;
      }
    }
    std::size_t band = 0;
    while (band < nb) {
      const std::array<uint32_t, 6> act = acts[band];
      std::size_t end = band + 1;
      while (end < nb && acts[end] == act) ++end;
      const Q ya = lim[band], yb = lim[end];
      band = end;
      std::vector<Cand> cands;
      for (int s = 0; s < 4; ++s)
        if (act[s] != kNone) {
          const Ray& r = rays[act[s]];
          cands.push_back({st4[s].gx, st4[s].up ? 1 : -1, r.K + st4[s].c0, r.root, kNone, {}});
        }
      for (const Cand& c : fronts) cands.push_back(c);
      for (int side = 0; side < 2; ++side)
        if (act[4 + side] != kNone) cands.push_back(flat_cands[act[4 + side]].c);
      if (cands.empty()) throw std::logic_error("spm: a band of a reached trapezoid has no ray");
      // A candidate no lower than another at every corner of the band's bounding box
      // [xl, xr] x [ya, yb] is no lower anywhere in the band (their difference is linear): it
      // wins nowhere with area, so it is dropped. Exact in __int128, scaled by the thresholds'
      // denominators. Two rays never tie on an area (their gradients differ); a shape's front
      // or flat may tie with a ray: the one listed first stays.
      if (cands.size() > 1) {
        auto diff_at = [&](const Cand& j, const Cand& i, i64 x, Q y) {  // sign of f_j - f_i at (x, y)
          const i128 v = i128{j.gx - i.gx} * x * y.d + i128{j.gy - i.gy} * y.n + (i128{j.c} - i.c) * y.d;
          return v < 0 ? -1 : (v > 0 ? 1 : 0);
        };
        std::vector<Cand> kept;
        for (std::size_t i = 0; i < cands.size(); ++i) {
          bool dominated = false;
          for (std::size_t j = 0; j < cands.size() && !dominated; ++j) {
            if (j == i) continue;
            const int d[4] = {diff_at(cands[j], cands[i], t.pl.x, ya), diff_at(cands[j], cands[i], t.pr.x, ya),
                              diff_at(cands[j], cands[i], t.pl.x, yb), diff_at(cands[j], cands[i], t.pr.x, yb)};
            const bool le = d[0] <= 0 && d[1] <= 0 && d[2] <= 0 && d[3] <= 0;
            const bool tie = d[0] == 0 && d[1] == 0 && d[2] == 0 && d[3] == 0;
            dominated = le && (!tie || j < i);
          }
          if (!dominated) kept.push_back(cands[i]);
        }
        cands = std::move(kept);
      }
      bool uniform = true;
      for (const Cand& c : cands) uniform = uniform && same(c, cands[0]);
      if (uniform) {
        if (run.c && same(*run.c, cands[0])) {
          run.yb = yb;
        } else {
          flush();
          run = {ya, yb, cands[0]};
        }
        continue;
      }
      flush();
      std::vector<RPoint> b = poly;
      if (cmp(ya, ylo) > 0) clip_convex(b, 0, -1, rq(ya));   // y >= ya
      if (cmp(yb, yhi) < 0) clip_convex(b, 0, 1, -rq(yb));   // y <= yb
      if (!has_area(b)) continue;
      for (std::size_t a = 0; a < cands.size(); ++a) {
        std::vector<RPoint> p = b;
        for (std::size_t o = 0; o < cands.size() && p.size() >= 3; ++o) {
          if (o == a) continue;
          const Cand &x = cands[a], &y = cands[o];
          // x's part: f_x <= f_y, and where they tie the earlier candidate's (strictly: the
          // later one keeps only f_x < f_y, a set of no area more than f_x <= f_y)
          clip_convex(p, x.gx - y.gx, x.gy - y.gy, Rational(x.c) - y.c);
        }
        emit(std::move(p), cands[a]);
      }
    }
    flush();
  }

  bool is_free(Point q) const {
    if (!in_domain(q)) return false;
    if (find(q) != kNone) return true;
    const uint32_t v = point_id(q);
    return v != kNone && vertex_free[v];
  }

  std::size_t memory_bytes() const {
    return P.capacity() * sizeof(Point) + src_at.capacity() * sizeof(uint32_t) + edges.capacity() * sizeof(Edge) +
           traps.capacity() * sizeof(Trap) + rays.capacity() * sizeof(Ray) + roots.capacity() * sizeof(Root) +
           root_begin.capacity() * sizeof(uint32_t) + vertex_free.capacity() / 8 + pset.bytes() +
           flats.capacity() * sizeof(Flat) + trap_flats.capacity() * sizeof(trap_flats[0]) +
           (above_begin.capacity() + above.capacity() + x_first.capacity() + cell_begin.capacity() +
            cell_traps.capacity()) * sizeof(uint32_t) + cell_complete.capacity() / 8;
  }
};

// The free sources (point, index), in input order.
template <class Wf>
std::vector<std::pair<Point, uint32_t>> free_sources(const Wf& wf, std::span<const Point> sources) {
  std::vector<std::pair<Point, uint32_t>> out;
  for (std::size_t i = 0; i < sources.size(); ++i)
    if (wf.is_free(sources[i])) out.push_back({sources[i], static_cast<uint32_t>(i)});
  return out;
}
template <class Wf>
Wf ran(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources) {
  Wf wf(domain, obstacles);
  wf.run(sources, {}, WavefrontStop::Never);
  return wf;
}

// The octilinear map's frames: (u, v) = A (x - cx, y - cy) with det A = +1; the inverse's
// columns are the frame's two orientations (u: the first, v: the second), one an axis (weight
// 1) and one a diagonal (weight sqrt2, on x when sqrt2_x). Between them they cover the eight
// cones between neighbouring orientations, each frame a cone and its opposite.
struct OctFrame {
  i64 a, b, c, d;      // u = a x + b y, v = c x + d y
  i64 ia, ib, ic, id;  // x = ia u + ib v, y = ic u + id v
  bool sqrt2_x;
};
constexpr OctFrame kOctFrames[4] = {
    {1, -1, 0, 1, 1, 1, 0, 1, false},    // E (u), NE (v)
    {1, 0, -1, 1, 1, 0, 1, 1, true},     // NE (u), N (v)
    {1, 1, -1, 0, 0, -1, 1, 1, false},   // N (u), NW (v)
    {0, 1, -1, -1, -1, -1, 1, 0, true},  // NW (u), W (v)
};
constexpr bool oct_frames_consistent() {
  for (const OctFrame& f : kOctFrames) {
    if (f.a * f.ia + f.b * f.ic != 1 || f.a * f.ib + f.b * f.id != 0) return false;
    if (f.c * f.ia + f.d * f.ic != 0 || f.c * f.ib + f.d * f.id != 1) return false;
    if (f.a * f.d - f.b * f.c != 1) return false;
    // the diagonal column has no zero, the axis column one
    const bool u_diag = f.ia != 0 && f.ic != 0, v_diag = f.ib != 0 && f.id != 0;
    if (u_diag == v_diag || u_diag != f.sqrt2_x) return false;
  }
  return true;
}
static_assert(oct_frames_consistent());

}  // namespace

// Shape sources: checked, cleaned (geom::normalize_obstacles on each alone), and their edges.
struct ShapeSet {
  std::vector<Polygon> rings;            // one counter-clockwise outer ring each
  std::vector<geom::Segment> edges;      // every ring edge, as segment sources
  std::vector<uint32_t> edge_shape;      // per edge: its shape
};
// Per shape, in order: why it cannot be a source ("" when it can) beside the blockages, the
// shapes before it that can, and the points given (a point on or in a shape would not be free).
// Cost: linear box scans, O(k (n + k)) box tests for k shapes and n obstacles, and exact tests
// only where boxes meet.
std::vector<L1Map::ShapeProblem> shape_problems_of(const geom::Box& domain, std::span<const Polygon> obstacles,
                                           std::span<const Polygon> shapes, std::span<const Point> points, ShapeSet* out) {
  auto box_of = [](const Polygon& p) {
    geom::Box b{p.outer[0], p.outer[0]};
    for (const Point q : p.outer) {
      b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y)};
      b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y)};
    }
    return b;
  };
  auto boxes_meet = [](const geom::Box& a, const geom::Box& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
  };
  // No common point: no two edges meet, and no vertex of one lies inside the other.
  auto apart = [](const Polygon& a, const Polygon& b) {
    auto rings = [](const Polygon& p) {
      std::vector<const geom::Ring*> v{&p.outer};
      for (const auto& h : p.holes) v.push_back(&h);
      return v;
    };
    for (const geom::Ring* ra : rings(a))
      for (const geom::Ring* rb : rings(b))
        for (std::size_t i = 0; i < ra->size(); ++i)
          for (std::size_t j = 0; j < rb->size(); ++j)
            if (geom::intersect({(*ra)[i], (*ra)[(i + 1) % ra->size()]}, {(*rb)[j], (*rb)[(j + 1) % rb->size()]}) !=
                geom::SegmentIntersection::None)
              return false;
    return geom::locate(a.outer[0], b) == geom::Location::Outside && geom::locate(b.outer[0], a) == geom::Location::Outside;
  };
  std::vector<geom::Box> obstacle_boxes;
  for (const Polygon& o : obstacles) obstacle_boxes.push_back(box_of(o));
  ShapeSet set;
  std::vector<geom::Box> taken_boxes;
  std::vector<std::size_t> taken_index;  // the input index of each taken shape
  using Kind = L1Map::ShapeProblem::Kind;
  std::vector<L1Map::ShapeProblem> why(shapes.size());
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    L1Map::ShapeProblem& w = why[k];
    if (shapes[k].outer.size() < 3 || !shapes[k].holes.empty()) {
      w.kind = Kind::NotPolygon;
      continue;
    }
    bool inside = true;
    for (const Point p : shapes[k].outer)
      inside = inside && p.x > domain.lo.x && p.x < domain.hi.x && p.y > domain.lo.y && p.y < domain.hi.y;
    if (!inside) {
      w.kind = Kind::OffDomain;
      continue;
    }
    const Polygon one[1] = {shapes[k]};
    geom::NormalizedObstacles n = geom::normalize_obstacles(one, domain);
    const geom::i128 a2 = geom::twice_area(shapes[k].outer);
    if (n.obstacles.size() != 1 || !n.obstacles[0].holes.empty() || geom::twice_area(n.obstacles[0].outer) != (a2 < 0 ? -a2 : a2)) {
      w.kind = Kind::NotSimple;
      continue;
    }
    const Polygon& ring = n.obstacles[0];
    for (std::size_t i = 0; i < ring.outer.size() && w.kind == Kind::None; ++i) {
      const Point a = ring.outer[i], b = ring.outer[(i + 1) % ring.outer.size()];
      const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
      if (dx != 0 && dy != 0 && dx != dy && dx != -dy) w.kind = Kind::Angle;
    }
    if (w.kind != Kind::None) continue;
    const geom::Box bk = box_of(ring);
    for (std::size_t o = 0; o < obstacles.size() && w.kind == Kind::None; ++o)
      if (boxes_meet(bk, obstacle_boxes[o]) && !apart(ring, obstacles[o])) w.kind = Kind::Blockage;
    for (std::size_t t = 0; t < set.rings.size() && w.kind == Kind::None; ++t)
      if (boxes_meet(bk, taken_boxes[t]) && !apart(ring, set.rings[t])) w = {Kind::Shape, taken_index[t]};
    for (std::size_t p = 0; p < points.size() && w.kind == Kind::None; ++p)
      if (geom::locate(points[p], ring) != geom::Location::Outside) w = {Kind::Point, p};
    if (w.kind != Kind::None) continue;
    for (std::size_t i = 0; i < ring.outer.size(); ++i) {
      set.edges.push_back({ring.outer[i], ring.outer[(i + 1) % ring.outer.size()]});
      set.edge_shape.push_back(static_cast<uint32_t>(set.rings.size()));
    }
    set.rings.push_back(ring);
    taken_boxes.push_back(bk);
    taken_index.push_back(k);
  }
  if (out) *out = std::move(set);
  return why;
}

struct L1Map::Impl {
  std::size_t npoints;  // point sources given (shape k is source npoints + k)
  ShapeSet shapes;
  L1Wavefront wf;
  Decomp<i64> dec;
  static ShapeSet checked(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Polygon> shapes) {
    ShapeSet set;
    const auto why = shape_problems_of(domain, obstacles, shapes, {}, &set);
    for (std::size_t k = 0; k < why.size(); ++k)
      if (why[k]) throw std::invalid_argument("shape source " + std::to_string(k) + ": " + why[k].text());
    return set;
  }
  static L1Wavefront ran_with(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources,
                              const ShapeSet& shapes) {
    if (shapes.rings.empty()) return ran<L1Wavefront>(domain, obstacles, sources);
    std::vector<Polygon> all(obstacles.begin(), obstacles.end());
    all.insert(all.end(), shapes.rings.begin(), shapes.rings.end());
    L1Wavefront wf(domain, all);
    wf.run(sources, shapes.edges, {}, WavefrontStop::Never);
    return wf;
  }
  // Per polygon of the wavefront's frame obstacles: the source index of a shape, else kNone
  // (shapes keep off everything, so they are there as themselves; found by a vertex).
  std::vector<uint32_t> poly_sources(std::size_t npoints) const {
    std::vector<uint32_t> out;
    if (shapes.rings.empty()) return out;
    std::vector<std::pair<Point, uint32_t>> first;
    for (uint32_t k = 0; k < shapes.rings.size(); ++k) first.push_back({shapes.rings[k].outer[0], k});
    std::sort(first.begin(), first.end());
    for (const Polygon& p : wf.frame_obstacles()) {
      uint32_t src = kNone;
      for (const Point v : p.outer) {
        const auto it = std::lower_bound(first.begin(), first.end(), std::pair<Point, uint32_t>{v, 0});
        if (it != first.end() && it->first == v) src = static_cast<uint32_t>(npoints + it->second);
      }
      out.push_back(src);
    }
    return out;
  }
  // A wedge's source as the map numbers them: point sources, then shapes (the wavefront numbers
  // the shapes' edges).
  uint32_t source_of(const std::optional<std::size_t>& s, std::size_t npoints) const {
    if (!s) return kNone;
    if (*s < npoints) return static_cast<uint32_t>(*s);
    return static_cast<uint32_t>(npoints + shapes.edge_shape[*s - npoints]);
  }
  Impl(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources,
       std::span<const Polygon> shape_sources, bool grid)
      : npoints(sources.size()),
        shapes(checked(domain, obstacles, shape_sources)),
        wf(ran_with(domain, obstacles, sources, shapes)),
        dec(domain, wf.frame_obstacles(), free_sources(wf, sources),
            [&](Point p) {
              std::vector<WedgeIn<i64>> out;
              for (const auto& w : wf.vertex_wedges(p)) out.push_back({w.lo, w.distance, source_of(w.source, sources.size())});
              return out;
            },
            1, 1, grid, 1.0, poly_sources(sources.size())) {}
};

L1Map::L1Map(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources,
             Options options)
    : impl_(std::make_unique<Impl>(domain, obstacles, sources, std::span<const Polygon>{}, options.grid)) {}
L1Map::L1Map(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources,
             std::span<const Polygon> shapes, Options options)
    : impl_(std::make_unique<Impl>(domain, obstacles, sources, shapes, options.grid)) {}
std::vector<L1Map::ShapeProblem> L1Map::shape_problems(const geom::Box& domain, std::span<const Polygon> obstacles,
                                                       std::span<const Polygon> shapes, std::span<const Point> points) {
  return shape_problems_of(domain, obstacles, shapes, points, nullptr);
}
std::string L1Map::ShapeProblem::text() const {
  switch (kind) {
    case Kind::None: return "";
    case Kind::NotPolygon: return "it is not a polygon without holes";
    case Kind::OffDomain: return "it does not lie inside the domain off its sides";
    case Kind::NotSimple: return "it is not a simple polygon";
    case Kind::Angle: return "it has an edge that is not horizontal, vertical or at 45 degrees";
    case Kind::Blockage: return "it touches or overlaps a blockage";
    case Kind::Shape: return "it touches or overlaps shape source " + std::to_string(other);
    case Kind::Point: return "point source " + std::to_string(other) + " lies on or in it";
  }
  return "";
}
std::string L1Map::shape_problem(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Polygon> shapes) {
  const auto why = shape_problems_of(domain, obstacles, shapes, {}, nullptr);
  for (std::size_t k = 0; k < why.size(); ++k)
    if (why[k]) return "shape source " + std::to_string(k) + ": " + why[k].text();
  return "";
}
L1Map::~L1Map() = default;
L1Map::L1Map(L1Map&&) noexcept = default;
L1Map& L1Map::operator=(L1Map&&) noexcept = default;

bool L1Map::is_free(Point q) const { return impl_->dec.is_free(q); }

std::optional<L1Map::Answer> L1Map::locate(Point q) const {
  const auto b = impl_->dec.best_root(q);
  if (!b) return std::nullopt;
  if (b->root == kFootRoot) return Answer{b->value, b->src, b->foot, kFootRoot};
  const auto& r = impl_->dec.roots[b->root];
  return Answer{b->value, r.source, r.p, b->root};
}

std::vector<Point> L1Map::path(Point q) const {
  const auto a = locate(q);
  return a ? path(q, *a) : std::vector<Point>{};
}

std::vector<Point> L1Map::path(Point q, const Answer& a) const {
  if (a.root_id == kFootRoot) return a.root == q ? std::vector<Point>{q} : std::vector<Point>{a.root, q};
  if (a.root_id >= impl_->dec.roots.size()) return {};
  const auto& r = impl_->dec.roots[a.root_id];
  std::vector<Point> out;
  if (r.wedge == kNone)
    out.push_back(r.p);
  else
    out = impl_->wf.wedge_path(r.p, r.wedge);
  if (out.empty() || out.back() != q) out.push_back(q);
  return out;
}

std::vector<L1Map::Trapezoid> L1Map::trapezoids() const {
  const Decomp<i64>& m = impl_->dec;
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

RationalRoot2 twice_signed_area(const std::vector<R2Point>& ring) {
  RationalRoot2 a2;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const R2Point &p = ring[i], &q = ring[(i + 1) % n];
    a2 = a2 + (p.x * q.y - q.x * p.y);
  }
  return a2;
}

std::vector<L1Map::Piece> L1Map::pieces(Detail detail) const {
  std::vector<Piece> out;
  for (uint32_t i = 0; i < impl_->dec.traps.size(); ++i) impl_->dec.trapezoid_pieces(i, detail == Detail::ByRoot, out);
  return out;
}

const L1Map::Stats& L1Map::stats() const { return impl_->dec.st; }

std::span<const Polygon> L1Map::shape_sources() const { return impl_->shapes.rings; }
std::size_t L1Map::shape_source_index(std::size_t k) const { return impl_->npoints + k; }

std::size_t L1Map::memory_bytes() const { return impl_->wf.memory_bytes() + impl_->dec.memory_bytes(); }

// ----------------------------------------------------------------------------------------------
namespace {

bool has_area_r2(const std::vector<R2Point>& poly) { return poly.size() >= 3 && twice_signed_area(poly).sign() > 0; }

// A piece of one octilinear frame: on `ring` the frame's value is gx x + gy y + c (coordinates
// of whatever plane the ring is in), from root `root` of that frame's decomposition.
struct LinearPiece {
  std::vector<R2Point> ring;
  RationalRoot2 gx, gy, c;
  uint32_t root;
};

// The pieces of trapezoid i of a weighted frame decomposition (frame coordinates): L1Map's bands
// (trapezoid_pieces), with the weighted gradients (+-wx, +-wy), always cut at every threshold
// (so each piece has one linear function), merged only across bands with the same function.
void frame_pieces(const Decomp<geom::Root2>& m, uint32_t i, std::vector<LinearPiece>& out) {
  using R = RationalRoot2;
  const Trap& t = m.traps[i];
  if (t.pl.x == t.pr.x) return;
  auto y_q = [](Point a, Point b, i64 x) {
    return Q{i64{a.y} * (i64{b.x} - x) + i64{b.y} * (x - a.x), i64{b.x} - a.x};
  };
  auto rq = [](Q q) { return R(Rational(q.n, q.d)); };
  const Q bl = y_q(t.b0, t.b1, t.pl.x), br = y_q(t.b0, t.b1, t.pr.x);
  const Q tl = y_q(t.t0, t.t1, t.pl.x), tr = y_q(t.t0, t.t1, t.pr.x);
  const R xl{Rational(t.pl.x)}, xr{Rational(t.pr.x)};
  std::vector<R2Point> poly{{xl, rq(bl)}, {xr, rq(br)}, {xr, rq(tr)}, {xl, rq(tl)}};
  if (poly[1] == poly[2]) poly.erase(poly.begin() + 2);
  if (poly[0] == poly.back()) poly.pop_back();
  const R wx(m.wx), wy(m.wy);
  struct Stair {
    uint32_t b, e;
    bool up;
    int gx;
    i64 x0;  // value = K + gx wx (x - x0) +- wy y
  };
  const Stair st4[4] = {{t.lo[0], t.lo[1], true, 1, i64{t.pl.x}},
                        {t.lo[1], t.lo[2], false, 1, i64{t.pl.x}},
                        {t.ro[0], t.ro[1], true, -1, i64{t.pr.x}},
                        {t.ro[1], t.ro[2], false, -1, i64{t.pr.x}}};
  bool any = false;
  for (const Stair& st : st4) any = any || st.e > st.b;
  if (!any) return;  // walled in
  const Q ylo = qmin(bl, br), yhi = qmax(tl, tr);
  std::vector<Q> lim{ylo};
  for (const Stair& st : st4)
    for (uint32_t k = st.b; k < st.e; ++k)
      if (cmp(m.rays[k].t(), ylo) > 0 && cmp(m.rays[k].t(), yhi) < 0) lim.push_back(m.rays[k].t());
  std::sort(lim.begin() + 1, lim.end(), [](Q a, Q b) { return cmp(a, b) < 0; });
  lim.erase(std::unique(lim.begin(), lim.end(), [](Q a, Q b) { return cmp(a, b) == 0; }), lim.end());
  lim.push_back(yhi);
  struct Cand {
    R gx, gy, c;
    uint32_t root;
    bool same(const Cand& o) const { return root == o.root && gx == o.gx && gy == o.gy && c == o.c; }
  };
  auto active = [&](const Stair& st, Q a, Q b) -> uint32_t {  // L1Map's rule, searched
    uint32_t best = kNone;
    for (uint32_t k = st.b; k < st.e; ++k) {
      if (st.up ? cmp(m.rays[k].t(), a) <= 0 : cmp(m.rays[k].t(), b) >= 0) best = k;
      else break;
    }
    return best;
  };
  struct Run {
    Q ya, yb;
    std::optional<Cand> c;
  } run;
  auto slab = [&](Q ya, Q yb) {
    std::vector<R2Point> b = poly;
    if (cmp(ya, ylo) > 0) clip_convex(b, R(), R(Rational(-1)), rq(ya));   // y >= ya
    if (cmp(yb, yhi) < 0) clip_convex(b, R(), R(Rational(1)), -rq(yb));   // y <= yb
    return b;
  };
  auto emit = [&](std::vector<R2Point>&& ring, const Cand& c) {
    // Only the exact ones: the frame's value d(r) + wx |du| + wy |dv| is the octilinear length
    // of q - r when du and dv have one sign (q - r in the frame's cone or its opposite), and
    // strictly more when they have opposite signs (the octagon is strictly convex between
    // orientations 135 degrees apart): such a piece is nowhere the least over the frames.
    if ((c.gx.sign() > 0) != (c.gy.sign() > 0)) return;
    if (has_area_r2(ring)) out.push_back({std::move(ring), c.gx, c.gy, c.c, c.root});
  };
  auto flush = [&] {
    if (!run.c) return;
    emit(slab(run.ya, run.yb), *run.c);
    run.c.reset();
  };
  // the active ray of each staircase per band; consecutive bands with the same ones are one
  const std::size_t nb = lim.size() - 1;
  std::vector<std::array<uint32_t, 4>> acts(nb);
  for (std::size_t i = 0; i < nb; ++i)
    for (int k = 0; k < 4; ++k) acts[i][k] = active(st4[k], lim[i], lim[i + 1]);
  for (std::size_t band = 0; band < nb;) {
    std::size_t end = band + 1;
    while (end < nb && acts[end] == acts[band]) ++end;
    const Q ya = lim[band], yb = lim[end];
    const std::array<uint32_t, 4> act = acts[band];
    band = end;
    std::vector<Cand> cands;
    for (int si = 0; si < 4; ++si) {
      const uint32_t k = act[si];
      if (k == kNone) continue;
      const Stair& st = st4[si];
      const auto& ray = m.rays[k];
      const R gx = st.gx > 0 ? wx : -wx, gy = st.up ? wy : -wy;
      cands.push_back({gx, gy, R(ray.K) - gx * R(Rational(st.x0)), ray.root});
    }
    if (cands.empty()) throw std::logic_error("spm: a band of a reached octilinear trapezoid has no ray");
    if (cands.size() > 1) {  // drop candidates no lower anywhere in the band's box (linear)
      auto diff = [&](const Cand& j, const Cand& k, const R& x, const R& y) {
        return ((j.gx - k.gx) * x + (j.gy - k.gy) * y + (j.c - k.c)).sign();
      };
      const R yar = rq(ya), ybr = rq(yb);
      std::vector<Cand> kept;
      for (std::size_t a = 0; a < cands.size(); ++a) {
        bool dominated = false;
        for (std::size_t b = 0; b < cands.size() && !dominated; ++b) {
          if (b == a) continue;
          const int d[4] = {diff(cands[b], cands[a], xl, yar), diff(cands[b], cands[a], xr, yar),
                            diff(cands[b], cands[a], xl, ybr), diff(cands[b], cands[a], xr, ybr)};
          const bool le = d[0] <= 0 && d[1] <= 0 && d[2] <= 0 && d[3] <= 0;
          const bool tie = d[0] == 0 && d[1] == 0 && d[2] == 0 && d[3] == 0;
          dominated = le && (!tie || b < a);
        }
        if (!dominated) kept.push_back(cands[a]);
      }
      cands = std::move(kept);
    }
    if (cands.size() == 1) {
      if (run.c && run.c->same(cands[0])) {
        run.yb = yb;
      } else {
        flush();
        run = {ya, yb, cands[0]};
      }
      continue;
    }
    flush();
    const std::vector<R2Point> b = slab(ya, yb);
    if (!has_area_r2(b)) continue;
    for (std::size_t a = 0; a < cands.size(); ++a) {
      std::vector<R2Point> p = b;
      for (std::size_t o = 0; o < cands.size() && p.size() >= 3; ++o)
        if (o != a) clip_convex(p, cands[a].gx - cands[o].gx, cands[a].gy - cands[o].gy, cands[a].c - cands[o].c);
      emit(std::move(p), cands[a]);
    }
  }
  flush();
}

}  // namespace

struct OctMap::Impl {
  OctWavefront wf;
  geom::Box domain;
  i64 cx, cy;  // the frames' origin: the domain's centre
  std::vector<Decomp<geom::Root2>> dec;
  L1Map::Stats st;

  static i64 centre(i64 lo, i64 hi) { return (lo + hi) >> 1; }
  static std::array<i64, 2> frame_coords(const OctFrame& f, i64 x, i64 y) { return {f.a * x + f.b * y, f.c * x + f.d * y}; }
  Point fwd(int k, Point p) const {
    const auto [u, v] = frame_coords(kOctFrames[k], i64{p.x} - cx, i64{p.y} - cy);
    return {static_cast<geom::Coord>(u), static_cast<geom::Coord>(v)};
  }
  Point back(int k, Point p) const {
    const OctFrame& f = kOctFrames[k];
    return {static_cast<geom::Coord>(f.ia * p.x + f.ib * p.y + cx), static_cast<geom::Coord>(f.ic * p.x + f.id * p.y + cy)};
  }
  // Every point the frames hold lies in the frame obstacle's outer ring (the domain grown by 1):
  // its corners' frame coordinates bound them all (the maps are linear).
  static bool fits(const geom::Box& d) {
    const i64 ox = centre(d.lo.x, d.hi.x), oy = centre(d.lo.y, d.hi.y);
    for (const OctFrame& f : kOctFrames)
      for (const i64 x : {i64{d.lo.x} - 1, i64{d.hi.x} + 1})
        for (const i64 y : {i64{d.lo.y} - 1, i64{d.hi.y} + 1})
          for (const i64 c : frame_coords(f, x - ox, y - oy))
            if (!geom::in_range(c)) return false;
    return true;
  }
  static OctWavefront checked(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources) {
    if (!fits(domain))
      throw std::domain_error("the octilinear shortest path map needs a domain whose width plus height is below about 2^31");
    return ran<OctWavefront>(domain, obstacles, sources);
  }

  Impl(const geom::Box& dom, std::span<const Polygon> obstacles, std::span<const Point> sources, bool grid)
      : wf(checked(dom, obstacles, sources)), domain(dom), cx(centre(dom.lo.x, dom.hi.x)), cy(centre(dom.lo.y, dom.hi.y)) {
    const auto free_src = free_sources(wf, sources);
    dec.reserve(4);
    for (int k = 0; k < 4; ++k) {
      std::vector<Polygon> polys;
      auto ring = [&](const geom::Ring& r) {
        geom::Ring out;
        out.reserve(r.size());
        for (Point p : r) out.push_back(fwd(k, p));
        return out;
      };
      for (const Polygon& p : wf.frame_obstacles()) {
        Polygon q{ring(p.outer), {}};
        for (const auto& h : p.holes) q.holes.push_back(ring(h));
        polys.push_back(std::move(q));
      }
      std::vector<std::pair<Point, uint32_t>> src;
      for (const auto& [p, i] : free_src) src.push_back({fwd(k, p), i});
      geom::Box box{fwd(k, dom.lo), fwd(k, dom.lo)};
      for (Point c : {dom.lo, dom.hi, Point{dom.lo.x, dom.hi.y}, Point{dom.hi.x, dom.lo.y}}) {
        const Point u = fwd(k, c);
        box.lo = {std::min(box.lo.x, u.x), std::min(box.lo.y, u.y)};
        box.hi = {std::max(box.hi.x, u.x), std::max(box.hi.y, u.y)};
      }
      const geom::Root2 one{1, 0}, root2{0, 1};
      dec.emplace_back(box, polys, src,
                       [&](Point pu) {
                         std::vector<WedgeIn<geom::Root2>> out;
                         for (const auto& w : wf.vertex_wedges(back(k, pu)))
                           out.push_back({fwd(k, w.lo), w.distance, static_cast<uint32_t>(w.source.value_or(kNone))});
                         return out;
                       },
                       kOctFrames[k].sqrt2_x ? root2 : one, kOctFrames[k].sqrt2_x ? one : root2, grid,
                       // the box over the domain's image (a parallelogram of the same area)
                       (static_cast<double>(box.hi.x) - box.lo.x + 1) * (static_cast<double>(box.hi.y) - box.lo.y + 1) /
                           ((static_cast<double>(dom.hi.x) - dom.lo.x + 1) * (static_cast<double>(dom.hi.y) - dom.lo.y + 1)));
      if (dec.back().roots.size() >= (1u << 30)) throw std::length_error("the octilinear map needs more than 2^30 roots");
      const L1Map::Stats& s = dec.back().st;
      st.vertices = s.vertices;
      st.trapezoids += s.trapezoids;
      st.rays += s.rays;
      st.roots += s.roots;
      st.location_nodes += s.location_nodes;
    }
  }
  bool in_domain(Point q) const {
    return q.x >= domain.lo.x && q.x <= domain.hi.x && q.y >= domain.lo.y && q.y <= domain.hi.y;
  }
};

OctMap::OctMap(const geom::Box& domain, std::span<const Polygon> obstacles, std::span<const Point> sources,
               Options options)
    : impl_(std::make_unique<Impl>(domain, obstacles, sources, options.grid)) {}
OctMap::~OctMap() = default;
OctMap::OctMap(OctMap&&) noexcept = default;
OctMap& OctMap::operator=(OctMap&&) noexcept = default;

bool OctMap::fits(const geom::Box& domain) { return Impl::fits(domain); }

bool OctMap::is_free(Point q) const { return impl_->in_domain(q) && impl_->dec[0].is_free(impl_->fwd(0, q)); }

std::optional<OctMap::Answer> OctMap::locate(Point q) const {
  const Impl& m = *impl_;
  if (!m.in_domain(q)) return std::nullopt;
  // The least value over the frames; ties go to the first frame. Each frame's answer has a root
  // that sees q straight (its staircases prefer the larger root distance, L1Map's argument in
  // the frame's weighted metric), so any of the tied ones will do.
  std::optional<Answer> best;
  for (int k = 0; k < 4; ++k) {
    const auto b = m.dec[k].best_root(m.fwd(k, q));
    if (!b || (best && !(b->value < best->distance))) continue;
    const auto& r = m.dec[k].roots[b->root];
    best = Answer{b->value, r.source, m.back(k, r.p), (static_cast<uint32_t>(k) << 30) | b->root};
  }
  return best;
}

std::vector<Point> OctMap::path(Point q) const {
  const auto a = locate(q);
  return a ? path(q, *a) : std::vector<Point>{};
}

std::vector<Point> OctMap::path(Point q, const Answer& a) const {
  const Impl& m = *impl_;
  const int k = static_cast<int>(a.root_id >> 30);
  const uint32_t id = a.root_id & ((1u << 30) - 1);
  if (id >= m.dec[k].roots.size()) return {};
  const auto& r = m.dec[k].roots[id];
  std::vector<Point> out;
  if (r.wedge == kNone)
    out.push_back(m.back(k, r.p));
  else
    out = m.wf.wedge_path(m.back(k, r.p), r.wedge);
  if (out.empty() || out.back() != q) out.push_back(q);
  return out;
}

std::vector<OctMap::Piece> OctMap::pieces() const {
  using R = RationalRoot2;
  const Impl& m = *impl_;
  namespace bgi = boost::geometry::index;
  using BPoint = boost::geometry::model::point<std::int64_t, 2, boost::geometry::cs::cartesian>;
  using BBox = boost::geometry::model::box<BPoint>;
  struct World {
    LinearPiece p;  // world coordinates
    BBox box;       // integer bounding box of the ring
  };
  // an integer box holding the ring (exact floors, each rounded up by one for the top)
  auto box_of = [](const std::vector<R2Point>& ring) {
    std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    for (std::size_t j = 0; j < ring.size(); ++j) {
      const std::int64_t fx = ring[j].x.floor(), fy = ring[j].y.floor();
      if (j == 0 || fx < x0) x0 = fx;
      if (j == 0 || fy < y0) y0 = fy;
      if (j == 0 || fx + 1 > x1) x1 = fx + 1;
      if (j == 0 || fy + 1 > y1) y1 = fy + 1;
    }
    return BBox(BPoint(x0, y0), BPoint(x1, y1));
  };
  std::vector<std::vector<World>> frames(4);
  using Tree = bgi::rtree<std::pair<BBox, uint32_t>, bgi::rstar<16>>;
  std::vector<Tree> trees(4);
  for (int k = 0; k < 4; ++k) {
    const OctFrame& f = kOctFrames[k];
    const Decomp<geom::Root2>& d = m.dec[k];
    std::vector<LinearPiece> local;
    for (uint32_t i = 0; i < d.traps.size(); ++i) frame_pieces(d, i, local);
    std::vector<std::pair<BBox, uint32_t>> items;
    for (LinearPiece& lp : local) {
      // world = M^-1 (u, v) + centre; the value gu u + gv v + c with u = a (x - cx) + b (y - cy),
      // v = c' (x - cx) + d (y - cy)
      World w;
      for (const R2Point& p : lp.ring)
        w.p.ring.push_back({R(Rational(f.ia)) * p.x + R(Rational(f.ib)) * p.y + R(Rational(m.cx)),
                            R(Rational(f.ic)) * p.x + R(Rational(f.id)) * p.y + R(Rational(m.cy))});
      w.p.gx = lp.gx * R(Rational(f.a)) + lp.gy * R(Rational(f.c));
      w.p.gy = lp.gx * R(Rational(f.b)) + lp.gy * R(Rational(f.d));
      w.p.c = lp.c - w.p.gx * R(Rational(m.cx)) - w.p.gy * R(Rational(m.cy));
      w.p.root = lp.root;
      w.box = box_of(w.p.ring);
      items.push_back({w.box, static_cast<uint32_t>(frames[k].size())});
      frames[k].push_back(std::move(w));
    }
    trees[k] = Tree(items.begin(), items.end());
  }
  // Every piece here is exact (frame_pieces), and the map's value at q is attained by the exact
  // piece of some frame there; so a piece keeps q unless an exact piece of another frame holding
  // q is lower there. Each piece therefore loses, for
  // every exact piece C of another frame it meets, the convex part of C where C is no higher:
  // the part minus a convex polygon is cut into convex pieces, one per edge of the polygon.
  std::vector<Piece> out;
  auto minus = [](const std::vector<R2Point>& part, const std::vector<R2Point>& c, std::vector<std::vector<R2Point>>& res) {
    std::vector<R2Point> rest = part;  // part, inside the edges of c handled so far
    for (std::size_t e = 0; e < c.size() && rest.size() >= 3; ++e) {
      const R2Point &a = c[e], &b = c[(e + 1) % c.size()];
      // (b - a) x (p - a) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x): outside (right) <= 0
      const R ex = b.x - a.x, ey = b.y - a.y;
      std::vector<R2Point> outside = rest;
      clip_convex(outside, -ey, ex, ey * a.x - ex * a.y);  // cross <= 0
      if (has_area_r2(outside)) res.push_back(std::move(outside));
      clip_convex(rest, ey, -ex, ex * a.y - ey * a.x);     // inside (left): cross >= 0
    }
  };
  for (int k = 0; k < 4; ++k)
    for (const World& w : frames[k]) {
      std::vector<std::vector<R2Point>> parts{w.p.ring};
      std::vector<std::pair<BBox, uint32_t>> hits;
      for (int g = 0; g < 4 && !parts.empty(); ++g) {
        if (g == k) continue;
        hits.clear();
        trees[g].query(bgi::intersects(w.box), std::back_inserter(hits));
        for (const auto& [box, id] : hits) {
          const LinearPiece& o = frames[g][id].p;
          // c: where o is no higher than w. Their gradients differ: an exact piece's gradient
          // is the octilinear functional of one of its frame's two cones, and no two frames
          // share a cone; so they tie on a line at most, and either may keep it.
          const R dgx = w.p.gx - o.gx, dgy = w.p.gy - o.gy, dc = w.p.c - o.c;
          if (dgx.sign() == 0 && dgy.sign() == 0)
            throw std::logic_error("spm: two octilinear frames with one gradient");
          std::vector<R2Point> c = o.ring;
          clip_convex(c, -dgx, -dgy, -dc);  // w - o >= 0
          if (!has_area_r2(c)) continue;
          std::vector<std::vector<R2Point>> next;
          for (auto& part : parts) {
            // does c meet part with area? (part inside every edge of c)
            std::vector<R2Point> meet = part;
            for (std::size_t e = 0; e < c.size() && meet.size() >= 3; ++e) {
              const R2Point &a = c[e], &b = c[(e + 1) % c.size()];
              clip_convex(meet, b.y - a.y, a.x - b.x, (b.x - a.x) * a.y - (b.y - a.y) * a.x);
            }
            if (!has_area_r2(meet)) {
              next.push_back(std::move(part));
              continue;
            }
            minus(part, c, next);
          }
          parts = std::move(next);
          if (parts.empty()) break;
        }
      }
      const auto& r = m.dec[k].roots[w.p.root];
      for (auto& part : parts) out.push_back({std::move(part), r.source, m.back(k, r.p), r.d});
    }
  return out;
}

const L1Map::Stats& OctMap::stats() const { return impl_->st; }

std::size_t OctMap::memory_bytes() const {
  std::size_t b = impl_->wf.memory_bytes();
  for (const auto& d : impl_->dec) b += d.memory_bytes();
  return b;
}

}  // namespace taut::router
