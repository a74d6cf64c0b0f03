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

}  // namespace taut::test
