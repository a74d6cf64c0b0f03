// Direction sets at multiples of 30 degrees that are not lattice sets: c:0,60,120 (the example
// of FORMAT.md), c:30,90,150, c:0,30,60,90,120,150, c:0,60 and the like (at least two
// orientations modulo 180, one of them at 30, 60, 120 or 150 degrees). Their unit vectors lie in
// Q(sqrt3) (geom/root3.h), so cones, lengths and the test below are exact.
//
//   auto d = geom::Root3Directions::parse("c:0,60,120");
//   int c = d->cone(3, 1);              // the open cone between 0 and 60 degrees: 0
//   geom::Root3 l = d->length12(3, 1);  // 12 times the length of the shortest path in the set
//   bool ok = d->fits(10, 17);          // within the rounding of its ends of 60 degrees: true
//
// Integer vertices. No segment between lattice points runs exactly at 30, 60, 120 or 150 degrees
// (their tangents are irrational), and FORMAT.md's wires have integer vertices. A wire in such a
// set is therefore written with its exact vertices rounded to the nearest integers, and a
// written segment p q is taken to run in the set when its ends can be moved by at most half a
// unit in x and in y each so that it runs exactly along a direction of the set: when the ray from
// 0 along some direction meets the square (q - p) + [-1, 1]^2 (fits()). This is what taut check
// verifies for <routes orientations> of such a set (CHECK-0002).
//
// Cones and length (H&S Lemma 6.1). The steps are twice the set's unit vectors, counter-clockwise
// from +x; cone i is the open angle from step i to step i + 1 (30 to 150 degrees). A vector v in
// cone (s1, s2) is a s1 + b s2 with a, b >= 0, and the shortest path in the set from 0 to v has
// length 2(a + b), the convex distance function of the set; length12 returns twelve times it,
// which lies in Z[sqrt3] (the cross product of two steps is 2, 2 sqrt3 or 4).
//
// Sets at other angles (parse_any, since 2026-12-07; taken by tighten, route and check). A set such
// as c:0,10 or c:0,45,60 holds the same kind of steps, vectors in Z[sqrt3]^2, of different
// lengths:
//   - a multiple of 30 degrees: twice its unit vector, as above (exact, length 2);
//   - a multiple of 45 degrees that is not one of 90: (1, 1) or (-1, 1) (exact, length sqrt 2);
//   - any other direction: the integer step (A, B), gcd 1, |A|, |B| <= 2^24, nearest it among
//     the last convergent of the continued fraction of its slope (or of the inverse slope,
//     whichever is at most 1 in magnitude) within that bound and the semiconvergent past it (a
//     best approximation is one of them). Its angle is off the direction's by less than
//     1 / (q 2^24), q the denominator: over the random sets of tests/geom/root3_test.cpp,
//     2^-48.6 radians the median and 2^-40.7 the largest. A set is refused past 2^-36, which a
//     direction about 10^-6 degrees off a slope p/q of small q can be (c:0,0.000001 and
//     c:0,45.000001 are refused; c:0,0.00001 is (5729578, 1)).
//   The slope is computed in 50-digit binary floating point (Boost's cpp_bin_float, the same on
//   every machine) from the written degrees: that chooses the step, and
//   from then on every decision (cones, fits, the router's predicates) is exact for that step. A
//   written wire is rounded to integers anyway, so a segment is off its exact direction by up to
//   a unit over its length; the step's own error is below 2^-36 of that length. fits() judges
//   against the step.
// Steps no longer share a length, so length12 is for the sets of parse() only; norm2(i) gives
// each step's squared length (4, 2 or A^2 + B^2), which a length in such a set needs: the
// coefficients over the cone's two steps times their lengths, a sum of square roots.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geom/root3.h"
#include "geom/types.h"

namespace taut::geom {

class Root3Directions {
 public:
  // Twice a unit vector: x and y in Z[sqrt3].
  struct Step {
    Root3 x, y;
  };
  // cross(s, v), cross(v, s) and dot(s, v) for an integer vector v, cross(s, t) of two steps, in
  // Z[sqrt3] (below 2^57 for |dx|, |dy| < 2^32 and steps below 2^24).
  static Root3 cross(const Step& s, std::int64_t dx, std::int64_t dy) { return dy * s.x - dx * s.y; }
  static Root3 cross(std::int64_t dx, std::int64_t dy, const Step& s) { return dx * s.y - dy * s.x; }
  static Root3 dot(const Step& s, std::int64_t dx, std::int64_t dy) { return dx * s.x + dy * s.y; }
  static Root3 cross(const Step& s, const Step& t) { return s.x * t.y - s.y * t.x; }
  // Orientations as a mask: bit k = 30k degrees (k = 0..5). nullopt when fewer than two bits are
  // set, or only 0 and 90 (rectilinear: a lattice set).
  static std::optional<Root3Directions> from_mask(unsigned mask);
  // "c:<deg>,<deg>,..." whose every direction is a multiple of 30 degrees written exactly (as
  // LatticeDirections::parse reads them: "60", "060", "60.0"), modulo 180, at least two
  // orientations, one of them at 30, 60, 120 or 150. nullopt for anything else (the lattice sets,
  // "any", c:0,45,60, c:0,22.5).
  static std::optional<Root3Directions> parse(std::string_view orientations);
  // Any "c:" set of at least two orientations modulo 180 degrees that is not a lattice set
  // (LatticeDirections::parse): what parse() takes, the same; otherwise each direction (digits
  // with at most one '.', in degrees, as whole_degrees reads them, but any fraction) as the top
  // of the file says. Directions written alike modulo 180 ("10", "190", "10.0") are one; nullopt
  // for two others whose steps are parallel or out of order, a step off its direction by more
  // than 2^-36 radians (see the top of the file), or more than eight directions at multiples of
  // neither 30 nor 45 degrees (each one more square root in a length, router/radical_sum.h).
  static std::optional<Root3Directions> parse_any(std::string_view orientations);
  // The same; `why` says what is refused when nullopt ("" otherwise), for messages.
  static std::optional<Root3Directions> parse_any(std::string_view orientations, std::string& why);

  // The set's orientations as a mask (bit k = 30k degrees); 0 for a set of parse_any that
  // parse() would not give.
  unsigned mask() const { return mask_; }
  // Every step lies exactly along its direction (parse()'s sets, and those of parse_any whose
  // directions are multiples of 30 or 45 degrees).
  bool exact() const {
    for (const Orientation& o : orient_)
      if (!o.exact) return false;
    return true;
  }
  // "c:" with the orientations in increasing order ("c:0,60,120", "c:0,10", "c:0,22.5").
  std::string name() const;
  // The orientations in degrees, increasing: for a set with mask() only (throws otherwise).
  std::vector<int> degrees() const;
  // The orientations as written in name(), increasing ("0", "22.5").
  std::vector<std::string> orientation_texts() const {
    std::vector<std::string> t;
    for (const Orientation& o : orient_) t.push_back(o.text);
    return t;
  }
  // How far orientation k's step is off its written angle, in radians: 0 for an exact one, else
  // the long double estimate made at parse (below 2^-36; a report, no decision uses it).
  long double off_radians(std::size_t k) const { return orient_[k].off; }
  // Orientation k's step lies exactly along its written angle (a multiple of 30 or 45 degrees).
  bool orientation_exact(std::size_t k) const { return orient_[k].exact; }
  // The squared length of step i: 4 (a multiple of 30 degrees), 2 (of 45) or A^2 + B^2.
  std::int64_t norm2(std::size_t i) const { return norm2_[i]; }
  // The steps, counter-clockwise from +x (4 to 12 of them in parse()'s sets; any even count from 4
  // in parse_any's).
  const std::vector<Step>& steps() const { return steps_; }
  // v (not zero, |dx|, |dy| < 2^40; < 2^36 in a set of parse_any with integer steps) lies exactly
  // along one of the steps (in parse()'s sets only the axes can).
  bool along(std::int64_t dx, std::int64_t dy) const { return step_along(dx, dy) >= 0; }
  // Which step v lies exactly along (an index into steps()), or -1.
  int step_along(std::int64_t dx, std::int64_t dy) const;
  // Some cone's two steps do not lie in one closed quadrant (it straddles an axis, as 60 and 120
  // degrees in c:0,60,120), so a staircase in it leaves the box of its link's ends.
  bool cones_leave_box() const;
  // How far a staircase in a cone of the set can reach out of its link's box, in units of the
  // link's |dx| + |dy|: 1 when every cone is at most 135 degrees (the lattice sets' bound, which
  // callers grow by), else the ceiling of 1 / sin of the widest cone (its parallelogram's corners
  // lie within |v| / sin of the link's start): c:0,30 2, c:0,10 6. A sizing (long double), not a
  // geometric decision.
  int box_growth() const;
  // The open cone holding v's direction (v not zero; |dx|, |dy| < 2^40, < 2^36 with integer
  // steps), or -1 when v lies along a step.
  int cone(std::int64_t dx, std::int64_t dy) const;
  // The cone's two steps (counter-clockwise order), as LatticeDirections::cone_steps.
  std::array<Step, 2> cone_steps(int cone) const {
    return {steps_[static_cast<std::size_t>(cone)], steps_[(static_cast<std::size_t>(cone) + 1) % steps_.size()]};
  }
  // Twelve times the length of the shortest path in the set from 0 to (dx, dy) (|dx|, |dy| <
  // 2^40); for a set with mask() only (throws otherwise: steps of other lengths).
  Root3 length12(std::int64_t dx, std::int64_t dy) const;
  // The written segment (dx, dy) (|dx|, |dy| < 2^40; 2^36 with integer steps) runs in the set within the rounding of its
  // ends: some direction's ray from 0 meets the square [dx - 1, dx + 1] x [dy - 1, dy + 1]. True
  // when that square holds 0 (|dx|, |dy| <= 1).
  bool fits(std::int64_t dx, std::int64_t dy) const;
  // Every segment of the polyline fits (as LatticeDirections::runs_along for the lattice sets).
  bool runs_within(std::span<const Point> line) const;

  friend bool operator==(const Root3Directions& x, const Root3Directions& y) {
    return x.orientation_texts() == y.orientation_texts();  // (canonical: they decide the steps)
  }

 private:
  explicit Root3Directions(unsigned mask);
  Root3Directions() = default;
  unsigned mask_ = 0;
  std::vector<Step> steps_;
  std::vector<std::int64_t> norm2_;
  // per orientation, increasing: as written in name(), along its step exactly, how far off
  struct Orientation {
    std::string text;
    bool exact = true;
    long double off = 0;
  };
  std::vector<Orientation> orient_;
};

}  // namespace taut::geom
