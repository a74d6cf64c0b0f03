// What de Berg's query structure keeps at a node of the cut tree (seeds/002, section 3.1): for
// every vertex v of one part of a cut polygon, its link distance to the cut segment b, the parts
// of b it reaches with that many links and with one more (Lemmas 2-4: e(v, d_v), e(v, d_v + 1)),
// and the links of a path that reaches b running along b's line (the arrivals Lemma 2 leaves out:
// tests/router/link_cut_test.cpp found 851 pairs across cuts that only such a path joins).
//
//   const std::vector<BaseReach> r = base_reach(part, cut.from, cut.to);
//   int d = links_across(r_left[i], r_right[j]);   // d(v_i, w_j) for v_i, w_j on either side
//
// Closed polygon, paths may run along the boundary and through reflex vertices (what the router
// and the reference mean by a path). Work is done in the frame where b is horizontal with the
// polygon above it.
//
// How (not the paper's histogram partition, which the OCR of its figures and the degenerate
// cases it leaves out made hard to follow exactly; this is simpler to get right and is checked
// against the reference's own per-point counts):
//   - the vertical decomposition (a cut up or down from every reflex vertex, continuing its
//     vertical edge; and up from b's ends) into open rectangles "V-cells", and the horizontal one
//     into "H-cells": inside a V-cell every vertical link spans the cell, inside an H-cell every
//     horizontal link does; a V-cell and an H-cell that overlap always overlap across the
//     H-cell's whole height and the V-cell's whole width (an edge bounding one would otherwise
//     cross the other's interior);
//   - the maximal closed segments of the polygon, both ways, through every vertex and b's ends:
//     every link that is not inside a cell lies on one (a link on a cell's side lies on a cut or
//     an edge, hence on a line through a vertex);
//   - a breadth-first search over these nodes from b (a node's level: the fewest links of a path
//     starting along it and ending perpendicular on b), adjacent when perpendicular and meeting
//     in a point (segments) or along a piece of positive length (a cell and a segment, two cells
//     by area). Levels alternate in parity with the node's direction. What a node reaches on b
//     is one interval (Lemma 3), the union of what its neighbours one level down reach.
// Cost: O(n log n) to build the nodes, plus one R-tree query per vertical node for the
// adjacencies (kept as compressed rows that both searches walk) and the pairs it reports (O(n)
// on the tested layouts, quadratic for a polygon whose V- and H-cells cross like a grid); the
// paper's histogram partition is O(n).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geom/types.h"
#include "router/link_cut.h"

namespace taut::router {

// Closed positions along b, measured from b's first end (empty when lo > hi).
struct ReachInterval {
  std::int64_t lo = 0, hi = -1;
  bool empty() const { return lo > hi; }
  bool meets(const ReachInterval& o) const { return !empty() && !o.empty() && lo <= o.hi && o.lo <= hi; }
  bool contains(std::int64_t t) const { return lo <= t && t <= hi; }
};

struct BaseReach {
  int links = -1;       // d(v, b): the fewest links of a path from v to a point of b whose last
                        // link is perpendicular to b, where a path that comes along b's line may
                        // turn on b in place (so links <= along + 1, as in the reference's
                        // per-state counts); 0 for a vertex on b
  ReachInterval at;     // e(v, links): the points of b such a path of `links` links reaches
  ReachInterval next;   // e(v, links + 1) (contains `at`)
  int along = -1;       // the fewest links of a path from v whose last link runs along b's line
                        // over b (0 on b, 1 on that line elsewhere)
};

// polygon: a simple rectilinear ring, counter-clockwise, no repeated or collinear vertices.
// b0-b1: an axis-parallel segment of positive length on one of its edges. One record per vertex
// of the polygon, in ring order. std::invalid_argument for a segment that is not on an edge.
std::vector<BaseReach> base_reach(const geom::Ring& polygon, geom::Point b0, geom::Point b1);

// The same search, kept: the record of any point of the polygon (section 3.2), found by locating
// the point among the nodes (the maximal segment through it when it lies on one, else the cell
// holding it) in an R-tree, O(log n).
class CutReach {
 public:
  CutReach(const geom::Ring& polygon, geom::Point b0, geom::Point b1);  // as base_reach()
  ~CutReach();
  CutReach(CutReach&&) noexcept;
  CutReach& operator=(CutReach&&) noexcept;
  std::optional<BaseReach> at(geom::Point q) const;  // std::nullopt when q is outside
  const std::vector<BaseReach>& vertices() const;   // base_reach()

  // The paths behind a point's record (section 3.3's building blocks, for LinkPointQueries::path).
  // A point q of the part off b has up to three ways to b: `first`, a path ending perpendicular on
  // b that starts along the node through q with the lower level; `second`, one that starts along
  // the other node (one link more); `along`, one whose last link runs along b's line. links -1:
  // no such way. `at`: the positions of b (from b's first end) a perpendicular way can land on.
  struct Way {
    int links = -1;
    ReachInterval at;
  };
  struct Ways {
    Way first, second, along;
  };
  std::optional<Ways> ways(geom::Point q) const;  // std::nullopt when q is outside or on b
  // A way's links from q to b, in the polygon's coordinates: each link's axis and the closed
  // interval its fixed coordinate may take (x for a vertical link, y for a horizontal one). Any
  // choice of those coordinates, with the first link through q, gives a path in the polygon with
  // that many links (each link stays in one node's closed cell or segment, which is convex, and
  // consecutive links' nodes cross). A perpendicular way lands on b inside `within`, which is
  // narrowed to the positions every node chosen on the way still reaches (it must meet the way's
  // `at`); the along way's last link lies on b's line.
  struct Run {
    bool vertical = false;
    std::int64_t lo = 0, hi = -1;
  };
  std::vector<Run> runs(geom::Point q, int way, ReachInterval& within) const;  // way: 0, 1, 2

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// d(s, t) for vertices s, t off the cut, on its two sides, from their records for the same cut
// (base_reach of each part with the cut's two ends): Lemma 2, d_s + d_t + (-1, 0 or +1 by how
// their reach intervals meet), or a path along the cut's line from one or both sides.
int links_across(const BaseReach& s, const BaseReach& t);

// d(q, t) for q on a cut at `position` (from its first end) and t off it, from t's record.
int links_to_cut_point(const BaseReach& t, std::int64_t position);

// Link distances between any two points of the polygon (section 3.2): the cut tree with both
// parts' CutReach kept at every cut. A query locates each point among the tree's leaf rectangles
// (one R-tree query: the leaves whose closed rectangle holds it, at most four); the node where a
// point stops going down the tree is the lowest common ancestor of its leaves (a point on a node's
// cut lies in both parts, so in leaves on both sides; a point off it in one part only), and the
// node where the two points part is the lowest common ancestor of those two (parent pointers,
// O(depth)). Only there is a point's record looked up (one CutReach::at, an R-tree query): then
// links_across() of the two records, or links_to_cut_point() when one lies on the cut, or 0, 1 or 2
// in a leaf rectangle. O(log n) per query, as in the paper (which uses a monotone subdivision's
// optimal point location where this uses R-trees: their O(log n) is the expected case for
// disjoint boxes, not a worst-case bound). Memory: every part's decomposition cells and segments,
// O(n log n).
//
// links_by_descent() answers the same by walking down the tree, locating each point in a part at
// every level (O(log n) levels, O(log^2 n)): the benchmark's baseline and the tests' cross-check.
class LinkPointQueries {
 public:
  explicit LinkPointQueries(const geom::Ring& polygon);  // counter-clockwise, no collinear vertices
  ~LinkPointQueries();
  LinkPointQueries(LinkPointQueries&&) noexcept;
  LinkPointQueries& operator=(LinkPointQueries&&) noexcept;
  std::optional<int> links(geom::Point a, geom::Point b) const;  // std::nullopt: a or b outside
  std::optional<int> links_by_descent(geom::Point a, geom::Point b) const;
  // A path from a to b with links(a, b) links that is also L1-shortest (section 3.3): a, its
  // bends, b (just {a} when a == b); std::nullopt when a or b is outside. The ways of both
  // records at the node where the points part are glued on the cut (the paper's gluing, Figure
  // 6), and the free coordinate of every link is then chosen to minimise the L1 length: the x's
  // of the vertical links and the y's of the horizontal ones are two independent chains of
  // intervals, each solved exactly by one pass forward and one back (the least total variation
  // through intervals). Where a node has several neighbours one level down on the way, the one
  // nearest to its coordinate chain's optimal set so far is taken (the paper's "as close to the
  // entrance as possible"; checked against the L1 reference, not proven here). O(log n) plus the
  // degrees of the nodes on the way (the paper: O(log n + l)).
  std::optional<std::vector<geom::Point>> path(geom::Point a, geom::Point b) const;
  const CutTree& tree() const { return tree_; }

 private:
  struct Leaves;
  // The node where p stops going down the tree (see above); nullopt outside the polygon.
  std::optional<std::int32_t> stop_node(geom::Point p) const;
  std::int32_t common_ancestor(std::int32_t a, std::int32_t b) const;

  CutTree tree_;
  std::vector<std::array<std::optional<CutReach>, 2>> parts_;  // per node with a cut
  std::unique_ptr<Leaves> leaves_;                             // the leaf rectangles, in an R-tree
};

// De Berg's query structure for the vertices of a simple rectilinear polygon (section 3.1): the
// cut tree with base_reach() of both parts at every cut, and for every vertex its way down the
// tree (the node, side and index of its record at each level, until it lies on a node's cut or
// reaches a leaf). links(i, j) walks the two ways together to the node where they part: there
// links_across() of the two records (or, when one lies on the cut, the other's record at that
// point of the cut; in a leaf, a rectangle, 1 or 2). O(depth) = O(log n) per query (the paper
// reaches O(1) with constant-time lowest common ancestors); O(n log n) records.
//
//   const LinkVertexQueries q(ring);   // counter-clockwise, no collinear vertices
//   int d = q.links(i, j);              // d(ring[i], ring[j]) in links
class LinkVertexQueries {
 public:
  explicit LinkVertexQueries(const geom::Ring& polygon);
  int links(std::size_t i, std::size_t j) const;
  const CutTree& tree() const { return tree_; }

  // The link diameter over the polygon's convex vertices (where it is attained, de Berg section
  // 4) by the divide and conquer of section 4.1: at every cut, the farthest pair across it from
  // the records alone. Its link distance lies within [d_v + d_w - 3, d_v + d_w + 1] (Lemma 2
  // and the along-the-cut paths), so only vertices within 3 of each side's largest d_v can be
  // farther apart than the two largest; grouped by d_v and by how their along-the-cut count compares with it (3 kinds: the
  // along paths are then the same for the whole group), a group pair's best Lemma 2 term comes
  // from two dominance questions on the intervals' ends (Lemma 9's scan) and one comparison.
  // O(n log^2 n) over the tree; the paper's O(n log n) keeps the ends presorted.
  struct Diameter {
    int links = 0;
    std::size_t from = 0, to = 0;  // indices of two convex vertices that far apart
  };
  Diameter diameter() const;
  std::size_t records() const;  // BaseReach records kept, over all nodes

 private:
  struct Step {
    std::int32_t node = 0;
    std::int8_t side = 0;  // 0 left, 1 right; -1 on the node's cut (index: position along it); -2 leaf
    std::int64_t index = 0;
  };
  CutTree tree_;
  std::vector<std::vector<BaseReach>> reach_[2];  // per node: its children's records
  std::vector<std::vector<Step>> way_;            // per vertex of the polygon
};

}  // namespace taut::router
