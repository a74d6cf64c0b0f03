// Test support: small random obstacle sets shared by the oracle tests.
#pragma once

#include <random>
#include <vector>

#include "geom/types.h"

namespace taut::test {

// 1 to max_count triangles with vertices drawn uniformly from the closed domain box (std
// uniform_int_distribution on rng, in this order: the count, then x and y of each vertex);
// degenerate ones are dropped, the others made counter-clockwise. Sloped edges that cross at
// non-integer points, touch and pinch: inputs for geom::normalize_obstacles.
std::vector<geom::Polygon> random_triangles(std::mt19937& rng, const geom::Box& domain, int max_count);

// A w x h box that touches box o only at one of its corners (0: NE, 1: NW, 2: SW, 3: SE of o):
// the two make a pinch.
inline geom::Box corner_box(const geom::Box& o, int w, int h, int corner) {
  switch (corner) {
    case 0: return {o.hi, {o.hi.x + w, o.hi.y + h}};
    case 1: return {{o.lo.x - w, o.hi.y}, {o.lo.x, o.hi.y + h}};
    case 2: return {{o.lo.x - w, o.lo.y - h}, o.lo};
    default: return {{o.hi.x, o.lo.y - h}, {o.hi.x + w, o.lo.y}};
  }
}

}  // namespace taut::test
