// Validity of polygons as users write them (FORMAT.md): every problem with a stable code.
//
// A ring lists >= 3 distinct vertices in either orientation (closing vertex already dropped by
// the reader); it must be simple: no self-intersection, no zero-area spike. Holes lie inside
// their shell and do not overlap each other. Consecutive repeated vertices and collinear
// vertices are allowed (normalization removes them). O(n log n) expected: candidate edge pairs
// come from an R-tree; each pair is decided exactly.
//
// Codes (at most one problem per code and ring; hole relations once per hole or hole pair):
//   GEOM-0001 fewer than 3 distinct vertices
//   GEOM-0002 zero area: all vertices collinear
//   GEOM-0003 self-intersection: two non-adjacent edges cross, touch or overlap (a ring that
//             passes twice through one vertex is invalid); the message names both edges
//   GEOM-0004 spike: the boundary turns back 180 degrees at a vertex (consecutive edges
//             overlap); reported instead of GEOM-0003 for that adjacent pair
//   GEOM-0005 hole not inside its shell: crosses it, overlaps an edge of it, lies outside it,
//             or meets it in two or more points
//   GEOM-0006 two holes cross, overlap, nest, or meet in two or more points
//   GEOM-0007 coordinate out of range (|v| > 2^30 - 1); the ring is not checked further
//   GEOM-0008 interior disconnected: holes and shell, each pair touching at one point, form
//             a cycle (e.g. three holes touching pairwise at three different points)
// A hole may touch its shell, and two holes may touch each other, at ONE point (a vertex of
// either ring); this is allowed unless it disconnects the interior (GEOM-0008). Relations
// (0005, 0006, 0008) are only checked between rings that passed 0001-0004 and 0007.
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
