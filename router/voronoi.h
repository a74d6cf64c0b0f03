// The L1 geodesic Voronoi diagram of point sites among polygonal obstacles: the cells of the
// shortest path map (router/spm.h) merged by source, as polygons with holes and exact
// rational vertices (Mitchell §5; Chen & Wang §1.3).
//
//   L1Map map(norm.domain, norm.obstacles, sites);
//   for (const VoronoiRegion& r : l1_voronoi(map)) r.site, r.polygons, r.area;
//
// A region is every free point whose nearest site (by L1 geodesic distance) is r.site; a point
// at equal distance from several sites goes where L1Map::locate() sends it (the tie rule of
// spm.h), so the regions never overlap. L1 bisectors can be two-dimensional (two sites on a
// diagonal tie on whole quadrants); such areas go to one site by that same rule. Points no site
// reaches (walled in) are in no region.
//
// How. The map's convex pieces of one site are joined by cancelling the boundary they share:
// the piece edges are grouped by their supporting line, and along each line the signed
// coverage (+1 for an edge with the site on its left, -1 on its right) is summed; what is left
// is the region's boundary, split where it changes. Those segments are linked into rings,
// turning as sharply left as possible at a vertex where a region touches itself (so every ring
// is simple); counter-clockwise rings are outer boundaries, clockwise ones holes, each hole
// given to the smallest outer ring that contains it. Everything is exact (Rational).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "router/spm.h"

namespace taut::router {

struct RPolygon {
  std::vector<RPoint> outer;               // counter-clockwise
  std::vector<std::vector<RPoint>> holes;  // clockwise
};

struct VoronoiRegion {
  std::size_t site = 0;  // the source index (position in the sources given to L1Map)
  std::vector<RPolygon> polygons;
  Rational area;  // exact
};

// One region per site that reaches some area, in site order (sites at one point: the least
// index has the region). A shape site's region holds the shape as well.
std::vector<VoronoiRegion> l1_voronoi(const L1Map& map);
// The same from map.pieces(L1Map::Detail::BySource), for a caller that already has them.
std::vector<VoronoiRegion> l1_voronoi(std::span<const L1Map::Piece> by_source);

}  // namespace taut::router
