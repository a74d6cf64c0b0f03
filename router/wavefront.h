// Exact L1 shortest paths among polygonal obstacles by continuous Dijkstra (Mitchell,
// "L1 shortest paths among polygonal obstacles in the plane", Algorithmica 1992, §2-§5).
//
//   L1Wavefront wf(normalized.domain, normalized.obstacles);
//   Point s{0, 0}, t{900, 40};
//   wf.run({&s, 1}, {&t, 1});
//   if (auto d = wf.target_distance(0)) { auto path = wf.target_path(0); }
//
// What it computes. From one or more free source points a signal spreads through free space;
// every obstacle vertex (more exactly: every (vertex, free wedge) pair, see below) gets its
// exact L1 distance d(v) (an integer) and its parent in the shortest path tree, and every
// target point gets its distance and a polygonal shortest path: source, bends at obstacle
// vertices, target. With several sources the distances are to the nearest source.
//
// How (Mitchell §4). The wavefront is kept as "wavelets": ±45° segments dragged in one of the
// four diagonal directions, each with a root r (a source or an obstacle vertex) and two track
// rays (a horizontal ray, a vertical ray, or an obstacle edge the end slides along). Wavelets
// sit in a priority queue keyed by the distance at which they next hit something; popping one
// is an event:
//   - hitting a vertex p inside the segment (Type II) or at an end (Type III) splits the wavelet
//     into the part left of p (bounded by the vertical ray up from p, or by p's obstacle edge)
//     and the part right of p; p, when reached for the first time, is labelled and becomes a
//     root, its own wavelets covering the quadrants around it that the obstacle leaves free;
//   - stop points (a track ray running into an obstacle edge, Type I) are not separate events
//     here: the edge a track ray hits is found when the wavelet is made (ray shooting), and the
//     wavelet's swept region is the intersection of the half-planes of its tracks and of those
//     stop edges, which is exactly the region Mitchell's Type I event would produce;
//   - clipping (§4 Propagate, case 4) is NOT applied yet: every part of a split wavelet goes
//     on even when an earlier root reached the vertex from the same direction. That is always
//     correct (a part only ever gives upper bounds that are real path lengths) but costs
//     events. A first rule (drop the left part unless the root lies left of every earlier
//     hitter, the right part unless below) was wrong when the earlier hitter had slid along an
//     obstacle edge into the vertex (random seed 1003015, kept as a regression seed); it was
//     removed until it is restated with a proof (git history: commit d6deb71).
//
// Segment-dragging queries (§3): "which vertex does this wavelet hit first" is the vertex with
// the smallest diagonal coordinate inside the wavelet's region, a convex region given by at most
// five half-planes. A static k-d tree over the vertices answers it by branch and bound on the
// diagonal coordinate, searched bottom-up from the leaf of the wavelet's apex (a vertex): that
// leaf, then the sibling subtree of each ancestor, until the region's bounding box (the region
// clipped exactly from the domain, rounded out to integers) and the best level found show that
// nothing outside the subtree can be hit earlier. Cost: proportional to the nodes whose boxes
// meet the region near the answer, up to O(sqrt n) for thin regions; measured: about 6 nodes
// per query at 3*10^5 vertices (from 48 for the same search from the root), stats().drag_nodes.
// The tracks' ends, the edges met
// by the vertical and horizontal rays of every obstacle vertex, are found once at construction
// by two plane sweeps (O(n log n) in all, a balanced tree of the edges crossing the sweep
// line, exact orientation tests in the sheared order); rays from query points (sources,
// targets) probe the R-tree of obstacle edges with exact rational crossings (geom/index.h
// windows; O(log n) per window; a crossing beyond the window is not taken, since a nearer edge
// may miss the window's box, which for diagonal rays is the square around the segment).
//
// Degeneracy rule: symbolic shear. Real layouts put vertices on common horizontals, verticals
// and diagonals; Mitchell assumes they do not (his GPA). taut runs the algorithm on the sheared
// plane X = x + e*y, Y = y + e^2*x for an infinitesimal e > 0. The shear is linear, so it keeps
// every incidence, touching point and visibility of the layout, and orientation signs; but no
// two distinct points share X, Y, X+Y or X-Y, and no edge is parallel to an axis or a diagonal.
// Every comparison of a coordinate or a distance is a lexicographic comparison of the integer
// coefficients of 1, e, e^2 (e.g. "q is right of p's vertical" is (q.x, q.y) > (p.x, p.y)).
// Distances carry the same three coefficients; the constant term is the exact L1 length, which
// is what every interface returns (the shortest sheared path is a shortest path: both metrics
// are continuous in e over the same finite set of visibility paths). Ties that remain (two
// roots reaching a vertex at identical symbolic distance) go to the earlier-made wavelet.
//
// Free space and pinches: as in tests/oracle/l1_oracle.h. Obstacles are closed and the domain
// side is a wall (the domain is merged into a frame obstacle so an obstacle vertex touching it
// is a pinch); a path passes through a vertex only within one free wedge ("a wire may not pass
// through a point where two blockages touch"), so the algorithm labels (vertex, wedge) pairs; a
// query point at a pinch may start or end in any of its wedges.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "geom/root2.h"
#include "geom/types.h"

namespace taut::router {

// When a run may stop: once every free target is reached, once the first one is (a nearest
// target to the sources: compare target_distance() over the reached targets; others may be
// reached too, never nearer), or never (the whole distance field).
enum class WavefrontStop { AllTargets, FirstTarget, Never };

struct WavefrontStats {
  std::int64_t vertices = 0;      // distinct obstacle vertex points (frame included)
  std::int64_t entities = 0;      // (vertex, free wedge) pairs, plus the run's query points
  std::int64_t events = 0;        // wavelets popped from the queue
  std::int64_t wavelets = 0;      // wavelets made
  std::int64_t labelled = 0;      // entities reached
  std::int64_t drag_queries = 0;  // segment-dragging (k-d tree) queries
  std::int64_t drag_nodes = 0;    // k-d tree nodes those queries visited
  std::int64_t ray_queries = 0;   // track rays shot one by one (ray grid or R-tree): from query
                                  // points, and from obstacle vertices until an orientation has
                                  // shot as many as there are vertices (a plane sweep then
                                  // answers the rest)
};

// A free wedge of an obstacle vertex p: it runs counter-clockwise from the direction of ring
// neighbour `lo` to that of `hi`, with its distance and source after run() (nullopt when not
// reached). A pinch has one wedge per free side. C: the metric's distance type.
template <class C>
struct WavefrontWedge {
  geom::Point lo, hi;
  std::optional<C> distance;
  std::optional<std::size_t> source;
};

class L1Wavefront {
 public:
  // Obstacles as geom::normalize_obstacles() returns them (integer vertices, outer rings
  // counter-clockwise, holes clockwise, pairwise disjoint closed sets, weakly simple rings,
  // inside the closed domain).
  L1Wavefront(const geom::Box& domain, std::span<const geom::Polygon> obstacles);
  ~L1Wavefront();
  L1Wavefront(L1Wavefront&&) noexcept;
  L1Wavefront& operator=(L1Wavefront&&) noexcept;

  // A point is free when some piece of open free space touches it (same rule as the oracle):
  // inside the domain, not inside an obstacle, not on an obstacle edge that lies flush on the
  // domain side.
  bool is_free(geom::Point p) const;

  // One run: propagates from every free source (distance 0) until every free target is
  // reached (stop_early) or the wavefront dies out (the whole distance field). Sources and
  // targets that are not free are ignored (unreachable). A new run forgets the previous one.
  void run(std::span<const geom::Point> sources, std::span<const geom::Point> targets,
           bool stop_early = true);
  // stop_early = true is Stop::AllTargets, false is Stop::Never.
  using Stop = WavefrontStop;
  void run(std::span<const geom::Point> sources, std::span<const geom::Point> targets, Stop stop);
  // The same with SEGMENT sources too (wires, pin edges): each segment, horizontal, vertical or
  // at 45 degrees, is a source along its whole length (distance 0 at each of its points). Source
  // indices in answers (target_source, Wedge::source) number the point sources first, then the
  // segments (sources.size() + k for segment k); target_path() starts at the segment's point the
  // path leaves from. A segment of another direction throws std::invalid_argument. Points of a
  // segment that are not free are not sources (a wire must not cross a blockage).
  //
  // How: the L1 distance from a segment S is the least over finitely many of its points, so
  // they run as point sources. A shortest path from S leaves it at a point p and runs to its
  // first bend w (an obstacle vertex, or the target) with length |w - p|_1, p ranging over the
  // part F_w of S from which a monotone free path reaches w. |w - p|_1 is piecewise linear along
  // S with its breaks where p is level with w (the vertical or horizontal projection of w onto
  // S), and the ends of F_w are where a blocking obstacle's extreme vertex projects onto S. So
  // the least value is at S's ends or at the horizontal or vertical projection of a ring vertex
  // or a target: every such point of S (integer points, as every coordinate is) is a source.
  // Cost: O(number of distinct vertex and target coordinates in S's range) sources per segment.
  void run(std::span<const geom::Point> sources, std::span<const geom::Segment> segment_sources,
           std::span<const geom::Point> targets, Stop stop);

  // After run(): exact L1 distance of target i to the nearest source; nullopt = unreachable.
  std::optional<std::int64_t> target_distance(std::size_t i) const;
  // Index (into run's sources) of the source target i was reached from.
  std::optional<std::size_t> target_source(std::size_t i) const;
  // A shortest path source -> bends (obstacle vertices) -> target i, consecutive points
  // distinct; {p} when the target equals its source; empty when unreachable.
  std::vector<geom::Point> target_path(std::size_t i) const;
  // Distance of obstacle vertex p (minimum over its wedges); nullopt when p is not an obstacle
  // vertex or was not reached.
  std::optional<std::int64_t> vertex_distance(geom::Point p) const;

  // For structures built on a finished run (router/spm.h). The obstacles the algorithm works
  // on: the input's, with the domain side merged into a frame obstacle (an outer ring around
  // the domain and the domain as its hole), so every wall of free space is an obstacle edge.
  std::span<const geom::Polygon> frame_obstacles() const;
  // The free wedges of obstacle vertex p (empty when p is not one): each runs counter-
  // clockwise from the direction of ring neighbour `lo` to that of `hi`, with its distance and
  // source after run() (nullopt when not reached). A pinch has one wedge per free side.
  using Wedge = WavefrontWedge<std::int64_t>;
  std::vector<Wedge> vertex_wedges(geom::Point p) const;
  // A shortest path source -> bends -> p reaching p in its wedge k (vertex_wedges() order);
  // empty when not reached.
  std::vector<geom::Point> wedge_path(geom::Point p, std::size_t k) const;

  const WavefrontStats& stats() const;
  // Bytes held by its own arrays (points, entities, k-d tree, ray answers, ...); the R-tree of
  // obstacle edges and the queue are not counted (bench_wavefront measures those by heap use).
  std::size_t memory_bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The same continuous Dijkstra in the OCTILINEAR metric (Mitchell §6, Theorem 3: fixed
// orientations 0, 45, 90 and 135 degrees): the length of a vector (dx, dy) is
// d8 = max(|dx|, |dy|) + (sqrt2 - 1) min(|dx|, |dy|), the length of the shortest path from 0 to
// (dx, dy) that uses only the four orientations, so distances are the least lengths of
// octilinear paths among the obstacles. They are exact numbers a + b*sqrt2 (geom/root2.h).
//
// How it differs from L1Wavefront: eight frames instead of four, one per cone between two
// neighbouring orientations (E..NE, NE..N, ...). A frame's local axes are its cone's two
// orientations, its local east an axis direction (weight 1) and its local north a diagonal
// (weight sqrt2), as the integer unimodular map (u, v) = M (x, y), e.g. u = x - y, v = y for
// the cone E..NE; a wavelet is a segment of the line u + sqrt2 v = const (an edge of the unit
// octagon) dragged across its cone, with track rays along the two orientations (diagonal rays
// included). Levels and distances are pairs of the sheared T3 numbers compared in Z[sqrt2] one
// order of the shear at a time; everything else (events, wedges, pinches, the degeneracy rule,
// free space) is as in L1Wavefront. target_path() is the polygonal path (bends at obstacle
// vertices, links of any direction, each measured by d8); router/staircase.h turns it into an
// octilinear wire.
class OctWavefront {
 public:
  OctWavefront(const geom::Box& domain, std::span<const geom::Polygon> obstacles);
  ~OctWavefront();
  OctWavefront(OctWavefront&&) noexcept;
  OctWavefront& operator=(OctWavefront&&) noexcept;

  bool is_free(geom::Point p) const;
  using Stop = WavefrontStop;
  void run(std::span<const geom::Point> sources, std::span<const geom::Point> targets,
           Stop stop = Stop::AllTargets);
  // With SEGMENT sources too, numbered and checked as L1Wavefront's: each segment, horizontal,
  // vertical or at 45 degrees, is a source at each of its LATTICE points (integer points: a wire
  // leaving it starts at one, as wire vertices are integers). How: as L1Wavefront's, with d8 for
  // L1. A shortest path from S leaves it at p and runs to its first bend w with length d8(w - p),
  // piecewise linear along S with its breaks where w - p is horizontal, vertical or diagonal (the
  // projections of w onto S), over the part F_w of S from which such a path reaches w, whose
  // ends are projections of blocking obstacles' vertices (a path from an end passes such a
  // vertex v as short, so v takes w's place there). So the least over S's lattice points is at
  // S's ends or next to a projection of a ring vertex or a target (ProjectionLines): along a
  // horizontal or vertical S, d8(w - p) grows with |p - w's perpendicular projection|, so the
  // perpendicular projections suffice (the diagonal ones were sources until 2026-12-03: dropping
  // them changed no test and no benchmark length, and made trees 1.0-1.6 times faster); along a
  // diagonal S every break counts (horizontal, vertical and the other diagonal's projection,
  // which may fall halfway between two lattice points: both are sources). The least over all
  // points of S may be less (at a half-integer point), not reachable by a wire with integer
  // vertices.
  // LATTICE k > 1 (NetRouter's scaled plane, NetRouterOptions::exact_gaps: its wires are snapped
  // to multiples of k): the other diagonal's projections onto a diagonal S are rounded down and
  // up to multiples of k in x instead of to integers (S's own line being near such a multiple,
  // the points are then near multiples of k in y too), so no source lies halfway between two
  // multiples of k, where snapping would move a wire off its direction. The same argument (the
  // least over those points of S is next to a break) holds for the coarser lattice.
  void run(std::span<const geom::Point> sources, std::span<const geom::Segment> segment_sources,
           std::span<const geom::Point> targets, Stop stop, std::int64_t lattice = 1);
  std::optional<geom::Root2> target_distance(std::size_t i) const;
  std::optional<std::size_t> target_source(std::size_t i) const;
  std::vector<geom::Point> target_path(std::size_t i) const;
  std::optional<geom::Root2> vertex_distance(geom::Point p) const;
  // As L1Wavefront's (for router/spm.h's octilinear map).
  std::span<const geom::Polygon> frame_obstacles() const;
  using Wedge = WavefrontWedge<geom::Root2>;
  std::vector<Wedge> vertex_wedges(geom::Point p) const;
  std::vector<geom::Point> wedge_path(geom::Point p, std::size_t k) const;
  const WavefrontStats& stats() const;
  std::size_t memory_bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The same continuous Dijkstra in a FIXED-ORIENTATION NORM of geom/fixed_norm.h (Mitchell §6,
// Theorem 3, with more orientations): `order` 2, 3 or 4 gives 16, 32 or 48 directions (k = 8,
// 16 or 24 orientations, Farey directions, not evenly spaced), each direction d_i costing
// w_i = ceil(kNormScale |d_i|) per unit. Distances are exact integers: the least N-length of a
// path among the obstacles, N(v) = max_i lambda_i . v. They bracket the Euclidean geodesic
// distance d_E: d_E in [d / Lambda, d / kNormScale] (geom::fixed_norm_epsilon(order): 2.75 %,
// 1.31 %, 0.76 %), which is what `taut spm --orientations any [--epsilon E]` reports.
//
// How it differs from L1Wavefront: one frame per cone between consecutive directions, whose
// local axes are the cone's two directions (a unimodular frame: consecutive Farey directions
// have determinant 1), level w_i u + w_{i+1} v; track rays along every direction (a plane sweep
// per orientation). Everything else (events, wedges, pinches, the symbolic shear, which breaks
// ties along every fixed direction) is L1Wavefront's. target_path() is the polygonal path (bends
// at obstacle vertices).
//
// Range: path lengths are kNormScale (2^12) times an L1 length; the constructor throws
// std::domain_error when (vertices + 2) * (width + height + 2) * 2^12 could pass 2^62.
class NormWavefront {
 public:
  NormWavefront(const geom::Box& domain, std::span<const geom::Polygon> obstacles, int order);
  ~NormWavefront();
  NormWavefront(NormWavefront&&) noexcept;
  NormWavefront& operator=(NormWavefront&&) noexcept;

  int order() const { return order_; }
  bool is_free(geom::Point p) const;
  using Stop = WavefrontStop;
  void run(std::span<const geom::Point> sources, std::span<const geom::Point> targets,
           Stop stop = Stop::AllTargets);
  // The N-length (scaled by geom::kNormScale) of the nearest source.
  std::optional<std::int64_t> target_distance(std::size_t i) const;
  std::optional<std::size_t> target_source(std::size_t i) const;
  std::vector<geom::Point> target_path(std::size_t i) const;
  std::optional<std::int64_t> vertex_distance(geom::Point p) const;
  const WavefrontStats& stats() const;
  std::size_t memory_bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int order_ = 0;
};

// Where a shortest path to or from a segment may leave or reach it (the segment sources of
// L1Wavefront::run and OctWavefront::run, and the Steiner trees' re-joins, l1_router.h): the
// lines through a set of points along which a projection onto a segment falls. add() points,
// then done() sorts; the diagonal keys only when `octilinear`.
class ProjectionLines {
 public:
  explicit ProjectionLines(bool octilinear, std::int64_t lattice = 1) : octilinear_(octilinear), lattice_(lattice) {}
  void add(geom::Point p);
  void done();
  // Appends to `out` the lattice points of segment ab (horizontal, vertical or at 45 degrees;
  // not checked) STRICTLY between a and b where a vertical or horizontal line through one of the
  // points meets it (for a horizontal segment the vertical lines only, and the other way round),
  // and for octilinear along a diagonal segment where the other diagonal through one of them
  // meets it, rounded down and up to the segment's lattice when that is halfway between two
  // lattice points (OctWavefront::run says why these suffice). With `lattice` k > 1, the
  // other diagonal's points are instead rounded down and up to multiples of k in x
  // (OctWavefront::run, LATTICE).
  void inside(geom::Point a, geom::Point b, std::vector<geom::Point>& out) const;

 private:
  bool octilinear_;
  std::int64_t lattice_ = 1;
  std::vector<std::int64_t> xs_, ys_, ds_, ss_;  // distinct x, y, y - x, x + y, ascending
};

// Convenience: the exact L1 distance between two points among the obstacles (nullopt when
// either is not free or t is unreachable).
std::optional<std::int64_t> l1_distance(const geom::Box& domain,
                                        std::span<const geom::Polygon> obstacles, geom::Point s,
                                        geom::Point t);

}  // namespace taut::router
