// Brute-force homotopy classes of paths among obstacles: the reference that tightened wires
// (issue #5) are to be checked against. Independent of the triangulation and the funnel: it
// shares only geom's types with the code under test.
//
// Cuts. Obstacle k's top vertex v is its largest y, then largest x. The cut of k lies on the
// vertical line x = v.x + e (sigma = +1) when an edge of k through v runs to the right of v,
// else on x = v.x - e (sigma = -1), e an infinitesimal, which misses every vertex and every
// vertical edge (all at integer x). It runs up that line from k's topmost crossing of it (on an
// edge through v, so free space lies just above it) to the first obstacle boundary above, or
// to the domain's top side. Every obstacle is then joined to the domain's outer boundary by a
// chain of cuts (each ends on an obstacle whose top is higher), so free space minus the cuts
// is simply connected (a plane region with a connected complement), and the cuts are disjoint
// (each ends at the first boundary above it).
//
// The base is found among all edges of k, not from v's ring neighbours: a normalized outer
// ring is only weakly simple and may pass through v twice (two inputs touching at their top
// vertices are merged into lobes pinched at v), and then the neighbours of one visit of v can
// belong to different lobes and bound a free wedge. (Taking them as the interior's sides once
// threw on such rings, or, with the lobes in the other order, ran the cut from one lobe across
// the notch to the next, so that it never reached the outside and loops around the obstacle
// had the empty word.) The construction does not use the rings' orientation either, and
// repeated (zero-length edges) and collinear vertices change nothing.
//
// Words. A path crossing the cut of obstacle k from left to right writes the letter k + 1,
// from right to left -(k + 1); cancelling adjacent k, -k pairs gives its reduced word. Two paths
// in free space with the same ends are homotopic (ends fixed) iff their reduced words are equal.
// A path touching an obstacle (along an edge, through a vertex) is counted as the free paths
// just off it are: a crossing at exactly the cut's ends counts.
//
// Exactness: a segment crosses the line x = X + sigma e iff its ends lie on both sides (x <= X
// and x >= X + 1 for sigma = +1); its height there is y(X) + sigma s e with s its slope,
// compared lexicographically in GMP rationals.
#pragma once

#include <gmpxx.h>

#include <span>
#include <vector>

#include "geom/types.h"
#include "oracle/qroot3.h"

namespace taut::oracle {

// A point with rational coordinates (minimum-link paths bend at intersections of lines).
struct QPoint {
  mpq_class x, y;
};

class HomotopyWords {
 public:
  // Obstacles as geom::normalize_obstacles() returns them (pairwise disjoint closed sets with
  // weakly simple rings) inside the closed domain; the rings may run in either orientation and
  // hold repeated or collinear vertices. std::invalid_argument when an outer ring is empty or
  // an obstacle's top vertex has only vertical edges (a zero-width spike: no valid polygon).
  HomotopyWords(const geom::Box& domain, std::span<const geom::Polygon> obstacles);
  ~HomotopyWords();
  HomotopyWords(const HomotopyWords&) = delete;
  HomotopyWords& operator=(const HomotopyWords&) = delete;

  // The reduced word of a polyline in free space (consecutive points joined by segments).
  std::vector<int> word(std::span<const geom::Point> path) const;
  // The same for a polyline with rational vertices (the line x = X + sigma e is crossed iff the
  // ends lie on both sides of it: x <= X < x' for sigma = +1, x < X <= x' for sigma = -1).
  std::vector<int> word(std::span<const QPoint> path) const;
  // The same with vertices in Q(sqrt3) (paths in a set at multiples of 30 degrees).
  std::vector<int> word(std::span<const Q3Point> path) const;

  std::size_t cut_count() const;

 private:
  template <class P>
  std::vector<int> word_of(std::span<const P> path) const;
  struct Impl;
  Impl* impl_ = nullptr;
};

}  // namespace taut::oracle
