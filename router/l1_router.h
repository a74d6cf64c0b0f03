// Shortest rectilinear wires between two points among obstacles, exact in L1: the wavefront
// (router/wavefront.h) finds the length and a polygonal shortest path, the staircase builder
// (router/staircase.h) turns it into a rectilinear wire of the same length with integer
// vertices. One object serves many queries (`taut route` routes every two-pin net with one).
//
//   L1Router router(normalized.domain, normalized.obstacles);
//   L1Wire w = router.shortest({500, 500}, {8000, 9000});
//   if (w.status == WireStatus::Ok) { use(w.points, *w.length); }
//
// When no wire is returned the status says why, so callers can tell the user:
//   - SourceNotFree / TargetNotFree: the point is outside the domain, inside an obstacle, or
//     on an obstacle edge that lies flush on the domain side;
//   - Unreachable: both are free but in different parts of free space (`length` empty);
//   - NoIntegerStaircase: the exact L1 distance is known (`length`, `polygonal`), but no
//     rectilinear path with integer vertices of that length exists through the polygonal
//     path's bends, e.g. when sloped blockages pinch every lattice staircase (staircase.h,
//     Limitation). Returning a longer wire would break "provably shortest" silently, so the
//     caller reports it instead (a wire of another route of equal length is not searched).
//
// The same class serves the octilinear metric (router/oct_router.h: OctRouter = BasicRouter<
// OctWavefront>, lengths a + b*sqrt2): the wavefront and the staircase style differ; shape pins
// take the same shapes (pin_shape_supported(): edges at 0, 45 and 90 degrees), with more
// candidate points on 45-degree edges (pin_candidates(), router/pin_shapes.h).
#pragma once

#include <cstdint>
#include <optional>
#include <type_traits>
#include <span>
#include <vector>

#include "geom/root2.h"
#include "geom/types.h"
#include "router/pin_shapes.h"
#include "router/staircase.h"
#include "router/wavefront.h"

namespace taut::router {

enum class WireStatus { Ok, SourceNotFree, TargetNotFree, Unreachable, NoIntegerStaircase };

// Len: std::int64_t (L1) or geom::Root2 (octilinear).
template <class Len>
struct BasicWire {
  WireStatus status = WireStatus::Unreachable;
  std::optional<Len> length;           // exact distance (Ok, NoIntegerStaircase)
  std::vector<geom::Point> polygonal;  // the wavefront's shortest path (Ok, NoIntegerStaircase)
  std::vector<geom::Point> points;     // the rectilinear (octilinear) wire: bends only, integer (Ok)
  // length as a + b sqrt2 (an L1 length has b = 0), for code that takes either metric
  std::optional<geom::Root2> root2_length() const {
    if (!length) return std::nullopt;
    if constexpr (std::is_same_v<Len, geom::Root2>) return *length;
    else return geom::Root2{*length, 0};
  }
};
using L1Wire = BasicWire<std::int64_t>;

// Wavefront: L1Wavefront or OctWavefront (instantiated for those two in l1_router.cpp).
template <class Wavefront>
class BasicRouter {
 public:
  static constexpr bool kOctilinear = std::is_same_v<Wavefront, OctWavefront>;
  using Len = std::conditional_t<kOctilinear, geom::Root2, std::int64_t>;
  using Wire = BasicWire<Len>;

  // Obstacles as geom::normalize_obstacles() returns them.
  BasicRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles);

  // The shortest rectilinear (octilinear) wire from `from` to `to` ({from} when they are equal).
  Wire shortest(geom::Point from, geom::Point to);

  // The shortest rectilinear wire between two pins, each a point (an outer ring of one point,
  // no holes) or a closed polygon with holes (integer vertices, rings in either orientation,
  // every edge horizontal, vertical or at 45 degrees: pin_shape_supported()). The wire starts
  // anywhere on `from` and ends anywhere on `to` (pins that share a point get a wire of one
  // point); SourceNotFree / TargetNotFree mean that no point of that pin is free. Exact: see
  // pin_candidates(). Octilinear the same (edges at 45 degrees too, since 2026-12-03).
  Wire shortest(const geom::Polygon& from, const geom::Polygon& to);

  // A net of one source pin and several sink pins (points or shapes, as shortest() takes them)
  // joined by a SHORTEST-PATH TREE: every sink is reached from the source pin along the wires
  // by a path of exactly its shortest distance from the source pin (a minimum-delay topology:
  // the total length is not minimised; Steiner trees come with the net router). How: one
  // wavefront run from the source's candidate points to every sink's candidates (stopping when
  // the last is reached: the shortest path map of the source, restricted to what the sinks
  // need), each sink's path taken from the run's parent chain. Paths through the same vertex
  // share the run's prefix, so the polygonal paths form a tree; it is cut into chains at its
  // branch points, each chain becomes one staircase (the same builder as shortest()); a chain
  // whose joint at its branch point would pass through a pinch (its staircase reaches the point
  // on the other side of an obstacle touching it) is staircased again with its whole path from
  // the source; and without_overlaps() removes the lengths where staircases run along the
  // same line.
  struct Tree {
    // Ok; SourceNotFree; TargetNotFree / Unreachable / NoIntegerStaircase for sink `failed`.
    WireStatus status = WireStatus::Unreachable;
    std::optional<std::size_t> failed;     // index into sinks, when the status is about a sink
    std::vector<std::optional<Len>> distance;  // per sink: exact distance from the source pin
                                               // (0 when they touch; nullopt: not free or
                                               // not reached)
    std::vector<std::vector<geom::Point>> wires;  // Ok: polylines with integer vertices, no
                                                  // two overlapping along a positive length;
                                                  // one wire of one point when every sink
                                                  // touches the source
  };
  Tree tree(const geom::Polygon& source, std::span<const geom::Polygon> sinks);

  // Point pins joined by a rectilinear (octilinear) STEINER TREE among the obstacles (issue #7):
  // short total length instead of shortest paths from a source. How: the tree starts as the
  // first pin; then, repeatedly, one wavefront run from the whole tree so far (its points, and
  // its wires as segment sources: a new wire may leave the tree anywhere along it) that stops
  // at the nearest pin not yet joined (Stop::FirstTarget), whose shortest path becomes a
  // staircase added to the tree; finally without_overlaps(). Each step joins the pin nearest to
  // the tree by an exact shortest path (Prim's rule with the tree's segments as sources, so
  // branches start mid-wire: Steiner points). The tree is grown from each of the first `starts`
  // pins in turn and the shortest kept (the start changes which pins join early, and so where
  // the branches leave). Then an improvement pass (on the kImproved shortest of those trees)
  // re-embeds the tree's paths: the metal is a
  // graph (every segment split where another ends, crosses or a pin lies), its key nodes the
  // pins and the nodes of degree other than 2, its paths the chains between key nodes; a path is
  // taken out, and when its two ends are still joined it is dropped, else the two parts left are
  // joined again by one wavefront run from one part's metal (segment sources) to the nearest
  // point of the other's (its nodes and the projections onto its segments of every obstacle
  // vertex, domain corner and node of the first part: the candidate argument of pin_shapes.h),
  // and the new path replaces the old one when it is strictly shorter; longest paths first,
  // until no path improves (each change shortens the tree by an integer, so it ends; a path
  // tried without a gain is not tried again after later changes). When no path gains, Steiner
  // point moves (on every start's improved tree): a key node that is no pin, of degree three or
  // more, or a pin of degree two or more, with its key paths taken out leaves one part per path
  // (and the pin a part of its own); the candidate point s (a grid of the x and y of the node,
  // the paths' far ends, the tree's nodes and, while few, the obstacle vertices in their box)
  // with the least sum of exact distances from the parts (one run per part, to the candidates
  // whose L1 bound, blockages ignored, could still gain) is joined to each part by a shortest
  // path when that sum is strictly less than the paths' length; then the path pass again (a move
  // tried without a gain is not tried again after later changes, like a path). The
  // result is never longer and still joins every pin. Not minimal in general: tests/oracle's
  // Dreyfus-Wagner reference measures the excess (router/steiner_test.cpp). starts x (k - 1)
  // runs for k pins, plus one run per path tried and up to one per part and move tried.
  // OCTILINEAR (OctRouter): the tree is grown the same way, each step an exact shortest
  // octilinear path from the tree so far (OctWavefront's segment sources: the tree's wires,
  // diagonal ones included, leave it at any of their lattice points) staircased with integer
  // vertices; the improvement pass re-embeds its paths as above (the metal graph takes diagonal
  // pieces, the other part's targets are projected along the four orientations) and moves
  // Steiner points as above, with octilinear bounds (the d8 distance to each part's metal,
  // blockages ignored) and more candidates: where a diagonal (x + y or x - y) of a node meets
  // another node's horizontal, vertical or other diagonal at an integer point in the box (the
  // octilinear Hanan grid of the nodes; on the tests' nets the axis grid alone left 761 of 1,000
  // trees minimal, this 951). tests/router/steiner_test.cpp
  // measures its excess over the exact minimum among trees with integer vertices
  // (tests/oracle/oct_steiner_oracle.h).
  struct Steiner {
    // Ok; SourceNotFree (the first pin); TargetNotFree / Unreachable / NoIntegerStaircase for
    // pin `failed` (an index into pins).
    WireStatus status = WireStatus::Unreachable;
    std::optional<std::size_t> failed;
    Len length{};                                 // Ok: the tree's total length (L1, or
                                                  // octilinear: a + b sqrt2)
    std::vector<std::vector<geom::Point>> wires;  // Ok: as Tree::wires
    std::vector<std::size_t> order;               // the pins in the order they were joined
    std::size_t improved = 0;                     // paths the improvement pass replaced or dropped,
                                                  // and Steiner points it moved
  };
  // improve = false: without the improvement pass (the tests measure what it gains).
  Steiner steiner(std::span<const geom::Point> pins, std::size_t starts = 8, bool improve = true);

  // The same for pins that may be shapes (points, or shapes as shortest(pin, pin) takes them; a
  // wire may end anywhere on a shape, and a shape is metal of its net: what touches it is joined).
  // All points: the overload above. Otherwise the tree is grown the same way, with the shapes
  // joined so far as segment sources along every edge, to the nearest point a pin not yet joined
  // may be reached at: itself for a point, for a shape its candidate points against every point
  // of the tree so far (pin_candidates: a shortest path from the tree leaves it at a point r, a
  // tree vertex or a point of a tree segment it runs straight from, and reaches the shape at a
  // point s minimising |s - r|_1 along an edge, so at a vertex or a projection of a tree vertex
  // or obstacle vertex); from each of the first `starts` pins, the shortest kept; then the
  // improvement pass (improve(): the pads as metal; Steiner points moved off the pads only), on
  // the kImproved shortest starts' trees; tests/router/steiner_test.cpp measures the excess over
  // the exact minimum with rectangular pads. `failed` indexes `pins`. Octilinear: shapes with
  // edges at 0, 45 and 90 degrees (pin_shape_supported()), the same candidates with the projections
  // along the other diagonal onto 45-degree edges (pin_shapes.h; as r runs along a straight tree
  // segment, at one of its ends or where a pin vertex projects onto it), the same pass;
  // the excess is measured against the exact minimum with diamonds, triangles and cut boxes.
  Steiner steiner(std::span<const geom::Polygon> pins, std::size_t starts = 8, bool improve = true);

  // The points of pin `pin` a shortest wire from it may be taken to start at (and why those:
  // PinShapes::candidates, router/pin_shapes.h).
  std::vector<geom::Point> pin_candidates(const geom::Polygon& pin, const geom::Polygon& other) const;

  // The first obstacle whose interior meets the interior of a shape pin
  // (PinShapes::meets_obstacle).
  std::optional<std::size_t> pin_meets_obstacle(const geom::Polygon& pin) const;

  // Octilinear wires for a plane whose wires are then snapped to multiples of k (NetRouter's
  // scaled plane, NetRouterOptions::exact_gaps): no branch of a Steiner tree leaves a diagonal
  // wire, no Steiner point is moved, and no wire leaves a shape pin's 45-degree edge, halfway
  // between two multiples of k, where snapping would turn a diagonal off its direction
  // (OctWavefront::run, LATTICE; PinShapes::set_lattice; the moves' candidates where two
  // diagonals cross are rounded the same way). 1 (the default): integer points. Rectilinear wires
  // need none (they leave on horizontal and vertical lines through vertices of the tree, the
  // pins and the obstacles), and L1Router ignores it.
  void set_lattice(std::int64_t k);

  bool is_free(geom::Point p) const { return wavefront_.is_free(p); }
  const Wavefront& wavefront() const { return wavefront_; }
  const StaircaseStats& staircase_stats() const { return staircase_stats_; }

 private:
  // How many of the starts' trees, the shortest first, steiner() improves: on the tests' nets
  // three gave a mean excess of 0.10 % and all eight 0.07 % (the worst 11.1 % either way, before
  // the Steiner point moves), for 1.7 times the time without the pass on a generated layout of
  // 8-pin nets, against 2.1. With the moves on the best tree only the worst of ten seed sets rose
  // from 7.7 % to 9.6 %, for about a fifth less time: the moves run on all three.
  static constexpr std::size_t kImproved = 3;
  // The Steiner point move's candidate grid: obstacle vertices are added on an axis while they
  // number at most kMoveGridSide in the box, and a grid of more than kMoveGridPoints is not
  // tried (on the tests' nets 16 obstacle coordinates find what 48 do); octilinear, the diagonal
  // candidates are added only while the whole stays within kMoveGridPoints.
  static constexpr std::size_t kMoveGridSide = 16;
  static constexpr std::size_t kMoveGridPoints = 2304;
  // steiner() grown from pins[0] only.
  Steiner steiner_from_first(std::span<const geom::Point> pins);
  Steiner steiner_from_first(std::span<const geom::Polygon> pins);
  // The improvement pass of steiner() (see there): returns how many paths it replaced or dropped
  // and Steiner points it moved.
  // With pads (shape pins; `pins` then the point pins only), the paths are re-embedded with the
  // pads as metal (a pad's nodes key, joined through it; a part's pads sources along their edges,
  // the other part's pads targets at their candidate points), and Steiner points off the pads
  // are moved with each part's pads among its metal (a part floods through a pad; its edges are
  // sources); a join on a pad stays.
  std::size_t improve(std::span<const geom::Point> pins, Steiner& t, std::span<const geom::Polygon> pads = {});
  // The wire to target `target` of the last run (Unreachable when none).
  Wire finish(std::optional<std::size_t> target);
  // wavefront_.run with segment sources on lattice_ (octilinear).
  void run_from(std::span<const geom::Point> points, std::span<const geom::Segment> segments,
                std::span<const geom::Point> targets, WavefrontStop stop);

  Wavefront wavefront_;
  StaircaseBuilder staircase_;
  PinShapes pins_;
  StaircaseStats staircase_stats_;
  // Octilinear improve(): the obstacle vertices (the frame's too) projected onto the other part's
  // segments, built at the first use.
  std::optional<ProjectionLines> obstacle_lines_;
  std::int64_t lattice_ = 1;  // set_lattice()
};

using L1Router = BasicRouter<L1Wavefront>;
extern template class BasicRouter<L1Wavefront>;
extern template class BasicRouter<OctWavefront>;

const char* to_string(WireStatus status);

// The same wires without overlaps: each wire, in order, loses the parts of its segments that
// run along (overlap with positive length) a segment of an earlier wire or an earlier segment
// of itself, and is split where what remains does not go on from the point where it stopped
// (a lost there-and-back spike leaves it in one piece); every piece keeps its direction of
// travel, and pieces of one point are dropped. The union of the wires is unchanged, so connectivity and
// every path along them are kept, and the total length is the union's. Overlaps are found for
// horizontal, vertical and 45-degree segments (the only ones staircases have); segments at other
// angles are kept as they are. Exact (integer arithmetic).
std::vector<std::vector<geom::Point>> without_overlaps(std::span<const std::vector<geom::Point>> wires);

}  // namespace taut::router
