// Canonical polygons, and the exact union of blockages as disjoint obstacles.
//
// normalize_polygon(): outer ring counter-clockwise, holes clockwise, consecutive repeated
// vertices and collinear (0 degree continuation) vertices removed, each ring starting at its
// lexicographically smallest (x, then y) vertex, holes sorted by that vertex: equal shapes
// compare equal.
//
// normalize_obstacles(): the union of valid polygons (validate.h) clipped to a domain, as
// obstacles that share no point at all: inputs that overlap, share an edge or touch at a single
// point are merged ("a wire may not pass through a point where two blockages touch", FORMAT.md).
// Output invariants: every input point in the domain is covered (closed sets); obstacles lie in
// the closed domain; distinct obstacles are disjoint; rings are weakly simple (they may touch
// themselves or each other only at vertices, never cross or overlap along an edge); every
// coordinate is an integer. Each ring is canonical as above, except that a vertex where rings
// touch is kept even when its two edges are collinear (dropping it would leave a touch in the
// middle of an edge).
//
// Rounding rule (never shrinks an obstacle). Where two sloped edges cross at a non-integer
// point p, the union has a vertex there (in a clipped input, also where a sloped edge meets the
// domain side). Going around the ring with the obstacle on the left, p is replaced by an integer
// point q with orient(prev, p, q) <= 0 and orient(p, next, q) <= 0 (q right of, i.e. on the
// free side of, both edges at p) inside the domain. The ring then changes by the loop
// prev -> q -> next -> p -> prev, which has winding number >= 0 everywhere, so the new ring
// covers the old one. Among the lattice points of the 16x16 grid around p (then 64x64) that
// satisfy this exactly, q is the one closest to the two edge lines (the growth lies within that
// distance of the old ring; floating point only ranks points already proven valid); if none
// (an extremely thin free wedge), q is the previous or next ring vertex when that is integer
// (the thin triangle prev, p, next is filled), else a wider search, else (a spike tip whose wedge
// leaves the domain before it meets a lattice point) the same search outside the domain, which
// the next union pass clips back to the domain box. Vertices are rounded one
// after the other, each against its already rounded neighbour. The rounded rings are then unioned again (the growth
// may create new contacts or crossings), repeating until no vertex is rational; with only
// axis-parallel edges every crossing is integer and the union is exact in one pass, no rounding.
// The growth is a union of thin triangles at the rounded vertices: every added point is within
// about 1.5 DBU of an input (tested: <= 2), except when the thin-wedge fallback fills a sliver.
//
// Why not Clipper or Boost.Geometry's union: both round intersection points to the nearest
// integer, which can move an obstacle edge inward (a wire could then touch the real blockage),
// and neither merges shapes that touch at a single point.
//
// Algorithm (union_sweep.h): edges split at all intersections, windings from a lexicographic
// sweep with a balanced tree, boundary pieces linked into rings, rings grouped by connectivity.
// O((n + k) log n) for n vertices and k intersections, plus the R-tree candidate pairs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geom/types.h"

namespace taut::geom {

// Canonical form of a valid polygon (see above). Rings left with fewer than 3 vertices (not
// possible for valid input) are returned as they are after cleaning.
Polygon normalize_polygon(const Polygon& polygon);

struct NormalizeStats {
  std::int64_t input_polygons = 0;
  std::int64_t input_vertices = 0;
  std::int64_t removed_repeated = 0;   // consecutive repeated input vertices dropped
  std::int64_t removed_collinear = 0;  // collinear input vertices dropped
  std::int64_t output_obstacles = 0;
  std::int64_t output_vertices = 0;
  std::int64_t merges = 0;             // inputs merged into another: sum(sources - 1)
  std::int64_t crossings = 0;          // proper edge crossings at non-integer points (pass 1)
  std::int64_t rounded = 0;            // non-integer union vertices rounded (all passes)
  int passes = 0;                      // union passes (1 unless something was rounded)
};

struct NormalizedObstacles {
  // The boundary when there is one; otherwise the bounding box of all inputs grown by
  // kDomainMargin on every side (clamped to +-kMaxCoord), or an empty box at the origin when
  // there is no input.
  Box domain;
  std::vector<Polygon> obstacles;                 // sorted by first outer vertex
  std::vector<std::vector<std::size_t>> sources;  // input indices (sorted) in each obstacle
  NormalizeStats stats;
};

inline constexpr Coord kDomainMargin = 64;

// The union of `inputs` (valid polygons, any orientation) clipped to `boundary`.
NormalizedObstacles normalize_obstacles(std::span<const Polygon> inputs,
                                        std::optional<Box> boundary);
// The same, of polygons held elsewhere (a caller that gathers them from several stores need not
// copy them; `sources` then index `inputs` as here).
NormalizedObstacles normalize_obstacle_refs(std::span<const Polygon* const> inputs,
                                            std::optional<Box> boundary);

// Pieces whose union is the Minkowski sum of the polygons with the square [-r, r]^2 (r >= 0):
// each polygon itself (holes kept) and, for every edge ab of every ring, the convex hull of the
// squares at a and b (a hexagon, or a rectangle for an axis-parallel edge). A point outside the
// union is at L-infinity distance > r, so at Euclidean distance > r, from every polygon; a point
// on its boundary at distance >= r. Pass them to normalize_obstacles() for the union (sloped
// crossings are rounded outward there, never inward). Integer vertices; std::domain_error when a
// grown coordinate would pass kMaxCoord.
std::vector<Polygon> square_grown(std::span<const Polygon> polygons, Coord r);

// The polygon (a valid one, as normalize_obstacles takes) with less of it outside the box d,
// for normalize_obstacles(..., d), whose result depends only on the part in d: side after side,
// each run of consecutive ring vertices strictly beyond that side of d is cut to its first and
// last vertex. The chord between them lies strictly beyond the side too, so the ring's winding
// number is unchanged at every point of d (a ray from there away from the side never meets what
// changed); a ring cut so that its signed area would change sign (possible when the chord
// crosses another stretch of the ring out there) is kept whole, so normalize_obstacles orients
// it as before. A hole entirely beyond a side is dropped; when the outer ring is (then
// the polygon has no point in d: false, the polygon left as it was). In place; a polygon with
// its outer ring in d is not touched. Exact; no vertex is moved or added.
bool cut_beyond(Polygon& polygon, const Box& d);
// Whether cut_beyond(polygon, d) leaves the polygon as it is: its outer ring lies in d (or it
// has none). A caller holding the polygon elsewhere copies it only when this is false.
bool cut_leaves(const Polygon& polygon, const Box& d);

// The frame of a domain box d: the box one unit larger on every side (not clamped: d must lie
// within the coordinate limit, so the frame lies within it plus one) with d as its hole, outer
// ring counter-clockwise from its lower-left corner. The wavefronts wall a domain with it
// (router/wavefront.h); its interior holds no point of d.
Polygon domain_frame(const Box& d);

// The box grown by r >= 0 on every side, clamped to the coordinate limit.
Box grown_box(const Box& box, std::int64_t r);

// The bounding box of points (at least one).
Box bounding_box(std::span<const Point> points);

// w clipped to dom (both closed; w must meet dom).
Box clipped_box(Box w, const Box& dom);

// The closed boxes share a point.
inline bool boxes_meet(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

// The convex hull of the points: counter-clockwise from the lexicographically smallest, collinear
// and repeated points dropped (exact; fewer than 3 points when they are collinear).
Ring convex_hull(std::vector<Point> points);

// The L-infinity r-neighbourhood of the segment ab (the convex hull of the squares [-r, r]^2 at
// a and b: a hexagon, or a rectangle when ab is horizontal or vertical or a point), counter-
// clockwise. std::domain_error when a coordinate would pass kMaxCoord.
Ring square_grown_segment(Point a, Point b, Coord r);

// Convex pieces whose union covers the closed convex polygon `convex` (counter-clockwise,
// integer vertices) minus the open box s, none entering the open box: the parts left, right,
// below and above s. Where a part's boundary crosses a side line of s at a non-integer point,
// the point is replaced by its two integer neighbours along that line and the part is the hull,
// so a part reaches at most 1 DBU beyond `convex`, along the side lines of s only (an obstacle
// never shrinks). `convex` itself when it does not meet the open box; nothing when the box
// covers it. Parts of zero area are left out (they are covered by the others' closures only
// when they lie on s's boundary, which is free anyway).
std::vector<Ring> convex_minus_box(const Ring& convex, Box s);

// A pad: a convex polygon whose edges are horizontal, vertical or at 45 degrees (a rectangle, a
// diamond, an octagon, a box with cut corners), in either orientation, repeated vertices and
// vertices where it runs straight on allowed. Its ring counter-clockwise without those vertices;
// nullopt for any other ring.
std::optional<Ring> octilinear_convex_ring(const Ring& r);

// The same as convex_minus_box for a pad (a counter-clockwise octilinear_convex_ring): convex
// pieces whose union covers the closed convex polygon minus the open pad, none entering the open
// pad: the parts outside the pad's box (convex_minus_box), and the parts in the triangles its
// 45-degree edges cut off the box's corners. A crossing of `convex`'s boundary with a triangle's
// side at a non-integer point is replaced by its two integer neighbours along that side (the
// side's ends are integers, so they stay on it), so a part reaches at most about 1 DBU beyond
// `convex` and never into the open pad.
std::vector<Ring> convex_minus_pad(const Ring& convex, const Ring& pad);

}  // namespace taut::geom
