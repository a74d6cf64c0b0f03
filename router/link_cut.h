// The rectilinear polygon cutting theorem (de Berg, "On rectilinear link distance", seeds/002,
// section 2) and the cut tree built on it: the divide and conquer under the paper's O(log n + l)
// link-distance queries (section 3) and its O(n log n) diameter (section 4.1).
//
//   const CutTree tree(polygon_ring);          // a simple rectilinear polygon
//   tree.nodes()[0]                             // the whole polygon; .cut splits it in two
//
// Theorem 2: a simple rectilinear polygon of n vertices has a cut segment (an axis-parallel
// segment joining two boundary points through the interior) incident upon a vertex that leaves
// both parts with at most 3n/4 + 2 vertices (weights 1; the cut's ends count in both parts).
// Such a segment starting at a vertex v runs through the interior, so v is reflex and the segment
// extends one of v's edges (at a convex vertex the interior lies between its own edges): the
// candidates are the two extensions of every reflex vertex, each running until it first meets
// the boundary (a vertex, or the inside of a perpendicular edge). A segment that only ends at a
// vertex is the extension from that vertex, so it is among the candidates too. balanced_cut()
// tries all of them (one ray in an R-tree each, O(n log n)) and keeps the one whose larger part
// has the fewest vertices (the paper finds one meeting the bound in O(n) by a sweep; trying all
// is simpler and never worse). The tests check the bound and the choice against an independent
// search over every extension.
//
// The tree: every node is a simple rectilinear polygon (counter-clockwise, no collinear
// vertices); a rectangle is a leaf, any other is cut in two children by balanced_cut(). Depth
// O(log n) (each part has at most 3n/4 + 2 vertices); O(n log^2 n) to build.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geom/index.h"
#include "geom/types.h"

namespace taut::router {

// Small helpers of the rectilinear link code (link_cut.cpp, link_reach.cpp): the unit step of an
// axis-parallel move from a to b, a step reversed, and the ray direction of a unit step.
namespace link_steps {
inline geom::Point unit(geom::Point a, geom::Point b) {
  return {static_cast<geom::Coord>((b.x > a.x) - (b.x < a.x)), static_cast<geom::Coord>((b.y > a.y) - (b.y < a.y))};
}
inline geom::Point neg(geom::Point d) { return {static_cast<geom::Coord>(-d.x), static_cast<geom::Coord>(-d.y)}; }
inline geom::Direction ray_of(geom::Point d) {
  if (d.x > 0) return geom::Direction::E;
  if (d.x < 0) return geom::Direction::W;
  return d.y > 0 ? geom::Direction::N : geom::Direction::S;
}
}  // namespace link_steps

struct PolygonCut {
  geom::Point from;        // a reflex vertex of the polygon
  geom::Point to;          // where the segment first meets the boundary again
  std::size_t vertex = 0;  // the index of `from` in the ring
  // The two parts, counter-clockwise, no collinear vertices: `left` is the ring from `from`
  // forward to `to` (closed by the cut), `right` the rest.
  geom::Ring left, right;
};

// The polygon: a simple rectilinear ring, counter-clockwise, without repeated or collinear
// vertices (LinkPolygon::ring() is one); std::invalid_argument for a sloped edge, a repeated or
// straight vertex, or a clockwise ring (found when an extension leaves it). nullopt for a
// rectangle (no reflex vertex).
std::optional<PolygonCut> balanced_cut(const geom::Ring& polygon);

class CutTree {
 public:
  struct Node {
    geom::Ring polygon;
    std::optional<PolygonCut> cut;  // none at a leaf (a rectangle); cut->left/right are moved
                                    // into the children and left empty here
    std::int32_t parent = -1, left = -1, right = -1;
    int depth = 0;
  };
  explicit CutTree(const geom::Ring& polygon);
  const std::vector<Node>& nodes() const { return nodes_; }
  int depth() const { return depth_; }  // the deepest node's depth (the root's is 0)

 private:
  std::vector<Node> nodes_;
  int depth_ = 0;
};

}  // namespace taut::router
