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
  // Orientations as a mask: bit k = 30k degrees (k = 0..5). nullopt when fewer than two bits are
  // set, or only 0 and 90 (rectilinear: a lattice set).
  static std::optional<Root3Directions> from_mask(unsigned mask);
  // "c:<deg>,<deg>,..." whose every direction is a multiple of 30 degrees written exactly (as
  // LatticeDirections::parse reads them: "60", "060", "60.0"), modulo 180, at least two
  // orientations, one of them at 30, 60, 120 or 150. nullopt for anything else (the lattice sets,
  // "any", c:0,45,60, c:0,22.5).
  static std::optional<Root3Directions> parse(std::string_view orientations);

  unsigned mask() const { return mask_; }
  // "c:" with the orientations in increasing order ("c:0,60,120").
  std::string name() const;
  // The orientations in degrees, increasing.
  std::vector<int> degrees() const;
  // The steps, counter-clockwise from +x (4 to 12 of them).
  const std::vector<Step>& steps() const { return steps_; }
  // v (not zero, |dx|, |dy| < 2^40) lies exactly along one of the steps (only the axes can).
  bool along(std::int64_t dx, std::int64_t dy) const { return step_along(dx, dy) >= 0; }
  // Which step v lies exactly along (an index into steps()), or -1.
  int step_along(std::int64_t dx, std::int64_t dy) const;
  // Some cone's two steps do not lie in one closed quadrant (it straddles an axis, as 60 and 120
  // degrees in c:0,60,120), so a staircase in it leaves the box of its link's ends.
  bool cones_leave_box() const;
  // The open cone holding v's direction (v not zero), or -1 when v lies along a step.
  int cone(std::int64_t dx, std::int64_t dy) const;
  // The cone's two steps (counter-clockwise order), as LatticeDirections::cone_steps.
  std::array<Step, 2> cone_steps(int cone) const {
    return {steps_[static_cast<std::size_t>(cone)], steps_[(static_cast<std::size_t>(cone) + 1) % steps_.size()]};
  }
  // Twelve times the length of the shortest path in the set from 0 to (dx, dy) (|dx|, |dy| <
  // 2^40).
  Root3 length12(std::int64_t dx, std::int64_t dy) const;
  // The written segment (dx, dy) (|dx|, |dy| < 2^40) runs in the set within the rounding of its
  // ends: some direction's ray from 0 meets the square [dx - 1, dx + 1] x [dy - 1, dy + 1]. True
  // when that square holds 0 (|dx|, |dy| <= 1).
  bool fits(std::int64_t dx, std::int64_t dy) const;
  // Every segment of the polyline fits (as LatticeDirections::runs_along for the lattice sets).
  bool runs_within(std::span<const Point> line) const;

  friend bool operator==(const Root3Directions& x, const Root3Directions& y) { return x.mask_ == y.mask_; }

 private:
  explicit Root3Directions(unsigned mask);
  unsigned mask_ = 0;
  std::vector<Step> steps_;
};

}  // namespace taut::geom
