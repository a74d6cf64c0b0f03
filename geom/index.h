// ObstacleIndex: the edges of a set of obstacle polygons in Boost.Geometry R-trees (packed
// construction), answering exact ray shooting in the 8 directions and box queries.
//
//   ObstacleIndex index(obstacles);
//   RayHit h = index.shoot({0, 0}, Direction::NE);
//   if (h.hit()) { /* first point p + t*d, t = h.t.num / h.t.den; edges h.edges */ }
//
// Ray semantics (all exact; closed edges; d = step(dir) in {-1,0,1}^2):
//   - The ray is {p + t d : t >= 0}. An edge's hit parameter is the smallest t >= 0 with
//     p + t d on the closed edge. shoot() returns the minimal hit parameter over all edges and
//     EVERY edge attaining it (sorted by id), so a ray through a vertex returns both edges that
//     share it, and a ray through a point where obstacles touch returns all of them.
//   - A start point lying on an edge hits that edge at t = 0 (unless RayOptions::
//     ignore_edges_at_start, which drops every edge containing p from consideration).
//   - A ray running along a collinear edge hits it at the edge's nearest point (t = 0 when the
//     edge contains p).
//   - Zero-length edges (repeated vertices) are not indexed: their point belongs to the
//     neighbouring edges anyway.
// t is rational only for diagonal rays; for E/N/W/S it is an integer (den = 1).
//
// Cost: a ray probes the R-tree in windows of geometrically growing length along the ray
// (diagonal rays use a second R-tree in the rotated frame u = x + y, v = y - x, where they are
// axis-parallel), so only edges whose bounding boxes meet the ray near the answer are tested.
// Each R-tree is built by the first query that needs it (once, thread-safe), and the first 16
// sorted box queries read every edge instead, so an index asked about a few points only costs
// its list of edges.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "geom/predicates.h"
#include "geom/types.h"

namespace taut::geom {

enum class Direction : std::uint8_t { E, NE, N, NW, W, SW, S, SE };
inline constexpr Direction kAllDirections[] = {Direction::E, Direction::NE, Direction::N,
                                               Direction::NW, Direction::W, Direction::SW,
                                               Direction::S, Direction::SE};
// The unit step (dx, dy) of a direction, e.g. NE = (1, 1).
inline constexpr Point step(Direction d) {
  constexpr Point kSteps[] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  return kSteps[static_cast<int>(d)];
}

// An exact non-negative rational num / den with den > 0 (not necessarily reduced).
struct Rational {
  i64 num = 0;
  i64 den = 1;
};
// Sign of a - b, exact (__int128 cross-multiplication).
inline int compare(Rational a, Rational b) {
  return sign(i128{a.num} * b.den - i128{b.num} * a.den);
}

// Where an indexed edge came from: ring[vertex] -> ring[(vertex + 1) % size] of obstacle
// `polygon`, ring -1 = outer ring, k >= 0 = hole k.
struct EdgeRef {
  std::uint32_t polygon = 0;
  std::int32_t ring = -1;
  std::uint32_t vertex = 0;
};

struct RayHit {
  Rational t;                         // meaningful when hit()
  std::vector<std::uint32_t> edges;   // every edge hit at t, ascending ids; empty = no hit
  bool hit() const { return !edges.empty(); }
};

struct RayOptions {
  bool ignore_edges_at_start = false;  // drop edges that contain the start point
};

// The exact point p + t d.
inline RationalPoint ray_point(Point p, Direction dir, Rational t) {
  const Point d = step(dir);
  return {i128{p.x} * t.den + i128{d.x} * t.num, i128{p.y} * t.den + i128{d.y} * t.num,
          i128{t.den}};
}

class ObstacleIndex {
 public:
  explicit ObstacleIndex(std::span<const Polygon> obstacles);
  ~ObstacleIndex();
  ObstacleIndex(ObstacleIndex&&) noexcept;
  ObstacleIndex& operator=(ObstacleIndex&&) noexcept;

  std::size_t edge_count() const { return edges_.size(); }
  const Segment& edge(std::uint32_t id) const { return edges_[id]; }
  const EdgeRef& edge_ref(std::uint32_t id) const { return refs_[id]; }

  // First edge(s) hit by the ray from p in direction dir (semantics above).
  RayHit shoot(Point p, Direction dir, RayOptions options = {}) const;
  // Ids (ascending) of the edges whose closed segment meets the closed box.
  std::vector<std::uint32_t> edges_in_box(const Box& box) const;
  // The same ids, unsorted, into `out` (cleared first; its capacity is reused, so a caller in
  // a hot loop allocates nothing).
  void edges_in_box(const Box& box, std::vector<std::uint32_t>& out) const;

 private:
  struct Trees;
  void build_axis() const;  // the (x, y) R-tree, once (thread-safe)
  std::vector<Segment> edges_;
  std::vector<EdgeRef> refs_;
  std::unique_ptr<Trees> trees_;
};

}  // namespace taut::geom
