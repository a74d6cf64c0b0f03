// Free-space constrained triangulation: triangles covering exactly domain minus obstacles.
//
// A constrained Delaunay triangulation (CGAL, inside triangulation.cpp only) of the domain
// corners and every obstacle vertex, with every obstacle edge and the domain boundary as
// constraints. Faces are classified by the direction of the constraint edges, never by parity
// of crossings (parity breaks where an obstacle edge runs along the domain boundary): the face
// left of a directed ring edge (outer CCW, hole CW) is inside that obstacle, the face right of it
// is free (or outside the domain when the edge lies on the domain boundary); the labels are then
// flood-filled across unconstrained edges. A face reached with two different labels means the
// input breaks the contract below and is reported, never guessed.
//
//   FreeSpaceTriangulation t = triangulate_free_space(domain, obstacles);
//   if (!t.ok()) return t.diagnostics();          // GEOM-0040 .. GEOM-0046
//   for (const FreeTriangle& tri : t.triangles()) ...  // tri.v indexes t.vertices()
//   if (auto i = t.locate({x, y})) ...            // a free triangle containing (x, y)
//
// Input contract: `domain` has lo < hi on both axes; every obstacle is a Polygon with integer
// vertices within kMaxCoord, outer ring counter-clockwise, holes clockwise, at least 3 vertices
// per ring; the closed obstacles are pairwise disjoint and lie in the closed domain (they may
// touch or run along the domain boundary); rings never cross or overlap along an edge and may
// touch themselves or each other only at shared vertices (weakly simple rings, e.g. where a
// union pinches). A hole may contain other obstacles. Tolerated beyond the contract: collinear
// consecutive vertices, repeated consecutive vertices, obstacles touching at a point.
//
// Exactness: CGAL's Exact_predicates_inexact_constructions_kernel decides every orientation and
// in-circle test exactly (coordinates below 2^30 are exact doubles). No point is ever
// constructed: every triangulation vertex is verified to be an input vertex (a crossing of
// constraints would create one: GEOM-0043). Everything exposed here is integer data.
//
// Cost: O(n log n) expected to build (spatially sorted insertion), n = number of vertices;
// locate() is a CGAL walk starting from a face of a coarse bucket grid (about 4 vertices per
// cell): O(1) expected steps for evenly spread vertices, O(sqrt n) in the worst spread.
// Measured (Release, 2 shared cores, disjoint random rectangles, CPU time): 10^4 / 10^5 / 10^6
// obstacle vertices build in 0.02 / 0.23 / 2.7 s; a random locate takes about 1 us.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geom/diagnostic.h"
#include "geom/types.h"

namespace taut::geom {

// Values of FreeTriangle::constraint[i].
inline constexpr std::int32_t kUnconstrained = -2;  // an ordinary edge between free triangles
inline constexpr std::int32_t kDomainEdge = -1;     // a piece of the domain boundary
// (a value k >= 0 means: a piece of an edge of obstacles[k])

struct FreeTriangle {
  std::array<std::int32_t, 3> v;           // vertex indices, counter-clockwise
  // Edge i runs from v[i] to v[(i + 1) % 3].
  std::array<std::int32_t, 3> neighbor;    // free triangle across edge i, -1 when constrained
  std::array<std::int32_t, 3> constraint;  // kUnconstrained, kDomainEdge or an obstacle index
};

class FreeSpaceTriangulation {
 public:
  FreeSpaceTriangulation();  // empty, ok()
  ~FreeSpaceTriangulation();
  FreeSpaceTriangulation(FreeSpaceTriangulation&&) noexcept;
  FreeSpaceTriangulation& operator=(FreeSpaceTriangulation&&) noexcept;

  // False when the input broke the contract; then diagnostics() says why and there are no
  // triangles.
  bool ok() const;
  const std::vector<Diagnostic>& diagnostics() const;

  const Box& domain() const;
  // Distinct input points (domain corners and obstacle vertices), sorted by (x, y).
  const std::vector<Point>& vertices() const;
  // Only free triangles: their union is exactly the closed domain minus the obstacles'
  // interiors (up to boundaries), their interiors are disjoint.
  const std::vector<FreeTriangle>& triangles() const;

  // A free triangle containing p (closed triangle), or nullopt when no free triangle contains
  // p: p outside the domain, in an obstacle's interior, or on an obstacle boundary that has no
  // free space next to it (e.g. along the domain boundary). When p lies on an edge or vertex
  // shared by several free triangles, the one with the smallest index is returned. Exact.
  // The walk starts from a bucket grid's face near p; the overload walks from `hint` (a
  // triangle index, e.g. the previous answer), which costs O(distance) in triangles.
  // Thread-safe (CGAL's walk keeps a random generator; calls are serialized by a mutex).
  std::optional<std::int32_t> locate(Point p) const;
  std::optional<std::int32_t> locate(Point p, std::int32_t hint) const;

  // Validation on the plain data (no CGAL), O(n) expected: every triangle is counter-clockwise
  // and non-degenerate; adjacency is symmetric and only across unconstrained edges; twice the
  // free area, in __int128, equals twice the domain area minus the twice-areas of the
  // obstacles; every obstacle edge off the domain boundary is the union of constrained free
  // triangle edges owned by that obstacle (traversed the other way); the domain boundary is
  // tiled exactly by domain edges of free triangles and obstacle edges lying on it; no other
  // constrained edge exists. Returns the problems found, empty when valid.
  std::vector<std::string> check() const;

  struct Impl;  // opaque: holds the CGAL triangulation (kept alive for locate())

 private:
  std::unique_ptr<Impl> impl_;
  friend FreeSpaceTriangulation triangulate_free_space(const Box&, std::span<const Polygon>);
};

// The triangles incident to each vertex, in compressed rows: vertex v's are
// triangles[start[v] .. start[v + 1]), in increasing index order.
struct VertexFans {
  std::vector<std::int32_t> start;      // vertices().size() + 1 offsets
  std::vector<std::int32_t> triangles;  // triangle indices
};
VertexFans vertex_fans(const FreeSpaceTriangulation& t);

// Triangulates domain minus the obstacles (see the contract above). Diagnostics:
//   GEOM-0040  the domain box is empty or degenerate, or a coordinate exceeds kMaxCoord
//   GEOM-0041  a ring has fewer than 3 vertices, or the wrong orientation (outer ring not
//              counter-clockwise, hole not clockwise), or zero area
//   GEOM-0042  an obstacle vertex lies outside the closed domain
//   GEOM-0043  obstacle edges cross (a constraint intersection would create a new vertex)
//   GEOM-0044  contradictory classification: obstacles overlap or are nested without a hole,
//              an edge is shared by two rings, a ring has a zero-width spike, or an obstacle
//              lies outside the domain along its boundary
//   GEOM-0045  the free area does not add up (input breaking the contract in a way not caught
//              above)
//   GEOM-0046  CGAL reported a failure (should not happen on valid input)
FreeSpaceTriangulation triangulate_free_space(const Box& domain,
                                              std::span<const Polygon> obstacles);

}  // namespace taut::geom
