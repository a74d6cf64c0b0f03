// Shortest wires in a direction set at multiples of 30 degrees (geom/root3_directions.h:
// c:0,60,120 and the like), H&S §6.2 and §6.4, in the homotopy class of a taut wire.
//
//   Root3StaircaseBuilder b(norm.domain, norm.obstacles);
//   Root3Wire w = b.staircase(taut, *geom::Root3Directions::parse("c:0,60,120"));
//   if (w.ok()) { /* w.points: integer vertices, every segment fits the set */ }
//
// Method (as StaircaseBuilder::staircase_in_class for the lattice sets, router/staircase.h and
// docs/DESIGN.md). The taut wire is the class's shortest under every convex distance (Theorem
// 6.2), and every shortest wire in the set passes through its points whose tangent is a direction
// of the set (Lemma 6.3): its vertices where consecutive segments are not strictly inside one cone.
// Between two such cuts the shortest wires are the monotone staircases of the cone's two
// directions s1, s2 (Lemma 6.1) that pass every blockage on the side the taut piece does. In the
// piece's frame (a point p = a + u s1 + v s2 has coordinates (U, V) = D (u, v), D = cross(s1, s2),
// which lie in Z[sqrt3] for integer points) the taut piece increases in U and V, every blockage
// edge in the box [0, U(b)] x [0, V(b)] is clipped and classified as above or below it, and a
// staircase is in the class iff it avoids the open up-left quadrant of every point above and the
// open down-right quadrant of every point below: a staircase polygon, where the greedy that
// alternates maximal runs has the fewest links for its first direction. Both first directions are
// tried and a DP joins the pieces (a run continuing across a cut saves a link). There is no
// lattice here, so runs are not floored: their ends are numbers a + b sqrt3 with rational a and b
// (router/rational_root.h), exact. The exact wire's vertices are then rounded to integers: to the
// nearest (ties upwards), which keeps every segment within the rounding of a direction of the set
// (Root3Directions::fits), unless that makes a segment leave free space (a run that grazes a
// blockage's corner may cut it once its ends move by half a unit): then a DP over the sixteen
// integer points round each vertex (floor - 1 to floor + 2 in each coordinate; every segment's
// rule is checked, so a vertex moved farther than its rounding still leaves each segment within
// half a unit at each end of a direction) takes, with the fewest vertices off their nearest, a
// wire whose every segment fits the set and is free (`free`, the
// caller's test; nothing when there is none), and failing that the same for the exact wire with
// the taut wire's cut points that lie inside a link kept as vertices (integer points, the corners
// it wraps, which a rounded link could cut). The whole rounded wire is not checked here: the
// caller tightens it back to the taut wire (free space and class) as for the lattice sets.
//
// When there is none. H&S §6 assume blockage edges in the set's directions; with others (a
// vertical edge under c:0,60,120) a wedge narrower than a cone can ask for infinitely many runs,
// so a piece whose greedy passes `max_runs_per_piece` (or gets stuck, which a valid taut piece
// does not) has no wire here, and `why` says so.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "geom/root3.h"
#include "geom/index.h"
#include "geom/root3_directions.h"
#include "geom/types.h"
#include "router/rational_root.h"

namespace taut::router {

struct Root3Wire {
  std::vector<geom::Point> points;  // the exact wire rounded (repeated points dropped)
  int moved = 0;                    // vertices not at their nearest integer point (see above)
  std::vector<R3Point> exact;       // the exact wire: every link along a direction of the set
  std::string why;                  // empty when there is a wire
  bool ok() const { return why.empty(); }
};

class Root3StaircaseBuilder {
 public:
  // obstacles as geom::normalize_obstacles() returns them (outer rings counter-clockwise).
  Root3StaircaseBuilder(const geom::Box& domain, std::span<const geom::Polygon> obstacles);
  // taut: the class's Euclidean shortest path as router::Tightener returns it (open, integer
  // vertices, at least one point).
  // free(p, q): the segment p q lies in free space (the caller's test, e.g. a Tightener's lift).
  Root3Wire staircase(std::span<const geom::Point> taut, const geom::Root3Directions& set,
                      const std::function<bool(geom::Point, geom::Point)>& free) const;
  // A guard against the infinitely many runs above (a channel of constant width across the
  // set's directions takes about its length over its width runs, finite).
  std::size_t max_runs_per_piece = 256;

 private:
  // Rounds `exact` into out.points (and out.moved); false when no rounding is free.
  static bool round_wire(const std::vector<R3Point>& exact, const geom::Root3Directions& set,
                         const std::function<bool(geom::Point, geom::Point)>& free, Root3Wire& out);
  geom::Box domain_;
  geom::ObstacleIndex index_;          // the obstacles' edges, each with the obstacle on its left
  std::vector<geom::Segment> sides_;   // the domain's, the outside on their left
};

}  // namespace taut::router
