// Exact predicates on integer points (no epsilon anywhere).
//
// Proof of exactness in int64: inputs satisfy |v| <= 2^30 - 1, so every coordinate difference
// d satisfies |d| <= 2^31 - 2 and every product of two differences |d1*d2| <= (2^31-2)^2 < 2^62.
// orient() subtracts two such products: |result| < 2^63. Dot products likewise.
// Predicates that multiply three differences (e.g. comparing points on two segments) use
// __int128: |d1*d2*d3| < 2^93.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "geom/types.h"

namespace taut::geom {

using i64 = std::int64_t;
using i128 = __int128;

// Twice the signed area of triangle abc: > 0 left turn (counter-clockwise), < 0 right turn,
// 0 collinear. Exact for inputs within kMaxCoord.
inline constexpr i64 orient(Point a, Point b, Point c) {
  return (i64{b.x} - a.x) * (i64{c.y} - a.y) - (i64{b.y} - a.y) * (i64{c.x} - a.x);
}
inline constexpr int sign(i64 v) { return (v > 0) - (v < 0); }
inline constexpr int sign(i128 v) { return (v > 0) - (v < 0); }
inline constexpr int orientation(Point a, Point b, Point c) { return sign(orient(a, b, c)); }

// Integer division rounded down / up (d > 0), exact for every numerator; C++'s / rounds towards 0.
inline constexpr i128 floor_div(i128 n, i128 d) { return n / d - (n % d != 0 && n < 0); }
inline constexpr i128 ceil_div(i128 n, i128 d) { return -floor_div(-n, d); }

// The multiples of k (k >= 1) next to twice / 2, below and above: the x where two lines meet is
// often a half-integer (twice = 2x), and a router with a lattice takes both neighbours on it
// (equal when twice / 2 is a multiple of k).
inline constexpr std::array<i64, 2> lattice_neighbours(i64 twice, i64 k) {
  return {static_cast<i64>(floor_div(twice, 2 * i128{k})) * k, static_cast<i64>(ceil_div(twice, 2 * i128{k})) * k};
}

// Dot product of (b - a) and (d - c).
inline constexpr i64 dot(Point a, Point b, Point c, Point d) {
  return (i64{b.x} - a.x) * (i64{d.x} - c.x) + (i64{b.y} - a.y) * (i64{d.y} - c.y);
}

// True when p lies on the closed segment ab (ab may be degenerate).
bool on_segment(Point p, Point a, Point b);

// The squared Euclidean distance from p to the closed segment ab (ab may be degenerate), exactly:
// num / den with den > 0 (den = |ab|^2 where the nearest point lies inside ab, else 1). With
// coordinates within kMaxCoord (2^30 - 1): |cross| < 2^63, num < 2^126 and den < 2^63 (beyond
// that the square overflows).
struct SquaredDistance {
  i128 num = 0, den = 1;
};
SquaredDistance point_segment_distance2(Point p, Point a, Point b);

// How two closed segments meet. Either segment may be a single point (a == b): a point on the
// other segment is a Touch, two equal points are a Touch, otherwise None.
enum class SegmentIntersection {
  None,       // disjoint
  Proper,     // cross at a single point interior to both
  Touch,      // meet at a single point that is an endpoint of at least one of them
  Overlap,    // collinear and share more than one point
};
SegmentIntersection intersect(Segment s, Segment t);

// An exact rational point (x_num / den, y_num / den), den > 0; used for constructed points such
// as proper segment crossings. Compare with the functions below, never by converting to double.
struct RationalPoint {
  i128 x_num = 0;
  i128 y_num = 0;
  i128 den = 1;
  bool is_integer() const { return x_num % den == 0 && y_num % den == 0; }
};
// The intersection point of the supporting lines of two non-parallel segments.
// Precondition: orient-based cross product of directions is non-zero.
RationalPoint line_intersection(Segment s, Segment t);

// Where p lies with respect to a closed polygon region.
enum class Location { Outside, Boundary, Inside };
// Location of p relative to the region bounded by a simple ring (either orientation).
Location locate(Point p, std::span<const Point> ring);
// Location of p relative to a polygon with holes (inside the outer ring, outside every hole;
// on the outer ring or on a hole ring inside the outer ring is Boundary).
Location locate(Point p, const Polygon& poly);

// Twice the signed area of a ring (> 0 when counter-clockwise). Exact: the sum of at most
// 2^31 terms each below 2^63 could overflow int64, so it is accumulated in __int128.
i128 twice_area(std::span<const Point> ring);

// Direction changes inside a polyline: a turn or a 180-degree reversal counts one, a collinear
// continuation or a zero-length segment none. Exact (int64 cross and dot products).
std::int64_t count_bends(std::span<const Point> polyline);

}  // namespace taut::geom
