// Lattice direction sets: the wire directions a c-oriented output may use when its vertices are
// integers. A direction with an integer step is one of the eight at multiples of 45 degrees (the
// tangent of a rational number of degrees is rational only at multiples of 45), so the sets that
// can be written with integer vertices are the subsets of {0, 45, 90, 135} (modulo 180 degrees:
// a wire runs both ways along an orientation) with at least two orientations: rectilinear
// {0, 90}, octilinear {0, 45, 90, 135}, and the nine others such as c:0,45 or c:45,135.
//
//   auto d = geom::LatticeDirections::parse("c:0,45,180");   // E, NE, W, SW
//   int c = d->cone(1, 3);                // the open cone between NE and W: 1
//   geom::Root2 len = d->length2(1, 3);   // twice the length of the shortest path in the set
//
// Cones. The steps are the set's unit lattice vectors counter-clockwise from +x; cone i is the
// open angle from step i to step i + 1. A cone spans 45, 90 or 135 degrees (never 180: the set
// holds two orientations at least). Its two steps d1, d2 have cross(d1, d2) = 1, except between
// the two diagonals (e.g. NE and NW in c:45,135), where it is 2: a path along d1 and d2 from a
// lattice point only reaches the points a + u d1 + v d2 with integer u and v, half of the lattice
// (those with the same parity of x + y).
//
// Length (H&S Lemma 6.1). A vector v in cone (d1, d2) is a d1 + b d2 with a, b >= 0, and the
// shortest path in the set from 0 to v has length a |d1| + b |d2| (a convex distance function).
// With det 2 the coefficients are halves; length2 returns twice the length, exactly, as
// (axis part) + (diagonal part) * sqrt(2).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geom/root2.h"
#include "geom/types.h"

namespace taut::geom {

// The directions of a "c:<deg>,<deg>,..." set when each is a whole number of degrees written
// exactly (digits with at most one '.', any fraction all zeros: "45", "045", "45.0", "90.",
// ".0"), each taken modulo 180, in the order written; nullopt for anything else ("c:0,22.5",
// "c:-45,45", "any").
std::optional<std::vector<int>> whole_degrees(std::string_view orientations);

// One direction of a "c:" set as written, modulo 180 degrees: the whole part (taken modulo 180
// digit by digit) and the fraction's digits without trailing zeros ("22.50" -> 22, "5").
struct WrittenDegrees {
  int whole = 0;
  std::string fraction;
  // "22.5", "10"
  std::string text() const { return fraction.empty() ? std::to_string(whole) : std::to_string(whole) + "." + fraction; }
  friend bool operator==(const WrittenDegrees&, const WrittenDegrees&) = default;
  // numeric order ("5" < "51" < "6" as fractions: no trailing zeros)
  friend bool operator<(const WrittenDegrees& a, const WrittenDegrees& b) {
    return a.whole != b.whole ? a.whole < b.whole : a.fraction < b.fraction;
  }
};
// The directions of a "c:<deg>,<deg>,..." set, each digits with at most one '.' (whole_degrees'
// grammar, any fraction), in the order written; nullopt for anything else ("c:-45,45", "any").
std::optional<std::vector<WrittenDegrees>> written_degrees(std::string_view orientations);

class LatticeDirections {
 public:
  static LatticeDirections rectilinear() { return LatticeDirections(0b0101); }
  static LatticeDirections octilinear() { return LatticeDirections(0b1111); }
  // Orientations as a mask: bit 0 = 0 degrees, bit 1 = 45, bit 2 = 90, bit 3 = 135. nullopt when
  // fewer than two bits are set.
  static std::optional<LatticeDirections> from_mask(unsigned mask);
  // "rectilinear", "octilinear", or "c:<deg>,<deg>,..." whose every direction is a multiple of 45
  // degrees written exactly (digits with at most one '.', any fraction all zeros: "45", "045",
  // "45.0", "90.", ".0"), at least two orientations modulo 180. nullopt for anything else ("any",
  // c:0,60,120, c:0,22.5, c:0,180, c:-45,45).
  static std::optional<LatticeDirections> parse(std::string_view orientations);

  unsigned mask() const { return mask_; }
  bool is_rectilinear() const { return mask_ == 0b0101; }
  bool is_octilinear() const { return mask_ == 0b1111; }
  // "rectilinear", "octilinear", or "c:" with the orientations in increasing order ("c:0,45").
  std::string name() const;
  // The orientations in degrees, increasing ({0, 45} for c:0,45).
  std::vector<int> degrees() const;
  // The unit lattice steps, counter-clockwise from +x (4, 6 or 8 of them).
  const std::vector<Point>& steps() const { return steps_; }
  // v (not zero) lies along one of the steps.
  bool along(std::int64_t dx, std::int64_t dy) const;
  // Every segment of the polyline of non-zero length lies along one of the steps.
  bool runs_along(std::span<const Point> line) const;
  // Some cone's two steps do not lie in one closed quadrant (c:0,45: NE and W; c:45,135: NE and
  // SE), so a staircase in it leaves the box of its link's ends, by up to |dx| + |dy| (the
  // parallelogram of its steps). Not for rectilinear, octilinear, c:0,45,90 and the like.
  bool cones_leave_box() const;
  // The set is the two diagonals alone (c:45,135): every step keeps the parity of x + y, so a
  // wire of the set joins only lattice points of one parity.
  bool keeps_parity() const { return mask_ == 0b1010; }
  // The open cone holding v's direction (v not zero), or -1 when v lies along a step.
  int cone(std::int64_t dx, std::int64_t dy) const;
  // The cone's two steps (counter-clockwise order).
  std::array<Point, 2> cone_steps(int cone) const {
    return {steps_[static_cast<std::size_t>(cone)], steps_[(static_cast<std::size_t>(cone) + 1) % steps_.size()]};
  }
  // Twice the length of the shortest path in the set from 0 to (dx, dy): |dx|, |dy| < 2^61.
  Root2 length2(std::int64_t dx, std::int64_t dy) const;
  // Twice the set's length of a polyline (each segment by length2).
  Root2 length2(std::span<const Point> path) const;

  friend bool operator==(const LatticeDirections&, const LatticeDirections&) = default;

 private:
  explicit LatticeDirections(unsigned mask);
  unsigned mask_ = 0;
  std::vector<Point> steps_;
};

}  // namespace taut::geom
