// Minimum-link paths of a given homotopy class (Hershberger & Snoeyink, seeds/001, section 4):
// the path with the fewest segments among all paths homotopic to a given one with the same
// ends, at any angle.
//
//   const router::Tightener tight(t);
//   const router::Tightened r = tight.tighten(sketch);        // the shortest path of the class
//   const router::MinLinker ml(t);
//   const router::MinLinkPath m = ml.path(r.points);          // m.points: exact rationals
//
// The input is the class's Euclidean shortest path alpha (Tightener::tighten). Each of its
// vertices turns left or right; an edge whose ends turn differently, and the first and the last
// edge, is an inflection edge. Lemma 4.1: some minimum-link path uses a piece of the extension
// of every inflection edge (the edge prolonged both ways until it meets the boundary). Between
// two inflection edges alpha is a convex chain, and the links joining the two extensions are
// found greedily (Lemma 4.2, table 2): the link's point a slides forward along the current
// link's extension while the segment from a to its tangent point c on the chain sweeps free
// space; it stops when (1) the tangent becomes the next inflection edge's line (that line is the
// next link), (2) a reaches the end of the extension, or (3) the sweep meets a vertex b (then
// the link is the line through b and c). The next link starts at c along that line, and so on.
//
// The cover. Everything is done on the triangulation in the plane, walking each extension
// through the triangles it meets from a vertex of alpha, so what the walk finds is the lift of
// the extension into the universal cover. Candidate blockers are the ends of the triangle edges
// that the extension and the chain cross and the neighbours of the vertices they pass through
// (Lemma 4.3, extended to paths that touch vertices). A candidate counts only if its obstacle
// lies on the unswept side of the segment through it.
//
// Degenerate layouts. An extension that passes a vertex whose obstacle reaches into the swept
// side stops there (the shorter extension still separates the ends); one that runs along an
// obstacle edge on the other side goes on. A chain edge that grazes a vertex with the obstacle
// on the outer side is a blocker at the start of the sweep, so the link follows that edge.
//
// Exactness. The bends are intersections of lines, rationals whose size grows with each link
// that starts at the end of an extension (case 2), so all arithmetic here is in GMP rationals
// (Boost.Multiprecision); no predicate is decided in floating point.
//
// Cost. Each sweep gathers the candidates of the whole rest of its chain and tries each against
// every chain vertex (a scan, not the paper's hull deque), and a chain may take several sweeps:
// up to cubic in the length of one convex chain in the worst case (linear in the paper).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geom/triangulation.h"
#include "geom/types.h"
#include "router/spm.h"  // Rational, RPoint

namespace taut::router {

struct MinLinkPath {
  std::vector<RPoint> points;  // the ends and the bends; empty for an empty input
  std::size_t links() const { return points.empty() ? 0 : points.size() - 1; }
};

// A closed path (front == back) with few links, freely homotopic to a given loop (section 5.2).
struct MinLinkLoop {
  std::vector<RPoint> points;  // the bends, closed: points.front() == points.back()
  std::size_t links() const { return points.empty() ? 0 : points.size() - 1; }
  // The loop has the fewest links of its class: the class's shortest loop has an inflection
  // edge (Lemma 4.1), or the loop has `at_least` links. Otherwise (a convex shortest loop: every
  // turn the same way) the loop is the best of the greedy runs started on the lines of the
  // shortest loop's edges, and a loop with fewer links may exist (the nested-polygon case,
  // Aggarwal et al.; not computed).
  bool minimal = false;
  // A lower bound on the links of every loop of the class: 2w + 1 for the largest number of
  // times w the loop winds round a blockage (each link turns less than a half turn as seen from
  // a point inside it, and the winding number does not change within the class), at least 3.
  std::size_t at_least = 3;
  bool inflection = false;  // the shortest loop has an inflection edge (so the loop is minimal)
  std::size_t starts = 0;  // greedy runs made (1 when the loop has an inflection edge)
};

// The vertices of a closed path (front == back), cyclically, without repeats. Throws
// std::invalid_argument (prefixed by `who`) when it is not closed or has fewer than three.
std::vector<geom::Point> loop_vertices(std::span<const geom::Point> loop, const char* who);

class MinLinker {
 public:
  // The triangulation must outlive the MinLinker and be ok().
  explicit MinLinker(const geom::FreeSpaceTriangulation& t);

  // A minimum-link path homotopic to `taut`, which must be a shortest path of its class as
  // Tightener::tighten returns it (every bend a strict turn at a triangulation vertex). Throws
  // std::invalid_argument when it is not.
  MinLinkPath path(std::span<const geom::Point> taut) const;

  // A loop with few links freely homotopic to `taut_loop`, which must be a shortest loop of its
  // class as Tightener::tighten_loop returns it (closed, every vertex a strict turn at a
  // triangulation vertex; not contractible). With an inflection edge e = (a, b): the path from a
  // once around to b, whose first and last links both lie on e's extension (the ends of the path
  // are on the extension, and Lemma 4.1 puts a link on it), so they join into one link of the
  // loop and the loop has one link less than that path; some minimum-link loop has a link on e's
  // extension too (Lemma 4.1 for loops, section 5.2), and cutting it there gives a path of the
  // same class with one link more, so the loop is minimal. A convex loop has no inflection edge:
  // the same is done from up to `max_starts` of its distinct edges (spread evenly round it; a loop
  // wound several times repeats its edges), the fewest kept. Throws std::invalid_argument when the input is not such a loop.
  MinLinkLoop loop(std::span<const geom::Point> taut_loop, std::size_t max_starts = 64) const;

 private:
  struct Sweep;
  const geom::FreeSpaceTriangulation* t_;
  std::vector<std::int32_t> fan_start_;  // CSR: triangles incident to each vertex
  std::vector<std::int32_t> fan_;
  std::vector<std::int32_t> first_, last_;  // the free fan's bounding neighbours (vertex ids)
};

}  // namespace taut::router
