// Brute-force exact bend-aware rectilinear paths among rectilinear obstacles: the reference
// router::BendRouter (router/bend_router.h) is checked against. It shares no code with the
// router: the free-space rules come from the L1 reference (l1_oracle.h: wedges_at, visible),
// itself test code that reads only the obstacle rings and geom/predicates.h.
//
// Cost of a rectilinear path: its L1 length and its bends (direction changes; a path never
// reverses on itself). Combined metric: minimise length + C * bends, ties broken by fewer
// bends. Link metric: minimise bends, ties broken by shorter length. Either way the optimum
// (length, bends) is unique, so the router's answer must equal it exactly.
//
// Free space: exactly that of the L1 reference (see its header): the closed domain minus the
// open obstacles; a path may run along obstacle edges and turn at their vertices, but at every
// point it passes through or turns at, the direction back along the path and the direction on
// must lie in ONE wedge of that point (no slipping between blockages that touch at a corner); an
// obstacle edge flush on the domain side is not free; a query point at a pinch may start or end
// in any of its wedges.
//
// Method: Dijkstra on a state graph. The grid is the Hanan grid of every obstacle vertex x and
// y, the domain sides, s and t; a state is a grid point with the direction the path arrived in
// (E, N, W, S) or the start state at s. From (p, d_in) the path may step to the next grid point
// q in any direction d that is not the reverse of d_in, when the segment pq is free
// (L1Reference::visible) and, unless p is s at the start, the directions -d_in and d lie in one
// wedge of p; the step costs |pq| and one bend when d != d_in. Costs are compared as the pair
// (length + C * bends, bends) or (bends, length), lexicographically: both orders are translation
// invariant on Z^2 and every step is >= (0, 0) in them, so Dijkstra is exact.
//
// Why the Hanan grid is enough. Some optimal path has every link but the first and the last
// touching an obstacle vertex (slide a middle link that touches none, keeping its neighbours'
// lines, until it does or a neighbouring link vanishes: length + C * bends and bends never grow,
// as the length is linear in the slide; de Berg et al., Lemma 2.1). So every link lies on a grid
// line through s, t or a vertex, every turn is at a crossing of two such lines, and the path is a
// walk of the state graph. Conversely every walk is a legal path with exactly the walk's cost
// (a walk that stops without turning at a grid point costs no bend there). The oracle test checks
// the claim against the same search on the full integer lattice.
//
// Not thread-safe: the L1 reference it builds on appends to its problems() in const queries, and
// the wedges of grid points and the freedom of grid steps are memoized across queries (pure
// functions of the points: the grid lines of s and t differ from query to query, the others not).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <span>
#include <vector>

#include "geom/types.h"
#include "oracle/l1_oracle.h"

namespace taut::oracle {

struct BendAnswer {
  std::int64_t length = 0;
  std::int64_t bends = 0;
  friend bool operator==(const BendAnswer&, const BendAnswer&) = default;
};

class BendReference {
 public:
  // Obstacles as geom::normalize_obstacles() returns them, every edge horizontal or vertical.
  BendReference(const geom::Box& domain, std::span<const geom::Polygon> obstacles);

  // The optimum (length, bends) from s to t: link == false is the combined metric with bend cost
  // C >= 0, link == true the link metric (C ignored). nullopt when s or t is not free or t is
  // unreachable; {0, 0} when s == t is free.
  std::optional<BendAnswer> best(geom::Point s, geom::Point t, bool link, std::int64_t C) const;
  // The same search with grid lines at every integer x and y of the domain as well as the
  // Hanan lines (small integer domains only): equal to best() when the Hanan grid is enough.
  std::optional<BendAnswer> best_on_lattice(geom::Point s, geom::Point t, bool link,
                                            std::int64_t C) const;

  // The best from any point of S to any point of T (free ones; nullopt when S or T has none or
  // no target is reached; {0, 0} when they share a free point), on the lattice as
  // best_on_lattice(): a path may start in any direction at every point of S.
  std::optional<BendAnswer> best_between_on_lattice(std::span<const geom::Point> S,
                                                    std::span<const geom::Point> T, bool link,
                                                    std::int64_t C) const;

  // The L1 length and bends of a path (its points, consecutive repeats ignored) when every
  // segment is horizontal or vertical, the path never reverses on itself (a 180 degree turn is
  // rejected) and the whole path is legal under the free-space rules above; else nullopt. A bend
  // is a change of direction between consecutive segments (a point in the middle of a straight
  // run is not one). {s} alone: {0, 0} when s is free.
  std::optional<BendAnswer> check_path(std::span<const geom::Point> path) const;

  const L1Reference& l1() const { return ref_; }

 private:
  std::optional<BendAnswer> search(std::span<const geom::Point> S, std::span<const geom::Point> T, bool link,
                                   std::int64_t C, bool lattice) const;

  const std::vector<Wedge>& wedges_at(geom::Point p) const;
  bool step_free(geom::Point a, geom::Point b) const;  // L1Reference::visible(a, b)

  geom::Box domain_;
  std::vector<geom::Coord> xs_, ys_;  // obstacle vertex and domain side coordinates
  L1Reference ref_;
  mutable std::map<geom::Point, std::vector<Wedge>> wedges_;
  mutable std::map<std::pair<geom::Point, geom::Point>, bool> steps_;
};

}  // namespace taut::oracle
