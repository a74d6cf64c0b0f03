#include "geom/union_sweep.h"

#include <algorithm>
#include <cassert>
#include <numeric>
#include <memory_resource>
#include <optional>
#include <set>
#include <type_traits>
#include <stdexcept>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

namespace taut::geom::detail {

namespace {

using u128 = unsigned __int128;

u128 gcd128(u128 a, u128 b) {
  while (b != 0) {
    const u128 t = a % b;
    a = b;
    b = t;
  }
  return a;
}
u128 abs128(i128 v) { return v < 0 ? u128(-v) : u128(v); }
int cmp_frac(std::int64_t f1, std::int64_t d1, std::int64_t f2, std::int64_t d2) {
  const i128 l = i128{f1} * d2, r = i128{f2} * d1;
  return (l > r) - (l < r);
}
// Differences of points in 64 bits: the wavefront's frame obstacle lies one unit outside a
// domain that may reach +-(2^30 - 1), so a difference can reach 2^31 (not an int32).
struct Vec {
  i64 x, y;
};
i64 cross(Vec d1, Vec d2) { return d1.x * d2.y - d1.y * d2.x; }
Vec sub(Point a, Point b) { return {i64{a.x} - b.x, i64{a.y} - b.y}; }

struct Seg {
  Point a, b;  // as directed in its loop
  int loop = -1;
  bool box = false;
};

struct Piece {
  int u = 0, v = 0, seg = 0;  // u < v: vertex ids in lexicographic order
};

struct Group {  // merged collinear pieces between vertices u < v
  int u = 0, v = 0;
  Point sa, sb;  // supporting integer segment, sa lexicographically before sb
  int dw = 0, db = 0;  // winding above minus winding below (loops / domain box)
  int w_below = 0, b_below = 0;
  int bpred = -1;       // nearest boundary group below at insertion
  bool boundary = false;
  bool union_below = false, union_above = false;
};

bool covered(int w, int b) { return w >= 1 && b >= 1; }

// What the sweep's order reads of a group, packed: its supporting segment, its first vertex's id
// in verts, and that vertex as a point when it is an integer point (`integer`).
struct SweepKey {
  Point sa, sb, start;
  int u = 0;
  bool integer = true;
};

// Order of two groups crossing the sweep line (lexicographic sweep, pieces never cross).
struct Below {
  const std::vector<SweepKey>* keys;
  const std::vector<RPoint>* verts;
  // orient_sign(a, b, start of k), integer points without the call
  int side(Point a, Point b, const SweepKey& k) const {
    return k.integer ? sign(orient(a, b, k.start)) : orient_sign(a, b, (*verts)[static_cast<std::size_t>(k.u)]);
  }
  bool operator()(int a, int b) const {
    if (a == b) return false;
    const SweepKey& ga = (*keys)[static_cast<std::size_t>(a)];
    const SweepKey& gb = (*keys)[static_cast<std::size_t>(b)];
    if (ga.u == gb.u) return cross(sub(ga.sb, ga.sa), sub(gb.sb, gb.sa)) > 0;
    if (ga.u > gb.u) {
      const int s = side(gb.sa, gb.sb, ga);
      if (s != 0) return s < 0;
    } else {
      const int s = side(ga.sa, ga.sb, gb);
      if (s != 0) return s > 0;
    }
    // Only reachable if a piece were still active past its right end; keep a strict order.
    return cross(sub(ga.sb, ga.sa), sub(gb.sb, gb.sa)) > 0;
  }
};

// The sweep's order of the groups crossing the sweep line (union_loops): a sorted vector, or a
// balanced tree for inputs of more than kVectorSweep edges (there a sweep line may cross many
// edges, and a vector would move them all at each vertex below them). A position is where a
// group goes: below the entry there.
constexpr std::int64_t kVectorSweep = 8192;
[[noreturn]] void lost_group() { throw std::logic_error("union_loops: a group lost from the sweep's order"); }
struct VectorOrder {
  using Pos = std::size_t;
  std::vector<int> v;
  const Below* order;
  const std::vector<Group>* groups;
  Pos lower_bound(int g) const { return static_cast<Pos>(std::lower_bound(v.begin(), v.end(), g, *order) - v.begin()); }
  // Removes the run of groups that end at vertex x around g (`count` of them when >= 0); its place.
  Pos erase_ending(int g, int x, int count) {
    const Pos at = lower_bound(g);
    if (at == v.size() || v[at] != g) lost_group();
    Pos lo = at, hi = at + 1;
    while (lo > 0 && (*groups)[v[lo - 1]].v == x) --lo;
    while (hi < v.size() && (*groups)[v[hi]].v == x) ++hi;
    if (count >= 0 && hi - lo != static_cast<Pos>(count)) lost_group();
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(lo), v.begin() + static_cast<std::ptrdiff_t>(hi));
    return lo;
  }
  int below(Pos p) const { return p == 0 ? -1 : v[p - 1]; }
  // Inserts g at p, which then names the entry above it; the entry below it (-1: none).
  int insert(Pos& p, int g) {
    const int b = below(p);
    v.insert(v.begin() + static_cast<std::ptrdiff_t>(p++), g);
    return b;
  }
};
struct TreeOrder {
  using Set = std::pmr::set<int, Below>;
  using Pos = Set::iterator;
  Set s;
  const std::vector<Group>* groups;
  Pos lower_bound(int g) { return s.lower_bound(g); }
  Pos erase_ending(int g, int x, int count) {
    const Pos at = s.find(g);
    if (at == s.end()) lost_group();
    Pos lo = at, hi = std::next(at);
    int n = 1;
    while (lo != s.begin() && (*groups)[*std::prev(lo)].v == x) --lo, ++n;
    while (hi != s.end() && (*groups)[*hi].v == x) ++hi, ++n;
    if (count >= 0 && n != count) lost_group();
    return s.erase(lo, hi);
  }
  int below(Pos p) const { return p == s.begin() ? -1 : *std::prev(p); }
  int insert(Pos& p, int g) {  // (a wrong hint costs a search, never a wrong order)
    const Pos it = s.emplace_hint(p, g);
    p = std::next(it);
    return below(it);
  }
};

// Angle class of d seen counter-clockwise from ref, in (0, 2*pi]: 0 (0, pi), 1 pi,
// 2 (pi, 2 pi), 3 exactly 2 pi.
int angle_class(Vec ref, Vec d) {
  const i64 c = cross(ref, d);
  if (c > 0) return 0;
  if (c < 0) return 2;
  return ref.x * d.x + ref.y * d.y < 0 ? 1 : 3;
}
bool ccw_before(Vec ref, Vec d1, Vec d2) {  // angle(ref -> d1) < angle(ref -> d2)
  const int c1 = angle_class(ref, d1), c2 = angle_class(ref, d2);
  if (c1 != c2) return c1 < c2;
  if (c1 == 1 || c1 == 3) return false;
  return cross(d1, d2) > 0;
}

// Stable counting sort of v by key(x), which lies in [0, buckets); `scratch` (any contents)
// is swapped with v, so sorts in a row reuse one buffer.
template <class T, class Key>
void counting_sort(std::vector<T>& v, std::size_t buckets, Key key, std::vector<T>& scratch) {
  std::vector<std::size_t> first(buckets + 1, 0);
  for (const T& x : v) ++first[static_cast<std::size_t>(key(x)) + 1];
  for (std::size_t i = 0; i < buckets; ++i) first[i + 1] += first[i];
  scratch.resize(v.size());
  for (const T& x : v) scratch[first[static_cast<std::size_t>(key(x))]++] = x;
  v.swap(scratch);
}

// Sorts v[0, n) by the 64-bit key key(x), stably (the order of std::stable_sort by key): most
// significant varying bits first. The top eight bits in which the keys differ (fewer for fewer
// elements) split them into up to 256 runs by a stable counting sort (`scratch` holds n
// elements), and each run is sorted the same way, or by insertion when short. The keys here are
// points of a window, and many share a coordinate (tracks): a run is mostly a few points, so
// this reads the elements about twice, where sorting least significant byte first read them
// once for each of the six bytes in which a window's scaled coordinates vary (a twentieth of a
// window union's time).
template <class T, class Key>
void msd_sort(T* v, std::size_t n, Key key, T* scratch) {
  if (n < 32) {
    for (std::size_t i = 1; i < n; ++i) {
      T x = v[i];
      const std::uint64_t kx = key(x);
      std::size_t j = i;
      for (; j > 0 && key(v[j - 1]) > kx; --j) v[j] = v[j - 1];
      v[j] = x;
    }
    return;
  }
  std::uint64_t any = 0, all = ~std::uint64_t{0};
  for (std::size_t i = 0; i < n; ++i) any |= key(v[i]), all &= key(v[i]);
  const std::uint64_t differ = any ^ all;
  if (differ == 0) return;  // equal keys: already in order
  const int high = 63 - __builtin_clzll(differ);
  // (fewer runs for fewer elements, about one per two: 16 to 256)
  const int bits = std::clamp(62 - __builtin_clzll(n), 4, 8), buckets = 1 << bits;
  const int shift = std::max(0, high - bits + 1);
  const std::uint64_t mask = static_cast<std::uint64_t>(buckets - 1);
  std::size_t first[257] = {};
  for (std::size_t i = 0; i < n; ++i) ++first[(key(v[i]) >> shift & mask) + 1];
  for (int b = 0; b < buckets; ++b) first[b + 1] += first[b];
  std::size_t fill[256];
  std::copy(first, first + buckets, fill);
  for (std::size_t i = 0; i < n; ++i) scratch[fill[key(v[i]) >> shift & mask]++] = v[i];
  std::copy(scratch, scratch + n, v);
  if (shift == 0) return;  // every run holds one key
  for (int b = 0; b < buckets; ++b)
    if (first[b + 1] - first[b] > 1) msd_sort(v + first[b], first[b + 1] - first[b], key, scratch);
}

template <class T, class Key>
void radix_sort(std::vector<T>& v, Key key) {
  std::vector<T> scratch(v.size());
  msd_sort(v.data(), v.size(), key, scratch.data());
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

void sort_by_key(std::vector<std::pair<std::uint64_t, int>>& v) {
  radix_sort(v, [](const std::pair<std::uint64_t, int>& k) { return k.first; });
}

RPoint to_rpoint(Point p) { return {p.x, p.y, 0, 0, 1}; }

RPoint to_rpoint(const RationalPoint& r) {
  i128 x = r.x_num, y = r.y_num, den = r.den;
  const u128 g = gcd128(gcd128(abs128(x), abs128(y)), abs128(den));
  x /= i128(g);
  y /= i128(g);
  den /= i128(g);
  const i128 xi = floor_div(x, den), yi = floor_div(y, den);
  RPoint p;
  p.xi = static_cast<Coord>(xi);
  p.yi = static_cast<Coord>(yi);
  p.xf = static_cast<std::int64_t>(x - xi * den);
  p.yf = static_cast<std::int64_t>(y - yi * den);
  p.d = static_cast<std::int64_t>(den);
  return p;
}

bool lex_less(const RPoint& a, const RPoint& b) {
  if (a.xi != b.xi) return a.xi < b.xi;
  if (a.d != 1 || b.d != 1) {
    const int c = cmp_frac(a.xf, a.d, b.xf, b.d);
    if (c != 0) return c < 0;
  }
  if (a.yi != b.yi) return a.yi < b.yi;
  if (a.d != 1 || b.d != 1) return cmp_frac(a.yf, a.d, b.yf, b.d) < 0;
  return false;
}

int orient_sign(Point a, Point b, const RPoint& v) {
  if (v.d == 1) return sign(orient(a, b, v.floor()));
  // |(v - a) * d| < 2^31 * 2^63 and |b - a| < 2^31: each product < 2^125, difference < 2^126.
  const i128 dx = i128{b.x} - a.x, dy = i128{b.y} - a.y;
  const i128 vx = (i128{v.xi} - a.x) * v.d + v.xf;
  const i128 vy = (i128{v.yi} - a.y) * v.d + v.yf;
  return sign(dx * vy - dy * vx);
}

UnionResult union_loops(const std::vector<Loop>& loops, const Box& domain, std::int64_t sweep_budget,
                        std::int64_t vector_sweep) {
  UnionResult result;

  // --- Edges of the loops and of the domain box.
  std::vector<Seg> segs;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& pts = loops[l].points;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Point a = pts[i], b = pts[(i + 1) % pts.size()];
      if (a != b) segs.push_back({a, b, static_cast<int>(l), false});
    }
  }
  if (segs.empty()) return result;
  {
    const Point c[4] = {domain.lo, {domain.hi.x, domain.lo.y}, domain.hi, {domain.lo.x, domain.hi.y}};
    for (int i = 0; i < 4; ++i)
      if (c[i] != c[(i + 1) % 4]) segs.push_back({c[i], c[(i + 1) % 4], -1, true});
  }
  const int ns = static_cast<int>(segs.size());

  // --- Split points from every pair of edges whose closed boxes meet. The pairs come from a
  // sweep over x (boxes by their left side, compared with the boxes still open, whose right side
  // is not left of it): on layouts few boxes span a sweep line, and this took a third of the
  // R-tree's time there. When the comparisons pass 64 per box plus 2^20 (many long edges
  // open at once), the pairs are found again with a packed R-tree of the boxes instead. The
  // pairs, and so the splits, are the same either way (and the order they come in changes no
  // output: every split point is sorted and deduplicated below).
  std::vector<std::pair<int, RPoint>> splits;
  {
    struct SBox {
      Coord lox, loy, hix, hiy;
    };
    std::vector<SBox> boxes(static_cast<std::size_t>(ns));
    for (int i = 0; i < ns; ++i) {
      const Seg& g = segs[static_cast<std::size_t>(i)];
      boxes[static_cast<std::size_t>(i)] = {std::min(g.a.x, g.b.x), std::min(g.a.y, g.b.y), std::max(g.a.x, g.b.x),
                                            std::max(g.a.y, g.b.y)};
    }
    auto consider = [&](int i, int j) {  // i < j, their boxes meet
      const Seg& s = segs[static_cast<std::size_t>(i)];
      const Seg& t = segs[static_cast<std::size_t>(j)];
      // Edges with a common end that are not collinear meet only there (most pairs: an edge and
      // the next one of its loop): nothing to split.
      if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) {
        const Point c = s.a == t.a || s.a == t.b ? s.a : s.b;
        if (orient(c, c == s.a ? s.b : s.a, c == t.a ? t.b : t.a) != 0) return;
      }
      const SegmentIntersection r = intersect({s.a, s.b}, {t.a, t.b});
      if (r == SegmentIntersection::None) return;
      if (r == SegmentIntersection::Proper) {
        // (a vertical and a horizontal edge, most crossings here: the point without a division)
        const RPoint p = s.a.x == s.b.x && t.a.y == t.b.y   ? to_rpoint(Point{s.a.x, t.a.y})
                         : s.a.y == s.b.y && t.a.x == t.b.x ? to_rpoint(Point{t.a.x, s.a.y})
                                                            : to_rpoint(line_intersection({s.a, s.b}, {t.a, t.b}));
        splits.emplace_back(i, p);
        splits.emplace_back(j, p);
        if (!p.is_integer()) ++result.proper_crossings;
        return;
      }
      for (Point e : {s.a, s.b})
        if (e != t.a && e != t.b && on_segment(e, t.a, t.b)) splits.emplace_back(j, to_rpoint(e));
      for (Point e : {t.a, t.b})
        if (e != s.a && e != s.b && on_segment(e, s.a, s.b)) splits.emplace_back(i, to_rpoint(e));
    };
    // (by left side, then index: one 64-bit key each, left side offset to unsigned)
    std::vector<int> by_left(static_cast<std::size_t>(ns));
    {
      std::vector<std::uint64_t> keyed(static_cast<std::size_t>(ns));
      for (int i = 0; i < ns; ++i)
        keyed[static_cast<std::size_t>(i)] =
            std::uint64_t{static_cast<std::uint32_t>(boxes[static_cast<std::size_t>(i)].lox) ^ 0x80000000u} << 32 |
            static_cast<std::uint32_t>(i);
      radix_sort(keyed, [](std::uint64_t k) { return k; });
      for (int i = 0; i < ns; ++i) by_left[static_cast<std::size_t>(i)] = static_cast<int>(keyed[static_cast<std::size_t>(i)] & 0xffffffffu);
    }
    const std::int64_t budget = sweep_budget >= 0 ? sweep_budget : 64 * static_cast<std::int64_t>(ns) + (std::int64_t{1} << 20);
    std::int64_t compared = 0;
    // The open boxes are kept in bands of y (each box in every band its y-range meets; a closed
    // one is dropped from a band when that band is next read), so a box is compared only with
    // the open boxes in its own bands: on the net router's windows, long wire edges are open
    // together over much of the sweep, and one list of them all cost some 40 comparisons per
    // box. A pair whose boxes meet is considered once, in the band of the lower end of their
    // common y-range (a band both lie in).
    std::int64_t ylo = boxes[0].loy, yhi = boxes[0].hiy;
    for (const SBox& x : boxes) ylo = std::min<std::int64_t>(ylo, x.loy), yhi = std::max<std::int64_t>(yhi, x.hiy);
    // (bands 2^shift high, at most ns / 8 of them, up to 1024: a band is a shift, not a division)
    const std::int64_t most = std::clamp<std::int64_t>(ns / 8, 1, 1024);
    int shift = 0;
    while (((yhi - ylo) >> shift) + 1 > most) ++shift;
    const std::int64_t nbands = ((yhi - ylo) >> shift) + 1;
    auto band = [&](std::int64_t y) { return static_cast<std::size_t>((y - ylo) >> shift); };
    // (each open box is held with its edge's index, so the scan reads the lists in order)
    struct Open {
      SBox box;
      int i;
    };
    // (for small inputs, a window's, the bands' lists are kept from one call to the next on each
    // thread, emptied: made anew, their growth was most of its calls to the allocator; a large
    // input's lists are its own, so no thread keeps their size)
    thread_local std::vector<std::vector<Open>> kept;
    std::vector<std::vector<Open>> own;
    std::vector<std::vector<Open>>& open = ns <= kVectorSweep ? kept : own;
    if (open.size() < static_cast<std::size_t>(nbands)) open.resize(static_cast<std::size_t>(nbands));
    for (std::size_t k = 0; k < static_cast<std::size_t>(nbands); ++k) open[k].clear();
    bool swept = true;
    for (const int b : by_left) {
      const SBox& bb = boxes[static_cast<std::size_t>(b)];
      const std::size_t k0 = band(bb.loy), k1 = band(bb.hiy);
      for (std::size_t k = k0; k <= k1; ++k) {
        std::vector<Open>& list = open[k];
        std::size_t keep = 0;
        for (std::size_t m = 0; m < list.size(); ++m) {
          const Open o = list[m];
          const SBox& ab = o.box;
          if (ab.hix < bb.lox) continue;  // closed for good: every later box starts right of it
          list[keep++] = o;
          if (ab.loy <= bb.hiy && bb.loy <= ab.hiy && band(std::max(ab.loy, bb.loy)) == k)
            consider(std::min(o.i, b), std::max(o.i, b));
        }
        list.resize(keep);
        list.push_back({bb, b});
        compared += static_cast<std::int64_t>(keep) + 1;
      }
      if (compared > budget || sweep_budget == 0) {
        swept = false;
        break;
      }
    }
    if (!swept) {
      splits.clear();
      result.proper_crossings = 0;
      namespace bg = boost::geometry;
      namespace bgi = boost::geometry::index;
      // int64 like index.cpp: the R*-tree sums coordinates (centroids), which overflows int at
      // the wavefront's frame (domain +- 1, up to 2^30).
      using BPoint = bg::model::point<std::int64_t, 2, bg::cs::cartesian>;
      using BBox = bg::model::box<BPoint>;
      using Value = std::pair<BBox, int>;
      std::vector<Value> values;
      values.reserve(segs.size());
      for (int i = 0; i < ns; ++i) {
        const SBox& x = boxes[static_cast<std::size_t>(i)];
        values.emplace_back(BBox(BPoint(x.lox, x.loy), BPoint(x.hix, x.hiy)), i);
      }
      const bgi::rtree<Value, bgi::rstar<16>> tree(values.begin(), values.end());
      std::vector<Value> hits;
      for (int i = 0; i < ns; ++i) {
        hits.clear();
        tree.query(bgi::intersects(values[static_cast<std::size_t>(i)].first), std::back_inserter(hits));
        for (const Value& h : hits)
          if (h.second > i) consider(i, h.second);
      }
    }
    result.pairs_by_rtree = !swept;
  }

  // --- Vertex ids in lexicographic order.
  std::vector<RPoint> pts;
  std::vector<int> owner;
  pts.reserve(2 * segs.size() + splits.size());
  owner.reserve(pts.capacity());
  for (int i = 0; i < ns; ++i) {
    pts.push_back(to_rpoint(segs[i].a));
    owner.push_back(i);
    pts.push_back(to_rpoint(segs[i].b));
    owner.push_back(i);
  }
  for (const auto& [i, p] : splits) {
    pts.push_back(p);
    owner.push_back(i);
  }
  splits.clear();
  splits.shrink_to_fit();
  std::vector<int> order(pts.size());
  {
    // Sorted by one 64-bit key per point, (x, y) in doubled units offset to unsigned: 2 xi for an
    // integer x, 2 xi + 1 for x in (xi, xi + 1), the same for y, and y left out (0) when x is not
    // an integer. The key never orders two points against lex_less; equal keys hold equal
    // integer points or points that only lex_less tells apart (x, or y, in one open unit
    // interval), and such runs are sorted by it afterwards. (The indirect sort by lex_less was a
    // tenth of the union's time on the net router's windows; sloped edges there make rational
    // crossings in about a quarter of them.)
    Coord xlo = pts.front().xi, ylo = pts.front().yi, xhi = xlo, yhi = ylo;
    for (const RPoint& p : pts) {
      xlo = std::min(xlo, p.xi), xhi = std::max(xhi, p.xi);
      ylo = std::min(ylo, p.yi), yhi = std::max(yhi, p.yi);
    }
    const bool fits = 2 * (i64{xhi} - xlo) + 1 <= i64{0xffffffff} && 2 * (i64{yhi} - ylo) + 1 <= i64{0xffffffff};
    if (fits) {
      auto key = [&](const RPoint& p) {
        const std::uint64_t kx = 2 * std::uint64_t(i64{p.xi} - xlo) + (p.xf != 0);
        const std::uint64_t ky = p.xf != 0 ? 0 : 2 * std::uint64_t(i64{p.yi} - ylo) + (p.yf != 0);
        return kx << 32 | ky;
      };
      std::vector<std::pair<std::uint64_t, int>> keyed(pts.size());
      for (std::size_t k = 0; k < pts.size(); ++k) keyed[k] = {key(pts[k]), static_cast<int>(k)};
      sort_by_key(keyed);
      for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
      for (std::size_t k = 0; k < keyed.size();) {
        std::size_t e = k + 1;
        bool exact = pts[order[k]].is_integer();
        for (; e < keyed.size() && keyed[e].first == keyed[k].first; ++e) exact = exact && pts[order[e]].is_integer();
        if (!exact)
          std::sort(order.begin() + static_cast<std::ptrdiff_t>(k), order.begin() + static_cast<std::ptrdiff_t>(e),
                    [&](int a, int b) { return lex_less(pts[a], pts[b]); });
        k = e;
      }
    } else {
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](int a, int b) { return lex_less(pts[a], pts[b]); });
    }
  }
  std::vector<RPoint> verts;
  // (segment, vertex id) for every vertex on a segment, by segment, then by vertex: a counting
  // sort by segment of the vertices in order (each segment's list then comes sorted by id),
  // duplicates (a split at an end, or twice) dropped.
  std::vector<std::pair<int, int>> seg_vertex;
  {
    std::vector<int> vid(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k == 0 || !(pts[order[k]] == verts.back())) verts.push_back(pts[order[k]]);
      vid[k] = static_cast<int>(verts.size()) - 1;
    }
    std::vector<int> first(static_cast<std::size_t>(ns) + 1, 0);
    for (const int k : order) ++first[static_cast<std::size_t>(owner[k]) + 1];
    for (int i = 0; i < ns; ++i) first[i + 1] += first[i];
    seg_vertex.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      const int sgm = owner[order[k]];
      seg_vertex[static_cast<std::size_t>(first[sgm]++)] = {sgm, vid[k]};
    }
  }
  pts = {};
  owner = {};
  order = {};
  seg_vertex.erase(std::unique(seg_vertex.begin(), seg_vertex.end()), seg_vertex.end());
  const int nv = static_cast<int>(verts.size());

  // --- Pieces between consecutive vertices of each edge, merged into groups.
  std::vector<Piece> pieces;
  pieces.reserve(seg_vertex.size());
  for (std::size_t k = 0; k + 1 < seg_vertex.size(); ++k)
    if (seg_vertex[k].first == seg_vertex[k + 1].first)
      pieces.push_back({seg_vertex[k].second, seg_vertex[k + 1].second, seg_vertex[k].first});
  seg_vertex = {};
  // Ordered by (u, v, seg): two stable counting sorts, by v and then by u, of pieces that come
  // ordered by seg.
  {
    std::vector<Piece> scratch;
    counting_sort(pieces, static_cast<std::size_t>(nv), [](const Piece& p) { return p.v; }, scratch);
    counting_sort(pieces, static_cast<std::size_t>(nv), [](const Piece& p) { return p.u; }, scratch);
  }
  std::vector<Group> groups;
  std::vector<int> piece_group(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Piece& p = pieces[k];
    if (groups.empty() || groups.back().u != p.u || groups.back().v != p.v) {
      Group g;
      g.u = p.u;
      g.v = p.v;
      const Seg& s = segs[p.seg];
      g.sa = std::min(s.a, s.b);
      g.sb = std::max(s.a, s.b);
      groups.push_back(g);
    }
    Group& g = groups.back();
    const Seg& s = segs[p.seg];
    const int delta = s.a < s.b ? 1 : -1;  // loop direction agrees with lexicographic direction
    (s.box ? g.db : g.dw) += delta;
    piece_group[k] = static_cast<int>(groups.size()) - 1;
  }
  const int ng = static_cast<int>(groups.size());

  // Groups starting at each vertex, lowest direction first; groups ending at each vertex.
  // (the groups come ordered by u: each vertex's run is sorted by direction; no two groups from
  // one vertex share a direction, as collinear pieces are split at each other's ends)
  std::vector<int> start_order(ng);
  std::iota(start_order.begin(), start_order.end(), 0);
  for (int k = 0; k < ng;) {
    int e = k + 1;
    while (e < ng && groups[e].u == groups[k].u) ++e;
    if (e - k > 1)
      std::sort(start_order.begin() + k, start_order.begin() + e, [&](int a, int b) {
        return cross(sub(groups[a].sb, groups[a].sa), sub(groups[b].sb, groups[b].sa)) > 0;
      });
    k = e;
  }
  std::vector<int> end_first(nv + 1, 0), end_list(ng);
  for (const Group& g : groups) ++end_first[g.v + 1];
  for (int i = 0; i < nv; ++i) end_first[i + 1] += end_first[i];
  {
    std::vector<int> fill(end_first.begin(), end_first.end() - 1);
    for (int g = 0; g < ng; ++g) end_list[fill[groups[g].v]++] = g;
  }

  // --- Sweep.
  std::vector<SweepKey> keys(static_cast<std::size_t>(ng));
  for (int g = 0; g < ng; ++g) {
    const RPoint& v = verts[static_cast<std::size_t>(groups[g].u)];
    keys[static_cast<std::size_t>(g)] = {groups[g].sa, groups[g].sb, v.floor(), groups[g].u, v.is_integer()};
  }
  const Below below{&keys, &verts};
  // The groups crossing the sweep line, and the boundary groups among them, sorted by `below`:
  // the groups that end at a vertex are adjacent there (a group between two of them would pass
  // through the vertex, and pieces are split at every vertex on them), and the groups that start
  // there go in their place, upward; so each vertex costs one search in each order. (Vectors,
  // for up to kVectorSweep edges: each vertex then also moves the entries above it, few on a
  // window, where a balanced tree cost a third more of the union's time; a tree beyond.)
  auto sweep = [&](auto& status, auto& bstatus) {
    std::size_t next_start = 0;
    for (int x = 0; x < nv; ++x) {
      // where the vertex lies in each order: the place of the groups that end there, or, when
      // none does, found by the first group that starts there (none: nothing to insert)
      using Pos = typename std::remove_reference_t<decltype(status)>::Pos;
      std::optional<Pos> at, bat;
      if (end_first[x] < end_first[x + 1]) {
        int gb = -1;
        for (int k = end_first[x]; k < end_first[x + 1] && gb < 0; ++k)
          if (groups[end_list[k]].boundary) gb = end_list[k];
        at = status.erase_ending(end_list[end_first[x]], x, end_first[x + 1] - end_first[x]);
        if (gb >= 0) bat = bstatus.erase_ending(gb, x, -1);
      }
      if (next_start == start_order.size() || groups[start_order[next_start]].u != x) continue;
      const int first = start_order[next_start];
      if (!at) at = status.lower_bound(first);
      if (!bat) bat = bstatus.lower_bound(first);
      Pos p = *at, bp = *bat;
      while (next_start < start_order.size() && groups[start_order[next_start]].u == x) {
        const int gi = start_order[next_start++];
        Group& g = groups[gi];
        const int below_g = status.insert(p, gi);
        if (below_g >= 0) {
          const Group& q = groups[below_g];
          g.w_below = q.w_below + q.dw;
          g.b_below = q.b_below + q.db;
        }
        g.union_below = covered(g.w_below, g.b_below);
        g.union_above = covered(g.w_below + g.dw, g.b_below + g.db);
        g.boundary = g.union_below != g.union_above;
        // the nearest boundary group below: the one under the vertex among the boundary groups
        if (g.boundary)
          g.bpred = bstatus.insert(bp, gi);
        else if (g.union_below)
          g.bpred = bstatus.below(bp);
      }
    }
  };
  if (ns <= (vector_sweep >= 0 ? vector_sweep : kVectorSweep)) {
    VectorOrder status{{}, &below, &groups}, bstatus{{}, &below, &groups};
    sweep(status, bstatus);
  } else {
    // (their nodes from one arena, freed together)
    std::pmr::monotonic_buffer_resource arena;
    TreeOrder status{std::pmr::set<int, Below>(below, &arena), &groups};
    TreeOrder bstatus{std::pmr::set<int, Below>(below, &arena), &groups};
    sweep(status, bstatus);
  }

  // --- Boundary edges directed with the union on their left, linked into rings.
  std::vector<int> bedges;
  for (int g = 0; g < ng; ++g)
    if (groups[g].boundary) bedges.push_back(g);
  const int nb = static_cast<int>(bedges.size());
  std::vector<int> edge_of_group(ng, -1);
  std::vector<int> from(nb), to(nb);
  std::vector<Segment> line(nb);
  for (int e = 0; e < nb; ++e) {
    const Group& g = groups[bedges[e]];
    edge_of_group[bedges[e]] = e;
    const bool fwd = g.union_above;  // above = left of the lexicographic direction
    from[e] = fwd ? g.u : g.v;
    to[e] = fwd ? g.v : g.u;
    line[e] = fwd ? Segment{g.sa, g.sb} : Segment{g.sb, g.sa};
  }
  std::vector<int> out_first(nv + 1, 0), out_list(nb);
  for (int e = 0; e < nb; ++e) ++out_first[from[e] + 1];
  for (int i = 0; i < nv; ++i) out_first[i + 1] += out_first[i];
  {
    std::vector<int> fill(out_first.begin(), out_first.end() - 1);
    for (int e = 0; e < nb; ++e) out_list[fill[from[e]]++] = e;
  }
  std::vector<int> next(nb, -1);
  for (int e = 0; e < nb; ++e) {
    const int v = to[e];
    const int b = out_first[v], n = out_first[v + 1] - b;
    if (n == 1) {
      next[e] = out_list[b];
      continue;
    }
    if (n == 0) throw std::logic_error("union_loops: boundary edge without successor");
    const Vec ref = sub(line[e].a, line[e].b);  // from v back along e
    int best = -1;
    for (int k = b; k < b + n; ++k) {
      const int o = out_list[k];
      if (best < 0 || ccw_before(ref, sub(line[o].b, line[o].a), sub(line[best].b, line[best].a)))
        best = o;
    }
    next[e] = best;
  }
  std::vector<int> ring_of(nb, -1);
  for (int e0 = 0; e0 < nb; ++e0) {
    if (ring_of[e0] >= 0) continue;
    const int r = static_cast<int>(result.rings.size());
    UnionRing ring;
    std::size_t len = 1;  // (a reserve only: bounded should the walk not come back to e0)
    for (int e = next[e0]; e != e0 && len < static_cast<std::size_t>(nb); e = next[e]) ++len;
    ring.vertices.reserve(len);
    ring.lines.reserve(len);
    for (int e = e0; ring_of[e] < 0; e = next[e]) {
      ring_of[e] = r;
      ring.vertices.push_back(verts[from[e]]);
      ring.lines.push_back(line[e]);
      if (!verts[from[e]].is_integer()) ++result.rational_vertices;
    }
    result.rings.push_back(std::move(ring));
  }

  // --- Connected obstacles.
  const int nr = static_cast<int>(result.rings.size());
  UnionFind uf(nr);
  for (int v = 0; v < nv; ++v)
    for (int k = out_first[v] + 1; k < out_first[v + 1]; ++k)
      uf.unite(ring_of[out_list[out_first[v]]], ring_of[out_list[k]]);
  for (int e = 0; e < nb; ++e) {
    const Group& g = groups[bedges[e]];
    if (g.union_below && g.bpred >= 0) uf.unite(ring_of[e], ring_of[edge_of_group[g.bpred]]);
  }
  std::vector<int> comp_id(nr, -1);
  for (int r = 0; r < nr; ++r) {
    const int root = uf.find(r);
    if (comp_id[root] < 0) comp_id[root] = result.components++;
    result.rings[r].component = comp_id[root];
  }

  // --- Which obstacle each loop ended in. (A loop's pieces nearly all name the component its
  // last piece named: those are not listed again before the sort.)
  std::vector<int> last_component(loops.size(), -1);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Seg& s = segs[pieces[k].seg];
    if (s.box) continue;
    const Group& g = groups[piece_group[k]];
    int e = -1;
    if (g.boundary)
      e = edge_of_group[piece_group[k]];
    else if (g.union_below && g.bpred >= 0)
      e = edge_of_group[g.bpred];
    if (e < 0) continue;
    const int c = result.rings[ring_of[e]].component;
    if (last_component[static_cast<std::size_t>(s.loop)] == c) continue;
    last_component[static_cast<std::size_t>(s.loop)] = c;
    result.tag_components.emplace_back(loops[s.loop].tag, c);
  }
  std::sort(result.tag_components.begin(), result.tag_components.end());
  result.tag_components.erase(
      std::unique(result.tag_components.begin(), result.tag_components.end()),
      result.tag_components.end());
  return result;
}

}  // namespace taut::geom::detail
