// taut geometry types: integer database units (DBU), exact by construction.
//
// Every coordinate a user writes is an integer with |v| <= kMaxCoord = 2^30 - 1. Under that
// limit a coordinate difference fits in 31 bits and a product of two differences in 62 bits,
// so orientation tests are exact in int64 (see predicates.h for the proof); constructions that
// need more (segment intersection points) use __int128 rationals and never feed a predicate
// unchecked.
#pragma once

#include <compare>
#include <cstdint>
#include <vector>

namespace taut::geom {

using Coord = std::int32_t;
inline constexpr Coord kMaxCoord = (Coord{1} << 30) - 1;  // 1073741823

inline constexpr bool in_range(std::int64_t v) { return v >= -kMaxCoord && v <= kMaxCoord; }

struct Point {
  Coord x = 0;
  Coord y = 0;
  friend constexpr auto operator<=>(const Point&, const Point&) = default;
};

struct Segment {
  Point a;
  Point b;
  friend constexpr bool operator==(const Segment&, const Segment&) = default;
};

// Closed axis-parallel box [lo.x, hi.x] x [lo.y, hi.y].
struct Box {
  Point lo;
  Point hi;
  friend constexpr bool operator==(const Box&, const Box&) = default;
};

// A ring lists its vertices once (no repeated closing vertex).
using Ring = std::vector<Point>;

// A polygon with holes. After normalization (normalize.h) the outer ring is counter-clockwise,
// holes are clockwise, and no ring repeats a vertex consecutively or has collinear vertices.
struct Polygon {
  Ring outer;
  std::vector<Ring> holes;
  friend bool operator==(const Polygon&, const Polygon&) = default;
};

}  // namespace taut::geom
