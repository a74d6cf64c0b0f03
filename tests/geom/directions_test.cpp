// geom/directions.h: lattice direction sets. The length is checked against Dijkstra on the unit
// lattice with only the set's steps (weights 1 and sqrt(2), compared exactly as Root2), which
// shares nothing with the cone decomposition; parsing and cones against hand cases.
#include "geom/directions.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <map>
#include <queue>
#include <string>
#include <tuple>
#include <vector>

namespace taut::geom {
namespace directions_test {

TEST(LatticeDirections, ParsesMultiplesOf45Only) {
  EXPECT_EQ(LatticeDirections::parse("rectilinear")->mask(), 0b0101u);
  EXPECT_EQ(LatticeDirections::parse("octilinear")->mask(), 0b1111u);
  EXPECT_EQ(LatticeDirections::parse("c:90,0")->name(), "rectilinear");
  EXPECT_EQ(LatticeDirections::parse("c:0,45,90,135,180")->name(), "octilinear");
  EXPECT_EQ(LatticeDirections::parse("c:180,45")->name(), "c:0,45");
  EXPECT_EQ(LatticeDirections::parse("c:45,315")->name(), "c:45,135");
  EXPECT_EQ(LatticeDirections::parse("c:45.0,135.00")->name(), "c:45,135");
  EXPECT_EQ(LatticeDirections::parse("c:0,90,135")->name(), "c:0,90,135");
  EXPECT_EQ(LatticeDirections::parse("c:0,225,90")->name(), "c:0,45,90");
  // the spellings the other commands' reading accepts (review): leading zeros, "90.", ".0", and
  // numbers of any length, taken modulo 180
  EXPECT_EQ(LatticeDirections::parse("c:0,90.")->name(), "rectilinear");
  EXPECT_EQ(LatticeDirections::parse("c:.0,90")->name(), "rectilinear");
  EXPECT_EQ(LatticeDirections::parse("c:0,0000000000090")->name(), "rectilinear");
  ASSERT_TRUE(LatticeDirections::parse("c:0,99999999999990"));  // 90 + 180 k
  EXPECT_EQ(LatticeDirections::parse("c:0,99999999999990")->name(), "rectilinear");
  ASSERT_TRUE(LatticeDirections::parse("c:0,180000000000000000000045"));  // 45 + 180 k
  EXPECT_EQ(LatticeDirections::parse("c:0,180000000000000000000045")->name(), "c:0,45");
  for (const char* bad : {"any", "", "c:", "c:0", "c:0,180", "c:45,225", "c:0,60,120", "c:0,45.5", "c:0,22.5",
                          "c:0,90,", "c:-45,45", "c:0,4a5", "c:.,90", "c:1e2,0", "hexagonal", "c:0,99999999999991",
                          "c:0,9.0.0", "c:0,+90", "c:0, 90", "c:0,1000000000000000000000045"})
    EXPECT_FALSE(LatticeDirections::parse(bad).has_value()) << bad;
  EXPECT_FALSE(LatticeDirections::from_mask(0b0100).has_value());
  EXPECT_EQ(LatticeDirections::from_mask(0b1010)->name(), "c:45,135");
}

TEST(LatticeDirections, StepsAndCones) {
  const auto d = *LatticeDirections::parse("c:0,45");
  const std::vector<Point> steps{{1, 0}, {1, 1}, {-1, 0}, {-1, -1}};
  EXPECT_EQ(d.steps(), steps);
  EXPECT_EQ(d.cone(2, 1), 0);   // between E and NE
  EXPECT_EQ(d.cone(0, 1), 1);   // north lies between NE and W
  EXPECT_EQ(d.cone(-1, 5), 1);
  EXPECT_EQ(d.cone(-3, -1), 2);
  EXPECT_EQ(d.cone(0, -1), 3);  // south: between SW and E
  EXPECT_EQ(d.cone(7, 7), -1);
  EXPECT_TRUE(d.along(-4, 0));
  EXPECT_FALSE(d.along(0, 4));
  EXPECT_FALSE(d.along(-4, 4));
  // a polyline: every segment of non-zero length along a step (a repeated point, one point, none)
  EXPECT_TRUE(d.runs_along(std::vector<Point>{{0, 0}, {3, 0}, {3, 0}, {5, 2}, {1, 2}}));
  EXPECT_TRUE(d.runs_along(std::vector<Point>{{4, 4}}));
  EXPECT_TRUE(d.runs_along(std::vector<Point>{}));
  EXPECT_FALSE(d.runs_along(std::vector<Point>{{0, 0}, {3, 0}, {3, 2}}));  // north is not in c:0,45
  EXPECT_TRUE(LatticeDirections::rectilinear().runs_along(std::vector<Point>{{0, 0}, {3, 0}, {3, 2}}));
  EXPECT_FALSE(LatticeDirections::rectilinear().runs_along(std::vector<Point>{{0, 0}, {3, 0}, {5, 2}}));
}

// Dijkstra from (0, 0) over [-R, R]^2 with the set's unit steps; twice the lengths.
std::map<std::pair<int, int>, Root2> lattice_lengths(const LatticeDirections& d, int R) {
  using Item = std::tuple<double, std::int64_t, std::int64_t, int, int>;  // order only: ties settle exactly
  std::map<std::pair<int, int>, Root2> best{{{0, 0}, {0, 0}}};
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  pq.emplace(0.0, 0, 0, 0, 0);
  std::map<std::pair<int, int>, bool> done;
  while (!pq.empty()) {
    const auto [f, a, b, x, y] = pq.top();
    pq.pop();
    if (done[{x, y}] || !(best.at({x, y}) == Root2{a, b})) continue;
    done[{x, y}] = true;
    for (const Point s : d.steps()) {
      const int nx = x + s.x, ny = y + s.y;
      if (nx < -R || nx > R || ny < -R || ny > R) continue;
      const Root2 w = (s.x != 0 && s.y != 0) ? Root2{0, 2} : Root2{2, 0};
      const Root2 nd = Root2{a, b} + w;
      auto it = best.find({nx, ny});
      if (it == best.end() || nd < it->second) {
        best[{nx, ny}] = nd;
        pq.emplace(nd.to_double(), nd.a, nd.b, nx, ny);
      }
    }
  }
  return best;
}

// cones_leave_box against its meaning: for every set (every mask of two orientations or more),
// some cone's staircase from 0 to d1 + d2 (inside the cone) turns at d1 or d2, and one of those
// lies outside the box of 0 and d1 + d2.
TEST(LatticeDirections, ConesLeaveTheBoxExactlyWhenAStaircaseDoes) {
  int leave = 0;
  for (unsigned mask = 1; mask < 16; ++mask) {
    const auto set = geom::LatticeDirections::from_mask(mask);
    if (!set) continue;
    bool want = false;
    const auto& st = set->steps();
    for (std::size_t i = 0; i < st.size(); ++i) {
      const geom::Point d1 = st[i], d2 = st[(i + 1) % st.size()], e{d1.x + d2.x, d1.y + d2.y};
      const geom::Box box{{std::min(0, e.x), std::min(0, e.y)}, {std::max(0, e.x), std::max(0, e.y)}};
      for (const geom::Point c : {d1, d2})
        want = want || c.x < box.lo.x || c.x > box.hi.x || c.y < box.lo.y || c.y > box.hi.y;
    }
    EXPECT_EQ(set->cones_leave_box(), want) << set->name();
    leave += want;
  }
  EXPECT_FALSE(geom::LatticeDirections::rectilinear().cones_leave_box());
  EXPECT_FALSE(geom::LatticeDirections::octilinear().cones_leave_box());
  EXPECT_TRUE(geom::LatticeDirections::parse("c:0,45")->cones_leave_box());
  EXPECT_TRUE(geom::LatticeDirections::parse("c:45,135")->cones_leave_box());
  EXPECT_FALSE(geom::LatticeDirections::parse("c:0,45,90")->cones_leave_box());
  EXPECT_GT(leave, 0);
}

TEST(LatticeDirections, LengthIsTheShortestLatticePathInTheSet) {
  const int R = 9;
  int compared = 0, halves = 0;
  for (unsigned mask = 0; mask < 16; ++mask) {
    const auto d = LatticeDirections::from_mask(mask);
    if (!d) continue;
    const auto best = lattice_lengths(*d, 2 * R);  // room for detours beyond the box
    for (int x = -R; x <= R; ++x)
      for (int y = -R; y <= R; ++y) {
        const Root2 got = d->length2(x, y);
        const auto it = best.find({x, y});
        // Strictly between the two diagonals with x + y odd: the set's length (real steps) is
        // shorter than any lattice path's, whose steps along the diagonals keep x + y's parity.
        bool half = false;
        if ((x != 0 || y != 0) && d->cone(x, y) >= 0) {
          const auto [d1, d2] = d->cone_steps(d->cone(x, y));
          half = d1.x * d2.y - d1.y * d2.x == 2 && (x + y) % 2 != 0;
        }
        if (half) {
          ++halves;
          if (it != best.end()) {
            EXPECT_LT(got, it->second) << d->name() << " to " << x << "," << y;
          }
          continue;
        }
        if (it == best.end()) {  // every lattice point off the half cases is reached
          ADD_FAILURE() << d->name() << ": no lattice path to " << x << "," << y;
          continue;
        }
        ++compared;
        EXPECT_EQ(got, it->second) << d->name() << " to " << x << "," << y;
        // along a step exactly when the set's path is one segment
        const bool one = d->along(x, y);
        EXPECT_EQ(one, (x != 0 || y != 0) && d->cone(x, y) < 0) << d->name() << " " << x << "," << y;
      }
  }
  EXPECT_EQ(compared + halves, 11 * 19 * 19);
  EXPECT_GT(halves, 300);  // c:45,135, c:0,45,135 and c:45,90,135
  std::printf("%d lengths equal to the lattice's, %d shorter (half steps between the diagonals)\n", compared, halves);
}

}  // namespace directions_test
}  // namespace taut::geom
