// Rectilinear link distance inside a simple rectilinear polygon (issue #6; M. de Berg, "On
// rectilinear link distance", seeds/002): the fewest links (axis-parallel segments) of a path
// between two points of the polygon, paths that are shortest in links and in L1 at once, and the
// link diameter: the largest link distance between two points of the polygon.
//
//   FreeSpacePolygon f = free_space_polygon(domain, blockages);   // a layout's free space
//   if (f.status == FreeSpacePolygon::Status::Ok) {
//     LinkPolygon p(f.ring);
//     LinkDiameter d = p.diameter();   // d.links, d.from, d.to, d.path
//   }
//
// Distances and paths. A query runs the bend-aware router (router/bend_router.h) with the link
// metric, bends first and length second, on the polygon's complement in its bounding box
// (distances alone: a 0-1 breadth-first search on bends over the same graph). That
// router is exact for any rectilinear obstacles (de Berg et al., Lemma 2.1); in a simple
// polygon some path is optimal in links and in L1 at once (de Berg, Lemma 8), so the path it
// returns, the shortest among those with the fewest links, is L1-shortest too (the tests check
// its length against the L1 reference).
//
// The diameter. It is attained at two convex vertices of the polygon (de Berg, section 4; the
// reference test checks it over every Hanan grid point of small polygons). diameter() runs
// searches from convex vertices to all convex vertices (BendRouter::fewest_bends: one 0-1
// breadth-first search over the router's graph, O(V + E)), pruned by eccentricity bounds (see
// diameter() in the .cpp): a few searches on winding channels, but k for k convex vertices in the
// worst case (a comb whose tooth tips are all equally far apart), O(k (V + E)). So after
// `search_budget` searches (32 by default) it switches to de Berg's divide and conquer on the
// rectilinear cutting theorem (router/link_reach.h: O(n log n) records, then the farthest pair
// across every cut from them): 5-13 times the graph's build, where on channels the bounds need
// 3-6 searches, but n log n where the bounds need n searches (a 20,000-vertex comb: 17 s -> 1.0 s).
// The result says which found it. Budget 0: the cut tree always; SIZE_MAX: never.
//
// Counting. A path of l links has l - 1 bends. d(a, a) = 0; d(a, b) = 1 when the segment ab is
// horizontal or vertical and lies in the polygon; a rectangle has diameter 2.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geom/types.h"
#include "router/bend_router.h"

namespace taut::router {

// The free space of a bounded layout (the closed domain minus the open union of the blockages,
// as everywhere in taut) as one simple rectilinear polygon, or why it is not one.
struct FreeSpacePolygon {
  enum class Status {
    Ok,
    Sloped,  // free space has an edge that is neither horizontal nor vertical, at `at`, along a
             // sloped edge of `blockage` (its ring `sloped_ring`)
    Island,  // `blockage` (with those touching it) does not reach the domain side: a hole in free space
    Pieces,  // free space falls into several pieces (`pieces`: the lowest vertex of each), or is one
             // piece that touches itself at a point where blockages meet (`pieces`: that point)
    Empty,   // the blockages cover the domain
  };
  Status status = Status::Empty;
  geom::Ring ring;                  // Ok: counter-clockwise, no repeated or collinear vertex
  std::size_t blockage = 0;         // Sloped, Island: index into the blockage polygons
  int sloped_ring = -1;             // Sloped: -1 the outer ring, k hole k
  geom::Point at;                   // Sloped: a vertex of the sloped free-space edge
  std::vector<geom::Point> pieces;  // Pieces: see above
};
// domain: a closed box with non-empty interior; blockages: valid polygons (geom/validate.h), any
// orientation, holes allowed. Checked in this order: islands, no free space, pieces, a sloped
// edge of free space (sloped blockage edges outside the domain or under other blockages are fine).
FreeSpacePolygon free_space_polygon(const geom::Box& domain, std::span<const geom::Polygon> blockages);

struct LinkPath {
  int links = 0;                    // 0 when the ends are equal
  std::int64_t length = 0;          // L1 length: the L1 distance between the ends in the polygon
  std::vector<geom::Point> points;  // from, bends..., to ({from} when equal)
};

struct LinkDiameter {
  int links = 0;         // the link diameter
  geom::Point from, to;  // two convex vertices that far apart
  LinkPath path;         // a path between them, fewest links and L1-shortest
  std::size_t vertices = 0;
  std::size_t convex_vertices = 0;
  std::size_t searches = 0;  // single-source searches run
  bool cut_tree = false;     // found by de Berg's divide and conquer (the searches ran out)
};

// A ring with its repeated consecutive and collinear vertices dropped (for an axis-parallel ring
// every straight continuation is collinear; a 180-degree turn cannot occur in a simple ring).
geom::Ring clean_ring(const geom::Ring& ring);

class LinkPolygon {
 public:
  // A simple rectilinear ring with integer vertices, either orientation (collinear and repeated
  // consecutive vertices are dropped); std::invalid_argument when an edge is sloped or the ring is
  // not simple (a spike that turns back on itself included).
  explicit LinkPolygon(const geom::Ring& polygon);
  ~LinkPolygon();
  LinkPolygon(LinkPolygon&&) noexcept;
  LinkPolygon& operator=(LinkPolygon&&) noexcept;

  const geom::Ring& ring() const { return ring_; }  // counter-clockwise, cleaned
  bool contains(geom::Point p) const;               // the closed polygon
  // A path with the fewest links, L1-shortest among those; std::nullopt when an end lies outside.
  std::optional<LinkPath> path(geom::Point a, geom::Point b) const;
  std::optional<int> distance(geom::Point a, geom::Point b) const;
  // The link distance from a to each target, from one search; a target that is a polygon vertex
  // costs O(1) beyond it, another point its own tracks and a scan of the graph's tracks.
  // std::invalid_argument when a point lies outside.
  std::vector<int> distances(geom::Point a, std::span<const geom::Point> targets) const;
  LinkDiameter diameter(std::size_t search_budget = 32) const;
  // The vertices with an interior angle of 90 degrees, in ring order.
  std::vector<geom::Point> convex_corners() const;
  const BendGraphStats& graph_stats() const;

 private:
  // distances() of points that may lie outside: std::nullopt then.
  std::optional<std::vector<int>> search(geom::Point a, std::span<const geom::Point> targets) const;
  geom::Ring ring_;
  std::unique_ptr<BendRouter> router_;
};

}  // namespace taut::router
