// The rectilinear link diameter within 3 (de Berg, "On rectilinear link distance", seeds/002,
// section 4.2, procedure MAXDIST), for a polygon too large for the exact divide and conquer
// (router/link_reach.h, O(n log^2 n) time and O(n log n) records: 615 MB at 86,000 vertices).
//
//   const LinkDiameterEstimate e = approximate_link_diameter(ring);
//   // the link diameter lies in [e.lo, e.hi]: e.estimate - 3 .. e.estimate + 3, clipped
//
// How. MAXDIST sweeps a horizontal edge e with two convex ends into the polygon until it first
// meets a vertex; the swept rectangle leaves one or two smaller polygons, each again with such
// an edge, and the procedure recurses on them. It returns D, the estimate, and M, the most links
// a path from any point of the polygon to a given piece s of e needs when its first and last
// links are vertical (the paper proves M exact: the recursion adds 2 only when the piece's
// projection misses the next edge; the tests here check the estimate, not M). Five cases by what the sweep meets (the OCR of the paper lost their figures; the
// formulas survive, and this is how they read here):
//   (i)   the top edge caps the whole rectangle: the polygon is a rectangle (M 1 or 3, D 3);
//   (ii)  one side ends at a reflex vertex and the polygon widens above: recurse above (D, M as
//         there);
//   (iii) one side ends at a convex vertex and the polygon narrows: recurse on the rest, M + 2
//         when s does not reach under it;
//   (iv)  as (ii), but the line also crosses a pocket hanging below: recurse on both,
//         D = max(D', D'', M, M' + M'' - 2);
//   (v)   a tooth hangs into the middle: recurse on both sides, D = max(D', D'', M, M' + M'' - 1).
// Each recursion is one cell of the horizontal decomposition (a chord along every reflex vertex's
// horizontal edge), so this is a pass over the decomposition's tree, built by one sweep.
//
// One correction to the paper. In case (v) M' and M'' are the two sides' M to the pieces of s
// projected onto e' and e'', which can exceed their M to the whole e' and e'' by 2 each; the
// estimate then exceeded the diameter by 4 (a 40,000-polygon random run found three such
// polygons: diameter 5, estimate 9; kept in the tests). Here the term is M'(e') + M''(e'') - 1,
// the sides' M to their whole chords: a pair across the tooth is then d(x, e') + d(y, e'') + 1
// links at most and d(x, e') + d(y, e'') - 1 at least, and d <= d' <= d + 1 to a chord, so the
// term is within 2 of the farthest pair across. M to a whole chord asks the same of the cells
// beyond, which may ask for other pieces in turn (M is computed once per cell and piece): on the
// benchmark's channels and combs 1.0-1.3 pieces per cell; a polygon could ask O(depth) pieces of
// one cell, which no test has shown.
//
// General position. The cases assume no two horizontal edges on one line (and the paper moves
// edges "slightly" to get it). Here every edge is moved outward by its own infinitesimal amount
// (symbolically: coordinates become ranks, ties at one height broken so that edges with the
// interior above go below those with it below, and likewise for x), so the moved polygon holds
// the original, and link distances between its points are the original ones (a path in the
// moved polygon tends to one in the closed original as the amounts go to 0; the original's paths
// stay inside). The tests check |estimate - diameter| <= 3 on polygons full of shared x's and y's.
//
// Cost: O(n log n) for the sort and the sweep's ordered map (the paper's O(n) needs the visible
// vertices of every edge from a linear-time triangulation) plus the pieces; O(n + pieces)
// memory, no recursion. A ring that is not simple is refused (std::invalid_argument) when the
// sweep or the decomposition finds it out (cells that overlap, or a cycle of cells); a weakly
// simple one (touching itself along a slit) can pass and get an estimate.
#pragma once

#include <cstddef>

#include "geom/types.h"

namespace taut::router {

struct LinkDiameterEstimate {
  int estimate = 0;          // MAXDIST's D: |estimate - diameter| <= 3 (2, exact, for a rectangle)
  int lo = 0, hi = 0;        // the diameter lies in [lo, hi]: estimate -+ 3, at least 2 (2 for a rectangle)
  std::size_t cells = 0;     // cells of the horizontal decomposition (recursive calls)
  std::size_t pieces = 0;    // (cell, piece s) pairs M was computed for
};

// polygon: a simple rectilinear ring, counter-clockwise, without repeated or collinear vertices
// (LinkPolygon::ring() is one); std::invalid_argument otherwise (when it is found out, above).
LinkDiameterEstimate approximate_link_diameter(const geom::Ring& polygon);

}  // namespace taut::router
