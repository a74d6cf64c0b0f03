#include "io/layout_geometry.h"

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

}  // namespace taut::io
