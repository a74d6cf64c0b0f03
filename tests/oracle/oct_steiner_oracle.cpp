#include "oracle/oct_steiner_oracle.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "geom/predicates.h"
#include "oracle/oct_oracle.h"

namespace taut::oracle {

namespace {

using geom::Point;
using geom::Root2;
using i64 = std::int64_t;

// Exact order keys. Every length formed below is a + b*sqrt2 with 0 <= a, b < 2^16: the lattice
// graph has at most 4 unit edges per point (so fewer than 4 * 80 * 80 = 25600 in all; a pin's
// edges are 0), a least tree uses each at most once, and a value is at most two least trees
// (a split) or one plus an edge (a tentative Dijkstra value); a value's (a, b) is unique (a + b*sqrt2
// == c + d*sqrt2 only for a == c, b == d), so that of a least value is its tree's edge counts.
// For these, key(a, b) = a * 2^20 + floor(b * sqrt2 * 2^20) orders exactly as the numbers do:
// two different ones differ by |A + B*sqrt2| = |A^2 - 2 B^2| / |A - B*sqrt2| >= 1 / (|A| +
// |B|*sqrt2) > 2^-18 (A^2 - 2 B^2 is a non-zero integer; |A|, |B| < 2^16), while the floor loses
// less than 2^-20; equal numbers have equal keys. The floors are exact integer square roots
// (floor(sqrt(2 b^2 2^40)), in unsigned __int128), tabled once.
constexpr int kShift = 20;
constexpr i64 kRange = i64{1} << 16;  // a, b below this
constexpr i64 kInfKey = std::numeric_limits<i64>::max();  // unreached

const std::vector<i64>& sqrt2_floors() {
  static const std::vector<i64> table = [] {
    std::vector<i64> t(static_cast<std::size_t>(kRange));
    for (i64 b = 0; b < kRange; ++b) {
      using u128 = unsigned __int128;
      const u128 n = static_cast<u128>(2 * b * b) << (2 * kShift);
      i64 lo = 0, hi = i64{1} << 40;  // floor(sqrt(n)) in [lo, hi): n < 2^73 < (2^40)^2
      while (hi - lo > 1) {
        const i64 mid = lo + (hi - lo) / 2;
        (static_cast<u128>(mid) * static_cast<u128>(mid) <= n ? lo : hi) = mid;
      }
      t[static_cast<std::size_t>(b)] = lo;
    }
    return t;
  }();
  return table;
}

// A length with its key; key == kInfKey: unreached.
struct Len {
  i64 key = kInfKey;
  std::int32_t a = 0, b = 0;
};

Len make_len(i64 a, i64 b, const std::vector<i64>& floors) {
  if (a >= kRange || b >= kRange) throw std::logic_error("oct_steiner_minimal_length: a length beyond 2^16");
  return {(a << kShift) + floors[static_cast<std::size_t>(b)], static_cast<std::int32_t>(a),
          static_cast<std::int32_t>(b)};
}

struct Arc {
  std::uint32_t to;
  std::int32_t kind;  // 0: a pin's join (length 0), 1: axis (1), 2: diagonal (sqrt2)
};

// The lattice graph of the header: nodes (point, wedge), arcs in compressed rows.
struct Lattice {
  std::vector<std::uint32_t> first;  // arcs of node v: arcs[first[v] .. first[v + 1])
  std::vector<Arc> arcs;
};

// Index of the wedge in `ws` holding direction (dx, dy); ws.size() when none does. The wedges at
// a point are disjoint closed intervals (separated by blocked sectors), so at most one holds it.
std::size_t wedge_holding(const std::vector<Wedge>& ws, i64 dx, i64 dy) {
  for (std::size_t i = 0; i < ws.size(); ++i)
    if (ws[i].contains(dx, dy)) return i;
  return ws.size();
}

// Dijkstra from every node at its value (unreached: kInfKey), with four FIFO queues instead of a
// heap: the start values sorted, and one queue per edge kind (0 at a pin on a pinch, 1, sqrt2).
// Nodes are settled in nondecreasing order, so what a settled node pushes through an edge of one
// kind comes in nondecreasing order too: each queue stays sorted, and the least of the four
// fronts is the least tentative value, as a heap would give it. Stale entries (a node lowered
// since) are skipped. Stops once `stop` is settled when stop < d.size() (its value is then final;
// the others may not be). `q` is scratch space, reused between calls. An entry is key * 2^24 +
// node in one integer (keys are below 2^38 (2^16 * 2^20 * (1 + sqrt2)), nodes below 2^24).
using Item = std::uint64_t;
constexpr int kNodeBits = 24;
void relax(const Lattice& g, Len* d, std::size_t n, std::size_t stop, const std::vector<i64>& floors,
           std::vector<Item> (&q)[4]) {
  auto item = [](i64 key, std::size_t v) { return static_cast<Item>(key) << kNodeBits | v; };
  for (auto& queue : q) queue.clear();
  for (std::size_t v = 0; v < n; ++v)
    if (d[v].key != kInfKey) q[3].push_back(item(d[v].key, v));
  std::sort(q[3].begin(), q[3].end());
  std::size_t at[4] = {0, 0, 0, 0};
  for (;;) {
    int best = -1;
    for (int i = 0; i < 4; ++i)
      if (at[i] < q[i].size() && (best < 0 || q[i][at[i]] < q[best][at[best]])) best = i;
    if (best < 0) return;
    const Item it = q[best][at[best]++];
    const std::size_t v = it & ((Item{1} << kNodeBits) - 1);
    if (static_cast<i64>(it >> kNodeBits) != d[v].key) continue;
    if (v == stop) return;
    const Len dv = d[v];
    for (std::uint32_t i = g.first[v]; i < g.first[v + 1]; ++i) {
      const Arc& arc = g.arcs[i];
      const Len nd = arc.kind == 0 ? dv : make_len(i64{dv.a} + (arc.kind == 1), i64{dv.b} + (arc.kind == 2), floors);
      if (nd.key < d[arc.to].key) {
        d[arc.to] = nd;
        q[arc.kind].push_back(item(nd.key, arc.to));
      }
    }
  }
}

}  // namespace

namespace {

// Both overloads: each terminal a set of lattice points (a point pin: one; a shape: every integer
// point it holds), joined as the header says.
std::optional<Root2> minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                    const std::vector<std::vector<Point>>& terms) {
  const i64 nx = std::max<i64>(0, i64{domain.hi.x} - domain.lo.x + 1);
  const i64 ny = std::max<i64>(0, i64{domain.hi.y} - domain.lo.y + 1);
  if (nx * ny > 80 * 80) throw std::invalid_argument("oct_steiner_minimal_length: more than 80 * 80 lattice points");
  const std::size_t k = terms.size();
  if (k > 8) throw std::invalid_argument("oct_steiner_minimal_length: at most 8 distinct terminals");
  if (k == 0) return Root2{};

  const OctilinearReference ref(domain, obstacles);
  // Lattice point (x, y) of the box is index (x - lo.x) * ny + (y - lo.y); its wedges are nodes
  // node0[i] .. node0[i + 1] - 1, in the order of wedges_at.
  const std::size_t points = static_cast<std::size_t>(nx * ny);
  auto point_at = [&](std::size_t i) {
    return Point{static_cast<geom::Coord>(domain.lo.x + static_cast<i64>(i) / ny),
                 static_cast<geom::Coord>(domain.lo.y + static_cast<i64>(i) % ny)};
  };
  auto index_of = [&](Point p) {
    return static_cast<std::size_t>((i64{p.x} - domain.lo.x) * ny + (i64{p.y} - domain.lo.y));
  };
  auto in_box = [&](Point p) {
    return domain.lo.x <= p.x && p.x <= domain.hi.x && domain.lo.y <= p.y && p.y <= domain.hi.y;
  };
  std::vector<std::vector<Wedge>> wedges(points);
  std::vector<std::uint32_t> node0(points + 1, 0);
  for (std::size_t i = 0; i < points; ++i) {
    wedges[i] = ref.wedges_at(point_at(i));
    node0[i + 1] = node0[i] + static_cast<std::uint32_t>(wedges[i].size());
  }
  // Terminals: a point's one node, or at a pinch a node of its own joined at no cost to each of
  // the point's wedges (the pin is metal; see the header).
  std::size_t n = node0[points];
  std::vector<std::uint32_t> term(k);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // undirected, with weights below
  std::vector<std::int32_t> kinds;
  for (std::size_t t = 0; t < k; ++t) {
    std::vector<std::size_t> at;  // its free lattice points
    for (const Point p : terms[t])
      if (in_box(p) && !wedges[index_of(p)].empty()) at.push_back(index_of(p));
    if (at.empty() || (terms[t].size() == 1 && at.size() != 1)) return std::nullopt;
    if (at.size() == 1 && wedges[at[0]].size() == 1) {
      term[t] = node0[at[0]];
      continue;
    }
    term[t] = static_cast<std::uint32_t>(n++);
    for (const std::size_t i : at)
      for (std::uint32_t v = node0[i]; v < node0[i + 1]; ++v) {
        edges.push_back({term[t], v});
        kinds.push_back(0);
      }
  }
  if (k == 1) return Root2{};

  // The unit moves, each undirected edge once: right, up, up-right, down-right.
  constexpr int kMoves[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  for (std::size_t i = 0; i < points; ++i) {
    if (wedges[i].empty()) continue;
    const Point p = point_at(i);
    for (const auto& m : kMoves) {
      const Point q{static_cast<geom::Coord>(p.x + m[0]), static_cast<geom::Coord>(p.y + m[1])};
      if (!in_box(q)) continue;
      const std::size_t j = index_of(q);
      if (wedges[j].empty() || !ref.visible(p, q)) continue;
      const std::size_t wp = wedge_holding(wedges[i], m[0], m[1]);
      const std::size_t wq = wedge_holding(wedges[j], -m[0], -m[1]);
      if (wp == wedges[i].size() || wq == wedges[j].size()) continue;  // not after visible()
      edges.push_back({node0[i] + static_cast<std::uint32_t>(wp), node0[j] + static_cast<std::uint32_t>(wq)});
      kinds.push_back(m[0] != 0 && m[1] != 0 ? 2 : 1);
    }
  }
  if (n >= (std::size_t{1} << kNodeBits)) throw std::logic_error("oct_steiner_minimal_length: too many lattice nodes");
  Lattice g;
  g.first.assign(n + 1, 0);
  for (const auto& [u, v] : edges) ++g.first[u + 1], ++g.first[v + 1];
  for (std::size_t v = 0; v < n; ++v) g.first[v + 1] += g.first[v];
  g.arcs.resize(g.first[n]);
  std::vector<std::uint32_t> fill(g.first.begin(), g.first.end() - 1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    g.arcs[fill[edges[e].first]++] = {edges[e].second, kinds[e]};
    g.arcs[fill[edges[e].second]++] = {edges[e].first, kinds[e]};
  }

  // Dreyfus-Wagner rooted at terms[0]: dp over subsets of the other k - 1 terminals, row `mask`
  // of dp holding dp[mask][v] for every node v.
  const std::vector<i64>& floors = sqrt2_floors();
  const std::size_t m = k - 1, full = (std::size_t{1} << m) - 1;
  const std::size_t root = term[0];
  std::vector<Len> dp((full + 1) * n);
  std::vector<Item> queues[4];
  for (std::size_t mask = 1; mask <= full; ++mask) {
    Len* d = &dp[mask * n];
    if ((mask & (mask - 1)) == 0) {
      d[term[1 + static_cast<std::size_t>(__builtin_ctzll(mask))]] = make_len(0, 0, floors);
    } else {
      const std::size_t low = mask & (~mask + 1);
      for (std::size_t sub = (mask - 1) & mask; sub > 0; sub = (sub - 1) & mask) {
        if (!(sub & low)) continue;  // each split once
        const Len *a = &dp[sub * n], *b = &dp[(mask ^ sub) * n];
        for (std::size_t v = 0; v < n; ++v)
          if (a[v].key != kInfKey && b[v].key != kInfKey) {
            const Len s = make_len(i64{a[v].a} + b[v].a, i64{a[v].b} + b[v].b, floors);
            if (s.key < d[v].key) d[v] = s;
          }
      }
    }
    relax(g, d, n, mask == full ? root : n, floors, queues);
  }
  const Len best = dp[full * n + root];
  if (best.key == kInfKey) return std::nullopt;
  return Root2{best.a, best.b};
}

}  // namespace

std::optional<Root2> oct_steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                 std::span<const Point> terminals) {
  std::vector<Point> pts(terminals.begin(), terminals.end());
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() > 8) throw std::invalid_argument("oct_steiner_minimal_length: at most 8 distinct terminals");
  std::vector<std::vector<Point>> terms;
  for (const Point p : pts) terms.push_back({p});
  return minimal_length(domain, obstacles, terms);
}

std::optional<Root2> oct_steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                 std::span<const geom::Polygon> terminals) {
  if (terminals.size() > 8) throw std::invalid_argument("oct_steiner_minimal_length: at most 8 terminals");
  std::vector<std::vector<Point>> terms;
  for (const geom::Polygon& shape : terminals) {
    std::vector<Point> pts;
    if (shape.outer.size() == 1 && shape.holes.empty()) {
      pts.push_back(shape.outer[0]);
    } else {
      geom::Box b{shape.outer[0], shape.outer[0]};
      for (const Point v : shape.outer) {
        b.lo = {std::min(b.lo.x, v.x), std::min(b.lo.y, v.y)};
        b.hi = {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y)};
      }
      for (i64 x = b.lo.x; x <= b.hi.x; ++x)
        for (i64 y = b.lo.y; y <= b.hi.y; ++y) {
          const Point p{static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)};
          if (geom::locate(p, shape) != geom::Location::Outside) pts.push_back(p);
        }
    }
    terms.push_back(std::move(pts));
  }
  return minimal_length(domain, obstacles, terms);
}

}  // namespace taut::oracle
