// Continuous Dijkstra for L1 (Mitchell 1992, §3-§5). See wavefront.h for the model, the
// symbolic shear that removes degeneracies and the rules used at each event.
#include "router/wavefront.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cassert>
#include <limits>
#include <queue>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <variant>

#include "geom/index.h"
#include "geom/normalize.h"
#include "geom/fixed_norm.h"
#include "geom/predicates.h"

namespace taut::router {
namespace {

using geom::Box;
using geom::ceil_div;
using geom::floor_div;
using geom::i128;
using geom::i64;
using geom::Point;
using geom::Polygon;
using std::uint32_t;
using std::uint64_t;
using std::uint8_t;

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
constexpr uint32_t kUnknown = kNone - 1;  // a track ray not shot yet (WaveCore::ray_cache)

// A number c0 + c1*e + c2*e^2 for an infinitesimal e > 0, compared lexicographically.
struct T3 {
  i64 a = 0, b = 0, c = 0;
  friend bool operator==(const T3&, const T3&) = default;
  [[gnu::always_inline]] friend auto operator<=>(const T3& x, const T3& y) {
    if (x.a != y.a) return x.a <=> y.a;
    if (x.b != y.b) return x.b <=> y.b;
    return x.c <=> y.c;
  }
  T3 operator+(const T3& o) const { return {a + o.a, b + o.b, c + o.c}; }
  T3 operator-(const T3& o) const { return {a - o.a, b - o.b, c - o.c}; }
};

// Direction frames: the wave moves "north-east" in local coordinates (u, v) = M (X, Y) of the
// sheared plane, M an integer matrix with determinant +-1 (so lattice points stay lattice
// points and lines stay lines); the local axes u (east) and v (north) are the frame's two track
// directions. L1 (frames 0-3): M = diag(sx, sy), one frame per quadrant (NE, NW, SW, SE), level
// u + v. Octilinear (frames 4-11): one frame per cone between two neighbouring orientations, its
// local east the axis direction and its local north the diagonal, level u + sqrt2 v (a distance
// t*east + s*north, t, s >= 0, has octilinear length t + sqrt2 s). Fixed-orientation norms
// (geom/fixed_norm.h, frames 12-107): one frame per cone between consecutive directions d_i,
// d_{i+1} (east d_i, north d_{i+1}: determinant 1 by the Farey construction), level
// w_i u + w_{i+1} v, which is the cone's functional lambda_i applied to (X, Y).
struct Frame {
  i64 a, b, c, d;          // u = a*X + b*Y, v = c*X + d*Y
  i64 ia, ib, ic, id;      // the inverse: X = ia*u + ib*v, Y = ic*u + id*v
  int sigma;               // det M: +1 keeps orientation, -1 mirrors it
  // Integer levels (L1, norms): level = wu*u + wv*v = la*X + lb*Y (octilinear: unused).
  i64 wu = 1, wv = 1, la = 0, lb = 0;
  // The ray-cache mode (sweep_rays()) of the east and north directions, and their sense along
  // the mode's direction (+1 or -1).
  int east_mode = 0, east_sense = 1, north_mode = 0, north_sense = 1;
};
// The orientations (one direction each, y > 0 or y == 0 < x) whose track rays a metric caches,
// in mode order: L1 and octilinear share the first two / four.
struct ModeDir {
  i64 x, y;
};
constexpr ModeDir kAxisModes[4] = {{0, 1}, {1, 0}, {1, 1}, {-1, 1}};

constexpr int kNormFirst2 = 12, kNormFirst3 = kNormFirst2 + geom::FareyNorm<2>::kDirs,
              kNormFirst4 = kNormFirst3 + geom::FareyNorm<3>::kDirs,
              kFrameCount = kNormFirst4 + geom::FareyNorm<4>::kDirs;

// The mode of world direction (x, y) among `modes`, and its sense.
constexpr void find_mode(const ModeDir* modes, int n, i64 x, i64 y, int& mode, int& sense) {
  for (int j = 0; j < n; ++j) {
    if (modes[j].x * y - modes[j].y * x != 0) continue;
    mode = j;
    sense = modes[j].x * x + modes[j].y * y > 0 ? 1 : -1;
    return;
  }
  mode = -1;
}
template <int N>
constexpr void add_norm_frames(std::array<Frame, kFrameCount>& out, int first,
                               const geom::FareyNorm<N>& norm) {
  constexpr int m = geom::FareyNorm<N>::kDirs;
  std::array<ModeDir, m / 2> modes{};
  for (int j = 0; j < m / 2; ++j) modes[j] = {norm.dir[j].x, norm.dir[j].y};
  for (int i = 0; i < m; ++i) {
    const auto e = norm.dir[i], g = norm.dir[(i + 1) % m];
    Frame f{g.y, -g.x, -e.y, e.x, e.x, g.x, e.y, g.y, 1};
    f.wu = norm.weight[i];
    f.wv = norm.weight[(i + 1) % m];
    f.la = f.wu * f.a + f.wv * f.c;
    f.lb = f.wu * f.b + f.wv * f.d;
    find_mode(modes.data(), m / 2, e.x, e.y, f.east_mode, f.east_sense);
    find_mode(modes.data(), m / 2, g.x, g.y, f.north_mode, f.north_sense);
    out[first + i] = f;
  }
}
constexpr std::array<Frame, kFrameCount> make_frames() {
  std::array<Frame, kFrameCount> out{};
  const Frame fixed[12] = {
      {1, 0, 0, 1, 1, 0, 0, 1, 1},      // L1 NE
      {-1, 0, 0, 1, -1, 0, 0, 1, -1},   // L1 NW
      {-1, 0, 0, -1, -1, 0, 0, -1, 1},  // L1 SW
      {1, 0, 0, -1, 1, 0, 0, -1, -1},   // L1 SE
      // octilinear, inverse columns (east, north):
      {1, -1, 0, 1, 1, 1, 0, 1, 1},        // E, NE
      {-1, 1, 1, 0, 0, 1, 1, 1, -1},       // N, NE
      {1, 1, -1, 0, 0, -1, 1, 1, 1},       // N, NW
      {-1, -1, 0, 1, -1, -1, 0, 1, -1},    // W, NW
      {-1, 1, 0, -1, -1, -1, 0, -1, 1},    // W, SW
      {1, -1, -1, 0, 0, -1, -1, -1, -1},   // S, SW
      {-1, -1, 1, 0, 0, 1, -1, -1, 1},     // S, SE
      {1, 1, 0, -1, 1, 1, 0, -1, -1},      // E, SE
  };
  for (int d = 0; d < 12; ++d) {
    Frame f = fixed[d];
    f.la = f.a + f.c;
    f.lb = f.b + f.d;
    find_mode(kAxisModes, d < 4 ? 2 : 4, f.ia, f.ic, f.east_mode, f.east_sense);
    find_mode(kAxisModes, d < 4 ? 2 : 4, f.ib, f.id, f.north_mode, f.north_sense);
    out[d] = f;
  }
  add_norm_frames(out, kNormFirst2, geom::kFarey2);
  add_norm_frames(out, kNormFirst3, geom::kFarey3);
  add_norm_frames(out, kNormFirst4, geom::kFarey4);
  return out;
}
constexpr std::array<Frame, kFrameCount> kFrames = make_frames();
constexpr bool frames_consistent() {
  for (const Frame& f : kFrames) {
    if (f.a * f.ia + f.b * f.ic != 1 || f.a * f.ib + f.b * f.id != 0) return false;
    if (f.c * f.ia + f.d * f.ic != 0 || f.c * f.ib + f.d * f.id != 1) return false;
    if (f.a * f.d - f.b * f.c != f.sigma) return false;
    if (f.east_mode < 0 || f.north_mode < 0) return false;
  }
  // octilinear: local east an axis, local north a diagonal; consecutive cones share an axis
  for (int d = 4; d < 12; ++d) {
    const Frame& f = kFrames[d];
    if ((f.ia == 0) == (f.ic == 0)) return false;   // east = (ia, ic) has one zero
    if (f.ib == 0 || f.id == 0) return false;       // north = (ib, id) has none
  }
  // norms: the level meets the weights on the frame's two directions
  for (int d = kNormFirst2; d < kFrameCount; ++d) {
    const Frame& f = kFrames[d];
    if (f.la * f.ia + f.lb * f.ic != f.wu || f.la * f.ib + f.lb * f.id != f.wv) return false;
  }
  return true;
}
static_assert(frames_consistent());
// Range [lo, hi] of a*x + b*y over the box [blo, bhi] (exact in int64: |a|, |b| <= 1 here).
struct Range {
  i64 lo, hi;
};
[[gnu::always_inline]] inline Range linear_range(i64 a, i64 b, Point blo, Point bhi) {
  const i64 x0 = a * blo.x, x1 = a * bhi.x, y0 = b * blo.y, y1 = b * bhi.y;
  return {std::min(x0, x1) + std::min(y0, y1), std::max(x0, x1) + std::max(y0, y1)};
}
[[gnu::always_inline]] inline Range u_range(int d, Point blo, Point bhi) { return linear_range(kFrames[d].a, kFrames[d].b, blo, bhi); }
[[gnu::always_inline]] inline Range v_range(int d, Point blo, Point bhi) { return linear_range(kFrames[d].c, kFrames[d].d, blo, bhi); }

// Sheared local coordinates of a world point: with X = (x, y, 0) and Y = (y, 0, x) as
// coefficients of 1, e, e^2 (X = x + e*y, Y = y + e^2*x), u = a*X + b*Y, v = c*X + d*Y.
[[gnu::always_inline]] inline T3 U(int d, Point p) {
  const Frame& f = kFrames[d];
  return {f.a * p.x + f.b * p.y, f.a * p.y, f.b * p.x};
}
[[gnu::always_inline]] inline T3 V(int d, Point p) {
  const Frame& f = kFrames[d];
  return {f.c * p.x + f.d * p.y, f.c * p.y, f.d * p.x};
}

// A number x + sqrt2*y with x, y in T3, compared one order of e at a time in Z[sqrt2] (exact:
// geom::Root2::sign_of). Octilinear levels and distances.
struct R3 {
  T3 u, v;
  friend bool operator==(const R3&, const R3&) = default;
  friend std::strong_ordering operator<=>(const R3& x, const R3& y) {
    int s = geom::Root2::sign_of(i128{x.u.a} - y.u.a, i128{x.v.a} - y.v.a);
    if (s == 0) s = geom::Root2::sign_of(i128{x.u.b} - y.u.b, i128{x.v.b} - y.v.b);
    if (s == 0) s = geom::Root2::sign_of(i128{x.u.c} - y.u.c, i128{x.v.c} - y.v.c);
    return s <=> 0;
  }
  R3 operator+(const R3& o) const { return {u + o.u, v + o.v}; }
  R3 operator-(const R3& o) const { return {u - o.u, v - o.v}; }
};

// What differs between the metrics: the frames, the level's type (T3 for L1: u + v, and for
// the norms: wu u + wv v; R3 for the octilinear metric: u + sqrt2 v) and its constant term's
// type (what distances and the k-d tree's bounds are), the track rays cached per vertex (the
// four axis directions, the four diagonals for octilinear, every direction of a norm) and the
// width of the per-entity wedge bits (6 per frame). kRoot2: levels in Z[sqrt2]; kPerFrame: the
// k-d search is instantiated per frame (L1, octilinear; a norm's 16 to 48 frames share one
// instantiation that reads the frame at run time).
struct L1Metric {
  static constexpr int kFirst = 0, kCount = 4, kRaySlots = 4;
  static constexpr bool kRoot2 = false, kPerFrame = true, kUnitWeights = true;
  using Lv = T3;
  using C = i64;
  using Bits = uint32_t;
  [[gnu::always_inline]] static Lv level(int d, Point p) { return U(d, p) + V(d, p); }
  [[gnu::always_inline]] static C constant(const Lv& l) { return l.a; }
  [[gnu::always_inline]] static C combine(int, i64 u, i64 v) { return u + v; }
  static constexpr ModeDir mode_dir(int j) { return kAxisModes[j]; }
};
struct OctMetric {
  static constexpr int kFirst = 4, kCount = 8, kRaySlots = 8;
  static constexpr bool kRoot2 = true, kPerFrame = true, kUnitWeights = false;
  using Lv = R3;
  using C = geom::Root2;
  using Bits = uint64_t;
  [[gnu::always_inline]] static Lv level(int d, Point p) { return {U(d, p), V(d, p)}; }
  [[gnu::always_inline]] static C constant(const Lv& l) { return {l.u.a, l.v.a}; }
  [[gnu::always_inline]] static C combine(int, i64 u, i64 v) { return {u, v}; }
  static constexpr ModeDir mode_dir(int j) { return kAxisModes[j]; }
};
// Wedge bits wider than 64 (a norm's frames).
template <int W>
struct WideBits {
  std::array<uint64_t, W> w{};
};
template <int N, int First>
struct NormMetric {
  using Norm = geom::FareyNorm<N>;
  static constexpr int kFirst = First, kCount = Norm::kDirs, kRaySlots = Norm::kDirs;
  static constexpr bool kRoot2 = false, kPerFrame = false, kUnitWeights = false;
  using Lv = T3;
  using C = i64;
  using Bits = WideBits<(6 * kCount + 63) / 64>;
  [[gnu::always_inline]] static Lv level(int d, Point p) {
    const Frame& f = kFrames[d];
    return {f.la * p.x + f.lb * p.y, f.la * p.y, f.lb * p.x};
  }
  [[gnu::always_inline]] static C constant(const Lv& l) { return l.a; }
  [[gnu::always_inline]] static C combine(int d, i64 u, i64 v) { return kFrames[d].wu * u + kFrames[d].wv * v; }
  static constexpr ModeDir mode_dir(int j) { return {norm().dir[j].x, norm().dir[j].y}; }
  static constexpr const Norm& norm() {
    if constexpr (N == 2) return geom::kFarey2;
    else if constexpr (N == 3) return geom::kFarey3;
    else return geom::kFarey4;
  }
};
using Norm2Metric = NormMetric<2, kNormFirst2>;
using Norm3Metric = NormMetric<3, kNormFirst3>;
using Norm4Metric = NormMetric<4, kNormFirst4>;
static_assert(Norm2Metric::kCount + kNormFirst2 == kNormFirst3 && Norm4Metric::kFirst + Norm4Metric::kCount == kFrameCount);

// The 6 wedge bits of frame slot k (d - kFirst).
template <class Bits>
inline void put_bits(Bits& bits, int k, uint32_t b) {
  if constexpr (std::is_integral_v<Bits>) {
    bits |= static_cast<Bits>(b) << (6 * k);
  } else {
    const int bit = 6 * k, word = bit / 64, off = bit % 64;
    bits.w[word] |= uint64_t{b} << off;
    if (off > 58) bits.w[word + 1] |= uint64_t{b} >> (64 - off);
  }
}
template <class Bits>
inline uint32_t get_bits(const Bits& bits, int k) {
  if constexpr (std::is_integral_v<Bits>) {
    return static_cast<uint32_t>(bits >> (6 * k)) & 63u;
  } else {
    const int bit = 6 * k, word = bit / 64, off = bit % 64;
    uint64_t v = bits.w[word] >> off;
    if (off > 58) v |= bits.w[word + 1] << (64 - off);
    return static_cast<uint32_t>(v) & 63u;
  }
}

// f(std::integral_constant<int, d>) for the runtime frame d of metric M: lets the k-d search be
// instantiated per frame, so each frame's matrix folds into its arithmetic. A norm metric gets
// d = -1: the search then reads the region's frame at run time.
template <class M, class F>
[[gnu::always_inline]] inline decltype(auto) with_frame(int d, F&& f) {
  using std::integral_constant;
  if constexpr (!M::kPerFrame) {
    return f(integral_constant<int, -1>{});
  } else if constexpr (M::kCount == 4) {
    switch (d) {
      case 0: return f(integral_constant<int, 0>{});
      case 1: return f(integral_constant<int, 1>{});
      case 2: return f(integral_constant<int, 2>{});
      default: return f(integral_constant<int, 3>{});
    }
  } else {
    switch (d) {
      case 4: return f(integral_constant<int, 4>{});
      case 5: return f(integral_constant<int, 5>{});
      case 6: return f(integral_constant<int, 6>{});
      case 7: return f(integral_constant<int, 7>{});
      case 8: return f(integral_constant<int, 8>{});
      case 9: return f(integral_constant<int, 9>{});
      case 10: return f(integral_constant<int, 10>{});
      default: return f(integral_constant<int, 11>{});
    }
  }
}
// The world vector (unsheared, exact integers) of the local vector (u, v): M^-1 (u, v).
inline Point local_int(int d, i64 u, i64 v) {
  const Frame& f = kFrames[d];
  return {static_cast<geom::Coord>(f.ia * u + f.ib * v), static_cast<geom::Coord>(f.ic * u + f.id * v)};
}

// A symbolic world direction: each component a polynomial in e (coefficients of 1, e, e^2).
struct Dir {
  std::array<i64, 3> x{}, y{};
};
inline Dir int_dir(i64 dx, i64 dy) { return Dir{{dx, 0, 0}, {dy, 0, 0}}; }
// The world direction of the sheared local vector (a, b) of frame d.
inline Dir local_dir(int d, int a, int b) {
  // (wx, wy) = M^-1 (a, b) in the sheared plane; unsheared: x = X - e*Y + ..., y = Y - e^2*X
  // + ..., which to the orders that decide a sign is (wx - e wy, wy - e^2 wx).
  const Point w = local_int(d, a, b);
  return Dir{{w.x, -i64{w.y}, 0}, {w.y, 0, -i64{w.x}}};
}
// Signs of cross(p, q) and dot(p, q) as polynomials in e, compared lexicographically: the
// coefficient of e^k only matters when every lower one is zero, so it is computed only then
// (most directions differ already in their constant terms).
inline int cross_sign(const Dir& p, const Dir& q) {
  if (const i128 r0 = i128{p.x[0]} * q.y[0] - i128{p.y[0]} * q.x[0]; r0 != 0) return r0 > 0 ? 1 : -1;
  for (int k = 1; k <= 4; ++k) {
    i128 r = 0;
    for (int i = std::max(0, k - 2); i <= std::min(2, k); ++i)
      r += i128{p.x[i]} * q.y[k - i] - i128{p.y[i]} * q.x[k - i];
    if (r != 0) return r > 0 ? 1 : -1;
  }
  return 0;
}
inline int dot_sign(const Dir& p, const Dir& q) {
  if (const i128 r0 = i128{p.x[0]} * q.x[0] + i128{p.y[0]} * q.y[0]; r0 != 0) return r0 > 0 ? 1 : -1;
  for (int k = 1; k <= 4; ++k) {
    i128 r = 0;
    for (int i = std::max(0, k - 2); i <= std::min(2, k); ++i)
      r += i128{p.x[i]} * q.x[k - i] + i128{p.y[i]} * q.y[k - i];
    if (r != 0) return r > 0 ? 1 : -1;
  }
  return 0;
}
// x strictly before y going counter-clockwise from base (base itself is first).
inline bool ccw_less(const Dir& base, const Dir& x, const Dir& y) {
  auto half = [&](const Dir& v) {
    const int c = cross_sign(base, v);
    return (c > 0 || (c == 0 && dot_sign(base, v) > 0)) ? 0 : 1;
  };
  const int hx = half(x), hy = half(y);
  if (hx != hy) return hx < hy;
  return cross_sign(x, y) > 0;
}
inline bool same_dir(const Dir& x, const Dir& y) {
  return cross_sign(x, y) == 0 && dot_sign(x, y) > 0;
}
// x strictly inside the counter-clockwise arc from a to b.
inline bool in_ccw(const Dir& a, const Dir& b, const Dir& x) {
  // = !same_dir(x, a) && ccw_less(a, x, b), with cross(a, x) computed once: once x is not a's
  // direction, x is in a's half (half 0) exactly when cross(a, x) > 0.
  const int cax = cross_sign(a, x);
  if (cax == 0 && dot_sign(a, x) > 0) return false;
  const int hx = cax > 0 ? 0 : 1;
  const int cab = cross_sign(a, b);
  const int hb = (cab > 0 || (cab == 0 && dot_sign(a, b) > 0)) ? 0 : 1;
  if (hx != hb) return hx < hb;
  return cross_sign(x, b) > 0;
}

// ---------------------------------------------------------------------------------------------
// Static k-d tree over points: the segment-dragging query "smallest diagonal coordinate inside a
// convex region". Nodes in depth-first order, leaves of up to 16 points.
template <class M>
struct RegionT {
  int d = 0;
  typename M::Lv start;     // level must be > start
  int nlex = 0;             // lexicographic half-planes on U or V
  struct Lex {
    bool on_u;              // U(q) vs value, else V(q)
    bool greater;           // require > value, else <
    T3 value;
  } lex[2];
  int nedges = 0;           // orient(a, b, q) <= 0
  Point ea[4], eb[4];
  Box hull;                 // world box holding every point of the region (region_hull())
};

// The world bounding box of a wavelet's region, rounded out to integers; false when the region
// is empty. The region is relaxed to a closed convex polygon (U > c becomes u >= c.a, the level
// bound u + v >= start.a for L1, a rational line below the octilinear level bound (see the code);
// stop edges exactly) and clipped from the box `frame` by
// Sutherland-Hodgman. Every vertex is kept as the pair of input lines it lies on and computed
// exactly from them: lines are a*x + b*y <= c with |a|, |b| < 2^31 and |c| < 2^62, so a vertex
// is (xn / den, yn / den) with |den| < 2^63 and |xn|, |yn| < 2^94, and the side test
// a*xn + b*yn - c*den stays below 2^127 in __int128.
// Used only to bound k-d tree searches (KdTree::query_near()), never to decide a hit.
template <class M>
inline bool region_hull(const RegionT<M>& r, const Box& frame, Box& out) {
  struct Line {
    i64 a, b, c;
  };
  // World box bounds from the frame, the lexicographic half-planes and axis-parallel stop edges
  // (the common case: those need no clipping).
  i64 xlo = frame.lo.x, xhi = frame.hi.x, ylo = frame.lo.y, yhi = frame.hi.y;
  std::array<Line, 8> slanted;
  int ns = 0;
  // a*x + b*y <= c: a bound on x or y when the line is axis-parallel, else a line to clip by
  auto add = [&](i64 a, i64 b, i64 c) {
    if (b == 0 && (a == 1 || a == -1)) {
      if (a > 0) xhi = std::min(xhi, c);
      else xlo = std::max(xlo, -c);
    } else if (a == 0 && (b == 1 || b == -1)) {
      if (b > 0) yhi = std::min(yhi, c);
      else ylo = std::max(ylo, -c);
    } else {
      slanted[ns++] = {a, b, c};
    }
  };
  const Frame& fr = kFrames[r.d];
  for (int i = 0; i < r.nlex; ++i) {  // U > c gives u.a >= c.a, U < c gives u.a <= c.a
    const auto& l = r.lex[i];
    const i64 a = l.on_u ? fr.a : fr.c, b = l.on_u ? fr.b : fr.d;
    if (l.greater)
      add(-a, -b, -l.value.a);
    else
      add(a, b, l.value.a);
  }
  for (int i = 0; i < r.nedges; ++i) {  // (B-A) x (q-A) <= 0
    const i64 dx = i64{r.eb[i].x} - r.ea[i].x, dy = i64{r.eb[i].y} - r.ea[i].y;
    if (dy == 0) {  // dx * (y - A.y) <= 0
      if (dx > 0) yhi = std::min(yhi, i64{r.ea[i].y});
      else ylo = std::max(ylo, i64{r.ea[i].y});
    } else if (dx == 0) {  // -dy * (x - A.x) <= 0
      if (dy > 0) xlo = std::max(xlo, i64{r.ea[i].x});
      else xhi = std::min(xhi, i64{r.ea[i].x});
    } else {
      slanted[ns++] = {-dy, dx, dx * r.ea[i].y - dy * r.ea[i].x};
    }
  }
  if constexpr (M::kRoot2) {
    // Octilinear: the level line u + sqrt2 v >= S is irrational; it is replaced by a rational
    // line every point of the region satisfies. With v0 the least v over the current box (so
    // v >= v0 there) and 99/70 > sqrt2: u + (99/70)(v - v0) >= u + sqrt2 (v - v0) >= S - sqrt2 v0,
    // i.e. 70 u + 99 v >= 70 S + (99 - 70 sqrt2) v0, relaxed to the floor of the right side
    // (exact in Z[sqrt2]). It is off the true line by (99/70 - sqrt2)(v - v0) < 10^-4 (v - v0).
    if (xlo > xhi || ylo > yhi) return false;
    const Point blo{static_cast<geom::Coord>(xlo), static_cast<geom::Coord>(ylo)};
    const Point bhi{static_cast<geom::Coord>(xhi), static_cast<geom::Coord>(yhi)};
    const i64 v0 = v_range(r.d, blo, bhi).lo;
    const geom::Root2 st = M::constant(r.start);
    if (M::combine(r.d, u_range(r.d, blo, bhi).hi, v_range(r.d, blo, bhi).hi) < st) return false;
    const i128 ra = i128{70} * st.a + i128{99} * v0, rb = i128{70} * st.b - i128{70} * v0;
    // floor(ra + rb sqrt2): estimate, then correct with exact signs
    i128 f = static_cast<i128>(std::floor(static_cast<long double>(ra) +
                                          static_cast<long double>(rb) * 1.41421356237309504880L));
    while (geom::Root2::sign_of(ra - f, rb) < 0) --f;
    while (geom::Root2::sign_of(ra - (f + 1), rb) >= 0) ++f;
    // -(70 u + 99 v) <= -f with u = fr.a x + fr.b y, v = fr.c x + fr.d y
    slanted[ns++] = {-(70 * fr.a + 99 * fr.c), -(70 * fr.b + 99 * fr.d), static_cast<i64>(-f)};
  }
  // the level: sx*x + sy*y >= start, with the level's coefficients (L1: sx, sy = +-1; a
  // norm: the cone's functional)
  const i64 sx = fr.la, sy = fr.lb;
  auto level_ok_box = [&] {
    if constexpr (M::kRoot2) {
      return true;
    } else {
      const i64 best = (sx > 0 ? sx * xhi : sx * xlo) + (sy > 0 ? sy * yhi : sy * ylo);
      return best >= M::constant(r.start);
    }
  };
  if (xlo > xhi || ylo > yhi || !level_ok_box()) return false;
  if (ns == 0) {
    if constexpr (M::kUnitWeights) {
      // tighten by the level: local u >= start - vmax, v >= start - umax
      const i64 st = M::constant(r.start);
      const i64 umax = sx > 0 ? xhi : -xlo, vmax = sy > 0 ? yhi : -ylo;
      if (sx > 0) xlo = std::max(xlo, st - vmax); else xhi = std::min(xhi, vmax - st);
      if (sy > 0) ylo = std::max(ylo, st - umax); else yhi = std::min(yhi, umax - st);
    }
    out = Box{{static_cast<geom::Coord>(xlo), static_cast<geom::Coord>(ylo)},
              {static_cast<geom::Coord>(xhi), static_cast<geom::Coord>(yhi)}};
    return true;
  }
  std::array<Line, 13> lines;  // (the level line: integer levels only)
  int nl = 0;
  lines[nl++] = {0, -1, -ylo};  // y >= ylo
  lines[nl++] = {1, 0, xhi};    // x <= xhi
  lines[nl++] = {0, 1, yhi};    // y <= yhi
  lines[nl++] = {-1, 0, -xlo};  // x >= xlo
  if constexpr (!M::kRoot2) lines[nl++] = {-sx, -sy, -M::constant(r.start)};
  for (int i = 0; i < ns; ++i) lines[nl++] = slanted[i];
  struct V {
    uint8_t in, out;  // lines before and after the vertex (counter-clockwise)
    i128 xn, yn, den;
  };
  auto make = [&](uint8_t i, uint8_t j) {
    const Line& p = lines[i];
    const Line& q = lines[j];
    V v{i, j, i128{p.c} * q.b - i128{q.c} * p.b, i128{p.a} * q.c - i128{q.a} * p.c,
        i128{p.a} * q.b - i128{q.a} * p.b};
    if (v.den < 0) {
      v.xn = -v.xn;
      v.yn = -v.yn;
      v.den = -v.den;
    }
    return v;
  };
  std::array<V, 16> poly, next;  // a convex polygon cut from 4 + 1 + 4 lines: <= 9 vertices
  int np = 4;
  for (int i = 0; i < 4; ++i) poly[i] = make(static_cast<uint8_t>(i), static_cast<uint8_t>((i + 1) % 4));
  for (int h = 4; h < nl && np > 0; ++h) {
    const Line& L = lines[h];
    auto inside = [&](const V& v) { return L.a * v.xn + L.b * v.yn - i128{L.c} * v.den <= 0; };
    int nn = 0;
    for (int i = 0; i < np; ++i) {
      const V& P = poly[(i + np - 1) % np];
      const V& Q = poly[i];  // edge P -> Q lies on line Q.in
      const bool pin = inside(P), qin = inside(Q);
      if (pin && qin) {
        next[nn++] = Q;
      } else if (pin) {
        next[nn++] = make(Q.in, static_cast<uint8_t>(h));
      } else if (qin) {
        next[nn++] = make(static_cast<uint8_t>(h), Q.in);
        next[nn++] = Q;
      }
    }
    poly = next;
    np = nn;
  }
  if (np == 0) return false;
  i128 bxlo = xhi, bxhi = xlo, bylo = yhi, byhi = ylo;
  for (int i = 0; i < np; ++i) {
    bxlo = std::min(bxlo, floor_div(poly[i].xn, poly[i].den));
    bxhi = std::max(bxhi, ceil_div(poly[i].xn, poly[i].den));
    bylo = std::min(bylo, floor_div(poly[i].yn, poly[i].den));
    byhi = std::max(byhi, ceil_div(poly[i].yn, poly[i].den));
  }
  out = Box{{static_cast<geom::Coord>(bxlo), static_cast<geom::Coord>(bylo)},
            {static_cast<geom::Coord>(bxhi), static_cast<geom::Coord>(byhi)}};
  return true;
}

// D == r.d: the frame as a template argument, so its matrix folds into the arithmetic (the k-d
// search below is instantiated per frame).
template <class M, int D>
inline bool satisfies(const RegionT<M>& r, Point q) {
  const int d = D >= 0 ? D : r.d;
  if (!(M::level(d, q) > r.start)) return false;
  for (int i = 0; i < r.nlex; ++i) {
    const auto& l = r.lex[i];
    const T3 v = l.on_u ? U(d, q) : V(d, q);
    if (l.greater ? !(v > l.value) : !(v < l.value)) return false;
  }
  for (int i = 0; i < r.nedges; ++i)
    if (geom::orient(r.ea[i], r.eb[i], q) > 0) return false;
  return true;
}

template <class M>
class KdTree {
  using Lv = typename M::Lv;
  using C = typename M::C;
  using Region = RegionT<M>;

 public:
  KdTree() = default;
  // `id_bound` > every item id: the tree then records each item's leaf (query_near()).
  explicit KdTree(std::vector<std::pair<Point, uint32_t>> items, uint32_t id_bound = 0)
      : items_(std::move(items)) {
    if (!items_.empty()) build(0, static_cast<uint32_t>(items_.size()), kNone);
    if (id_bound > 0) {
      leaf_of_.assign(id_bound, kNone);
      for (uint32_t n = 0; n < nodes_.size(); ++n)
        if (nodes_[n].left == kNone)
          for (uint32_t i = nodes_[n].begin; i < nodes_[n].end; ++i) leaf_of_[items_[i].second] = n;
    }
  }
  bool empty() const { return items_.empty(); }
  std::size_t memory_bytes() const {
    return items_.capacity() * sizeof(items_[0]) + nodes_.capacity() * sizeof(Node) +
           leaf_of_.capacity() * sizeof(uint32_t);
  }
  // The leaf holding item `id` (kNone: not an item, or the tree was built without id_bound).
  uint32_t leaf_of(uint32_t id) const { return id < leaf_of_.size() ? leaf_of_[id] : kNone; }

  // Same answer as query(), searched bottom-up from `leaf` (the leaf of the region's apex, where
  // the answer usually is): the leaf, then the sibling subtree of each ancestor in turn, until
  // no point of the region outside the current subtree's box can beat the best found
  // (outside_bound()). A wavelet's region mostly ends a few neighbours away from its apex, so
  // this visits the few nodes around the answer instead of a path from the root and the
  // bounding tests on both sides of it (measured in bench_wavefront: stats().drag_nodes).
  bool query_near(uint32_t leaf, const Region& r, uint32_t& best_id, Lv& best_level,
                  std::int64_t& nodes) const {
    return with_frame<M>(r.d, [&](auto dc) {
      return query_near_t<decltype(dc)::value>(leaf, r, best_id, best_level, nodes);
    });
  }

  // The id of the satisfying point with the smallest level (false = none); `nodes` counts the
  // nodes visited.
  bool query(const Region& r, uint32_t& best_id, Lv& best_level, std::int64_t& nodes) const {
    if (items_.empty()) return false;
    bool found = false;
    with_frame<M>(r.d, [&](auto dc) {
      visit<decltype(dc)::value>(0, r, found, best_id, best_level, nodes);
    });
    return found;
  }

 private:
  template <int D>
  bool query_near_t(uint32_t leaf, const Region& r, uint32_t& best_id, Lv& best_level,
                    std::int64_t& nodes) const {
    bool found = false;
    visit<D>(leaf, r, found, best_id, best_level, nodes);
    for (uint32_t cur = leaf; cur != 0;) {
      C outside;
      if (!outside_bound<D>(nodes_[cur], r, outside) ||
          (found && outside > M::constant(best_level)))
        break;
      const uint32_t par = nodes_[cur].parent;
      const uint32_t sib = nodes_[par].left == cur ? nodes_[par].right : nodes_[par].left;
      visit<D>(sib, r, found, best_id, best_level, nodes);
      cur = par;
    }
    return found;
  }

  struct Node {
    Point lo, hi;
    uint32_t begin, end;
    uint32_t left = kNone, right = kNone;
    uint32_t parent = kNone;
  };
  // A lower bound (`bound`) of the level's constant term over the points of region r that lie
  // outside node n's box; false when there can be none. Such a point lies in the region's hull
  // box (region_hull()) and strictly beyond the node's box on some side (the splits leave no
  // coordinate value on both sides), i.e. in one of four boxes; over each the level is at least
  // start and at least its minimum over that box (L1: exact; octilinear: min u + sqrt2 min v).
  // Stop edges only shrink the region, so the bound is conservative.
  template <int D>
  static bool outside_bound(const Node& n, const Region& r, C& bound) {
    const Frame& f = kFrames[D >= 0 ? D : r.d];
    const Box& h = r.hull;
    bool any = false;
    const C st = M::constant(r.start);
    auto side = [&](i64 xlo, i64 ylo, i64 xhi, i64 yhi) {
      if (xlo > xhi || ylo > yhi) return;
      C b;
      if constexpr (!M::kRoot2) {
        const i64 la = f.la, lb = f.lb;  // level = la*x + lb*y (constant term)
        const i64 x0 = la * xlo, x1 = la * xhi, y0 = lb * ylo, y1 = lb * yhi;
        b = std::min(x0, x1) + std::min(y0, y1);
      } else {
        b = oct_box_min<D>(xlo, ylo, xhi, yhi);
      }
      b = std::max(b, st);
      bound = any ? std::min(bound, b) : b;
      any = true;
    };
    side(h.lo.x, h.lo.y, i64{n.lo.x} - 1, h.hi.y);  // left of the box
    side(i64{n.hi.x} + 1, h.lo.y, h.hi.x, h.hi.y);  // right
    side(h.lo.x, h.lo.y, h.hi.x, i64{n.lo.y} - 1);  // below
    side(h.lo.x, i64{n.hi.y} + 1, h.hi.x, h.hi.y);  // above
    return any;
  }
  uint32_t build(uint32_t begin, uint32_t end, uint32_t parent) {
    const uint32_t id = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_[id].parent = parent;
    Point lo{std::numeric_limits<geom::Coord>::max(), std::numeric_limits<geom::Coord>::max()};
    Point hi{std::numeric_limits<geom::Coord>::min(), std::numeric_limits<geom::Coord>::min()};
    for (uint32_t i = begin; i < end; ++i) {
      lo.x = std::min(lo.x, items_[i].first.x);
      lo.y = std::min(lo.y, items_[i].first.y);
      hi.x = std::max(hi.x, items_[i].first.x);
      hi.y = std::max(hi.y, items_[i].first.y);
    }
    nodes_[id].lo = lo;
    nodes_[id].hi = hi;
    nodes_[id].begin = begin;
    nodes_[id].end = end;
    if (end - begin > 16) {
      // Split at the median of the wider side, with no coordinate value on both sides (points
      // equal to the median go to the side that keeps both non-empty): the left subtree's
      // points are then strictly below the split value and the right's at or above it, so a
      // point outside a subtree lies strictly outside the subtree's box on some side, which
      // query_near()'s stopping bound relies on. The points are distinct, so when every point
      // shares the wider side's value the other side splits.
      bool by_x = (i64{hi.x} - lo.x) >= (i64{hi.y} - lo.y);
      if ((by_x ? hi.x == lo.x : hi.y == lo.y)) by_x = !by_x;
      auto key = [by_x](const std::pair<Point, uint32_t>& a) { return by_x ? a.first.x : a.first.y; };
      uint32_t mid = begin + (end - begin) / 2;
      std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                       [&](const auto& a, const auto& b) { return key(a) < key(b); });
      const geom::Coord m = key(items_[mid]);
      // [begin, mid) <= m <= [mid, end): move the values equal to m out of the left part ...
      mid = static_cast<uint32_t>(
          std::partition(items_.begin() + begin, items_.begin() + mid, [&](const auto& a) { return key(a) < m; }) -
          items_.begin());
      if (mid == begin)  // ... or, when nothing is below m, the values equal to m into it
        mid = static_cast<uint32_t>(
            std::partition(items_.begin() + begin, items_.begin() + end, [&](const auto& a) { return key(a) == m; }) -
            items_.begin());
      const uint32_t l = build(begin, mid, id);
      const uint32_t rr = build(mid, end, id);
      nodes_[id].left = l;
      nodes_[id].right = rr;
    }
    return id;
  }
  // Lower bound of the level's constant term over the part of the box the region's lower
  // bounds on U, V and the level leave (a box left of a vertical track counts from the track).
  // Octilinear: the exact least constant term of the level (a + sqrt2 c) x + (b + sqrt2 d) y
  // over a box, at the corner its coefficients' signs pick (fixed per frame).
  template <int D>
  static geom::Root2 oct_box_min(i64 xlo, i64 ylo, i64 xhi, i64 yhi) {
    constexpr Frame f = kFrames[D];
    constexpr bool x_lo = geom::Root2::sign_of(f.a, f.c) > 0, y_lo = geom::Root2::sign_of(f.b, f.d) > 0;
    const i64 x = x_lo ? xlo : xhi, y = y_lo ? ylo : yhi;
    return {f.a * x + f.b * y, f.c * x + f.d * y};
  }
  template <int D>
  static C box_min_level(const Node& n, const Region& r) {
    const int d = D >= 0 ? D : r.d;
    i64 umin = u_range(d, n.lo, n.hi).lo;
    i64 vmin = v_range(d, n.lo, n.hi).lo;
    for (int i = 0; i < r.nlex; ++i) {
      const auto& l = r.lex[i];
      if (!l.greater) continue;
      i64& m = l.on_u ? umin : vmin;
      m = std::max(m, l.value.a);
    }
    if constexpr (M::kRoot2) {
      return std::max({M::combine(d, umin, vmin), M::constant(r.start),
                       oct_box_min<D>(n.lo.x, n.lo.y, n.hi.x, n.hi.y)});
    } else if constexpr (!M::kUnitWeights) {
      // a norm: also the exact least level la*x + lb*y over the box (at the corner its signs
      // pick); wu*umin + wv*vmin alone takes u and v at different corners
      const Frame& f = kFrames[d];
      const i64 exact = f.la * (f.la > 0 ? n.lo.x : n.hi.x) + f.lb * (f.lb > 0 ? n.lo.y : n.hi.y);
      return std::max({M::combine(d, umin, vmin), M::constant(r.start), exact});
    } else {
      return std::max(M::combine(d, umin, vmin), M::constant(r.start));
    }
  }
  template <int D>
  static bool box_may_satisfy(const Node& n, const Region& r) {
    if (n.hi.x < r.hull.lo.x || n.lo.x > r.hull.hi.x || n.hi.y < r.hull.lo.y || n.lo.y > r.hull.hi.y)
      return false;
    const int d = D >= 0 ? D : r.d;
    const Range ur = u_range(d, n.lo, n.hi), vr = v_range(d, n.lo, n.hi);
    const i64 umax = ur.hi, umin = ur.lo, vmax = vr.hi, vmin = vr.lo;
    if (M::combine(d, umax, vmax) < M::constant(r.start)) return false;
    for (int i = 0; i < r.nlex; ++i) {
      const auto& l = r.lex[i];
      const i64 mx = l.on_u ? umax : vmax;
      const i64 mn = l.on_u ? umin : vmin;
      if (l.greater ? mx < l.value.a : mn > l.value.a) return false;
    }
    // orient(a, b, q) is linear in q, (b - a) x (q - a): its minimum over the box is at the
    // corner picked by the signs of its gradient (a.y - b.y, b.x - a.x) (exact, one test).
    for (int i = 0; i < r.nedges; ++i) {
      const Point a = r.ea[i], b = r.eb[i];
      const Point c{a.y > b.y ? n.lo.x : n.hi.x, b.x > a.x ? n.lo.y : n.hi.y};
      if (geom::orient(a, b, c) > 0) return false;
    }
    return true;
  }
  template <int D>
  void visit(uint32_t id, const Region& r, bool& found, uint32_t& best_id, Lv& best,
             std::int64_t& nodes) const {
    ++nodes;
    const Node& n = nodes_[id];
    if (found && box_min_level<D>(n, r) > M::constant(best)) return;
    if (!box_may_satisfy<D>(n, r)) return;
    if (n.left == kNone) {
      for (uint32_t i = n.begin; i < n.end; ++i) {
        const Point q = items_[i].first;
        const Lv lv = M::level(D >= 0 ? D : r.d, q);
        if (found && !(lv < best)) continue;
        if (!satisfies<M, D>(r, q)) continue;
        found = true;
        best = lv;
        best_id = items_[i].second;
      }
      return;
    }
    const C bl = box_min_level<D>(nodes_[n.left], r);
    const C br = box_min_level<D>(nodes_[n.right], r);
    if (bl <= br) {
      visit<D>(n.left, r, found, best_id, best, nodes);
      visit<D>(n.right, r, found, best_id, best, nodes);
    } else {
      visit<D>(n.right, r, found, best_id, best, nodes);
      visit<D>(n.left, r, found, best_id, best, nodes);
    }
  }

  std::vector<std::pair<Point, uint32_t>> items_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> leaf_of_;  // item id -> its leaf (when built with id_bound)
};

// ---------------------------------------------------------------------------------------------

// A track of a wavelet. V: the sheared vertical line through `origin` (local north), H: the
// sheared horizontal (local east); both carry the stop edge their ray runs into (ea -> eb, a
// ring edge with free space on its right), if any. O: the track is the ring edge ea -> eb.
// `far` is the edge end with the larger level: where the sliding end leaves the edge.
struct Bound {
  uint8_t kind = 0;  // 0 V, 1 H, 2 O
  uint32_t origin = kNone;
  uint32_t ea = kNone, eb = kNone, far = kNone;
};
enum : uint8_t { kV = 0, kH = 1, kO = 2 };

template <class M>
struct WaveT {
  typename M::Lv key;
  uint64_t seq = 0;
  uint32_t root = kNone;   // entity
  uint32_t start = kNone;  // point: the region lies beyond its level
  uint32_t event = kNone;  // point hit next
  uint8_t dir = 0;
  uint8_t event_is_target = 0;
  Bound left, right;       // left: upper-left track (region on its right); right: lower-right
};
template <class M>
struct WaveLater {
  bool operator()(const WaveT<M>& a, const WaveT<M>& b) const {
    if (a.key != b.key) return a.key > b.key;
    return a.seq > b.seq;
  }
};

template <class M>
struct EntityT {
  uint32_t point = kNone;
  uint32_t lo = kNone, hi = kNone;  // world ring neighbours: free wedge ccw from dir(lo) to dir(hi)
  bool full = false;                // every direction free (lo/hi unused)
  bool labelled = false;
  typename M::Lv d;
  uint32_t parent = kNone;  // entity
  uint32_t source = kNone;  // index into run's sources
};

template <class M>
struct WaveCore {
  using Lv = typename M::Lv;
  using Wave = WaveT<M>;
  using Entity = EntityT<M>;
  using Region = RegionT<M>;
  [[gnu::always_inline]] static Lv level(int d, Point p) { return M::level(d, p); }

  Box domain;
  std::vector<Polygon> polys;  // obstacles after merging the domain frame
  std::vector<Box> poly_boxes;
  std::unique_ptr<geom::ObstacleIndex> index;
  std::vector<std::pair<uint32_t, uint32_t>> edge_pts;  // index edge id -> (a, b) point ids

  std::vector<Point> pts;  // vertex points [0, nvert), then run-time points
  uint32_t nvert = 0;
  std::vector<std::pair<uint64_t, uint32_t>> point_ids;  // (key_of, id) of vertex points, sorted
  uint32_t point_id(Point p) const {  // kNone when p is not a vertex point
    const uint64_t k = key_of(p);
    auto it = std::lower_bound(point_ids.begin(), point_ids.end(), std::pair<uint64_t, uint32_t>{k, 0});
    return it != point_ids.end() && it->first == k ? it->second : kNone;
  }
  std::vector<uint32_t> ent_begin;                  // per vertex point: entities [begin, begin+1..)
  std::vector<Entity> ents;                         // vertex entities [0, nvent), run-time after
  // per entity: compute_wedge_bits(), made when first read (a net's window labels about a fifth
  // of its entities)
  mutable std::vector<typename M::Bits> ent_bits;
  mutable std::vector<char> bits_made;
  uint32_t nvent = 0;
  KdTree<M> vertex_tree;
  // Track-ray answers per vertex point and world direction (M::kRaySlots per point: two per
  // mode of sweep_rays(), the mode's direction and its opposite): the edge id hit, or kNone;
  // kUnknown until shot. A vertex's rays are shot one by one (shoot_uncached(): vertical and
  // horizontal rays walk ray_grid's cells, diagonal and norm rays query the R-tree),
  // as a query point's are, until a mode has shot nvert of them (half its slots); then
  // sweep_rays() answers the rest of that mode at once. A run that labels few of the vertices,
  // as a net's window does (about a fifth), seldom pays for the sweep. (Measured on 3,000
  // planted nets: paths 4.4-5.0 s when the sweep came after nvert / 8 rays, 4.0-4.3 s after
  // nvert; a whole layout's field was the same within the noise.)
  std::vector<uint32_t> ray_cache;
  std::array<uint32_t, M::kRaySlots / 2> lazy_rays{};  // per mode: rays shot one by one
  std::vector<uint32_t> box_edges;  // scratch for edges_in_box
  i64 ray_window = 64;              // first window length of a track ray (set in the constructor)

  // run state
  std::vector<uint32_t> touched;  // vertex entities this run labelled or gave a source (reset)
  KdTree<M> target_tree;
  std::vector<std::vector<uint32_t>> target_ents;  // per target: its entities
  std::vector<Point> target_pts;
  std::vector<uint32_t> point_target_entity;  // run-time point -> entity
  std::priority_queue<Wave, std::vector<Wave>, WaveLater<M>> queue;
  uint64_t seq = 0;
  WavefrontStats stats;

  bool in_domain(Point q) const {
    return q.x >= domain.lo.x && q.x <= domain.hi.x && q.y >= domain.lo.y && q.y <= domain.hi.y;
  }
  // Z-order (Morton) key: the bits of x and y (offset to unsigned) interleaved.
  static uint64_t morton(Point p) {
    auto spread = [](uint64_t v) {
      v &= 0xFFFFFFFFull;
      v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
      v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
      v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
      v = (v | (v << 2)) & 0x3333333333333333ull;
      v = (v | (v << 1)) & 0x5555555555555555ull;
      return v;
    };
    const uint64_t x = static_cast<uint32_t>(p.x) ^ 0x80000000u, y = static_cast<uint32_t>(p.y) ^ 0x80000000u;
    return spread(x) | (spread(y) << 1);
  }
  static uint64_t key_of(Point p) {
    return (uint64_t{static_cast<uint32_t>(p.x)} << 32) | static_cast<uint32_t>(p.y);
  }

  WaveCore(const Box& dom, std::span<const Polygon> obstacles) : domain(dom) {
    merge_frame(obstacles);
    index = std::make_unique<geom::ObstacleIndex>(polys);
    {
      const double extent = std::max<double>(i64{domain.hi.x} - domain.lo.x, i64{domain.hi.y} - domain.lo.y);
      const double gap = extent / std::sqrt(static_cast<double>(std::max<std::size_t>(1, index->edge_count())));
      ray_window = std::max<i64>(16, static_cast<i64>(2 * gap));  // a speed heuristic only
    }
    for (const Polygon& p : polys) {
      Box b{{std::numeric_limits<geom::Coord>::max(), std::numeric_limits<geom::Coord>::max()},
            {std::numeric_limits<geom::Coord>::min(), std::numeric_limits<geom::Coord>::min()}};
      for (Point q : p.outer) {
        b.lo.x = std::min(b.lo.x, q.x);
        b.lo.y = std::min(b.lo.y, q.y);
        b.hi.x = std::max(b.hi.x, q.x);
        b.hi.y = std::max(b.hi.y, q.y);
      }
      poly_boxes.push_back(b);
    }
    // Vertex points, numbered along a Z-order curve so that points near each other in the
    // plane are near each other in memory (the wavefront sweeps the plane as a front: this
    // keeps its entity, point and ray-cache accesses local), and their occurrences
    // (prev, next) on rings.
    std::vector<uint32_t> occ_begin;                       // per point: [begin, next begin)
    std::vector<std::pair<uint32_t, uint32_t>> occ_list;  // (prev, next) ids, flat
    // the id of every ring vertex, in the order of the rings (outer, then holes, polygon after
    // polygon), numbered by the sort that numbers the points (no search per vertex)
    std::vector<uint32_t> ring_ids;
    {
      struct At {
        uint64_t key;
        Point q;
        uint32_t at;  // index in ring_ids
      };
      std::vector<At> order;
      auto add_points = [&](const geom::Ring& ring) {
        for (Point q : ring) order.push_back({morton(q), q, static_cast<uint32_t>(order.size())});
      };
      for (const Polygon& p : polys) {
        add_points(p.outer);
        for (const geom::Ring& h : p.holes) add_points(h);
      }
      std::sort(order.begin(), order.end(), [](const At& a, const At& b) {
        return a.key != b.key ? a.key < b.key : a.q < b.q;
      });
      ring_ids.resize(order.size());
      for (std::size_t k = 0; k < order.size(); ++k) {
        if (k == 0 || order[k].q != order[k - 1].q) {
          point_ids.push_back({key_of(order[k].q), static_cast<uint32_t>(pts.size())});
          pts.push_back(order[k].q);
        }
        ring_ids[order[k].at] = static_cast<uint32_t>(pts.size() - 1);
      }
    }
    std::sort(point_ids.begin(), point_ids.end());
    occ_begin.assign(pts.size() + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {  // count, then fill
      std::size_t base = 0;                  // the ring's first vertex in ring_ids
      auto add_ring = [&](const geom::Ring& ring) {
        const std::size_t n = ring.size();
        const uint32_t* ids = ring_ids.data() + base;
        base += n;
        for (std::size_t i = 0; i < n; ++i) {
          if (pass == 0)
            ++occ_begin[ids[i] + 1];
          else
            occ_list[occ_begin[ids[i]]++] = {ids[(i + n - 1) % n], ids[(i + 1) % n]};
        }
      };
      for (const Polygon& p : polys) {
        add_ring(p.outer);
        for (const auto& h : p.holes) add_ring(h);
      }
      if (pass == 0) {
        for (std::size_t v = 0; v < pts.size(); ++v) occ_begin[v + 1] += occ_begin[v];
        occ_list.resize(occ_begin.back());
      } else {  // the fill advanced every begin to the next one's: shift back
        for (std::size_t v = pts.size(); v > 0; --v) occ_begin[v] = occ_begin[v - 1];
        occ_begin[0] = 0;
      }
    }
    nvert = static_cast<uint32_t>(pts.size());
    // Free wedges: sort occurrences by the direction of `next`; the free wedge after
    // occurrence i runs from dir(prev_i) to dir(next_{i+1}).
    ent_begin.assign(nvert + 1, 0);
    for (uint32_t v = 0; v < nvert; ++v) {
      ent_begin[v] = static_cast<uint32_t>(ents.size());
      const std::span<const std::pair<uint32_t, uint32_t>> o(occ_list.data() + occ_begin[v],
                                                           occ_begin[v + 1] - occ_begin[v]);
      const Point p = pts[v];
      auto dirto = [&](uint32_t q) { return int_dir(i64{pts[q].x} - p.x, i64{pts[q].y} - p.y); };
      if (o.size() == 1) {
        Entity e;
        e.point = v;
        e.lo = o[0].first;
        e.hi = o[0].second;
        ents.push_back(e);
        continue;
      }
      // A pinch: the ring's own pairing of in/out edges need not match the obstacle wedges
      // (a weakly simple ring may enter from one lobe and leave into another). Sort every edge
      // direction around p: the free wedges run from a "prev" direction (obstacle just
      // clockwise of it) counter-clockwise to the following "next" direction.
      std::vector<std::pair<uint32_t, bool>> dirs;  // (neighbour, is_next)
      for (const auto& [pr, nx] : o) {
        dirs.push_back({pr, false});
        dirs.push_back({nx, true});
      }
      const Dir base = dirto(dirs[0].first);
      std::sort(dirs.begin(), dirs.end(), [&](const auto& a, const auto& b) {
        return ccw_less(base, dirto(a.first), dirto(b.first));
      });
      for (std::size_t i = 0; i < dirs.size(); ++i) {
        if (dirs[i].second) continue;
        const auto& nx = dirs[(i + 1) % dirs.size()];
        Entity e;
        e.point = v;
        e.lo = dirs[i].first;
        e.hi = nx.first;
        ents.push_back(e);
      }
    }
    ent_begin[nvert] = static_cast<uint32_t>(ents.size());
    nvent = static_cast<uint32_t>(ents.size());
    ent_bits.resize(nvent);
    bits_made.assign(nvent, 0);
    stats.vertices = nvert;
    stats.entities = nvent;
    // Edge id -> point ids: the index numbers the ring edges in the rings' order, leaving out
    // an edge of two equal points (geom/index.h).
    edge_pts.reserve(index->edge_count());
    {
      std::size_t base = 0;
      auto add_ring = [&](const geom::Ring& ring) {
        const std::size_t n = ring.size();
        for (std::size_t i = 0; i < n; ++i) {
          const uint32_t a = ring_ids[base + i], b = ring_ids[base + (i + 1) % n];
          if (a != b) edge_pts.push_back({a, b});
        }
        base += n;
      };
      for (const Polygon& p : polys) {
        add_ring(p.outer);
        for (const auto& h : p.holes) add_ring(h);
      }
    }
    if (edge_pts.size() != index->edge_count()) throw std::logic_error("WaveCore: the index's edges are not the rings'");
    std::vector<std::pair<Point, uint32_t>> items;
    items.reserve(nvert);
    for (uint32_t v = 0; v < nvert; ++v) {
      const Point q = pts[v];
      if (!in_domain(q)) continue;  // the frame's outer ring lies outside the domain: never reached
      items.push_back({q, v});
    }
    vertex_tree = KdTree<M>(std::move(items), nvert);
    ray_cache.assign(std::size_t{M::kRaySlots} * nvert, kUnknown);
  }

  // Track rays of every vertex point at once, by one plane sweep per orientation (two for L1,
  // four for octilinear, 8 to 24 for the norms; O(n log n) each, against
  // one R-tree probe sequence per ray): for the sheared vertical (horizontal) line through each
  // vertex point q, the first ring edge above and below (east and west of) q. The sweep runs
  // in the sheared order of X = x + e*y, which is lexicographic (x, y); for horizontal rays the
  // same code runs on the mirrored points (y, x) (lexicographic (y, x) is the order of
  // Y = y + e^2*x). In the sheared plane no edge is vertical and no two points share X, so the
  // edges crossing the sweep line at q are exactly those with left end < q < right end, and
  // rings only touch at vertices, so two of them never cross and their order along the line is
  // the order of an orientation test at the later left end. Edges ending at q are removed
  // before the lookup and edges starting at q inserted after it, so edges through q (its own)
  // are never the answer, as in shoot_uncached().
  // Diagonal rays (octilinear) use the same sweep on points mapped by a unimodular T that makes
  // the diagonal vertical: (x - y, y) for NE/SW, (x + y, y) for NW/SE. A diagonal track is a line
  // U = const of a frame whose u is -+(X - Y) (or -+(X + Y)), and the sign of U(q) - U(p) is
  // lexicographic (x - y, y) (or (x + y, y)), the sheared order of the mapped points; T keeps
  // orientations and incidences, so the sweep's argument holds verbatim. A norm's direction
  // (p, q) is mapped the same way (below).
  // mode: M::mode_dir(mode); for L1 and octilinear 0 vertical (slots N, S), 1 horizontal (E, W),
  // 2 NE/SW diagonal, 3 NW/SE diagonal; for a norm, its directions with y > 0 or y == 0 < x.
  void sweep_rays(int mode) {
    struct MP {
      i64 x, y;
    };
    // The mode's direction (dx, dy) made vertical: (dy x - dx y, y) when dy > 0 (for the
    // diagonals the unimodular maps above; for a norm's direction a map of determinant dy > 0,
    // which keeps orientations and incidences just the same), (y, x) for the horizontal. The
    // order of (dy X - dx Y) in the sheared plane is lexicographic (dy x - dx y, y) (the e term
    // is dy y, dy > 0), so the sweep's argument holds verbatim.
    const ModeDir md = M::mode_dir(mode);
    auto mp = [&](uint32_t v) {
      const Point p = pts[v];
      return md.y == 0 ? MP{p.y, p.x} : MP{md.y * p.x - md.x * p.y, p.y};
    };
    auto lex_less = [](MP a, MP b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    auto orient = [](MP a, MP b, MP c) {
      const i128 v = i128{b.x - a.x} * (c.y - a.y) - i128{b.y - a.y} * (c.x - a.x);
      return v > 0 ? 1 : (v < 0 ? -1 : 0);
    };
    const uint32_t m = static_cast<uint32_t>(edge_pts.size());
    std::vector<std::array<uint32_t, 2>> lr(m);  // (left end, right end) in sweep order
    std::vector<uint32_t> starts(nvert + 1, 0), ends(nvert + 1, 0);
    for (uint32_t e = 0; e < m; ++e) {
      auto [a, b] = edge_pts[e];
      if (lex_less(mp(b), mp(a))) std::swap(a, b);
      lr[e] = {a, b};
      ++starts[a + 1];
      ++ends[b + 1];
    }
    for (uint32_t v = 0; v < nvert; ++v) {
      starts[v + 1] += starts[v];
      ends[v + 1] += ends[v];
    }
    std::vector<uint32_t> start_list(m), end_list(m);
    {
      std::vector<uint32_t> fs(starts.begin(), starts.end() - 1), fe(ends.begin(), ends.end() - 1);
      for (uint32_t e = 0; e < m; ++e) {
        start_list[fs[lr[e][0]]++] = e;
        end_list[fe[lr[e][1]]++] = e;
      }
    }
    struct Key {
      MP q;
    };
    struct Below {  // bottom-to-top order of the edges crossing the sweep line
      struct is_transparent {};  // lower_bound(Key) (a type, not a typedef GCC calls unused)
      const std::vector<std::array<uint32_t, 2>>* lr;
      const decltype(mp)* to;
      decltype(lex_less) less;
      decltype(orient) ori;
      bool operator()(uint32_t e, uint32_t f) const {
        if (e == f) return false;
        const MP le = (*to)((*lr)[e][0]), re = (*to)((*lr)[e][1]);
        const MP lf = (*to)((*lr)[f][0]), rf = (*to)((*lr)[f][1]);
        if ((*lr)[e][0] == (*lr)[f][0]) return ori(le, re, rf) > 0;  // common left end: slopes
        if (less(lf, le)) return ori(lf, rf, le) < 0;                 // e starts below f
        return ori(le, re, lf) > 0;                                   // f starts above e
      }
      bool operator()(uint32_t e, const Key& k) const {  // edge below the point
        return ori((*to)((*lr)[e][0]), (*to)((*lr)[e][1]), k.q) > 0;
      }
      bool operator()(const Key& k, uint32_t e) const {  // point below the edge
        return ori((*to)((*lr)[e][0]), (*to)((*lr)[e][1]), k.q) < 0;
      }
    };
    std::set<uint32_t, Below> active(Below{&lr, &mp, lex_less, orient});
    std::vector<typename std::set<uint32_t, Below>::iterator> where(m, active.end());
    std::vector<uint32_t> order(nvert);
    for (uint32_t v = 0; v < nvert; ++v) order[v] = v;
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return lex_less(mp(a), mp(b)); });
    const std::size_t up = 2 * static_cast<std::size_t>(mode), down = up + 1;  // slots (shoot())
    // (a ray already shot one by one, on the grid or the R-tree, must get the same answer:
    // all are exact)
    auto put = [&](uint32_t& slot, uint32_t hit) {
      if (slot != kUnknown && slot != hit) throw std::logic_error("WaveCore: a track ray's sweep and single-ray answers differ");
      slot = hit;
    };
    for (const uint32_t q : order) {
      for (uint32_t i = ends[q]; i < ends[q + 1]; ++i) active.erase(where[end_list[i]]);
      auto it = active.lower_bound(Key{mp(q)});
      put(ray_cache[std::size_t{M::kRaySlots} * q + up], it == active.end() ? kNone : *it);
      put(ray_cache[std::size_t{M::kRaySlots} * q + down], it == active.begin() ? kNone : *std::prev(it));
      for (uint32_t i = starts[q]; i < starts[q + 1]; ++i)
        where[start_list[i]] = active.insert(start_list[i]).first;
    }
  }

  // The domain side is a wall: a frame obstacle around the domain, merged with every obstacle
  // that touches the side, so a vertex touching it is a pinch.
  // Obstacles that hold the frame already merged (NetSpace::obstacles(..., framed)) are taken as
  // they are: one obstacle whose outer ring is the frame's and whose holes lie in the closed
  // domain (so it holds the whole frame), and no other with a vertex on a side of the domain or
  // beyond it (so none touches the frame). Otherwise the merge is made here.
  void merge_frame(std::span<const Polygon> obstacles) {
    const Polygon frame = geom::domain_frame(domain);
    auto on_side = [&](Point q) {
      return q.x == domain.lo.x || q.x == domain.hi.x || q.y == domain.lo.y || q.y == domain.hi.y;
    };
    {
      int framed = 0;
      bool apart = true;
      for (const Polygon& p : obstacles) {
        if (p.outer == frame.outer && !p.holes.empty()) {
          ++framed;
          for (const geom::Ring& h : p.holes)
            for (Point q : h) apart = apart && in_domain(q);
          continue;
        }
        for (Point q : p.outer) apart = apart && in_domain(q) && !on_side(q);
      }
      if (framed == 1 && apart) {
        polys.assign(obstacles.begin(), obstacles.end());
        return;
      }
    }
    // (what has a vertex on a side or beyond it is merged too: a frame of an earlier merge, or
    // an obstacle the caller did not clip to the domain)
    const Box g{frame.outer[0], frame.outer[2]};
    std::vector<Polygon> touching{frame};
    for (const Polygon& p : obstacles) {
      bool t = false;
      for (Point q : p.outer)
        if (on_side(q) || !in_domain(q)) t = true;
      for (const geom::Ring& h : p.holes)
        for (Point q : h)
          if (on_side(q) || !in_domain(q)) t = true;
      if (t)
        touching.push_back(p);
      else
        polys.push_back(p);
    }
    geom::NormalizedObstacles merged = geom::normalize_obstacles(touching, g);
    for (Polygon& p : merged.obstacles) polys.push_back(std::move(p));
  }

  // ------------------------------------------------------------------------------------------
  // Entities and wedges.
  Dir lo_dir(const Entity& e) const {
    const Point p = pts[e.point], q = pts[e.lo];
    return int_dir(i64{q.x} - p.x, i64{q.y} - p.y);
  }
  Dir hi_dir(const Entity& e) const {
    const Point p = pts[e.point], q = pts[e.hi];
    return int_dir(i64{q.x} - p.x, i64{q.y} - p.y);
  }
  // How an entity's free wedge lies against the axes of each frame d, 6 bits per frame (bit
  // 6d + k), fixed by the geometry and so computed once per entity (these orientation tests
  // were 16 % of `taut route`'s time when spawn() and process() made them per event). With L0,
  // L1 the wedge's local clockwise and counter-clockwise ends and E, N, NW, SE local directions:
  //   k = 0: E strictly inside (L0, L1)   k = 1: N inside (L0, L1)   k = 2: L0 inside (E, N)
  //   k = 3: L1 inside (E, N)             k = 4: L1 inside (SE, E)   k = 5: L0 inside (N, NW)
  // (arcs counter-clockwise in local coordinates). A full entity has no bits.
  enum : uint32_t { kEInWedge = 1, kNInWedge = 2, kL0InQuad = 4, kL1InQuad = 8, kRightByEdge = 16,
                    kLeftByEdge = 32 };
  typename M::Bits compute_wedge_bits(const Entity& e) const {
    if (e.full) return {};
    typename M::Bits bits{};
    for (int d = M::kFirst; d < M::kFirst + M::kCount; ++d) {
      const int sigma = kFrames[d].sigma;
      const Dir L0 = sigma > 0 ? lo_dir(e) : hi_dir(e);
      const Dir L1 = sigma > 0 ? hi_dir(e) : lo_dir(e);
      auto local_in = [&](const Dir& a, const Dir& b, const Dir& x) {
        return sigma > 0 ? in_ccw(a, b, x) : in_ccw(b, a, x);
      };
      const Dir E = local_dir(d, 1, 0), N = local_dir(d, 0, 1);
      uint32_t b = 0;
      if (local_in(L0, L1, E)) b |= kEInWedge;
      if (local_in(L0, L1, N)) b |= kNInWedge;
      if (local_in(E, N, L0)) b |= kL0InQuad;
      if (local_in(E, N, L1)) b |= kL1InQuad;
      if constexpr (!M::kRoot2) {
        // the front wu u + wv v = const runs along the local lattice directions (wv, -wu) and
        // (-wv, wu) (L1: SE and NW)
        const int wu = static_cast<int>(kFrames[d].wu), wv = static_cast<int>(kFrames[d].wv);
        const Dir NW = local_dir(d, -wv, wu), SE = local_dir(d, wv, -wu);
        if (local_in(SE, E, L1)) b |= kRightByEdge;
        if (local_in(N, NW, L0)) b |= kLeftByEdge;
      } else {
        // The front u + sqrt2 v = const runs along (sqrt2, -1): L1 lies in the arc from it to E
        // iff it points below E (v < 0) and ahead of the front (level > 0); L0 in the arc from N
        // to (-sqrt2, 1) iff u < 0 and level > 0 (open arcs; the sheared edge directions are
        // never parallel to an axis, a diagonal or the irrational front).
        const Entity& ee = e;
        const uint32_t l0 = sigma > 0 ? ee.lo : ee.hi, l1 = sigma > 0 ? ee.hi : ee.lo;
        auto uv = [&](uint32_t q, T3& u, T3& v) {
          const i64 dx = i64{pts[q].x} - pts[ee.point].x, dy = i64{pts[q].y} - pts[ee.point].y;
          const Frame& f = kFrames[d];
          u = {f.a * dx + f.b * dy, f.a * dy, f.b * dx};
          v = {f.c * dx + f.d * dy, f.c * dy, f.d * dx};
        };
        T3 u, v;
        uv(l1, u, v);
        if (v < T3{} && R3{u, v} > R3{}) b |= kRightByEdge;
        uv(l0, u, v);
        if (u < T3{} && R3{u, v} > R3{}) b |= kLeftByEdge;
      }
      put_bits(bits, d - M::kFirst, b);
    }
    return bits;
  }
  uint32_t wedge_bits(uint32_t ent, int d) const {
    if (!bits_made[ent]) {
      ent_bits[ent] = compute_wedge_bits(ents[ent]);
      bits_made[ent] = 1;
    }
    return get_bits(ent_bits[ent], d - M::kFirst);
  }

  bool wedge_contains(const Entity& e, const Dir& x) const {
    if (e.full) return true;
    return in_ccw(lo_dir(e), hi_dir(e), x);
  }

  // Where p is: a vertex point (its id), on an edge interior (edge a->b), inside an obstacle,
  // or in open free space.
  enum class Where { Vertex, Edge, Inside, Free };
  Where locate(Point p, uint32_t& vid, uint32_t& ea, uint32_t& eb) const {
    if (!in_domain(p)) return Where::Inside;  // (the frame's outer corners are vertices, but not free)
    if (const uint32_t id = point_id(p); id != kNone) {
      vid = id;
      return Where::Vertex;
    }
    for (uint32_t e : index->edges_in_box(Box{p, p})) {
      const geom::Segment& s = index->edge(e);
      if (geom::on_segment(p, s.a, s.b)) {
        ea = edge_pts[e].first;
        eb = edge_pts[e].second;
        return Where::Edge;
      }
    }
    for (std::size_t i = 0; i < polys.size(); ++i) {
      const Box& b = poly_boxes[i];
      if (p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y) continue;
      if (geom::locate(p, polys[i]) != geom::Location::Outside) return Where::Inside;
    }
    return Where::Free;
  }

  bool is_free(Point p) const {
    uint32_t v, a, b;
    const Where w = locate(p, v, a, b);
    return w == Where::Vertex || w == Where::Edge || w == Where::Free;
  }

  // Entities of a query point (adds a run-time point/entity when it is not a vertex).
  std::vector<uint32_t> query_entities(Point p) {
    uint32_t v = kNone, a = kNone, b = kNone;
    switch (locate(p, v, a, b)) {
      case Where::Vertex: {
        std::vector<uint32_t> out;
        for (uint32_t e = ent_begin[v]; e < ent_begin[v + 1]; ++e) out.push_back(e);
        return out;
      }
      case Where::Inside:
        return {};
      case Where::Edge:
      case Where::Free: {
        const uint32_t pid = static_cast<uint32_t>(pts.size());
        pts.push_back(p);
        Entity e;
        e.point = pid;
        if (a != kNone) {
          e.lo = a;
          e.hi = b;
        } else {
          e.full = true;
        }
        ents.push_back(e);
        ent_bits.push_back(compute_wedge_bits(e));
        bits_made.push_back(1);
        return {static_cast<uint32_t>(ents.size() - 1)};
      }
    }
    return {};
  }

  // ------------------------------------------------------------------------------------------
  // Track rays: the first ring edge crossed by the sheared vertical (local north of frame d) or
  // horizontal (local east) ray from point o. Exact: crossings compared as rationals on the
  // exact axis line, ties (edges through one point of it) by slope, which is the order the
  // sheared ray meets them in (see header).
  bool shoot(int d, bool vertical, uint32_t o, uint32_t& ea, uint32_t& eb) {
    // The track's world direction: local north (V track) or east (H track), one of the
    // metric's directions; sweep_rays()' mode and slot for it.
    const Frame& f = kFrames[d];
    const int mode = vertical ? f.north_mode : f.east_mode;
    const int s = vertical ? f.north_sense : f.east_sense;  // +1: along the mode's direction
    uint32_t hit;
    if (o < nvert) {
      uint32_t& slot = ray_cache[std::size_t{M::kRaySlots} * o + 2 * mode + (s > 0 ? 0 : 1)];
      if (slot == kUnknown) {
        if (lazy_rays[mode] < nvert) {
          ++lazy_rays[mode];
          slot = shoot_uncached(s, mode, o);
        } else {
          sweep_rays(mode);
        }
      }
      hit = slot;
    } else {
      hit = shoot_uncached(s, mode, o);
    }
    if (hit == kNone) return false;
    ea = edge_pts[hit].first;
    eb = edge_pts[hit].second;
    return true;
  }
  // The first edge the sheared ray from point o meets (see shoot()): for an axis direction by
  // walking the cells of ray_grid along it, otherwise by R-tree windows that grow 4x.
  uint32_t shoot_uncached(int s, int mode, uint32_t o) {
    ++stats.ray_queries;
    const Point p = pts[o];
    const ModeDir md = M::mode_dir(mode);
    const bool vertical = md.y != 0;
    // Work in coordinates where the ray is along +/- the "t" axis and "w" is the other one
    // (sweep_rays()' mapped coordinates: the mode's direction mapped to vertical).
    auto tc = [&](Point q) -> i64 { return vertical ? q.y : q.x; };
    auto wc = [&](Point q) -> i64 { return vertical ? md.y * q.x - md.x * q.y : q.y; };
    // side of q relative to the sheared line through p: lexicographic (w, t) for vertical
    // (X = x + e y), (w, t) likewise for horizontal (Y = y + e^2 x) and the diagonals.
    auto side = [&](Point q) {
      const i64 dw = wc(q) - wc(p);
      if (dw != 0) return dw > 0 ? 1 : -1;
      const i64 dt = tc(q) - tc(p);
      return dt > 0 ? 1 : (dt < 0 ? -1 : 0);
    };
    const i64 lim_lo = vertical ? domain.lo.y - 1 : domain.lo.x - 1;
    const i64 lim_hi = vertical ? domain.hi.y + 1 : domain.hi.x + 1;
    bool found = false;
    i128 bn = 0, bd = 1;  // best crossing t = bn / bd
    i64 bsn = 0, bsd = 1;  // its slope dt/dw
    uint32_t best = kNone;
    // Edge e, if it crosses the sheared ray no farther than t1, against the best so far.
    auto consider = [&](uint32_t e, i64 t1) {
      const auto [ia, ib] = edge_pts[e];
      if (ia == o || ib == o) return;
      const Point a = pts[ia], b = pts[ib];
      const int sa = side(a), sb = side(b);
      if (sa == 0 || sb == 0 || sa == sb) return;
      // exact crossing of the line w = wc(p): t = ta + (wp - wa) (tb - ta) / (wb - wa)
      i64 dw = wc(b) - wc(a), dt = tc(b) - tc(a);
      i128 num = i128{tc(a)} * dw + i128{wc(p) - wc(a)} * dt;
      i128 den = dw;
      if (den < 0) {
        num = -num;
        den = -den;
      }
      // beyond p in direction s
      const i128 rel = num - i128{tc(p)} * den;
      if (rel == 0) return;  // through p: p lies on this edge
      if ((rel > 0 ? 1 : -1) != s) return;
      if (s > 0 ? num > i128{t1} * den : num < i128{t1} * den) return;
      // slope dt/dw with dw > 0
      i64 sn = dt, sd = dw;
      if (sd < 0) {
        sn = -sn;
        sd = -sd;
      }
      bool better;
      if (!found) {
        better = true;
      } else {
        const i128 c = num * bd - bn * den;  // sign of (this t - best t)
        if (c != 0) {
          better = s > 0 ? c < 0 : c > 0;
        } else {
          better = i128{sn} * bsd > i128{bsn} * sd;  // larger slope is met first
        }
      }
      if (better) {
        found = true;
        bn = num;
        bd = den;
        bsn = sn;
        bsd = sd;
        best = e;
      }
    };
    auto within = [&](i64 t1) { return s > 0 ? bn <= i128{t1} * bd : bn >= i128{t1} * bd; };
    if (md.y == 0 || (md.x == 0 && md.y == 1)) {
      // An axis ray: the cells of its column (row) from p's on. Every edge that meets the ray's
      // segment from p to the far side of a cell lies in the cells passed so far, so once the
      // best crossing lies no farther than that side it is the first.
      if (!ray_grid.built) build_ray_grid();
      const RayGrid& g = ray_grid;
      const i64 lim = s > 0 ? lim_hi : lim_lo;
      // f: the coordinate the ray keeps (its column or row), t: the one it walks along
      const i64 f = vertical ? p.x : p.y, f0 = vertical ? g.x0 : g.y0, nf = vertical ? g.nx : g.ny;
      const i64 t = vertical ? p.y : p.x, t0 = vertical ? g.y0 : g.x0, nt = vertical ? g.ny : g.nx;
      if (f < f0 || f >= f0 + g.cs * nf) return kNone;  // (no edge out there)
      const i64 cf = (f - f0) / g.cs;
      for (i64 ct = t < t0 ? -1 : std::min<i64>((t - t0) / g.cs, nt); s > 0 ? ct < nt : ct >= 0; ct += s) {
        if (ct >= 0 && ct < nt) {
          const std::size_t c = static_cast<std::size_t>(vertical ? ct * g.nx + cf : cf * g.nx + ct);
          for (uint32_t k = g.start[c]; k < g.start[c + 1]; ++k) consider(g.items[k], lim);
        }
        // the cell's far side: every crossing up to it has been seen
        const i64 far = s > 0 ? t0 + (ct + 1) * g.cs - 1 : t0 + ct * g.cs;
        if (found && within(far)) return best;
      }
      return best;  // every cell passed: the best of all, or none
    }
    // First window: about two typical gaps between edges (extent / sqrt(edges)); it grows 4x.
    i64 len = ray_window;
    while (true) {
      const i64 t0 = tc(p);
      const i64 t1 = s > 0 ? std::min<i64>(t0 + len, lim_hi) : std::max<i64>(t0 - len, lim_lo);
      Box box;
      if (vertical && md.x != 0) {  // the sloped segment's box, cut to the frame (no edges outside it)
        // x moves by md.x / md.y per unit of y: the far end's x, rounded outwards
        const i64 num = md.x * (t1 - t0);
        const i64 x1lo = p.x + (num >= 0 ? num / md.y : -((-num + md.y - 1) / md.y));
        const i64 x1hi = p.x + (num >= 0 ? (num + md.y - 1) / md.y : -((-num) / md.y));
        const i64 xlo = std::max<i64>(std::min<i64>(p.x, x1lo), domain.lo.x - 1);
        const i64 xhi = std::min<i64>(std::max<i64>(p.x, x1hi), domain.hi.x + 1);
        box = Box{{static_cast<geom::Coord>(xlo), static_cast<geom::Coord>(std::min(t0, t1))},
                  {static_cast<geom::Coord>(xhi), static_cast<geom::Coord>(std::max(t0, t1))}};
      } else if (vertical)
        box = Box{{p.x, static_cast<geom::Coord>(std::min(t0, t1))},
                  {p.x, static_cast<geom::Coord>(std::max(t0, t1))}};
      else
        box = Box{{static_cast<geom::Coord>(std::min(t0, t1)), p.y},
                  {static_cast<geom::Coord>(std::max(t0, t1)), p.y}};
      // Edges crossing the sheared line near the exact line x = p.x touch the exact segment
      // (the sheared line is within an infinitesimal of it). Within the window: a sloped mode's
      // box is the box around the ray's segment, so an edge may meet it and cross the ray
      // beyond t1, past a nearer edge that misses the box; it is taken only by a wider window
      // (consider() leaves it out). (For the axis modes the box is the segment itself and every
      // edge meeting it crosses within [t0, t1].)
      found = false;
      best = kNone;
      index->edges_in_box(box, box_edges);
      for (uint32_t e : box_edges) consider(e, t1);
      // The crossing lies inside the window [t0, t1] (the edge met the box), and every edge
      // crossing the ray nearer meets the window too.
      if (found) return best;
      if (t1 == lim_hi || t1 == lim_lo) return kNone;
      len *= 4;
    }
  }

  // The edges by the cells of a grid over their points (about one edge per cell, cells square,
  // at most 2^22 of them), each edge in every cell its segment passes (a superset, exactly
  // computed per column): the axis track rays walk it (shoot_uncached()). Made at the first
  // such ray.
  struct RayGrid {
    bool built = false;
    i64 x0 = 0, y0 = 0, cs = 1, nx = 0, ny = 0;
    std::vector<uint32_t> start, items;  // per cell (row-major): items[start[c], start[c + 1])
  } ray_grid;
  void build_ray_grid() {
    RayGrid& g = ray_grid;
    g.built = true;
    const std::size_t m = edge_pts.size();
    if (m == 0) {
      g.nx = g.ny = 0;
      g.start.assign(1, 0);
      return;
    }
    i64 xlo = pts[edge_pts[0].first].x, xhi = xlo, ylo = pts[edge_pts[0].first].y, yhi = ylo;
    for (const auto& [a, b] : edge_pts)
      for (const uint32_t v : {a, b}) {
        xlo = std::min<i64>(xlo, pts[v].x), xhi = std::max<i64>(xhi, pts[v].x);
        ylo = std::min<i64>(ylo, pts[v].y), yhi = std::max<i64>(yhi, pts[v].y);
      }
    const double area = static_cast<double>(xhi - xlo + 1) * static_cast<double>(yhi - ylo + 1);
    g.cs = std::max<i64>(1, static_cast<i64>(std::ceil(std::sqrt(area / static_cast<double>(m)))));
    while (((xhi - xlo) / g.cs + 1) * ((yhi - ylo) / g.cs + 1) > (i64{1} << 22)) g.cs *= 2;
    g.x0 = xlo;
    g.y0 = ylo;
    g.nx = (xhi - xlo) / g.cs + 1;
    g.ny = (yhi - ylo) / g.cs + 1;
    // cells of edge (a, b): per column its x-range meets, the rows between the segment's lowest
    // and highest y over that column (exact: floor and ceiling of the rational end values)
    auto cells = [&](Point a, Point b, auto&& put) {
      if (a.x > b.x) std::swap(a, b);
      const i64 c0 = (i64{a.x} - g.x0) / g.cs, c1 = (i64{b.x} - g.x0) / g.cs;
      const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
      auto floor_div = [](i128 n, i128 d) { return static_cast<i64>(n >= 0 ? n / d : -((-n + d - 1) / d)); };
      for (i64 c = c0; c <= c1; ++c) {
        i64 ya, yb;
        if (dx == 0) {
          ya = std::min(a.y, b.y);
          yb = std::max(a.y, b.y);
        } else {
          // (the column is the real interval [x0 + c cs, x0 + (c + 1) cs): a horizontal ray's
          // crossing may lie between its last integer and the next column's first)
          const i64 xa = std::max<i64>(a.x, g.x0 + c * g.cs), xb = std::min<i64>(b.x, g.x0 + (c + 1) * g.cs);
          // y(x) = a.y + dy (x - a.x) / dx at xa and xb, outwards
          const i128 na = i128{a.y} * dx + i128{dy} * (xa - a.x), nb = i128{a.y} * dx + i128{dy} * (xb - a.x);
          const i128 lo = std::min(na, nb), hi = std::max(na, nb);
          ya = floor_div(lo, dx);
          yb = -floor_div(-hi, dx);
        }
        const i64 r0 = std::max<i64>(0, (ya - g.y0) / g.cs), r1 = std::min<i64>(g.ny - 1, (yb - g.y0) / g.cs);
        for (i64 r = r0; r <= r1; ++r) put(static_cast<std::size_t>(r * g.nx + c));
      }
    };
    g.start.assign(static_cast<std::size_t>(g.nx * g.ny) + 1, 0);
    for (const auto& [a, b] : edge_pts) cells(pts[a], pts[b], [&](std::size_t c) { ++g.start[c + 1]; });
    for (std::size_t c = 0; c + 1 < g.start.size(); ++c) g.start[c + 1] += g.start[c];
    g.items.resize(g.start.back());
    std::vector<uint32_t> fill(g.start.begin(), g.start.end() - 1);
    for (uint32_t e = 0; e < m; ++e)
      cells(pts[edge_pts[e].first], pts[edge_pts[e].second], [&](std::size_t c) { g.items[fill[c]++] = e; });
  }

  uint32_t far_end(int d, uint32_t a, uint32_t b) const {
    return level(d, pts[a]) > level(d, pts[b]) ? a : b;
  }
  Bound axis_bound(int d, bool vertical, uint32_t origin) {
    Bound bd;
    bd.kind = vertical ? kV : kH;
    bd.origin = origin;
    uint32_t a, b;
    if (shoot(d, vertical, origin, a, b)) {
      bd.ea = a;
      bd.eb = b;
      bd.far = far_end(d, a, b);
    }
    return bd;
  }
  // O track along the ring edge at the lo (prev -> p) or hi (p -> next) end of an entity.
  Bound edge_bound(int d, const Entity& e, bool lo_end) const {
    Bound bd;
    bd.kind = kO;
    if (lo_end) {
      bd.ea = e.lo;
      bd.eb = e.point;
    } else {
      bd.ea = e.point;
      bd.eb = e.hi;
    }
    if (e.point >= nvert) {  // a query point inside a ring edge: track along the whole edge
      bd.ea = e.lo;
      bd.eb = e.hi;
    }
    bd.far = far_end(d, bd.ea, bd.eb);
    return bd;
  }

  void add_constraints(Region& r, const Bound& b, bool is_left) const {
    const int d = r.d;
    if (b.kind == kO) {
      r.ea[r.nedges] = pts[b.ea];
      r.eb[r.nedges] = pts[b.eb];
      ++r.nedges;
      return;
    }
    typename Region::Lex l;
    const Point o = pts[b.origin];
    if (b.kind == kV) {
      l.on_u = true;
      l.value = U(d, o);
      l.greater = is_left;  // left track: region to its right (u > u_o)
    } else {
      l.on_u = false;
      l.value = V(d, o);
      l.greater = !is_left;  // left track (east ray): region below (v < v_o)
    }
    r.lex[r.nlex++] = l;
    // The stop edge bounds the region only when the track end slides along it into the region
    // (its far end on the region side). Otherwise its near end lies in the region and is hit
    // before the stop point; the pieces made there get their own tracks.
    bool slides_in = false;
    if (b.ea != kNone) {
      const Point f = pts[b.far];
      const T3 fv = l.on_u ? U(d, f) : V(d, f);
      slides_in = l.greater ? fv > l.value : fv < l.value;
    }
    if (slides_in) {
      r.ea[r.nedges] = pts[b.ea];
      r.eb[r.nedges] = pts[b.eb];
      ++r.nedges;
    }
  }

  // Finds the wave's next event and queues it (or drops the wave when it hits nothing).
  void insert(Wave w) {
    ++stats.wavelets;
    Region r;
    r.d = w.dir;
    r.start = level(w.dir, pts[w.start]);
    add_constraints(r, w.left, true);
    add_constraints(r, w.right, false);
    ++stats.drag_queries;
    const Box frame{{domain.lo.x - 1, domain.lo.y - 1}, {domain.hi.x + 1, domain.hi.y + 1}};
    if (!region_hull(r, frame, r.hull)) return;
    uint32_t vid = kNone, tid = kNone;
    Lv vl, tl;
    const uint32_t leaf = vertex_tree.leaf_of(w.start);
    const bool hv = leaf != kNone ? vertex_tree.query_near(leaf, r, vid, vl, stats.drag_nodes)
                                  : vertex_tree.query(r, vid, vl, stats.drag_nodes);
    const bool ht = !target_tree.empty() && target_tree.query(r, tid, tl, stats.drag_nodes);
    if (!hv && !ht) return;
    const Point root = pts[ents[w.root].point];
    if (ht && (!hv || tl < vl)) {
      w.event = tid;
      w.event_is_target = 1;
      w.key = ents[w.root].d + tl - level(w.dir, root);
    } else {
      w.event = vid;
      w.event_is_target = 0;
      w.key = ents[w.root].d + vl - level(w.dir, root);
    }
    w.seq = seq++;
    queue.push(w);
  }

  void label(uint32_t ent, const Lv& d, uint32_t parent) {
    Entity& e = ents[ent];
    e.labelled = true;
    e.d = d;
    e.parent = parent;
    e.source = parent == kNone ? e.source : ents[parent].source;
    if (ent < nvent) touched.push_back(ent);
    ++stats.labelled;
  }

  // The wavelets of a newly labelled root entity in every frame, except arcs inside `covered`
  // (world ccw arc from c0 to c1; has_cover false = none).
  void spawn(uint32_t ent, bool has_cover, const Dir& c0, const Dir& c1) {
    const Entity e = ents[ent];
    const uint32_t p = e.point;
    for (int d = M::kFirst; d < M::kFirst + M::kCount; ++d) {
      const int sigma = kFrames[d].sigma;
      const Dir E = local_dir(d, 1, 0), N = local_dir(d, 0, 1);
      auto emit = [&](const Dir& a0, const Dir& a1, Bound right, Bound left) {
        if (has_cover && !e.full) {
          // local arc a0 -> a1 as a world arc
          const Dir w0 = sigma > 0 ? a0 : a1, w1 = sigma > 0 ? a1 : a0;
          const Dir base = lo_dir(e);
          const bool inside = !ccw_less(base, w0, c0) && !ccw_less(base, c1, w1);
          if (inside) return;
        }
        Wave w;
        w.root = ent;
        w.start = p;
        w.dir = static_cast<uint8_t>(d);
        w.left = left;
        w.right = right;
        insert(w);
      };
      if (e.full) {
        emit(E, N, axis_bound(d, false, p), axis_bound(d, true, p));
        continue;
      }
      // local wedge ends
      const Dir L0 = sigma > 0 ? lo_dir(e) : hi_dir(e);
      const Dir L1 = sigma > 0 ? hi_dir(e) : lo_dir(e);
      const bool L0_is_lo = sigma > 0;
      const uint32_t bits = wedge_bits(ent, d);
      const bool a = bits & kEInWedge, b = bits & kNInWedge;
      const bool c = bits & kL0InQuad, dd = bits & kL1InQuad;
      if (a && b && !c && !dd) {
        emit(E, N, axis_bound(d, false, p), axis_bound(d, true, p));
      } else if (a && b && c && dd) {
        emit(E, L1, axis_bound(d, false, p), edge_bound(d, e, !L0_is_lo));
        emit(L0, N, edge_bound(d, e, L0_is_lo), axis_bound(d, true, p));
      } else if (a && !b) {
        emit(E, L1, axis_bound(d, false, p), edge_bound(d, e, !L0_is_lo));
      } else if (!a && b) {
        emit(L0, N, edge_bound(d, e, L0_is_lo), axis_bound(d, true, p));
      } else if (!a && !b && c && dd) {
        emit(L0, L1, edge_bound(d, e, L0_is_lo), edge_bound(d, e, !L0_is_lo));
      }
    }
  }

  uint32_t entity_at(uint32_t p, uint32_t lo, uint32_t hi, const Dir* contains) const {
    for (uint32_t i = ent_begin[p]; i < ent_begin[p + 1]; ++i) {
      const Entity& e = ents[i];
      if (lo != kNone && e.lo == lo) return i;
      if (hi != kNone && e.hi == hi) return i;
      if (contains && wedge_contains(e, *contains)) return i;
    }
    return kNone;
  }

  void process(const Wave& w) {
    ++stats.events;
    const int d = w.dir;
    const int sigma = kFrames[d].sigma;
    const uint32_t p = w.event;
    if (w.event_is_target) {
      const uint32_t te = point_target_entity[p - nvert];
      if (!ents[te].labelled) label(te, w.key, w.root);
      Wave c = w;
      c.start = p;
      insert(c);
      return;
    }
    const bool left_end = w.left.far == p && (w.left.kind == kO || w.left.ea != kNone);
    const bool right_end = w.right.far == p && (w.right.kind == kO || w.right.ea != kNone);
    uint32_t ent = kNone;
    // p on the exact axis line of a track (the sheared track passes infinitesimally beside it):
    // the wave reaches p only from the sector between that line and the front.
    const Point pp = pts[p];
    auto on_line = [&](const Bound& b) {
      if (b.kind == kO) return false;
      const Point o = pts[b.origin];
      return b.kind == kV ? U(d, pp).a == U(d, o).a : V(d, pp).a == V(d, o).a;
    };
    const bool on_left = !left_end && !right_end && on_line(w.left);
    const bool on_right = !left_end && !right_end && !on_left && on_line(w.right);
    Dir arrive = local_dir(d, -1, -1);  // SW
    auto world_int = [&](i64 u, i64 v) {
      const Point w = local_int(d, u, v);
      return int_dir(w.x, w.y);
    };
    // a direction strictly between the track's back direction (local south, west) and the
    // front's: (1, -2) and (-2, 1) for L1 (front SE/NW) and octilinear (front (sqrt2, -1)); for
    // a norm's front (wv, -wu): (wv, -(wu + wv)) and (-(wu + wv), wu)
    i64 fu = 1, fv = 1;
    if constexpr (!M::kRoot2) {
      fu = kFrames[d].wu;
      fv = kFrames[d].wv;
    }
    if (on_left && w.left.kind == kV) arrive = world_int(fv, -(fu + fv));
    if (on_right && w.right.kind == kH) arrive = world_int(-(fu + fv), fu);
    auto arriving_edge_entity = [&](const Bound& b) {
      // ring edge ea -> eb ends here: at eb it is the entity's lo edge, at ea its hi edge
      return b.eb == p ? entity_at(p, b.ea, kNone, nullptr) : entity_at(p, kNone, b.eb, nullptr);
    };
    if (left_end)
      ent = arriving_edge_entity(w.left);
    else if (right_end)
      ent = arriving_edge_entity(w.right);
    else
      ent = entity_at(p, kNone, kNone, &arrive);
    if (ent == kNone) {  // contradicts the free-space invariants: a bug, not bad input
      char buf[160];
      std::snprintf(buf, sizeof buf, "wavefront: no free wedge of (%d,%d) holds the wave (dir %d)",
                    pts[p].x, pts[p].y, d);
      throw std::logic_error(buf);
    }
    Entity& e = ents[ent];

    // Mitchell §4 case 4 (clipping against earlier hitters from the same direction) is not
    // applied: see wavefront.h. Every part of the wave goes on.
    // Local wedge ends and the continuation tracks at p.
    const Dir L0 = sigma > 0 ? lo_dir(e) : hi_dir(e);  // local cw end
    const Dir L1 = sigma > 0 ? hi_dir(e) : lo_dir(e);  // local ccw end
    const bool L0_is_lo = sigma > 0;
    // Right piece's left track: p's edge when it points into (SE, E), else the east ray.
    const uint32_t bits = wedge_bits(ent, d);
    const bool right_by_edge = !e.full && (bits & kRightByEdge);
    const bool left_by_edge = !e.full && (bits & kLeftByEdge);
    const Dir E = local_dir(d, 1, 0), N = local_dir(d, 0, 1);

    if (!e.labelled) {
      label(ent, w.key, w.root);
      // Covered near p: from the left piece's right track through the back half-plane to the
      // right piece's left track (local ccw), or the arriving track's back direction.
      Dir c0 = left_by_edge ? L0 : N;
      Dir c1 = right_by_edge ? L1 : E;
      if (left_end) c0 = L0;
      if (right_end) c1 = L1;
      // exact local south / west: the back direction of a track line p lies on
      if (on_left) c0 = w.left.kind == kV ? world_int(0, -1) : world_int(-1, 0);
      if (on_right) c1 = w.right.kind == kV ? world_int(0, -1) : world_int(-1, 0);
      // as a world arc
      const Dir w0 = sigma > 0 ? c0 : c1, w1 = sigma > 0 ? c1 : c0;
      spawn(ent, true, w0, w1);
    }

    // The continuation: the part left of p (bounded by p's vertical or p's edge) and the part
    // right of p. An endpoint collision ends the side whose track arrived at p.
    if (!left_end && !on_left) {
      Wave c;
      c.root = w.root;
      c.start = p;
      c.dir = w.dir;
      c.left = w.left;
      c.right = left_by_edge ? edge_bound(d, e, L0_is_lo) : axis_bound(d, true, p);
      insert(c);
    }
    if (!right_end && !on_right) {
      Wave c;
      c.root = w.root;
      c.start = p;
      c.dir = w.dir;
      c.left = right_by_edge ? edge_bound(d, e, !L0_is_lo) : axis_bound(d, false, p);
      c.right = w.right;
      insert(c);
    }
  }


  void run(std::span<const Point> sources, std::span<const Point> targets, WavefrontStop stop) {
    // reset
    pts.resize(nvert);
    ents.resize(nvent);  // run-time entities go; vertex entities of the last run are reset
    ent_bits.resize(nvent);
    bits_made.resize(nvent);
    for (const uint32_t e : touched) {
      ents[e].labelled = false;
      ents[e].d = Lv{};
      ents[e].parent = kNone;
      ents[e].source = kNone;
    }
    touched.clear();
    queue = {};
    seq = 0;
    stats = WavefrontStats{};
    stats.vertices = nvert;
    stats.entities = nvent;
    target_ents.clear();
    target_pts.assign(targets.begin(), targets.end());
    point_target_entity.clear();
    // targets
    std::vector<std::pair<Point, uint32_t>> titems;
    std::unordered_map<uint64_t, uint32_t> runtime_point;
    for (Point t : targets) {
      if (auto it = runtime_point.find(key_of(t)); it != runtime_point.end()) {
        target_ents.push_back({point_target_entity[it->second - nvert]});
        continue;
      }
      const std::size_t before = pts.size();
      auto es = query_entities(t);
      if (pts.size() > before) {
        const uint32_t pid = static_cast<uint32_t>(pts.size() - 1);
        runtime_point[key_of(t)] = pid;
        point_target_entity.resize(pid - nvert + 1, kNone);
        point_target_entity[pid - nvert] = es[0];
        titems.push_back({t, pid});
      }
      target_ents.push_back(es);
    }
    target_tree = KdTree<M>(std::move(titems));
    // sources
    for (std::size_t i = 0; i < sources.size(); ++i) {
      std::vector<uint32_t> es;
      if (auto it = runtime_point.find(key_of(sources[i])); it != runtime_point.end())
        es = {point_target_entity[it->second - nvert]};
      else
        es = query_entities(sources[i]);
      for (uint32_t e : es) {
        if (ents[e].labelled) continue;
        ents[e].source = static_cast<uint32_t>(i);
        if (e < nvent) touched.push_back(e);
        label(e, Lv{}, kNone);
      }
    }
    stats.entities = static_cast<std::int64_t>(ents.size());  // with the query points'
    for (std::size_t i = 0; i < ents.size(); ++i)
      if (ents[i].labelled && ents[i].parent == kNone) spawn(static_cast<uint32_t>(i), false, {}, {});
    auto all_targets_done = [&] {
      for (const auto& es : target_ents) {
        if (es.empty()) continue;
        bool any = false;
        for (uint32_t e : es) any = any || ents[e].labelled;
        if (!any) return false;
      }
      return true;
    };
    auto any_target_done = [&] {
      for (const auto& es : target_ents)
        for (uint32_t e : es)
          if (ents[e].labelled) return true;
      return false;
    };
    std::size_t check_every = 0;
    while (!queue.empty()) {
      // Labels are final when made (Dijkstra order: a target or vertex is labelled when its
      // event is popped, and later keys are no smaller), so stopping between pops is exact; the
      // first target labelled is a nearest one.
      if (stop != WavefrontStop::Never && !targets.empty() && (++check_every & 63) == 0 &&
          (stop == WavefrontStop::AllTargets ? all_targets_done() : any_target_done()))
        break;
      Wave w = queue.top();
      queue.pop();
      process(w);
    }
  }

  std::optional<uint32_t> best_target_entity(std::size_t i) const {
    std::optional<uint32_t> best;
    for (uint32_t e : target_ents.at(i))
      if (ents[e].labelled && (!best || ents[e].d < ents[*best].d)) best = e;
    return best;
  }
};

// Per point source of the run: the source index the caller sees (run with segment sources);
// empty: the identity.
struct SourceOrigin {
  std::vector<std::size_t> source_origin;
  std::optional<std::size_t> origin(uint32_t s) const {
    if (s == kNone) return std::nullopt;
    return source_origin.empty() ? std::size_t{s} : source_origin[s];
  }
};

}  // namespace

struct L1Wavefront::Impl : WaveCore<L1Metric>, SourceOrigin {
  using WaveCore::WaveCore;
};
struct OctWavefront::Impl : WaveCore<OctMetric>, SourceOrigin {
  using WaveCore::WaveCore;
};

namespace {
// The public classes' queries, shared (Core = WaveCore<M>).
template <class Core>
std::vector<Point> path_of(const Core& c, std::size_t i) {
  std::vector<Point> out;
  auto e = c.best_target_entity(i);
  if (!e) return out;
  for (uint32_t x = *e; x != kNone; x = c.ents[x].parent) {
    const Point p = c.pts[c.ents[x].point];
    if (out.empty() || out.back() != p) out.push_back(p);
  }
  std::reverse(out.begin(), out.end());
  return out;
}
template <class M, class Core>
std::optional<typename M::C> vertex_distance_of(const Core& c, Point p) {
  const uint32_t v = c.point_id(p);
  if (v == kNone) return std::nullopt;
  std::optional<typename M::C> best;
  for (uint32_t e = c.ent_begin[v]; e < c.ent_begin[v + 1]; ++e)
    if (c.ents[e].labelled) {
      const typename M::C d = M::constant(c.ents[e].d);
      if (!best || d < *best) best = d;
    }
  return best;
}
template <class M, class Core>
std::vector<WavefrontWedge<typename M::C>> wedges_of(const Core& c, Point p) {
  std::vector<WavefrontWedge<typename M::C>> out;
  const uint32_t v = c.point_id(p);
  if (v == kNone) return out;
  for (uint32_t e = c.ent_begin[v]; e < c.ent_begin[v + 1]; ++e) {
    const auto& en = c.ents[e];
    WavefrontWedge<typename M::C> w{c.pts[en.lo], c.pts[en.hi], std::nullopt, std::nullopt};
    if (en.labelled) {
      w.distance = M::constant(en.d);
      if (en.source != kNone) w.source = en.source;
    }
    out.push_back(w);
  }
  return out;
}
template <class Core>
std::vector<Point> wedge_path_of(const Core& c, Point p, std::size_t k) {
  std::vector<Point> out;
  const uint32_t v = c.point_id(p);
  if (v == kNone || k >= c.ent_begin[v + 1] - c.ent_begin[v]) return out;
  const uint32_t e0 = c.ent_begin[v] + static_cast<uint32_t>(k);
  if (!c.ents[e0].labelled) return out;
  for (uint32_t x = e0; x != kNone; x = c.ents[x].parent) {
    const Point q = c.pts[c.ents[x].point];
    if (out.empty() || out.back() != q) out.push_back(q);
  }
  std::reverse(out.begin(), out.end());
  return out;
}
template <class Core>
std::size_t memory_of(const Core& m) {
  std::size_t b = m.pts.capacity() * sizeof(Point) + m.ents.capacity() * sizeof(m.ents[0]) +
                  m.touched.capacity() * sizeof(uint32_t) +
                  m.ent_begin.capacity() * sizeof(uint32_t) +
                  m.ent_bits.capacity() * sizeof(m.ent_bits[0]) +
                  m.edge_pts.capacity() * sizeof(m.edge_pts[0]) + m.vertex_tree.memory_bytes() +
                  m.ray_cache.capacity() * sizeof(uint32_t) + m.bits_made.capacity() +
                  (m.ray_grid.start.capacity() + m.ray_grid.items.capacity()) * sizeof(uint32_t) +
                  m.point_ids.capacity() * sizeof(m.point_ids[0]);
  for (const Polygon& p : m.polys) {
    b += p.outer.capacity() * sizeof(Point);
    for (const auto& h : p.holes) b += h.capacity() * sizeof(Point);
  }
  return b;
}
}  // namespace

L1Wavefront::L1Wavefront(const Box& domain, std::span<const Polygon> obstacles)
    : impl_(std::make_unique<Impl>(domain, obstacles)) {}
L1Wavefront::~L1Wavefront() = default;
L1Wavefront::L1Wavefront(L1Wavefront&&) noexcept = default;
L1Wavefront& L1Wavefront::operator=(L1Wavefront&&) noexcept = default;

bool L1Wavefront::is_free(Point p) const { return impl_->is_free(p); }

void L1Wavefront::run(std::span<const Point> sources, std::span<const Point> targets,
                      bool stop_early) {
  run(sources, targets, stop_early ? Stop::AllTargets : Stop::Never);
}

void L1Wavefront::run(std::span<const Point> sources, std::span<const Point> targets, Stop stop) {
  impl_->source_origin.clear();
  impl_->run(sources, targets, stop);
}

void ProjectionLines::add(Point p) {
  xs_.push_back(p.x);
  ys_.push_back(p.y);
  if (octilinear_) {
    ds_.push_back(i64{p.y} - p.x);
    ss_.push_back(i64{p.x} + p.y);
  }
}

void ProjectionLines::done() {
  for (auto* v : {&xs_, &ys_, &ds_, &ss_}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
}

void ProjectionLines::inside(Point a, Point b, std::vector<Point>& cand) const {
  auto strictly_between = [](const std::vector<i64>& v, i64 lo, i64 hi) {
    if (hi <= lo + 1) return std::span<const i64>();  // (a single point has no inside)
    return std::span<const i64>(std::upper_bound(v.begin(), v.end(), lo), std::lower_bound(v.begin(), v.end(), hi));
  };
  if (b < a) std::swap(a, b);  // a before b: by x, then y
  auto at = [](i64 x, i64 y) { return Point{static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)}; };
  if (a.x == b.x) {
    // x = a.x: y level with a point (d8 along it is least there: OctWavefront::run)
    for (const i64 y : strictly_between(ys_, a.y, b.y)) cand.push_back(at(a.x, y));
    return;
  }
  const i64 sl = (b.y > a.y) - (b.y < a.y);  // slope 0, 1 or -1
  auto on = [&](i64 x) { return at(x, a.y + sl * (x - a.x)); };
  for (const i64 x : strictly_between(xs_, a.x, b.x)) cand.push_back(on(x));  // vertical projections
  if (sl != 0)  // horizontal projections
    for (const i64 y : strictly_between(ys_, std::min(a.y, b.y), std::max(a.y, b.y))) cand.push_back(on(a.x + sl * (y - a.y)));
  if (!octilinear_) return;
  if (sl == 0) return;
  // along y - x = c (sl = 1) the other diagonal x + y = s meets it at x = (s - c) / 2; along
  // x + y = c (sl = -1) the diagonal y - x = d at x = (c - d) / 2; halfway: both neighbours (by
  // symmetry they are as far from the point when nothing is in the way; an obstacle may part them)
  const i64 c0 = sl == 1 ? i64{a.y} - a.x : i64{a.y} + a.x;
  const std::vector<i64>& other = sl == 1 ? ss_ : ds_;
  const i64 lo = sl == 1 ? i64{a.x} + a.y : i64{b.y} - b.x, hi = sl == 1 ? i64{b.x} + b.y : i64{a.y} - a.x;
  for (const i64 v : strictly_between(other, lo, hi)) {
    const i64 twice = sl == 1 ? v - c0 : c0 - v;  // 2x
    for (const i64 x : geom::lattice_neighbours(twice, lattice_))
      if (a.x < x && x < b.x) cand.push_back(on(x));
  }
}

namespace {

// A run with segment sources (L1Wavefront::run and OctWavefront::run with segments,
// wavefront.h): from the point sources, then for each segment every free point of it where the
// least distance to a target may be taken (its ends and the ProjectionLines of the ring vertices
// and targets), each mapped to the source index the caller sees (Impl: WaveCore and SourceOrigin).
template <class Impl>
void run_with_segment_sources(Impl& c, std::span<const Point> sources, std::span<const geom::Segment> segment_sources,
                              std::span<const Point> targets, WavefrontStop stop, bool octilinear,
                              i64 lattice = 1) {
  // The ring vertices (frame included) and the targets: where projections onto a segment fall.
  ProjectionLines lines(octilinear, lattice);
  for (uint32_t v = 0; v < c.nvert; ++v) lines.add(c.pts[v]);
  for (const Point t : targets) lines.add(t);
  lines.done();
  std::vector<Point> pts(sources.begin(), sources.end());
  std::vector<std::size_t> origin;
  for (std::size_t i = 0; i < sources.size(); ++i) origin.push_back(i);
  std::vector<Point> cand;
  for (std::size_t k = 0; k < segment_sources.size(); ++k) {
    const Point a = segment_sources[k].a, b = segment_sources[k].b;
    const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
    if (dx != 0 && dy != 0 && dx != dy && dx != -dy)
      throw std::invalid_argument("a segment source must be horizontal, vertical or at 45 degrees");
    cand.assign({a, b});
    lines.inside(a, b, cand);
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    for (const Point p : cand)
      if (c.is_free(p)) {
        pts.push_back(p);
        origin.push_back(sources.size() + k);
      }
  }
  c.run(pts, targets, stop);
  c.source_origin = std::move(origin);
}

}  // namespace

void L1Wavefront::run(std::span<const Point> sources, std::span<const geom::Segment> segment_sources,
                      std::span<const Point> targets, Stop stop) {
  run_with_segment_sources(*impl_, sources, segment_sources, targets, stop, false);
}

std::optional<std::int64_t> L1Wavefront::target_distance(std::size_t i) const {
  auto e = impl_->best_target_entity(i);
  if (!e) return std::nullopt;
  return impl_->ents[*e].d.a;
}

std::optional<std::size_t> L1Wavefront::target_source(std::size_t i) const {
  auto e = impl_->best_target_entity(i);
  if (!e) return std::nullopt;
  return impl_->origin(impl_->ents[*e].source);
}

std::vector<Point> L1Wavefront::target_path(std::size_t i) const { return path_of(*impl_, i); }

std::optional<std::int64_t> L1Wavefront::vertex_distance(Point p) const {
  return vertex_distance_of<L1Metric>(*impl_, p);
}

std::span<const Polygon> L1Wavefront::frame_obstacles() const { return impl_->polys; }

std::vector<L1Wavefront::Wedge> L1Wavefront::vertex_wedges(Point p) const {
  std::vector<Wedge> w = wedges_of<L1Metric>(*impl_, p);
  for (Wedge& x : w)
    if (x.source) x.source = impl_->origin(static_cast<uint32_t>(*x.source));
  return w;
}

std::vector<Point> L1Wavefront::wedge_path(Point p, std::size_t k) const { return wedge_path_of(*impl_, p, k); }

const WavefrontStats& L1Wavefront::stats() const { return impl_->stats; }

std::size_t L1Wavefront::memory_bytes() const { return memory_of(*impl_); }

OctWavefront::OctWavefront(const Box& domain, std::span<const Polygon> obstacles)
    : impl_(std::make_unique<Impl>(domain, obstacles)) {}
OctWavefront::~OctWavefront() = default;
OctWavefront::OctWavefront(OctWavefront&&) noexcept = default;
OctWavefront& OctWavefront::operator=(OctWavefront&&) noexcept = default;

bool OctWavefront::is_free(Point p) const { return impl_->is_free(p); }

void OctWavefront::run(std::span<const Point> sources, std::span<const Point> targets, Stop stop) {
  impl_->source_origin.clear();
  impl_->run(sources, targets, stop);
}

void OctWavefront::run(std::span<const Point> sources, std::span<const geom::Segment> segment_sources,
                       std::span<const Point> targets, Stop stop, std::int64_t lattice) {
  if (lattice < 1) throw std::invalid_argument("the segment sources' lattice must be at least 1");
  run_with_segment_sources(*impl_, sources, segment_sources, targets, stop, true, lattice);
}

std::optional<geom::Root2> OctWavefront::target_distance(std::size_t i) const {
  auto e = impl_->best_target_entity(i);
  if (!e) return std::nullopt;
  return OctMetric::constant(impl_->ents[*e].d);
}

std::optional<std::size_t> OctWavefront::target_source(std::size_t i) const {
  auto e = impl_->best_target_entity(i);
  if (!e) return std::nullopt;
  return impl_->origin(impl_->ents[*e].source);
}

std::vector<Point> OctWavefront::target_path(std::size_t i) const { return path_of(*impl_, i); }

std::optional<geom::Root2> OctWavefront::vertex_distance(Point p) const {
  return vertex_distance_of<OctMetric>(*impl_, p);
}

std::span<const Polygon> OctWavefront::frame_obstacles() const { return impl_->polys; }

std::vector<OctWavefront::Wedge> OctWavefront::vertex_wedges(Point p) const {
  std::vector<Wedge> w = wedges_of<OctMetric>(*impl_, p);
  for (Wedge& x : w)
    if (x.source) x.source = impl_->origin(static_cast<uint32_t>(*x.source));
  return w;
}

std::vector<Point> OctWavefront::wedge_path(Point p, std::size_t k) const { return wedge_path_of(*impl_, p, k); }

const WavefrontStats& OctWavefront::stats() const { return impl_->stats; }

std::size_t OctWavefront::memory_bytes() const { return memory_of(*impl_); }

// One core per supported order; the public class dispatches at run time.
struct NormWavefront::Impl {
  std::variant<std::unique_ptr<WaveCore<Norm2Metric>>, std::unique_ptr<WaveCore<Norm3Metric>>,
               std::unique_ptr<WaveCore<Norm4Metric>>>
      core;
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit([&](const auto& c) -> decltype(auto) { return f(*c); }, core);
  }
  template <class F>
  decltype(auto) visit(F&& f) {
    return std::visit([&](auto& c) -> decltype(auto) { return f(*c); }, core);
  }
};

NormWavefront::NormWavefront(const Box& domain, std::span<const Polygon> obstacles, int order)
    : impl_(std::make_unique<Impl>()), order_(order) {
  if (order < 2 || order > 4)
    throw std::invalid_argument("NormWavefront: the order must be 2, 3 or 4");
  std::size_t vertices = 8;
  for (const Polygon& p : obstacles) {
    vertices += p.outer.size();
    for (const auto& h : p.holes) vertices += h.size();
  }
  const i128 extent = i128{domain.hi.x} - domain.lo.x + i128{domain.hi.y} - domain.lo.y + 2;
  if (i128(vertices + 2) * extent * geom::kNormScale >= (i128{1} << 62))
    throw std::domain_error("NormWavefront: the layout is too large for exact norm lengths in 64 bits");
  switch (order) {
    case 2: impl_->core = std::make_unique<WaveCore<Norm2Metric>>(domain, obstacles); break;
    case 3: impl_->core = std::make_unique<WaveCore<Norm3Metric>>(domain, obstacles); break;
    default: impl_->core = std::make_unique<WaveCore<Norm4Metric>>(domain, obstacles); break;
  }
}
NormWavefront::~NormWavefront() = default;
NormWavefront::NormWavefront(NormWavefront&&) noexcept = default;
NormWavefront& NormWavefront::operator=(NormWavefront&&) noexcept = default;

bool NormWavefront::is_free(Point p) const {
  return impl_->visit([&](const auto& c) { return c.is_free(p); });
}
void NormWavefront::run(std::span<const Point> sources, std::span<const Point> targets, Stop stop) {
  impl_->visit([&](auto& c) { c.run(sources, targets, stop); });
}
std::optional<std::int64_t> NormWavefront::target_distance(std::size_t i) const {
  return impl_->visit([&](const auto& c) -> std::optional<std::int64_t> {
    auto e = c.best_target_entity(i);
    if (!e) return std::nullopt;
    return c.ents[*e].d.a;
  });
}
std::optional<std::size_t> NormWavefront::target_source(std::size_t i) const {
  return impl_->visit([&](const auto& c) -> std::optional<std::size_t> {
    auto e = c.best_target_entity(i);
    if (!e) return std::nullopt;
    return c.ents[*e].source;
  });
}
std::vector<Point> NormWavefront::target_path(std::size_t i) const {
  return impl_->visit([&](const auto& c) { return path_of(c, i); });
}
std::optional<std::int64_t> NormWavefront::vertex_distance(Point p) const {
  return impl_->visit([&](const auto& c) { return vertex_distance_of<L1Metric>(c, p); });
}
const WavefrontStats& NormWavefront::stats() const {
  return impl_->visit([&](const auto& c) -> const WavefrontStats& { return c.stats; });
}
std::size_t NormWavefront::memory_bytes() const {
  return impl_->visit([&](const auto& c) { return memory_of(c); });
}

std::optional<std::int64_t> l1_distance(const Box& domain, std::span<const Polygon> obstacles,
                                        Point s, Point t) {
  L1Wavefront wf(domain, obstacles);
  wf.run({&s, 1}, {&t, 1});
  return wf.target_distance(0);
}

}  // namespace taut::router
