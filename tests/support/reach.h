// Whether the sources reach all of free space, by a brute-force reference: every obstacle vertex
// and domain corner that is free is reached from some source, and no vertex is a pinch (two
// wedges; else a walled-in component could hide behind a reached wedge of the same point). For
// the cell tests, where the cells' total area must then be the free area. Ref: any reference
// of tests/oracle/ (distances(), is_free(), wedges_at()).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "geom/types.h"

namespace taut::test {

// The cell-lattice references' wedges at a lattice point: given whether each of the four unit
// cells around it (NE, NW, SW, SE) is free, a label per cell, equal for free cells joined
// through a shared free side (the 4-cycle of cells), -1 for a blocked cell.
inline std::array<int, 4> cell_wedge_labels(const std::array<bool, 4>& f) {
  std::array<int, 4> label = {-1, -1, -1, -1};
  for (int i = 0; i < 4; ++i)
    if (f[i]) label[i] = i;
  for (int round = 0; round < 2; ++round)  // twice around the 4-cycle suffices
    for (int i = 0; i < 4; ++i) {
      const int j = (i + 1) % 4;
      if (f[i] && f[j]) label[i] = label[j] = std::min(label[i], label[j]);
    }
  return label;
}

// Every ring vertex of the obstacles (outer rings and holes, in ring order; repeats kept).
inline std::vector<geom::Point> obstacle_vertices(const std::vector<geom::Polygon>& obstacles) {
  std::vector<geom::Point> vs;
  for (const auto& p : obstacles) {
    vs.insert(vs.end(), p.outer.begin(), p.outer.end());
    for (const auto& h : p.holes) vs.insert(vs.end(), h.begin(), h.end());
  }
  return vs;
}

template <class Ref>
bool all_free_space_reached(const Ref& ref, const geom::Box& D, const std::vector<geom::Polygon>& obstacles,
                            const std::vector<geom::Point>& sources) {
  using geom::Point;
  std::vector<Point> vs = obstacle_vertices(obstacles);
  for (Point corner : {D.lo, D.hi, Point{D.lo.x, D.hi.y}, Point{D.hi.x, D.lo.y}}) vs.push_back(corner);
  std::vector<bool> reached(vs.size(), false);
  for (Point s : sources) {
    const auto d = ref.distances(s, vs);
    for (std::size_t i = 0; i < vs.size(); ++i) reached[i] = reached[i] || d[i].has_value();
  }
  for (std::size_t i = 0; i < vs.size(); ++i)
    if (!(reached[i] || !ref.is_free(vs[i])) || ref.wedges_at(vs[i]).size() > 1) return false;
  return true;
}

}  // namespace taut::test
