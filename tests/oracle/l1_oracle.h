// Brute-force exact L1 shortest paths among obstacles: the reference the wavefront
// (router/wavefront) is checked against. Visibility graph + Dijkstra (Boost.Graph); shares only
// geom/predicates.h and geom/root2.h (exact a + b*sqrt(2): the distance type of the Dijkstra,
// shared with the octilinear reference, oct_oracle.h; b == 0 throughout for L1) with the code
// under test. O(n^3) to build, for n up to a few hundred.
//
// Free space. O = interior of the domain minus the closed obstacles (an open set); the free
// space is its closure F. At a point p of F the "wedges" are the local pieces of O around p:
// maximal closed angular intervals of directions d such that p + e*d lies in O for small e > 0
// (a boundary direction belongs to the wedge beside it). A path may run along obstacle edges
// and through vertices, but where it passes through p it must arrive and leave inside ONE
// wedge: this is FORMAT.md's "a wire may not pass through a point where two blockages touch"
// (two squares touching at a corner give the shared vertex two wedges). The domain boundary
// counts as a wall like an obstacle edge: an obstacle vertex touching the domain side is a
// pinch too, and a stretch where an obstacle lies flush on the domain side is not free (no
// wedge: nothing of O beside it). A query point is free iff it has at least one wedge; a
// query point at a pinch may start (or end) in any of its wedges.
//
// Why the visibility graph is exact. Cut F open at every pinch (one copy of the vertex per
// wedge): a polygonal domain whose paths are exactly the allowed paths. Some L1-shortest path
// exists and lies in some homotopy class; the Euclidean-shortest (taut) path of that class is
// also shortest for every convex distance function, in particular L1 (Hershberger-Snoeyink,
// Computing minimum length paths of a given homotopy class, Theorem 6.2, with the per-segment
// length of Lemma 6.1). The taut path is polygonal
// and bends only at reflex vertices of the cut-open domain, i.e. at obstacle vertices (copy =
// wedge); domain corners are convex. So it is a walk in the graph whose nodes are (obstacle
// vertex, wedge) plus s and t, with an edge wherever the straight segment is allowed, weighted
// |dx| + |dy|; Dijkstra on that graph gives the exact distance (every graph walk is a path).
// The same holds for every norm, with the norm's length of a segment as the weight: class
// VisibilityGraph below builds the graph once for either Metric.
//
// Segment ab (a != b) is allowed iff: a and b lie in the closed domain; it properly crosses no
// obstacle edge; cutting ab at every obstacle vertex on it, no piece's midpoint (exact, doubled
// coordinates) lies inside an obstacle, or on an obstacle edge that lies on the domain side;
// at every obstacle vertex v inside ab the directions to a and to b lie in one wedge of v; and
// it leaves each end into the end's wedge (a graph node) or into some wedge (a query point).
// (The wedge tests alone already imply the midpoint tests; those stay as the plain statement.)
// Measured (Release): ~320 vertices build and answer 800 queries in 0.16 s, ~600 in 0.3 s.
// Not thread-safe: problems() is appended to by const queries.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geom/root2.h"
#include "geom/types.h"

namespace taut::oracle {

// A closed angular interval of directions, counter-clockwise from `from` to `to`; `full` is
// every direction (a point in the open free space). Directions are integer vectors.
struct Wedge {
  std::int64_t from_x = 0, from_y = 0;
  std::int64_t to_x = 0, to_y = 0;
  bool full = false;
  bool contains(std::int64_t dx, std::int64_t dy) const;
};

// How a reference measures a straight segment ab: L1 is |dx| + |dy|; Octilinear is the length
// of the shortest path from a to b in the four orientations 0, 45, 90 and 135 degrees,
// (max - min) + min * sqrt(2) of |dx| and |dy| (geom/root2.h). Both are norms, so the argument
// above holds for each; an L1 length is a Root2 with b == 0. Farey2..Farey4: the
// fixed-orientation norms of geom/fixed_norm.h, N(v) = max_i lambda_i . v (an integer, scaled
// by geom::kNormScale; a Root2 with b == 0).
enum class Metric { L1, Octilinear, Farey2, Farey3, Farey4 };
geom::Root2 segment_length(Metric metric, geom::Point a, geom::Point b);

// The visibility graph of the comment above and Dijkstra on it, in either metric: the nodes and
// the allowed edges (the free-space, wedge and pinch rules) do not depend on the metric, only
// the edge weights do. The base of L1Reference (below, answers in int64) and of
// OctilinearReference (oct_oracle.h, answers as they are here). Lengths are exact Root2 numbers:
// the Dijkstra of Boost.Graph runs with Root2 as its distance type, compared exactly.
class VisibilityGraph {
 public:
  // Obstacles as geom::normalize_obstacles() makes them: integer vertices, outer rings
  // counter-clockwise, holes clockwise, closed sets pairwise disjoint, weakly simple rings,
  // inside the closed domain.
  VisibilityGraph(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                  Metric metric);

  // Shortest length; nullopt when s or t is not free or t is unreachable from s.
  std::optional<geom::Root2> distance(geom::Point s, geom::Point t) const;
  std::vector<std::optional<geom::Root2>> distances(geom::Point s,
                                                    std::span<const geom::Point> targets) const;
  // A shortest path s, bends (obstacle vertices)..., t; {s} when s == t is free.
  std::optional<std::vector<geom::Point>> path(geom::Point s, geom::Point t) const;

  // The wedges at p (empty: p is not free; two or more: p is a pinch).
  std::vector<Wedge> wedges_at(geom::Point p) const;
  bool is_free(geom::Point p) const { return !wedges_at(p).empty(); }
  // Segment ab allowed between two query points (each end may use any of its wedges).
  bool visible(geom::Point a, geom::Point b) const;
  // Total length of a polygonal path if every segment is allowed (intermediate points must
  // stay in one wedge: checked with the wedge of each point), else nullopt. For checking
  // paths produced by other code.
  std::optional<geom::Root2> check_path(std::span<const geom::Point> path) const;

  // Inconsistencies seen in the input (a sector both inside and outside an obstacle,...);
  // empty for input that meets the contract above.
  const std::vector<std::string>& problems() const { return problems_; }
  std::size_t node_count() const { return nodes_.size(); }
  std::size_t edge_count() const { return graph_edges_.size(); }

 private:
  struct Edge {  // a directed ring edge with the obstacle on its left
    geom::Point a, b;
  };
  struct Node {
    geom::Point p;
    Wedge wedge;
  };
  struct GraphEdge {
    std::size_t u, v;
    geom::Root2 w;
  };
  struct Search;   // one Dijkstra run from a source (l1_oracle.cpp)
  struct Arrival;  // the best way from a Search to a target

  bool inside_domain(geom::Point p) const;
  // The conditions above except the end wedges.
  bool segment_clear(geom::Point a, geom::Point b) const;
  // Segment ab allowed, leaving a into one of `wa` and b into one of `wb`.
  bool allowed(geom::Point a, std::span<const Wedge> wa, geom::Point b,
               std::span<const Wedge> wb) const;
  Search search_from(geom::Point s) const;
  Arrival arrive(const Search& sr, geom::Point t, std::span<const Wedge> wt) const;
  geom::Root2 length(geom::Point a, geom::Point b) const { return segment_length(metric_, a, b); }

  geom::Box domain_;
  Metric metric_;
  std::vector<geom::Polygon> obstacles_;
  std::vector<Edge> edges_;
  std::map<geom::Point, std::vector<Wedge>> vertex_wedges_;  // every obstacle vertex
  std::vector<Node> nodes_;
  std::vector<GraphEdge> graph_edges_;
  mutable std::vector<std::string> problems_;
};

// The L1 reference: VisibilityGraph with Metric::L1, lengths as int64 (the Root2 lengths of L1
// have b == 0).
class L1Reference : private VisibilityGraph {
 public:
  // Obstacles as for VisibilityGraph.
  L1Reference(const geom::Box& domain, std::span<const geom::Polygon> obstacles)
      : VisibilityGraph(domain, obstacles, Metric::L1) {}

  // Shortest L1 length; nullopt when s or t is not free or t is unreachable from s.
  std::optional<std::int64_t> distance(geom::Point s, geom::Point t) const;
  std::vector<std::optional<std::int64_t>> distances(geom::Point s,
                                                     std::span<const geom::Point> targets) const;
  // Total L1 length of a polygonal path if every segment is allowed, else nullopt.
  std::optional<std::int64_t> check_path(std::span<const geom::Point> path) const;

  // As in VisibilityGraph.
  using VisibilityGraph::edge_count;
  using VisibilityGraph::is_free;
  using VisibilityGraph::node_count;
  using VisibilityGraph::path;
  using VisibilityGraph::problems;
  using VisibilityGraph::visible;
  using VisibilityGraph::wedges_at;

 protected:
  // Another metric whose lengths are integers (NormReference).
  L1Reference(const geom::Box& domain, std::span<const geom::Polygon> obstacles, Metric metric)
      : VisibilityGraph(domain, obstacles, metric) {}
};

// The reference for a fixed-orientation norm of geom/fixed_norm.h (order 2, 3 or 4): the same
// graph, each edge weighted by N(b - a) = max_i lambda_i . (b - a), an exact integer (the
// argument above holds for every norm); the interface of L1Reference, lengths in N.
class NormReference : public L1Reference {
 public:
  NormReference(const geom::Box& domain, std::span<const geom::Polygon> obstacles, int order)
      : L1Reference(domain, obstacles,
                    order == 2 ? Metric::Farey2 : order == 3 ? Metric::Farey3 : Metric::Farey4) {}
};

}  // namespace taut::oracle
