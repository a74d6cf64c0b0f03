// Shape pins (FORMAT.md: a wire may end anywhere on a pin's shape): the finite set of points of
// a shape some optimal wire may be taken to start or end at, for every router that takes shape
// pins (the L1 and octilinear routers, router/l1_router.h, and the bend-aware router,
// router/bend_router.h), and the checks those routers need of a shape.
//
// A pin is a geom::Polygon: a point is an outer ring of one vertex and no holes; a shape is a
// closed polygon with holes, integer vertices, rings in either orientation.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "geom/types.h"

namespace taut::router {

// Calls f(a, b) for every edge of the pin's rings (closing edges included; nothing for a point).
template <class F>
void for_each_pin_edge(const geom::Polygon& pin, F f) {
  auto ring_edges = [&](const geom::Ring& r) {
    if (r.size() < 2) return;
    for (std::size_t i = 0; i < r.size(); ++i) f(r[i], r[(i + 1) % r.size()]);
  };
  ring_edges(pin.outer);
  for (const geom::Ring& h : pin.holes) ring_edges(h);
}

// A point pin: one vertex, no holes.
bool is_point_pin(const geom::Polygon& pin);
// The closed pin holds p.
bool in_pin(geom::Point p, const geom::Polygon& pin);

// A pin the routers take: a point, or rings of at least 3 vertices whose every edge (closing ones
// included) has non-zero length and is horizontal, vertical or at 45 degrees.
bool pin_shape_supported(const geom::Polygon& pin);

// An integer point two pins share for which `usable` holds (the routers: a free point), or
// nullopt: the first of a's candidates lying in b, else the first of b's lying in a, else a
// point where an edge of a meets an edge of b. Why that finds one whenever the pins share a
// usable integer point away from the free space's own boundary: their intersection is a polygon
// with edges at 0, 45 and 90 degrees whose vertices are vertices of one pin lying in the other
// (candidates), crossings of an axis-parallel edge with another edge (integer: projections of a
// vertex, so candidates too), or crossings of a 45-degree edge with a 135-degree one, which can
// be half-integer points (x - y and x + y of different parity): then the integer points a half
// diagonal away along each of the two edges are on the intersection's boundary (its edges run
// at least that far), so those neighbours are tried.
std::optional<geom::Point> shared_point(std::span<const geom::Point> a_cands, const geom::Polygon& a,
                                        std::span<const geom::Point> b_cands, const geom::Polygon& b,
                                        const std::function<bool(geom::Point)>& usable);

// Does the interior of a shape pin meet the interior of an obstacle (as geom::normalize_obstacles
// returns them: outer ring counter-clockwise, holes clockwise)? Exact; false for a point pin.
// (PinShapes::meets_obstacle makes the same test of each obstacle whose box meets the pin's.)
bool shape_meets_obstacle(const geom::Polygon& pin, const geom::Polygon& obstacle);

// Shape pins among one set of obstacles.
class PinShapes {
 public:
  // Obstacles as geom::normalize_obstacles() returns them; the domain (the closed routing box),
  // when there is one: its corners' rows and columns are projected as the obstacle vertices' are,
  // and so are the points where the other pin's edges cross its sides.
  // octilinear: candidates() adds the diagonal projections onto 45-degree edges (below).
  explicit PinShapes(std::span<const geom::Polygon> obstacles, std::optional<geom::Box> domain = std::nullopt,
                     bool octilinear = false);

  // The points of pin `pin` an optimal wire from it may be taken to start at: its vertices, and
  // the horizontal and vertical projections onto its edges of every obstacle vertex, domain
  // corner, vertex of `other` (the other pin, or every other pin) and point where an edge of
  // `other` crosses a domain side. Sorted, distinct; for edges at 0, 45 or 90 degrees every
  // candidate is an integer point.
  //
  // Why that suffices, for L1 (and octilinear) length: a shortest path leaves the pin at s
  // straight towards its first bend r (an obstacle vertex, or a point of the other pin when it
  // runs straight there), so s minimises |s - r|_1 over the part of an edge that r sees; along
  // an edge that is a convex piecewise-linear function whose breakpoints are the projections of
  // r, so its minimum is at a projection, at an edge end, or where the sight of r ends at an
  // obstacle vertex v on the segment r-s (the path through v is as short, and v takes r's
  // place). When r is a point of the other pin the pair (s, r) minimises |s - r|_1 over two
  // edges, which is attained with s or r a vertex, the other its projection or a vertex too.
  // Octilinear: along a horizontal edge the octilinear length of s - r, max(|dx|, |dy|) +
  // (sqrt2 - 1) min(|dx|, |dy|) with |dy| fixed, is convex and least where dx = 0, at r's
  // vertical projection (likewise for vertical edges), so the argument holds as it is; along a
  // 45-degree edge it is convex with three breakpoints, where dx = 0, where dy = 0 (r's vertical
  // and horizontal projections) and where |dx| = |dy| (r's projection along the other diagonal),
  // so with `octilinear` the candidates add, on each 45-degree edge, the projections along the
  // other diagonal of the same points (obstacle vertices, domain corners, the other pin's points
  // above). Such a projection is a half-integer point when x + y of the point and x - y of the
  // edge's line differ in parity; wire vertices are integers, and a convex function's least value
  // over the integer points of the edge is at one of the two integer points beside its least
  // point, so both are taken (tests/router/pin_test.cpp checks the lengths against every pair
  // of free integer points of two shapes).
  //
  // For length + C * bends and for the link metric (rectilinear paths): take an optimal path and
  // let s be its last point on the pin. If s is not a vertex, slide the first link sideways,
  // keeping s on its edge and the second link on its line: the first link's length changes by
  // 0 (edge across the link) or by the slide (45-degree edge), the second link's by the slide, so
  // the cost is linear in the slide and one way it does not grow. Slide that way until s reaches
  // a vertex of the pin, or the first link meets an obstacle vertex (s is then that vertex's
  // projection), or the second link vanishes (one bend fewer: go on with the shorter path). A
  // path of one link from pin to pin slides with both ends on their edges: it stops at a vertex
  // of one pin (the other end is that vertex's projection), where one end leaves the domain (a
  // pin may reach past it: the end is a domain side's crossing with its edge, the other end that
  // crossing's projection) or at an obstacle vertex (both ends are its projections). Such paths never leave the closed free space: what they sweep holds no
  // obstacle vertex until they stop, and an obstacle edge cannot cross the pin's edge, since the
  // pin does not overlap obstacles (meets_obstacle()). The bend router's tests check this
  // against a search from every integer point of the shapes.
  std::vector<geom::Point> candidates(const geom::Polygon& pin, const geom::Polygon& other) const;

  // Octilinear, for a plane whose wires are then snapped to multiples of k (NetRouter's scaled
  // plane; BasicRouter::set_lattice): the projections along the other diagonal onto a 45-degree
  // edge are rounded down and up to multiples of k in x instead of to integers, so none lies
  // halfway between two of them (the same convexity argument, over the coarser lattice; exact
  // for edges whose line is a multiple of k, as a scaled pin's are). 1 (the default): integers.
  void set_lattice(std::int64_t k);

  // The first obstacle (index into the constructor's obstacles) whose interior meets the
  // interior of a shape pin, exactly; nullopt for a point pin or a shape that at most touches
  // obstacles. The routers need shapes that do not: a shape partly under a blockage may be left
  // through the blockage's edges, which candidates() does not cover.
  std::optional<std::size_t> meets_obstacle(const geom::Polygon& pin) const;

  // The distinct x and y of the obstacle vertices and the domain's corners, ascending (what
  // candidates() projects).
  const std::vector<geom::Coord>& vertex_xs() const { return xs_; }
  const std::vector<geom::Coord>& vertex_ys() const { return ys_; }

 private:
  std::vector<geom::Coord> xs_, ys_;  // the distinct x and y of obstacle vertices, ascending
  bool octilinear_ = false;
  std::int64_t lattice_ = 1;  // set_lattice()
  std::vector<std::int64_t> sums_, diffs_;  // octilinear: their distinct x + y and x - y, ascending
  std::optional<geom::Box> domain_;
  std::vector<geom::Polygon> obstacles_;
  std::vector<geom::Box> boxes_;
};

}  // namespace taut::router
