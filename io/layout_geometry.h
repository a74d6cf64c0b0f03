// Geometry of a layout's objects as geom types: the bridge between the file model (io) and the
// algorithms (geom, router), so neither has to know the other.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "geom/types.h"
#include "io/layout.h"

namespace taut::io {

// A <rect> or <polygon> shape as a polygon (a rect becomes its 4 corners, counter-clockwise).
geom::Polygon shape_polygon(const Shape& shape);

// A pin as the routers take it: a point pin as an outer ring of that one point, a shape pin as
// shape_polygon() of its shape with each vertex written twice in a row taken once.
geom::Polygon pin_polygon(const Pin& pin);

// Every blockage shape as a polygon, in file order; owner[i] is the index of the blockage that
// polygon i belongs to (when owner is not null).
std::vector<geom::Polygon> blockage_polygons(const Layout& layout,
                                             std::vector<std::size_t>* owner = nullptr);

// The area routing happens in: the <boundary> when there is one; otherwise the bounding box of
// every blockage vertex, every point pin and shape-pin vertex and the `extra` points, grown by
// geom::kDomainMargin on each side and clamped to the coordinate limit. Without a boundary the
// plane is unbounded, and a shortest L1 path never needs to leave that box: clamping a path
// into a box that holds every obstacle with a margin and both ends keeps it free and never
// lengthens it. With nothing at all, the margin round the origin (never an empty box).
geom::Box routing_domain(const Layout& layout, std::span<const geom::Point> extra = {});

// Number of vertices written in blockage shapes (a rect counts 4).
std::size_t blockage_vertex_count(const Layout& layout);

// Whether p lies on the pin: the point pin itself, or in the closed pin shape.
bool point_on_pin(geom::Point p, const Pin& pin);

// Why a two-pin net's open <sketch> does not join its pins ("starts at (x,y), not on the first
// pin \"a\"", or the end and the second pin), or "" when it does, from either pin to the other
// (LAYOUT-0008 warns of any other order; the tightening commands cannot take a sketch that misses
// a pin as the net's wire).
std::string sketch_off_pins(const Net& net);
// A two-pin net's open <sketch> that starts on its second pin and ends on its first: it joins
// them the other way round (sketch_off_pins takes it; LAYOUT-0008 warns of the order).
bool sketch_reversed(const Net& net);

}  // namespace taut::io
