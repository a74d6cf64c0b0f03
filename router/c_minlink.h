// Minimum-link c-oriented paths of a given homotopy class (Hershberger & Snoeyink, seeds/001,
// section 6.3): the path with the fewest links among all paths homotopic to a given one, with the
// same ends, whose every link runs in one of the directions of a set (the lattice sets of
// geom/directions.h: rectilinear, octilinear, c:0,45,90, ...; and, since 2026-12-07, the sets
// at multiples of 30 degrees of geom/root3_directions.h: c:0,60,120, ...), of any length.
// CMinLinker::loop does the same for a loop (its free homotopy class), from starts on the
// shortest loop, with a lower bound that proves most of them minimal.
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
// In a set at multiples of 30 degrees the steps have coordinates in Z[sqrt3], so the same
// algorithm (one template over the kind of set) runs with points and parameters in Q(sqrt3)
// (RationalRoot3: rational pairs, exact signs) and offsets of vertices in Z[sqrt3]; its bends
// are numbers a + b sqrt3.
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
#include "geom/root3_directions.h"
#include "geom/triangulation.h"
#include "geom/types.h"
#include "router/minlink.h"  // MinLinkLoop
#include "router/rational_root.h"  // R3Point
#include "router/spm.h"  // Rational, RPoint

namespace taut::router {

template <class P>
struct CMinLinkPathOf {
  std::vector<P> points;  // the ends and the bends; empty when there is no such path
  std::string why;             // when points is empty: why there is no c-oriented path
  bool ok() const { return !points.empty(); }
  std::size_t links() const { return points.empty() ? 0 : points.size() - 1; }
  // Work done: sweeps computed and the pieces (lifted triangle, offset interval) they visited.
  std::size_t sweeps = 0, pieces = 0;
};

// A closed path (front == back) in the directions of a set, freely homotopic to a given loop,
// with few links (the loop version of section 6.3, which the paper leaves open; see
// CMinLinker::loop for what is proven).
template <class P>
struct CMinLinkLoopOf {
  std::vector<P> points;  // the bends, closed: points.front() == points.back(); empty when none found
  std::string why;             // when points is empty: why
  bool ok() const { return !points.empty(); }
  std::size_t links() const { return points.empty() ? 0 : points.size() - 1; }
  // A lower bound on the links of every loop of the class in the set's directions (see loop());
  // the loop is proven minimal when it has that many.
  std::size_t at_least = 3;
  bool minimal = false;
  std::size_t starts = 0;  // paths computed (from vertices of the shortest loop)
};

// Lattice sets: rational points. Sets at multiples of 30 degrees: points in Q(sqrt3).
using CMinLinkPath = CMinLinkPathOf<RPoint>;
using CMinLinkPath3 = CMinLinkPathOf<R3Point>;
using CMinLinkLoop = CMinLinkLoopOf<RPoint>;
using CMinLinkLoop3 = CMinLinkLoopOf<R3Point>;

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
  // The same in a set at multiples of 30 degrees (geom/root3_directions.h): exact bends in
  // Q(sqrt3), links exactly along the set's directions (not rounded to integers).
  CMinLinkPath3 path(std::span<const geom::Point> taut, const geom::Root3Directions& set,
                     std::size_t max_links = 4096) const;

  // A loop in the directions of `set` freely homotopic to `taut_loop`, which must be a shortest
  // loop of its class as Tightener::tighten_loop returns it (closed, every vertex a strict turn at
  // a triangulation vertex; not contractible), with few links:
  //   - upper bound: from a vertex v of the shortest loop, the loop once round from v back to v is
  //     a shortest path of its class in the universal cover (locally taut, hence shortest), so
  //     path() gives its minimum-link path in the set from v to v's other lift; closed at v it is
  //     a loop of the class, with one link less when its first and last links lie on one line
  //     (they join through v). From an edge e = (a, b) of the shortest loop that runs along a
  //     direction of the set: the path from a once round to b, whose first link runs along e,
  //     closed by e back to a; when its last link runs along e too, the three join into one.
  //     This is done from up to `max_starts` such edges and distinct vertices (edges first,
  //     spread evenly), the fewest kept, stopping early at the lower bound.
  //   - lower bound (at_least): a loop in the set's directions is a loop, so MinLinker::loop's
  //     bound holds (its count when proven minimal, else 2w + 1 for a loop winding w times round
  //     a blockage, at least 3); with two orientations the links of a minimum-link loop alternate
  //     between them (two consecutive links of one orientation run back over each other and
  //     merge into one), so the count is even, at least 4.
  // minimal when the two meet. A loop with fewer links may exist otherwise (one that passes
  // through none of the starts in those ways). No loop (`why`) when no direction of the set leaves any
  // start's free wedge. Throws std::invalid_argument when the input is not such a loop.
  // `any_angle`: MinLinker::loop of the same loop when the caller has it (else it is computed).
  CMinLinkLoop loop(std::span<const geom::Point> taut_loop, const geom::LatticeDirections& set,
                    const MinLinkLoop* any_angle = nullptr, std::size_t max_starts = 64) const;
  // The same in a set at multiples of 30 degrees (the vertex starts with a direction use only
  // the set's axis steps, by their unit vectors: v +- d must be points).
  CMinLinkLoop3 loop(std::span<const geom::Point> taut_loop, const geom::Root3Directions& set,
                     const MinLinkLoop* any_angle = nullptr, std::size_t max_starts = 64) const;

 private:
  const geom::FreeSpaceTriangulation* t_;
};

}  // namespace taut::router
