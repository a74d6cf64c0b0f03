// Minimum-link c-oriented paths of a given homotopy class (Hershberger & Snoeyink, seeds/001,
// section 6.3): the path with the fewest links among all paths homotopic to a given one, with the
// same ends, whose every link runs in one of the directions of a set (the lattice sets of
// geom/directions.h: rectilinear, octilinear, c:0,45,90, ...), of any length.
//
//   const router::Tightener tight(t);
//   const router::Tightened r = tight.tighten(sketch);   // the shortest path of the class
//   const router::CMinLinker cm(t);
//   const router::CMinLinkPath m = cm.path(r.points, geom::LatticeDirections::octilinear());
//   if (m.ok()) use(m.points);                            // exact rationals
//
// Link regions. R_i, the points of the universal cover U that a c-oriented path of i links from p
// reaches, grows link by link: every link into the component Q_i of U - R_i that holds q crosses
// its frontier F_i = boundary(Q_i) - boundary(U), so R_{i+1} inside Q_i is the union of the sweeps
// V(d, s): for a frontier segment s and a direction d of the set pointing into Q_i from s, the
// closed maximal rays in direction d from the points of s. Lemma 6.4: F_i is at most two segments
// from one point r (the corner). The algorithm keeps F_i and nothing else:
//   - the first frontier: the rays from p in the two directions that bracket the taut path's first
//     edge (or, when that edge runs along a direction, the ray along it beyond the taut path's
//     first bend, which the blockage there bounds);
//   - each step computes every sweep of the frontier and the last point E of the taut path alpha
//     (from p to q) in their union. E = q: one more link reaches q. Otherwise E lies on the
//     maximal ray s of some sweep V(d, s0), and alpha leaves it into Q_{i+1} on one side of s.
//     Walking back along s from E, the frontier follows s until (a) material of a blockage
//     touches s on that side (then F_{i+1} is s from there on: the tangent case of the lemma's
//     proof, "the segment of t following b") or (b) another sweep's ray t crosses s (then
//     F_{i+1} is s and t from that point r', the first case and the second half of the tangent
//     case). Each frontier segment remembers where its ray starts (on the previous frontier), so
//     the links are read back from q: the last from the point of the final sweep's segment whose
//     ray holds q, each earlier one along a frontier segment's line from its start.
// This is the greedy of the paper with its two candidate paths and extreme tangents found as the
// boundary of the union of the sweeps, instead of by the paper's case analysis.
//
// The cover. Lifted triangles are named relative to alpha's sleeve (Tightener::lift): a sleeve
// index, or a reduced walk of triangle edges leaving the sleeve (interned, so one lifted triangle
// has one name). A sweep is a breadth-first search of pieces (lifted triangle, closed interval of
// the rays' offsets cross(d, x)) across the edges its rays leave through; a constrained edge
// stops them. A ray through a vertex goes on into the free triangle beyond it only inside the
// vertex's free fan (pieces of one offset flood round the fan across the edges the direction
// leaves through): touching blockages, running along their edges and grazing their corners are
// allowed, passing through a point where two blockages touch is not (FORMAT.md). The points of
// alpha are looked up in the lifted triangles that hold them (its sleeve, the fans at its
// vertices, the triangles across edges it runs along).
//
// Exactness. Rays start at rational points (the corners and the starts of the rays), so all
// geometry here is in GMP rationals (Boost.Multiprecision); vertex offsets are integers; no
// predicate is decided in floating point. The bends of the result are rationals: intersections
// of lines of the set through rational points (through a blockage vertex or the end of another
// ray); they need not be integers (two diagonals through integer points meet at half-integers).
//
// Cost. Each step computes up to 2 x (c - 1) sweeps of the two frontier segments, each over the
// part of the cover its rays reach: O(k c n) for k links in the worst case (the paper's bound),
// far less when the rays are short.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "geom/directions.h"
#include "geom/triangulation.h"
#include "geom/types.h"
#include "router/spm.h"  // Rational, RPoint

namespace taut::router {

struct CMinLinkPath {
  std::vector<RPoint> points;  // the ends and the bends; empty when there is no such path
  std::string why;             // when points is empty: why there is no c-oriented path
  bool ok() const { return !points.empty(); }
  std::size_t links() const { return points.empty() ? 0 : points.size() - 1; }
  // Work done: sweeps computed and the pieces (lifted triangle, offset interval) they visited.
  std::size_t sweeps = 0, pieces = 0;
};

class CMinLinker {
 public:
  // The triangulation must outlive the CMinLinker and be ok().
  explicit CMinLinker(const geom::FreeSpaceTriangulation& t);

  // A minimum-link path homotopic to `taut` in the directions of `set`, which must be a shortest
  // path of its class as Tightener::tighten returns it (its lift must succeed). A one-point path
  // has 0 links. No path (`why` says which end) when no direction of the set leaves p's free
  // wedge or enters q's. Throws std::invalid_argument when `taut` does not lift, and
  // std::logic_error when a step makes no progress (a bug) or the links pass `max_links`.
  CMinLinkPath path(std::span<const geom::Point> taut, const geom::LatticeDirections& set,
                    std::size_t max_links = 4096) const;

 private:
  const geom::FreeSpaceTriangulation* t_;
};

}  // namespace taut::router
