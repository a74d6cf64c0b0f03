#include "io/layout_geometry.h"

#include <algorithm>
#include <cstdint>

#include "geom/normalize.h"
#include "geom/predicates.h"

namespace taut::io {

geom::Polygon shape_polygon(const Shape& shape) {
  if (shape.kind == Shape::Kind::Polygon) return shape.polygon;
  const Box& b = shape.rect;
  return geom::Polygon{{b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}, {}};
}

std::vector<geom::Polygon> blockage_polygons(const Layout& layout,
                                             std::vector<std::size_t>* owner) {
  std::vector<geom::Polygon> out;
  if (owner) owner->clear();
  for (std::size_t i = 0; i < layout.blockages.size(); ++i) {
    for (const Shape& s : layout.blockages[i].shapes) {
      out.push_back(shape_polygon(s));
      if (owner) owner->push_back(i);
    }
  }
  return out;
}

geom::Polygon pin_polygon(const Pin& pin) {
  if (pin.point) return geom::Polygon{{*pin.point}, {}};
  geom::Polygon g = shape_polygon(*pin.shape);
  // a vertex written twice in a row (valid: FORMAT.md asks for 3 distinct vertices) once, so no
  // edge of length zero reaches the routers (which refused it as an edge at no supported angle,
  // ROUTE-0005, before 2026-12-05)
  auto once = [](geom::Ring& r) {
    r.erase(std::unique(r.begin(), r.end()), r.end());
    while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  };
  once(g.outer);
  for (geom::Ring& h : g.holes) once(h);
  return g;
}

geom::Box routing_domain(const Layout& layout, std::span<const geom::Point> extra) {
  if (layout.boundary) return layout.boundary->box;
  bool any = false;
  std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  auto add = [&](geom::Point p) {
    if (!any) {
      x0 = x1 = p.x;
      y0 = y1 = p.y;
      any = true;
      return;
    }
    x0 = std::min<std::int64_t>(x0, p.x);
    y0 = std::min<std::int64_t>(y0, p.y);
    x1 = std::max<std::int64_t>(x1, p.x);
    y1 = std::max<std::int64_t>(y1, p.y);
  };
  auto add_polygon = [&](const geom::Polygon& poly) {
    for (geom::Point p : poly.outer) add(p);  // holes lie inside the outer ring
  };
  for (const Blockage& b : layout.blockages)
    for (const Shape& s : b.shapes) add_polygon(shape_polygon(s));
  for (const Net& n : layout.nets)
    for (const Pin& pin : n.pins) {
      if (pin.point) add(*pin.point);
      if (pin.shape) add_polygon(shape_polygon(*pin.shape));
    }
  for (geom::Point p : extra) add(p);
  const std::int64_t m = geom::kDomainMargin;
  // nothing drawn (no blockage, pin or point): the margin round the origin, so the domain is
  // never empty (the triangulation of tightening refuses an empty one; taut tighten on such a
  // file was an internal error, found by fuzzing on 2026-12-06)
  if (!any) return geom::Box{{-m, -m}, {m, m}};
  auto clamp = [](std::int64_t v) {
    return static_cast<geom::Coord>(std::clamp<std::int64_t>(v, -geom::kMaxCoord, geom::kMaxCoord));
  };
  return geom::Box{{clamp(x0 - m), clamp(y0 - m)}, {clamp(x1 + m), clamp(y1 + m)}};
}

std::size_t blockage_vertex_count(const Layout& layout) {
  std::size_t n = 0;
  for (const Blockage& b : layout.blockages)
    for (const Shape& s : b.shapes) {
      if (s.kind == Shape::Kind::Rect) {
        n += 4;
        continue;
      }
      n += s.polygon.outer.size();
      for (const auto& h : s.polygon.holes) n += h.size();
    }
  return n;
}

bool point_on_pin(geom::Point p, const Pin& pin) {
  if (pin.point) return *pin.point == p;
  if (!pin.shape) return false;
  if (pin.shape->kind == Shape::Kind::Rect) {
    const geom::Box& b = pin.shape->rect;
    return b.lo.x <= p.x && p.x <= b.hi.x && b.lo.y <= p.y && p.y <= b.hi.y;
  }
  return geom::locate(p, pin.shape->polygon) != geom::Location::Outside;
}

bool sketch_reversed(const Net& net) {
  if (!net.sketch || net.sketch->points.empty() || net.pins.size() != 2) return false;
  const auto& pts = net.sketch->points;
  return point_on_pin(pts.front(), net.pins[1]) && point_on_pin(pts.back(), net.pins[0]);
}

std::string sketch_off_pins(const Net& net) {
  if (!net.sketch || net.sketch->points.empty() || net.pins.size() != 2) return {};
  const auto& pts = net.sketch->points;
  auto text = [](geom::Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; };
  if (sketch_reversed(net)) return {};  // drawn from the second pin to the first, it joins them too
  if (!point_on_pin(pts.front(), net.pins[0]))
    return "starts at " + text(pts.front()) + ", not on the first pin \"" + net.pins[0].name + "\"";
  if (!point_on_pin(pts.back(), net.pins[1]))
    return "ends at " + text(pts.back()) + ", not on the second pin \"" + net.pins[1].name + "\"";
  return {};
}

}  // namespace taut::io
