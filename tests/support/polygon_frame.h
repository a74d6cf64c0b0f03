// Test support for simple rectilinear polygons (the link diameter's tests): the bounding box, a
// box as a ring, a ring in canonical order, and the L1 reference inside a polygon.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "geom/types.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "oracle/l1_oracle.h"
#include "router/link_polygon.h"

namespace taut::test {

// The free space of `taut gen channel --size size --seed seed` (no nets): one winding simple
// rectilinear polygon, counter-clockwise and cleaned. Throws if it is not one polygon.
inline geom::Ring channel_ring(std::int64_t size, std::uint64_t seed) {
  io::GenOptions go;
  go.kind = io::GenKind::Channel;
  go.size = size;
  go.nets = 0;
  go.seed = seed;
  const io::Layout layout = io::generate_layout(go);
  const router::FreeSpacePolygon f = router::free_space_polygon(layout.boundary->box, io::blockage_polygons(layout));
  if (f.status != router::FreeSpacePolygon::Status::Ok) throw std::logic_error("channel " + std::to_string(size) + ": not one polygon");
  return f.ring;
}

inline geom::Box ring_box(const geom::Ring& r) {
  geom::Box b{r[0], r[0]};
  for (const geom::Point p : r) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
  }
  return b;
}

// The box's corners, counter-clockwise from its lower left.
inline geom::Ring box_ring(const geom::Box& b) { return {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}; }

// The ring counter-clockwise, rotated to start at its lowest-then-leftmost vertex: equal shapes
// compare equal.
inline geom::Ring canonical(geom::Ring r) {
  if (geom::twice_area(r) < 0) std::reverse(r.begin(), r.end());
  const auto it = std::min_element(r.begin(), r.end(), [](geom::Point a, geom::Point b) {
    return a.y != b.y ? a.y < b.y : a.x < b.x;
  });
  std::rotate(r.begin(), it, r.end());
  return r;
}

// The L1 reference (tests/oracle/l1_oracle.h) with the polygon as its free space: a frame around
// the polygon's box with the polygon as its hole, clipped to the box. L1 distances inside a
// simple polygon, to check that a fewest-link path is also L1-shortest.
struct L1InPolygon {
  geom::NormalizedObstacles norm;
  std::unique_ptr<oracle::L1Reference> ref;
  explicit L1InPolygon(const geom::Ring& ring) {
    const geom::Box b = ring_box(ring);
    geom::Ring hole(ring.begin(), ring.end());
    if (geom::twice_area(hole) > 0) std::reverse(hole.begin(), hole.end());
    const geom::Box outer{{b.lo.x - 1, b.lo.y - 1}, {b.hi.x + 1, b.hi.y + 1}};
    const geom::Polygon frame[1] = {geom::Polygon{box_ring(outer), {hole}}};
    norm = geom::normalize_obstacles(frame, b);
    ref = std::make_unique<oracle::L1Reference>(norm.domain, norm.obstacles);
  }
};

}  // namespace taut::test
