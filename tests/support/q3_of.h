// The router's numbers in Q(sqrt3) (router::RationalRoot3, router::R3Point) as the references'
// own (oracle::Q3, gmpxx), through their decimal text, so a test judges the router's exact
// output in arithmetic it does not share with it.
#pragma once

#include <gmpxx.h>

#include <string>
#include <vector>

#include "oracle/qroot3.h"
#include "geom/root3.h"
#include "geom/root3_directions.h"
#include "router/rational_root.h"

namespace taut::test {

inline oracle::Q3 q3of(const router::RationalRoot3& v) {
  mpq_class a(v.a.str()), b(v.b.str());
  a.canonicalize();
  b.canonicalize();
  return {a, b};
}
inline oracle::Q3Point q3of(const router::R3Point& p) { return {q3of(p.x), q3of(p.y)}; }
inline oracle::Q3 q3of(const geom::Root3& r) { return {mpq_class(r.a), mpq_class(r.b)}; }
inline oracle::Q3Point q3of(const geom::Root3Directions::Step& s) { return {q3of(s.x), q3of(s.y)}; }

}  // namespace taut::test
