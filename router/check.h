// The independent checker of routed layouts (issue #7; `taut check`): it shares only geom (types,
// predicates, the blockage union) with the routers, so a router bug is not repeated here.
//
//   const CheckResult r = check_routes(normalized, nets);   // r.problems: empty when legal
//
// What a routed net must be (FORMAT.md):
//   - free: every wire stays in the closed free space (the closed domain minus the open union of
//     the blockages). It may run along blockage edges and through their vertices, but where it
//     passes through a point it arrives and leaves inside one wedge of free space there, so it
//     never passes through a point where two blockages touch (a pinch), and never runs along an
//     edge that lies flush on the boundary (no free space beside it);
//   - connected: its wires and pins form one connected set (a wire may end on another wire of
//     its net; a point pin is reached when a wire passes through it, a shape pin when a wire
//     touches the closed shape), and no wire is left apart from the rest;
//   - apart from the other nets: no wire shares a point with another net's wire or pin (a
//     short, whatever the rules say; FORMAT.md's "distance >= w + s" with w = s = 0 would allow
//     touching, which no process does).
//   - clear (when <rules> has a wire width w or a spacing s): every wire keeps Euclidean
//     distance >= w/2 + s from every blockage and from other nets' shape pins, and >= w + s from
//     other nets' wires and point pins (a point pin counts as the end of a wire of its net).
//     Pin access: the parts of a net's wires in the access zones of its own point pins are not
//     held to the blockage clearance (a pin may sit on a blockage's edge, FORMAT.md, and its
//     wire has to get away from it). A zone is the closed square of half-side a = ceil(w/2) + s
//     around a point pin: w/2 + s rounded up to an integer, as the net router grows blockages
//     (router/net_router.h: with w odd, a square of w/2 + s would stop half a unit short of the
//     grown blockage's integer edge and wall the pin in); the whole square counts, not only a
//     wire's first segment, because a pin in a corner between blockages may need a bend inside
//     it. Shape pins get no zone: a wire reaches a pad from outside it and keeps the clearance
//     up to its end (a zone round every wire end on a pad let wires split into many ends hug a
//     blockage along the pad's whole side, a review found). The
//     clearance to other nets holds everywhere. Distances are compared
//     exactly: squared distances as fractions of integers against (w + 2s)^2 / 4 and (w + s)^2
//     in 256-bit integers, and where the pin access cuts a segment at a rational point, in
//     arbitrary-precision integers (Boost.Multiprecision cpp_int) scaled by its denominator.
//
// How. The wedges of free space at a point p (the maximal closed sectors of directions d with
// p + e d in the open free space for small e > 0) come from the ring edges through p (outer
// rings counter-clockwise, holes clockwise, the domain as a clockwise ring: material left of
// every directed edge). Their directions from p, sorted by angle, cut the directions into
// sectors; a sector is material when an edge at its clockwise end leaves p (material on its
// left), else free. (Pairing each ring visit's two edges fails where a ring touches itself at p:
// a pinch.) A segment running along an edge that lies on the domain's side has material on both
// sides of its direction at the edge's ends, so it fails the wedge test there.
// A segment ab is free iff its ends lie in the closed domain, it properly crosses no edge, at
// every point q of ab on a ring (a ring vertex on it, or an end of ab on a ring) the directions
// to a and b lie in one free sector (to the other end only at a or b), and, when it touches no
// ring, a lies in no obstacle. Exact:
// directions are compared by __int128 cross and dot products. Edges are found in a Boost.Geometry
// R-tree; connectivity by union-find over wires and pins; shorts by an R-tree of all wire
// segments. O((n + m) log (n + m)) for n ring edges and m wire segments, plus the pairs of a
// net's segments whose boxes meet.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "geom/normalize.h"
#include "geom/types.h"

namespace taut::router {

struct CheckPin {
  std::string name;
  std::optional<geom::Point> point;    // a point pin ...
  std::optional<geom::Polygon> shape;  // ... or a shape pin
  int line = 0;
};

struct CheckWire {
  std::vector<geom::Point> points;
  int line = 0;
};

struct CheckNet {
  std::string name;
  std::vector<CheckPin> pins;
  std::vector<CheckWire> wires;  // empty for a net not routed (not checked)
  bool routed = false;
  int line = 0;  // the <route>'s line
  // A net with a loop sketch (a guard ring, README's "Loops"): its loop belongs to no pin, and its
  // pins are not joined to it, so a closed wire of it (first point = last) need touch no pin, and
  // when all its wires are closed its pins need not be connected (free space, shorts and the
  // clearance are checked as for every net; its other wires as for every net).
  bool loop = false;
};

struct CheckProblem {
  enum class Kind {
    NotFree,       // a wire leaves free space (into a blockage, out of the domain, through a pinch)
    Disconnected,  // a pin of the net is not connected to the others through its wires
    StrayWire,     // a wire touches no pin and no wire connected to the pins
    Short,         // a wire shares a point with another net's wire or pin
    BlockageClearance,  // a wire comes closer than w/2 + s to a blockage
    NetClearance,       // a wire comes closer than w + s to another net's wire or point pin, or
                        // than w/2 + s to its shape pin
  };
  Kind kind = Kind::NotFree;
  std::size_t net = 0;    // index into the nets given
  std::optional<std::size_t> wire;  // the wire (index into the net's wires), when about one
  int line = 0;           // the wire's line (the pin's for Disconnected)
  geom::Point at;         // a point where it happens (an end of the offending segment, or the pin)
  std::optional<std::size_t> obstacle;  // NotFree: the obstacle met (index into obstacles), if one
  std::optional<std::size_t> other_net; // Short, NetClearance: the other net
  std::string message;    // what happened, for a person
};

struct CheckResult {
  std::vector<CheckProblem> problems;
  std::size_t wires = 0, segments = 0;
};

struct CheckRules {
  std::int64_t wire_width = 0, spacing = 0;  // <rules wire-width spacing>, each >= 0
};

// obstacles: geom::normalize_obstacles() of the blockages in a domain holding every wire point
// (the layout's boundary when it has one). Nets not routed are skipped.
CheckResult check_routes(const geom::NormalizedObstacles& obstacles, std::span<const CheckNet> nets,
                         const CheckRules& rules = {});

// The free-space part alone, for tests: is the polyline a legal wire (each segment free, every
// interior vertex passed within one wedge)?
class FreeSpaceChecker {
 public:
  explicit FreeSpaceChecker(const geom::NormalizedObstacles& obstacles);
  ~FreeSpaceChecker();
  FreeSpaceChecker(FreeSpaceChecker&&) noexcept;
  FreeSpaceChecker& operator=(FreeSpaceChecker&&) noexcept;
  struct Verdict {
    bool free = true;
    geom::Point at;                        // the first offending point when not free
    std::optional<std::size_t> obstacle;  // the obstacle met there, if one
    std::string why;
  };
  Verdict polyline(std::span<const geom::Point> points) const;
  bool point_free(geom::Point p) const;
  // The obstacle edges whose boxes meet `box`, with their obstacle (the domain's sides left out).
  std::vector<std::pair<geom::Segment, std::size_t>> obstacle_edges_near(const geom::Box& box) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace taut::router
