// Exact (GMP rational) ring predicates for tests that read the Voronoi regions and map cells:
// shared by tests/router/voronoi_test.cpp and tests/cli/voronoi_test.cpp, independent of the
// code under test.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <vector>

namespace taut::test {

struct P2 {
  mpq_class x, y;
};
inline int sgn(const mpq_class& v) { return sgn(v.get_num()); }
inline mpq_class cross(const P2& o, const P2& a, const P2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
// Twice the signed area (positive: counter-clockwise).
inline mpq_class twice_area(const std::vector<P2>& r) {
  mpq_class a = 0;
  for (std::size_t i = 0; i < r.size(); ++i) a += r[i].x * r[(i + 1) % r.size()].y - r[(i + 1) % r.size()].x * r[i].y;
  return a;
}
inline bool on_segment(const P2& a, const P2& b, const P2& q) {
  return sgn(cross(a, b, q)) == 0 && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y);
}
// Any simple ring: 1 inside, 0 on it, -1 outside (crossing number).
inline int in_ring(const std::vector<P2>& r, const P2& q) {
  bool in = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const P2 &a = r[i], &b = r[(i + 1) % r.size()];
    if (on_segment(a, b, q)) return 0;
    if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in ? 1 : -1;
}

}  // namespace taut::test
