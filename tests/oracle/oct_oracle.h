// Brute-force exact OCTILINEAR shortest paths among obstacles: the reference an octilinear
// wavefront is to be checked against. The octilinear length of a vector (dx, dy) is
// d8 = (max(|dx|,|dy|) - min(|dx|,|dy|)) + min(|dx|,|dy|) * sqrt(2), the length of the shortest
// path from 0 to (dx, dy) in the four orientations 0, 45, 90 and 135 degrees; it is a norm (unit
// ball: an octagon). Lengths are exact a + b*sqrt(2) numbers (geom/root2.h).
//
// Same contract as L1Reference (l1_oracle.h): the same free space, wedges, pinch rule and
// domain rule, the same allowed segments, and the same visibility graph (class VisibilityGraph,
// built once per reference), with each edge weighted by its d8 length instead of its L1 length.
// Why that is exact: as in l1_oracle.h, the taut path of the homotopy class of a shortest path
// is shortest for every convex distance function (Hershberger-Snoeyink, Theorem 6.2), d8 among
// them, and it bends only at obstacle vertices (one wedge each); so Dijkstra on the graph gives
// the least d8 length over all allowed polygonal paths, each measured segment by segment.
//
// What the number means for wires in the four orientations only: a segment of any direction
// measured by d8 is as long as the octilinear staircases that approach it, so distance() is the
// infimum of the lengths of allowed octilinear paths. It is attained in free space and, for
// axis-parallel rectangles with integer corners, by a path with integer bends (the lattice
// argument of oct_oracle_test.cpp); along a sloped obstacle edge a staircase may only approach
// it. path() returns the visibility path (segments of any direction, bends at obstacle
// vertices), not an octilinear one.
//
// Cost as L1Reference: O(n^3) to build, for n up to a few hundred vertices. Not thread-safe:
// problems() is appended to by const queries.
#pragma once

#include <optional>
#include <span>

#include "geom/root2.h"
#include "geom/types.h"
#include "oracle/l1_oracle.h"

namespace taut::oracle {

// VisibilityGraph with Metric::Octilinear: distance(), distances(), path(), wedges_at(),
// is_free(), visible(), check_path(), problems() as documented there, with d8 lengths. path()
// has segments of any direction, whose d8 lengths add up to distance(s, t); check_path()
// measures a polygonal path of any directions by d8.
class OctilinearReference : public VisibilityGraph {
 public:
  // Obstacles as for L1Reference (geom::normalize_obstacles() output).
  OctilinearReference(const geom::Box& domain, std::span<const geom::Polygon> obstacles)
      : VisibilityGraph(domain, obstacles, Metric::Octilinear) {}

  // check_path, and also every segment horizontal, vertical or at +-45 degrees (else nullopt):
  // for wires of the octilinear router.
  std::optional<geom::Root2> check_octilinear_path(std::span<const geom::Point> path) const;
};

// The segment ab is horizontal, vertical or diagonal (a == b counts as octilinear).
bool is_octilinear(geom::Point a, geom::Point b);

}  // namespace taut::oracle
