// Many nets routed together with the width and spacing of <rules> (issue #7): every net's wires
// keep w/2 + s from the blockages and w + s from the other nets' wires and pins, by routing each
// net among obstacles grown by squares (FORMAT.md: "square-corner inflation is fine"), then
// ripping up the nets that block a net left unrouted and routing again.
//
//   NetRouter nr(normalized.domain, normalized.obstacles, nets, {.wire_width = 200, .spacing = 200});
//   nr.run(NetRouter::l1_router(/*steiner=*/false));
//   for (const NetOutcome& o : nr.outcomes()) { ... o.routed, o.wires, o.reason ... }
//
// The space a net is routed in (NetSpace::obstacles), every coordinate an integer:
//   - the blockages, and each blockage edge grown by the square [-a, a]^2 with a = ceil(w/2) + s
//     (a point outside is at L-infinity, so Euclidean, distance >= w/2 + s from every blockage);
//   - pin access: around each point pin of the net itself, the open square of half-side a is cut
//     out of the grown edges (not out of the blockages), so a pin on a blockage's edge is reached
//     (router/check.h exempts exactly that square from the blockage clearance); the cut rounds
//     outward, never inward (geom::convex_minus_box);
//   - every other net's wire segments and point pins grown by b = max(w + s, 1), and its shape
//     pins grown by max(a, 1) (b >= 1 with w = s = 0, so wires of different nets never touch:
//     the checker calls a shared point a short whatever the rules).
// A wire in that space keeps the clearance the checker (router/check.h) asks for, and a wire of
// another net routed later keeps it from this one, because both grow by the same b.
//
// Gaps of exactly the clearance (NetRouterOptions::exact_gaps). Two grown obstacles that touch
// merge (the wavefront takes touching obstacles as a pinch), so in that space a gap of exactly 2a
// between blockages, or a track at exactly the pitch between two wires, takes no wire although
// one is legal there. With exact_gaps the router works in the plane scaled by K (a power of two,
// NetRouter::scale(), at least 8, with K x (the domain's reach + a + b) <= 2^29, and under
// Combined K x bend_cost <= 2^31): the blockages,
// the domain and the pins are multiplied by K and grown by K a - 1 and K b - 1 instead of a and b
// (NetRules::scale), so regions whose interiors overlap still overlap and only exact touches open,
// to corridors 2 wide; a point pin's access square is cut with half-side K a + 1, one more than
// the scaled square the checker exempts (a wire in that band snaps onto the square's side; with
// K a, where two of a net's access squares meet at a blockage's corner, the grown remainder
// touched the blockage and pinched the way shut). Every wire the route function returns is snapped at once to the nearest
// multiples of K (before any other net sees it), so every obstacle of the scaled space stays a
// multiple of K grown by K x - 1, and a wire's vertices, which lie on lines through those
// obstacles' vertices and the pins (and on 45-degree lines through them), sit a few units from a
// multiple of K (far less than K/4): snapping then keeps each segment's direction and every wire's connections, and moves
// a wire hugging a grown region out to exactly the clearance. Where that does not hold (two
// diagonals of an octilinear Steiner tree crossing half way between multiples, an L1 staircase
// beside a 45-degree edge) the attempt is counted in NetRouterStats::snap_far, and the caller
// routes again without exact_gaps (taut route does). The outcomes are divided by K at
// the end of run(). The space then holds K times every legal wire (it keeps K a > K a - 1 and
// K b > K b - 1 from what it grows), so no wire is lost to the scale; a snapped wire is checked by
// the caller (router::check_routes: taut route does, and routes again without exact_gaps when it
// fails, which no test has seen). Lengths: the route function sees K times the lengths (a
// Combined metric's bend cost is multiplied by K for bend_router; a route function of one's own
// must do the same: NetPins::scale is K on the pins it is given).
//
// Limitations (measured in net_router_test and bench_net_router):
//   - without exact_gaps, exact minimum gaps are closed (above); with it, a layout whose reach
//     leaves no K >= 8 keeps them closed (NetRouter::scale() is then 1), and so does one with
//     a blockage or shape pin edge that is not horizontal, vertical or at 45 degrees (a wire
//     vertex beside such an edge may lie anywhere between multiples of K, and snapping it
//     moved octilinear wires into the clearance in exact_gaps_test before this rule);
//   - a net's own pads (shape pins that are rectangles, or, with NetRules::cover_pieces 0, any
//     shape whose edges are horizontal, vertical or at 45 degrees: diamonds, octagons, and as
//     convex pieces concave ones and ones with holes) are cut out of the grown blockage edges
//     like the access squares (geom::convex_minus_box, geom::convex_minus_pad: so a pad on a
//     blockage's edge is reached from outside the grown blockage, and the wire's stretch inside
//     the pad is trimmed); with the bend-aware metrics only the pads whose edges are all
//     horizontal and vertical (rectangles, L-shapes, ..., as rectangles), since their router takes
//     rectilinear obstacles only: a pin with a 45-degree edge within a of a blockage is not
//     routed (ROUTE-0010); a pad that another net's grown wire enters cannot be
//     taken, and that net counts as a blocker (ripped up like one);
//   - cost: every window is a new union of its pieces and a new wavefront (no reuse between
//     nets); a net whose pins are far apart pays for a window as big as its span.
//
// Windows. A net is routed in a window round its pins (their bounding box grown by m = 2 x its
// half-perimeter + 8(a + b) + 64), with only the pieces that meet it (R-trees), and the answer is
// kept when it is provably what the whole layout gives (a shortest way; for a tree grown from its
// first pin, every sink's distance, see NetRouter::try_net_unsnapped): for two point pins when its length L is
// at most the least of |dy| + 2(d - 2) over the window's top and bottom sides inside the domain
// (d: that side's distance from the pins' box) and of |dx| + 2(d - 2) over its left and right
// ones: a way out through a side and back climbs at least that far along one axis, so it is at
// least that long in L1 and in the octilinear metric alike (L: the wires' L1 length, or with
// NetRouterOptions::octilinear their exact octilinear length a + b sqrt2; the 2 covers the
// outward rounding where sloped blockages are clipped to the window). For other nets when L1
// length < m'' - 2, m'' the distance from the box of the pins and wires to those sides (every
// wavefront run then stops before it could reach a side; the octilinear length is at most the
// L1 one). A review found the first version's L1 bound |p - q|_1 + 2(m' - 2) taken for
// octilinear wires too, which kept a 9,784 wire where the whole layout's was 9,598 (kept as a
// test). Otherwise, or when the net's pins are apart in the window
// (ROUTE-0002), the window grows (m := max(4m, L + 3), or 4m) up to the whole domain, where the
// answer stands; other failures (a pin not free, no integer staircase) are decided near the pins
// and end the search in the first window.
//
// With the bend-aware metrics (NetRouterOptions::cost: length + C x bends, or bends then length)
// every sink's path from the first pin is optimal on its own (router::BendRouter::tree), and the
// window is kept when, for every sink, the cost of its path is at most the least a path out of
// the window could cost: such a path leaves through a side at distance d >= d_min from the pins'
// box and comes back, so it is at least 2(d_min - 2) long (plus |dx| + |dy| between two point
// pins), and it runs away from the box and back along one axis, so it has two antiparallel links
// and at least two bends (an optimal path never reverses on itself). Combined: cost <= that
// length + 2C; Link: fewer than two bends, or two and no longer than that length. Otherwise the
// net is routed once more in a relaxation: the window's pieces with the window's sides opened onto
// a free ring one unit wide (the domain grown by 1, clipped to the layout's). Clamping a way of the
// whole layout into the window and the ring never lengthens it nor adds a bend, and keeps it out
// of the pieces (inside the window it is unchanged; the ring holds none), so the relaxation's
// optimum is at most the layout's, which is at most the window's; when every sink costs the same
// in both, the window's answer is the layout's. Else the window grows as above (m := max(4m,
// cost + 3)), up to the whole domain. The blockages must be
// rectilinear here: the caller replaces sloped ones by their rectilinear cover before it builds
// the router (as `taut route` does), so a window never clips a sloped edge and the cover is the
// same in every window; the constructor throws std::invalid_argument for a sloped blockage edge
// when NetRouterOptions::cost is not Length, and for NetRules::cover_pieces 0 with it.
//
// Order and rip-up. Nets go shortest first (by the half-perimeter of their pins' bounding box,
// then by their place in the file): a short net has the fewest ways round, a long one the most
// room to detour (the usual order of sequential routers). Then, while some net is unrouted and
// the last round made progress: each unrouted net is routed again without the other nets'
// wires; the nets whose grown wires that wire enters are its blockers; they are ripped up, the
// net is routed, and the blockers are routed again after it (in their order). A net is ripped up
// at most `max_rips` times (PathFinder's history, in its simplest form: a net that keeps being
// in the way stays put); when some blocker has reached that limit, the net is routed among the
// other nets' pins and the wires of the nets at the limit alone, and the nets that way crosses
// are its blockers instead. A rip-up after which fewer of the net and its blockers are routed
// than before is undone (the blockers' wires put back: a state that held before, so legal).
// The best state seen (most nets routed, then least total length) is the
// one kept; a final round then tries each net still unrouted once more, its blockers ripped up
// whatever their rips, and keeps only the rip-ups that route more nets. In the first pass and
// the rounds a net finding no way in its first search_windows
// windows (NetRouterOptions) though its pins meet in the last among the blockages and pins alone, or (length cost) only a detour there that they cannot prove
// shortest after the other nets' wires set its pins apart in its first one, is taken as blocked
// there, not widened to the whole domain; the
// last pass then tries each net still unrouted without that limit, and places what it routes;
// it first builds, once, a superset of every unrouted net's free space on the whole domain
// (NetRouterOptions::superset), so a net whose pins lie in different free components of it stops
// at its first window that finds no way (the same outcome: its pins are apart in its own space
// too), instead of growing its windows to the whole domain (10^4 planted nets over 91,830
// vertices: the last pass 11.3 s -> 0.65 s, 8 whole-domain windows -> 0, the same routing).
// Work whose outcome is known is not done again (NetRouterOptions::reuse; the outcome is the
// same, bit for bit): every wire piece placed or removed is logged (changed_), and an attempt
// depends on nothing but the pieces meeting its windows, so a net's failed attempt in a round is
// taken again while no other net's piece has changed in its last window, and likewise its way
// round the nets at the rip limit (while the same nets there are at the limit); a rip-up that is
// undone leaves the space as it was, so its log entries are dropped, and the same rip-up (same
// blockers) is not made again while nothing has changed in the windows its attempts read (its
// rips are still counted); a rip-up's nets stop being routed once so many failed that it
// will be undone; and in the last pass a net whose last failed attempt never met the window
// limit, with nothing changed in its window, keeps that attempt (unlimited, it goes the same way). On 10^4 planted nets over 91,830 vertices: 18,035 -> 15,891 windows, the same
// routing.
// When nets stay unrouted, each gets the most telling reason (NetOutcome::reason):
//   - the net cannot be routed even alone, among the plain blockages: the router's own reason
//     (an enclosed pin, a pin in a blockage, ...);
//   - alone with the clearance it cannot: the clearance closes its way (a gap narrower than the
//     rules allow, or a pin too near a blockage corner), or, when the route function says
//     ROUTE-0018 there (its one way, e.g. a tightened sketch, comes within the clearance), its
//     own reason;
//   - among the other nets' pins it cannot: their pins block it (named);
//   - otherwise the nets whose wires block it (named).
//
// Threads (NetRouterOptions::threads). An attempt depends on nothing but the pieces whose boxes
// meet the windows it was tried in (NetSpace::obstacles reads no others, and sorts what it
// reads). So nets are tried ahead of their turn against the space as it is, and an attempt is
// kept when no wire piece placed or removed since it first read the space meets its last window
// (changed_, a log of piece boxes); otherwise it is tried again in turn. The outcome is then
// the one-thread outcome, bit for bit. Where: the first pass and the last pass (route_in_order:
// workers try, this thread places in order), the Full attempt of every unrouted net at the start
// of a rip-up round, the Pins attempts (fixed for the run, made once), the rip-ups of the
// rounds and of the final round, and the explanations (which only read); the pipelines are
// router::Lookahead (router/lookahead.h). A rip-up is worked out whole ahead of its turn
// (RipPlan: the blockers found, the way round the nets at the rip limit, the net and its
// blockers routed again in an overlay of their new wires, the undo decided) without changing
// the space, and made in its turn when nothing logged since meets what it read; so the rip-ups
// of unrouted nets far apart go on at once (on the 10^4 planted row about 1,100 of 1,150 were
// made as worked out ahead; a worker that had the net's stale attempt of the round's start made
// again first gained nothing). Not the nets within one rip-up: the net's
// new wire runs where its blockers' wires were, so their attempts made ahead were almost never
// valid (the rounds took 1.07-1.19 x one thread's time with them).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <shared_mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "geom/normalize.h"
#include "geom/root2.h"
#include "geom/types.h"
#include "router/bend_router.h"

namespace taut::router {

struct FreeComponents;  // net_router.cpp
struct BlockageParts;   // net_router.cpp

struct NetRules {
  std::int64_t wire_width = 0, spacing = 0;  // <rules wire-width spacing>, each >= 0
  // 0: the other nets' shape pins are obstacles as they are. k > 0 (the bend-aware metrics, whose
  // router takes rectilinear obstacles only): a shape pin with a sloped edge is taken with its
  // rectilinear cover (router::rectilinear_cover with k pieces: the pin plus the boxes along its
  // sloped edges), and grown by the boxes grown instead of by its sloped edges grown; never less
  // clearance, and every piece a net is routed among then has horizontal and vertical edges only
  // (when the blockages have).
  int cover_pieces = 0;
  // K > 1: the space is the plane scaled by K (its caller multiplies the domain, the blockages and
  // the pins by K), and grows by K a - 1 and K b - 1 instead of a and b (NetRouterOptions::exact_gaps).
  std::int64_t scale = 1;
};

// The two clearances of the rules, in the layout's units: a = ceil(w/2) + s from blockages and
// b = max(w + s, 1) between nets (what NetSpace grows by without a scale).
inline std::int64_t blockage_rule(const NetRules& r) { return (r.wire_width + 1) / 2 + r.spacing; }
inline std::int64_t net_rule(const NetRules& r) { return std::max<std::int64_t>(r.wire_width + r.spacing, 1); }

// A net's pins: a point pin is an outer ring of one point, a shape pin a polygon.
// Whether p lies on the lattice of multiples of k (every point when k is 1).
inline bool on_lattice(geom::Point p, std::int64_t k) { return k == 1 || (p.x % k == 0 && p.y % k == 0); }

struct NetPins {
  std::string name;  // for reasons
  std::vector<geom::Polygon> pins;
  // The plane's scale (NetRouter::scale): pins, obstacles and wires are this many times the
  // layout's. An octilinear route function routes on its lattice (BasicRouter::set_lattice; the
  // L1 one needs none), and a bend-aware one weighs a bend by this many times its cost; NetRouter
  // sets it on the pins it passes, so no route function has to be told.
  std::int64_t scale = 1;
  // Empty, or when NetRouter routes some of the net's pins only (one of each group of pins that
  // meet, see NetRouter::try_net_unsnapped): pins[j] is the net's pin index[j]. A route function
  // that reads the net's own pins by the net's index must take these ones.
  std::vector<std::size_t> index{};
};

// The scaled plane of NetRouterOptions::exact_gaps (NetRouter::scale() K) and back: every
// coordinate times K (NetPins::scale and NetRules::scale set to K); snapped(v, K) is the multiple
// of K nearest v (halves away from zero).
geom::Point scaled(geom::Point p, std::int64_t k);
geom::Polygon scaled(const geom::Polygon& poly, std::int64_t k);
std::vector<geom::Polygon> scaled(std::span<const geom::Polygon> polys, std::int64_t k);
std::vector<NetPins> scaled(std::vector<NetPins> nets, std::int64_t k);
std::vector<std::vector<geom::Point>> scaled_wires(std::vector<std::vector<geom::Point>> wires, std::int64_t k);
NetRules with_scale(NetRules r, std::int64_t k);
geom::Coord snapped(geom::Coord v, std::int64_t k);
// The scale NetRouterOptions::exact_gaps takes for a layout (before any bend-cost cap): the
// largest power of two K <= 2^13 that keeps K (the domain's reach + both clearances) <= 2^29, when
// every edge of the blockages and shape pins is at a multiple of 45 degrees and K >= 8; else 1.
// any_angle: whatever the edges' angles. (The scaled plane then opens the gaps of exactly the
// clearance too, but is not exact: an L-infinity distance to a sloped edge may fall between its
// units, so a wire it takes must still be checked in the layout's units.)
std::int64_t exact_gaps_scale(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                              std::span<const NetPins> nets, const NetRules& rules, bool any_angle = false);

// The octilinear length a + b sqrt2 of wires whose segments are axis-parallel or diagonal (of
// any segment, its octilinear distance).
geom::Root2 oct_length(const std::vector<std::vector<geom::Point>>& wires);

// The segments of `before` (one of length zero for a wire of one point) that the segments of
// `after` do not cover: a point set contained in the union of after's segments (collinear ones
// covering it end to end, or one through the point), exactly. A net's wires changed from
// `before` to `after` free only what the L-infinity neighbourhoods of these left, since the
// neighbourhood of a union is the union of the neighbourhoods (NetSpace::removed_boxes).
std::vector<std::pair<geom::Point, geom::Point>> uncovered_segments(const std::vector<std::vector<geom::Point>>& before,
                                                                     const std::vector<std::vector<geom::Point>>& after);

// What a net may be routed among (NetSpace::obstacles).
enum class NetSpaceLevel {
  Plain,      // the blockages only, no clearance (why a net fails when it fails even there)
  Clearance,  // the grown blockages, with the net's pin access
  Pins,       // ... and the other nets' grown pins
  Full,       // ... and the other nets' grown wires
};

// Wires of some nets as they would be (a rip-up worked out before it is made, see NetRouter):
// per net in `nets`, the union of its grown segments (NetSpace::wire_union; empty: no wires),
// which NetSpace::obstacles reads instead of the net's wires in the space.
struct WireOverlay {
  struct Entry {
    std::size_t net;
    std::vector<geom::Polygon> wire_union;
  };
  std::vector<Entry> entries;
  const std::vector<geom::Polygon>* find(std::size_t net) const {
    for (const Entry& e : entries)
      if (e.net == net) return &e.wire_union;
    return nullptr;
  }
  void set(std::size_t net, std::vector<geom::Polygon> u) {
    for (Entry& e : entries)
      if (e.net == net) {
        e.wire_union = std::move(u);
        return;
      }
    entries.push_back({net, std::move(u)});
  }
  // Moves the net's union out (empty when it has none).
  std::vector<geom::Polygon> take(std::size_t net) {
    for (Entry& e : entries)
      if (e.net == net) return std::move(e.wire_union);
    return {};
  }
};

// The staircase NetSpace::reach takes for a shape pin with a 45-degree edge, or (since
// 2026-12-06) an edge at any other angle, holes and concave pins too, on the lattice of `step`
// (the scale; see there): nullopt where reach keeps the pin as it is (a point, a pin whose edges
// are all horizontal and vertical, a vertex off the lattice, no cell of the lattice in it). A
// sloped edge's y at a column's side is a fraction, rounded inwards to the lattice exactly. A pin more than NetSpace::kMaxStaircaseColumns steps wide takes
// columns of several steps (see NetSpace::reach). When the cells do not make one valid polygon,
// the largest part that is (see NetSpace::reach), among the parts `clear` accepts when it accepts
// any (NetSpace: those whose interior meets no grown blockage, so a wire reaches them from
// outside the clearance; the part touching the blockage may lie wholly inside it).
// `cuts` (since 2026-12-06): obstacles whose interiors meet the pin's (a pad partly under a
// blockage); the staircase then holds the cells that meet none of their interiors either (their
// extent over a column rounded outwards to the lattice), so the part of the pin outside them,
// exactly when everything is rectilinear; their vertices must be on the lattice too (else
// nullopt), and a rectilinear pin gets a staircase only with cuts.
std::optional<geom::Polygon> pad_staircase(const geom::Polygon& pin, std::int64_t step,
                                           const std::function<bool(const geom::Polygon&)>& clear = {},
                                           std::span<const geom::Polygon> cuts = {});

// The obstacles whose interior meets a shape pin's (none for a point pin): the cuts of
// routable_pin.
std::vector<geom::Polygon> obstacles_under(const geom::Polygon& pin, std::span<const geom::Polygon> obstacles);
// A pin as the routers reach it (since 2026-12-06). One partly under obstacles (`under`,
// obstacles_under) as the part outside them: the union of the unit lattice's cells in the pin
// that meet none of their interiors (pad_staircase with cuts; exactly that part when the pin and
// those obstacles are rectilinear and it is one piece; else its largest piece). One with an edge
// at an angle other than 0, 45 or 90 degrees, which no router takes, as its staircase, the union
// of the unit lattice's cells that lie in it, so a wire, whose vertices are integers, ends on a
// lattice point of the pin. (Either way the largest part that is one polygon when the cells are
// not.) nullopt when no cell is left (ROUTE-0005); `pin` itself when the routers take it.
std::optional<geom::Polygon> routable_pin(const geom::Polygon& pin, std::span<const geom::Polygon> under = {});
// A net's pins as a route function's router takes them (the CLI's route functions and the
// library's route_with / route_bends): routable_pin of each, with the obstacles under it when
// `meets` (the router's pin_meets_obstacle) says it meets them. `cut`: some pin was cut so (then
// no shortest claim: a sloped cut takes whole cells, and a part in pieces is reached at its
// largest). `failed`: the first pin with no cell left, `failed_under` whether obstacles met it.
struct ReachedPins {
  std::vector<geom::Polygon> pins;
  bool cut = false;
  std::optional<std::size_t> failed;
  bool failed_under = false;
};
ReachedPins reach_pins(std::span<const geom::Polygon> pins, std::span<const geom::Polygon> obstacles,
                       const std::function<bool(const geom::Polygon&)>& meets);

class NetSpace {
 public:
  // obstacles: geom::normalize_obstacles() of the blockages in `domain`.
  NetSpace(const geom::Box& domain, std::span<const geom::Polygon> obstacles, std::vector<NetPins> nets,
           NetRules rules);
  ~NetSpace();
  NetSpace(NetSpace&&) noexcept;
  NetSpace& operator=(NetSpace&&) noexcept;

  // What the space grows by: a = ceil(w/2) + s and b = max(w + s, 1), or with NetRules::scale K
  // > 1, K a - 1 (0 when a is) and K b - 1.
  std::int64_t blockage_clearance() const { return a_; }
  std::int64_t net_clearance() const { return b_; }
  // a and b themselves, in the layout's units (for messages).
  std::int64_t blockage_rule() const { return rule_a_; }
  std::int64_t net_rule() const { return rule_b_; }
  // Whether a net's shape pins with 45-degree edges are cut out of the grown blockages like its
  // rectilinear ones (pads): not with NetRules::cover_pieces (the bend-aware metrics take
  // rectilinear obstacles only; shape pins with horizontal and vertical edges only are cut either
  // way).
  bool cuts_shape_pads() const { return cut_shapes_; }
  // Net i's pins as its own wires are routed to them: its pins, except that (since 2026-12-06) a
  // shape pin partly under a blockage is taken as the staircase of its part outside the
  // blockages (pad_staircase with the blockages it meets as cuts: that part exactly when all are
  // rectilinear), and one with an edge at an angle other than 0, 45 or 90 degrees, which no
  // router takes, as its staircase (either stays as it is, and is refused, ROUTE-0005, when no
  // cell is left), and that without the cut of
  // shape pins with 45-degree edges (cuts_shape_pads() false) such a pin whose interior meets the
  // grown blockages is taken as its staircase: the union of the rectangles over each column
  // [x, x + K] between its leftmost and rightmost vertex (K the scale, 1 without one), one per
  // trapezoid of the pin over the column (between two consecutive edges that span it), of the
  // y's the trapezoid holds at both of the column's sides: so the union of the lattice's K x K
  // cells that lie in the pin. The staircase has horizontal and vertical edges only (so it is cut
  // out of the grown blockages like a pad with such edges, and the bend-aware router takes it)
  // and holds every lattice point of the pin that is a corner of such a cell: for a convex pin
  // every one but its peaks (vertices whose inner angle holds no quadrant of the axes: one of 45
  // degrees, or of 90 between two 45-degree edges, as a diamond's four corners), for another
  // also not those in a neck less than a step wide (between a hole or a notch and an edge). So a
  // rectilinear wire with vertices on that lattice ends on the staircase wherever it could end
  // on the pin, save those points (a wire that would end at one ends elsewhere on the staircase,
  // when that is free: never illegal, at most a little longer).
  // A pin more than kMaxStaircaseColumns steps wide takes columns of m steps instead, the fewest
  // that make at most that many, each also split at the pin's vertices: a coarser staircase (the
  // rectangles of the y's each trapezoid holds at both sides of its column, still in the pin),
  // which holds fewer of the pin's lattice points, so a wire ending on it may be a little longer.
  // When that staircase is not one valid polygon (a diagonal bar thinner than two columns), columns
  // of m/2, m/4, ... steps are tried while they make at most kMaxUnitStaircaseColumns (the bound
  // before 2026-12-04): such a pin is reached as before, at the bend router's cost.
  // (The bend router's work grows with the square of its obstacles' vertices: one net with a
  // diamond pad 20,002 wide took 0.37 s with 256 columns, 1.3 s with 512, 5.3 s with 1,024 and
  // 92 s with 4,096, 2026-12-04.)
  // When the rectangles' union is not one valid polygon (a part of the pin too thin to hold a
  // column's rectangle splits it, or joins it at a corner: a thin diagonal bar, a neck), the
  // largest part that is: the rectangles joined along edges of positive length, each such part's
  // union when it is one valid polygon, the one of largest area among those whose interior meets
  // no grown blockage when there is one (a wire reaches such a part from outside the clearance;
  // the part touching the blockage may lie wholly in it), else among all (since 2026-12-05: before, the pin
  // stayed as it is, and the net was ROUTE-0010 when its pin met the grown blockages). A wire then
  // ends on that part only: legal, perhaps longer. Not when its vertices are not on that lattice,
  // or when no part is one valid polygon (no cell of the lattice lies in the pin): the pin then
  // stays as it is (and the net, when its pin meets the grown blockages, is not routed: ROUTE-0010
  // says why). Everything else (the other nets, the checker) sees the pin itself.
  const NetPins& reach(std::size_t i) const {
    const auto it = reach_.find(i);
    return it == reach_.end() ? nets_[i] : it->second;
  }
  // Whether net i has a pin reached as a staircase (reach() is not its pins): then no claim of
  // the shortest is made for it (NetOutcome::shortest), as a staircase may miss a pin's peaks,
  // or hold only the largest part of what is free of a pad.
  bool reached_otherwise(std::size_t i) const { return reach_.count(i) > 0; }
  static constexpr std::int64_t kMaxStaircaseColumns = 256;  // 4,096 (and then refused) until 2026-12-04
  static constexpr std::int64_t kMaxUnitStaircaseColumns = 4096;

  // Net `net`'s wires as the other nets see them (replacing earlier ones; empty: none).
  // (`unioned`: wire_union(wires), when the caller has it already)
  void set_wires(std::size_t net, const std::vector<std::vector<geom::Point>>& wires,
                 std::optional<std::vector<geom::Polygon>> unioned = std::nullopt);

  // The obstacles net `net` is routed among at `level`, normalized in `window` (clipped to the
  // domain; the whole domain when nullopt): every piece meeting the window, found in R-trees.
  // `only` (Full level; empty: every net): the wires of the nets j with only[j] != 0 alone.
  // framed: the obstacles also hold the domain's frame (geom::domain_frame) merged with every
  // obstacle that touches the domain's sides, in the one union that makes them: what the L1 and
  // octilinear wavefronts would otherwise merge again themselves (router/wavefront.h). Every
  // point of the domain is free or not as without the frame. (Not for the plain blockages of the
  // whole domain: those are returned as they are, unframed.)
  // `overlay` (Full level): the wires of its nets as it holds them instead of theirs here.
  geom::NormalizedObstacles obstacles(std::size_t net, NetSpaceLevel level,
                                      std::optional<geom::Box> window = std::nullopt,
                                      std::span<const char> only = {}, bool framed = false,
                                      const WireOverlay* overlay = nullptr) const;
  // What the other nets see of these wires: the union of their grown segments (as set_wires
  // keeps it).
  std::vector<geom::Polygon> wire_union(const std::vector<std::vector<geom::Point>>& wires) const;

  // Whether a wire of one point at p keeps the clearance for net `net`: p lies in the domain, at
  // a Euclidean distance of at least K a from every blockage (exactly; since 2026-12-06: the grown
  // blockages are L-infinity neighbourhoods, which hold points the rule allows, and a pad of the
  // net cut out of them does not count) and in the interior of no other net's grown pin or wire.
  // (A point on such a boundary keeps exactly the clearance.) The wires of the nets `only` marks
  // (all when empty), an overlay's nets' wires being the overlay's.
  bool keeps_clearance(std::size_t net, geom::Point p, std::span<const char> only = {},
                       const WireOverlay* overlay = nullptr) const;
  // Its first part: p in the domain and at least K a from every blockage.
  bool keeps_blockage_clearance(geom::Point p) const;
  // Integer points to try for such a point in the closed polygon `pin`: its vertices, the
  // vertices in its box of the pieces keeps_clearance tests (the grown blockages, their union's
  // components, the other nets' grown pins, and with `with_wires` the other nets' grown wires and
  // the overlay's unions), the integer points next to where their edges meet the pin's edges (a
  // crossing may be a half-integer point), and next to where the circles of radius K a round the
  // blockages' vertices meet the pin's horizontal and vertical edges. The corners of the region of
  // a rectilinear pin that keeps the blockages' clearance on its boundary are next to these
  // points; they may lie outside `pin` (tested by the caller, with keeps_clearance). Without
  // `with_wires` the answer reads no wires (the same whenever it is asked).
  std::vector<geom::Point> clearance_candidates(std::size_t net, const geom::Polygon& pin,
                                                const WireOverlay* overlay = nullptr, bool with_wires = true) const;

  // The nets (other than `net`) whose grown wires the polyline enters (meets in their interior),
  // and, separately, the nets whose grown pins it enters.
  std::vector<std::size_t> wire_blockers(std::size_t net, std::span<const geom::Point> line) const;
  std::vector<std::size_t> pin_blockers(std::size_t net, std::span<const geom::Point> line) const;
  // The nets (other than `net`) whose grown wires the polyline touches (meets, boundary
  // included): where it enters none, the ones it runs at exactly the clearance from.
  std::vector<std::size_t> wire_touchers(std::size_t net, std::span<const geom::Point> line) const;
  // The nets (other than `net`) whose grown wires enter one of its shape pins (for a shape that
  // is not a rectangle: whose box they meet), which the router then cannot take.
  std::vector<std::size_t> pad_blockers(std::size_t net) const;
  // The nets whose wires the other nets see in `window` (the union of their grown segments meets
  // it, clipped to the domain, as obstacles() reads them), in increasing order.
  std::vector<std::size_t> wire_nets_in(const geom::Box& window) const;
  // The boxes of what the other nets see of net `net`'s wires (the union of its grown segments).
  std::vector<geom::Box> wire_boxes(std::size_t net) const;
  // When a net's wires change from `before` to `after`: boxes whose union holds every point the
  // other nets saw covered by the grown `before` and no longer by the grown `after` (the grown
  // pieces of uncovered_segments; none when only the representation changed, e.g. a wire cut at
  // a joint or written in the other direction). With a sloped segment in `before`, the boxes of
  // its whole union (which rounds sloped crossings outward). `net`: `before` are that net's wires
  // as set_wires holds them (its union is not made again).
  std::vector<geom::Box> removed_boxes(const std::vector<std::vector<geom::Point>>& before,
                                       const std::vector<std::vector<geom::Point>>& after,
                                       std::optional<std::size_t> net = std::nullopt) const;
  // The whole domain, framed (geom::domain_frame), with less in it than any net without wires
  // sees at the Full level: the blockages, every net's grown wires, and the grown blockage edges
  // whose boxes meet no net's pin access (a point pin's access square, a shape pin's box); no
  // pins. Each net's own access cuts and the other nets' pins only add obstacles to this, so
  // pins apart here (in different free components) are apart there, for every such net.
  // with_wires false: without the wires too, so a superset of every net's space at every level
  // with the clearance (not Plain, whose blockages are not grown), whatever wires are placed or
  // removed.
  geom::NormalizedObstacles superset_obstacles(bool with_wires = true) const;
  // The whole domain, framed, with the plain blockages: the Plain level's space of every net.
  geom::NormalizedObstacles plain_obstacles_framed() const;

  const geom::Box& domain() const { return domain_; }
  std::size_t size() const { return nets_.size(); }
  const NetPins& net(std::size_t i) const { return nets_[i]; }

  struct Index;  // the R-trees (Boost.Geometry): defined in net_router.cpp only

 private:
  // `obstacles` with the domain's frame, normalized over the whole domain (grown by 1)
  geom::NormalizedObstacles framed_whole(std::vector<geom::Polygon> obstacles) const;

  geom::Box domain_;
  std::vector<NetPins> nets_;
  std::map<std::size_t, NetPins> reach_;  // reach(): the nets with a pin reached as its staircase
  std::int64_t a_ = 0, b_ = 1, rule_a_ = 0, rule_b_ = 1;
  std::int64_t access_ = 0;  // a point pin's access square's half-side: a, or K a when scaled
  std::int64_t scale_ = 1;   // NetRules::scale
  bool cut_shapes_ = true;
  std::unique_ptr<Index> index_;
};

// One attempt at routing one net among given obstacles (what NetRouter::run calls).
struct NetAttempt {
  bool routed = false;
  std::vector<std::vector<geom::Point>> wires;  // routed: polylines, integer vertices
  std::string code, reason;                     // not routed: a code (ROUTE-xxxx) and a reason
  // Routed as a tree grown from the first pin alone (a wavefront from its shape that stopped when
  // it had reached every other pin): the greatest exact distance from the first pin to another
  // (L1, or octilinear a + b sqrt2). Every point that wave labelled lies that near the first pin,
  // which proves a window whose sides are farther (NetRouter); nullopt: not such a tree.
  std::optional<geom::Root2> radius;
  // With radius: each sink's exact distance from the first pin (pins 1, 2, ... in order; radius
  // is the greatest), which proves a window sink by sink (NetRouter; empty: not proven so; set
  // without radius, or not matching it or the pins, NetRouter throws std::logic_error).
  std::vector<geom::Root2> sink_distances;
  // With NetRouterOptions::cost Combined or Link: per sink (every pin but the first), the L1
  // length and the bends of its optimal path from the first pin (what the windows' proof bounds).
  std::vector<std::pair<std::int64_t, std::int64_t>> sink_costs;
  // Two pins routed by a shortest path: the exact distance between them in the obstacles routed
  // among (L1, or octilinear a + b sqrt2), which the wire's length equals; NetRouter certifies
  // shortest wires with it (NetOutcome::shortest). nullopt: no such claim (a route function of
  // one's own may leave it).
  std::optional<geom::Root2> distance;
  // false: the route function reached a pin otherwise than as it is (a pad partly under the
  // window's obstacles, reached from its part outside them: since 2026-12-06), so neither
  // distance nor sink_costs may certify the shortest (they still prove the window).
  bool claims = true;
  // Set by NetRouter (route functions leave them): see NetOutcome::shortest.
  bool shortest = false;
  geom::Box window{};
  // ROUTE-0002 must mean "the pins are in different parts of free space": the one failure a
  // larger window can undo (NetRouter widens the window for it, and for no other code).
};
using NetRouteFn =
    std::function<NetAttempt(std::size_t net, const NetPins& pins, const geom::NormalizedObstacles& obstacles)>;

// Each sink's exact distance from the source of a routed tree (L1Router::Tree or
// OctRouter::Tree), in the sinks' order, as NetAttempt::sink_distances; nullopt when a sink has
// none.
template <class Tree>
std::optional<std::vector<geom::Root2>> tree_sink_distances(const Tree& t) {
  std::vector<geom::Root2> out;
  out.reserve(t.distance.size());
  for (const auto& d : t.distance) {
    if (!d) return std::nullopt;
    if constexpr (std::is_same_v<std::decay_t<decltype(*d)>, geom::Root2>) out.push_back(*d); else out.push_back(geom::Root2{*d, 0});
  }
  return out;
}
// The greatest of them, as NetAttempt::radius (0 for none).
inline geom::Root2 greatest_distance(std::span<const geom::Root2> d) {
  geom::Root2 r{0, 0};
  for (const geom::Root2& v : d) r = std::max(r, v);
  return r;
}
// The greatest exact distance of a routed tree's sinks from its source, as NetAttempt::radius;
// nullopt when a sink has none.
template <class Tree>
std::optional<geom::Root2> tree_radius(const Tree& t) {
  const auto d = tree_sink_distances(t);
  if (!d) return std::nullopt;
  return greatest_distance(*d);
}

struct NetOutcome {
  bool routed = false;
  std::vector<std::vector<geom::Point>> wires;
  std::string code, reason;            // not routed
  std::vector<std::size_t> blockers;   // not routed: the nets whose wires or pins block it
  int rips = 0;                        // times it was ripped up
  // Routed, and proven as short as any wire that keeps the clearance as the router measures it
  // (in squares: FORMAT.md's square-corner inflation) between its two pins (points or shapes;
  // shapes since 2026-12-05) among the blockages and the other nets' wires and pins as they are at
  // the end (NetRouter's certificate, with gaps of exactly the clearance open: scale() > 1, and
  // with NetRouterOptions::cost Length a route function that sets NetAttempt::distance). Any such
  // wire (from its last point on one pin to its first on the other), scaled by K, lies in
  // the scaled plane's free space (it keeps K a and K b, more than the K a - 1 and K b - 1 grown
  // there), so none is shorter than S / K for that plane's exact distance S; the snapped wire
  // passes the rules (`taut route` checks it), so it is shortest when its length R has K R < S + K
  // in L1 (then R = ceil(S / K), and lengths are integers) or K R = S octilinear. Under the
  // bend-aware costs (since 2026-12-05) the same with the cost: the route function's sink_costs
  // give the optimal path's scaled length L and bends b, and the snapped wire (one polyline) of
  // length R and b' bends is claimed when K R + K C b' < L + K C b + K (Combined) or b' = b and
  // K R < L + K (Link: fewest bends, then shortest); not when NetRouterOptions::blockages_covered
  // or a pin has a sloped edge (the space is then smaller than the layout's). Not claimed with
  // the gaps closed (two grown obstacles that touch merge there, so a legal wire through a gap of
  // exactly the clearance would be missed), nor for trees. The claim is made when the net is
  // placed, among the wires then; wires placed later only take ways away, and it is withdrawn at
  // the end of run() when a wire piece of another net was removed since then from the window its
  // route was proven in (outside it every way is longer than the wire, whatever lies there) and,
  // in L1, from the region a shorter wire would lie in, d(x, P) + d(x, Q) <= K R - K round the
  // boxes P and Q of its scaled pins (since 2026-12-05; a shorter wire that met no removed piece
  // was free when the claim was made; under Combined R is the cost R + C b', and a cheaper wire
  // is no longer than that less 1; under Link the window alone, as a wire of fewer bends is
  // better however long). withdraw_claims does the same for wires changed after run().
  bool shortest = false;
};

// What NetRouterOptions::progress is told: after each net tried, the nets routed now, the nets
// tried so far in this phase, and the phase.
struct NetRouterProgress {
  enum class Phase { FirstPass, RipUp, Explain } phase = Phase::FirstPass;
  std::size_t routed = 0, tried = 0, nets = 0;
  int round = 0;  // the rip-up round (RipUp)
};

// Thrown out of NetRouter::run when NetRouterOptions::stop says so (a time limit, a signal): the
// outcomes are then incomplete and must not be written.
struct NetRouterStopped : std::runtime_error {
  NetRouterStopped() : std::runtime_error("the net router was stopped") {}
};

struct NetRouterOptions {
  int max_rips = 3;     // per net
  int max_rounds = 20;  // rip-up rounds after the first pass
  bool windows = true;  // false: every net on the whole domain (for tests and benchmarks)
  bool octilinear = false;  // the route function's wires are octilinear (the windows' proof
                            // then measures their octilinear length)
  // What the route function's wires minimise: their length (L1, or octilinear), or length +
  // bend_cost x bends (Combined), or bends then length (Link; the bend-aware router,
  // router/bend_router.h). With Combined or Link the windows' proof bounds that cost, from
  // NetAttempt::sink_costs (see the header).
  enum class Cost { Length, Combined, Link } cost = Cost::Length;
  std::int64_t bend_cost = 0;
  // Asked before every window is routed: true stops the run (NetRouterStopped). A window's
  // route is not interrupted, so a run stops within one window's time.
  std::function<bool()> stop;
  // Told after every net tried (for a progress bar), always on the thread that called run().
  std::function<void(const NetRouterProgress&)> progress;
  // Threads that try nets at once (>= 1). The outcome is the same for every count, bit for bit:
  // with more than one, the next nets in order are tried speculatively against the state before
  // them, and each is kept only when no wire placed in between meets the windows it was tried
  // in (a net's attempt depends on nothing outside them); otherwise it is tried again in order.
  // `stop` and the route function are then called from several threads at once.
  int threads = 1;
  // With threads > 1, a net is tried ahead of its turn only when no net before it that is still
  // to be placed is likely to change its first window (few attempts are then wasted; in the last
  // pass a net not tried yet is taken to fail, as its nets almost all do). false:
  // any net ahead is tried (for tests: every check of an attempt's validity is then exercised).
  bool cautious = true;
  // In the first pass and the rip-up rounds, a net that finds no way among the other nets' wires
  // in this many windows (each 4 times the last's margin) is taken as blocked by them, and its
  // blockers are ripped up, instead of its window growing to the whole domain to look for a
  // detour, when its pins meet in the last of them among the blockages and pins alone (since
  // 2026-12-06: one the blockages alone keep apart grows on, as no rip-up could help it there);
  // so is one (length cost) whose pins were apart in its first window, though not among the
  // blockages and pins alone there, and whose way in a later one is a detour that window cannot
  // prove shortest (since 2026-12-06; with a limit of 1 such a net is stopped in its first window). Every net still unrouted after the rounds is then tried
  // once more without the limit (so a net is left unrouted only when no way exists in the whole
  // final layout). 0: no limit. 1 since 2026-12-06 (2 before, once that check was made): on the
  // congested spread rows of docs/PERFORMANCE.md it routes 22 and 26 more of 3,000 nets in 0.66
  // to 0.77 times the time, on 3,000 planted nets the same nets with 0.7 % less wire in 0.82
  // times, and on 10^4 planted nets 4 fewer (9,921) with 1.0 % less wire in 0.81 times.
  int search_windows = 1;
  // After the rounds, one final round over the nets still unrouted in the best state, in which
  // every blocker may be ripped up whatever its rips; a rip-up there is kept only when it routes
  // more of the net and its blockers than before (so the round never loses a net). false: none.
  bool final_round = true;
  // In the rip-up rounds and the final round, work whose outcome is known is not done again (the
  // outcome is the same, bit for bit; see the header's Rip-up): a net's failed attempt, or its
  // way round the nets at the rip limit, is taken again while no wire has changed in its
  // windows; a rip-up that was undone is not made again while nothing has changed in the windows
  // it read; and a rip-up's nets stop being routed once it is sure to be undone. false: every
  // attempt made afresh (for tests).
  bool reuse = true;
  // The last pass first builds, once, a superset of every unrouted net's free space over the
  // whole domain (NetSpace::superset_obstacles: no wire is removed in that pass, so it stays
  // one); a net whose pins lie in different free components of it fails in its first window that
  // finds no way, instead of in windows up to the whole domain. The outcome is the same (the
  // failed attempt of a window is what an attempt gives when its pins are apart); false: not
  // built (for tests and benchmarks).
  bool superset = true;
  // The nets whose windows the route function takes with the domain's frame merged into their
  // obstacles (NetSpace::obstacles(..., framed)): one union per window instead of two (the
  // space's, then the wavefront's own merge of the frame). Only for a route function that reads
  // the obstacles through L1Router, OctRouter or their wavefronts alone. Empty: every net when
  // the route function is l1_router's or oct_router's (NetRouter::takes_frames), none otherwise.
  std::function<bool(std::size_t net)> framed;
  // Gaps of exactly the clearance take wires (see the header): the router works in the plane
  // scaled by NetRouter::scale(). The route function is then given scaled pins and obstacles
  // and must read the pins it is given (not its own copy); their NetPins::scale tells it the
  // lattice to route on, and to weigh bends by bend_cost x scale under Combined. outcomes()'
  // wires are in the layout's units (a reason a route function gave for a net it could not route
  // is its own text, of the scaled plane: taut route asks the route function again in real
  // units for those). false: gaps of
  // exactly 2a, and tracks at exactly the pitch, are closed.
  bool exact_gaps = false;
  // The obstacles given stand for sloped blockages by their rectilinear covers (taut route does
  // that under the bend-aware costs): the router's space is then smaller than the layout's, and
  // no NetOutcome::shortest is claimed.
  bool blockages_covered = false;
};

struct NetRouterStats {
  int rounds = 0;                 // rip-up rounds run
  std::int64_t attempts = 0;      // nets tried (each in one or more windows)
  std::int64_t windows = 0;       // calls of the route function (one per window tried)
  std::int64_t whole = 0;         // of those, on the whole domain
  std::int64_t relaxed = 0;       // bend-aware metrics: windows checked by the relaxation (see above)
  std::int64_t rips = 0;          // nets ripped up in all
  std::size_t first_pass = 0;     // nets routed by the first pass
  // Nets unrouted after the rounds, tried again in the last pass without the window limit
  // (NetRouterOptions::search_windows), and how many of them it routed.
  std::size_t last_pass = 0, last_pass_routed = 0;
  // Nets tried in the final round (NetRouterOptions::final_round), and the nets it gained.
  std::size_t final_round = 0, final_round_routed = 0;
  std::int64_t capped = 0;  // attempts that stopped at the window limit
  // Last-pass attempts that stopped because the net's pins are apart in a superset of its space
  // (NetRouterOptions::superset).
  std::int64_t superset_apart = 0;
  // Attempts (every pass, every level, explanations too) that stopped without a way instead of
  // widening their window because the net's pins lie in different free components among the
  // blockages alone, grown by the clearance (the plain ones at the Plain level), built once per
  // run with NetRouterOptions::superset (since 2026-12-06): a wall across the whole domain.
  std::int64_t blockages_apart = 0;
  // Attempts routed with one pin of each group of pins that meet, after the route function failed
  // on all of them (try_net_unsnapped; since 2026-12-06).
  std::int64_t group_choices = 0;
  // NetRouterOptions::exact_gaps: attempts whose wires had a vertex a quarter of the scale or
  // more from the multiple it was snapped to (see the header); such a wire may have lost its
  // direction, a connection or the clearance, and the outcomes must be routed again without
  // exact_gaps (taut route does). 0 without exact_gaps.
  std::int64_t snap_far = 0;
  // Rip-ups planned round the wires of nets that may not be ripped up again (see above).
  std::int64_t around_fixed = 0;
  std::int64_t undone = 0;  // rip-ups undone: fewer of the net and its blockers routed after
  // With threads > 1: attempts made ahead of their turn, and those of them tried again because a
  // wire placed in between met their window (not counted in attempts/windows above, which are
  // the same for every thread count; these two depend on timing).
  std::int64_t speculated = 0, redone = 0;
  // With threads > 1: rip-ups of the rounds worked out ahead of their turn (NetRouter::RipPlan),
  // and those of them worked out again in turn because a wire changed where they read the space.
  std::int64_t rip_ups_ahead = 0, rip_ups_redone = 0;
  // Attempts of the rip-up rounds and the final round taken again without routing: a net's last
  // failed attempt, or its last way round the nets at the rip limit, when no other net's wire has
  // been placed or removed in its windows since (the same outcome, bit for bit; not counted in
  // attempts and windows).
  std::int64_t reused = 0;
  // Rip-ups not made again because the same one was undone before and nothing has changed in the
  // windows its attempts read (it would be undone again: its rips are counted, in rips and undone).
  std::int64_t replayed = 0;
  // NetOutcome::shortest: claims kept at the end of run(), and claims withdrawn there (a wire
  // piece of another net removed from the window since)
  std::int64_t shortest = 0, shortest_withdrawn = 0;
  double space_seconds = 0, route_seconds = 0;  // building obstacles; routing in them
  double whole_seconds = 0;  // of those two, in windows on the whole domain
  // Wall-clock time of each phase of run(): the first pass, the rip-up rounds, the final round,
  // the last pass and the explanations of the nets left (the space and path seconds above are
  // summed over threads and over every phase).
  struct Phases {
    double first_pass = 0, rounds = 0, final_round = 0, last_pass = 0, explain = 0;
  } phase_seconds;
};

class NetRouter {
 public:
  NetRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles, std::vector<NetPins> nets,
            NetRules rules, NetRouterOptions options = {});

  // Routes every net (see above).
  void run(const NetRouteFn& route);

  // After run(), when a net's wires are changed (taut route --tighten pulls every wire taut):
  // `before` (net j's wires as outcomes() gave them, in the layout's units) are gone. As run()
  // does for the wire pieces removed while it routes, the claim (NetOutcome::shortest) of every
  // other net whose proof window, and in L1 the region a shorter wire of it would lie in, meet a
  // grown piece of them is withdrawn: a way may have opened there. (A claim this leaves stands for the net's new wire too when that is no longer in the
  // output's metric, as tightening's are: outside the window every way is longer, and inside it
  // only wires were added.) Returns how many claims it withdrew; stats() counts them.
  // `after`: its wires now (the same units): what they still cover was not freed
  // (NetSpace::removed_boxes).
  std::size_t withdraw_claims(std::size_t j, const std::vector<std::vector<geom::Point>>& before,
                              const std::vector<std::vector<geom::Point>>& after);

  // A route function for L1 rectilinear wires (router/l1_router.h): two pins by shortest(), more
  // by tree() from the first pin, or by steiner() when `steiner` (point and shape pins).
  static NetRouteFn l1_router(bool steiner);
  // The same for octilinear wires (router/oct_router.h): run it with
  // NetRouterOptions::octilinear.
  static NetRouteFn oct_router(bool steiner = false);
  // The route function is l1_router's or oct_router's, whose wavefronts take the windows'
  // obstacles with the domain's frame merged (NetSpace::obstacles(..., framed)): one union per
  // window instead of two.
  static bool takes_frames(const NetRouteFn& route);
  // The same for the bend-aware metrics (router/bend_router.h: length + bend_cost x bends, or
  // bends then length): the tree of optimal paths from the first pin (two pins: the optimal
  // wire), point and shape pins. Run it with NetRouterOptions::cost set to the same metric, on
  // rectilinear blockages (rectilinear_cover) with NetRules::cover_pieces > 0.
  static NetRouteFn bend_router(BendMetric metric, std::int64_t bend_cost);

  const std::vector<NetOutcome>& outcomes() const { return out_; }
  const std::vector<std::size_t>& order() const { return order_; }
  const NetRouterStats& stats() const { return stats_; }
  const NetSpace& space() const { return space_; }  // scaled by scale()
  // The factor the router's plane is scaled by (NetRouterOptions::exact_gaps), else 1.
  std::int64_t scale() const { return scale_; }

 private:
  // One net tried at one level, in growing windows: the attempt, the last (largest) window
  // tried (clipped to the domain; everything the attempt saw lies in it) and its counts.
  struct Tried {
    NetAttempt a;
    geom::Box window;
    NetRouterStats counts;
    std::size_t since = 0;  // the length of changed_ when it first read the space
  };
  // `overlay`: some nets' wires as they would be (NetSpace::obstacles).
  // With scale_ > 1 the wires are snapped to multiples of it (see the header).
  Tried try_net(const NetRouteFn& route, std::size_t net, NetSpaceLevel level, std::span<const char> only = {},
                const WireOverlay* overlay = nullptr) const;
  Tried try_net_unsnapped(const NetRouteFn& route, std::size_t net, NetSpaceLevel level, std::span<const char> only,
                          const WireOverlay* overlay) const;
  // A wire of one point that does not keep the clearance moved to another point its pins share
  // that does, when there is one among their vertices (try_net at the Full level; see there).
  void move_point_wires(std::vector<std::vector<geom::Point>>& wires, std::size_t net, NetSpaceLevel level,
                        std::span<const char> only, const WireOverlay* overlay) const;
  // Whether a wire of one point lies within the clearance of a blockage where no point of the
  // net's pins (NetSpace::clearance_candidates, on the lattice) keeps it: the pins meet, and no wire
  // on them can keep the clearance (try_net then fails the attempt, ROUTE-0010).
  bool point_wire_stuck(const std::vector<std::vector<geom::Point>>& wires, std::size_t net) const;
  // Whether p lies on the scaled plane's lattice (the multiples of scale_; every point when 1).
  bool on_lattice(geom::Point p) const { return router::on_lattice(p, scale_); }
  // The first point pin of `pins` on the lattice: always a legal wire of one point (the checker's
  // access zone exempts the wire there, and the other nets keep their clearance from the pin).
  static std::optional<geom::Point> lattice_point_pin(std::span<const geom::Polygon> pins, std::int64_t scale);
  // The first lattice point in pin g, taken next to each of NetSpace::clearance_candidates(net, g,
  // overlay, with_wires) in turn (geom::lattice_neighbours), that `usable` accepts; when none is,
  // and g's box holds at most kPinScanPoints lattice points, the first of those in g (x, then y,
  // increasing); the caller holds space_mutex_. move_point_wires, point_wire_stuck and
  // joined_point try their points so.
  static constexpr std::int64_t kPinScanPoints = 4096;
  std::optional<geom::Point> pin_candidate(std::size_t net, const geom::Polygon& g, const WireOverlay* overlay,
                                           bool with_wires, const std::function<bool(geom::Point)>& usable) const;
  // For pins that all meet: a point on them for a wire of one point that keeps the clearance at
  // this level (none at Plain, the blockages' at Clearance, the other nets' pins' too at Pins, and
  // the wires `only` and the overlay give at Full: the lower levels read no wires), on the
  // scaled lattice; nullopt when none of the points tried (a point pin, the shared points, the
  // NetSpace::clearance_candidates) does.
  std::optional<geom::Point> joined_point(std::size_t net, const NetPins& pins, NetSpaceLevel level,
                                          std::span<const char> only, const WireOverlay* overlay) const;
  void run_scaled(const NetRouteFn& route);
  geom::Box first_window(std::size_t net) const;  // the first window try_net tries
  NetAttempt attempt(const NetRouteFn& route, std::size_t net, NetSpaceLevel level);  // counted
  // The nets whose grown wires these wires of net `net` enter, and those that enter its pads.
  std::set<std::size_t> way_blockers(std::size_t net, const std::vector<std::vector<geom::Point>>& wires) const;
  // Routes `nets` at the Full level one after another, placing each (as if with one thread).
  // `after` is told each net placed and the last window its attempt read; false stops there (the nets after it are left as they are).
  // How: with threads, workers try the nets ahead, a net only when the nets before it still to be
  // placed are unlikely to change its first window (Cautious: see NetRouterOptions::cautious;
  // Failing: the same, but a net not tried yet is taken to fail and change nothing, as in the
  // last pass, whose nets all failed before); Serial: this thread alone, as with one.
  enum class InOrder { Cautious, Failing, Serial };
  void route_in_order(const NetRouteFn& route, std::span<const std::size_t> nets,
                      const std::function<bool(std::size_t, const geom::Box&)>& after, InOrder how = InOrder::Cautious);
  // (`unioned`: the union of a's wires, NetSpace::wire_union, when made already)
  void place(std::size_t net, NetAttempt a, std::optional<std::vector<geom::Polygon>> unioned = std::nullopt);
  // A way round the wires of the nets that may not be ripped up again (around_), with those of
  // them whose wires met its last window.
  struct AroundWay {
    Tried tried;
    std::vector<std::size_t> fixed;
  };
  // A rip-up for net `net` (run: the nets in the way of its route alone are ripped up, and it and
  // they are routed again), worked out against the space without changing it, then made (commit:
  // true when it is undone, as before it, or not made again because the same one was undone
  // before). Worked out by a worker ahead of its turn, it is made in its turn when no wire piece
  // placed or removed since (changed_), nor any wire of a net whose rips were counted since
  // (rips_log_), meets what it read (`reads`): it would have been worked out the same way then.
  struct RipPlan {
    enum class Kind { Nothing, Replay, Made } kind = Kind::Nothing;
    std::size_t net = 0;
    bool gain = false;
    std::size_t since = 0, rips_since = 0;  // the lengths of changed_ and rips_log_ when it began
    std::vector<geom::Box> reads;      // every box of the space it read
    bool any_fixed_read = false;       // it stopped because no net was at the rip limit
    int limit = 0;
    NetRouterStats counts;             // its attempts' counts, and the reused and around_fixed it adds
    std::optional<Tried> alone;        // the net alone, when not kept yet
    std::optional<AroundWay> around;   // a new way round the nets at the limit
    std::set<std::size_t> blockers;
    std::vector<std::pair<std::size_t, NetAttempt>> again;  // the net, then its blockers, as routed
    WireOverlay overlay;               // their wires' unions (NetSpace::wire_union), which commit moves
    std::vector<geom::Box> windows;    // the last windows of those attempts
    bool undone = false;               // Made: fewer of them routed after (with gain: not more)
  };
  RipPlan plan_rip_up(const NetRouteFn& route, std::size_t net, int limit, bool gain,
                      const std::optional<Tried>* ahead_alone = nullptr) const;
  bool plan_valid(const RipPlan& p) const;
  bool commit(RipPlan p);
  struct Explained {
    std::string code, reason;
    std::vector<std::size_t> blockers;
    NetRouterStats counts;
  };
  Explained explain(const NetRouteFn& route, std::size_t net) const;
  // During the last pass (no wire is removed then, so it stays a superset of every unrouted
  // net's free space): the free components of NetSpace::superset_obstacles, built once.
  std::shared_ptr<const FreeComponents> superset_;
  // For the whole run (NetRouterOptions::superset): the free components among the grown blockages
  // alone, a superset of every net's space at every level but Plain, and among the plain ones,
  // each built when an attempt first needs it.
  std::shared_ptr<BlockageParts> blockage_parts_;

  std::int64_t scale_ = 1;  // before space_, which is built scaled
  NetSpace space_;
  NetRouterOptions options_;
  std::vector<NetOutcome> out_;
  std::vector<std::size_t> order_;
  NetRouterStats stats_;
  // per net, its attempt at the Pins level (the blockages and other nets' pins only: fixed for
  // the run, so tried once per net and kept)
  std::vector<std::optional<NetAttempt>> alone_;
  std::vector<char> final_undone_;  // per net: its rip-up in the final round was undone
  // per net: its pins all meet (joined pair by pair at lattice points they share, into one
  // group), so an attempt first tries a wire of one point on them (try_net_unsnapped)
  std::vector<char> joined_;
  // per net: its pins in groups that meet, when there are two groups or more and fewer than its
  // pins (else empty); try_net_unsnapped routes one pin of each group when the route function
  // fails on all of them (see there)
  std::vector<std::vector<std::vector<std::size_t>>> groups_;
  static constexpr std::size_t kMaxGroupChoices = 16;
  bool capped_ = false;  // Full attempts stop after options_.search_windows unreachable windows
  // The boxes of every wire piece placed or removed since run() began, with their net (an attempt
  // made ahead, or a failed one kept, is valid while none of another net meets its last window).
  // A rip-up that is undone drops its entries (the space is then as it was before it).
  std::vector<std::pair<geom::Box, std::size_t>> changed_;
  // The boxes of every wire piece removed since run() began, with their net (never dropped: see
  // NetOutcome::shortest).
  std::vector<std::pair<geom::Box, std::size_t>> removed_;
  // Per net, its claim's (NetOutcome::shortest) window and the length of removed_ when it was made.
  struct Claim {
    geom::Box window{};
    std::size_t since = 0;
  };
  std::vector<Claim> claims_;
  // Whether NetOutcome::shortest may be claimed in this run (else removed_ stays empty): with
  // the scale, and only when the space is the layout's own: no blockage covered, and with
  // NetRules::cover_pieces > 0 (always under the bend-aware costs) every pin of every net
  // rectilinear (none stands for a staircase or a cover)
  bool certifies() const {
    return scale_ > 1 && !options_.blockages_covered && (rectilinear_pins_ || !covers_pins_);
  }
  bool rectilinear_pins_ = true;  // every pin of every net: a point, or edges horizontal and vertical
  bool covers_pins_ = false;      // NetRules::cover_pieces > 0
  // Net i's claimed cost (scaled): the L1 length of its wires, or with Combined the length +
  // bend_cost x bends; a cheaper wire lies within the cost less K of its pins (may_open).
  std::int64_t claimed_cost(const std::vector<std::vector<geom::Point>>& wires) const;
  bool may_open(std::size_t i, std::int64_t kr, const geom::Box& b) const;
  // The boxes of the wires of every net whose rips were counted without its wires changing (a
  // rip-up undone), since run() began.
  std::vector<std::pair<geom::Box, std::size_t>> rips_log_;
  // Per net: its last failed attempt at the Full level in the rip-up rounds and the final round.
  std::vector<std::optional<Tried>> failed_;
  // Per net: its last rip-up, when it was undone: the blockers ripped up, whether it had to gain
  // nets (the final round), the log's length before it and the windows its attempts read (the
  // state after an undo is the state before, so the same rip-up would go the same way while no
  // wire of any net is placed or removed in those windows).
  struct UndoneRipUp {
    std::set<std::size_t> blockers;
    bool gain = false;
    std::size_t mark = 0;
    std::vector<geom::Box> windows;
  };
  std::vector<std::optional<UndoneRipUp>> undone_;
  // Per net: its last way round the wires of the nets that may not be ripped up again (rip_up in
  // run), with those of them whose wires met its last window (valid while no wire changes there
  // and the same nets there are fixed).
  std::vector<std::optional<AroundWay>> around_;
  mutable std::shared_mutex space_mutex_;  // place() writes space_ and changed_; attempts read them
};

}  // namespace taut::router
