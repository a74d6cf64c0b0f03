#include "support/random_shapes.h"

#include <algorithm>

#include "geom/predicates.h"

namespace taut::test {

std::vector<geom::Polygon> random_triangles(std::mt19937& rng, const geom::Box& domain, int max_count) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<geom::Polygon> out;
  const int n = uni(1, max_count);
  for (int i = 0; i < n; ++i) {
    geom::Ring r;
    for (int k = 0; k < 3; ++k) r.push_back({uni(domain.lo.x, domain.hi.x), uni(domain.lo.y, domain.hi.y)});
    const auto a = geom::twice_area(r);
    if (a == 0) continue;
    if (a < 0) std::reverse(r.begin(), r.end());
    out.push_back({r, {}});
  }
  return out;
}

}  // namespace taut::test
