// Small scenes, sketches and lattice searches shared by the tests of tightening and of
// minimum-link paths (issue #5): the references they are judged by share only geom's types with
// the code under test (oracle::HomotopyWords for classes, oracle::L1Reference for free space).
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <optional>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "geom/directions.h"
#include "geom/triangulation.h"
#include "oracle/homotopy.h"
#include "oracle/l1_oracle.h"
#include "router/staircase.h"
#include "router/tighten.h"
#include "support/sketcher.h"
#include "support/taut_check.h"
#include "support/wavefront_hand.h"

namespace taut::test {

using Path = std::vector<geom::Point>;

// The free-space triangulation of a scene and a Tightener on it (tight is null when the
// triangulation is not ok()).
struct Scenery {
  geom::FreeSpaceTriangulation t;
  std::unique_ptr<router::Tightener> tight;
};
Scenery setup(const geom::Box& domain, const std::vector<geom::Polygon>& obstacles);

// Unit steps of the lattice as the references see them: a step is free (and its word of crossed
// cuts), a turn (or going straight on) at a point is allowed (not through a pinch).
struct LatticeSteps {
  using Point = geom::Point;
  static constexpr Point kSteps[8] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  const oracle::L1Reference& ref;
  const oracle::HomotopyWords& h;
  geom::Box D;
  std::map<std::pair<Point, int>, std::pair<bool, std::vector<int>>> step_cache;
  std::map<std::tuple<Point, int, int>, bool> turn_cache;
  const std::pair<bool, std::vector<int>>& step(Point p, int d) {
    auto it = step_cache.find({p, d});
    if (it != step_cache.end()) return it->second;
    const Point q{p.x + kSteps[d].x, p.y + kSteps[d].y};
    const bool in = q.x >= D.lo.x && q.x <= D.hi.x && q.y >= D.lo.y && q.y <= D.hi.y;
    std::pair<bool, std::vector<int>> v{in && ref.visible(p, q), {}};
    if (v.first) v.second = h.word(Path{p, q});
    return step_cache.emplace(std::pair{p, d}, std::move(v)).first->second;
  }
  bool turn_ok(Point p, int din, int dout) {
    auto [it, fresh] = turn_cache.emplace(std::tuple{p, din, dout}, false);
    if (fresh) {
      const Point prev{p.x - kSteps[din].x, p.y - kSteps[din].y}, next{p.x + kSteps[dout].x, p.y + kSteps[dout].y};
      it->second = ref.check_path(Path{prev, p, next}).has_value();
    }
    return it->second;
  }
  // the reduced word of w followed by the step's word
  static std::vector<int> append(std::vector<int> w, const std::vector<int>& more) {
    for (int x : more) {
      if (!w.empty() && w.back() == -x) w.pop_back();
      else w.push_back(x);
    }
    return w;
  }
};

// The bit mask of LatticeSteps::kSteps for a lattice direction set's steps.
unsigned step_mask(const geom::LatticeDirections& set);

// The fewest bends of any lattice path from a to b in the class `word`, of any length, made of
// the unit steps LatticeSteps::kSteps[d] whose bit d is set in `steps` (0x0F: rectilinear, 0xFF:
// octilinear; step_mask for another set), no step reversing the last, every step and turn allowed
// by the reference: a 0-1 BFS over (point, last step, reduced word) with cost = bends, exhaustive
// up to `cap` bends. -1 when there is none within cap.
int fewest_bends_any_length(const oracle::L1Reference& ref, const oracle::HomotopyWords& h, const geom::Box& D,
                            geom::Point a, geom::Point b, const std::vector<int>& word, int cap,
                            unsigned steps = 0x0F);

// The same search for closed paths: the fewest bends inside a lattice path from x back to x in the
// class `word` (its reduced word from x), whose closing turn at x stays in one free wedge (or goes
// straight on); b bends make a loop of at most b + 1 links. -1 when there is none within cap.
int fewest_bends_closed(const oracle::L1Reference& ref, const oracle::HomotopyWords& h, const geom::Box& D,
                        geom::Point x, const std::vector<int>& word, int cap, unsigned steps = 0x0F);

// A random sketch (a walk of `legs` legs, with loops appended when asked) and its taut path;
// nullopt when the sketch is closed or does not tighten.
struct TautSketch {
  Path sketch;
  router::Tightened taut;
};
std::optional<TautSketch> taut_sketch(Sketcher& sk, const router::Tightener& tight, int legs, bool loops);
// A random closed walk of 3 to 6 points (loops appended when asked) and its shortest loop; nullopt
// when the walk does not close by a free segment, or its loop is contractible or does not tighten.
struct TautLoop {
  Path loop;
  router::Tightener::Loop taut;
};
std::optional<TautLoop> taut_loop(Sketcher& sk, const router::Tightener& tight, bool loops);

// Lattice points of [0, N]^2 that are free with one wedge (where the sketches start, end and bend).
Path single_wedge_points(const oracle::L1Reference& ref, int N);

// A StaircaseBuilder whose first slab is 1: the pieces gather their walls from many slabs even in
// small layouts.
router::StaircaseBuilder many_slabs(const Scene& sc);

// A small scene with what the c-oriented tests judge by. The homotopy reference is built first:
// it cuts every normalized layout (obstacles pinched at their top vertex included), so a throw
// there fails the test; a layout the L1 reference finds problems in is skipped by the caller.
struct Judged {
  explicit Judged(const Scene& s)
      : sc(s), h(sc.domain, sc.obstacles), ref(sc.domain, sc.obstacles), st(setup(sc.domain, sc.obstacles)),
        sb(many_slabs(sc)) {}
  Scene sc;
  oracle::HomotopyWords h;
  oracle::L1Reference ref;
  Scenery st;
  router::StaircaseBuilder sb;
};
// The judged scene, or nullptr when the L1 reference finds problems in it (skipped).
std::unique_ptr<Judged> judge(const Scene& sc);

// The loops' hand case: the square [40, 60]^2 in [0, 100]^2 judged, a loop once round it, its
// shortest loop and its cyclic word (ok(): the scene judged and the loop tightened).
struct SquareLoop {
  std::unique_ptr<Judged> j;
  Path once;
  router::Tightener::Loop taut;
  std::vector<int> cyclic;
  bool ok() const { return j && j->st.t.ok() && taut.status == router::TightenStatus::Ok; }
};
SquareLoop square_loop();

// A polygon from its vertices in either orientation (counter-clockwise as normalization wants).
geom::Polygon poly(std::vector<geom::Point> r);

// Degenerate small layouts in [0, N]^2 (from a review of staircase_in_class): kind 0 sloped
// triangles; 1 rectangles touching at corners and edges, with triangles; 2 octilinear diamonds,
// 45-degree triangles and squares; 3 T-pinches (a tip on the middle of a rectangle's edge);
// 4 thin slivers and quads with sloped sides. Not always valid: normalize and skip what throws.
std::vector<geom::Polygon> degenerate_scene(std::mt19937& rng, int kind, int N);

// A normalized small scene in [0, N]^2: kinds 0 to 4 of degenerate_scene, or kind 5, one to three
// rectangles that may touch (corners in 1..6, sides 1..3). nullopt when normalization refuses it.
std::optional<Scene> small_scene(std::mt19937& rng, int kind, int N);

// The small scenes of seeds 1..n, each of the six kinds (small_scene on an mt19937 seeded
// seed * mul + kind), that the references take: fn(seed, kind, judged scene, its single-wedge
// lattice points, a 64-bit generator for its sketches). Stops at the first scene with a failure.
template <class F>
long long for_each_small_scene(int n, int N, unsigned mul, std::uint64_t sketch_mul, F&& fn) {
  long long scenes = 0;
  for (int seed = 1; seed <= n; ++seed) {
    for (int kind = 0; kind < 6; ++kind) {
      std::mt19937 rng(static_cast<unsigned>(seed) * mul + static_cast<unsigned>(kind));
      const std::optional<Scene> scene = small_scene(rng, kind, N);
      if (!scene) continue;
      const auto j = judge(*scene);
      if (!j) continue;
      EXPECT_TRUE(j->st.t.ok());
      if (!j->st.t.ok()) return scenes;
      ++scenes;
      const Path pts = single_wedge_points(j->ref, N);
      if (pts.size() < 3) continue;
      std::mt19937_64 rng64(static_cast<std::uint64_t>(seed) * sketch_mul + static_cast<std::uint64_t>(kind));
      fn(seed, kind, *j, pts, rng64);
      if (::testing::Test::HasFailure()) {
        ADD_FAILURE() << "stopping at the first failing layout (seed " << seed << " kind " << kind << ")";
        return scenes;
      }
    }
  }
  return scenes;
}

// The loop tests' random loops: on the small scenes of seeds 1..n (for_each_small_scene with
// mul 137 and sketch_mul 6007), `per_scene` closed walks each, loops appended to every second;
// fn(judged scene, its single-wedge points, the walk's index t, the walk and its shortest loop,
// the walk's cyclic word, "seed S kind K loop ...") for each walk that closes and is not
// contractible. Returns the scenes.
template <class F>
long long for_each_random_loop(int n, int per_scene, F&& fn) {
  return for_each_small_scene(n, 9, 137, 6007,
                              [&](int seed, int kind, const Judged& j, const Path& pts, std::mt19937_64& rng64) {
                                Sketcher sk{j.ref, j.h, pts, rng64};
                                for (int t = 0; t < per_scene; ++t) {
                                  const std::optional<TautLoop> tl = taut_loop(sk, *j.st.tight, t % 2 == 1);
                                  if (!tl) continue;
                                  fn(j, pts, t, *tl, cyclic_word(j.h.word(tl->loop)),
                                     "seed " + std::to_string(seed) + " kind " + std::to_string(kind) + " loop " +
                                         str(tl->loop));
                                }
                              });
}

}  // namespace taut::test
