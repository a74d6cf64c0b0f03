// Brute-force references for minimum-link paths (issue #5, Hershberger & Snoeyink section 4),
// independent of the triangulation and of router::MinLinker: they read only the obstacle rings
// and compute in GMP rationals (gmpxx).
//
// segment_free: a closed segment with rational ends lies in the closed free space (the domain
// minus the obstacles' interiors; touching a boundary is allowed). The segment is cut at every
// point where it meets an obstacle edge (or where an edge on its line begins or ends); every
// piece between two cuts is then either inside an obstacle or not, decided at its midpoint. A
// segment that passes through an obstacle vertex with material on both sides of it (edges leaving
// on both sides, or an edge along it with its material on the other side) is not free either: it
// enters material there, or slips between blockages that touch (FORMAT.md).
//
// LinkSearch: the fewest links of a path from p to q in a given homotopy class (reduced cut word,
// oracle/homotopy.h) whose links lie on candidate lines: the first through p and another
// candidate point, the last through q and another, the middle ones through two candidate points,
// where the candidate points are p, q and the obstacle vertices. Exhaustive over those lines for
// up to three links. Every path it finds is a real path of the class, so its count bounds the
// minimum from above: a router that needs more links than it finds is wrong. Minimum-link paths
// whose links are not on such lines (a link from the end of another link's extension) are
// outside it, so finding none proves nothing.
#pragma once

#include <gmpxx.h>

#include <functional>
#include <span>
#include <vector>

#include "geom/types.h"
#include "oracle/homotopy.h"
#include "oracle/qroot3.h"

namespace taut::oracle {

bool segment_free(const QPoint& a, const QPoint& b, const geom::Box& domain,
                  std::span<const geom::Polygon> obstacles);
// The same with ends in Q(sqrt3) (paths in a set at multiples of 30 degrees).
bool segment_free(const Q3Point& a, const Q3Point& b, const geom::Box& domain,
                  std::span<const geom::Polygon> obstacles);

class LinkSearch {
 public:
  LinkSearch(const geom::Box& domain, std::span<const geom::Polygon> obstacles, const HomotopyWords& words);
  // The fewest links (1 .. max_links <= 3) of a candidate-line path from p to q with word
  // `word`, with that path in `path`; 0 when there is none within max_links.
  int fewest(geom::Point p, geom::Point q, const std::vector<int>& word, int max_links,
             std::vector<QPoint>* path = nullptr) const;
  bool path_ok(const std::vector<QPoint>& path, const std::vector<int>& word) const;
  // Closed paths: whether a triangle (three links, the fewest any loop around something can
  // have) whose sides lie on candidate lines (through two of the obstacle vertices and the
  // domain's corners) is free and `in_class` (the caller's test of its free homotopy class; the
  // triangle is given closed, front == back); the first found goes to `loop`. Finding none
  // proves nothing (a minimum-link loop's links need not lie on such lines).
  bool triangle_loop(const std::function<bool(const std::vector<QPoint>&)>& in_class,
                     std::vector<QPoint>* loop = nullptr) const;

 private:
  geom::Box domain_;
  std::vector<geom::Polygon> obstacles_;
  std::vector<geom::Point> vertices_;
  const HomotopyWords& words_;
};

}  // namespace taut::oracle
