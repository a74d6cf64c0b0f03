// Geometry of a layout's objects as geom types: the bridge between the file model (io) and the
// algorithms (geom, router), so neither has to know the other.
#pragma once

#include <cstddef>
#include <vector>

#include "geom/types.h"
#include "io/layout.h"

namespace taut::io {

// A <rect> or <polygon> shape as a polygon (a rect becomes its 4 corners, counter-clockwise).
geom::Polygon shape_polygon(const Shape& shape);

// Every blockage shape as a polygon, in file order; owner[i] is the index of the blockage that
// polygon i belongs to (when owner is not null).
std::vector<geom::Polygon> blockage_polygons(const Layout& layout,
                                             std::vector<std::size_t>* owner = nullptr);

// Number of vertices written in blockage shapes (a rect counts 4).
std::size_t blockage_vertex_count(const Layout& layout);

}  // namespace taut::io
