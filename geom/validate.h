// Validity of polygons as users write them (FORMAT.md): every problem with a stable code.
//
// A ring lists >= 3 distinct vertices in either orientation (closing vertex already dropped by
// the reader); it must be simple: no self-intersection, no zero-area spike. Holes lie inside
// their shell and do not overlap each other. Consecutive repeated vertices and collinear
// vertices are allowed (normalization removes them). Codes GEOM-0001 .. GEOM-0019.
// O(n log n) expected: candidate edge pairs come from an R-tree; each pair is decided exactly.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "geom/types.h"

namespace taut::geom {

struct PolygonProblem {
  std::string code;     // "GEOM-00xx"
  std::string message;  // what is wrong, with the coordinates of the place
  int ring = -1;        // -1 outer ring, k >= 0 hole k (for file:line of the <hole>)
};

// Problems of a polygon with holes; empty when valid.
std::vector<PolygonProblem> validate_polygon(const Polygon& polygon);
// Problems of one ring on its own (the ring field of each problem is -1).
std::vector<PolygonProblem> validate_ring(const Ring& ring);

}  // namespace taut::geom
