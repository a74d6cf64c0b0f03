// Brute-force homotopy classes of paths among obstacles: the reference that tightened wires
// (issue #5) are to be checked against. Independent of the triangulation and the funnel: it
// shares only geom's types with the code under test.
//
// Cuts. Obstacle k's top vertex v is its largest y, then largest x. Just below v the
// obstacle's interior meets the vertical line x = v.x + e (sigma = +1: the edge from v to its
// ring predecessor runs right and down) or else x = v.x - e (sigma = -1), e an infinitesimal,
// which misses every vertex and every vertical edge (all at integer x). The cut of k runs up
// that line from where it leaves k's boundary to the first obstacle boundary above, or to the
// domain's top side. Every obstacle is then joined to the domain's outer boundary by a chain
// of cuts, so free space minus the cuts is simply connected (a plane region with a connected
// complement), and the cuts are disjoint (each ends at the first boundary above it).
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

namespace taut::oracle {

// A point with rational coordinates (minimum-link paths bend at intersections of lines).
struct QPoint {
  mpq_class x, y;
};

class HomotopyWords {
 public:
  // Obstacles as geom::normalize_obstacles() returns them (outer rings counter-clockwise,
  // holes clockwise, pairwise disjoint closed sets) inside the closed domain.
  HomotopyWords(const geom::Box& domain, std::span<const geom::Polygon> obstacles);
  ~HomotopyWords();

  // The reduced word of a polyline in free space (consecutive points joined by segments).
  std::vector<int> word(std::span<const geom::Point> path) const;
  // The same for a polyline with rational vertices (the line x = X + sigma e is crossed iff the
  // ends lie on both sides of it: x <= X < x' for sigma = +1, x < X <= x' for sigma = -1).
  std::vector<int> word(std::span<const QPoint> path) const;

  std::size_t cut_count() const;

 private:
  template <class P>
  std::vector<int> word_of(std::span<const P> path) const;
  struct Impl;
  Impl* impl_;
};

}  // namespace taut::oracle
