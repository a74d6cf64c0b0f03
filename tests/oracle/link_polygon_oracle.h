// Brute-force rectilinear link distance inside a simple rectilinear polygon (de Berg, "On
// rectilinear link distance"): the reference the product's link-distance code is checked
// against. It shares no code with router/: it reads only the polygon's ring and uses
// geom/types.h and geom/predicates.h.
//
// Definitions. P is a simple rectilinear polygon, closed (boundary included). A rectilinear path
// in P is a polyline with axis-parallel segments lying in P; its link length is its number of
// maximal straight pieces. d(a, b) is the least link length of a path from a to b (0 when a == b,
// 1 when ab is axis-parallel and lies in P). Dia(P) = max d(a, b) over a, b in P.
//
// Method. The Hanan grid of the polygon's vertex x's and y's, plus the query points' x and y. A
// grid point is usable when it lies in closed P; a step between two adjacent grid points on one
// grid line is usable when its midpoint (doubled coordinates, exact in int64) lies in closed P:
// no polygon vertex lies strictly between adjacent grid lines, so no edge crosses or ends inside
// the open step, and the open step lies wholly in P or wholly outside it. A 0-1 BFS on the
// states (grid point, orientation H or V): one usable step along the orientation costs 0, a
// change of orientation at a point costs 1, both start states cost 1 (the first link); d(a, b)
// is the least cost of b's two states. A walk whose straight runs go back and forth is no
// cheaper than a real path: a run from p to q visits every step between them, so the segment pq
// lies in P and the run is one link.
//
// Why the Hanan grid is enough. Take a least-link path a = p0, p1, ..., pk = b. Its first link
// lies on a grid line through a, its last on one through b. Slide a middle link p_i p_{i+1}
// perpendicular to itself, lengthening or shortening its two neighbours along their own lines:
// the link count does not change until the link reaches a neighbour's far end (then a neighbour
// vanishes and the path has fewer links, impossible for a least-link path) or the sliding link
// meets the boundary of P. It can only meet the boundary at a vertex of P (a parallel edge it
// runs into ends at vertices on the same line, a perpendicular edge is met at its end), so it
// stops on a line through a vertex. Slide every middle link this way (each slide keeps the
// others' lines): every link lies on a grid line, every turn is at a crossing of two grid lines,
// and the path is a walk of the state graph with exactly its link count as cost.
//
// Why diameter() over Hanan grid points is the diameter over all of P (sketch; the reference
// does not assume the paper's claim that convex vertices attain it, and the test compares
// diameter() with a BFS over every lattice point of stretched polyominoes, most of which are not
// Hanan points). Fix b and k. In a simple polygon every component Q of P minus the points within
// k links of b is a pocket whose boundary inside P lies on one axis-parallel window segment w
// (the histogram structure the paper builds on). Let C be a closed Hanan cell (or step) in P, a
// point of C in Q, and suppose no corner of C is in Q. The segment from a to each corner lies in
// C, so in P, and leaves Q, so it meets w on the line of w: a lies strictly on one side of that
// line and every corner on the other side or on it, impossible as a is a convex combination of
// the corners (a on the line: the segments would have to run along it and through w, which does
// not contain a, in every direction of C at once). So d(., b) is maximised over C at a corner, a
// Hanan grid point. Apply this to a, then to b.
//
// Cost: the grid has G <= (n+2)^2 points; distance() is O(G n) to classify the grid plus O(G) for
// the BFS; diameter() is one BFS per usable grid point, O(G^2) (polygons of ~40 vertices: ~0.5 M
// states per BFS sweep, fine).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "geom/types.h"

namespace taut::oracle {

class LinkPolygonReference {
 public:
  // polygon: a simple rectilinear ring with integer vertices, either orientation, no repeated
  // closing vertex; collinear vertices allowed (consecutive repeated vertices are dropped).
  // Throws std::invalid_argument when an edge is sloped, when fewer than 4 corners remain, when
  // the ring turns back on itself, or when two edges that are not neighbours meet (not simple).
  explicit LinkPolygonReference(const geom::Ring& polygon);

  // Closed P (exact, integer arithmetic).
  bool contains(geom::Point p) const;

  // d(a, b) in links; std::nullopt when a or b is outside P. Any integer points: their x and y
  // are added to the grid for that query.
  std::optional<int> distance(geom::Point a, geom::Point b) const;

  // de Berg's e(a, d) (section 3): for every grid point x of the axis-parallel segment e0-e1
  // (which must lie in P; the grid: the polygon's vertex x's and y's, a's and the segment's ends),
  // in order from e0, the least links of a path from a to x whose last link runs perpendicular to
  // the segment, and of one whose last link runs along it (0 when a == x; -1 when there is none).
  // e(a, d) is the set of x whose perpendicular count is at most d.
  struct Arrival {
    geom::Point x;
    int perpendicular = -1, along = -1;
  };
  std::vector<Arrival> arrival_links(geom::Point a, geom::Point e0, geom::Point e1) const;

  struct Diameter {
    int links = 0;
    geom::Point a, b;  // one pair at that distance: the first a, then b, in (x, y) order
  };
  // Exhaustive: the max of d over every pair of Hanan grid points (every vertex x times every
  // vertex y) inside P.
  Diameter diameter() const;
  // The max of d over pairs of polygon corners (ring vertices that are not collinear), and over
  // pairs of convex corners (interior angle 90 degrees).
  int vertex_diameter() const;
  int convex_vertex_diameter() const;

  // The ring without repeated and collinear vertices, in the input's orientation.
  const geom::Ring& corners() const { return ring_; }
  const std::vector<bool>& convex() const { return convex_; }  // per corner

 private:
  struct Grid {
    std::vector<geom::Coord> xs, ys;  // sorted, distinct
    std::vector<char> point;          // usable point (i, j) at i * ny + j
    std::vector<char> hstep;          // step (i, j) - (i + 1, j) at i * ny + j
    std::vector<char> vstep;          // step (i, j) - (i, j + 1) at i * ny + j
    int nx() const { return static_cast<int>(xs.size()); }
    int ny() const { return static_cast<int>(ys.size()); }
  };
  Grid make_grid(std::vector<geom::Coord> xs, std::vector<geom::Coord> ys) const;
  // Links from grid point `source` (index i * ny + j, usable) to every grid point: 0 at the
  // source, -1 where unusable.
  std::vector<int> bfs(const Grid& g, int source) const;
  // The same search's cost per state (2 * point + o, o = 0 horizontal, 1 vertical: links of a
  // path arriving at the point along o); unreached states kUnreached.
  std::vector<int> bfs_states(const Grid& g, int source) const;
  static constexpr int kUnreached = 1 << 30;
  // Closed P at (x2 / 2, y2 / 2).
  bool contains2(std::int64_t x2, std::int64_t y2) const;
  int index_of(geom::Point p) const;  // p's index in grid_ (p on the vertex grid)
  int max_over(const std::vector<geom::Point>& sources) const;

  geom::Ring ring_;          // corners
  std::vector<bool> convex_;
  Grid grid_;                // the vertex grid
};

}  // namespace taut::oracle
