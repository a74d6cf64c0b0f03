// Test support: small random obstacle sets shared by the oracle tests.
#pragma once

#include <random>
#include <span>
#include <vector>

#include "geom/types.h"

namespace taut::test {

// 1 to max_count triangles with vertices drawn uniformly from the closed domain box (std
// uniform_int_distribution on rng, in this order: the count, then x and y of each vertex);
// degenerate ones are dropped, the others made counter-clockwise. Sloped edges that cross at
// non-integer points, touch and pinch: inputs for geom::normalize_obstacles.
std::vector<geom::Polygon> random_triangles(std::mt19937& rng, const geom::Box& domain, int max_count);

// A w x h box that touches box o only at one of its corners (0: NE, 1: NW, 2: SW, 3: SE of o):
// the two make a pinch.
inline geom::Box corner_box(const geom::Box& o, int w, int h, int corner) {
  switch (corner) {
    case 0: return {o.hi, {o.hi.x + w, o.hi.y + h}};
    case 1: return {{o.lo.x - w, o.hi.y}, {o.lo.x, o.hi.y + h}};
    case 2: return {{o.lo.x - w, o.lo.y - h}, o.lo};
    default: return {{o.hi.x, o.lo.y - h}, {o.hi.x + w, o.lo.y}};
  }
}

// A random simple rectilinear polygon (counter-clockwise ring, no collinear vertices) built as a
// polyomino: up to `cells` unit cells grown from one uniform cell by adding a uniform empty
// 4-neighbour of the set at a time on a grid of side `side` (fewer when the grid fills up), the
// whole growth rejected and retried when the union has a hole or pinches (two cells meeting only
// at a corner); then column and row widths stretched by random integers in [1, max_stretch]
// (shared x/y, collinear edges) and moved by `origin`: grid cell (c, r) becomes the box from
// origin + (widths of columns < c, heights of rows < r) to the same plus (width of c, height of
// r). rng is used in this order: the growth attempts, the `side` column widths, the `side` row
// heights. side >= 1, cells >= 1, max_stretch >= 1 (else std::invalid_argument).
geom::Ring random_rectilinear_polygon(std::mt19937& rng, int side, int cells, int max_stretch, geom::Point origin);

// The same polygon with the boxes of its stretched cells (closed, their union is the polygon):
// for tests that decide membership without the ring. Same rng use as above.
struct RectilinearPolygonSample {
  geom::Ring ring;
  std::vector<geom::Box> cells;
};
RectilinearPolygonSample random_rectilinear_sample(std::mt19937& rng, int side, int cells, int max_stretch,
                                                   geom::Point origin);

// Thin random polygons, for diameters beyond what compact polyominoes reach: 1 to 3 width-1
// walks of unit cells (the first from (0, 0), the others from a random cell already there), each
// of 2 to 12 runs of 1 to 5 cells turning left or right at random, retried until the union is
// one simple polygon without holes; then columns and rows stretched by 1 to max_stretch. With
// the stretched cells (for the lattice).
RectilinearPolygonSample random_thin_polygon(std::mt19937& rng, int max_stretch);

// `count` boxes tried at random, each with its low corner at lo + [0, span) in x and in y and
// sides of 1 to max_side, kept when at least 1 apart from every box kept before (so each is one
// obstacle of the union, and no two pinch). rng is used in that order, x before y, width before
// height.
std::vector<geom::Box> random_boxes_apart(std::mt19937& rng, int count, int lo, int span, int max_side);
// Each box as a counter-clockwise rectangle without holes.
std::vector<geom::Polygon> box_polygons(std::span<const geom::Box> boxes);

// The boundary of the union of closed boxes (geom::normalize_obstacles), counter-clockwise, no
// collinear vertices; std::invalid_argument unless the union is one polygon without holes whose
// ring repeats no vertex (boxes that only touch at a corner pinch).
geom::Ring union_ring(std::span<const geom::Box> boxes);

}  // namespace taut::test
