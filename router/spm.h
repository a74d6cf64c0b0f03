// The L1 shortest path map of one or more point sources among polygonal obstacles: built once,
// then the distance to the nearest source, which source, and a shortest path for any query
// point by point location (Mitchell §2 "SPM", §5 multiple sources; the cells merged by source are the
// L1 geodesic Voronoi diagram).
//
//   L1Map map(normalized.domain, normalized.obstacles, sources);
//   if (auto a = map.locate({900, 40})) { a->distance; a->source; map.path({900, 40}); }
//
// How. One multi-source wavefront run (router/wavefront.h, to the end) labels every obstacle
// vertex with its exact distance. The map is then a vertical (trapezoidal) decomposition of free
// space, with on each trapezoid side the exact distance function of the points beyond it:
//
//   Every shortest path ends with a straight link from its last bend r (an obstacle vertex or a
//   source) to the query point q. Cut free space by the vertical walls through every vertex and
//   source into trapezoids; the link crosses the walls in x order, each inside a trapezoid side.
//   So d(q) = min over the left-to-right and right-to-left families of "rays": a ray is a root r
//   carried along monotone paths from wall to wall, with value d(r) + |x - x_r| + |y - y_r| on
//   the points it reaches. A ray that went up (y >= y_r) reaches, in the next trapezoid, every
//   point with y >= a, its threshold (the lowest height at which it entered); one that went down
//   every point with y <= b. Every value is the length of a real path (so never below d(q)),
//   and the straight last link is one of them (so d(q) is attained).
//
// A side keeps its rays as two staircases (up: thresholds rising, values falling; down: the
// mirror): a ray that starts no lower and costs no less than another is dropped, since it is
// beaten wherever it reaches. A query finds its trapezoid by point location: a uniform grid of
// about one cell per trapezoid answers most queries (a cell lists the trapezoids whose box meets
// it; a short, complete list decides); the rest go to a search in the sweep itself (Sarnak &
// Tarjan): the sweep's ordered set of edges, made persistent by node copying (a treap; every
// version kept in O(1) expected nodes per update), is searched in the version of the last point
// before q, and the trapezoid above the edge found is the one open there. Then four staircases
// of its two sides are binary-searched. What queries read lives on transparent huge pages
// (router/huge_pages.h).
//
// Costs, honestly. Query: O(log n) on every layout, with high probability over the treap's
// priorities (a fixed hash of the edge id), plus at most 16 exact tests in the grid: 1.7-1.8 us
// at 10^6 vertices on generated layouts (1-4 % of queries reach the treap), about 1.3 us on
// 16,000 parallel sloped strips, where the R-tree of trapezoid boxes used before scanned O(n)
// of them (205 us). Size: sides do not share their staircases, so a side can hold a ray per root: about
// 20 rays per trapezoid measured on generated and Moving AI layouts, but O(n (n + k)) in the
// worst case (k sources on a diagonal below-left of m tall walls: 120 million rays, 3.2 GB for
// k = m = 4,000). Mitchell's map is O(n); sharing staircases between sides would get there.
// Past 2^32 rays the constructor throws std::length_error (taut: exit status 4).
//
// Paths. Among the rays of least value at q the one with the largest root distance d(r) wins:
// its root sees q straight (if it did not, the taut monotone path from r to q would bend at a
// vertex v with d(v) = d(r) + |v - r| > d(r) whose ray reaches q as cheaply). The path is the
// wavefront's shortest path to r, then q: O(k).
//
// Shape sources (pins: polygons with horizontal, vertical and 45-degree edges, sources along
// their whole boundary; L1 only). The shapes are obstacles of the decomposition and their
// edges are labelled with their source. The wavefront labels the vertices from segment sources
// (router/wavefront.h). What a point source's rays cannot carry is the part of the distance
// that runs straight out of a side: a trapezoid whose bottom (top) edge is a shape's
// horizontal or 45-degree side has its "front", the distance straight down (up) to it, and
// passes it on at its walls as the rays of the side's point on the wall (a root of distance 0);
// a vertical side starts "flat" rays on the wall side it faces, the distance straight across
// (K plus the horizontal distance, for y in a range), carried from side to side like the
// staircases and clipped to each side's range (their ends are the side's own corners, or
// blockage edges). An answer from a front or a flat names the foot on the shape (root_id
// kFootRoot; the foot sees the query straight); on a tie a root is preferred. Cost: a query
// also scans the flats of its trapezoid's two sides, one per vertical shape side it sees
// straight across (a column of n pads facing one open region: O(n) there), so the O(log n)
// query bound above holds for maps without shape sources.
//
// Exactness. Values are integers; thresholds are the heights where walls meet sloped edges,
// exact rationals. Degeneracies (shared x, vertical edges, several vertices on one wall) are
// resolved by the same symbolic shear as the wavefront's: the sweep orders points by (x, y), so
// walls through vertices on a common vertical are distinct, separated by trapezoids of width 0.
// Pinches: a wall part below a vertex and the part above it exchange rays only when free space
// joins them on one side of the vertex; a wedge that only touches the vertex (a pinch) gets the
// vertex's own distance in that wedge and nothing else.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geom/root2.h"
#include "geom/types.h"
#include "router/rational_root.h"

namespace taut::router {

struct RPoint {
  Rational x, y;
  friend bool operator==(const RPoint&, const RPoint&) = default;
  friend bool operator<(const RPoint& a, const RPoint& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; }
};
// Twice the signed area of a ring (positive: counter-clockwise).
Rational twice_signed_area(const std::vector<RPoint>& ring);

struct R2Point {
  RationalRoot2 x, y;
  friend bool operator==(const R2Point&, const R2Point&) = default;
};
RationalRoot2 twice_signed_area(const std::vector<R2Point>& ring);

class L1Map {
 public:
  // Obstacles as geom::normalize_obstacles() returns them; sources that are not free are
  // ignored (no query reaches them); source indices in answers are positions in `sources`.
  struct Options {
    // Answer queries from the grid first (the fast path); false: every query by the
    // persistent search alone (the same answers; the tests compare the two).
    bool grid = true;
  };
  L1Map(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
        std::span<const geom::Point> sources, Options options);
  L1Map(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
        std::span<const geom::Point> sources)
      : L1Map(domain, obstacles, sources, Options{}) {}
  // With SHAPE sources as well (pins): polygons without holes whose edges are horizontal,
  // vertical or at 45 degrees, each a source along its whole boundary (distance 0 there; its
  // inside is not free: paths go around it). Each must lie inside the domain off its sides and
  // have no point in common with an obstacle or another shape; else std::invalid_argument with
  // what shape_problem() returns. Source indices: the point sources first, then the shapes.
  // Answers reached straight out of a shape's side name the foot on the shape as their root
  // (root_id kFootRoot); the cells from such a side are pieces with a root_segment.
  L1Map(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
        std::span<const geom::Point> sources, std::span<const geom::Polygon> shapes, Options options);
  L1Map(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
        std::span<const geom::Point> sources, std::span<const geom::Polygon> shapes)
      : L1Map(domain, obstacles, sources, shapes, Options{}) {}
  // Why the shapes cannot be sources of a map on these obstacles ("" when they can): the first
  // problem, naming its shape ("shape source k: it touches or overlaps a blockage").
  static std::string shape_problem(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                   std::span<const geom::Polygon> shapes);
  // Per shape, in order, why it cannot be a source beside the obstacles, the shapes before it
  // that can, and `points` (point sources: one on or in a shape would not be free); kind None
  // for those that can. For choosing the shapes to pass (taut voronoi leaves the others out).
  struct ShapeProblem {
    enum class Kind { None, NotPolygon, OffDomain, NotSimple, Angle, Blockage, Shape, Point } kind = Kind::None;
    std::size_t other = 0;  // Shape: the earlier shape it touches; Point: the point on or in it
    explicit operator bool() const { return kind != Kind::None; }
    std::string text() const;  // "it touches or overlaps a blockage", ...
  };
  static std::vector<ShapeProblem> shape_problems(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                  std::span<const geom::Polygon> shapes,
                                                  std::span<const geom::Point> points = {});
  static constexpr std::uint32_t kFootRoot = 0xFFFFFFFEu;
  // The shape sources as the map holds them (cleaned: one counter-clockwise outer ring each,
  // in the order given), and shape k's source index (the number of point sources + k).
  std::span<const geom::Polygon> shape_sources() const;
  std::size_t shape_source_index(std::size_t k) const;
  ~L1Map();
  L1Map(L1Map&&) noexcept;
  L1Map& operator=(L1Map&&) noexcept;

  // Same rule as L1Wavefront::is_free, answered by the map's point location.
  bool is_free(geom::Point q) const;

  struct Answer {
    std::int64_t distance = 0;  // exact L1 distance to the nearest source
    std::size_t source = 0;     // that source's index
    geom::Point root;           // the last bend (or the source) before q: it sees q straight;
                                // q itself when q is an obstacle vertex or a source
    std::uint32_t root_id = 0;  // the map's handle of that root (for path(q, answer))
  };
  // nullopt when q is not free or no source reaches it (walled in).
  std::optional<Answer> locate(geom::Point q) const;
  // A shortest path: the source, bends at obstacle vertices, q ({q} when q is a source); empty
  // when locate() is nullopt.
  std::vector<geom::Point> path(geom::Point q) const;
  // The same from locate()'s answer for q, without locating q again: O(k).
  std::vector<geom::Point> path(geom::Point q, const Answer& a) const;

  // The decomposition's cells (for checks and pictures): trapezoid i lies between the walls
  // through `left` and `right` (x from left.x to right.x; width 0 between points on a common
  // vertical, ordered by y), above segment `bottom` and below segment `top` (obstacle edges).
  struct Trapezoid {
    geom::Point left, right;
    geom::Segment bottom, top;
  };
  std::vector<Trapezoid> trapezoids() const;

  // The map's cells as convex pieces with exact vertices (Mitchell's SPM refined by the
  // decomposition): every point q of a piece has d(q) = root_distance + |q - root|_1 and is
  // seen straight from root. Pieces have positive area, cover the reached free space and
  // overlap only on their boundaries; points no source reaches are in no piece.
  // ByRoot: one root per piece (the structure the tests check against the reference).
  // BySource: a piece may join the cells of several roots of one source (fewer, larger pieces:
  // what the Voronoi diagram merges); its root fields are then those of one of them, and only
  // `source` is meaningful.
  enum class Detail { ByRoot, BySource };
  struct Piece {
    std::vector<RPoint> ring;  // convex, counter-clockwise, no repeated vertex
    std::size_t source = 0;
    geom::Point root;
    std::int64_t root_distance = 0;
    // Set for a piece reached straight out of a shape source's side (its front: straight up
    // or down to a horizontal or 45-degree edge; a flat: straight across to a vertical one):
    // the distance of each of its points is its L1 distance to this segment's supporting line
    // (root is the segment's first end, root_distance 0).
    std::optional<geom::Segment> root_segment;
  };
  std::vector<Piece> pieces(Detail detail) const;

  struct Stats {
    std::int64_t vertices = 0;    // decomposition points (obstacle vertices, frame, sources)
    std::int64_t trapezoids = 0;  // free trapezoids (cells of the map before merging by root)
    std::int64_t rays = 0;        // staircase entries over all trapezoid sides
    std::int64_t roots = 0;       // (vertex, wedge) roots and sources carrying a ray, and the
                                  // points of shape sides on walls (shape sources)
    std::int64_t location_nodes = 0;  // nodes of the persistent search tree (point location)
  };
  const Stats& stats() const;
  std::size_t memory_bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The OCTILINEAR shortest path map (Mitchell §6, Theorem 3): the same questions as L1Map, with
// distances the least lengths of paths in the four orientations 0, 45, 90 and 135 degrees
// (exact a + b*sqrt2, geom/root2.h), from one OctWavefront run (router/wavefront.h).
//
//   OctMap map(normalized.domain, normalized.obstacles, sources);
//   if (auto a = map.locate({900, 40})) { a->distance; a->source; map.path({900, 40}); }
//
// How. The octilinear length of a vector in the cone between two neighbouring orientations e
// (an axis, weight 1) and f (a diagonal, weight sqrt2) is s + sqrt2 t for the vector s e + t f,
// s, t >= 0. In the integer coordinates (u, v) of the basis (e, f) (a unimodular map, so
// lattice points, lines and orientations are kept) that is the weighted L1 length
// |du| + sqrt2 |dv|, and it is exact in the opposite cone as well. So four frames, one per pair
// of opposite cones, each get L1Map's decomposition and staircases in their own coordinates
// with steps weighted 1 and sqrt2; every value in a frame is the length of a real octilinear
// path (a staircase in the frame's two orientations), and the straight last link from a
// query's last bend lies in some frame's cones, where its value is exact. A query is located
// in all four and takes the least value. Each frame's answer has a root that sees the query
// straight (L1Map's argument, in the frame's weighted metric: a root whose monotone path bends
// at a vertex v loses to v's ray, of equal value and larger root distance), so ties between
// frames may go to any of them (the first). The vertex distances come from OctWavefront; paths are its
// polygonal paths (links of any direction measured by their octilinear length; router/
// staircase.h makes wires of them).
//
// Costs: four decompositions, so about four times L1Map's memory and query time (bench_spm
// --orientations octilinear). Coordinates: each frame centres the domain and its coordinates
// are sums of two, so a domain whose width plus height exceeds about 2^31 does not fit the
// frames' exact integer range; the constructor then throws std::domain_error (fits() tells
// before), and callers answer such queries with OctWavefront runs. The map's cells: pieces()
// (exact, in Q(sqrt2)); the octilinear Voronoi diagram (cells merged by source, written as
// XML and SVG) is not available yet.
class OctMap {
 public:
  using Options = L1Map::Options;
  OctMap(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
         std::span<const geom::Point> sources, Options options);
  OctMap(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
         std::span<const geom::Point> sources)
      : OctMap(domain, obstacles, sources, Options{}) {}
  ~OctMap();
  OctMap(OctMap&&) noexcept;
  OctMap& operator=(OctMap&&) noexcept;

  // Whether the constructor accepts this domain (see Costs above).
  static bool fits(const geom::Box& domain);

  bool is_free(geom::Point q) const;
  struct Answer {
    geom::Root2 distance;      // exact octilinear distance to the nearest source
    std::size_t source = 0;
    geom::Point root;          // the last bend (or the source) before q: it sees q straight
    std::uint32_t root_id = 0;
  };
  std::optional<Answer> locate(geom::Point q) const;
  std::vector<geom::Point> path(geom::Point q) const;
  std::vector<geom::Point> path(geom::Point q, const Answer& a) const;

  // The map's cells as convex pieces with exact vertices in Q(sqrt2): every point q of a piece
  // has d(q) = root_distance + d8(q - root) and is seen straight from root. Pieces have positive
  // area, cover the reached free space and overlap only on their boundaries. How: each frame's
  // decomposition gives pieces on which its value is one linear function (L1Map's bands, with
  // the weighted gradients); the map's value is the least over the frames, so each piece keeps
  // the part where its function is no larger than those of the other frames' pieces it meets
  // (found on an R-tree of their integer bounding boxes). Only pieces where the frame is exact
  // take part (d(r) + wx |du| + wy |dv| with du, dv of one sign: the cone or its opposite);
  // elsewhere a frame's value exceeds the octilinear one.
  // Cost: exact Q(sqrt2) arithmetic on GMP rationals, pieces times the other frames' pieces they
  // meet: for checks and pictures, not for large maps.
  struct Piece {
    std::vector<R2Point> ring;  // convex, counter-clockwise, no repeated vertex
    std::size_t source = 0;
    geom::Point root;
    geom::Root2 root_distance;
  };
  std::vector<Piece> pieces() const;

  // Summed over the four frames (vertices: of one frame).
  const L1Map::Stats& stats() const;
  std::size_t memory_bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace taut::router
