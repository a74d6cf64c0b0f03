// Tightening every net of a layout together, keeping the clearance of <rules> (issue #5,
// "Clearance"): each wire is pulled taut in its homotopy class among the blockages grown by
// a = ceil(w/2) + s and the other nets' wires and pins grown by b = max(w + s, 1), exactly the
// space the net router routes it in (router/net_router.h: NetSpace at the Full level), and the
// nets are tightened again round after round until no wire gets shorter.
//
//   NetSpace space(norm.domain, norm.obstacles, nets, rules);
//   NetsTightener nt(space, {.orientations = TightenOrientations::Rectilinear});
//   std::vector<NetLines> wires = ...;            // per net: its wires (each in its net's space)
//   const auto errors = nt.run(wires);            // wires now tightened; errors: inputs not free
//
// Why nothing crosses and no class changes. A wire moves only inside the free space of its net's
// space, which is a subset of the free space among the plain blockages: the homotopy from the old
// wire to the new one (through the sleeve) stays there, so its class among the blockages is kept,
// it never enters another net's grown wires or pins (no crossing, the clearance kept: growing by
// squares keeps at least that Euclidean distance), and the other nets' later moves avoid its new
// position the same way. Every move is an improvement in (length in the output's metric, bends),
// never worse in either: a finite set of values, so the rounds end (NetsTightenOptions::max_rounds
// is a guard, reported when hit). When they end, each net's wires are joined and cut again as a
// second run would cut them (since 2026-12-07; a joined line may tighten further as one), and the
// rounds go on with the nets whose pieces differ; a re-cut keeps the metal (its length) but may
// count a bend at a joint, so it is not a move: once a re-cut round moves nothing, or at
// max_rounds, the rounds stop.
//
// Trees. A net's wires may end on each other (branch points, Steiner points) and pass through its
// pins. Tightening a wire with its ends fixed would pull it off a branch point or a pin it passes,
// so every wire is first cut at the ends of the net's other wires and at the net's point pins that
// lie on it (its ends stay where they are), then joined again where exactly two wires end at a
// point on no pin (join_at_twos): every wire then runs between fixed points (pins, points where
// one or three or more wires end) and the net stays connected. The result is joined where two
// wires end, pins included. A shape pin reached only along a wire's side is cut there too when a vertex of
// the wire lies on it; otherwise (it is touched mid-segment only) that wire is kept as it is.
//
// Windows. A wire is tightened in a window round it (its box grown by 2(a + b) + 64): the
// obstacles of its net's space clipped there (NetSpace::obstacles). The result is the class's
// shortest in the window's space, which is homotopic to the input in the whole space; when no
// vertex of it lies on a side of the window inside the domain it is locally taut in the whole
// space too (every bend wraps an obstacle vertex), so the shortest of its class there: kept.
// Otherwise the margin grows fourfold, up to the whole domain. A rectilinear or octilinear
// staircase between two cuts lies in their bounding box (monotone), so inside the window as well.
//
// Rounds. Only a net whose window some change of another net's wires has met since it was last
// tightened is tried again (its result depends on nothing outside its windows), so a round after
// the first costs as much as the nets still moving.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "geom/triangulation.h"
#include "geom/types.h"
#include "router/net_router.h"
#include "router/root3_staircase.h"
#include "router/staircase.h"
#include "router/tighten.h"

namespace taut::router {

// The output's directions: any angle (no set: the Euclidean taut wire), a lattice direction
// set (geom/directions.h: rectilinear, octilinear, c:0,45, c:45,135, ...), or (since 2026-12-07;
// NetsTightener since 2026-12-07) a set at multiples of 30 degrees (geom/root3_directions.h:
// c:0,60,120, ...), written rounded (router/root3_staircase.h).
struct TightenOrientations {
  std::optional<geom::LatticeDirections> set;
  std::optional<geom::Root3Directions> set30;
  // A direction set (either kind), not any angle.
  bool c_oriented() const { return set || set30; }
  // The line is written in these directions: any angle; every segment along a direction of the
  // lattice set (LatticeDirections::runs_along); every segment within the rounding of one of the
  // set at multiples of 30 degrees (Root3Directions::fits, what taut check verifies).
  bool runs_in(std::span<const geom::Point> line) const;
  // The set's name (LatticeDirections::name, Root3Directions::name), or "any".
  std::string name() const;
  // A staircase in some cone of the set leaves the box of its link's ends (either kind's
  // cones_leave_box; false for any angle).
  bool cones_leave_box() const;
  // How many times its link's |dx| + |dy| a staircase may reach out of the link's box
  // (Root3Directions::box_growth; 1 for the lattice sets and any angle).
  int box_growth() const { return set30 ? set30->box_growth() : 1; }
  static const TightenOrientations Any, Rectilinear, Octilinear;
  friend bool operator==(const TightenOrientations&, const TightenOrientations&) = default;
};
inline const TightenOrientations TightenOrientations::Any{};
inline const TightenOrientations TightenOrientations::Rectilinear{geom::LatticeDirections::rectilinear(), std::nullopt};
inline const TightenOrientations TightenOrientations::Octilinear{geom::LatticeDirections::octilinear(), std::nullopt};

// Tightening in one space: the free-space triangulation of normalized obstacles, the tightener,
// and for output in a lattice direction set the staircase builder.
class SpaceTightener {
 public:
  // snap_scale K > 1 (a plane scaled by K, whose results are snapped back to multiples of K):
  // a staircase too fine to survive that (StaircaseTooFine, staircase.h) is not built, and the
  // piece is taken as having none (no_staircase).
  SpaceTightener(const geom::NormalizedObstacles& norm, TightenOrientations orientations, std::int64_t snap_scale = 1);
  struct Result {
    Tightened taut;                   // the lift and the Euclidean shortest path of the class
    std::vector<geom::Point> points;  // in the orientations (a repeated point for a one-point wire)
    bool no_staircase = false;        // c-oriented: no lattice staircase in the class, or (snap_scale
                                      // > 1) one too fine to snap back; a set at multiples of 30
                                      // degrees: no wire (why)
    std::string why;                  // a set at multiples of 30 degrees: why there is no wire
    bool loop = false;                // the line was closed: `points` is the shortest closed loop
    bool contractible = false;        // a loop that winds around nothing
  };
  // A closed line (last point = first, around some other point) is a loop: the shortest closed
  // loop of its free homotopy class (Tightener::tighten_loop).
  Result run(std::span<const geom::Point> line) const;
  static bool is_loop(std::span<const geom::Point> line);
  const geom::FreeSpaceTriangulation& triangulation() const { return tri_; }
  const Tightener& tightener() const { return *tight_; }

 private:
  TightenOrientations orientations_;
  geom::FreeSpaceTriangulation tri_;
  std::unique_ptr<Tightener> tight_;
  std::unique_ptr<StaircaseBuilder> sb_;
  std::unique_ptr<Root3StaircaseBuilder> sb30_;
};

using NetLines = std::vector<std::vector<geom::Point>>;

struct NetsTightenOptions {
  TightenOrientations orientations = TightenOrientations::Rectilinear;
  int max_rounds = 100;  // a guard: the rounds end by themselves (see above)
  bool windows = true;          // false: every wire on the whole domain (tests)
  std::function<bool()> stop;   // asked before every window: true throws NetRouterStopped
  std::int64_t snap_scale = 1;  // > 1: the plane is scaled by it (tighten_scaled sets it; SpaceTightener)
};

struct NetsTightenStats {
  int rounds = 0;                  // rounds run (the last one changed nothing, unless capped)
  bool capped = false;             // max_rounds was reached with wires still moving
  std::int64_t tightenings = 0;    // wires tightened (each in one or more windows)
  std::int64_t windows = 0;        // triangulations built
  std::int64_t whole = 0;          // of those, on the whole domain
  std::int64_t moved = 0;          // results taken
  std::int64_t kept_shape_pin = 0; // wires kept as they are: a shape pin touched mid-segment only
  std::int64_t kept = 0;           // wires kept as they were at their last try: not free in their space, or no staircase
  std::int64_t kept_not_free = 0;  // of those at the end, not free (a gap of exactly the clearance)
  std::size_t split = 0;           // wires added by cutting at branch points and pins
};

// What happened to one net (NetsTightener::run).
struct NetTightenOutcome {
  // Its first problem. NotFree: a wire's lift failed in its net's space, so it is kept as it is:
  // in round 0 (sketches only) its input is not in that space (it leaves free space, comes within the
  // clearance of a blockage, of another net's wire or pin, or runs in a gap of exactly the
  // clearance, which the space closes: see net_router.h); in a later round the others moved to
  // exactly the clearance on both sides of it. NoStaircase: the class has no lattice staircase
  // (the wire is kept as it is). Contractible: a loop that winds around nothing; the net's wires
  // are then left out of the space and of the result (it is to be written as failed).
  enum class Status { Ok, NotFree, NoStaircase, Contractible } status = Status::Ok;
  int round = 0;                 // when it happened: 0 for a sketch that is not in its net's space as
                                 // given (the net is then not tightened; its wires stay as they are)
  // A sketch piece that no result replaced: it is still the sketch (`wire`): its class has no
  // lattice staircase (status NoStaircase), or its lift failed at every try after round 0 (the
  // other nets moved to exactly the clearance on both sides of it).
  bool untightened = false;
  std::size_t wire = 0;          // which wire (an index into the net's wires after the cuts)
  Tightened lift;                // NotFree: the failed lift (its segment and point)
  std::string why;               // untightened with no staircase (piece `wire`), in a set at multiples of 30
                                 // degrees: why (SpaceTightener::Result::why)
  std::vector<std::size_t> wire_blockers, pin_blockers;  // NotFree: nets whose grown wires / pins it enters
  double length_before = 0, length_taut = 0, length_after = 0;  // Euclidean
  std::int64_t bends_before = 0, bends_after = 0;
  std::size_t sleeve = 0, crossings = 0;  // of the first round's tightening
  int moves = 0;                           // results taken
  bool loop = false;
  // Per wire as it was tightened (after the cuts, before join_at_twos): left as it was at its last
  // try (1: not free in its space; 2: no staircase) or never tried (a shape pin touched
  // mid-segment); 0: tightened. `pieces` are those wires.
  std::vector<char> kept;
  NetLines pieces;
};

class NetsTightener {
 public:
  // The space holds the nets' pins and rules; its wires are set by run().
  NetsTightener(NetSpace& space, NetsTightenOptions options = {});

  // wires[i]: net i's wires (empty: none, it is not routed). In each net's space every wire
  // must lie in free space (its lift succeeds); the ones that do not are reported in the
  // outcome. On return wires[i] holds the tightened wires (cut at branch points, see above, then
  // joined again where exactly two of them meet: join_at_twos).
  // A result is taken when it is no longer than the wire it replaces and has no more bends, and
  // is better in one of the two (with `any` orientations: when it is another path, so shorter).
  // The nets of kind Sketch hold sketches, not wires in the output's directions: round 0
  // checks that they lie in their nets' spaces as given (all at once, before anything moves), and
  // each piece's first result is taken whatever it is, later ones when shorter (or as long with
  // fewer bends); their lines, and TautSketch ones, are never cut, joined or cleared of overlaps
  // (a sketch may run along itself, winding twice round a blockage), and their later results are
  // taken the same way. The nets of kind CheckedWires are wires as Wires are, checked in round 0
  // as sketches are (wires read from a file, which may not keep the clearance).
  // kind[i] (default Wires for every net): what net i's lines are.
  enum class Input : char {
    Wires,         // a router's wires (cut at joints, joined; moves no longer and with no more bends)
    Sketch,        // sketches as drawn (checked in round 0, first results taken whatever they are)
    TautSketch,    // sketches already tightened (e.g. by the net router): never cut or joined
    CheckedWires,  // wires (as Wires) whose pieces are checked in round 0 (as Sketch: taut tighten's routed wires)
  };
  std::vector<NetTightenOutcome> run(std::vector<NetLines>& wires, std::span<const Input> kind = {});
  const NetsTightenStats& stats() const { return stats_; }

 private:
  NetSpace* space_;
  NetsTightenOptions options_;
  NetsTightenStats stats_;
};

// A net router's attempt (NetRouteFn) tightened into `orientations` among the obstacles it was
// routed among (the net alone: a NetsTightener on a NetSpace of those obstacles with no rules, as
// they are grown already; they must not hold the domain's frame, NetRouterOptions::framed), so
// that a net router places wires already in those directions and routes the later nets round
// them (`taut route --orientations` with a lattice c: set, since 2026-12-06: a net whose octilinear
// wire is tightened only after every net is placed can be left in a gap of exactly the clearance
// between later wires, where no wire of a set that lacks its direction fits). The attempt is left
// as it was when it is not routed or when a wire stays outside the set (a piece the tightening
// could not move). Its claim (NetAttempt::distance) is dropped: it was the route's.
void tighten_attempt(NetAttempt& attempt, const NetPins& pins, const geom::NormalizedObstacles& obstacles,
                     const TightenOrientations& orientations, const std::function<bool()>& stop = {});

// Cuts a net's wires at the ends of its other wires, and at its pins, that lie on them (see
// Trees above). `frozen` flags the pieces of wires that touch a shape pin mid-segment only (they
// must stay as they are).
NetLines cut_at_joints(const NetLines& wires, std::span<const geom::Polygon> pins, std::vector<char>* frozen = nullptr);

// Whether a polyline is one point (empty, or every vertex the same): a wire of one point, which
// a router writes where two pins share a point; nothing to tighten.
bool one_point(std::span<const geom::Point> line);

// The wires joined where exactly two of them end at one point, except on the pins given: the same
// metal in fewer polylines (a bend there is counted again, and a point that joins nothing else is
// free to move). Where one, three or more wires end, they stay apart; so do closed wires (loops).
// Deterministic (in input order).
NetLines join_at_twos(const NetLines& wires, std::span<const geom::Polygon> pins = {});

// The nets' wires (layout units) tightened together (NetsTightener) in the net router's plane
// scaled by k > 1 (NetRouter::scale, exact_gaps_scale: the domain, blockages and pins times k, the
// rules' scale k, so gaps of exactly the clearance are open, net_router.h), then every vertex
// snapped back to the nearest multiple of k (halves away from zero) and divided by it. nullopt
// when a vertex lay k/4 or more from its multiple, or a net's wires (other than a sketch's as
// drawn, Input::Sketch, which may come back longer in a set's metric) came back empty or longer
// (octilinear length, exactly). The caller checks the result with its rules (router::check_routes)
// before it takes it. `stats`: the tightening's; `outcomes`: its per-net outcomes, with the
// lengths in layout units (divided by k) and every point (pieces, lift.where) still in the
// scaled plane. Also nullopt when a wire that ran in the set's directions in the scaled plane
// does not after the snap (links shorter than k collapse, or turn). A staircase too fine to snap
// back is not built there (StaircaseTooFine): its piece is taken as having none (NoStaircase) and
// kept as it was; a sketch's piece, or a wire's outside the set's directions, is then
// NetTightenOutcome::untightened, which `taut tighten` takes as a reason to work in the layout's
// units.
std::optional<std::vector<NetLines>> tighten_scaled(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                    std::vector<NetPins> nets, NetRules rules, std::int64_t k,
                                                    const std::vector<NetLines>& wires, std::span<const NetsTightener::Input> kind,
                                                    const NetsTightenOptions& options, NetsTightenStats* stats = nullptr,
                                                    std::vector<NetTightenOutcome>* outcomes = nullptr);

// The octilinear length a + b sqrt2 and the bends of a net's wires (segments at 0, 45 or 90
// degrees measured exactly, others by their octilinear distance).
std::pair<geom::Root2, std::int64_t> length_and_bends(const NetLines& wires);

}  // namespace taut::router
