// Semantic validation of a layout (see validate_layout.h).
//
// Diagnostic codes issued here (GEOM-00xx codes of geom::validate_polygon pass through with the
// line of the <polygon> or <hole>):
//   LAYOUT-0001  duplicate blockage id
//   LAYOUT-0002  duplicate net name
//   LAYOUT-0003  duplicate pin name within a net
//   LAYOUT-0004  a point pin lies in the interior of a blockage (or of the union of several
//                blockages that touch around it); on a blockage's boundary is fine
//   LAYOUT-0005  a shape pin lies entirely in the interior of one blockage shape
//   LAYOUT-0006  a pin lies outside the boundary (a point pin outside the closed box; a shape pin
//                that does not meet the closed box at all); on a boundary edge is fine
//   LAYOUT-0007  warning: a net has fewer than two pins (it is reported as not routable), unless
//                its sketch is a loop (closed: a guard ring)
//   LAYOUT-0008  warning: a sketch does not start on the net's first pin or end on its second (one
//                warning when it runs from the second to the first)
//   LAYOUT-0009  warning: a sketch on a net that does not have exactly two pins
//   (neither for a loop: a sketch whose last point is its first, which belongs to no pin)
//   LAYOUT-0010  a route names a net that does not exist
//   LAYOUT-0011  two routes for the same net
//   LAYOUT-0012  a blockage has no shapes (layouts built in memory; the reader says IO-0020)
//   LAYOUT-0013  a coordinate is outside [-(2^30-1), 2^30-1] (layouts built in memory)
//   LAYOUT-0014  rules: orientations unknown, or a c: set with fewer than 2 distinct directions
//                modulo 180 degrees (it cannot connect points in the plane)
//   LAYOUT-0015  a pin is not exactly one of point / shape (layouts built in memory)
//   LAYOUT-0016  rules: a negative wire-width, spacing or bend-cost (layouts built in memory)
//   LAYOUT-0017  an empty blockage id, net name or pin name (layouts built in memory)
//   GEOM-0008    a rect or the boundary is empty (lo >= hi on an axis)
#include "io/validate_layout.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <utility>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "geom/validate.h"

namespace taut::io {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using geom::i128;
using geom::i64;
using geom::Location;
using geom::Ring;

using BgPoint = bg::model::point<i64, 2, bg::cs::cartesian>;
using BgBox = bg::model::box<BgPoint>;
using IndexEntry = std::pair<BgBox, std::size_t>;

// The code the brief assigns to an empty rect/boundary; the same as the reader's (one place to
// change it if geom/validate.h takes GEOM-0008 for something else).
constexpr const char* kEmptyBox = "GEOM-0010";

std::string q(const std::string& s) { return "\"" + s + "\""; }
std::string pt(Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }

Ring rect_ring(const Box& b) {  // counter-clockwise
  return {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}};
}

Box bbox_of(const Ring& r) {
  Box b{r.front(), r.front()};
  for (Point p : r) {
    b.lo.x = std::min(b.lo.x, p.x);
    b.lo.y = std::min(b.lo.y, p.y);
    b.hi.x = std::max(b.hi.x, p.x);
    b.hi.y = std::max(b.hi.y, p.y);
  }
  return b;
}

bool in_box(Point p, const Box& b) {
  return b.lo.x <= p.x && p.x <= b.hi.x && b.lo.y <= p.y && p.y <= b.hi.y;
}

BgBox to_bg(const Box& b) { return BgBox(BgPoint(b.lo.x, b.lo.y), BgPoint(b.hi.x, b.hi.y)); }

// ---------------------------------------------------------------------------------------------
// Local geometry around a point p on the boundary of several closed polygons: is p in the
// interior of their union? Directions are integer vectors from p; angles are compared exactly
// (half-plane, then cross product in __int128).

struct Dir {
  i64 x = 0, y = 0;
};
i128 cross(Dir a, Dir b) { return i128{a.x} * b.y - i128{a.y} * b.x; }
i128 dotp(Dir a, Dir b) { return i128{a.x} * b.x + i128{a.y} * b.y; }
int half(Dir d) { return (d.y < 0 || (d.y == 0 && d.x < 0)) ? 1 : 0; }
bool angle_less(Dir a, Dir b) {
  const int ha = half(a), hb = half(b);
  if (ha != hb) return ha < hb;
  return cross(a, b) > 0;
}
bool same_dir(Dir a, Dir b) { return cross(a, b) == 0 && dotp(a, b) > 0; }
Dir dir(Point from, Point to) { return {i64{to.x} - from.x, i64{to.y} - from.y}; }

// t strictly inside the open sector swept counter-clockwise from s to e (t is never parallel
// to s or e here).
bool in_sector(Dir s, Dir e, Dir t) {
  const i128 c = cross(s, e);
  if (c > 0) return cross(s, t) > 0 && cross(t, e) > 0;
  if (c < 0) return cross(s, t) > 0 || cross(t, e) > 0;
  if (dotp(s, e) < 0) return cross(s, t) > 0;  // straight: a half-plane
  return false;                                // zero-width spike (an invalid ring anyway)
}

// Is direction t, infinitesimally from p, inside the region of ring r? p lies on r.
bool ring_contains_dir(const Ring& r, Point p, Dir t) {
  const i128 area = geom::twice_area(r);
  if (area == 0) return false;
  const bool ccw = area > 0;
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = r[i], b = r[(i + 1) % n];
    Point prev, next;
    if (a == p && r[(i + n - 1) % n] != p) {
      // Start of a run of copies of p: the neighbours are the nearest distinct vertices.
      prev = r[(i + n - 1) % n];
      std::size_t j = (i + 1) % n;
      while (r[j] == p && j != i) j = (j + 1) % n;
      if (j == i) return false;
      next = r[j];
    } else if (a != p && b != p && geom::on_segment(p, a, b)) {
      prev = a;
      next = b;
    } else {
      continue;
    }
    const Dir out = dir(p, next), back = dir(p, prev);
    if (ccw ? in_sector(out, back, t) : in_sector(back, out, t)) return true;
  }
  return false;
}

bool polygon_contains_dir(const Polygon& poly, Point p, Dir t) {
  switch (geom::locate(p, std::span<const Point>(poly.outer))) {
    case Location::Outside:
      return false;
    case Location::Boundary:
      if (!ring_contains_dir(poly.outer, p, t)) return false;
      break;
    case Location::Inside:
      break;
  }
  for (const Ring& h : poly.holes) {
    switch (geom::locate(p, std::span<const Point>(h))) {
      case Location::Inside:
        return false;
      case Location::Boundary:
        if (ring_contains_dir(h, p, t)) return false;
        break;
      case Location::Outside:
        break;
    }
  }
  return true;
}

// p lies on the boundary of every polygon given (and is in none's interior): is a whole
// neighbourhood of p covered by their union?
bool covered_around(Point p, const std::vector<const Polygon*>& polys) {
  std::vector<Dir> dirs;
  for (const Polygon* poly : polys) {
    auto add_ring = [&](const Ring& r) {
      const std::size_t n = r.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Point a = r[i], b = r[(i + 1) % n];
        if (a == b) continue;
        if (a == p) {
          dirs.push_back(dir(p, b));
        } else if (b == p) {
          dirs.push_back(dir(p, a));
        } else if (geom::on_segment(p, a, b)) {
          dirs.push_back(dir(p, a));
          dirs.push_back(dir(p, b));
        }
      }
    };
    add_ring(poly->outer);
    for (const Ring& h : poly->holes) add_ring(h);
  }
  if (dirs.empty()) return false;
  std::sort(dirs.begin(), dirs.end(), angle_less);
  dirs.erase(std::unique(dirs.begin(), dirs.end(), same_dir), dirs.end());
  // One test direction strictly inside each wedge between consecutive directions.
  const std::size_t k = dirs.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Dir u = dirs[i], v = dirs[(i + 1) % k];
    Dir t;
    if (k == 1) {
      t = {-u.x, -u.y};
    } else {
      const i128 c = cross(u, v);
      if (c > 0) t = {u.x + v.x, u.y + v.y};
      else if (c < 0) t = {-(u.x + v.x), -(u.y + v.y)};
      else t = {-u.y, u.x};  // opposite directions: the left half-plane of u
    }
    bool covered = false;
    for (const Polygon* poly : polys)
      if (polygon_contains_dir(*poly, p, t)) {
        covered = true;
        break;
      }
    if (!covered) return false;
  }
  return true;
}

bool segments_meet(Point a, Point b, Point c, Point d) {
  return geom::intersect({a, b}, {c, d}) != geom::SegmentIntersection::None;
}

// Does the closed region of `s` (its outer ring) lie in the open interior of `poly`?
bool ring_inside_interior(const Ring& s, const Box& s_box, const Polygon& poly, const Box& p_box) {
  if (!(p_box.lo.x < s_box.lo.x && s_box.hi.x < p_box.hi.x && p_box.lo.y < s_box.lo.y &&
        s_box.hi.y < p_box.hi.y))
    return false;
  // The boundaries must not meet at all ...
  auto meets = [&](const Ring& r) {
    const std::size_t n = r.size(), m = s.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = r[i], b = r[(i + 1) % n];
      if (std::max(a.x, b.x) < s_box.lo.x || std::min(a.x, b.x) > s_box.hi.x ||
          std::max(a.y, b.y) < s_box.lo.y || std::min(a.y, b.y) > s_box.hi.y)
        continue;
      for (std::size_t j = 0; j < m; ++j)
        if (segments_meet(a, b, s[j], s[(j + 1) % m])) return true;
    }
    return false;
  };
  if (meets(poly.outer)) return false;
  for (const Ring& h : poly.holes)
    if (meets(h)) return false;
  // ... then s lies in one face of the plane cut by poly's boundary: the interior, if one of
  // its vertices is inside; and no hole of poly may lie within s.
  if (geom::locate(s.front(), poly) != Location::Inside) return false;
  for (const Ring& h : poly.holes)
    if (geom::locate(h.front(), std::span<const Point>(s)) != Location::Outside) return false;
  return true;
}

// Does a closed polygon region meet a closed box?
bool polygon_meets_box(const Polygon& poly, const Box& b) {
  for (Point p : poly.outer)
    if (in_box(p, b)) return true;
  const Ring corners = rect_ring(b);
  for (Point c : corners)
    if (geom::locate(c, poly) != Location::Outside) return true;
  auto edges_meet = [&](const Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i)
      for (std::size_t j = 0; j < 4; ++j)
        if (segments_meet(r[i], r[(i + 1) % r.size()], corners[j], corners[(j + 1) % 4]))
          return true;
    return false;
  };
  if (edges_meet(poly.outer)) return true;
  for (const Ring& h : poly.holes)
    if (edges_meet(h)) return true;
  return false;
}

// ---------------------------------------------------------------------------------------------

struct IndexedShape {
  Polygon poly;
  Box box;
  std::size_t blockage = 0;
};

class Validator {
 public:
  explicit Validator(const Layout& layout) : layout_(layout) {}

  std::vector<Diagnostic> run() {
    check_rules();
    if (layout_.boundary) {
      const Box& b = layout_.boundary->box;
      check_range(b.lo, layout_.boundary->line, "boundary") &&
          check_range(b.hi, layout_.boundary->line, "boundary");
      if (b.lo.x >= b.hi.x || b.lo.y >= b.hi.y)
        error(kEmptyBox, layout_.boundary->line,
              "boundary " + pt(b.lo) + "-" + pt(b.hi) + " is empty: needs x0 < x1 and y0 < y1");
    }
    check_blockages();
    build_index();
    check_nets();
    check_routes();
    return std::move(diags_);
  }

 private:
  void add(Severity s, const char* code, int line, std::string message) {
    Diagnostic d;
    d.severity = s;
    d.code = code;
    d.file = layout_.file;
    d.line = line;
    d.message = std::move(message);
    diags_.push_back(std::move(d));
  }
  void error(const char* code, int line, std::string m) { add(Severity::Error, code, line, std::move(m)); }
  void warning(const char* code, int line, std::string m) { add(Severity::Warning, code, line, std::move(m)); }

  bool check_range(Point p, int line, const std::string& ctx) {
    if (geom::in_range(p.x) && geom::in_range(p.y)) return true;
    error("LAYOUT-0013", line, ctx + ": coordinate " + pt(p) + " is out of range (|v| <= 2^30 - 1)");
    return false;
  }

  void check_rules() {
    if (!layout_.rules) return;
    const Rules& r = *layout_.rules;
    const std::pair<const char*, std::int64_t> values[] = {
        {"wire-width", r.wire_width}, {"spacing", r.spacing}, {"bend-cost", r.bend_cost}};
    for (const auto& [name, v] : values)
      if (v < 0) error("LAYOUT-0016", r.line, std::string("rules: ") + name + " is negative");
    if (r.orientations == "rectilinear" || r.orientations == "octilinear" || r.orientations == "any")
      return;
    if (r.orientations.rfind("c:", 0) != 0) {
      error("LAYOUT-0014", r.line, "rules: orientations " + q(r.orientations) + " is unknown");
      return;
    }
    // Directions modulo 180 degrees (a direction and its opposite are the same wire direction).
    if (distinct_orientations(r.orientation_degrees) < 2)
      error("LAYOUT-0014", r.line,
            "rules: orientations " + q(r.orientations) +
                " has fewer than 2 distinct directions modulo 180 degrees");
  }

  // Range, rect emptiness and polygon validity of one shape. Returns true when it is valid.
  bool check_shape(const Shape& s, const std::string& ctx) {
    if (s.kind == Shape::Kind::Rect) {
      if (!check_range(s.rect.lo, s.line, ctx + " rect") || !check_range(s.rect.hi, s.line, ctx + " rect"))
        return false;
      if (s.rect.lo.x >= s.rect.hi.x || s.rect.lo.y >= s.rect.hi.y) {
        error(kEmptyBox, s.line,
              ctx + " rect " + pt(s.rect.lo) + "-" + pt(s.rect.hi) +
                  " is empty: needs x0 < x1 and y0 < y1");
        return false;
      }
      return true;
    }
    auto ring_ok = [&](const Ring& r, int line) {
      for (Point p : r)
        if (!check_range(p, line, ctx + " polygon")) return false;
      return true;
    };
    bool ok = ring_ok(s.polygon.outer, s.line);
    for (std::size_t k = 0; k < s.polygon.holes.size(); ++k)
      ok = ring_ok(s.polygon.holes[k], hole_line(s, static_cast<int>(k))) && ok;
    if (!ok) return false;
    if (s.polygon.outer.empty()) {
      error("GEOM-0001", s.line, ctx + " polygon: has no vertices");
      return false;
    }
    const auto problems = geom::validate_polygon(s.polygon);
    for (const auto& p : problems) {
      const int line = p.ring < 0 ? s.line : hole_line(s, p.ring);
      // geom's message names the ring ("outer ring", "hole 0"); the line is that ring's.
      error(p.code.c_str(), line, ctx + " polygon: " + p.message);
    }
    return problems.empty();
  }
  static int hole_line(const Shape& s, int k) {
    return k >= 0 && static_cast<std::size_t>(k) < s.hole_lines.size() ? s.hole_lines[k] : s.line;
  }

  void check_blockages() {
    std::unordered_map<std::string, int> seen;
    valid_.assign(layout_.blockages.size(), {});
    for (std::size_t i = 0; i < layout_.blockages.size(); ++i) {
      const Blockage& b = layout_.blockages[i];
      const std::string ctx = "blockage " + q(b.id);
      if (b.id.empty()) error("LAYOUT-0017", b.line, "blockage: empty id");
      const auto [it, fresh] = seen.emplace(b.id, b.line);
      if (!fresh && !b.id.empty())
        error("LAYOUT-0001", b.line,
              ctx + ": id already used by the blockage on line " + std::to_string(it->second));
      if (b.shapes.empty()) error("LAYOUT-0012", b.line, ctx + ": has no shapes");
      for (const Shape& s : b.shapes) valid_[i].push_back(check_shape(s, ctx));
    }
  }

  void build_index() {
    std::vector<IndexEntry> entries;
    for (std::size_t i = 0; i < layout_.blockages.size(); ++i) {
      const Blockage& b = layout_.blockages[i];
      for (std::size_t k = 0; k < b.shapes.size(); ++k) {
        if (!valid_[i][k]) continue;  // already reported; its geometry cannot be trusted
        const Shape& s = b.shapes[k];
        IndexedShape is;
        is.blockage = i;
        if (s.kind == Shape::Kind::Rect) {
          is.poly.outer = rect_ring(s.rect);
          is.box = s.rect;
        } else {
          is.poly = s.polygon;
          is.box = bbox_of(s.polygon.outer);
        }
        entries.emplace_back(to_bg(is.box), shapes_.size());
        shapes_.push_back(std::move(is));
      }
    }
    rtree_ = Rtree(entries.begin(), entries.end());  // bulk loading (packing)
  }

  std::vector<std::size_t> query(const Box& b) const {
    std::vector<IndexEntry> hits;
    rtree_.query(bgi::intersects(to_bg(b)), std::back_inserter(hits));
    std::vector<std::size_t> out;
    for (const auto& h : hits) out.push_back(h.second);
    std::sort(out.begin(), out.end());  // file order, so messages are deterministic
    return out;
  }

  void check_point_pin(Point p, const std::string& ctx, int line) {
    std::vector<const Polygon*> on_boundary;
    std::vector<std::size_t> owners;
    for (std::size_t k : query(Box{p, p})) {
      const IndexedShape& s = shapes_[k];
      const Location loc = geom::locate(p, s.poly);
      if (loc == Location::Inside) {
        error("LAYOUT-0004", line,
              ctx + " at " + pt(p) + " lies inside blockage " + q(layout_.blockages[s.blockage].id));
        return;
      }
      if (loc == Location::Boundary) {
        on_boundary.push_back(&s.poly);
        owners.push_back(s.blockage);
      }
    }
    if (on_boundary.size() < 2 || !covered_around(p, on_boundary)) return;
    std::sort(owners.begin(), owners.end());
    owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
    std::string names;
    for (std::size_t o : owners) names += (names.empty() ? "" : ", ") + q(layout_.blockages[o].id);
    error("LAYOUT-0004", line,
          ctx + " at " + pt(p) + " lies inside the union of blockage" +
              (owners.size() > 1 ? "s " : " ") + names + " (their shapes touch all around it)");
  }

  void check_shape_pin(const Shape& shape, const std::string& ctx, int line) {
    const Polygon poly = shape.kind == Shape::Kind::Rect ? Polygon{rect_ring(shape.rect), {}}
                                                         : shape.polygon;
    const Box box = bbox_of(poly.outer);
    if (layout_.boundary && !polygon_meets_box(poly, layout_.boundary->box))
      error("LAYOUT-0006", line, ctx + ": the pin shape lies outside the boundary");
    for (std::size_t k : query(box)) {
      const IndexedShape& s = shapes_[k];
      if (ring_inside_interior(poly.outer, box, s.poly, s.box)) {
        error("LAYOUT-0005", line,
              ctx + ": the pin shape lies inside blockage " + q(layout_.blockages[s.blockage].id));
        return;
      }
    }
  }


  void check_nets() {
    std::unordered_map<std::string, int> seen;
    for (const Net& net : layout_.nets) {
      const std::string ctx = "net " + q(net.name);
      if (net.name.empty()) error("LAYOUT-0017", net.line, "net: empty name");
      const auto [it, fresh] = seen.emplace(net.name, net.line);
      if (!fresh && !net.name.empty())
        error("LAYOUT-0002", net.line,
              ctx + ": name already used by the net on line " + std::to_string(it->second));
      if (net.pins.size() < 2 && !is_loop(net))  // a loop net (guard ring) needs no pins
        warning("LAYOUT-0007", net.line,
                ctx + ": has " + std::to_string(net.pins.size()) +
                    " pin(s), needs two or more; it will not be routed");
      std::unordered_map<std::string, int> pins;
      for (const Pin& pin : net.pins) {
        const std::string pctx = ctx + " pin " + q(pin.name);
        if (pin.name.empty()) error("LAYOUT-0017", pin.line, ctx + " pin: empty name");
        const auto [pit, pfresh] = pins.emplace(pin.name, pin.line);
        if (!pfresh && !pin.name.empty())
          error("LAYOUT-0003", pin.line,
                pctx + ": name already used by the pin on line " + std::to_string(pit->second));
        if (pin.point.has_value() == pin.shape.has_value()) {
          error("LAYOUT-0015", pin.line, pctx + ": must be either a point or a shape");
          continue;
        }
        if (pin.point) {
          if (!check_range(*pin.point, pin.line, pctx)) continue;
          if (layout_.boundary && !in_box(*pin.point, layout_.boundary->box))
            error("LAYOUT-0006", pin.line,
                  pctx + " at " + pt(*pin.point) + " lies outside the boundary");
          check_point_pin(*pin.point, pctx, pin.line);
        } else if (check_shape(*pin.shape, pctx)) {
          check_shape_pin(*pin.shape, pctx, pin.line);
        }
      }
      if (net.sketch) check_sketch(net, ctx);
    }
  }

  // A sketch whose last point is its first, around at least one other point: a loop (e.g. a
  // guard ring), tightened to the shortest closed loop of its class; it belongs to no pin.
  static bool is_loop(const Net& net) {
    if (!net.sketch || net.sketch->points.size() < 3) return false;
    const auto& pts = net.sketch->points;
    if (pts.front() != pts.back()) return false;
    for (Point p : pts)
      if (p != pts.front()) return true;
    return false;
  }

  void check_sketch(const Net& net, const std::string& ctx) {
    const Sketch& s = *net.sketch;
    for (Point p : s.points)
      if (!check_range(p, s.line, ctx + " sketch")) return;
    if (is_loop(net)) return;
    if (net.pins.size() != 2) {
      warning("LAYOUT-0009", s.line,
              ctx + " sketch: the net has " + std::to_string(net.pins.size()) +
                  " pins; a sketch is for 2-pin nets and is ignored");
      return;
    }
    if (s.points.empty()) return;
    const bool starts = point_on_pin(s.points.front(), net.pins[0]), ends = point_on_pin(s.points.back(), net.pins[1]);
    if (starts && ends) return;
    if (sketch_reversed(net)) {
      // drawn the other way round: it still joins the pins, and tighten and route --tighten
      // follow it; one warning, not one per end
      warning("LAYOUT-0008", s.line,
              ctx + " sketch: runs from the second pin " + q(net.pins[1].name) + " to the first " +
                  q(net.pins[0].name) + " (reversed)");
      return;
    }
    if (!starts)
      warning("LAYOUT-0008", s.line,
              ctx + " sketch: starts at " + pt(s.points.front()) + ", not on the first pin " +
                  q(net.pins[0].name));
    if (!ends)
      warning("LAYOUT-0008", s.line,
              ctx + " sketch: ends at " + pt(s.points.back()) + ", not on the second pin " +
                  q(net.pins[1].name));
  }

  void check_routes() {
    if (!layout_.routes) return;
    std::unordered_map<std::string, int> nets, routed;
    for (const Net& n : layout_.nets) nets.emplace(n.name, n.line);
    for (const Route& r : layout_.routes->routes) {
      const std::string ctx = "route " + q(r.net);
      if (!nets.count(r.net)) error("LAYOUT-0010", r.line, ctx + ": no net of that name");
      const auto [it, fresh] = routed.emplace(r.net, r.line);
      if (!fresh)
        error("LAYOUT-0011", r.line,
              ctx + ": the net was already routed on line " + std::to_string(it->second));
      for (const Wire& w : r.wires)
        for (Point p : w.points)
          if (!check_range(p, w.line, ctx + " wire")) break;
    }
  }

  using Rtree = bgi::rtree<IndexEntry, bgi::rstar<16>>;
  const Layout& layout_;
  std::vector<Diagnostic> diags_;
  std::vector<std::vector<bool>> valid_;  // per blockage, per shape
  std::vector<IndexedShape> shapes_;
  Rtree rtree_;
};

}  // namespace

std::vector<Diagnostic> validate_layout(const Layout& layout) { return Validator(layout).run(); }

}  // namespace taut::io
