#include "tools/route_common.h"

#include <cstdio>

#include "geom/predicates.h"
#include "io/layout_geometry.h"

namespace taut::cli {

geom::NormalizedObstacles routing_obstacles(const io::Layout& layout,
                                            std::span<const geom::Point> extra) {
  const geom::Box domain = io::routing_domain(layout, extra);
  return geom::normalize_obstacles(io::blockage_polygons(layout), domain);
}

std::string point_text(geom::Point p) { return std::to_string(p.x) + "," + std::to_string(p.y); }

std::string length_text(const geom::Root2& length) {
  if (length.b == 0) return std::to_string(length.a);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", length.to_double());
  return std::string(buf) + " (" + std::to_string(length.a) + (length.b < 0 ? "-" : "+") +
         std::to_string(length.b < 0 ? -length.b : length.b) + "*sqrt2)";
}

std::string why_not_free(const io::Layout& layout, geom::Point p) {
  const std::string where = " (" + layout.file + ":";
  if (layout.boundary) {
    const geom::Box& b = layout.boundary->box;
    if (p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y)
      return "lies outside the boundary" + where + std::to_string(layout.boundary->line) + ")";
  }
  for (const io::Blockage& blk : layout.blockages)
    for (const io::Shape& s : blk.shapes)
      if (geom::locate(p, io::shape_polygon(s)) == geom::Location::Inside)
        return "lies inside blockage \"" + blk.id + "\"" + where + std::to_string(s.line) + ")";
  return "is not in free space: it is enclosed where blockages touch or overlap, or lies on a "
         "blockage edge flush with the boundary";
}

}  // namespace taut::cli
