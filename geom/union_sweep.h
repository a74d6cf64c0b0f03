// Internal engine of normalize.h: the exact union of closed directed integer loops, clipped to
// a box, as rings whose vertices may be rational (proper crossings of sloped edges).
//
// Winding semantics: every directed loop adds +1 to the winding number of the points on its
// left. A point is covered when its winding number is >= 1 and it lies in the domain box. The
// inputs of normalize_obstacles() are valid polygons (shell counter-clockwise, holes clockwise),
// so the winding number is the number of inputs covering a point; rounded rings fed back in a
// later pass may overlap, which the same rule handles.
//
// Steps, all exact: (1) candidate edge pairs from a sweep over x of the edge boxes (or, when
// many long edges are open at once, a packed R-tree of them), each decided
// by intersect() (predicates.h); (2) every edge split at every point where another edge meets
// it, collinear overlapping pieces merged (their windings add); (3) a sweep in lexicographic
// (x, y) order (a vertical edge is the limit of a slightly tilted one) keeps the pieces
// crossing the sweep line in order (a sorted vector for small inputs, else a balanced tree):
// the winding below a new piece is the winding above its predecessor, so every piece learns
// the winding on both sides by one search (O(log n); the vector also moves the entries above);
// (4) pieces with covered points on exactly one side are the boundary, linked into rings that
// keep free space on their right; at a vertex where the union pinches, an incoming edge takes
// the first outgoing edge counter-clockwise from its own reverse, so each ring bounds one face
// of free space and obstacles touching at a point end up in one ring; (5) rings are grouped
// into connected obstacles: rings through a common vertex, and a boundary piece with covered
// points below it and its nearest boundary piece below (the vertical segment between them is
// covered). Cost O((n + k) log n) for the sweep; finding the pairs costs O(n log n) plus the
// comparisons (at most the budget below) or, by the R-tree, the pairs of edges whose boxes
// overlap (equal to k for axis-parallel edges).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "geom/predicates.h"
#include "geom/types.h"

namespace taut::geom::detail {

// An exact point with rational coordinates in lowest terms: x = xi + xf / d, y = yi + yf / d,
// 0 <= xf, yf < d, gcd(xf, yf, d) = 1, so equal points have equal fields. Integer points have
// d = 1. d < 2^63 (a cross product of two edge directions).
struct RPoint {
  Coord xi = 0, yi = 0;
  std::int64_t xf = 0, yf = 0, d = 1;
  bool is_integer() const { return d == 1; }
  Point floor() const { return {xi, yi}; }
  friend bool operator==(const RPoint&, const RPoint&) = default;
};
RPoint to_rpoint(Point p);
// Lowest-terms form of (x_num / den, y_num / den), den > 0.
RPoint to_rpoint(const RationalPoint& r);
// Lexicographic (x, then y) order.
bool lex_less(const RPoint& a, const RPoint& b);
// Sign of orient(a, b, v) (> 0: v left of the directed line a->b). Exact in __int128.
int orient_sign(Point a, Point b, const RPoint& v);

// Sorts by the first member, stably (std::stable_sort's order), most significant bits first:
// how union_loops orders its vertex keys.
void sort_by_key(std::vector<std::pair<std::uint64_t, int>>& v);

// A directed closed loop of integer points (no repeated closing vertex); `tag` is carried to
// the output so callers can tell which obstacle each loop ended in.
struct Loop {
  std::vector<Point> points;
  std::int64_t tag = -1;
};

struct UnionRing {
  std::vector<RPoint> vertices;  // union on the left of every edge
  std::vector<Segment> lines;    // lines[i]: integer segment carrying edge i -> i+1, same direction
  int component = -1;            // connected obstacle (closed sets) it belongs to
};

struct UnionResult {
  std::vector<UnionRing> rings;
  int components = 0;
  std::vector<std::pair<std::int64_t, int>> tag_components;  // (loop tag, component), sorted
  std::int64_t proper_crossings = 0;
  std::int64_t rational_vertices = 0;  // ring vertices that are not integer
  bool pairs_by_rtree = false;  // the edge pairs were found by the R-tree (see sweep_budget)
};

// sweep_budget: the box comparisons the sweep for edge pairs may make before the pairs are found
// by an R-tree instead (-1: 64 per edge plus 2^20; 0: the R-tree at once). vector_sweep: the most
// edges for which the winding sweep keeps its order in a sorted vector rather than a balanced
// tree (-1: 8192; 0: the tree always). Same result either way.
UnionResult union_loops(const std::vector<Loop>& loops, const Box& domain, std::int64_t sweep_budget = -1,
                        std::int64_t vector_sweep = -1);

}  // namespace taut::geom::detail
