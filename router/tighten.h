// Homotopic rubber-banding (Hershberger & Snoeyink, seeds/001, sections 2-3): the Euclidean
// shortest path homotopic to a given path among the obstacles, on the free-space triangulation
// (geom/triangulation.h).
//
//   const geom::FreeSpaceTriangulation t = geom::triangulate_free_space(domain, obstacles);
//   const router::Tightener tight(t);
//   router::Tightened r = tight.tighten(sketch);   // sketch: polyline in free space
//   if (r.status == router::TightenStatus::Ok) use(r.points);
//
// The lift (Lemma 2.4 / 3.1). The sketch is walked segment by segment through the triangles it
// meets, with exact int64 orientations only. A segment leaves its current triangle through the
// relative interior of an edge (the free triangle across it is entered; an obstacle edge or the
// domain side there means the sketch leaves free space) or through a vertex v. At a vertex the
// walk turns around v inside the fan of free triangles at v, from the triangle it came in to the
// one whose closed corner holds the outgoing direction, crossing the fan edges between them.
// Every triangulation vertex is an obstacle vertex or a domain corner, so each fan is bounded by
// constrained edges on both sides and the turn within it is unique: that is where a path that
// touches an obstacle, runs along its edge or bends on its corner is counted as the free paths
// just off it are. A direction that lies in no triangle of the current fan leaves free space or
// passes through a point where two blockages touch (FORMAT.md forbids both). The crossed edges
// form a walk in the dual graph; cancelling every immediate back-and-forth leaves the reduced
// walk, which is the path's lift into the universal cover: the sleeve, a sequence of triangles
// each sharing an edge (a portal) with the next.
//
// The funnel (Theorem 3.2). The shortest path from p to q inside the sleeve is found by the
// funnel algorithm in an array deque: the apex, the left chain (bending counter-clockwise) and
// the right chain (bending clockwise). Each portal brings one new vertex on one side; vertices
// it makes redundant are popped from that side's end, and when the side is emptied back to the
// apex the apex moves along the other chain, each move a vertex of the output. Collinear
// vertices are popped (the output never bends by 0 degrees), so every bend of the output is at
// a triangulation vertex with a strict turn. Time is linear in the sleeve (each vertex enters
// and leaves the deque once); space is the sleeve.
//
// The output is the shortest path in the homotopy class of the input with the same ends; for
// polygonal obstacles a locally taut path (each bend on an obstacle vertex, wrapping it) is the
// shortest of its class. Its vertices are the two ends and obstacle vertices (or domain
// corners): integers when the ends are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geom/triangulation.h"
#include "geom/types.h"
#include "router/staircase.h"

namespace taut::geom {
class Root3Directions;
}  // namespace taut::geom

namespace taut::router {

class Root3StaircaseBuilder;  // router/root3_staircase.h
struct Root3Wire;

enum class TightenStatus {
  Ok,
  StartNotFree,   // the first point is in no free triangle
  LeavesFreeSpace,  // a segment enters an obstacle or leaves the domain
  ThroughPinch,     // a segment passes through a point where obstacles touch
};

// Portal i lies between sleeve triangles i and i + 1, its ends seen from triangle i looking
// into triangle i + 1.
struct Portal {
  geom::Point left, right;
};

struct Sleeve {
  std::vector<std::int32_t> triangles;  // at least one when the lift succeeded
  std::vector<Portal> portals;          // triangles.size() - 1 of them
  std::size_t crossings = 0;            // edges crossed by the walk, before cancelling
};

struct Tightened {
  TightenStatus status = TightenStatus::Ok;
  std::size_t segment = 0;          // index of the input segment where the lift failed
  geom::Point where{};              // a point of that segment where it failed (a vertex or its start)
  std::vector<geom::Point> points;  // the shortest homotopic path (status Ok)
  std::size_t sleeve = 0;           // triangles in the sleeve
  std::size_t crossings = 0;        // edges crossed by the input, before cancelling
};

class OnlineTightener;

class Tightener {
 public:
  // The triangulation must outlive the Tightener and be ok().
  explicit Tightener(const geom::FreeSpaceTriangulation& t);

  // The lift of a polyline (consecutive repeated points are ignored). On failure the status
  // says why, with the segment index and a point.
  TightenStatus lift(std::span<const geom::Point> path, Sleeve& sleeve, std::size_t* segment = nullptr,
                     geom::Point* where = nullptr) const;

  // The shortest path from p to q inside the sleeve (p in its first triangle, q in its last).
  std::vector<geom::Point> funnel(geom::Point p, geom::Point q, const Sleeve& sleeve) const;

  // Both: the shortest path homotopic to `path` with the same ends.
  Tightened tighten(std::span<const geom::Point> path) const;

  // The segment pq lies in free space (its lift succeeds; tighten()'s status without the funnel).
  bool free(geom::Point p, geom::Point q) const;

  // Loops (H&S section 5.1, orientable bands: free space in the plane). `loop` is a closed
  // polyline (its last point equals its first). Its lift from the first point back to it is
  // closed up at that point (turning inside the fan when it is a vertex) and reduced cyclically
  // (Lemma 5.1): what remains is the band, the cycle of triangles every loop of the free
  // homotopy class crosses. Empty when the loop can be pulled to a point (contractible).
  TightenStatus band(std::span<const geom::Point> loop, std::vector<std::int32_t>& cycle,
                     std::size_t* segment = nullptr, geom::Point* where = nullptr) const;

  // The shortest closed loop freely homotopic to `loop` (the base point may move). Theorem 5.4:
  // for each end s of the band's first portal, the funnel's shortest path from s around the
  // band twice back to s; a vertex it visits twice bounds a loop around the band once. A
  // candidate is accepted only when it is certified exactly: its band equals the input's (up to
  // rotation), and it is taut at every vertex (tightening it from two different base points gives
  // it back), which for polygonal obstacles makes it a shortest loop of the class. Candidates
  // are tried shortest first. `points` is closed (front == back); empty with status Ok when the
  // loop is contractible (`contractible`).
  struct Loop {
    TightenStatus status = TightenStatus::Ok;
    std::size_t segment = 0;
    geom::Point where{};
    bool contractible = false;
    std::vector<geom::Point> points;
    std::size_t band = 0;  // triangles in the band
  };
  Loop tighten_loop(std::span<const geom::Point> loop) const;

  const geom::FreeSpaceTriangulation& triangulation() const { return *t_; }

 private:
  friend class OnlineTightener;
  struct Walker;
  // The portals between consecutive triangles (neighbours) of a sleeve.
  std::vector<Portal> portals_of(const std::vector<std::int32_t>& triangles) const;
  const geom::FreeSpaceTriangulation* t_;
  std::vector<std::int32_t> fan_start_;  // CSR: triangles incident to each vertex
  std::vector<std::int32_t> fan_;
};

// On-line tightening (H&S section 3.2): a sketch given point by point, whose shortest homotopic
// path is kept up to date. The walk through the triangles is the lift's (above); every triangle
// it pushes on the sleeve brings a portal and one funnel Add, every triangle it pops (the sketch
// going back the way it came) one Undo. The funnel is the array deque of the off-line algorithm
// with a history: an Add finds where the new vertex's tangent meets the funnel by binary search
// over the chains (the Split: the edges that the new vertex makes redundant form a run at the
// end of the chain walked from its tip past the apex), moves the end of that side (and the
// apex, copying the vertices it passes to the path), and writes the vertex into one array slot;
// the history keeps the old ends, apex, path length and the overwritten slot, so Undo restores
// them in O(1). Per triangle crossed: O(log n) plus the vertices the apex passes (each copied
// once per Add; forward-only sketches copy each output vertex once). path() adds the current
// point to the funnel, reads the path and undoes that, so it costs the path's length plus a
// binary search. It returns exactly what Tightener::tighten() returns for the points so far.
class OnlineTightener {
 public:
  // Starts a sketch at `start`; status() says whether that is a free point.
  OnlineTightener(const Tightener& t, geom::Point start);
  ~OnlineTightener();
  OnlineTightener(const OnlineTightener&) = delete;
  OnlineTightener& operator=(const OnlineTightener&) = delete;

  TightenStatus status() const;
  // The sketch goes on straight to q. On failure (the segment leaves free space or passes a
  // pinch; *where a point of it) nothing changes.
  TightenStatus extend(geom::Point q, geom::Point* where = nullptr);
  // The shortest path homotopic to the sketch so far (start to the current point).
  std::vector<geom::Point> path() const;
  geom::Point end() const;
  std::size_t sleeve() const;  // triangles in the current sleeve

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// c-oriented output (H&S section 6) for the lattice direction sets (rectilinear, octilinear and
// the other subsets of 0, 45, 90 and 135 degrees: geom/directions.h), with integer vertices. The Euclidean shortest path of a class is also the shortest in it under
// every convex distance function (Theorem 6.2), so its L1 (octilinear) length is the least of
// the class, and every least path passes through the points where the Euclidean path's tangent
// is a basis direction (Lemma 6.3): its vertices where consecutive links are not strictly
// inside one cone between neighbouring directions, and the ends of links along a direction.
// Between two such cuts the links all lie strictly inside one cone, so the least paths there
// are the monotone staircases of that cone's two directions (Lemma 6.1) that pass every
// blockage on the side the Euclidean path does; StaircaseBuilder::staircase_in_class builds the
// one with the fewest links per piece (section 6.4's sweep of fixed orientations, exact) and
// joins the pieces with the fewest links. The result is checked to tighten back to `taut`.
// Empty when some piece has no lattice staircase in its class (sloped blockages can pinch
// every one).
struct COriented {
  std::vector<geom::Point> points;  // empty: no staircase in the class was found; else the
                                    // fewest links of the class's shortest c-oriented paths
};
COriented c_oriented(const Tightener& tight, const StaircaseBuilder& sb, std::span<const geom::Point> taut,
                     StaircaseStyle style);
// The same for any lattice direction set (geom/directions.h): c:0,45, c:45,135, c:0,45,90, ...
// Either throws StaircaseTooFine when sb was built with StaircaseOptions::snap_scale > 1 (staircase.h).
COriented c_oriented(const Tightener& tight, const StaircaseBuilder& sb, std::span<const geom::Point> taut,
                     const geom::LatticeDirections& set);
// The same for a set at multiples of 30 degrees (router/root3_staircase.h): the builder's exact
// wire rounded to integer vertices, its free test the Tightener's lift, and the rounded wire
// tightened back to `taut` (free and in the class, as above); `why` says what failed.
Root3Wire c_oriented(const Tightener& tight, const Root3StaircaseBuilder& sb, std::span<const geom::Point> taut,
                     const geom::Root3Directions& set);

// Where a taut wire must be cut for output in a direction set (Lemma 6.3: every shortest wire in
// the set passes through its points whose tangent is a direction of the set): the indices of
// its first and last vertices and of every vertex whose two segments are not strictly inside one
// cone of the set. Set: geom::LatticeDirections or geom::Root3Directions (their cone()).
template <class Set>
std::vector<std::size_t> tangent_cuts(std::span<const geom::Point> taut, const Set& set) {
  auto cone_of = [&](geom::Point a, geom::Point b) {
    return set.cone(std::int64_t{b.x} - a.x, std::int64_t{b.y} - a.y);
  };
  std::vector<std::size_t> cuts{0};
  for (std::size_t i = 1; i + 1 < taut.size(); ++i) {
    const int c0 = cone_of(taut[i - 1], taut[i]), c1 = cone_of(taut[i], taut[i + 1]);
    if (c0 < 0 || c1 < 0 || c0 != c1) cuts.push_back(i);
  }
  if (taut.size() > 1) cuts.push_back(taut.size() - 1);
  return cuts;
}

// Euclidean length of a polyline (double sum of exact-input square roots).
double euclidean_length(std::span<const geom::Point> path);

// A person's words for a status.
std::string tighten_status_text(TightenStatus s);

}  // namespace taut::router
