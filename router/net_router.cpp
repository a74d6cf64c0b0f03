#include "router/net_router.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <limits>
#include <map>
#include <numeric>
#include <mutex>
#include <set>
#include <shared_mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include <boost/pending/disjoint_sets.hpp>

#include "geom/bg.h"
#include "geom/predicates.h"
#include "geom/validate.h"
#include "router/bend_router.h"
#include "router/l1_router.h"
#include "router/lookahead.h"
#include "router/oct_router.h"
#include "router/wavefront.h"

namespace taut::router {
namespace {

using geom::Box;
using geom::Point;
using geom::Polygon;
using geom::Ring;
using Lines = std::vector<std::vector<Point>>;
using geom::i128;
namespace bgi = boost::geometry::index;

Box box_of(std::span<const Point> pts) { return geom::bounding_box(pts); }
Box clipped(const Box& w, const Box& dom) { return geom::clipped_box(w, dom); }

// Calls f(p, q) for each segment of the polyline (one of length zero for a single point).
template <class F>
void for_segments(std::span<const Point> line, F&& f) {
  if (line.size() == 1) f(line[0], line[0]);
  for (std::size_t i = 0; i + 1 < line.size(); ++i) f(line[i], line[i + 1]);
}

std::int64_t l1_length(const Lines& wires) {
  std::int64_t n = 0;
  for (const auto& w : wires)
    for (std::size_t i = 0; i + 1 < w.size(); ++i)
      n += std::abs(std::int64_t{w[i + 1].x} - w[i].x) + std::abs(std::int64_t{w[i + 1].y} - w[i].y);
  return n;
}
bool two_point_pins(const NetPins& n) { return n.pins.size() == 2 && is_point_pin(n.pins[0]) && is_point_pin(n.pins[1]); }

std::string net_list(std::span<const std::size_t> nets, const std::function<std::string(std::size_t)>& name) {
  std::string s;
  for (std::size_t k = 0; k < nets.size(); ++k) {
    if (k) s += k + 1 == nets.size() ? " and " : ", ";
    s += name(nets[k]);
  }
  return s;
}

// The L-infinity r-neighbourhood of pq (geom::square_grown_segment), or where that would pass the
// coordinate limit its bounding box clipped to the limit (larger, so never less clearance; the
// domain lies inside the limit, so nothing in it is lost).
Ring grown_segment(Point p, Point q, std::int64_t r) {
  const std::int64_t x0 = std::min(p.x, q.x) - r, x1 = std::max(p.x, q.x) + r;
  const std::int64_t y0 = std::min(p.y, q.y) - r, y1 = std::max(p.y, q.y) + r;
  if (geom::in_range(x0) && geom::in_range(x1) && geom::in_range(y0) && geom::in_range(y1))
    return geom::square_grown_segment(p, q, static_cast<geom::Coord>(r));
  auto c = [](std::int64_t v) { return static_cast<geom::Coord>(std::clamp<std::int64_t>(v, -geom::kMaxCoord, geom::kMaxCoord)); };
  return Ring{{c(x0), c(y0)}, {c(x1), c(y0)}, {c(x1), c(y1)}, {c(x0), c(y1)}};
}

// A rectangle: four vertices on two x's and two y's, no holes.
bool is_rectangle(const Polygon& p) {
  if (p.outer.size() != 4 || !p.holes.empty()) return false;
  const Box b = box_of(p.outer);
  for (const Point v : p.outer)
    if ((v.x != b.lo.x && v.x != b.hi.x) || (v.y != b.lo.y && v.y != b.hi.y)) return false;
  return b.lo.x < b.hi.x && b.lo.y < b.hi.y;
}

// Are all the edges of p (outer ring and holes) horizontal or vertical?
bool is_rectilinear_shape(const Polygon& p) {
  bool all = true;
  for_each_pin_edge(p, [&](Point a, Point b) { all = all && (a.x == b.x || a.y == b.y); });
  return all;
}

// A shape pin cut out of its net's grown blockage edges (a pad, see NetSpace::obstacles): a
// shape whose edges are horizontal and vertical (a rectangle, an L, a U, holes too: as
// rectangles, pad_pieces), or with `shapes` any shape whose edges are horizontal, vertical or at
// 45 degrees (convex or not, holes too: pad_pieces). Not the 45-degree ones for the bend-aware
// metrics, whose router takes rectilinear obstacles only: such a cut would give them sloped
// edges; a rectilinear pad's pieces are rectangles, and a rectangle cut out of a grown
// rectilinear edge leaves rectangles (geom::convex_minus_box).
bool is_pad(const Polygon& p, bool shapes) {
  if (is_rectangle(p)) return true;
  if (is_point_pin(p) || !pin_shape_supported(p)) return false;
  return shapes || is_rectilinear_shape(p);
}
// A pin's edges that are not vertical, each left to right (for pad_pieces, edges at 0, 45 or 135
// degrees; for pad_staircase, at any angle).
std::vector<std::pair<Point, Point>> sloped_edges(const Polygon& p) {
  std::vector<std::pair<Point, Point>> edges;
  for_each_pin_edge(p, [&](Point a, Point b) {
    if (a.x != b.x) edges.push_back(a.x < b.x ? std::pair{a, b} : std::pair{b, a});
  });
  return edges;
}
// xs with the x of every vertex of p added, sorted, without repeats.
template <class X>
void add_vertex_xs(const Polygon& p, std::vector<X>& xs) {
  for_each_pin_edge(p, [&](Point a, Point) { xs.push_back(a.x); });
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
}
// The pin's trapezoids over the column [x0, x1], which no vertex lies strictly inside: the
// (y at x0, y at x1) of each edge of `edges` (sloped_edges) that spans it, in order from the
// bottom, so that entries 2i and 2i + 1 bound one trapezoid (even-odd: holes and notches stay
// out). Exact: the slopes are 0 and +-1. `ys` is the output (cleared first).
void column_edges(const std::vector<std::pair<Point, Point>>& edges, std::int64_t x0, std::int64_t x1,
                  std::vector<std::pair<std::int64_t, std::int64_t>>& ys) {
  ys.clear();
  for (const auto& [a, b] : edges)
    if (a.x <= x0 && x1 <= b.x) {
      const std::int64_t sl = (std::int64_t{b.y} - a.y) / (std::int64_t{b.x} - a.x);  // -1, 0 or 1
      ys.emplace_back(a.y + sl * (x0 - a.x), a.y + sl * (x1 - a.x));
    }
  // edges do not cross inside the column: ordered by their sum of ends
  std::sort(ys.begin(), ys.end(), [](const auto& u, const auto& v) { return u.first + u.second < v.first + v.second; });
}

// pad_staircase's column [x0, x1] (no vertex strictly inside it) on the lattice of `step`: per
// trapezoid of the pin over it (between two consecutive edges of `edges`, sloped_edges, that span
// the column, from the bottom, even-odd: holes and notches stay out), the y's on the lattice that
// it holds at both of the column's sides: [lo, hi] with lo the least multiple of step on or above
// the lower edge at x0 and at x1, hi the greatest on or below the upper edge at both (edges at any
// angle: their y there are fractions, rounded inwards exactly). The rectangle [x0, x1] x [lo, hi]
// lies in the trapezoid (convex) when lo <= hi. `out` is cleared first.
// With `outward`, the other way: [lo, hi] with lo the greatest multiple on or below the lower edge
// at both sides and hi the least on or above the upper edge at both (a blockage's extent over
// the column: every cell outside it meets none of the trapezoid's interior).
void column_lattice_ys(const std::vector<std::pair<Point, Point>>& edges, std::int64_t x0, std::int64_t x1,
                       std::int64_t step, std::vector<std::pair<std::int64_t, std::int64_t>>& out, bool outward = false) {
  struct At {
    i128 n0, n1, d;  // y at x0 = n0 / d, at x1 = n1 / d, d > 0
  };
  std::vector<At> at;
  for (const auto& [a, b] : edges)
    if (a.x <= x0 && x1 <= b.x) {
      const i128 d = i128{b.x} - a.x, dy = i128{b.y} - a.y;
      at.push_back({i128{a.y} * d + dy * (x0 - a.x), i128{a.y} * d + dy * (x1 - a.x), d});
    }
  // edges do not cross inside the column: ordered by their y at its middle, (n0 + n1) / 2d
  std::sort(at.begin(), at.end(), [](const At& u, const At& v) { return (u.n0 + u.n1) * v.d < (v.n0 + v.n1) * u.d; });
  out.clear();
  const i128 k = step;
  for (std::size_t i = 0; i + 1 < at.size(); i += 2) {
    const At& lo = at[i];
    const At& hi = at[i + 1];
    if (outward) {
      out.emplace_back(static_cast<std::int64_t>(std::min(geom::floor_div(lo.n0, lo.d * k), geom::floor_div(lo.n1, lo.d * k)) * k),
                       static_cast<std::int64_t>(std::max(geom::ceil_div(hi.n0, hi.d * k), geom::ceil_div(hi.n1, hi.d * k)) * k));
      continue;
    }
    out.emplace_back(static_cast<std::int64_t>(std::max(geom::ceil_div(lo.n0, lo.d * k), geom::ceil_div(lo.n1, lo.d * k)) * k),
                     static_cast<std::int64_t>(std::min(geom::floor_div(hi.n0, hi.d * k), geom::floor_div(hi.n1, hi.d * k)) * k));
  }
}

// A pad as convex pieces whose union is the pad, each a counter-clockwise octilinear_convex_ring
// (what geom::convex_minus_pad takes): the pad itself when convex; else its vertical slabs
// between consecutive vertex x's, each cut into the trapezoids between consecutive edges that
// span it (even-odd, so holes stay out; the edges are at 0, 45 or 135 degrees, so every corner
// is an integer point). Cutting every piece out of a grown blockage edge cuts the pad out (a
// piece's open interior is removed; the segments between pieces lie inside the pad and go
// with their neighbours, as the cut keeps only pieces of positive area).
std::vector<Ring> pad_pieces(const Polygon& p) {
  if (p.holes.empty())
    if (auto r = geom::octilinear_convex_ring(p.outer)) return {*r};
  const std::vector<std::pair<Point, Point>> edges = sloped_edges(p);
  std::vector<geom::Coord> xs;
  add_vertex_xs(p, xs);
  std::vector<Ring> out;
  std::vector<std::pair<std::int64_t, std::int64_t>> ys;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const geom::Coord x0 = xs[k], x1 = xs[k + 1];
    column_edges(edges, x0, x1, ys);
    for (std::size_t i = 0; i + 1 < ys.size(); i += 2) {
      const auto [b0, b1] = ys[i];
      const auto [t0, t1] = ys[i + 1];
      const Ring trapezoid{{x0, static_cast<geom::Coord>(b0)},
                           {x1, static_cast<geom::Coord>(b1)},
                           {x1, static_cast<geom::Coord>(t1)},
                           {x0, static_cast<geom::Coord>(t0)}};
      if (auto r = geom::octilinear_convex_ring(trapezoid)) out.push_back(*r);
    }
  }
  return out;
}

// Do the interiors of two convex counter-clockwise polygons meet? Not when an edge line of one
// has the other on its outer closed side (separating axes, exact: the separating line of two
// convex sets can always be taken along an edge of one of them). Either may be a segment (two
// points: its line, both ways) or a point (no line of its own).
bool convex_interiors_meet(const Ring& a, const Ring& b) {
  for (const auto* r : {&a, &b}) {
    const Ring& o = r == &a ? b : a;
    if (r->size() < 2) continue;
    for (std::size_t i = 0; i < r->size(); ++i) {
      const Point u = (*r)[i], v = (*r)[(i + 1) % r->size()];
      bool outside = true;
      for (const Point q : o) outside = outside && geom::orient(u, v, q) <= 0;
      if (outside) return false;
    }
  }
  return true;
}

// Does the closed segment pq (a point when p == q) meet the interior of the convex polygon c?
bool segment_enters(Point p, Point q, const Ring& c) {
  return convex_interiors_meet(p == q ? Ring{p} : Ring{p, q}, c);
}

// The closed segment pq meets the closed polygon bounded by ring c.
bool segment_touches(Point p, Point q, const Ring& c) {
  if (geom::locate(p, c) != geom::Location::Outside || geom::locate(q, c) != geom::Location::Outside) return true;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (geom::intersect(geom::Segment{p, q}, geom::Segment{c[i], c[(i + 1) % c.size()]}) != geom::SegmentIntersection::None)
      return true;
  return false;
}

}  // namespace

struct NetSpace::Index {
  enum Kind { Blockage, GrownEdge, GrownPin, ShapePin };
  struct Piece {
    Polygon poly;
    Kind kind;
    std::size_t owner;  // the net of a pin piece; the blockage index otherwise
  };
  using Entry = std::pair<Box, std::size_t>;
  std::vector<Piece> pieces;
  bgi::rtree<Entry, bgi::rstar<16>> tree;  // the pin pieces only
  // wires: per net its grown segments; the R-tree holds (box, (net, index))
  std::vector<std::vector<Ring>> wire_pieces;
  using WireEntry = std::pair<Box, std::pair<std::size_t, std::size_t>>;
  bgi::rtree<WireEntry, bgi::rstar<16>> wire_tree;
  // and the union of each net's grown segments (clipped to the domain), which the other nets are
  // routed among: fewer, larger pieces than the segments, without their overlaps at the bends
  std::vector<std::vector<Polygon>> wire_union;
  bgi::rtree<WireEntry, bgi::rstar<16>> union_tree;
  // The union of the blockages and their grown edges, once (its components, each with the
  // pieces it came from), and the blockages themselves, with their boxes in R-trees.
  struct Components {
    std::vector<Polygon> polys;
    std::vector<std::vector<std::size_t>> sources;  // indices into pieces (grown only: the
                                                    // plain level cuts nothing)
    bgi::rtree<Entry, bgi::rstar<16>> tree;
  };
  Components grown, plain;
};

namespace {

// Boxes of the components and their R-tree.
void index_components(NetSpace::Index::Components& c) {
  std::vector<NetSpace::Index::Entry> entries;
  for (std::size_t i = 0; i < c.polys.size(); ++i) entries.push_back({box_of(c.polys[i].outer), i});
  c.tree = decltype(c.tree)(entries.begin(), entries.end());
}

bool box_inside(const Box& in, const Box& out) {
  return in.lo.x >= out.lo.x && in.lo.y >= out.lo.y && in.hi.x <= out.hi.x && in.hi.y <= out.hi.y;
}
bool box_strictly_inside(const Box& in, const Box& out) {
  return in.lo.x > out.lo.x && in.lo.y > out.lo.y && in.hi.x < out.hi.x && in.hi.y < out.hi.y;
}
using geom::boxes_meet;

// The wires without their parts of positive length in the closed pads `pads` (the net's own pads,
// counter-clockwise convex rings with edges at 0, 45 or 90 degrees: metal of the net, so a wire's
// stretch over or along one is redundant, and where the pad lies on a blockage's edge that stretch
// would come too near it). Each wire is cut where it enters and leaves a pad, the pieces keep those
// points (so they still touch the pad), and pieces of one point are dropped. A horizontal,
// vertical or 45-degree segment is cut at integer points: its unit steps k meet each pad edge's
// line at an integer k, except a 45-degree segment against a 45-degree edge, where k may be a half;
// such a segment, and a segment of another slope, is kept whole.
Lines trim_at_pads(const Lines& wires, std::span<const Ring> pads) {
  if (pads.empty()) return wires;
  Lines out;
  for (const auto& w : wires) {
    if (w.size() == 1) {
      out.push_back(w);
      continue;
    }
    std::vector<Point> cur;
    auto flush = [&] {
      if (cur.size() >= 2) out.push_back(cur);
      cur.clear();
    };
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
      const Point p = w[i], q = w[i + 1];
      const std::int64_t dx = std::int64_t{q.x} - p.x, dy = std::int64_t{q.y} - p.y;
      const std::int64_t len = std::max(std::abs(dx), std::abs(dy));
      const bool regular = dx == 0 || dy == 0 || std::abs(dx) == std::abs(dy);
      if (cur.empty()) cur.push_back(p);
      if (!regular || len == 0) {
        if (cur.back() != q) cur.push_back(q);
        continue;
      }
      // the steps k in [0, len] (p + k u, u the unit step) inside each pad: an interval (left of
      // every edge: c0 + k c1 >= 0 with the edge's unit direction e, c0 = cross(e, p - a),
      // c1 = cross(e, u)); cut out the ones of positive length
      const std::int64_t ux = dx / len, uy = dy / len;
      std::vector<std::pair<std::int64_t, std::int64_t>> cuts;
      bool whole = false;
      for (const Ring& r : pads) {
        std::int64_t lo = 0, hi = len;
        for (std::size_t e = 0; e < r.size() && lo <= hi; ++e) {
          const Point a = r[e], b = r[(e + 1) % r.size()];
          const std::int64_t ex = std::int64_t{b.x} - a.x, ey = std::int64_t{b.y} - a.y;
          const std::int64_t el = std::max(std::abs(ex), std::abs(ey));
          const std::int64_t vx = ex / el, vy = ey / el;
          const std::int64_t c0 = vx * (std::int64_t{p.y} - a.y) - vy * (std::int64_t{p.x} - a.x);
          const std::int64_t c1 = vx * uy - vy * ux;
          if (c1 == 0) {
            if (c0 < 0) lo = 1, hi = 0;
            continue;
          }
          if (c0 % c1 != 0) {  // a half step: not cut
            whole = true;
            break;
          }
          const std::int64_t k = -c0 / c1;  // c0 + k c1 = 0
          if (c1 > 0) lo = std::max(lo, k);
          else hi = std::min(hi, k);
        }
        if (whole) break;
        if (lo < hi) cuts.push_back({lo, hi});
      }
      if (whole) {
        if (cur.back() != q) cur.push_back(q);
        continue;
      }
      std::sort(cuts.begin(), cuts.end());
      auto at = [&](std::int64_t k) { return Point{static_cast<geom::Coord>(p.x + k * ux), static_cast<geom::Coord>(p.y + k * uy)}; };
      std::int64_t done = 0;
      for (const auto& [lo, hi] : cuts) {
        if (hi <= done) continue;
        if (lo > done && cur.back() != at(lo)) cur.push_back(at(lo));
        flush();
        done = std::max(done, hi);
        cur.push_back(at(done));
      }
      if (done < len && cur.back() != q) cur.push_back(q);
    }
    flush();
  }
  return out;
}

}  // namespace

std::optional<Polygon> pad_staircase(const Polygon& pin, std::int64_t step, const std::function<bool(const Polygon&)>& clear,
                                     std::span<const Polygon> cuts) {
  if (step < 1) throw std::invalid_argument("pad_staircase: a step below 1");
  if (is_point_pin(pin) || (is_rectilinear_shape(pin) && cuts.empty())) return std::nullopt;
  bool ring_ok = pin.outer.size() >= 3;  // (rings of three vertices at least, no edge of length 0)
  for (const Ring& h : pin.holes) ring_ok = ring_ok && h.size() >= 3;
  for_each_pin_edge(pin, [&](Point a, Point b) { ring_ok = ring_ok && a != b; });
  if (!ring_ok) return std::nullopt;
  // the vertices' x range (on the lattice, so no vertex lies strictly inside a column)
  std::int64_t x0 = std::numeric_limits<std::int64_t>::max(), x1 = std::numeric_limits<std::int64_t>::min();
  bool on_lattice = true;
  for_each_pin_edge(pin, [&](Point a, Point) {
    on_lattice = on_lattice && a.x % step == 0 && a.y % step == 0;
    x0 = std::min<std::int64_t>(x0, a.x);
    x1 = std::max<std::int64_t>(x1, a.x);
  });
  // the cuts' vertices in the pin's x range too (then none lies strictly inside a column either)
  std::vector<std::int64_t> cut_xs;
  std::vector<std::vector<std::pair<Point, Point>>> cut_edges;
  for (const Polygon& c : cuts) {
    for_each_pin_edge(c, [&](Point a, Point) {
      if (a.x <= x0 || a.x >= x1) return;
      on_lattice = on_lattice && a.x % step == 0;
      cut_xs.push_back(a.x);
    });
    cut_edges.push_back(sloped_edges(c));
  }
  if (!on_lattice) return std::nullopt;
  const std::vector<std::pair<Point, Point>> edges = sloped_edges(pin);
  // The staircase of columns `width` wide (a multiple of step): [x, x + width] from x0 to x1,
  // each also split at the pin's vertices (column_lattice_ys needs none strictly inside a column), so
  // every bound is on the lattice. Per column, each trapezoid of the pin over it gives the
  // rectangle of the y's it holds at both sides; their union (exact: horizontal and vertical
  // edges only) must be one valid polygon: a part too thin for a column splits it, or joins it at
  // a corner only.
  // (`parts`: the rectangles of the last staircase tried, by column, for the fallback below)
  std::vector<std::vector<Polygon>> parts;
  auto staircase = [&](std::int64_t width) -> std::optional<Polygon> {
    parts.clear();
    std::vector<std::int64_t> xs;
    for (std::int64_t x = x0; x < x1; x += width) xs.push_back(x);
    xs.push_back(x1);
    if (width > step) {
      add_vertex_xs(pin, xs);
      xs.insert(xs.end(), cut_xs.begin(), cut_xs.end());
      std::sort(xs.begin(), xs.end());
      xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    }
    std::vector<Polygon> rects;
    std::vector<std::pair<std::int64_t, std::int64_t>> ys, blocked, more;
    for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
      const std::int64_t x = xs[k], cw = xs[k + 1] - x;
      column_lattice_ys(edges, x, x + cw, step, ys);
      blocked.clear();  // the cuts' extents over the column, sorted
      for (const auto& ce : cut_edges) {
        column_lattice_ys(ce, x, x + cw, step, more, true);
        blocked.insert(blocked.end(), more.begin(), more.end());
      }
      std::sort(blocked.begin(), blocked.end());
      parts.emplace_back();
      const auto c = [](std::int64_t v) { return static_cast<geom::Coord>(v); };
      auto emit = [&](std::int64_t lo, std::int64_t hi) {
        if (lo >= hi) return;  // a peak's column, or a part one column thin
        rects.push_back(Polygon{{{c(x), c(lo)}, {c(x + cw), c(lo)}, {c(x + cw), c(hi)}, {c(x), c(hi)}}, {}});
        parts.back().push_back(rects.back());
      };
      for (auto [lo, hi] : ys) {  // the pin's interval less the cuts' (in order from the bottom)
        for (const auto& [blo, bhi] : blocked) {
          if (bhi <= lo || blo >= hi) continue;
          emit(lo, blo);
          lo = std::max(lo, bhi);
        }
        emit(lo, hi);
      }
    }
    if (rects.empty()) return std::nullopt;
    geom::NormalizedObstacles u = geom::normalize_obstacles(rects, box_of(pin.outer));
    if (u.obstacles.size() != 1 || !geom::validate_polygon(u.obstacles[0]).empty()) return std::nullopt;
    return std::move(u.obstacles[0]);
  };
  // Columns of one step; for a pin more than kMaxStaircaseColumns steps wide, of m steps, the
  // fewest that make at most that many, and when that staircase is not one valid polygon (a thin
  // diagonal bar) of m/2, m/4, ... steps while they make at most kMaxUnitStaircaseColumns.
  const std::int64_t cols = (x1 - x0) / step;
  for (std::int64_t m = std::max<std::int64_t>(1, (cols + NetSpace::kMaxStaircaseColumns - 1) / NetSpace::kMaxStaircaseColumns);; m /= 2) {
    if (std::optional<Polygon> st = staircase(m * step)) return st;
    if (m == 1 || cols / (m / 2) > NetSpace::kMaxUnitStaircaseColumns) break;
  }
  // None is one valid polygon (a part of the pin too thin for a column: a diagonal bar, a neck):
  // the largest part of the last one tried that is (since 2026-12-05; before, none was taken, and
  // under the bend-aware metrics such a net was ROUTE-0010 when its pin met the grown blockages).
  // Its parts: the rectangles joined along edges of positive length (rectangles of one column
  // are apart; those of consecutive columns share such an edge when their y ranges overlap by
  // more than a point), each part's union taken when it is one valid polygon, the largest by
  // area (ties: the first, its columns from the left).
  std::vector<std::pair<std::size_t, std::size_t>> ids;  // (column, index) of each rectangle
  for (std::size_t c = 0; c < parts.size(); ++c)
    for (std::size_t k = 0; k < parts[c].size(); ++k) ids.push_back({c, k});
  std::vector<std::size_t> parent(ids.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (std::size_t u = 0; u < ids.size(); ++u)
    for (std::size_t v = u + 1; v < ids.size() && ids[v].first <= ids[u].first + 1; ++v) {
      if (ids[v].first != ids[u].first + 1) continue;
      const Box a = box_of(parts[ids[u].first][ids[u].second].outer), b = box_of(parts[ids[v].first][ids[v].second].outer);
      if (a.hi.x == b.lo.x && std::max(a.lo.y, b.lo.y) < std::min(a.hi.y, b.hi.y)) parent[find(v)] = find(u);
    }
  struct Part {
    std::vector<Polygon> rects;
    __int128 area = 0;
    std::size_t first = 0;  // its first rectangle's index (from the left)
  };
  std::map<std::size_t, Part> groups;  // by root
  for (std::size_t u = 0; u < ids.size(); ++u) {
    const Polygon& r = parts[ids[u].first][ids[u].second];
    const Box b = box_of(r.outer);
    const auto [it, fresh] = groups.try_emplace(find(u));
    if (fresh) it->second.first = u;
    it->second.rects.push_back(r);
    it->second.area += __int128{std::int64_t{b.hi.x} - b.lo.x} * (std::int64_t{b.hi.y} - b.lo.y);
  }
  std::vector<const Part*> order;
  for (const auto& [root, g] : groups) order.push_back(&g);
  std::sort(order.begin(), order.end(), [](const Part* a, const Part* b) {
    return a->area != b->area ? a->area > b->area : a->first < b->first;
  });
  // (the largest valid part `clear` accepts, else the largest valid part)
  std::optional<Polygon> largest;
  for (const Part* g : order) {
    geom::NormalizedObstacles u = geom::normalize_obstacles(g->rects, box_of(pin.outer));
    if (u.obstacles.size() != 1 || !geom::validate_polygon(u.obstacles[0]).empty()) continue;
    if (!clear || clear(u.obstacles[0])) return std::move(u.obstacles[0]);
    if (!largest) largest = std::move(u.obstacles[0]);
  }
  return largest;
}

NetSpace::~NetSpace() = default;
NetSpace::NetSpace(NetSpace&&) noexcept = default;
NetSpace& NetSpace::operator=(NetSpace&&) noexcept = default;

NetSpace::NetSpace(const geom::Box& domain, std::span<const geom::Polygon> obstacles, std::vector<NetPins> nets,
                   NetRules rules)
    : domain_(domain), nets_(std::move(nets)), index_(std::make_unique<Index>()) {
  if (rules.wire_width < 0 || rules.spacing < 0) throw std::invalid_argument("NetSpace: negative width or spacing");
  if (rules.scale < 1) throw std::invalid_argument("NetSpace: a scale below 1");
  cut_shapes_ = rules.cover_pieces == 0;
  scale_ = rules.scale;
  rule_a_ = router::blockage_rule(rules);
  rule_b_ = router::net_rule(rules);
  if (rule_a_ > geom::kMaxCoord || rule_b_ > geom::kMaxCoord) throw std::domain_error("the clearance of <rules> passes the coordinate limit");
  // scaled by K: K x - 1, so that only exact touches open (0 stays 0: nothing is grown)
  auto grow = [&](std::int64_t x) { return rules.scale > 1 && x > 0 ? rules.scale * x - 1 : x; };
  a_ = grow(rule_a_);
  // a point pin's access square: K a + 1 when scaled, one more than the whole square
  // router/check.h exempts, scaled: a wire in the band snaps onto the square's side, which is
  // exempt, and where two access squares of a net meet at a blockage's corner (or a square's
  // side meets a blockage) the grown remainder no longer touches the blockage and pinches the
  // way shut (K a - 1 or K a would)
  access_ = rules.scale > 1 && rule_a_ > 0 ? rules.scale * rule_a_ + 1 : a_;
  b_ = grow(rule_b_);
  if (a_ > geom::kMaxCoord || b_ > geom::kMaxCoord) throw std::domain_error("the clearance of <rules> passes the coordinate limit");
  Index& ix = *index_;
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const Polygon& poly = obstacles[k];
    ix.pieces.push_back({poly, Index::Blockage, k});
    if (a_ == 0) continue;
    std::vector<const Ring*> rings{&poly.outer};
    for (const Ring& h : poly.holes) rings.push_back(&h);
    for (const Ring* r : rings)
      for (std::size_t i = 0; i < r->size(); ++i)
        ix.pieces.push_back({Polygon{grown_segment((*r)[i], (*r)[(i + 1) % r->size()], a_), {}}, Index::GrownEdge, k});
  }
  for (std::size_t n = 0; n < nets_.size(); ++n)
    for (const Polygon& pin : nets_[n].pins) {
      if (is_point_pin(pin)) {
        ix.pieces.push_back({Polygon{grown_segment(pin.outer[0], pin.outer[0], b_), {}}, Index::GrownPin, n});
        continue;
      }
      // a shape pin: the shape itself, and its edges grown by max(a, 1); with cover_pieces, its
      // sloped edges' boxes instead of those edges (each box holds its piece of the edge, so the
      // box grown holds the piece grown)
      const std::int64_t g = grow(std::max<std::int64_t>(rule_a_, 1));
      ix.pieces.push_back({pin, Index::ShapePin, n});
      std::vector<const Ring*> rings{&pin.outer};
      for (const Ring& h : pin.holes) rings.push_back(&h);
      const bool cover = rules.cover_pieces > 0;
      for (const Ring* r : rings)
        for (std::size_t i = 0; i < r->size(); ++i) {
          const Point p = (*r)[i], q = (*r)[(i + 1) % r->size()];
          if (cover && p.x != q.x && p.y != q.y) continue;
          ix.pieces.push_back({Polygon{grown_segment(p, q, g), {}}, Index::GrownPin, n});
        }
      if (cover) {
        const Polygon only[1] = {pin};
        const std::vector<Polygon> c = rectilinear_cover(only, nullptr, rules.cover_pieces);
        for (std::size_t i = 1; i < c.size(); ++i) {  // c[0] is the pin itself
          const Box b = box_of(c[i].outer);
          ix.pieces.push_back({c[i], Index::ShapePin, n});
          const Box gb = geom::grown_box(b, g);  // clamped to the coordinate limit: never smaller in the domain
          ix.pieces.push_back({Polygon{{gb.lo, {gb.hi.x, gb.lo.y}, gb.hi, {gb.lo.x, gb.hi.y}}, {}}, Index::GrownPin, n});
        }
      }
    }
  std::vector<Index::Entry> entries;  // the pins' pieces (the blockages' are found through the components)
  for (std::size_t i = 0; i < ix.pieces.size(); ++i)
    if (ix.pieces[i].kind == Index::GrownPin || ix.pieces[i].kind == Index::ShapePin)
      entries.push_back({box_of(ix.pieces[i].poly.outer), i});
  ix.tree = decltype(ix.tree)(entries.begin(), entries.end());
  ix.wire_pieces.resize(nets_.size());
  ix.wire_union.resize(nets_.size());
  // the grown blockages' union, once; and the blockages as they are
  std::vector<Polygon> inputs;
  std::vector<std::size_t> input_piece;
  for (std::size_t i = 0; i < ix.pieces.size(); ++i)
    if (ix.pieces[i].kind == Index::Blockage || ix.pieces[i].kind == Index::GrownEdge) {
      inputs.push_back(ix.pieces[i].poly);
      input_piece.push_back(i);
    }
  geom::NormalizedObstacles g = geom::normalize_obstacles(inputs, domain_);
  ix.grown.polys = std::move(g.obstacles);
  for (const auto& src : g.sources) {
    ix.grown.sources.emplace_back();
    for (const std::size_t k : src) ix.grown.sources.back().push_back(input_piece[k]);
  }
  index_components(ix.grown);
  ix.plain.polys.assign(obstacles.begin(), obstacles.end());
  index_components(ix.plain);
  // reach(): a shape pin partly under a blockage is reached as the staircase of its part outside
  // the blockages, and one with an edge at another angle than 0, 45 or 90 degrees (which no router
  // takes) as its staircase; so, without the cut of pins with 45-degree edges, is such a pin that
  // meets the grown blockages
  auto clear_of_grown = [&](const Polygon& part) {
    std::vector<Index::Entry> near;
    ix.grown.tree.query(bgi::intersects(box_of(part.outer)), std::back_inserter(near));
    return std::none_of(near.begin(), near.end(),
                        [&](const Index::Entry& e) { return shape_meets_obstacle(part, ix.grown.polys[e.second]); });
  };
  auto blockages_under = [&](const Polygon& pin) {
    std::vector<Index::Entry> near;
    ix.plain.tree.query(bgi::intersects(box_of(pin.outer)), std::back_inserter(near));
    std::vector<Polygon> out;
    for (const Index::Entry& e : near)
      if (shape_meets_obstacle(pin, ix.plain.polys[e.second])) out.push_back(ix.plain.polys[e.second]);
    return out;
  };
  for (std::size_t n = 0; n < nets_.size(); ++n)
    for (std::size_t k = 0; k < nets_[n].pins.size(); ++k) {
      const Polygon& pin = nets_[n].pins[k];
      if (is_point_pin(pin)) continue;
      const std::vector<Polygon> under = blockages_under(pin);
      if (under.empty() && pin_shape_supported(pin) && (cut_shapes_ || a_ == 0 || is_pad(pin, false) || clear_of_grown(pin)))
        continue;
      // (a part of a pin too thin for one staircase: one clear of the grown blockages, when one is)
      std::optional<Polygon> st = pad_staircase(pin, rules.scale, clear_of_grown, under);
      if (!st) continue;
      NetPins& reached = reach_.try_emplace(n, nets_[n]).first->second;
      reached.pins[k] = std::move(*st);
    }
}

std::vector<Polygon> NetSpace::wire_union(const Lines& wires) const {
  std::vector<Polygon> grown;
  for (const auto& w : wires) for_segments(w, [&](Point p, Point q) { grown.push_back(Polygon{grown_segment(p, q, b_), {}}); });
  if (grown.empty()) return {};
  return geom::normalize_obstacles(grown, domain_).obstacles;
}

void NetSpace::set_wires(std::size_t net, const Lines& wires, std::optional<std::vector<Polygon>> unioned) {
  Index& ix = *index_;
  for (std::size_t k = 0; k < ix.wire_pieces[net].size(); ++k)
    ix.wire_tree.remove(Index::WireEntry{box_of(ix.wire_pieces[net][k]), {net, k}});
  for (std::size_t k = 0; k < ix.wire_union[net].size(); ++k)
    ix.union_tree.remove(Index::WireEntry{box_of(ix.wire_union[net][k].outer), {net, k}});
  ix.wire_pieces[net].clear();
  ix.wire_union[net].clear();
  for (const auto& w : wires)
    for_segments(w, [&](Point p, Point q) {
      Ring g = grown_segment(p, q, b_);
      ix.wire_tree.insert(Index::WireEntry{box_of(g), {net, ix.wire_pieces[net].size()}});
      ix.wire_pieces[net].push_back(std::move(g));
    });
  ix.wire_union[net] = unioned ? std::move(*unioned) : wire_union(wires);
  for (std::size_t k = 0; k < ix.wire_union[net].size(); ++k)
    ix.union_tree.insert(Index::WireEntry{box_of(ix.wire_union[net][k].outer), {net, k}});
}

geom::NormalizedObstacles NetSpace::obstacles(std::size_t net, NetSpaceLevel level, std::optional<geom::Box> window,
                                              std::span<const char> only, bool framed,
                                              const WireOverlay* overlay) const {
  const Index& ix = *index_;
  const Box dom = window ? clipped(*window, domain_) : domain_;
  const bool plain = level == NetSpaceLevel::Plain;
  if (plain && dom == domain_) {  // the blockages as they are
    geom::NormalizedObstacles n;
    n.domain = domain_;
    n.obstacles = ix.plain.polys;
    return n;
  }
  // The other nets' pieces in the window (the dynamic part), where they are kept (the union
  // reads them there: copied, they cost a tenth of the window's union).
  std::vector<const Polygon*> dynamic;
  std::vector<Box> dynamic_boxes;
  if (level == NetSpaceLevel::Pins || level == NetSpaceLevel::Full) {
    std::vector<Index::Entry> found;
    ix.tree.query(bgi::intersects(dom), std::back_inserter(found));
    std::sort(found.begin(), found.end(), [](const Index::Entry& x, const Index::Entry& y) { return x.second < y.second; });
    for (const auto& [box, id] : found) {
      const Index::Piece& pc = ix.pieces[id];
      if ((pc.kind == Index::GrownPin || pc.kind == Index::ShapePin) && pc.owner != net) {
        dynamic.push_back(&pc.poly);
        dynamic_boxes.push_back(box);
      }
    }
  }
  if (level == NetSpaceLevel::Full) {
    std::vector<Index::WireEntry> wf;
    ix.union_tree.query(bgi::intersects(dom), std::back_inserter(wf));
    if (overlay) {  // its nets' pieces instead, in the same order as if they were in the space
      std::erase_if(wf, [&](const Index::WireEntry& e) { return overlay->find(e.second.first) != nullptr; });
      for (const WireOverlay::Entry& e : overlay->entries)
        for (std::size_t j = 0; j < e.wire_union.size(); ++j)
          if (const Box b = box_of(e.wire_union[j].outer); boxes_meet(b, dom)) wf.push_back({b, {e.net, j}});
    }
    std::sort(wf.begin(), wf.end(), [](const Index::WireEntry& x, const Index::WireEntry& y) { return x.second < y.second; });
    for (const auto& [box, id] : wf)
      if (id.first != net && (only.empty() || only[id.first])) {
        const std::vector<Polygon>* o = overlay ? overlay->find(id.first) : nullptr;
        dynamic.push_back(o ? &(*o)[id.second] : &ix.wire_union[id.first][id.second]);
        dynamic_boxes.push_back(box);
      }
  }
  bgi::rtree<Index::Entry, bgi::rstar<16>> dyn_tree;
  {
    std::vector<Index::Entry> e;
    for (std::size_t i = 0; i < dynamic_boxes.size(); ++i) e.push_back({dynamic_boxes[i], i});
    dyn_tree = decltype(dyn_tree)(e.begin(), e.end());
  }
  // The net's own point pins' access squares, cut out of the grown blockage edges.
  // And the net's own rectangular shape pins (pads), cut out of them too: a pad is free space
  // for its net (FORMAT.md), so a pad on a blockage's edge is reached from outside the grown
  // blockage; the wire keeps the clearance up to its end on the pad.
  // (A pad that is not a rectangle, when cut_shapes_: its box, and the corner triangles its
  // 45-degree edges cut off it, geom::convex_minus_pad; access_ring holds its ring.)
  std::vector<Box> access;
  std::vector<Ring> access_ring;  // per access box: empty, or the pad's ring when not a rectangle
  if (!plain) {
    for (const Polygon& pin : reach(net).pins) {
      if (is_point_pin(pin)) {
        access.push_back(geom::grown_box(Box{pin.outer[0], pin.outer[0]}, access_));
        access_ring.emplace_back();
      } else if (is_rectangle(pin)) {
        access.push_back(box_of(pin.outer));
        access_ring.emplace_back();
      } else if (is_pad(pin, cut_shapes_)) {
        for (Ring& piece : pad_pieces(pin)) {  // (a concave pad: one box per convex piece)
          access.push_back(box_of(piece));
          access_ring.push_back(std::move(piece));
        }
      }
    }
  }
  // The static components in the window: passed through as they are when they lie inside it and
  // meet nothing else; otherwise unioned again with the dynamic pieces (those an access square
  // meets from the pieces they came from, cut).
  const Index::Components& comps = plain ? ix.plain : ix.grown;
  std::vector<Index::Entry> found;
  comps.tree.query(bgi::intersects(dom), std::back_inserter(found));
  std::sort(found.begin(), found.end(), [](const Index::Entry& x, const Index::Entry& y) { return x.second < y.second; });
  std::vector<char> cut(found.size(), 0);
  std::vector<Box> cut_boxes;
  for (std::size_t f = 0; f < found.size(); ++f)
    for (const Box& sq : access)
      if (boxes_meet(found[f].first, sq)) {
        cut[f] = 1;
        cut_boxes.push_back(found[f].first);
        break;
      }
  std::deque<Polygon> made;  // the pieces made here (cut, framed): `rest` points into it too
  std::vector<const Polygon*> rest = std::move(dynamic), pass;
  for (std::size_t f = 0; f < found.size(); ++f) {
    const auto& [box, c] = found[f];
    if (cut[f]) {
      for (const std::size_t id : comps.sources[c]) {
        const Index::Piece& pc = ix.pieces[id];
        if (pc.kind != Index::GrownEdge) {
          rest.push_back(&pc.poly);
          continue;
        }
        std::vector<Ring> cur{pc.poly.outer};
        const Box pb = box_of(pc.poly.outer);
        for (std::size_t k = 0; k < access.size(); ++k) {
          const Box& sq = access[k];
          if (!(sq.lo.x < pb.hi.x && pb.lo.x < sq.hi.x && sq.lo.y < pb.hi.y && pb.lo.y < sq.hi.y)) continue;
          std::vector<Ring> next;
          for (const Ring& r : cur)
            for (Ring& part : access_ring[k].empty() ? geom::convex_minus_box(r, sq) : geom::convex_minus_pad(r, access_ring[k]))
              next.push_back(std::move(part));
          cur = std::move(next);
        }
        for (Ring& r : cur) rest.push_back(&made.emplace_back(Polygon{std::move(r), {}}));
      }
      continue;
    }
    // (framed: a component on a side of the window joins the frame in the union)
    bool alone = (framed ? box_strictly_inside(box, dom) : box_inside(box, dom)) &&
                 dyn_tree.qbegin(bgi::intersects(box)) == dyn_tree.qend();
    for (std::size_t k = 0; k < cut_boxes.size() && alone; ++k) alone = !boxes_meet(box, cut_boxes[k]);
    (alone ? pass : rest).push_back(&comps.polys[c]);
  }
  // Passed-through components must be disjoint from everything else. They meet no other piece's
  // box (components of one union never touch), but the union of the rest rounds sloped crossings
  // outward (geom/normalize.h), and that growth may enter a passed component whose box meets the
  // box of a component in the rest (random seed 901347: a grown pin square on a thin triangle's
  // corner swung its long edge over the next triangle's vertex, 0.04 away; the wavefront then
  // threw on the overlap). So a passed component whose box meets an obstacle of the union's
  // output joins the rest, and the union is made again, until none does (disjoint closed boxes:
  // disjoint sets). Almost always one pass.
  // (First, what lies beyond the window's sides does not count, geom::cut_beyond: on 3,000
  // planted nets the pieces that cross a side carried a fifth of the union's input vertices, and
  // the cut removes 7 % of all of them. Then the union and its loop.)
  for (const Polygon*& p : rest) {
    if (geom::cut_leaves(*p, dom)) continue;
    Polygon c = *p;
    p = geom::cut_beyond(c, dom) ? &made.emplace_back(std::move(c)) : nullptr;
  }
  std::erase(rest, nullptr);
  // framed: the frame lies in the box one unit larger (what the cut left beyond the window's
  // sides joins it there), and the union is clipped to that box
  const Box clip = framed ? Box{{dom.lo.x - 1, dom.lo.y - 1}, {dom.hi.x + 1, dom.hi.y + 1}} : dom;
  if (framed) rest.push_back(&made.emplace_back(geom::domain_frame(dom)));
  geom::NormalizedObstacles out;
  for (;;) {
    out = geom::normalize_obstacle_refs(rest, clip);
    // nothing rounded: the union is exactly the rest's, which no passed component meets
    if (pass.empty() || out.stats.rounded == 0) break;
    std::vector<Index::Entry> ob;
    ob.reserve(out.obstacles.size());
    for (std::size_t i = 0; i < out.obstacles.size(); ++i) ob.push_back({box_of(out.obstacles[i].outer), i});
    const bgi::rtree<Index::Entry, bgi::rstar<16>> out_tree(ob.begin(), ob.end());
    std::vector<const Polygon*> apart;
    const std::size_t before = rest.size();
    for (const Polygon* p : pass)
      (out_tree.qbegin(bgi::intersects(box_of(p->outer))) == out_tree.qend() ? apart : rest).push_back(p);
    pass = std::move(apart);
    if (rest.size() == before) break;
  }
  for (const Polygon* p : pass) out.obstacles.push_back(*p);
  std::sort(out.obstacles.begin(), out.obstacles.end(),
            [](const Polygon& x, const Polygon& y) { return x.outer[0] < y.outer[0]; });
  out.sources.clear();
  out.domain = dom;
  return out;
}

namespace {
// The nets (other than `net`) with a grown wire piece that `meets` a segment of the line.
template <class Index, class Meets>
std::vector<std::size_t> nets_met(const Index& ix, std::size_t net, std::span<const Point> line, Meets meets) {
  std::set<std::size_t> out;
  for_segments(line, [&](Point p, Point q) {
    const Point pq[2] = {p, q};
    std::vector<typename Index::WireEntry> wf;
    ix.wire_tree.query(bgi::intersects(box_of(pq)), std::back_inserter(wf));
    for (const auto& [box, id] : wf)
      if (id.first != net && !out.count(id.first) && meets(p, q, ix.wire_pieces[id.first][id.second])) out.insert(id.first);
  });
  return {out.begin(), out.end()};
}
}  // namespace

bool NetSpace::keeps_blockage_clearance(Point p) const {
  const Index& ix = *index_;
  const Box at{p, p};
  if (!box_inside(at, domain_)) return false;
  auto inside = [&](const Polygon& poly) { return geom::locate(p, poly) == geom::Location::Inside; };
  std::vector<Index::Entry> found;
  // the blockages within K a (those in a component of the grown blockages' union holding p; the
  // union is cut at the domain's sides, so found by box)
  const i128 r = i128{rule_a_} * scale_;
  auto far_from = [&](const Ring& ring) {  // |p - ab| >= r for every edge ab, exactly
    for (std::size_t i = 0; i < ring.size(); ++i) {
      // (coordinates within 2^30 and r within 2^31: r^2 den fits)
      const geom::SquaredDistance d = geom::point_segment_distance2(p, ring[i], ring[(i + 1) % ring.size()]);
      if (d.num < r * r * d.den) return false;
    }
    return true;
  };
  if (r > 0) {
    const i128 reach = std::min<i128>(r, geom::kMaxCoord);
    ix.grown.tree.query(bgi::intersects(geom::grown_box(at, static_cast<std::int64_t>(reach))), std::back_inserter(found));
    for (const auto& [box, c] : found)
      for (const std::size_t id : ix.grown.sources[c]) {
        const Index::Piece& piece = ix.pieces[id];
        if (piece.kind != Index::Blockage) continue;
        if (inside(piece.poly) || !far_from(piece.poly.outer)) return false;
        for (const Ring& h : piece.poly.holes)
          if (!far_from(h)) return false;
      }
  } else {
    ix.grown.tree.query(bgi::intersects(at), std::back_inserter(found));
    for (const auto& [box, c] : found)
      if (inside(ix.grown.polys[c])) return false;
  }
  return true;
}

bool NetSpace::keeps_clearance(std::size_t net, Point p, std::span<const char> only, const WireOverlay* overlay) const {
  if (!keeps_blockage_clearance(p)) return false;
  const Index& ix = *index_;
  const Box at{p, p};
  const bool on_side = !box_strictly_inside(at, domain_);
  auto inside = [&](const Polygon& poly) { return geom::locate(p, poly) == geom::Location::Inside; };
  std::vector<Index::Entry> found;
  ix.tree.query(bgi::intersects(at), std::back_inserter(found));
  for (const auto& [box, id] : found)
    if (ix.pieces[id].owner != net && inside(ix.pieces[id].poly)) return false;
  std::vector<Index::WireEntry> wf;
  ix.wire_tree.query(bgi::intersects(at), std::back_inserter(wf));
  auto seen = [&](std::size_t n) { return n != net && (only.empty() || only[n]); };
  for (const auto& [box, id] : wf)
    if (seen(id.first) && !(overlay && overlay->find(id.first)) && inside(Polygon{ix.wire_pieces[id.first][id.second], {}}))
      return false;
  if (overlay)  // (its unions are cut at the domain's sides too: there a boundary point counts as inside)
    for (const WireOverlay::Entry& e : overlay->entries)
      if (seen(e.net))
        for (const Polygon& u : e.wire_union)
          if (boxes_meet(box_of(u.outer), at)) {
            const geom::Location l = geom::locate(p, u);
            if (l == geom::Location::Inside || (on_side && l == geom::Location::Boundary)) return false;
          }
  return true;
}

std::vector<Point> NetSpace::clearance_candidates(std::size_t net, const Polygon& pin, const WireOverlay* overlay,
                                                  bool with_wires) const {
  const Index& ix = *index_;
  const Box pb = box_of(pin.outer);
  std::vector<Point> out(pin.outer.begin(), pin.outer.end());
  // where the circle of radius K a round a blockage vertex c crosses a horizontal or vertical edge
  // of the pin: the integers next to c.x +- sqrt(r^2 - dy^2) (or in y)
  const i128 r = i128{rule_a_} * scale_;
  auto isqrt = [](i128 v) {  // floor(sqrt(v)), v >= 0
    i128 x = static_cast<i128>(std::sqrt(static_cast<long double>(v)));
    while (x > 0 && x * x > v) --x;
    while ((x + 1) * (x + 1) <= v) ++x;
    return x;
  };
  auto add_circle = [&](Point c) {
    for (std::size_t j = 0; j < pin.outer.size(); ++j) {
      const Point u = pin.outer[j], v = pin.outer[(j + 1) % pin.outer.size()];
      if (u.x != v.x && u.y != v.y) continue;
      const bool horizontal = u.y == v.y;
      const i128 d = horizontal ? i128{u.y} - c.y : i128{u.x} - c.x;
      if (d * d > r * r) continue;
      const i128 h = isqrt(r * r - d * d), m = horizontal ? c.x : c.y;
      for (const i128 t : {m - h - 1, m - h, m + h, m + h + 1}) {
        const Point q = horizontal ? Point{static_cast<geom::Coord>(std::clamp<i128>(t, -geom::kMaxCoord, geom::kMaxCoord)), u.y}
                                   : Point{u.x, static_cast<geom::Coord>(std::clamp<i128>(t, -geom::kMaxCoord, geom::kMaxCoord))};
        if (box_inside(Box{q, q}, pb)) out.push_back(q);
      }
    }
  };
  auto add_ring = [&](const Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point a = r[i], b = r[(i + 1) % r.size()];
      if (box_inside(Box{a, a}, pb)) out.push_back(a);
      if (!boxes_meet(Box{{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}}, pb)) continue;
      for (std::size_t j = 0; j < pin.outer.size(); ++j) {
        const geom::Segment s{a, b}, t{pin.outer[j], pin.outer[(j + 1) % pin.outer.size()]};
        if (geom::intersect(s, t) != geom::SegmentIntersection::Proper) continue;  // (a touch is at a vertex)
        const geom::RationalPoint c = geom::line_intersection(s, t);
        for (const geom::i128 x : {geom::floor_div(c.x_num, c.den), geom::ceil_div(c.x_num, c.den)})
          for (const geom::i128 y : {geom::floor_div(c.y_num, c.den), geom::ceil_div(c.y_num, c.den)})
            out.push_back({static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)});
      }
    }
  };
  auto add = [&](const Polygon& poly) {
    if (!boxes_meet(box_of(poly.outer), pb)) return;
    add_ring(poly.outer);
    for (const Ring& h : poly.holes) add_ring(h);
  };
  std::vector<Index::Entry> found;
  ix.grown.tree.query(bgi::intersects(pb), std::back_inserter(found));
  for (const auto& [box, c] : found) {
    add(ix.grown.polys[c]);
    for (const std::size_t id : ix.grown.sources[c]) {
      add(ix.pieces[id].poly);
      if (ix.pieces[id].kind == Index::Blockage && r > 0)
        for (const Point v : ix.pieces[id].poly.outer) add_circle(v);
    }
  }
  found.clear();
  ix.tree.query(bgi::intersects(pb), std::back_inserter(found));
  for (const auto& [box, id] : found)
    if (ix.pieces[id].owner != net) add(ix.pieces[id].poly);
  if (!with_wires) {
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  std::vector<Index::WireEntry> wf;
  ix.wire_tree.query(bgi::intersects(pb), std::back_inserter(wf));
  for (const auto& [box, id] : wf)
    if (id.first != net) add_ring(ix.wire_pieces[id.first][id.second]);
  if (overlay)
    for (const WireOverlay::Entry& e : overlay->entries)
      if (e.net != net)
        for (const Polygon& u : e.wire_union) add(u);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::size_t> NetSpace::wire_blockers(std::size_t net, std::span<const Point> line) const {
  return nets_met(*index_, net, line, segment_enters);
}

std::vector<std::size_t> NetSpace::wire_touchers(std::size_t net, std::span<const Point> line) const {
  return nets_met(*index_, net, line, segment_touches);
}

std::vector<std::size_t> NetSpace::wire_nets_in(const Box& window) const {
  std::vector<Index::WireEntry> wf;
  index_->union_tree.query(bgi::intersects(clipped(window, domain_)), std::back_inserter(wf));
  std::vector<std::size_t> out;
  for (const auto& [box, id] : wf) out.push_back(id.first);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

geom::NormalizedObstacles NetSpace::superset_obstacles(bool with_wires) const {
  const Index& ix = *index_;
  std::vector<Index::Entry> acc;  // every net's pin access: the boxes its obstacles() may cut
  for (const NetPins& n : nets_)
    for (const Polygon& pin : n.pins)
      acc.push_back({is_point_pin(pin) ? geom::grown_box(Box{pin.outer[0], pin.outer[0]}, access_) : box_of(pin.outer), acc.size()});
  const bgi::rtree<Index::Entry, bgi::rstar<16>> acc_tree(acc.begin(), acc.end());
  auto near_pin = [&](const Box& b) { return acc_tree.qbegin(bgi::intersects(b)) != acc_tree.qend(); };
  std::vector<Polygon> rest;
  for (std::size_t c = 0; c < ix.grown.polys.size(); ++c) {
    if (!near_pin(box_of(ix.grown.polys[c].outer))) {
      rest.push_back(ix.grown.polys[c]);
      continue;
    }
    for (const std::size_t id : ix.grown.sources[c]) {  // without the grown edges near a pin
      const Index::Piece& pc = ix.pieces[id];
      if (pc.kind != Index::GrownEdge || !near_pin(box_of(pc.poly.outer))) rest.push_back(pc.poly);
    }
  }
  if (with_wires)
    for (const auto& pieces : ix.wire_union) rest.insert(rest.end(), pieces.begin(), pieces.end());
  return framed_whole(std::move(rest));
}

geom::NormalizedObstacles NetSpace::plain_obstacles_framed() const { return framed_whole(index_->plain.polys); }

geom::NormalizedObstacles NetSpace::framed_whole(std::vector<Polygon> obstacles) const {
  obstacles.push_back(geom::domain_frame(domain_));
  geom::NormalizedObstacles out =
      geom::normalize_obstacles(obstacles, Box{{domain_.lo.x - 1, domain_.lo.y - 1}, {domain_.hi.x + 1, domain_.hi.y + 1}});
  out.domain = domain_;
  return out;
}

std::vector<Box> NetSpace::wire_boxes(std::size_t net) const {
  std::vector<Box> out;
  for (const Polygon& p : index_->wire_union[net]) out.push_back(box_of(p.outer));
  return out;
}

std::vector<Box> NetSpace::removed_boxes(const Lines& before, const Lines& after, std::optional<std::size_t> net) const {
  std::vector<Box> out;
  // What the others see is the union of the grown segments, which rounds sloped crossings outward
  // (geom/normalize.h): with a sloped segment in `before`, that growth may be freed too, so the
  // boxes of the whole union count, as before 2026-12-05 (axis-parallel pieces cross at lattice
  // points: nothing rounded).
  bool sloped = false;
  for (const auto& w : before)
    for (std::size_t j = 0; j + 1 < w.size(); ++j) sloped = sloped || (w[j].x != w[j + 1].x && w[j].y != w[j + 1].y);
  if (sloped) {
    const std::vector<Polygon> u = net ? index_->wire_union[*net] : wire_union(before);
    for (const Polygon& p : u) out.push_back(box_of(p.outer));
    return out;
  }
  for (const auto& [p, q] : uncovered_segments(before, after)) out.push_back(box_of(grown_segment(p, q, b_)));
  // A piece clamped at the coordinate limits (grown_segment) is a box, not the neighbourhood: its
  // part beyond the neighbourhood may be covered by nothing of `after`, so every piece of
  // `before` that was clamped counts as removed.
  for (const auto& w : before)
    for_segments(w, [&](Point p, Point q) {
      const std::int64_t r = b_;
      if (!geom::in_range(std::min(p.x, q.x) - r) || !geom::in_range(std::max(p.x, q.x) + r) ||
          !geom::in_range(std::min(p.y, q.y) - r) || !geom::in_range(std::max(p.y, q.y) + r))
        out.push_back(box_of(grown_segment(p, q, b_)));
    });
  return out;
}

std::vector<std::pair<Point, Point>> uncovered_segments(const Lines& before, const Lines& after) {
  std::vector<std::pair<Point, Point>> segs;
  std::vector<std::pair<Box, std::size_t>> entries;
  for (const auto& w : after)
    for_segments(w, [&](Point p, Point q) {
      const Point pq[2] = {p, q};
      entries.push_back({box_of(pq), segs.size()});
      segs.push_back({p, q});
    });
  const bgi::rtree<std::pair<Box, std::size_t>, bgi::rstar<16>> tree(entries.begin(), entries.end());
  std::vector<std::pair<Box, std::size_t>> hits;
  std::vector<std::pair<i128, i128>> cover;
  std::vector<std::pair<Point, Point>> out;
  for (const auto& w : before)
    for_segments(w, [&](Point p, Point q) {
      const Point pq[2] = {p, q};
      hits.clear();
      tree.query(bgi::intersects(box_of(pq)), std::back_inserter(hits));
      const i128 dx = i128{q.x} - p.x, dy = i128{q.y} - p.y, len = dx * dx + dy * dy;
      cover.clear();
      for (const auto& [box, k] : hits) {
        const auto& [a, b] = segs[k];
        // a and b on the line of pq (for p = q: the segment ab through p)
        if (len == 0) {
          const i128 ux = i128{b.x} - a.x, uy = i128{b.y} - a.y;
          if (ux * (i128{p.y} - a.y) - uy * (i128{p.x} - a.x) == 0) {  // p on ab's line, and in its box (the query)
            cover.push_back({0, 0});
            break;
          }
          continue;
        }
        if (dx * (i128{a.y} - p.y) - dy * (i128{a.x} - p.x) != 0 || dx * (i128{b.y} - p.y) - dy * (i128{b.x} - p.x) != 0)
          continue;
        const i128 ta = dx * (i128{a.x} - p.x) + dy * (i128{a.y} - p.y), tb = dx * (i128{b.x} - p.x) + dy * (i128{b.y} - p.y);
        cover.push_back({std::min(ta, tb), std::max(ta, tb)});
      }
      bool covered;
      if (len == 0) {
        covered = !cover.empty();
      } else {
        std::sort(cover.begin(), cover.end());
        i128 at = 0;  // [0, at] covered
        bool gap = false;
        for (const auto& [lo, hi] : cover) {
          if (lo > at) {
            gap = true;
            break;
          }
          at = std::max(at, hi);
          if (at >= len) break;
        }
        covered = !gap && at >= len;
      }
      if (!covered) out.push_back({p, q});
    });
  return out;
}

std::vector<std::size_t> NetSpace::pad_blockers(std::size_t net) const {
  const Index& ix = *index_;
  std::set<std::size_t> out;
  for (const Polygon& pin : nets_[net].pins) {
    if (is_point_pin(pin)) continue;
    const Box pb = box_of(pin.outer);
    const bool rect = is_rectangle(pin);
    const Ring hull = geom::convex_hull(pin.outer);
    std::vector<Index::WireEntry> wf;
    ix.wire_tree.query(bgi::intersects(pb), std::back_inserter(wf));
    for (const auto& [box, id] : wf)
      if (id.first != net && (!rect || convex_interiors_meet(ix.wire_pieces[id.first][id.second], hull)))
        out.insert(id.first);
  }
  return {out.begin(), out.end()};
}

std::vector<std::size_t> NetSpace::pin_blockers(std::size_t net, std::span<const Point> line) const {
  const Index& ix = *index_;
  std::set<std::size_t> out;
  if (line.empty()) return {};
  for_segments(line, [&](Point p, Point q) {
    const Point pq[2] = {p, q};
    std::vector<Index::Entry> found;
    ix.tree.query(bgi::intersects(box_of(pq)), std::back_inserter(found));
    for (const auto& [box, id] : found) {
      const Index::Piece& pc = ix.pieces[id];
      if (pc.kind == Index::GrownPin && pc.owner != net && !out.count(pc.owner) && segment_enters(p, q, pc.poly.outer))
        out.insert(pc.owner);
    }
  });
  return {out.begin(), out.end()};
}

namespace {

// The scale of NetRouterOptions::exact_gaps: the largest power of two K <= 2^13 with K x (the
// domain's reach + a + b) <= 2^29, or 1 when that leaves none of at least 8.
std::int64_t gap_scale(const Box& domain, const NetRules& rules) {
  const std::int64_t reach = std::max({std::abs(std::int64_t{domain.lo.x}), std::abs(std::int64_t{domain.lo.y}),
                                       std::abs(std::int64_t{domain.hi.x}), std::abs(std::int64_t{domain.hi.y})}) +
                              blockage_rule(rules) + net_rule(rules);
  std::int64_t k = 1;
  while (k < (std::int64_t{1} << 13) && 2 * k * reach <= (std::int64_t{1} << 29)) k *= 2;
  return k >= 8 ? k : 1;
}

// Whether every edge of the blockages and of the shape pins is horizontal, vertical or at 45
// degrees (pin_shape_supported's test, which normalized blockages pass as shapes): exact_gaps's
// snapping is sound only then (a wire vertex beside a sloped edge can lie anywhere between
// multiples of the scale, and snapping would move it into the clearance).
bool octilinear_edges(std::span<const Polygon> obstacles, std::span<const NetPins> nets) {
  if (!std::all_of(obstacles.begin(), obstacles.end(), [](const Polygon& p) { return pin_shape_supported(p); })) return false;
  for (const NetPins& n : nets)
    if (!std::all_of(n.pins.begin(), n.pins.end(), [](const Polygon& p) { return pin_shape_supported(p); })) return false;
  return true;
}

// NetRouter::scale(): gap_scale when exact_gaps applies, kept low enough that the bend cost
// times it stays within BendRouter's 2^31 under Combined; 1 when that leaves none of at least 8.
std::int64_t router_scale(const Box& domain, std::span<const Polygon> obstacles, std::span<const NetPins> nets,
                          const NetRules& rules, const NetRouterOptions& options) {
  if (!options.exact_gaps) return 1;
  std::int64_t k = exact_gaps_scale(domain, obstacles, nets, rules);
  if (options.cost == NetRouterOptions::Cost::Combined)
    while (k > 1 && options.bend_cost > 0 && options.bend_cost > (std::int64_t{1} << 31) / k) k /= 2;
  return k >= 8 ? k : 1;
}

}  // namespace

Point scaled(Point p, std::int64_t k) {
  return Point{static_cast<geom::Coord>(p.x * k), static_cast<geom::Coord>(p.y * k)};
}
Polygon scaled(const Polygon& poly, std::int64_t k) {
  Polygon out = poly;
  for (Point& p : out.outer) p = scaled(p, k);
  for (Ring& h : out.holes)
    for (Point& p : h) p = scaled(p, k);
  return out;
}
std::vector<Polygon> scaled(std::span<const Polygon> polys, std::int64_t k) {
  std::vector<Polygon> out;
  out.reserve(polys.size());
  for (const Polygon& p : polys) out.push_back(scaled(p, k));
  return out;
}
std::vector<NetPins> scaled(std::vector<NetPins> nets, std::int64_t k) {
  for (NetPins& n : nets) {
    for (Polygon& p : n.pins) p = scaled(p, k);
    n.scale = k;
  }
  return nets;
}
Lines scaled_wires(Lines wires, std::int64_t k) {
  for (auto& w : wires)
    for (Point& p : w) p = scaled(p, k);
  return wires;
}
NetRules with_scale(NetRules r, std::int64_t k) {
  r.scale = k;
  return r;
}

// (try_net counts a wire with a vertex k/4 or more from its multiple, NetRouterStats::snap_far,
// so halves never pass unnoticed.)
geom::Coord snapped(geom::Coord v, std::int64_t k) {
  const std::int64_t x = v, h = k / 2;
  const std::int64_t q = x >= 0 ? (x + h) / k : -((-x + h) / k);
  return static_cast<geom::Coord>(q * k);
}

geom::Root2 oct_length(const Lines& wires) {
  geom::Root2 n{0, 0};
  for (const auto& w : wires)
    for (std::size_t i = 0; i + 1 < w.size(); ++i)
      n = n + geom::octilinear_length(std::int64_t{w[i + 1].x} - w[i].x, std::int64_t{w[i + 1].y} - w[i].y);
  return n;
}

std::int64_t exact_gaps_scale(const Box& domain, std::span<const Polygon> obstacles, std::span<const NetPins> nets,
                              const NetRules& rules, bool any_angle) {
  return any_angle || octilinear_edges(obstacles, nets) ? gap_scale(domain, rules) : 1;
}

namespace {
// The pins in groups that meet: joined pair by pair at points they share on the lattice of
// multiples of k_lattice (router::shared_point), each group's pins in increasing order, the groups
// in the order of their first pin.
std::vector<std::vector<std::size_t>> pin_groups(const NetPins& pins, std::int64_t k_lattice) {
  const std::size_t k = pins.pins.size();
  std::vector<std::vector<std::size_t>> out;
  if (std::all_of(pins.pins.begin(), pins.pins.end(), [](const Polygon& g) { return g.outer.size() == 1; }) &&
      std::any_of(pins.pins.begin(), pins.pins.end(), [&](const Polygon& g) { return g.outer[0] != pins.pins[0].outer[0]; })) {
    // point pins apart (the common case, decided without the pairs): each its own group, unless
    // two share their point
    std::map<Point, std::size_t> at;
    for (std::size_t i = 0; i < k; ++i) {
      const auto [it, fresh] = at.try_emplace(pins.pins[i].outer[0], out.size());
      if (fresh) out.emplace_back();
      out[it->second].push_back(i);
    }
    return out;
  }
  std::vector<std::size_t> rank(k), parent(k);
  boost::disjoint_sets<std::size_t*, std::size_t*> groups(rank.data(), parent.data());
  for (std::size_t i = 0; i < k; ++i) groups.make_set(i);
  auto lattice = [&](Point q) { return on_lattice(q, k_lattice); };
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j) {
      if (groups.find_set(i) == groups.find_set(j)) continue;
      const Polygon &a = pins.pins[i], &b = pins.pins[j];
      if (!geom::boxes_meet(box_of(a.outer), box_of(b.outer))) continue;
      if (shared_point(a.outer, a, b.outer, b, lattice)) groups.union_set(i, j);
    }
  std::map<std::size_t, std::size_t> index;  // a group's root -> its place in out
  for (std::size_t i = 0; i < k; ++i) {
    const auto [it, fresh] = index.try_emplace(groups.find_set(i), out.size());
    if (fresh) out.emplace_back();
    out[it->second].push_back(i);
  }
  return out;
}
}  // namespace


NetRouter::NetRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles, std::vector<NetPins> nets,
                     NetRules rules, NetRouterOptions options)
    : scale_(router_scale(domain, obstacles, nets, rules, options)),
      space_(Box{scaled(domain.lo, scale_), scaled(domain.hi, scale_)}, scaled(obstacles, scale_),
             scaled(std::move(nets), scale_), with_scale(rules, scale_)),
      options_(options) {
  options_.bend_cost *= scale_;  // lengths are scale_ times (router_scale keeps it <= 2^31)
  joined_.resize(space_.size());
  groups_.resize(space_.size());
  for (std::size_t i = 0; i < space_.size(); ++i) {
    std::vector<std::vector<std::size_t>> g = pin_groups(space_.reach(i), scale_);
    const std::size_t k = space_.reach(i).pins.size();
    joined_[i] = k >= 2 && g.size() == 1;
    if (g.size() > 1 && g.size() < k) groups_[i] = std::move(g);
  }
  covers_pins_ = rules.cover_pieces > 0;
  for (std::size_t i = 0; i < space_.size() && rectilinear_pins_; ++i)
    for (const Polygon& pin : space_.net(i).pins) rectilinear_pins_ = rectilinear_pins_ && is_rectilinear_shape(pin);
  if (options_.cost == NetRouterOptions::Cost::Length) return;
  // the bend-aware router takes rectilinear obstacles only (see the header)
  if (rules.cover_pieces <= 0) throw std::invalid_argument("NetRouter: a bend-aware cost needs NetRules::cover_pieces > 0");
  for (const Polygon& p : obstacles) {
    std::vector<const geom::Ring*> rings{&p.outer};
    for (const geom::Ring& h : p.holes) rings.push_back(&h);
    for (const geom::Ring* r : rings)
      for (std::size_t i = 0; i < r->size(); ++i) {
        const Point a = (*r)[i], b = (*r)[(i + 1) % r->size()];
        if (a.x != b.x && a.y != b.y)
          throw std::invalid_argument("NetRouter: a bend-aware cost needs rectilinear blockages (router::rectilinear_cover)");
      }
  }
}

namespace {

// Proof that point pins are apart in the whole domain from their space clipped to window w: some
// pin's free component in the window reaches neither another pin nor the window's sides inside
// the domain (a way out would cross a side). The component touches a side iff the wave from the
// pin reaches a vertex on it (a window corner, or where an obstacle meets the side: the ends of
// every stretch of side the component touches). Two runs per pin: the first has the side
// vertices as targets and stops at the first it labels (Stop::FirstTarget: a component that
// touches a side is known as soon as one is reached; one that does not is run to its end, as
// nothing stops it, so no side vertex of it is missed); only for a component that reaches no
// side, a second run with the pins as targets, which never stops, says which pins it holds.
// (The first run has then labelled the same component, but not the pins, which are no targets
// of it; it is rare: the 10^4 planted row spends 9.7 s in all outside the timed phases.)
bool apart_in_window(const geom::NormalizedObstacles& obs, const NetPins& pins, const Box& w) {
  std::vector<Point> pts;
  for (const Polygon& pin : pins.pins) {
    if (!is_point_pin(pin)) return false;
    pts.push_back(pin.outer[0]);
  }
  std::vector<Point> side;  // vertices on the window's boundary
  for (const Point c : {w.lo, w.hi, Point{w.lo.x, w.hi.y}, Point{w.hi.x, w.lo.y}}) side.push_back(c);
  for (const Polygon& poly : obs.obstacles) {
    std::vector<const Ring*> rings{&poly.outer};
    for (const Ring& h : poly.holes) rings.push_back(&h);
    for (const Ring* r : rings)
      for (const Point v : *r)
        if (v.x == w.lo.x || v.x == w.hi.x || v.y == w.lo.y || v.y == w.hi.y) side.push_back(v);
  }
  L1Wavefront wf(obs.domain, obs.obstacles);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!wf.is_free(pts[i])) continue;
    // First whether the component reaches a side: the wave stops at the first side vertex it
    // labels (almost always the answer, and then only the part of the component nearer than
    // that vertex is labelled: run to the end, this took a sixth of the 10^4 planted row);
    // only a component shut in the window is run again to see which pins it holds.
    wf.run(std::span<const Point>(&pts[i], 1), side, WavefrontStop::FirstTarget);
    bool out = false;
    for (std::size_t k = 0; k < side.size(); ++k) out = out || wf.target_distance(k).has_value();
    if (out) continue;
    wf.run(std::span<const Point>(&pts[i], 1), pts, WavefrontStop::Never);
    bool apart = false;
    for (std::size_t j = 0; j < pts.size(); ++j) apart = apart || !wf.target_distance(j);
    if (apart) return true;
  }
  return false;
}

}  // namespace

// The free components of a framed whole-domain space (NetSpace::superset_obstacles): a free
// point's component is the innermost hole ring containing it (the frame's holes, and the holes of
// the obstacles in them: obstacles are disjoint, so the rings containing a point are nested and
// the innermost has the smallest box). A point on one ring only, not at a vertex the ring passes
// twice, is in that hole when the ring is a hole's, and outside it when it is an obstacle's outer
// ring (a way round the obstacle is a way in the hole round it); a point on two rings or at such
// a vertex (a pinch, which no wire passes) is not located, so pins there prove nothing.
struct FreeComponents {
  geom::NormalizedObstacles obs;
  struct R {
    const Ring* ring;
    bool hole;
  };
  std::vector<R> rings;
  bgi::rtree<std::pair<Box, std::size_t>, bgi::rstar<16>> tree;

  explicit FreeComponents(geom::NormalizedObstacles o) : obs(std::move(o)) {
    std::vector<std::pair<Box, std::size_t>> e;
    for (const Polygon& p : obs.obstacles) {
      rings.push_back({&p.outer, false});
      for (const Ring& h : p.holes) rings.push_back({&h, true});
    }
    for (std::size_t i = 0; i < rings.size(); ++i) e.push_back({box_of(*rings[i].ring), i});
    tree = decltype(tree)(e.begin(), e.end());
  }
  // p's component (an index into rings), or nullopt: in an obstacle, or not located (above)
  std::optional<std::size_t> component(Point p) const {
    std::vector<std::pair<Box, std::size_t>> found;
    tree.query(bgi::intersects(Box{p, p}), std::back_inserter(found));
    std::optional<std::size_t> best, on;
    std::int64_t best_area = 0;
    for (const auto& [b, i] : found) {
      const geom::Location loc = geom::locate(p, *rings[i].ring);
      if (loc == geom::Location::Outside) continue;
      if (loc == geom::Location::Boundary) {
        if (on || std::count(rings[i].ring->begin(), rings[i].ring->end(), p) > 1) return std::nullopt;
        on = i;
        continue;
      }
      const std::int64_t area = (std::int64_t{b.hi.x} - b.lo.x) * (std::int64_t{b.hi.y} - b.lo.y);
      if (!best || area < best_area) best = i, best_area = area;
    }
    if (on && rings[*on].hole) return on;
    if (!best || !rings[*best].hole) return std::nullopt;
    return best;
  }
  // Are the net's pins (point pins only) in different components?
  bool apart(const NetPins& pins) const {
    std::optional<std::size_t> first;
    bool all_same = true;
    for (const Polygon& pin : pins.pins) {
      if (!is_point_pin(pin)) return false;
      const auto c = component(pin.outer[0]);
      if (!c) return false;
      if (!first) first = c;
      all_same = all_same && *c == *first;
    }
    return !all_same;
  }
};

// The free components among the grown blockages alone (NetSpace::superset_obstacles without the
// wires), a superset of every net's space at every level but Plain for the whole run, and those
// of the plain blockages (NetSpace::plain_obstacles_framed), the Plain level's space: each built
// once, by the first attempt that needs it (on any thread); nullptr when the union rounded a
// sloped crossing.
struct BlockageParts {
  std::once_flag grown_once, plain_once;
  std::unique_ptr<const FreeComponents> grown, plain;
};

namespace {

// Adds the counts of one attempt (or explanation) to the run's.
void add_counts(NetRouterStats& to, const NetRouterStats& c) {
  to.attempts += c.attempts;
  to.windows += c.windows;
  to.whole += c.whole;
  to.relaxed += c.relaxed;
  to.space_seconds += c.space_seconds;
  to.route_seconds += c.route_seconds;
  to.whole_seconds += c.whole_seconds;
  to.capped += c.capped;
  to.superset_apart += c.superset_apart;
  to.blockages_apart += c.blockages_apart;
  to.group_choices += c.group_choices;
  to.snap_far += c.snap_far;
}

// Calls f(k) for k in [0, n) on up to `threads` threads (the caller's one of them); then rethrows
// the exception of the least k that threw, as calling them in order would have (after a
// NetRouterStopped the rest are not started).
template <class F>
void parallel_for(std::size_t n, int threads, F&& f) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::vector<std::exception_ptr> errors(n);
  auto work = [&] {
    for (std::size_t k; !stop.load() && (k = next.fetch_add(1)) < n;) {
      try {
        f(k);
      } catch (const NetRouterStopped&) {
        errors[k] = std::current_exception();
        stop = true;
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> pool;  // joined when it goes out of scope, also if a thread fails to start
    const std::size_t extra = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(threads, 1))) - (n > 0);
    for (std::size_t t = 0; t < extra; ++t) pool.emplace_back(work);
    work();
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace

NetAttempt NetRouter::attempt(const NetRouteFn& route, std::size_t net, NetSpaceLevel level) {
  Tried t = try_net(route, net, level);
  add_counts(stats_, t.counts);
  return std::move(t.a);
}

namespace {

// The margin of a net's first window round its pins' box hp. Two point pins: half the
// half-perimeter (the proof then keeps any wire up to twice its lower bound, which most are).
// Three or more pins: 1.125 times the greatest L1 gap from the first pin to another (a tree grown
// from the first pin is proven by its radius, NetAttempt::radius, which is at least that gap:
// so trees whose radius is up to an eighth longer are kept; a longer one gets the window it
// needs next, NetRouter::try_net_unsnapped's fit). Until 2026-12-06 1.5 times: on 10^4 planted
// nets (bench_net_router --planted --rounds 0) the first pass's windows then held a third more
// vertices in all, and after the last pass the same nets were routed with the same total
// length (each window's answer is the shortest it proves). Other nets: twice
// the half-perimeter (the proof then needs the whole length inside the margin).
std::int64_t first_margin(const NetPins& pins, const Box& hp, std::int64_t a, std::int64_t b) {
  const std::int64_t hpwl = (std::int64_t{hp.hi.x} - hp.lo.x) + (std::int64_t{hp.hi.y} - hp.lo.y);
  const bool two_points = two_point_pins(pins);
  if (two_points) return hpwl / 2 + 4 * (a + b) + 32;
  if (pins.pins.size() >= 3) {
    const Box s = box_of(pins.pins[0].outer);
    std::int64_t gap = 0;
    for (std::size_t k = 1; k < pins.pins.size(); ++k) {
      const Box t = box_of(pins.pins[k].outer);
      const std::int64_t gx = std::max<std::int64_t>({0, std::int64_t{t.lo.x} - s.hi.x, std::int64_t{s.lo.x} - t.hi.x});
      const std::int64_t gy = std::max<std::int64_t>({0, std::int64_t{t.lo.y} - s.hi.y, std::int64_t{s.lo.y} - t.hi.y});
      gap = std::max(gap, gx + gy);
    }
    return gap + gap / 8 + 4 * (a + b) + 32;
  }
  return 2 * hpwl + 8 * (a + b) + 64;
}

}  // namespace

Box NetRouter::first_window(std::size_t net) const {
  std::vector<Point> pts;
  for (const Polygon& pin : space_.net(net).pins) pts.insert(pts.end(), pin.outer.begin(), pin.outer.end());
  const Box& dom = space_.domain();
  if (pts.empty() || !options_.windows) return dom;
  const Box hp = box_of(pts);
  return clipped(geom::grown_box(hp, first_margin(space_.net(net), hp, space_.blockage_clearance(), space_.net_clearance())), dom);
}

NetRouter::Tried NetRouter::try_net(const NetRouteFn& route, std::size_t net, NetSpaceLevel level, std::span<const char> only,
                                     const WireOverlay* overlay) const {
  Tried t = try_net_unsnapped(route, net, level, only, overlay);
  if (scale_ > 1 && t.a.routed) {
    bool far = false;
    for (auto& w : t.a.wires) {
      std::vector<Point> s;
      s.reserve(w.size());
      for (const Point p : w) {
        const Point q{snapped(p.x, scale_), snapped(p.y, scale_)};
        // within k/4 of q in both coordinates, every segment keeps its direction (a 45-degree
        // one too: both ends' offsets differ by less than k/2) and every end on another segment
        // stays on it; farther (a crossing of two diagonals half way, a staircase beside a 45-
        // degree edge) it need not
        far = far || std::abs(std::int64_t{p.x} - q.x) * 4 >= scale_ || std::abs(std::int64_t{p.y} - q.y) * 4 >= scale_;
        if (s.empty() || s.back() != q) s.push_back(q);
      }
      if (s.size() == 1 && w.size() > 1) s.push_back(s[0]);  // a wire between pins at one point stays two points
      w = std::move(s);
    }
    t.counts.snap_far += far;
    // the certificate (NetOutcome::shortest): the snapped length against the scaled plane's
    // exact distance
    const NetPins& own = space_.net(net);
    const bool claimable = certifies() && own.pins.size() == 2 && t.a.claims && !space_.reached_otherwise(net);
    if (claimable && options_.cost == NetRouterOptions::Cost::Length && t.a.distance) {
      const geom::Root2 s = *t.a.distance;
      t.a.shortest = options_.octilinear ? oct_length(t.a.wires) == s : s.b == 0 && l1_length(t.a.wires) < s.a + scale_;
      t.a.window = t.window;
    } else if (claimable && options_.cost != NetRouterOptions::Cost::Length && t.a.sink_costs.size() == 1 &&
               t.a.wires.size() == 1) {
      // the bend-aware costs (since 2026-12-05): the optimal path's scaled length L and bends b
      // against the snapped wire's scaled length K R (the wires are still in the scaled plane,
      // on multiples of K) and bends b' (the scaled bend cost K C is options_.bend_cost):
      // Combined K R + K C b' < L + K C b + K; Link b' = b and K R < L + K
      const auto [l, b] = t.a.sink_costs[0];
      const __int128 k = scale_, kr = l1_length(t.a.wires), bb = geom::count_bends(t.a.wires[0]), c = options_.bend_cost;
      t.a.shortest = options_.cost == NetRouterOptions::Cost::Combined ? kr + c * bb < __int128{l} + c * b + k
                                                                        : bb == b && kr < __int128{l} + k;
      t.a.window = t.window;
    }
  }
  if (t.a.routed) move_point_wires(t.a.wires, net, level, only, overlay);
  if (t.a.routed && level != NetSpaceLevel::Plain && point_wire_stuck(t.a.wires, net)) {
    // the same at every level with the clearance (it reads the blockages only), so the net is
    // explained as ROUTE-0010 with this reason
    t.a = NetAttempt{};
    t.a.code = "ROUTE-0010";
    const std::string a = std::to_string(space_.blockage_rule());
    t.a.reason = "its pins meet (joined by their own metal), but no point of them tried keeps " + a +
                 " DBU (ceil(w/2) + s) from every blockage (their vertices, where the grown blockages' edges and the "
                 "circles of radius " + a + " round blockage corners cross their edges, and every point of a pin whose "
                 "box holds at most " + std::to_string(kPinScanPoints) + " points): no wire on them keeps the clearance of <rules>, and a "
                 "routed net has one or more wires";
  }
  return t;
}

std::optional<Point> NetRouter::joined_point(std::size_t net, const NetPins& pins, NetSpaceLevel level,
                                             std::span<const char> only, const WireOverlay* overlay) const {
  std::shared_lock lock(space_mutex_);
  const std::vector<char> none(space_.size(), 0);  // (no net's wires)
  auto usable = [&](Point q) {
    if (!on_lattice(q)) return false;
    switch (level) {
      case NetSpaceLevel::Plain: return true;
      case NetSpaceLevel::Clearance: return space_.keeps_blockage_clearance(q);
      case NetSpaceLevel::Pins: return space_.keeps_clearance(net, q, none, nullptr);
      default: return space_.keeps_clearance(net, q, only, overlay);
    }
  };
  if (const auto q = lattice_point_pin(pins.pins, scale_)) return q;
  for (std::size_t i = 0; i < pins.pins.size(); ++i)
    for (std::size_t j = i + 1; j < pins.pins.size(); ++j) {
      const Polygon &a = pins.pins[i], &b = pins.pins[j];
      if (!boxes_meet(box_of(a.outer), box_of(b.outer))) continue;
      if (const auto q = shared_point(a.outer, a, b.outer, b, usable)) return q;
    }
  if (level == NetSpaceLevel::Plain) return std::nullopt;
  for (const Polygon& g : pins.pins)
    if (const auto q = pin_candidate(net, g, overlay, level == NetSpaceLevel::Full, usable)) return q;
  return std::nullopt;
}

std::optional<Point> NetRouter::lattice_point_pin(std::span<const Polygon> pins, std::int64_t scale) {
  for (const Polygon& g : pins)
    if (g.outer.size() == 1 && router::on_lattice(g.outer[0], scale)) return g.outer[0];
  return std::nullopt;
}

std::optional<Point> NetRouter::pin_candidate(std::size_t net, const Polygon& g, const WireOverlay* overlay, bool with_wires,
                                              const std::function<bool(Point)>& usable) const {
  for (const Point v : space_.clearance_candidates(net, g, overlay, with_wires))
    for (const std::int64_t x : geom::lattice_neighbours(2 * std::int64_t{v.x}, scale_))
      for (const std::int64_t y : geom::lattice_neighbours(2 * std::int64_t{v.y}, scale_)) {
        const Point c{static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)};
        if (in_pin(c, g) && usable(c)) return c;
      }
  // A small pin (its box at most kPinScanPoints lattice points) is read whole (since 2026-12-06):
  // the points above miss a clear pocket inside it that the clearance's circles bound (and a
  // clear stretch of a 45-degree edge), where a wire of one point is legal
  // (NetRouter.PadsMeetingInAPocketTheCirclesBoundAreRouted).
  const Box b = box_of(g.outer);
  const std::int64_t x0 = static_cast<std::int64_t>(geom::ceil_div(b.lo.x, scale_)), x1 = static_cast<std::int64_t>(geom::floor_div(b.hi.x, scale_));
  const std::int64_t y0 = static_cast<std::int64_t>(geom::ceil_div(b.lo.y, scale_)), y1 = static_cast<std::int64_t>(geom::floor_div(b.hi.y, scale_));
  if (x0 <= x1 && y0 <= y1 && (x1 - x0 + 1) * (y1 - y0 + 1) <= kPinScanPoints)
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y) {
        const Point c{static_cast<geom::Coord>(x * scale_), static_cast<geom::Coord>(y * scale_)};
        if (in_pin(c, g) && usable(c)) return c;
      }
  return std::nullopt;
}

bool NetRouter::point_wire_stuck(const Lines& wires, std::size_t net) const {
  const std::vector<Polygon>& pins = space_.net(net).pins;
  for (const auto& w : wires) {
    if (w.empty() || !std::all_of(w.begin(), w.end(), [&](Point q) { return q == w[0]; })) return false;
    const Point p = w[0];
    if (std::any_of(pins.begin(), pins.end(), [&](const Polygon& g) { return g.outer.size() == 1; })) return false;
    std::shared_lock lock(space_mutex_);
    if (space_.keeps_blockage_clearance(p)) return false;
    for (const Polygon& g : pins)
      if (pin_candidate(net, g, nullptr, false, [&](Point c) { return space_.keeps_blockage_clearance(c); })) return false;
  }
  return !wires.empty();
}


// A wire of one point (every point the same) is the routers' answer for pins that share a point.
// In a pad cut out of the grown blockages (a pad is free space for its net) that point may lie
// within the clearance of a blockage, and taut check refused it (CHECK-0007) while route exited
// 0 (found by fuzzing, 2026-12-06: two touching pads next to a blockage, the wire at their shared
// corner). Such a wire moves to a point the same two pins share that keeps the clearance, the
// first found by router::shared_point over their vertices (and where their edges cross), on
// the scaled plane's lattice; with none, to another point of the net's pins (below); with none
// of those either it stays (every point of every pin within the clearance). Moved, it still joins what it joined: the pins
// holding the old point all meet there (the checker joins pins that meet by their own metal), and
// a wire through the old point meets those pins. Only at the Full level, as the attempt sees the
// space (`only`, the overlay): the lower levels' attempts read no wires and are kept for the run
// (NetRouter::alone_), so reading them here would make the outcome depend on when they were made.
void NetRouter::move_point_wires(Lines& wires, std::size_t net, NetSpaceLevel level, std::span<const char> only,
                                 const WireOverlay* overlay) const {
  if (level != NetSpaceLevel::Full) return;
  const std::vector<Polygon>& pins = space_.net(net).pins;
  std::shared_lock lock(space_mutex_);
  auto usable = [&](Point q) { return on_lattice(q) && space_.keeps_clearance(net, q, only, overlay); };
  auto point_pin = [&](Point q) {
    return std::any_of(pins.begin(), pins.end(), [&](const Polygon& g) { return g.outer.size() == 1 && g.outer[0] == q; });
  };
  for (auto& w : wires) {
    if (w.empty() || !std::all_of(w.begin(), w.end(), [&](Point q) { return q == w[0]; })) continue;
    const Point p = w[0];
    // on a point pin the checker exempts it (the pin's access zone), and other nets keep their
    // clearance from the pin
    if (point_pin(p) || space_.keeps_clearance(net, p, only, overlay)) continue;
    std::optional<Point> q;
    for (std::size_t i = 0; i < pins.size() && !q; ++i)
      for (std::size_t j = i + 1; j < pins.size() && !q; ++j)
        if (in_pin(p, pins[i]) && in_pin(p, pins[j])) q = shared_point(pins[i].outer, pins[i], pins[j].outer, pins[j], usable);
    // else any point of the net's pins that keeps the clearance (since 2026-12-06: the pins that
    // hold p meet there, so they stay joined without the wire, which FORMAT.md's one or more
    // wires of a routed net keep on a pin): a point of a pin holding p, a point pin (exempt, as
    // above), a point of any pin; the points tried are NetSpace::clearance_candidates on the
    // scaled plane's lattice (the multiples of K next to each)
    for (int pass = 0; pass < 3 && !q; ++pass)
      for (const Polygon& g : pins) {
        if (pass == 0 && !in_pin(p, g)) continue;
        if (pass == 1) q = lattice_point_pin(std::span<const Polygon>(&g, 1), scale_);
        else if (g.outer.size() > 1) q = pin_candidate(net, g, overlay, true, usable);
        if (q) break;
      }
    if (q) w.assign(w.size(), *q);
  }
}

NetRouter::Tried NetRouter::try_net_unsnapped(const NetRouteFn& route, std::size_t net, NetSpaceLevel level,
                                               std::span<const char> only, const WireOverlay* overlay) const {
  using Clock = std::chrono::steady_clock;
  Tried t;
  NetRouterStats& st = t.counts;
  ++st.attempts;
  // the pins routed to (a staircase where a 45-degree pad meets the grown blockages, under the
  // bend-aware metrics); the windows round the pins themselves, as first_window() (a staircase
  // lies in its pin, so the proofs below only get more cautious)
  const NetPins& pins = space_.reach(net);
  std::vector<Point> pts;
  for (const Polygon& pin : space_.net(net).pins) pts.insert(pts.end(), pin.outer.begin(), pin.outer.end());
  const Box& dom = space_.domain();
  const Box hp = pts.empty() ? dom : box_of(pts);
  std::int64_t m = first_margin(space_.net(net), hp, space_.blockage_clearance(), space_.net_clearance());  // as first_window()
  bool fitted = false;  // grown once to the margin its answer needs (see below)
  // the wavefronts' frame merged in the space's union
  const bool framed = options_.framed ? options_.framed(net) : takes_frames(route);
  // the net's pads (shape pins cut out of the grown blockages): the wires' stretches over and
  // along them are trimmed (trim_at_pads), every pad's, those that meet other pins of the net
  // too (until 2026-12-06 only the pads that met none: a wire along a chain of touching pads, or
  // on from one pad into an overlapping one, kept its stretch there within the clearance of a
  // blockage, and taut check refused it; found by fuzzing). Nothing the trimmed stretch joined
  // comes apart: it lies in the union of the closed pads, so the pins and wires it met meet those
  // pads, which meet one another along it (the checker joins pins that meet, as the router does).
  std::vector<Ring> pads;
  for (std::size_t i = 0; i < pins.pins.size(); ++i)
    if (is_pad(pins.pins[i], space_.cuts_shape_pads()))
      for (Ring& piece : pad_pieces(pins.pins[i])) pads.push_back(std::move(piece));
  // Pins that all meet (joined, pair by pair, at lattice points they share) are joined by their
  // own metal: no route, a wire of one point on them that keeps the clearance of this level
  // (joined_point); with none, the route function as for any net (move_point_wires and
  // point_wire_stuck then see to its wire). Since 2026-12-06: the route functions take the pins
  // apart, and where they meet only at corners that pinch shut in the cut pads, found pins of the
  // net in different parts of free space (ROUTE-0002, then ROUTE-0010; found by fuzzing).
  const bool joined = joined_[net];
  // Pins in two or more groups that meet (groups_): when the route function fails on all the
  // pins, one pin of each group is routed instead (the others meet it: the checker joins them by
  // their own metal), the first of each group first, then the others in turn, up to
  // kMaxGroupChoices choices; the choice that routes is kept for the larger windows, and the
  // proofs below read the pins routed (`use`). Since 2026-12-06: a group that meets only through
  // corners that pinch shut in the cut pads lies in several parts of free space, and the route
  // function, which takes every pin, found the net apart (ROUTE-0002, then ROUTE-0010), or a pin
  // of a group not free (ROUTE-0001, nested against a blockage), while a legal routing existed.
  // When all the pins are apart (ROUTE-0002), the choices are tried in the whole domain only (a
  // larger window may join all the pins; and a net of such groups that other nets' wires block
  // costs no more than before in the windows the rip-up rounds cap). After a failure that any
  // window decides (a pin not free), they are tried at once, and when one of them was apart
  // (ROUTE-0002) the window grows as for ROUTE-0002 (`choices_apart`), so the answer does not
  // depend on the first window; the net's reason stays the one for all its pins. (apart_in_window
  // and the last pass's superset prove nothing for shape pins, and for point pins a group is one
  // point, so they read all the pins as before.)
  const std::vector<std::vector<std::size_t>>& groups = groups_[net];
  NetPins chosen;
  const NetPins* use = &pins;
  bool choices_apart = false;  // no choice routed, and one of them was apart in this window
  bool was_apart = false;      // the pins were apart in an earlier window (ROUTE-0002)
  const std::int64_t first_m = m;
  // the window of margin mm
  auto window_at = [&](std::int64_t mm) { return options_.windows ? clipped(geom::grown_box(hp, mm), dom) : dom; };
  // Whether `pins_used` are apart (ROUTE-0002) in the window of margin mm among the blockages and
  // the other nets' pins alone (NetSpaceLevel::Pins: no wire, so the same all run long). The
  // first window's answer is kept for the pins asked (the window limit asks it there, then the
  // detour cap: with a limit of 1 a net the blockages alone keep apart in its first window is
  // the only kind to reach the detour cap); a later window's is not (a net not capped grows on,
  // and each later window the cap would stop asks again: rare).
  std::optional<bool> apart_first;
  const NetPins* apart_first_for = nullptr;
  auto apart_among_pins = [&](const NetPins& pins_used, std::int64_t mm) {
    const bool first = mm == first_m;
    if (first && apart_first && apart_first_for == &pins_used) return *apart_first;
    const Box w0 = window_at(mm);
    geom::NormalizedObstacles o;
    {
      std::shared_lock lock(space_mutex_);
      o = space_.obstacles(net, NetSpaceLevel::Pins, w0 == dom ? std::nullopt : std::optional<Box>(w0), {}, framed, nullptr);
    }
    const NetAttempt b = route(net, pins_used, o);
    const bool apart = !b.routed && b.code == "ROUTE-0002";
    if (first) {
      apart_first = apart;
      apart_first_for = &pins_used;
    }
    return apart;
  };
  while (true) {
    if (options_.stop && options_.stop()) throw NetRouterStopped();
    const Box w = window_at(m);
    const bool whole = w == dom;
    const auto t0 = Clock::now();
    geom::NormalizedObstacles obs;
    {
      // the space may be read by several threads at once, and is changed only by place()
      std::shared_lock lock(space_mutex_);
      if (st.windows == 0) t.since = changed_.size();
      obs = space_.obstacles(net, level, whole ? std::nullopt : std::optional<Box>(w), only, framed, overlay);
    }
    const auto t1 = Clock::now();
    t.window = w;
    NetAttempt& a = t.a;
    const std::optional<Point> at = joined ? joined_point(net, pins, level, only, overlay) : std::nullopt;
    if (at) {
      a = NetAttempt{};
      a.routed = true;
      a.wires = {{*at, *at}};
      a.sink_costs.assign(pins.pins.size() - 1, {0, 0});
      a.radius = geom::Root2{0, 0};
      if (pins.pins.size() == 2) a.distance = geom::Root2{0, 0};
    } else {
      a = route(net, *use, obs);
      choices_apart = false;
      if (!a.routed && use == &pins && !groups.empty() && (whole || a.code != "ROUTE-0002")) {
        std::size_t choices = 1;
        for (const auto& g : groups) choices = std::min(choices * g.size(), kMaxGroupChoices);
        for (std::size_t c = 0; c < choices; ++c) {
          NetPins r;
          r.name = pins.name;
          r.scale = pins.scale;
          std::size_t rest = c;
          for (const auto& g : groups) {
            r.pins.push_back(pins.pins[g[rest % g.size()]]);
            r.index.push_back(g[rest % g.size()]);
            rest /= g.size();
          }
          NetAttempt b = route(net, r, obs);
          if (!b.routed) {
            choices_apart = choices_apart || b.code == "ROUTE-0002";
            continue;
          }
          choices_apart = false;
          chosen = std::move(r);
          use = &chosen;
          a = std::move(b);
          ++st.group_choices;
          break;
        }
      }
    }
    // the length as routed, before the trim: the window proof below bounds how far the route's
    // wavefronts ran, and they ran over the pads too
    const std::int64_t routed_len = a.routed ? l1_length(a.wires) : 0;
    if (a.routed && level != NetSpaceLevel::Plain && !pads.empty()) {
      // every wire over pads only (the pins it joins meet one another): a wire of one point, on
      // a pin, stays, as FORMAT.md's routed net has one or more wires (move_point_wires may move it)
      Lines trimmed = trim_at_pads(a.wires, pads);
      if (trimmed.empty() && !a.wires.empty() && !a.wires[0].empty()) trimmed.push_back({a.wires[0][0], a.wires[0][0]});
      a.wires = std::move(trimmed);
    }
    const auto t2 = Clock::now();
    st.space_seconds += std::chrono::duration<double>(t1 - t0).count();
    st.route_seconds += std::chrono::duration<double>(t2 - t1).count();
    if (whole) st.whole_seconds += std::chrono::duration<double>(t2 - t0).count();
    ++st.windows;
    st.whole += whole;
    if (whole) return t;
    // the least distance from box b to a side of the window that lies inside the domain
    // box b's distance from each side of the window (left, right, bottom, top); none (the
    // int64 maximum) for a side on the domain's
    constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
    auto side_gaps = [&](const Box& b) {
      return std::array<std::int64_t, 4>{w.lo.x > dom.lo.x ? std::int64_t{b.lo.x} - w.lo.x : kNone,
                                         w.hi.x < dom.hi.x ? std::int64_t{w.hi.x} - b.hi.x : kNone,
                                         w.lo.y > dom.lo.y ? std::int64_t{b.lo.y} - w.lo.y : kNone,
                                         w.hi.y < dom.hi.y ? std::int64_t{w.hi.y} - b.hi.y : kNone};
    };
    auto inner = [&](const Box& b) {
      const auto g = side_gaps(b);
      return *std::min_element(g.begin(), g.end());
    };
    if (a.routed && options_.cost != NetRouterOptions::Cost::Length) {
      // the bend-aware metrics (see the header): per sink, the least a path out of the window costs
      if (a.sink_costs.size() + 1 != use->pins.size()) throw std::logic_error("NetRouter: a bend-aware attempt without its sinks' costs");
      const std::int64_t out = 2 * (inner(hp) - 2);
      const bool link = options_.cost == NetRouterOptions::Cost::Link;
      const __int128 c = options_.bend_cost;
      bool proven = true;
      __int128 worst = 0;
      for (std::size_t i = 0; i < a.sink_costs.size(); ++i) {
        const auto [len, bends] = a.sink_costs[i];
        std::int64_t least = out;
        if (is_point_pin(use->pins[0]) && is_point_pin(use->pins[i + 1])) {
          const Point p = use->pins[0].outer[0], q = use->pins[i + 1].outer[0];
          least += std::abs(std::int64_t{p.x} - q.x) + std::abs(std::int64_t{p.y} - q.y);
        }
        if (link) proven = proven && (bends < 2 || (bends == 2 && len <= least));
        else proven = proven && __int128{len} + c * bends <= __int128{least} + 2 * c;
        worst = std::max(worst, __int128{len} + c * bends);
      }
      if (!proven) {
        // The relaxation (see the header): the window's pieces with its sides opened onto a free
        // ring one unit wide. Every way of the whole layout, clamped into the window and the ring,
        // is a way there that costs no more, so the ring's optimum is at most the layout's; when
        // every sink costs the same there as in the window, the window's optimum is the layout's.
        geom::NormalizedObstacles open = obs;
        if (framed) {  // the window's pieces without its frame
          std::shared_lock lock(space_mutex_);
          open = space_.obstacles(net, level, whole ? std::nullopt : std::optional<Box>(w), only, false, overlay);
        }
        open.domain = clipped(geom::grown_box(w, 1), dom);
        const auto r0 = Clock::now();
        const NetAttempt r = route(net, *use, open);
        st.route_seconds += std::chrono::duration<double>(Clock::now() - r0).count();
        ++st.relaxed;
        proven = r.routed && r.sink_costs.size() == a.sink_costs.size();
        for (std::size_t i = 0; proven && i < r.sink_costs.size(); ++i) {
          const auto [l0, b0] = a.sink_costs[i];
          const auto [l1, b1] = r.sink_costs[i];
          proven = link ? (b0 == b1 && l0 == l1) : __int128{l0} + c * b0 == __int128{l1} + c * b1;
        }
      }
      if (proven) return t;
      const __int128 grow = std::max<__int128>(4 * __int128{m}, worst + 3);
      m = static_cast<std::int64_t>(std::min<__int128>(grow, std::numeric_limits<std::int64_t>::max() / 8));
    } else if (a.routed) {
      const std::int64_t len = routed_len;
      bool proven;
      std::optional<std::int64_t> fit;  // a margin in which this answer would pass its proof
      if (two_point_pins(*use)) {
        // A way out through a top or bottom side at distance d from the pins' box climbs at
        // least |dy| + 2d, through a left or right one |dx| + 2d: a lower bound in L1 and in
        // the octilinear metric alike (each unit along an axis costs at least 1).
        const Point p = use->pins[0].outer[0], q = use->pins[1].outer[0];
        const std::int64_t dx = std::abs(std::int64_t{p.x} - q.x), dy = std::abs(std::int64_t{p.y} - q.y);
        const std::int64_t big = std::numeric_limits<std::int64_t>::max() / 4;
        std::int64_t bound = big;
        if (w.lo.y > dom.lo.y) bound = std::min(bound, dy + 2 * (std::int64_t{hp.lo.y} - w.lo.y - 2));
        if (w.hi.y < dom.hi.y) bound = std::min(bound, dy + 2 * (std::int64_t{w.hi.y} - hp.hi.y - 2));
        if (w.lo.x > dom.lo.x) bound = std::min(bound, dx + 2 * (std::int64_t{hp.lo.x} - w.lo.x - 2));
        if (w.hi.x < dom.hi.x) bound = std::min(bound, dx + 2 * (std::int64_t{w.hi.x} - hp.hi.x - 2));
        if (!options_.octilinear) {
          proven = len <= dx + dy + 2 * (inner(hp) - 2);  // L1: the way out also covers the other axis
          fit = (len - dx - dy + 1) / 2 + 3;  // then len <= dx + dy + 2 (m - 2)
        } else {  // the octilinear length a + b sqrt2 (axis a, diagonal b) <= bound, exactly
          const auto [ax, dg] = oct_length(a.wires);
          const __int128 room = static_cast<__int128>(bound) - ax;
          proven = room >= 0 && 2 * static_cast<__int128>(dg) * dg <= room * room;
          fit = (len + 1) / 2 + 3;  // every side's bound is then >= len (L1) >= the octilinear length
        }
      } else {
        // A tree grown from the first pin alone: its wave labelled only points within its radius
        // of the first pin (geodesic distance, L1 or octilinear, is at least the distance along
        // either axis), so a window whose sides are farther from the first pin's box gives the
        // whole layout's distances. Otherwise every wavefront run of the route stopped within
        // its length of the pins and wires.
        std::vector<Point> all = pts;
        for (const auto& wire : a.wires) all.insert(all.end(), wire.begin(), wire.end());
        proven = len < inner(box_of(all)) - 2 ||
                 (a.radius && *a.radius < geom::Root2{inner(box_of(use->pins[0].outer)) - 2, 0});
        // Sink by sink (since 2026-12-06): a way of the whole layout from the first pin to sink s
        // that comes within 2 of an inner side runs, along the axis across that side, at least
        // the first pin's box's distance from the side and s's box's, less 2 each (out and
        // back): when each sink's distance is below the least such sum over the inner sides,
        // less 4, its shortest way lies where the window's space is the layout's, so the window
        // gives every sink the whole layout's distance (the radius's test asks the first pin's
        // distance alone to exceed the radius).
        if (!a.sink_distances.empty() && (a.sink_distances.size() + 1 != use->pins.size() || !a.radius ||
                                          *a.radius != greatest_distance(a.sink_distances)))
          throw std::logic_error("NetRouter: a tree's sink distances do not match its pins or its radius");
        if (!proven && !a.sink_distances.empty()) {
          const auto g0 = side_gaps(box_of(use->pins[0].outer));
          proven = true;
          for (std::size_t i = 0; proven && i < a.sink_distances.size(); ++i) {
            const auto gs = side_gaps(box_of(use->pins[i + 1].outer));
            std::int64_t least = kNone;
            for (std::size_t k = 0; k < 4; ++k)
              if (g0[k] != kNone) least = std::min(least, g0[k] + gs[k]);
            proven = a.sink_distances[i] < geom::Root2{least - 4, 0};
          }
        }
        if (a.radius && a.radius->a >= 0 && a.radius->b >= 0) fit = a.radius->a + 2 * a.radius->b + 3;  // > radius + 2
      }
      if (proven) return t;
      // A way round that a window found only after the pins were apart in a smaller one, and
      // that this window cannot prove, is a detour of more than its margin. When the other nets'
      // wires made it one (the pins meet in the first window among the blockages and pins
      // alone), within the window limit (NetRouterOptions::search_windows) the net is taken as
      // blocked, as when it finds no way there: its blockers are ripped up in the rounds, and the
      // last pass routes it without the limit. (Since 2026-12-06, length cost only. Before, the
      // window grew on to prove the detour; on 10^4 planted nets those windows, 70 in the rip-up
      // rounds, held 51,000 vertices each and took a third of the rounds' time, and the rip-ups
      // they made way for gave longer wires: 44,672,833 DBU then, 43,735,619 with this and the
      // smaller first margin above, 9,926 nets routed either way (1c9682c, which capped the
      // blockages' detours too; on that row it makes no difference: f399af9 gave 76e798d's
      // counts exactly). A net the blockages alone
      // send round a detour grows its window as before: no rip-up could shorten its way, and
      // capped it would wait for the last pass, where other wires may have shut it.) The code
      // and reason are internal: the last pass tries every capped net again.
      if (was_apart && level == NetSpaceLevel::Full && capped_ && options_.search_windows > 0 &&
          st.windows >= options_.search_windows && !apart_among_pins(*use, first_m)) {
        ++st.capped;
        a = NetAttempt{};
        a.code = "ROUTE-0002";
        a.reason = "no way in the windows searched that they prove shortest (a detour longer than their margin)";
        return t;
      }
      // The next window: the first time, just wide enough for this answer to pass its proof there
      // (a wider window keeps every way of this one, so its answer is no longer and passes too);
      // after that (or without such a margin) four times as wide, or the length, whichever is more.
      if (fit && !fitted) {
        m = std::max(m + 1, *fit);
        fitted = true;
      } else {
        m = std::max(4 * m, len + 3);
      }
    } else if (a.code == "ROUTE-0002") {  // unreachable: a larger window may hold a way round,
      // Pins apart in the last pass's superset of the space are apart in it (before a second
      // wavefront in this window, and before windows up to the whole domain)
      if (superset_ && level == NetSpaceLevel::Full && only.empty() && superset_->apart(pins)) {
        ++st.superset_apart;
        return t;
      }
      if (apart_in_window(obs, pins, w)) return t;  // unless a pin is shut in inside this one
      // While rounds remain, a net the other nets' wires shut out of its first windows is taken as
      // blocked (its blockers are ripped up) rather than followed round a detour up to the whole
      // domain; the last pass (run) tries every net left unrouted without this limit. Only when
      // the pins meet in this window among the blockages and pins alone (since 2026-12-06): when
      // the blockages alone keep them apart here, no rip-up could join them in it, and the window
      // grows as without the limit (capped, such a net waited for the last pass, where the wires
      // placed since may shut its way).
      if (level == NetSpaceLevel::Full && capped_ && options_.search_windows > 0 && st.windows >= options_.search_windows &&
          !apart_among_pins(*use, m)) {
        ++st.capped;
        return t;
      }
      // Before a wider window: pins apart among the grown blockages alone are apart at every level
      // with the clearance, whatever the wires (a wall from side to side of the domain: before
      // 2026-12-06 such a net grew its windows to the whole domain in every pass, and its way
      // alone did too); at the Plain level, whose blockages are not grown (a gap narrower than
      // the clearance is open there, and explain() tells such a net by it), the plain blockages'
      // own components. Each built by the first attempt that gets here, once per run.
      if (blockage_parts_) {
        BlockageParts& bp = *blockage_parts_;
        const bool plain = level == NetSpaceLevel::Plain;
        std::call_once(plain ? bp.plain_once : bp.grown_once, [&] {
          geom::NormalizedObstacles sup = plain ? space_.plain_obstacles_framed() : space_.superset_obstacles(/*with_wires=*/false);
          if (sup.stats.rounded == 0) (plain ? bp.plain : bp.grown) = std::make_unique<const FreeComponents>(std::move(sup));
        });
        const FreeComponents* parts = (plain ? bp.plain : bp.grown).get();
        if (parts && parts->apart(pins)) {
          ++st.blockages_apart;
          return t;
        }
      }
      was_apart = true;
      m *= 4;
    } else if (choices_apart && !whole) {  // (a choice of one pin per group may join in a larger window)
      m *= 4;
    } else {  // a pin that is not free, or no staircase: decided near the pins, in any window
      return t;
    }
  }
}

void NetRouter::place(std::size_t i, NetAttempt a, std::optional<std::vector<Polygon>> unioned) {
  // the log (changed_) tells attempts made ahead (threads) and failed attempts kept (failed_)
  // whether the space in their windows is still what they saw
  std::unique_lock lock(space_mutex_);
  for (const Box& b : space_.wire_boxes(i)) changed_.push_back({b, i});
  // what the old wires held that the new ones do not (nothing when only their representation changed)
  if (certifies())
    for (const Box& b : space_.removed_boxes(out_[i].wires, a.routed ? a.wires : Lines{}, i)) removed_.push_back({b, i});
  out_[i].routed = a.routed;
  out_[i].shortest = a.routed && a.shortest;
  claims_[i] = Claim{a.window, removed_.size()};
  out_[i].wires = a.routed ? std::move(a.wires) : Lines{};
  out_[i].code = a.routed ? std::string() : std::move(a.code);
  out_[i].reason = a.routed ? std::string() : std::move(a.reason);
  space_.set_wires(i, out_[i].wires, out_[i].routed ? std::move(unioned) : std::nullopt);
  for (const Box& b : space_.wire_boxes(i)) changed_.push_back({b, i});
}

std::set<std::size_t> NetRouter::way_blockers(std::size_t net, const std::vector<std::vector<Point>>& wires) const {
  std::set<std::size_t> bl;
  for (const auto& line : wires)
    for (const std::size_t x : space_.wire_blockers(net, line)) bl.insert(x);
  for (const std::size_t x : space_.pad_blockers(net)) bl.insert(x);
  return bl;
}

namespace {

// Does a wire piece placed or removed since entry `since` of the log `changed`, of a net other
// than `net`, meet window w (closed boxes, as the R-tree queries of NetSpace::obstacles meet them)?
bool changed_in(std::span<const std::pair<Box, std::size_t>> changed, std::size_t since, const Box& w, std::size_t net) {
  for (std::size_t k = since; k < changed.size(); ++k)
    if (changed[k].second != net && boxes_meet(changed[k].first, w)) return true;
  return false;
}

// ... of any net, one of the windows ws?
bool changed_in(std::span<const std::pair<Box, std::size_t>> changed, std::size_t since, std::span<const Box> ws) {
  for (std::size_t k = since; k < changed.size(); ++k)
    for (const Box& w : ws)
      if (boxes_meet(changed[k].first, w)) return true;
  return false;
}

}  // namespace

void NetRouter::route_in_order(const NetRouteFn& route, std::span<const std::size_t> nets,
                               const std::function<bool(std::size_t, const Box&)>& after, InOrder how) {
  const int threads = std::max(options_.threads, 1);
  if (threads == 1 || nets.size() < 2 || how == InOrder::Serial) {
    for (const std::size_t i : nets) {
      Tried t = try_net(route, i, NetSpaceLevel::Full);
      add_counts(stats_, t.counts);
      place(i, std::move(t.a));
      if (!after(i, t.window)) return;
    }
    return;
  }
  // A pipeline: `threads` workers try nets not placed yet that have no attempt (among the next
  // `ahead`, the earliest first) against the space as it is then; this thread places them in
  // order, each when its attempt is valid: no wire piece placed or removed since the attempt
  // first read the space meets the windows it was tried in (it depends on nothing else); it tries
  // the next net itself when no worker has, or again when the attempt was not valid, and
  // otherwise only waits (with `threads` - 1 workers and this thread trying, the worker took the
  // next net first and this thread waited for it: two threads took turns, 1.02 times one
  // thread's time on 3,000 planted nets). Workers take a net early only when no net before it
  // still to be placed is likely to change its first window: the wires of one already tried, or
  // the first window of one not tried yet (grown by b), meet it. So few attempts are wasted.
  const std::size_t n = nets.size(), ahead = 16 * static_cast<std::size_t>(threads);
  std::vector<Box> first(n), reach(n);  // first windows; the same grown by b (where their wires' pieces lie)
  for (std::size_t k = 0; k < n; ++k) {
    first[k] = first_window(nets[k]);
    reach[k] = geom::grown_box(first[k], space_.net_clearance());
  }
  // is net k's attempt t still valid? (read on this thread only, which alone writes changed_, in
  // place())
  auto valid = [&](const Tried& t, std::size_t k) { return !changed_in(changed_, t.since, t.window, nets[k]); };
  auto clear = [&](const Lookahead<Tried>& la, std::size_t j) {  // with its lock held: may net j be tried now?
    if (!options_.cautious) return true;
    for (std::size_t i = la.start(); i < j; ++i) {
      const Tried* t = la.ready(i);
      if (!t) {
        if (how == InOrder::Cautious && boxes_meet(reach[i], first[j])) return false;
        continue;
      }
      for (const auto& wire : t->a.wires)
        for (std::size_t v = 0; v < wire.size(); ++v) {
          const Point pq[2] = {wire[v], v + 1 < wire.size() ? wire[v + 1] : wire[v]};
          if (boxes_meet(geom::grown_box(box_of(pq), space_.net_clearance()), first[j])) return false;
        }
    }
    return true;
  };
  Lookahead<Tried> pipeline(
      n, ahead, threads,
      [&](std::size_t k) -> std::optional<Tried> { return try_net(route, nets[k], NetSpaceLevel::Full); }, clear);
  for (std::size_t next = 0; next < n; ++next) {
    std::optional<Tried> t = pipeline.take(next);
    if (!t || !valid(*t, next)) {
      // tried here, against the space as it is now: valid by construction (or it throws, as it
      // would with one thread); the workers go on meanwhile
      stats_.redone += t.has_value();
      t = try_net(route, nets[next], NetSpaceLevel::Full);
    }
    add_counts(stats_, t->counts);
    const Box window = t->window;
    place(nets[next], std::move(t->a));  // under the space's own lock: the workers go on
    // attempts ahead that this placement invalidates are tried again at once
    stats_.redone += pipeline.advance(next + 1, [&](std::size_t j, const Tried& r) { return !valid(r, j); });
    if (!after(nets[next], window)) break;
  }
  pipeline.finish();
  stats_.speculated += pipeline.made();
}

NetRouter::RipPlan NetRouter::plan_rip_up(const NetRouteFn& route, std::size_t i, int limit, bool gain,
                                           const std::optional<Tried>* ahead_alone) const {
  RipPlan p;
  p.net = i;
  p.gain = gain;
  p.limit = limit;
  {
    std::shared_lock lock(space_mutex_);
    p.since = changed_.size();
    p.rips_since = rips_log_.size();
  }
  const std::size_t n = space_.size();
  // the net alone (fixed for the run, read nothing of the wires)
  const NetAttempt* by_itself = nullptr;
  if (alone_[i]) {
    by_itself = &*alone_[i];
  } else {
    if (ahead_alone && *ahead_alone) p.alone = **ahead_alone;
    else p.alone = try_net(route, i, NetSpaceLevel::Pins);
    by_itself = &p.alone->a;
  }
  if (!by_itself->routed) return p;  // not the wires' doing: explained at the end
  // way_blockers, with what it reads: the wire pieces meeting the wires' segments and the pads
  // (pad_blockers reads the net's shape pins' boxes: read once for both calls)
  for (const Polygon& pin : space_.net(i).pins)
    if (!is_point_pin(pin)) p.reads.push_back(box_of(pin.outer));
  auto blockers_of = [&](const Lines& wires) {
    for (const auto& line : wires)
      for_segments(line, [&](Point a, Point b) {
        const Point pq[2] = {a, b};
        p.reads.push_back(box_of(pq));
      });
    std::shared_lock lock(space_mutex_);
    return way_blockers(i, wires);
  };
  std::set<std::size_t> blockers = blockers_of(by_itself->wires);
  if (blockers.empty()) return p;
  auto movable = [&] {
    std::shared_lock lock(space_mutex_);
    return std::all_of(blockers.begin(), blockers.end(), [&](std::size_t b) { return out_[b].rips < limit; });
  };
  if (!movable()) {
    // Some of them may not be ripped up again: look for a way round those nets' wires alone
    // (the other nets' pins kept), and rip up the nets that way crosses instead.
    std::vector<char> fixed(n, 0);
    bool any = false;
    {
      std::shared_lock lock(space_mutex_);
      for (std::size_t j = 0; j < n; ++j)
        if (j != i && out_[j].routed && out_[j].rips >= limit) fixed[j] = 1, any = true;
    }
    if (!any) {
      p.any_fixed_read = true;
      return p;
    }
    // (The last such way is taken again when no wire has changed in its windows since and the
    // nets fixed among those with wires there are the same: it depends on nothing else.)
    auto fixed_there = [&](const Box& w) {
      p.reads.push_back(w);
      std::shared_lock lock(space_mutex_);
      std::vector<std::size_t> f;
      for (const std::size_t j : space_.wire_nets_in(w))
        if (fixed[j]) f.push_back(j);
      return f;
    };
    Tried around;
    const auto& c = around_[i];
    bool same = false;
    if (options_.reuse && c) {
      p.reads.push_back(c->tried.window);
      {
        std::shared_lock lock(space_mutex_);
        same = !changed_in(changed_, c->tried.since, c->tried.window, i);
      }
      same = same && c->fixed == fixed_there(c->tried.window);
    }
    if (same) {
      around = c->tried;
      ++p.counts.reused;
    } else {
      around = try_net(route, i, NetSpaceLevel::Full, fixed);
      add_counts(p.counts, around.counts);
      p.around = AroundWay{around, fixed_there(around.window)};  // (which reads the window)
    }
    if (!around.a.routed) return p;
    ++p.counts.around_fixed;
    blockers = blockers_of(around.a.wires);
    if (blockers.empty() || !movable()) return p;
  }
  p.blockers = blockers;
  // The same rip-up undone before, and no wire placed or removed since in the windows its
  // attempts read: it would go the same way, bit for bit (see undone_).
  if (const auto& u = undone_[i]; options_.reuse && u && u->blockers == blockers && u->gain == gain) {
    p.reads.insert(p.reads.end(), u->windows.begin(), u->windows.end());
    std::shared_lock lock(space_mutex_);
    if (!changed_in(changed_, u->mark, u->windows)) {
      p.kind = RipPlan::Kind::Replay;
      return p;
    }
  }
  p.kind = RipPlan::Kind::Made;
  // The blockers ripped up, then the net and they routed in their order, each seeing the wires
  // of those routed before it (an overlay: the space is not changed).
  WireOverlay& ov = p.overlay;
  for (const std::size_t b : blockers) ov.set(b, {});
  std::vector<std::size_t> again_nets{i};
  for (const std::size_t j : order_)
    if (blockers.count(j)) again_nets.push_back(j);
  // Undone when more than 1 - gain of them stay unrouted: once that many have failed, the rest
  // are not tried (the undo puts back the same state either way).
  std::size_t failed = 0, now = 0;
  for (const std::size_t j : again_nets) {
    Tried t = try_net(route, j, NetSpaceLevel::Full, {}, &ov);
    add_counts(p.counts, t.counts);
    p.reads.push_back(t.window);
    p.windows.push_back(t.window);
    ov.set(j, t.a.routed ? space_.wire_union(t.a.wires) : std::vector<Polygon>{});
    failed += !t.a.routed;
    now += t.a.routed;
    p.again.push_back({j, std::move(t.a)});
    if (failed + gain > 1 && options_.reuse) break;
  }
  p.undone = now < blockers.size() + gain;  // fewer routed than before (with gain: not more)
  return p;
}

// What this relies on (see the header's Threads): a net worked out ahead has no wires and gets
// none before its turn (only its own rip-up places it), and its entries of alone_, around_ and
// undone_ are written only in its turn; within a round no net at the rip limit leaves it (such
// nets are never ripped up), so `any` can only turn true, which is checked again; and every wire
// and pin lies in the domain, so a wire piece that a blocker search meets lies in a logged box.
bool NetRouter::plan_valid(const RipPlan& p) const {
  std::shared_lock lock(space_mutex_);
  if (changed_in(changed_, p.since, p.reads) || changed_in(rips_log_, p.rips_since, p.reads)) return false;
  if (p.any_fixed_read)
    for (std::size_t j = 0; j < out_.size(); ++j)
      if (j != p.net && out_[j].routed && out_[j].rips >= p.limit) return false;
  return true;
}

bool NetRouter::commit(RipPlan p) {
  const std::size_t i = p.net;
  add_counts(stats_, p.counts);
  stats_.reused += p.counts.reused;
  stats_.around_fixed += p.counts.around_fixed;
  if (p.alone && !alone_[i]) {
    add_counts(stats_, p.alone->counts);
    alone_[i] = std::move(p.alone->a);
  }
  if (p.around) around_[i] = std::move(p.around);
  if (p.kind == RipPlan::Kind::Nothing) return false;
  // the blockers' rips, logged with their wires' boxes (a rip-up worked out ahead that read them
  // is then worked out again; a rip-up made has removed their wires first, which changed_ logs)
  auto count_rips = [&] {
    std::unique_lock lock(space_mutex_);
    for (const std::size_t b : p.blockers) {
      ++out_[b].rips;
      for (const Box& x : space_.wire_boxes(b)) rips_log_.push_back({x, b});
    }
    stats_.rips += static_cast<std::int64_t>(p.blockers.size());
  };
  if (p.kind == RipPlan::Kind::Replay || p.undone) {
    // undone: every wire as it was; the net (which had none) without its last attempt's reason
    count_rips();
    ++stats_.undone;
    stats_.replayed += p.kind == RipPlan::Kind::Replay;
    {
      std::unique_lock lock(space_mutex_);
      out_[i].code.clear();
      out_[i].reason.clear();
    }
    if (p.kind == RipPlan::Kind::Made) undone_[i] = UndoneRipUp{std::move(p.blockers), p.gain, changed_.size(), std::move(p.windows)};
    return true;
  }
  for (const std::size_t b : p.blockers) place(b, NetAttempt{});
  count_rips();
  for (auto& [j, a] : p.again) place(j, std::move(a), p.overlay.take(j));
  undone_[i].reset();
  return false;
}

namespace {
// NetRouter::bend_router's route function (its bends weigh bend_cost times NetPins::scale).
struct BendRouteFn {
  BendMetric metric;
  std::int64_t bend_cost;
  NetAttempt operator()(std::size_t, const NetPins& net, const geom::NormalizedObstacles& obs) const;
};
// The route functions of l1_router and oct_router, by name: their wavefronts take windows with
// the frame merged (NetSpace::obstacles(..., framed)), which try_net() recognises by these types.
// The octilinear one routes on the lattice of NetPins::scale (BasicRouter::set_lattice).
struct L1RouteFn {
  bool steiner;
  NetAttempt operator()(std::size_t, const NetPins& net, const geom::NormalizedObstacles& obs) const;
};
struct OctRouteFn {
  bool steiner;
  NetAttempt operator()(std::size_t, const NetPins& net, const geom::NormalizedObstacles& obs) const;
};
}  // namespace

void NetRouter::run(const NetRouteFn& route) {
  // the claims (NetOutcome::shortest) and the windows' proof take the options' cost for the route
  // function's: bend_router's must be the same (a route function of one's own is its caller's word)
  if (const auto* f = route.target<BendRouteFn>()) {
    const bool same = options_.cost == (f->metric == BendMetric::Link ? NetRouterOptions::Cost::Link : NetRouterOptions::Cost::Combined) &&
                      (f->metric == BendMetric::Link || f->bend_cost * scale_ == options_.bend_cost);
    if (!same) throw std::invalid_argument("NetRouter::run: bend_router's metric or bend cost differs from NetRouterOptions' cost");
  }
  run_scaled(route);  // the route function takes the scale from NetPins::scale
  // NetOutcome::shortest: withdrawn where another net's wire piece was removed from the window
  // since the claim
  if (certifies()) {
    std::vector<std::pair<Box, std::size_t>> entries;
    entries.reserve(removed_.size());
    for (std::size_t k = 0; k < removed_.size(); ++k) entries.push_back({removed_[k].first, k});
    const bgi::rtree<std::pair<Box, std::size_t>, bgi::rstar<16>> gone(entries.begin(), entries.end());
    std::vector<std::pair<Box, std::size_t>> hits;
    for (std::size_t i = 0; i < out_.size(); ++i) {
      NetOutcome& o = out_[i];
      if (!o.shortest) continue;
      hits.clear();
      gone.query(bgi::intersects(claims_[i].window), std::back_inserter(hits));
      const std::int64_t kr = claimed_cost(o.wires);  // (still in the scaled plane)
      for (const auto& [box, k] : hits)
        if (k >= claims_[i].since && removed_[k].second != i && may_open(i, kr, box)) o.shortest = false;
      if (o.shortest) ++stats_.shortest;
      else ++stats_.shortest_withdrawn;
    }
  }
  if (scale_ == 1) return;
  for (NetOutcome& o : out_)
    for (auto& w : o.wires)
      for (Point& p : w) p = Point{static_cast<geom::Coord>(p.x / scale_), static_cast<geom::Coord>(p.y / scale_)};
}

// Whether a wire of net i shorter than its claimed one (of length kr in the scaled plane; under
// Combined cheaper than its claimed cost kr, claimed_cost, so again no longer than kr - K) may
// pass through box b, where another net's wire piece was removed after the claim. Not when b lies
// outside the claim's window (every way out of it is longer, or costs more), nor, in L1 (not
// under Link, where a wire of fewer bends is better however long), when b misses the
// region {x : d(x, P) + d(x, Q) <= kr - K} round the boxes P and Q of the net's two pins (points
// or shapes; d the L1 distance): a legal wire of length at most R - 1 from one pin to the other
// lies there scaled (each of its points x has d(x, A) + d(x, B) <= K (R - 1) for the pins A and
// B themselves, and a box is no farther than its shape), so if it missed every removed piece it
// was free when the claim was made, and then the distance S there had K R >= S + K, which the
// claim excludes.
std::int64_t NetRouter::claimed_cost(const Lines& wires) const {
  std::int64_t cost = l1_length(wires);
  if (options_.cost == NetRouterOptions::Cost::Combined)
    for (const auto& w : wires) cost += options_.bend_cost * geom::count_bends(w);
  return cost;
}

bool NetRouter::may_open(std::size_t i, std::int64_t kr, const Box& b) const {
  if (!boxes_meet(b, claims_[i].window)) return false;
  // octilinear; Link, where a wire of fewer bends is better however long
  if (options_.octilinear || options_.cost == NetRouterOptions::Cost::Link) return true;
  const Box p = box_of(space_.net(i).pins[0].outer), q = box_of(space_.net(i).pins[1].outer);
  // the L1 distance from x to the interval [lo, hi]
  auto gap = [](std::int64_t x, std::int64_t lo, std::int64_t hi) { return std::max<std::int64_t>({0, lo - x, x - hi}); };
  // the least of gap(x, a0, a1) + gap(x, c0, c1) over x in [lo, hi]: a convex piecewise-linear
  // function, least at an end of [lo, hi] or at a breakpoint inside it
  auto least = [&](std::int64_t lo, std::int64_t hi, std::int64_t a0, std::int64_t a1, std::int64_t c0, std::int64_t c1) {
    std::int64_t m = std::numeric_limits<std::int64_t>::max();
    for (const std::int64_t x : {lo, hi, a0, a1, c0, c1}) {
      const std::int64_t y = std::clamp(x, lo, hi);
      m = std::min(m, gap(y, a0, a1) + gap(y, c0, c1));
    }
    return m;
  };
  return least(b.lo.x, b.hi.x, p.lo.x, p.hi.x, q.lo.x, q.hi.x) + least(b.lo.y, b.hi.y, p.lo.y, p.hi.y, q.lo.y, q.hi.y) <=
         kr - scale_;
}

std::size_t NetRouter::withdraw_claims(std::size_t j, const std::vector<std::vector<Point>>& before,
                                       const std::vector<std::vector<Point>>& after) {
  if (!certifies() || before.empty()) return 0;
  const std::vector<Box> gone = space_.removed_boxes(scaled_wires(before, scale_), scaled_wires(after, scale_));
  if (gone.empty()) return 0;
  std::size_t withdrawn = 0;
  for (std::size_t i = 0; i < out_.size(); ++i) {
    NetOutcome& o = out_[i];
    if (i == j || !o.shortest) continue;
    const std::int64_t kr = claimed_cost(scaled_wires(o.wires, scale_));
    if (std::none_of(gone.begin(), gone.end(), [&](const Box& b) { return may_open(i, kr, b); })) continue;
    o.shortest = false;
    --stats_.shortest;
    ++stats_.shortest_withdrawn;
    ++withdrawn;
  }
  return withdrawn;
}

void NetRouter::run_scaled(const NetRouteFn& route) {
  const std::size_t n = space_.size();
  const int threads = std::max(options_.threads, 1);
  out_.assign(n, NetOutcome{});
  claims_.assign(n, Claim{});
  stats_ = {};
  alone_.assign(n, std::nullopt);
  final_undone_.clear();
  changed_.clear();  // the log of wire pieces placed and removed
  removed_.clear();
  rips_log_.clear();
  failed_.assign(n, std::nullopt);
  undone_.assign(n, std::nullopt);
  around_.assign(n, std::nullopt);
  for (std::size_t i = 0; i < n; ++i) space_.set_wires(i, {});  // a second run starts afresh
  // shortest first: half-perimeter of the pins' bounding box, then the file's order
  std::vector<std::int64_t> hpwl(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Point> pts;
    for (const Polygon& pin : space_.net(i).pins) pts.insert(pts.end(), pin.outer.begin(), pin.outer.end());
    if (pts.empty()) continue;
    const Box b = box_of(pts);
    hpwl[i] = (std::int64_t{b.hi.x} - b.lo.x) + (std::int64_t{b.hi.y} - b.lo.y);
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t x, std::size_t y) { return hpwl[x] < hpwl[y]; });

  NetRouterProgress prog;
  prog.nets = n;
  std::size_t routed_now = 0;
  auto tell = [&] {
    if (!options_.progress) return;
    ++prog.tried;
    prog.routed = routed_now;
    options_.progress(prog);
  };
  capped_ = true;
  // the wall-clock time of each phase (NetRouterStats::phase_seconds)
  auto lap = [t = std::chrono::steady_clock::now()](double& to) mutable {
    const auto now = std::chrono::steady_clock::now();
    to += std::chrono::duration<double>(now - t).count();
    t = now;
  };
  // the free components among the blockages alone, built when first needed (try_net_unsnapped)
  blockage_parts_ = options_.superset ? std::make_shared<BlockageParts>() : nullptr;
  route_in_order(route, order_, [&](std::size_t i, const Box&) {
    routed_now += out_[i].routed;
    tell();
    return true;
  });
  lap(stats_.phase_seconds.first_pass);
  auto score = [&] {
    std::size_t routed = 0;
    std::int64_t len = 0;
    for (const NetOutcome& o : out_)
      if (o.routed) ++routed, len += l1_length(o.wires);
    return std::pair<std::size_t, std::int64_t>{routed, -len};
  };
  stats_.first_pass = score().first;
  std::vector<NetOutcome> best = out_;
  std::vector<Claim> best_claims = claims_;  // (NetOutcome::shortest's, with them)
  auto best_score = score();
  int stale = 0;
  // Rips up the nets in net i's way (found without the other nets' wires) and routes i, then
  // them; undone (then true) when fewer of them are routed after, or with `gain` not more than
  // before. A net ripped up `limit` times stays put (plan_rip_up). `ahead`: the rip-up as a
  // worker worked it out ahead of its turn (with the same limit and gain), made when it is still
  // valid, else worked out again.
  auto rip_up = [&](std::size_t i, int limit, bool gain, std::optional<RipPlan> ahead) -> bool {
    if (ahead) {
      ++stats_.rip_ups_ahead;
      if (!plan_valid(*ahead)) {
        ++stats_.rip_ups_redone;
        ahead.reset();
      }
    }
    return commit(ahead ? std::move(*ahead) : plan_rip_up(route, i, limit, gain));
  };
  // With threads, the rip-ups of the nets `cand` (in order) are worked out ahead: the workers
  // take the next ones after this thread's turn, and this thread takes net cand[k]'s in its turn
  // (planned), or, while a worker works it out, works out later ones itself. (Nets far apart
  // seldom meet each other's rip-ups.)
  struct RipsAhead {
    std::vector<std::size_t> cand;
    std::vector<std::size_t> at;  // per net: its place in cand, or none
    std::optional<Lookahead<RipPlan>> plans;
  };
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  auto rips_ahead = [&](RipsAhead& r, int limit, bool gain, const std::vector<std::optional<Tried>>* alone_ahead) {
    r.at.assign(n, kNone);
    for (std::size_t k = 0; k < r.cand.size(); ++k) r.at[r.cand[k]] = k;
    r.plans.emplace(r.cand.size(), 2 * static_cast<std::size_t>(threads), threads - 1, [&r, &route, limit, gain, alone_ahead, this](std::size_t k) {
      const std::size_t i = r.cand[k];
      return std::optional<RipPlan>(plan_rip_up(route, i, limit, gain, alone_ahead ? &(*alone_ahead)[i] : nullptr));
    });
  };
  // net i's rip-up worked out ahead, when a worker has; none is taken for it once this returns
  auto planned = [&](RipsAhead& r, std::size_t i) -> std::optional<RipPlan> {
    if (!r.plans || r.at[i] == kNone) return std::nullopt;
    r.plans->advance(r.at[i] + 1);
    return r.plans->take(r.at[i], /*help=*/true);
  };
  // Net i at the Full level in a round: the attempt made ahead when still valid; else its last
  // failed attempt when no other net's wire has changed in its windows since (an attempt depends
  // on nothing else: it would fail the same way, bit for bit); else a new one. A failed one is
  // kept for the next time (failed_).
  auto full = [&](std::size_t i, std::optional<Tried>& ahead_i) -> NetAttempt {
    std::optional<Tried> t;
    if (ahead_i && !changed_in(changed_, ahead_i->since, ahead_i->window, i)) {
      add_counts(stats_, ahead_i->counts);
      t = std::move(ahead_i);
    } else if (options_.reuse && failed_[i] && !changed_in(changed_, failed_[i]->since, failed_[i]->window, i)) {
      ++stats_.reused;
      return failed_[i]->a;
    } else {
      stats_.redone += ahead_i.has_value();
      t = try_net(route, i, NetSpaceLevel::Full);
      add_counts(stats_, t->counts);
    }
    if (t->a.routed) {
      failed_[i].reset();
      return std::move(t->a);
    }
    failed_[i] = t;
    return std::move(t->a);
  };
  for (int round = 0; round < options_.max_rounds && best_score.first < n && stale < 2; ++round) {
    ++stats_.rounds;
    prog.phase = NetRouterProgress::Phase::RipUp;
    prog.round = round + 1;
    prog.tried = 0;
    // With threads: every net unrouted now is tried again ahead (against this state), and alone.
    std::vector<std::optional<Tried>> ahead(n);
    std::vector<std::optional<Tried>> ahead_alone(n);
    if (threads > 1) {
      std::vector<std::size_t> todo;
      for (const std::size_t i : order_)
        if (!out_[i].routed) todo.push_back(i);
      parallel_for(2 * todo.size(), threads, [&](std::size_t k) {
        const std::size_t i = todo[k / 2];
        try {
          if (k % 2 == 0) {
            if (!options_.reuse || !failed_[i] || changed_in(changed_, failed_[i]->since, failed_[i]->window, i))
              ahead[i] = try_net(route, i, NetSpaceLevel::Full);
          } else if (!alone_[i])
            ahead_alone[i] = try_net(route, i, NetSpaceLevel::Pins);
        } catch (const NetRouterStopped&) {
          throw;
        } catch (...) {  // tried again in order
        }
      });
      for (const std::size_t i : todo) stats_.speculated += ahead[i].has_value() + ahead_alone[i].has_value();
    }
    // With threads, the rip-ups are worked out ahead too (plan_rip_up), for the nets whose attempt
    // ahead failed.
    RipsAhead rips;
    if (threads > 1) {
      for (const std::size_t i : order_)
        if (!out_[i].routed && (!ahead[i] || !ahead[i]->a.routed)) rips.cand.push_back(i);
      rips_ahead(rips, options_.max_rips, false, &ahead_alone);
    }
    for (const std::size_t i : order_) {
      if (out_[i].routed) continue;
      routed_now = 0;
      for (const NetOutcome& o : out_) routed_now += o.routed;
      tell();
      NetAttempt again = full(i, ahead[i]);  // others may have moved
      if (again.routed) {
        (void)planned(rips, i);
        place(i, std::move(again));
        continue;
      }
      std::optional<RipPlan> plan = planned(rips, i);
      if (!alone_[i] && ahead_alone[i]) {  // fixed for the run: kept whenever it was made
        add_counts(stats_, ahead_alone[i]->counts);
        alone_[i] = std::move(ahead_alone[i]->a);
      }
      (void)rip_up(i, options_.max_rips, false, std::move(plan));
    }
    const auto s = score();
    if (s > best_score) {
      best_score = s;
      best = out_;
      best_claims = claims_;
      stale = 0;
    } else {
      ++stale;
    }
  }
  {
    std::vector<int> rips(n);
    for (std::size_t i = 0; i < n; ++i) rips[i] = out_[i].rips;
    for (std::size_t i = 0; i < n; ++i) {
      best[i].rips = rips[i];
      if (best[i].wires == out_[i].wires) continue;
      NetAttempt was;
      was.routed = best[i].routed;
      was.wires = best[i].wires;
      place(i, std::move(was));
    }
    out_ = std::move(best);
    claims_ = std::move(best_claims);
  }
  lap(stats_.phase_seconds.rounds);
  // The final round: each net still unrouted in the best state is tried again, and else its
  // blockers are ripped up whatever their rips. A rip-up kept must route more of them than
  // before (else it is undone), so this round only gains nets: those the rip limit held.
  if (options_.final_round && best_score.first < n) {
    prog.phase = NetRouterProgress::Phase::RipUp;
    prog.round = stats_.rounds + 1;
    prog.tried = 0;
    const std::size_t had = best_score.first;
    final_undone_.assign(n, 0);
    // with threads, the rip-ups worked out ahead (as in the rounds) for every net unrouted now
    RipsAhead rips;
    if (threads > 1) {
      for (const std::size_t i : order_)
        if (!out_[i].routed) rips.cand.push_back(i);
      rips_ahead(rips, std::numeric_limits<int>::max(), true, nullptr);
    }
    for (const std::size_t i : order_) {
      if (out_[i].routed) continue;
      ++stats_.final_round;
      tell();
      std::optional<Tried> none;
      NetAttempt again = full(i, none);
      std::optional<RipPlan> plan = planned(rips, i);
      if (again.routed)
        place(i, std::move(again));
      else if (rip_up(i, std::numeric_limits<int>::max(), true, std::move(plan)))
        final_undone_[i] = 1;
    }
    best_score = score();
    stats_.final_round_routed = best_score.first - had;
  }
  lap(stats_.phase_seconds.final_round);
  // The last pass: every net still unrouted, tried without the window limit of the rounds (a
  // detour the rounds did not look for, or a net the best state had left behind), in order.
  capped_ = false;
  {
    std::vector<std::size_t> left;
    for (const std::size_t i : order_)
      if (!out_[i].routed) left.push_back(i);
    stats_.last_pass = left.size();
    // the superset of every unrouted net's space, while no wire is removed (NetSpace::superset_obstacles);
    // an inexact union (a sloped crossing rounded outward) might close a way, so it is then not used
    if (!left.empty() && options_.superset) {
      geom::NormalizedObstacles sup = space_.superset_obstacles();
      if (sup.stats.rounded == 0) superset_ = std::make_shared<const FreeComponents>(std::move(sup));
    }
    // A net whose last failed attempt of the rounds never met the window limit, with nothing
    // changed in its window since, would fail the same way without the limit (the windows grow
    // the same way, and no other step depends on the limit): that attempt is placed in its turn.
    std::vector<std::size_t> batch;
    auto flush = [&] {
      route_in_order(
          route, batch,
          [&](std::size_t i, const Box&) {
            stats_.last_pass_routed += out_[i].routed;
            return true;
          },
          InOrder::Failing);
      batch.clear();
    };
    for (const std::size_t i : left) {
      const auto& f = failed_[i];
      if (!options_.reuse || !f || f->counts.capped > 0) {
        batch.push_back(i);
        continue;
      }
      flush();
      if (changed_in(changed_, f->since, f->window, i)) {
        batch.push_back(i);
        continue;
      }
      ++stats_.reused;
      place(i, f->a);
    }
    flush();
    superset_.reset();
    best_score = score();
  }
  lap(stats_.phase_seconds.last_pass);
  // Explaining reads the final state only: the nets are explained at once.
  prog.phase = NetRouterProgress::Phase::Explain;
  prog.tried = 0;
  routed_now = best_score.first;
  std::vector<std::size_t> unrouted;
  for (const std::size_t i : order_)
    if (!out_[i].routed) unrouted.push_back(i);
  const std::size_t chunk = 4 * static_cast<std::size_t>(threads);  // then progress is told
  for (std::size_t c = 0; c < unrouted.size(); c += chunk) {
    const std::size_t e = std::min(unrouted.size(), c + chunk);
    std::vector<Explained> why(e - c);
    parallel_for(e - c, threads, [&](std::size_t k) { why[k] = explain(route, unrouted[c + k]); });
    for (std::size_t k = 0; k < e - c; ++k) {
      NetOutcome& o = out_[unrouted[c + k]];
      add_counts(stats_, why[k].counts);
      if (!why[k].code.empty()) {
        o.code = std::move(why[k].code);
        o.reason = std::move(why[k].reason);
      }
      o.blockers = std::move(why[k].blockers);
      tell();
    }
  }
  lap(stats_.phase_seconds.explain);
}

NetRouter::Explained NetRouter::explain(const NetRouteFn& route, std::size_t net) const {
  Explained e;
  auto tried = [&](NetSpaceLevel level) {
    Tried t = try_net(route, net, level);
    add_counts(e.counts, t.counts);
    return std::move(t.a);
  };
  const NetAttempt plain = tried(NetSpaceLevel::Plain);
  if (!plain.routed) {  // the router's own reason, about the blockages
    e.code = plain.code;
    e.reason = plain.reason;
    return e;
  }
  const NetAttempt clear = tried(NetSpaceLevel::Clearance);
  const std::string a = std::to_string(space_.blockage_rule()), b = std::to_string(space_.net_rule());
  // the route function's own way misses the clearance, or the net's pins meet within it everywhere
  // (try_net)
  if (!clear.routed && (clear.code == "ROUTE-0018" || clear.code == "ROUTE-0010")) {
    e.code = clear.code;
    e.reason = clear.reason;
    return e;
  }
  if (!clear.routed && clear.code == "ROUTE-0005" && !space_.cuts_shape_pads()) {
    // a shape pin the route function refused in the grown space: one that is not cut out of it
    // (no staircase, NetSpace::reach)
    for (const Polygon& pin : space_.reach(net).pins)
      if (!is_point_pin(pin) && pin_shape_supported(pin) && !is_pad(pin, false)) {
        e.code = "ROUTE-0010";
        e.reason = "a shape pin with a 45-degree edge lies within " + a +
                   " DBU (ceil(w/2) + s) of a blockage, and it is too thin for a staircase of rectangles: no cell "
                   "of the lattice lies inside it (unit steps; coarser ones for a pin more than " + std::to_string(NetSpace::kMaxStaircaseColumns) +
                   " steps wide): the bend-aware metrics reach such a pin only as its staircase (their router takes "
                   "rectilinear obstacles only)";
        return e;
      }
  }
  if (!clear.routed) {
    e.code = "ROUTE-0010";
    e.reason = "the clearance of <rules> closes every way between its pins: wires keep " + a +
               " DBU (ceil(w/2) + s) from blockages, so a gap on the way is narrower than " +
               std::to_string(2 * space_.blockage_rule()) + " DBU or a pin is within " + a +
               " DBU of a blockage it does not sit on";
    return e;
  }
  const NetAttempt pins = alone_[net] ? *alone_[net] : tried(NetSpaceLevel::Pins);
  auto name = [&](std::size_t i) { return "\"" + space_.net(i).name + "\""; };
  if (!pins.routed) {
    std::set<std::size_t> bl;
    for (const auto& line : clear.wires)
      for (const std::size_t x : space_.pin_blockers(net, line)) bl.insert(x);
    e.blockers.assign(bl.begin(), bl.end());
    e.code = "ROUTE-0011";
    e.reason = "the pins of other nets block every way (wires keep " + b + " DBU, w + s, from them)";
    if (!e.blockers.empty()) e.reason += ": its way alone passes the pins of nets " + net_list(e.blockers, name);
    return e;
  }
  const std::set<std::size_t> bl = way_blockers(net, pins.wires);
  e.blockers.assign(bl.begin(), bl.end());
  if (e.blockers.empty()) {
    // Its way alone enters no other net's grown wire. When it runs at exactly the clearance from
    // some, those may close it: two grown obstacles that touch merge, so a gap of width zero
    // between them, where a wire would be legal, is shut (see the header's limits).
    std::set<std::size_t> touch;
    for (const auto& line : pins.wires)
      for (const std::size_t x : space_.wire_touchers(net, line)) touch.insert(x);
    if (touch.empty()) return e;  // keeps the full attempt's own reason
    e.blockers.assign(touch.begin(), touch.end());
    e.code = "ROUTE-0012";
    e.reason = "the wires of other nets block every way: its way alone runs at exactly the clearance (" + b +
               " DBU, w + s) from the wires of nets " + net_list(e.blockers, name) +
               ", in a gap of width zero between grown wires, which the router closes (a limitation)";
    return e;
  }
  e.code = "ROUTE-0012";
  bool limit = false;
  for (const std::size_t x : e.blockers) limit = limit || out_[x].rips >= options_.max_rips;
  e.reason = "the wires of other nets block every way (kept " + b + " DBU, w + s, apart): its way alone crosses nets " +
             net_list(e.blockers, name) +
             (limit ? (options_.max_rips == 0 ? std::string("; they may not be ripped up (no rip-up rounds: --max-rips 0")
                                              : "; they may not be ripped up again (each net at most " +
                                                    std::to_string(options_.max_rips) + " times") +
                          (net < final_undone_.size() && final_undone_[net]
                               ? "; ripping them up once more in the final round routed no more nets and was undone)"
                               : ")")
                    : "; ripping them up and routing them again left no way either");
  return e;
}

std::vector<Polygon> obstacles_under(const Polygon& pin, std::span<const Polygon> obstacles) {
  std::vector<Polygon> out;
  if (is_point_pin(pin)) return out;
  const Box b = box_of(pin.outer);
  for (const Polygon& o : obstacles)
    if (boxes_meet(box_of(o.outer), b) && shape_meets_obstacle(pin, o)) out.push_back(o);
  return out;
}

std::optional<Polygon> routable_pin(const Polygon& pin, std::span<const Polygon> under) {
  if (!under.empty()) return pad_staircase(pin, 1, {}, under);
  if (pin_shape_supported(pin)) return pin;
  return pad_staircase(pin, 1);
}

ReachedPins reach_pins(std::span<const Polygon> pins, std::span<const Polygon> obstacles,
                       const std::function<bool(const Polygon&)>& meets) {
  ReachedPins r;
  for (std::size_t i = 0; i < pins.size(); ++i) {
    const std::vector<Polygon> under = meets(pins[i]) ? obstacles_under(pins[i], obstacles) : std::vector<Polygon>{};
    r.cut = r.cut || !under.empty();
    std::optional<Polygon> reached = routable_pin(pins[i], under);
    if (!reached) {
      r.failed = i;
      r.failed_under = !under.empty();
      return r;
    }
    r.pins.push_back(std::move(*reached));
  }
  return r;
}

namespace {

// A route function's pins as its router takes them (reach_pins): nullopt, with a's code and
// reason, when a pin keeps no cell; a.claims false when a pin was cut (a pad partly under other
// nets' grown wires or pins).
std::optional<std::vector<Polygon>> reachable_pins(const NetPins& net, const geom::NormalizedObstacles& obs,
                                                   const std::function<bool(const Polygon&)>& meets, NetAttempt& a) {
  ReachedPins r = reach_pins(net.pins, obs.obstacles, meets);
  if (r.failed) {
    a.code = "ROUTE-0005";
    a.reason = "a shape pin this router does not take here";
    return std::nullopt;
  }
  if (r.cut) a.claims = false;
  return std::move(r.pins);
}

// The route function of l1_router / oct_router: Router is L1Router or OctRouter; `lattice`:
// BasicRouter::set_lattice.
template <class Router>
NetAttempt route_with(const NetPins& net, const geom::NormalizedObstacles& obs, bool steiner, std::int64_t lattice) {
  NetAttempt a;
  if (net.pins.size() < 2) {
    a.code = "ROUTE-0006";
    a.reason = "fewer than two pins";
    return a;
  }
  Router r(obs.domain, obs.obstacles);
  r.set_lattice(lattice);
  auto fail = [&](WireStatus st) {
    a.code = st == WireStatus::SourceNotFree || st == WireStatus::TargetNotFree ? "ROUTE-0001"
             : st == WireStatus::Unreachable                                   ? "ROUTE-0002"
                                                                               : "ROUTE-0003";
    a.reason = to_string(st);
    return a;
  };
  const std::optional<std::vector<Polygon>> pins =
      reachable_pins(net, obs, [&](const Polygon& p) { return r.pin_meets_obstacle(p).has_value(); }, a);
  if (!pins) return a;
  if (pins->size() == 2) {
    const typename Router::Wire w = r.shortest((*pins)[0], (*pins)[1]);
    if (w.status != WireStatus::Ok) return fail(w.status);
    a.wires = {w.points};
    a.distance = w.root2_length();
  } else if (steiner) {
    const typename Router::Steiner t = r.steiner(std::span<const Polygon>(*pins));
    if (t.status != WireStatus::Ok) return fail(t.status);
    a.wires = t.wires;
  } else {
    const typename Router::Tree t = r.tree((*pins)[0], std::span<const Polygon>(*pins).subspan(1));
    if (t.status != WireStatus::Ok) return fail(t.status);
    a.wires = t.wires;
    if (auto d = tree_sink_distances(t)) {
      a.radius = greatest_distance(*d);
      a.sink_distances = std::move(*d);
    }
  }
  a.routed = true;
  return a;
}

// The route function of bend_router: the tree of optimal paths from the first pin (two pins: the
// optimal wire), with every sink's cost for the windows' proof.
NetAttempt route_bends(const NetPins& net, const geom::NormalizedObstacles& obs, BendMetric metric, std::int64_t bend_cost) {
  NetAttempt a;
  if (net.pins.size() < 2) {
    a.code = "ROUTE-0006";
    a.reason = "fewer than two pins";
    return a;
  }
  const BendRouter r(obs.domain, obs.obstacles);
  const std::optional<std::vector<Polygon>> pins =
      reachable_pins(net, obs, [&](const Polygon& p) { return r.pin_meets_obstacle(p).has_value(); }, a);
  if (!pins) return a;
  const BendTree t = r.tree((*pins)[0], std::span<const Polygon>(*pins).subspan(1), metric, bend_cost);
  if (t.status != WireStatus::Ok) {
    a.code = t.status == WireStatus::Unreachable ? "ROUTE-0002" : "ROUTE-0001";
    a.reason = to_string(t.status);
    return a;
  }
  a.wires = t.wires;
  for (auto& w : a.wires)
    if (w.size() == 1) w.push_back(w[0]);  // pins at one point
  for (const auto& p : t.paths) a.sink_costs.push_back({l1_length(Lines{p}), geom::count_bends(p)});
  a.routed = true;
  return a;
}

}  // namespace

NetAttempt L1RouteFn::operator()(std::size_t, const NetPins& net, const geom::NormalizedObstacles& obs) const {
  return route_with<L1Router>(net, obs, steiner, 1);
}

NetAttempt OctRouteFn::operator()(std::size_t, const NetPins& net, const geom::NormalizedObstacles& obs) const {
  return route_with<OctRouter>(net, obs, steiner, net.scale);
}

NetAttempt BendRouteFn::operator()(std::size_t, const NetPins& net, const geom::NormalizedObstacles& obs) const {
  return route_bends(net, obs, metric, bend_cost * net.scale);  // router_scale keeps it <= 2^31
}

NetRouteFn NetRouter::bend_router(BendMetric metric, std::int64_t bend_cost) { return BendRouteFn{metric, bend_cost}; }


bool NetRouter::takes_frames(const NetRouteFn& route) {
  return route.target<L1RouteFn>() != nullptr || route.target<OctRouteFn>() != nullptr;
}

NetRouteFn NetRouter::l1_router(bool steiner) { return L1RouteFn{steiner}; }

NetRouteFn NetRouter::oct_router(bool steiner) { return OctRouteFn{steiner}; }

}  // namespace taut::router
