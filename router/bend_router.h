// Bend-aware rectilinear paths (issue #6; de Berg, van Kreveld, Nilsson, Overmars, seeds/003):
// the cost of a rectilinear path is its L1 length plus C times its bends (the combined metric,
// C >= 0; C = 0 is L1), or its bends first and its length second (the link metric, the limit of
// large C). Obstacles are rectilinear polygons (every edge horizontal or vertical); other
// blockages are replaced by rectilinear_cover() before they get here.
//
//   BendRouter r(normalized.domain, normalized.obstacles);       // rectilinear obstacles
//   BendPath p = r.path({0, 0}, {90, 40}, BendMetric::Combined, 7);
//   if (p.status == WireStatus::Ok) use(p.points, p.length, p.bends);
//
// Why a graph is exact (Lemma 2.1). Some optimal path has every link but the first and the last
// touching an obstacle vertex: a middle link that touches none can be slid, without raising the
// length or the bends, until it does (or until a neighbouring link vanishes). Cutting such a
// path at the touched vertices leaves pieces of at most two links ("simple steps"): from the
// start to the first vertex, between consecutive vertices, from the last vertex to the end.
//
// The modified visibility graph (section 3). Every node is a point with a wedge (a vertex where
// blockages touch has one node per wedge: FORMAT.md forbids passing between them) split into an
// h-node (the path is horizontal there) and a v-node (vertical). Edges:
//   - straight: p_h - r_h (p_v - r_v) when the horizontal (vertical) segment pr is free;
//   - a turn at a point: p_h - p_v, no length, one bend;
//   - an L: p_h - r_v when the path p -> (r.x, p.y) -> r is free and its corner is not itself a
//     vertex (then it is the straight edges and the turn there), length |pr|_1, one bend.
// The walks of this graph are exactly the paths made of simple steps, with their cost: a walk's
// bends are its turn and L edges (a walk that reverses on itself is never shortest). Dijkstra
// (Boost.Graph) on it, with the cost ordered lexicographically as (length + C * bends, bends)
// or (bends, length), gives the optimum with its tie broken the same way every time.
//
// Construction (section 3 builds the graph by two plane sweeps; here the tracks come from ray
// shooting in an R-tree and the L edges from one sweep). From every node, in every
// direction its wedge allows, a track: the free segment until the first vertex (it ends there,
// as an edge to that vertex's node: the vertex's own tracks go on), a blockage edge crossed, or
// the domain side (exact ray shooting, geom::ObstacleIndex). The L edges are the crossings of a
// horizontal and a vertical track, found by one sweep over x with the horizontal tracks in a
// search tree on y: O(n log n + k) for n vertices and k edges (k is quadratic in the worst case).
// The tracks and edges among the obstacle vertices are built once, into a compressed sparse row
// graph (the metric's cost is computed per edge when a query reads it). A query end that is not a
// vertex gets its own tracks and their crossings with the built tracks (a scan); Dijkstra runs
// on the built graph from the start's neighbours, and stops when the best offer of the end's
// neighbours is below every distance left.
//
// Free space: the closed domain minus the open obstacles, as for the L1 router: a path may run
// along blockage edges and turn on their vertices, never through a point where two blockages
// touch (nor along an obstacle edge that lies flush on the domain side).
//
// Section 4 (many queries to one fixed target): BendTargetMap below. Shape pins: path() and
// tree() on geom::Polygon pins (router/pin_shapes.h). Link distance in a simple rectilinear
// polygon and its diameter: router/link_polygon.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "geom/types.h"
#include "router/l1_router.h"  // WireStatus

namespace taut::router {

enum class BendMetric {
  Combined,  // length + C * bends, then fewer bends
  Link,      // fewer bends, then shorter
};

struct BendPath {
  WireStatus status = WireStatus::Unreachable;  // Ok, SourceNotFree, TargetNotFree or Unreachable
  std::int64_t length = 0;                      // L1 length (Ok)
  std::int64_t bends = 0;                       // bends of `points` (Ok)
  std::vector<geom::Point> points;              // from, bends..., to; integer; {from} when equal
  // What the metric minimised: length + C * bends (Combined) or bends (Link).
  __int128 cost(BendMetric metric, std::int64_t bend_cost) const {
    return metric == BendMetric::Link ? __int128{bends} : __int128{length} + __int128{bend_cost} * bends;
  }
};

// A net of one source and several sinks (points): every sink is reached from the source along
// the wires by an optimal path of the metric (the predecessor tree of one Dijkstra run, so paths
// share their common start), written as wires that meet at branch points: the first from the
// source, each other from where its path leaves the wires already written. A stretch is written
// once where a wire leaves along an earlier one from its branch point; wires of two sinks can
// still touch or overlap elsewhere (the sum of their lengths then counts that stretch twice).
struct BendTree {
  WireStatus status = WireStatus::Unreachable;  // Ok, SourceNotFree, TargetNotFree or Unreachable
  std::size_t failed = 0;                       // the sink that is not free or not reached
  std::vector<std::vector<geom::Point>> wires;  // Ok: integer, rectilinear
  std::vector<std::vector<geom::Point>> paths;  // Ok: per sink, its optimal path from the source
                                                // (on the wires; as BendRouter::path would give)
};

// What a path to one sink costs (BendRouter::costs): as path() would give, without its points.
struct BendCost {
  bool reached = false;  // false: no path (walled in)
  std::int64_t length = 0;
  std::int64_t bends = 0;
};

struct BendGraphStats {
  std::size_t vertices = 0;  // obstacle vertices (a pinch vertex counted once)
  std::size_t nodes = 0;     // point-wedge nodes (each an h- and a v-node in the graph)
  std::size_t tracks = 0;
  std::size_t straight_edges = 0;
  std::size_t l_edges = 0;
};

class BendRouter {
 public:
  // Obstacles as geom::normalize_obstacles() returns them; every edge horizontal or vertical
  // (std::invalid_argument otherwise). The domain is the closed routing box.
  BendRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles);
  ~BendRouter();
  BendRouter(BendRouter&&) noexcept;
  BendRouter& operator=(BendRouter&&) noexcept;

  // An optimal rectilinear path from `from` to `to` under the metric (bend_cost >= 0 and at most
  // 2^31 for Combined; ignored for Link). Thread-safe (const).
  BendPath path(geom::Point from, geom::Point to, BendMetric metric, std::int64_t bend_cost) const;

  // The tree of one source and several sinks (BendTree above); sinks may repeat or coincide with
  // the source.
  BendTree tree(geom::Point source, std::span<const geom::Point> sinks, BendMetric metric,
                std::int64_t bend_cost) const;

  // Pins that are points or shapes (an outer ring of one point, or a closed polygon with holes
  // whose every edge is horizontal, vertical or at 45 degrees: pin_shape_supported(), else
  // std::invalid_argument; a shape must not overlap an obstacle: pin_meets_obstacle()). A wire
  // may start anywhere on `from` (the source) and end anywhere on `to` (each sink): the optimum
  // over all such points, exact (router/pin_shapes.h: PinShapes::candidates says why a finite
  // set of candidate points holds an optimal end; the search starts from all of the source's at
  // no cost and takes the best of each sink's). Pins that share a point are joined there by a
  // wire of that one point. In a tree the paths may start at different points of the source
  // pin; a sink that touches the source gets no wire of its own unless every sink does.
  // SourceNotFree / TargetNotFree: no point of that pin is free.
  BendPath path(const geom::Polygon& from, const geom::Polygon& to, BendMetric metric, std::int64_t bend_cost) const;
  BendTree tree(const geom::Polygon& source, std::span<const geom::Polygon> sinks, BendMetric metric,
                std::int64_t bend_cost) const;
  // The first obstacle (index into the constructor's obstacles) whose interior meets the
  // interior of a shape pin (PinShapes::meets_obstacle); nullopt for a point pin.
  std::optional<std::size_t> pin_meets_obstacle(const geom::Polygon& pin) const;

  // The cost of an optimal path from the source to each sink, from one Dijkstra run, without
  // building the paths (what many-pair questions such as the link diameter need). status: Ok, or
  // SourceNotFree / TargetNotFree (then *failed is that sink) and the vector is empty; a sink that
  // is free but walled in is reported as not reached.
  std::vector<BendCost> costs(geom::Point source, std::span<const geom::Point> sinks, BendMetric metric,
                              std::int64_t bend_cost, WireStatus* status = nullptr,
                              std::size_t* failed = nullptr) const;

  // The fewest bends from the source to each sink (-1: not reached), by one 0-1 breadth-first
  // search over the graph (no lengths, no paths): what link distances need, cheaper than
  // costs(). Status as costs().
  std::vector<std::int64_t> fewest_bends(geom::Point source, std::span<const geom::Point> sinks,
                                         WireStatus* status = nullptr, std::size_t* failed = nullptr) const;

  const BendGraphStats& stats() const;

 private:
  friend class BendTargetMap;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Many queries to one fixed target (section 4 of de Berg, van Kreveld, Nilsson, Overmars): the
// cost of an optimal path from any query point to the target in O(log n) time plus the R-tree's
// ray shots (expected O(log n)), its path by following the Dijkstra tree (a step per graph
// vertex on it: its links, and the vertices its straight runs pass), after O(E log n)
// preprocessing (one Dijkstra run from the target over the graph) and O(n log n) storage.
//
// An optimal path from a query point q that is no vertex leaves q by a "simple step" to the
// first vertex p it touches (Lemma 2.1): straight along one of q's four tracks to the vertex the
// track ends on, or an L of eight kinds (first link W, E, N or S, then turning one of two ways)
// whose corner is no vertex, or straight or L to the target itself. For an L of a given kind,
// say left then down, the candidates p are the vertices whose upward track crosses q's leftward
// track, and the cost is (q.x - p.x) + (q.y - p.y) + C + dist(p), so the best p minimises
// dist(p) - p.x - p.y among the vertical segments (p's upward tracks) that cross a horizontal
// query interval (q's leftward track). The paper's slab tree: the vertices in x order at the
// leaves of a balanced tree, each node holding the lower envelope of its vertices' keys along
// y (a piecewise-constant function, linear in the node's vertices: a Davenport-Schinzel
// sequence); a query takes the O(log n) nodes that cover the interval and looks up y in each,
// by fractional cascading as in the paper: one binary search, then O(1) per node, so O(log n)
// (see SlabTree in the .cpp). The intervals are found by ray shooting in the R-tree (the paper's
// interval finding structure).
// Exact, and equal to BendRouter::path's cost for every query (tested against it and the
// reference).
class BendTargetMap {
 public:
  // bend_cost as for BendRouter::path. The router must outlive the map.
  BendTargetMap(const BendRouter& router, geom::Point target, BendMetric metric, std::int64_t bend_cost);
  // A pin as the target (router/pin_shapes.h: a point, or a shape with edges at 0, 45 or 90
  // degrees, else std::invalid_argument): the best path from q to any point of it, as
  // BendRouter::path(point pin q, target) gives it. One Dijkstra run from the shape's free
  // candidate points; a query adds q's straight shots onto the shape (the candidates that depend
  // on q: a wire ending at q's projection onto the shape is straight). A q on the shape costs 0
  // when it is free. A shape that meets a blockage is not refused here (pin_meets_obstacle):
  // wires then leave it only from its free candidates.
  BendTargetMap(const BendRouter& router, const geom::Polygon& target, BendMetric metric, std::int64_t bend_cost);
  ~BendTargetMap();
  BendTargetMap(BendTargetMap&&) noexcept;
  BendTargetMap& operator=(BendTargetMap&&) noexcept;

  // Ok, or TargetNotFree when the target is not free (then every query says so, except that a
  // free query point on a shape target costs 0: a shape lying under blockages whose candidate
  // points are all covered can still hold free points).
  WireStatus status() const;
  // The cost of an optimal path from q to the target (as BendRouter::path(q, target) gives it);
  // *status (if not null): Ok, SourceNotFree, TargetNotFree, or Unreachable (reached false).
  BendCost cost(geom::Point q, WireStatus* status = nullptr) const;
  // An optimal path from q to the target, as BendRouter::path gives one (its cost equal).
  BendPath path(geom::Point q) const;
  // Pieces of the eight slab trees' envelopes, and the entries of their catalogs (what is
  // stored: at most 4/3 of the pieces, about 1.02 times on the benchmark's layouts; 16 bytes
  // each).
  std::size_t pieces() const;
  std::size_t catalog_entries() const;
  // How a query searches the slab trees (the same answers every way). Bounded, the default:
  // O(log n), fractional cascading from the lowest node that holds the query's interval, except
  // that an interval under a node of at most 4,096 leaves (most: a track from the query point to
  // the first obstacle is short) is searched node by node, a constant's work. Cascading: always
  // cascading (O(log n); about 1.4 times Bounded's time, measured). PerNode: a binary search in
  // every node that covers the interval (O(log^2 n)); the benchmark's baseline.
  enum class SlabSearch { Bounded, Cascading, PerNode };
  void set_slab_search(SlabSearch s);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A rectilinear cover of polygons (any edges): each polygon with a sloped edge, together with
// boxes along every sloped edge of its rings (outer and holes): the edge is cut into `pieces`
// equal pieces (fewer when it spans fewer units in x and in y), and each piece's bounding box,
// rounded outwards to integers, is added. The union of the result (geom::normalize_obstacles)
// contains every input polygon and its boundary is rectilinear: a sloped edge lies inside the
// union of its boxes, touching their boundary only at its two ends and at cut points where two
// boxes meet corner to corner. The cover never grows with more pieces: every piece's box lies in
// the edge's own bounding box (pieces = 1), and the area it adds beyond the polygon is about
// 1/pieces of that box's. Polygons without a sloped edge are passed through. `covered` (if not
// null) receives the indices of the polygons that had one. pieces in [1, kMaxCoverPieces], else
// std::invalid_argument.
inline constexpr int kDefaultCoverPieces = 16;
inline constexpr int kMaxCoverPieces = 4096;
std::vector<geom::Polygon> rectilinear_cover(std::span<const geom::Polygon> polygons,
                                             std::vector<std::size_t>* covered = nullptr,
                                             int pieces = kDefaultCoverPieces);

}  // namespace taut::router
