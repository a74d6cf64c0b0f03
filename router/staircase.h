// Staircases: a polygonal shortest path (free straight links of any slope, as the L1 wavefront
// returns them) turned into a rectilinear (or octilinear) polyline of the same length, with
// integer vertices, in free space, with the fewest bends the method can prove.
//
//   StaircaseBuilder sb(normalized.domain, normalized.obstacles);
//   std::vector<Point> poly = wf.target_path(0);
//   if (auto r = sb.rectilinear(poly)) { /* horizontal/vertical, same L1 length */ }
//   if (auto o = sb.octilinear(poly)) { /* 0/45/90/135 degrees, same octilinear length */ }
//
// Free space: as in router/wavefront.h and tests/oracle/l1_oracle.h (closed obstacles, the
// domain side is a wall, a path never passes through a pinch from one free wedge into another).
//
// Method. A link a->b has L1 length |dx| + |dy|, and a rectilinear path has that length iff it
// is monotone in x and y: a staircase in the rectangle R(a, b) made of the two axis directions
// d1, d2 pointing from a toward b. (Octilinear: the two of the 8 directions that bracket
// b - a, e.g. E and NE; every path made of those has the octilinear distance max + (sqrt2-1)
// min. The unimodular map p -> (u, v) with p = a + u d1 + v d2 makes it the same problem on
// the integer lattice; all geometry stays in the original coordinates.) Per link and per
// (first, last) direction pair, an A* search over "lines entered at a lattice point" with
// cost = bends (lower bound 0/1/2 bends left); a line is followed as far as it is free (exact
// rational crossings with the edges meeting it; through a vertex only inside one free wedge)
// and may be left at the candidate coordinates below. A DP over the links then picks each
// link's first and last direction so that joints bend only when they must, and never switch
// wedges at a joint. A final pass re-checks the whole polyline segment by segment.
//
// Candidate coordinates (exact and complete). In local coordinates (u along d1, v along d2,
// a = (0,0), b = (U,V)), a staircase moving along the d1-line v = y may turn onto a d2-line
// only at u in  VU  U  { floor(X) : a non-parallel obstacle edge crosses v = y at u = X }
// U {U - 1, U}, where VU = u of every vertex of an edge meeting R(a,b); symmetrically for
// d2-lines. Why this loses nothing: take any free lattice staircase with the fewest bends for
// its (first, last) pair and push its inner segments toward b one unit at a time while the
// result stays free (terminates: coordinates only grow). At the end each inner segment S (on
// u = c, from v = y0 up to y1, entered from the d1-segment on v = y0) cannot move to c + 1.
// Push lemma: if c is not in VU and no edge crosses v = y0 at an X with floor(X) = c, the move
// is free. Proof: the open strip c < u < c+1 holds no lattice point, so an edge entering the
// parallelogram Q = [c,c+1] x [y0,y1] must leave it through S (a proper crossing, or a vertex
// at u = c), through its top (a proper crossing of the old path, or through the old bend,
// which then leaves the two old directions on opposite sides of the edge), or through its
// bottom (then floor(X) = c); so the interior of Q is free, and the new pieces (its bottom
// and the side u = c+1) lie on its boundary with all turns in the wedge that contains Q. A
// move that empties an inner segment would save two bends, so at the fixed point every inner
// segment sits at a candidate of the line it came from, except that the segment before the
// last may stop at U - 1 / V - 1 (emptying the last segment would change the last direction).
// The search builds the lines it reaches lazily, so the closure of this set over all lines
// (which can be large) is never built; only edges meeting R(a,b) matter. The per-pair
// optima are compared with a brute-force BFS over every lattice point in the tests.
//
// Cost and budget. Work is about the number of lines entered times their candidates; with
// the A* bound most links take microseconds. A pair is only searched up to the bends the DP
// can still use (best pair so far + number of joints - 1). Each search stops after
// options.max_work_per_search steps; if no pair of a link finished, a depth-first fallback
// (farthest turn first) returns some free staircase: valid, bends not proven minimal
// (stats.greedy_links counts those links).
//
// Limitation (not of the candidates, of integers): with sloped edges a free link may have no
// lattice staircase at all, e.g. between the disjoint triangles (-1,0),(2,1),(-1,1) and
// (1,0),(4,0),(4,1) the segment (0,0)->(3,1) is free but every lattice staircase crosses one
// of them (a half-integer one exists). Then the call returns nullopt (also when even the
// fallback runs out of budget); it never returns a path that is not free or not of equal
// length. Staircases are searched per link, through the given bend points; a rectilinear path
// of equal length through other points is not considered.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "geom/directions.h"
#include "geom/predicates.h"
#include "geom/types.h"

namespace taut::router {

enum class StaircaseStyle : std::uint8_t { Rectilinear, Octilinear };

// The direction set of a style (one shared instance each).
const geom::LatticeDirections& lattice_set(StaircaseStyle style);

struct StaircaseOptions {
  // Work (search steps and turn candidates) per search of a link: 4 searches per link, each
  // about 1-10 microseconds per unit. When none of them finishes, a depth-first fallback with
  // 4x this budget returns some free staircase (bends not proven minimal).
  std::size_t max_work_per_search = std::size_t{1} << 18;
  // staircase_in_class: the width of the first slab a run gathers its walls from (doubled per
  // slab). Only speed depends on it; the tests set 1 so that small layouts use many slabs.
  std::int64_t first_slab = 32;
  // > 1: the plane is scaled by it, and its staircases are snapped back to multiples of it
  // (router::tighten_scaled): staircase_in_class throws StaircaseTooFine for a piece whose
  // staircase has more than 16 + 4 m + 4 L / snap_scale points (m the piece's vertices, L its L1
  // length), stopping there (see StaircaseTooFine).
  std::int64_t snap_scale = 1;
};

// A piece's staircase in a plane scaled by K (StaircaseOptions::snap_scale) with more points than
// 16 + 4 m + 4 L / K: its links average under K / 4 in L1 length beyond those the bends need, so
// snapped back to multiples of K they collapse or turn out of the set's directions. A staircase
// is that fine only along a stretch of free space about as narrow as the plane's unit, which a
// corridor of exactly the clearance is there, running in a direction the set lacks (a vertical
// one under c:45,135); its links grow with K times the stretch's length (before 2026-12-05,
// `tighten --clearance` to such a set took minutes and tens of GB there, K being up to 8192).
struct StaircaseTooFine : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct StaircaseStats {
  std::int64_t links = 0;          // links that needed a search (not straight)
  std::int64_t states = 0;         // search items expanded (a line entered at a point)
  std::int64_t pieces = 0;         // segments checked against the R-tree (straight links,
                                   // final check)
  std::int64_t lines = 0;          // lines whose crossing candidates were computed
  std::int64_t budget_hits = 0;    // searches stopped by max_work_per_search
  std::int64_t greedy_links = 0;   // links answered by the depth-first fallback (bends not
                                   // proven minimal)
  std::int64_t rejoined = 0;       // tree chains staircased again from the root because their
                                   // joint passed through a pinch (BasicRouter::tree)
};

// One link a -> b: its directions and the fewest bends of a free integer staircase per
// (first direction, last direction); -1 when there is none. A straight link (dx or dy zero,
// or |dx| = |dy| for octilinear) has dirs[0] == dirs[1] and bends 0 when it is free.
struct LinkTable {
  std::array<geom::Point, 2> dirs{};                // unit steps d1, d2
  std::array<std::array<int, 2>, 2> bends{{{-1, -1}, {-1, -1}}};  // [first][last]
  bool complete = true;  // false: a search ran out of budget (entries not proven minimal)
};

class StaircaseBuilder {
 public:
  // Obstacles as geom::normalize_obstacles() returns them; builds an ObstacleIndex.
  StaircaseBuilder(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                   StaircaseOptions options = {});
  ~StaircaseBuilder();
  StaircaseBuilder(StaircaseBuilder&&) noexcept;
  StaircaseBuilder& operator=(StaircaseBuilder&&) noexcept;

  // The rectilinear path: starts at path.front(), ends at path.back(), passes through every
  // point of `path` in order, each link replaced by a monotone staircase; vertices are the
  // bends only (no collinear points). nullopt: the first point is not free, some link has no
  // integer staircase (see Limitation), or even the fallback ran out of budget. Thread-safe
  // (const, no shared caches).
  std::optional<std::vector<geom::Point>> rectilinear(std::span<const geom::Point> path,
                                                      StaircaseStats* stats = nullptr) const;
  // The same with the 8 octilinear directions; length sum of max(|dx|,|dy|) + (sqrt2 - 1) *
  // min(|dx|,|dy|) over the links.
  std::optional<std::vector<geom::Point>> octilinear(std::span<const geom::Point> path,
                                                     StaircaseStats* stats = nullptr) const;
  std::optional<std::vector<geom::Point>> staircase(std::span<const geom::Point> path,
                                                    StaircaseStyle style,
                                                    StaircaseStats* stats = nullptr) const;

  // c-oriented output of a Euclidean taut path (router::c_oriented): `taut` is the shortest path
  // of its class, `cuts` the indices (first 0, last taut.size() - 1) of its points where the
  // tangent is a basis direction (Lemma 6.3), so between two cuts every segment lies strictly
  // inside one cone of the style, or the piece is one segment along a basis direction. Each
  // piece gets the staircase with the fewest links among those of its class (same length, the
  // same side of every blockage; see "One piece of a taut path" in staircase.cpp: exact, no
  // search budget), joined by the DP. nullopt: some piece has no lattice staircase in its class
  // (sloped blockages), or the pieces cannot be joined (pinches at a cut).
  std::optional<std::vector<geom::Point>> staircase_in_class(std::span<const geom::Point> taut,
                                                             std::span<const std::size_t> cuts,
                                                             StaircaseStyle style,
                                                             StaircaseStats* stats = nullptr) const;
  // The same in any lattice direction set (geom/directions.h; the style is rectilinear or
  // octilinear). A cone between the two diagonals (e.g. in c:45,135) has staircases from a only
  // through the lattice points of a's parity (x + y even or odd): a piece whose end is of the
  // other parity has none.
  std::optional<std::vector<geom::Point>> staircase_in_class(std::span<const geom::Point> taut,
                                                             std::span<const std::size_t> cuts,
                                                             const geom::LatticeDirections& set,
                                                             StaircaseStats* stats = nullptr) const;

  // Per-link table (diagnostics and tests).
  LinkTable link_table(geom::Point a, geom::Point b, StaircaseStyle style) const;
  // A point is free: in the domain, in no obstacle's interior, and with a free wedge.
  bool is_free(geom::Point p) const;
  // A path arriving at v from the direction of a and leaving towards b passes through v inside
  // one free wedge (a, b != v): what a joint of two staircases at v must satisfy.
  bool turn_ok(geom::Point a, geom::Point v, geom::Point b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Direction changes along a polyline: geom/predicates.h (the one definition stats use too).
using geom::count_bends;

}  // namespace taut::router
