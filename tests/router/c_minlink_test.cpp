// router::CMinLinker (minimum-link c-oriented paths of a homotopy class, Hershberger & Snoeyink
// section 6.3) against references that share only geom's types with it:
//   - every path is a path of the class in the set's directions: each link runs along a direction
//     of the set, lies in free space (oracle::segment_free, exact rationals), turns at a blockage
//     vertex only inside one free wedge (the L1 reference's wedges), and the path's reduced cut
//     word is the sketch's (oracle::HomotopyWords);
//   - it never has more links than the shortest c-oriented wire of the class with the fewest
//     links (router::c_oriented, section 6.4), which is a path of the class too; for the sets of
//     two orientations (rectilinear, c:0,45, c:45,135, ...) every basis direction has the halfplane
//     condition, so that wire is a minimum-link path (Lemma 6.6) and the counts must be equal;
//   - it never has more links than a path an exhaustive search over lattice paths of the class
//     finds (a 0-1 BFS over point, last step and reduced word), on the scene as it is and scaled by
//     2 (so bends at half-integers, where two diagonals meet, are lattice points too); how often
//     that search matches the count (a path with one link fewer not found, one with as many found)
//     is reported and required, so the comparison is not vacuous.
// Scenes: the degenerate 9x9 families of the tightening tests (sloped triangles, rectangles
// touching at corners and edges, octilinear shapes, T-pinches, slivers) and rectangles that may
// touch; sketches are random walks with loops appended (winding one to three times).
#include "router/c_minlink.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "geom/directions.h"
#include "geom/predicates.h"
#include "oracle/homotopy.h"
#include "oracle/l1_oracle.h"
#include "oracle/link_oracle.h"
#include "router/tighten.h"
#include "support/sanitized.h"
#include "support/taut_check.h"
#include "support/sketcher.h"
#include "support/taut_scenes.h"
#include "support/wavefront_hand.h"

namespace taut::test {
namespace c_minlink_test {

using geom::Point;
using router::Rational;
using router::RPoint;

std::string qstr(const std::vector<RPoint>& path) {
  std::string s;
  for (const RPoint& p : path) s += "(" + p.x.str() + "," + p.y.str() + ")";
  return s;
}

oracle::QPoint qp(const RPoint& p) { return {mpq_class(p.x.str()), mpq_class(p.y.str())}; }

// The path is one of the class in the set's directions (see the top of the file); "" when it is,
// else what is wrong.
std::string path_problem(const std::vector<RPoint>& path, const geom::LatticeDirections& set, const Scene& sc,
                         const oracle::HomotopyWords& h, const oracle::L1Reference& ref, const std::vector<int>* word) {
  std::vector<oracle::QPoint> qpath;
  for (const RPoint& p : path) qpath.push_back(qp(p));
  std::vector<Point> dirs;  // each link's step
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Rational dx = path[i + 1].x - path[i].x, dy = path[i + 1].y - path[i].y;
    Point step{0, 0};
    for (Point d : set.steps())
      if (Rational(dx * d.y - dy * d.x).sign() == 0 && Rational(dx * d.x + dy * d.y).sign() > 0) step = d;
    if (step == Point{0, 0}) return "link " + std::to_string(i) + " is not along the set";
    dirs.push_back(step);
    if (!oracle::segment_free(qpath[i], qpath[i + 1], sc.domain, sc.obstacles))
      return "link " + std::to_string(i) + " leaves free space";
  }
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const RPoint& x = path[i];
    if (x.x.convert_to<long long>() != x.x || x.y.convert_to<long long>() != x.y) continue;  // not a vertex
    const Point v{static_cast<int>(x.x.convert_to<long long>()), static_cast<int>(x.y.convert_to<long long>())};
    bool one = false;
    for (const auto& w : ref.wedges_at(v))
      one = one || (w.contains(-dirs[i - 1].x, -dirs[i - 1].y) && w.contains(dirs[i].x, dirs[i].y));
    if (!one) return "the turn at bend " + std::to_string(i) + " passes between blockages";
  }
  if (word && h.word(std::span<const oracle::QPoint>(qpath)) != *word) return "another homotopy class";
  return "";
}

// The scene's obstacles, ring by ring (for failure messages).
std::string scene_str(const Scene& sc) {
  std::string s;
  for (const geom::Polygon& p : sc.obstacles) {
    s += " ring" + str(p.outer);
    for (const geom::Ring& h : p.holes) s += " hole" + str(h);
  }
  return s;
}

Scene scaled(const Scene& sc, int f) {
  Scene out{{{sc.domain.lo.x * f, sc.domain.lo.y * f}, {sc.domain.hi.x * f, sc.domain.hi.y * f}}, sc.obstacles};
  for (geom::Polygon& p : out.obstacles) {
    for (Point& v : p.outer) v = {v.x * f, v.y * f};
    for (geom::Ring& r : p.holes)
      for (Point& v : r) v = {v.x * f, v.y * f};
  }
  return out;
}

// Every blockage edge runs along an orientation of the set (the paper's setting in section 6).
bool edges_in_set(const Scene& sc, const geom::LatticeDirections& set) {
  auto ring_ok = [&](const geom::Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point a = r[i], b = r[(i + 1) % r.size()];
      const long long dx = b.x - a.x, dy = b.y - a.y;
      if ((dx || dy) && !set.along(dx, dy) && !set.along(-dx, -dy)) return false;
    }
    return true;
  };
  for (const geom::Polygon& p : sc.obstacles) {
    if (!ring_ok(p.outer)) return false;
    for (const geom::Ring& h : p.holes)
      if (!ring_ok(h)) return false;
  }
  return true;
}

struct Totals {
  long long paths = 0, none = 0, links = 0, halfplane_equal = 0, fewer_than_shortest = 0, searched = 0,
            search_tight = 0, scaled_searched = 0, scaled_tight = 0, rational_bends = 0, sweeps = 0;
};

// One sketch's taut path in every lattice set, judged as at the top of the file.
void judge_sketch(const Judged& j, const Path& sketch, const Path& taut, const std::string& where, Totals& tot,
                  const Judged* twice) {
  const router::CMinLinker cm(j.st.t);
  const std::vector<int> word = j.h.word(sketch);
  for (unsigned mask = 1; mask < 16; ++mask) {
    const auto set = geom::LatticeDirections::from_mask(mask);
    if (!set) continue;
    const std::string at = where + " " + set->name() + " taut " + str(taut);
    router::CMinLinkPath c;
    try {
      c = cm.path(taut, *set);
    } catch (const std::exception& e) {
      ADD_FAILURE() << at << ": " << e.what();
      continue;
    }
    const router::COriented shortest = router::c_oriented(*j.st.tight, j.sb, taut, *set);
    const unsigned steps = step_mask(*set);
    if (!c.ok()) {
      ++tot.none;
      EXPECT_TRUE(shortest.points.empty()) << at << ": no path (" << c.why << "), but the shortest wire " << str(shortest.points);
      EXPECT_EQ(fewest_bends_any_length(j.ref, j.h, j.sc.domain, sketch.front(), sketch.back(), word, 6, steps), -1)
          << at << ": no path (" << c.why << "), but the lattice search finds one";
      continue;
    }
    ++tot.paths;
    tot.sweeps += static_cast<long long>(c.sweeps);
    const int links = static_cast<int>(c.links());
    tot.links += links;
    EXPECT_EQ(path_problem(c.points, *set, j.sc, j.h, j.ref, &word), "") << at << " path " << qstr(c.points);
    for (const RPoint& x : c.points)
      tot.rational_bends += x.x.convert_to<long long>() != x.x || x.y.convert_to<long long>() != x.y;
    if (!shortest.points.empty()) {
      const int sl = static_cast<int>(geom::count_bends(shortest.points)) + 1;
      EXPECT_LE(links, sl) << at << " path " << qstr(c.points) << " shortest " << str(shortest.points);
      tot.fewer_than_shortest += links < sl;
      // Two orientations: every basis direction has the halfplane condition, so with blockage
      // edges in the set's orientations the shortest wire with the fewest links is a minimum-link
      // one (section 6.4). A sloped edge breaks that: the shortest wire zigzags along it, a longer
      // one keeps away with fewer links.
      if (set->steps().size() == 4 && edges_in_set(j.sc, *set)) {
        EXPECT_EQ(links, sl) << at << ": two orientations (the halfplane condition), path " << qstr(c.points)
                             << " shortest " << str(shortest.points);
        ++tot.halfplane_equal;
      }
    }
    // the lattice searches: nothing with fewer links (bends <= links - 2)
    if (links >= 2 && links <= 6) {
      ++tot.searched;
      EXPECT_EQ(fewest_bends_any_length(j.ref, j.h, j.sc.domain, sketch.front(), sketch.back(), word, links - 2, steps), -1)
          << at << ": a lattice path with fewer links than " << qstr(c.points);
      tot.search_tight +=
          fewest_bends_any_length(j.ref, j.h, j.sc.domain, sketch.front(), sketch.back(), word, links - 1, steps) == links - 1;
      if (twice) {
        ++tot.scaled_searched;
        const Path s2{{sketch.front().x * 2, sketch.front().y * 2}, {sketch.back().x * 2, sketch.back().y * 2}};
        Path sk2;
        for (Point p : sketch) sk2.push_back({p.x * 2, p.y * 2});
        const std::vector<int> w2 = twice->h.word(sk2);
        EXPECT_EQ(fewest_bends_any_length(twice->ref, twice->h, twice->sc.domain, s2[0], s2[1], w2, links - 2, steps), -1)
            << at << ": a lattice path at half-integers with fewer links than " << qstr(c.points);
        tot.scaled_tight +=
            fewest_bends_any_length(twice->ref, twice->h, twice->sc.domain, s2[0], s2[1], w2, links - 1, steps) == links - 1;
      }
    }
  }
}

// Layouts where a first version went wrong (each from a random seed), with the fewest links: the
// path is judged as in the random test, has exactly that many links, and the lattice search at
// half-integers finds a path with that many and none with fewer, so the count is the minimum.
//   - a frontier that turns round a corner while alpha's exit point stays (c:0,135, first case);
//   - the corner of a blockage that alpha wraps bounds the frontier only when the material lies
//     just behind it, not ahead (c:45,90,135 and c:0,135 round the notch);
//   - rays along a triangulation edge lie in both triangles (c:90,135 round the diamond);
//   - the walk back reaches the blocked end of a frontier segment (c:0,45, at the domain's side)
//     or a vertex just where it starts (c:0,135 between triangles);
//   - the walk back must look in every lifted triangle that holds the ray, across an edge it runs
//     along (c:45,90 between two rectangles' corners);
//   - rays crossing the frontier ray from q's side only cover it; half-integer bends between the
//     diagonals (c:45,135 past a spike).
TEST(CMinLink, RegressionCases) {
  struct Case {
    const char* set;
    std::vector<std::vector<Point>> rings;
    Path sketch;
    int links;
  };
  auto box = [](int x0, int y0, int x1, int y1) { return std::vector<Point>{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; };
  const std::vector<Point> hook{{1, 2}, {2, 2}, {2, 1}, {3, 1}, {3, 5}, {1, 5}};
  const std::vector<Point> spike{{1, 1}, {2, 2}, {3, 4}, {3, 2}, {6, 2}, {6, 5}, {3, 5}, {3, 6}, {2, 5}, {1, 8}};
  const std::vector<Case> cases{
      {"c:0,135", {spike}, {{0, 8}, {6, 8}, {2, 6}}, 3},
      {"c:0,45", {hook, box(4, 3, 6, 6)}, {{1, 4}, {1, 2}, {1, 5}, {6, 9}, {8, 4}}, 5},
      {"c:45,90,135", {hook, box(4, 3, 6, 6)}, {{1, 4}, {1, 2}, {1, 5}, {6, 9}, {8, 4}}, 3},
      {"c:0,135", {{{3, 3}, {7, 3}, {7, 6}, {5, 6}, {6, 8}, {4, 6}, {3, 6}}}, {{6, 9}, {7, 6}, {7, 3}}, 5},
      {"c:90,135", {box(2, 8, 3, 9), box(5, 8, 6, 9), {{6, 7}, {7, 6}, {8, 7}, {7, 8}}},
       {{2, 2}, {3, 4}, {1, 2}, {6, 8}, {9, 9}, {8, 7}, {9, 2}, {1, 2}, {9, 2}}, 5},
      {"c:0,135", {{{1, 5}, {5, 3}, {2, 6}}, {{2, 8}, {9, 4}, {8, 6}}}, {{4, 8}, {3, 9}, {0, 9}, {1, 2}}, 5},
      {"c:45,90", {box(3, 2, 6, 5), box(6, 6, 7, 8)}, {{9, 2}, {6, 5}, {3, 5}, {3, 2}, {6, 2}, {6, 8}, {8, 8}}, 12},
      {"c:45,135", {spike}, {{0, 8}, {6, 8}, {2, 6}}, 3},
  };
  int checked = 0;
  for (const Case& c : cases) {
    std::vector<geom::Polygon> polys;
    for (const auto& r : c.rings) polys.push_back(poly(r));
    const Scene sc = normalized({{0, 0}, {9, 9}}, polys);
    const auto j = judge(sc);
    ASSERT_TRUE(j && j->st.t.ok()) << c.set << " " << str(c.sketch);
    const auto j2 = judge(scaled(sc, 2));
    ASSERT_TRUE(j2);
    const router::Tightened tt = j->st.tight->tighten(c.sketch);
    ASSERT_EQ(tt.status, router::TightenStatus::Ok);
    const auto set = geom::LatticeDirections::parse(c.set);
    const router::CMinLinkPath m = router::CMinLinker(j->st.t).path(tt.points, *set);
    const std::string at = std::string(c.set) + " sketch " + str(c.sketch) + " path " + qstr(m.points);
    ASSERT_TRUE(m.ok()) << at << ": " << m.why;
    const std::vector<int> word = j->h.word(c.sketch);
    EXPECT_EQ(path_problem(m.points, *set, sc, j->h, j->ref, &word), "") << at;
    const int links = static_cast<int>(m.links());
    EXPECT_EQ(links, c.links) << at;
    Path s2;
    for (Point p : c.sketch) s2.push_back({p.x * 2, p.y * 2});
    const std::vector<int> w2 = j2->h.word(s2);
    const unsigned steps = step_mask(*set);
    EXPECT_EQ(fewest_bends_any_length(j2->ref, j2->h, j2->sc.domain, s2.front(), s2.back(), w2, links - 1, steps), links - 1) << at;
    if (links >= 2) {
      EXPECT_EQ(fewest_bends_any_length(j2->ref, j2->h, j2->sc.domain, s2.front(), s2.back(), w2, links - 2, steps), -1) << at;
    }
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(cases.size()));
}

TEST(CMinLink, RandomSketchesAgainstTheReferences) {
  Totals tot;
  long long sketches = 0;
  const long long scenes = for_each_small_scene(
      static_cast<int>(sanitized_share(20, 10)), 9, 131, 7919,  // / 4 under the sanitizers until 2026-12-04
      [&](int seed, int kind, const Judged& j, const Path& pts, std::mt19937_64& rng64) {
        const auto j2 = judge(scaled(j.sc, 2));
        Sketcher sk{j.ref, j.h, pts, rng64};
        for (int t = 0; t < 3; ++t) {
          const auto ts = taut_sketch(sk, *j.st.tight, 2 + static_cast<int>(rng64() % 4), t == 2);
          if (!ts) continue;
          ++sketches;
          const std::string where = "seed " + std::to_string(seed) + " kind " + std::to_string(kind) + " (" +
                                    scene_str(j.sc) + ") sketch " + str(ts->sketch);
          judge_sketch(j, ts->sketch, ts->taut.points, where, tot, t == 0 ? j2.get() : nullptr);
        }
      });
  std::printf("%lld scenes, %lld sketches: %lld minimum-link paths (%lld links, %lld bends at non-integers, %lld sweeps), "
              "%lld with no path; %lld equal to the shortest wire's links under the halfplane condition, %lld with "
              "fewer links than the shortest wire; lattice search on %lld (as many links found on %lld), at "
              "half-integers on %lld (on %lld)\n",
              scenes, sketches, tot.paths, tot.links, tot.rational_bends, tot.sweeps, tot.none, tot.halfplane_equal,
              tot.fewer_than_shortest, tot.searched, tot.search_tight, tot.scaled_searched, tot.scaled_tight);
  EXPECT_GE(tot.paths, sanitized_share(3500, 10));  // 3,928 here
  // the searches are not vacuous: they find a path with as many links most of the time
  EXPECT_GE(tot.search_tight * 10, tot.searched * 8);
  EXPECT_GE(tot.scaled_tight * 100, tot.scaled_searched * 95);
}

// Loops in a direction set (CMinLinker::loop), judged by the references above: the loop is
// closed, every link runs along the set in free space, every turn (the closing one too) lies in
// one free wedge, and its cyclically reduced cut word equals the input's up to rotation (freely
// homotopic); it has at least its lower bound, and is called minimal exactly when it meets it.
// The lattice search then looks for a loop with fewer links: from every lattice point x with one
// free wedge, for every rotation r of the input's cyclic word, the fewest bends of a lattice path
// from x back to x whose reduced word is r (a path of b bends closes into a loop of at most b + 1
// links). A loop called minimal must not be beaten; how often the search finds as few links, and
// how often it beats a loop not called minimal, is reported. The search runs in rectilinear on
// every loop of at most six links and in octilinear on the first loop of each scene; with
// TAUT_LOOP_SEARCH_ALL set, in every set (about 6 minutes; 2026-12-03: 697 loops searched, as few
// links found on 688, fewer on none).
struct LoopTotals {
  long long loops = 0, none = 0, minimal = 0, open = 0, starts = 0, searched = 0, search_equal = 0, search_beats = 0;
};

router::CMinLinkLoop judge_loop(const Judged& j, const Path& taut, const std::vector<int>& cyclic,
                                const geom::LatticeDirections& set, const std::string& where, LoopTotals& tot,
                                const Path* search_points) {
  const router::CMinLinkLoop c = router::CMinLinker(j.st.t).loop(taut, set);
  tot.starts += static_cast<long long>(c.starts);
  const std::string at = where + " " + set.name() + " taut " + str(taut) + " loop " + qstr(c.points) +
                         (c.minimal ? " (minimal)" : "") + " at least " + std::to_string(c.at_least);
  if (!c.ok()) {
    ++tot.none;
    return c;
  }
  ++tot.loops;
  tot.minimal += c.minimal;
  tot.open += !c.minimal;
  EXPECT_GE(c.points.size(), 4u) << at;
  if (c.points.size() < 4) return c;
  EXPECT_TRUE(c.points.front() == c.points.back()) << at << ": not closed";
  std::vector<RPoint> wrapped_loop = c.points;
  wrapped_loop.push_back(c.points[1]);  // the closing turn as an interior bend
  EXPECT_EQ(path_problem(wrapped_loop, set, j.sc, j.h, j.ref, nullptr), "") << at;
  std::vector<oracle::QPoint> q;
  for (const RPoint& p : c.points) q.push_back(qp(p));
  EXPECT_TRUE(same_up_to_rotation(cyclic_word(j.h.word(std::span<const oracle::QPoint>(q))), cyclic))
      << at << ": another free homotopy class";
  EXPECT_GE(c.links(), c.at_least) << at;
  EXPECT_EQ(c.minimal, c.links() == c.at_least) << at;
  if (search_points && c.links() <= 6) {
    ++tot.searched;
    const unsigned steps = step_mask(set);
    int best = -1;
    for (std::size_t r = 0; r < std::max<std::size_t>(1, cyclic.size()); ++r) {
      std::vector<int> rot(cyclic.begin() + static_cast<std::ptrdiff_t>(r), cyclic.end());
      rot.insert(rot.end(), cyclic.begin(), cyclic.begin() + static_cast<std::ptrdiff_t>(r));
      for (const Point x : *search_points) {
        const int cap = best < 0 ? static_cast<int>(c.links()) - 1 : best - 2;  // b + 1 links: at most as many as so far
        if (cap < 1) break;
        const int b = fewest_bends_closed(j.ref, j.h, j.sc.domain, x, rot, cap, steps);
        if (b >= 0) best = b + 1;
      }
    }
    if (c.minimal) {
      EXPECT_TRUE(best < 0 || best >= static_cast<int>(c.links())) << at << ": a lattice loop of " << best << " links";
    }
    tot.search_equal += best == static_cast<int>(c.links());
    tot.search_beats += best >= 0 && best < static_cast<int>(c.links());
  }
  return c;
}

TEST(CMinLinkLoop, HandCases) {
  const SquareLoop sq = square_loop();
  ASSERT_TRUE(sq.ok());
  const auto& [j, once, l, cyc] = sq;
  LoopTotals tot;
  struct Want {
    const char* set;
    std::size_t links;
  };
  // round a square: a box in rectilinear, a right isosceles triangle in octilinear (its legs on
  // two sides of the square, its hypotenuse through the far corner), a diamond in the diagonals
  for (const Want& w : {Want{"rectilinear", 4}, Want{"octilinear", 3}, Want{"c:45,135", 4}, Want{"c:0,45", 4},
                        Want{"c:0,45,90", 3}}) {
    const auto set = geom::LatticeDirections::parse(w.set);
    const router::CMinLinkLoop c = judge_loop(*j, l.points, cyc, *set, w.set, tot, nullptr);
    EXPECT_EQ(c.links(), w.links) << w.set << " " << qstr(c.points);
    EXPECT_TRUE(c.minimal) << w.set;
  }
  // twice round, rectilinear: the winding bound (5, even: 6) is below what is found (8: a
  // rectilinear loop turns by right angles), so not proven
  const Path twice{{20, 50}, {50, 10}, {90, 50}, {50, 90}, {20, 50}, {50, 10}, {90, 50}, {50, 90}, {20, 50}};
  const router::Tightener::Loop l2 = j->st.tight->tighten_loop(twice);
  ASSERT_EQ(l2.status, router::TightenStatus::Ok);
  const router::CMinLinkLoop c2 =
      judge_loop(*j, l2.points, cyclic_word(j->h.word(twice)), geom::LatticeDirections::rectilinear(), "twice", tot, nullptr);
  EXPECT_EQ(c2.at_least, 6u);
  EXPECT_EQ(c2.links(), 8u) << qstr(c2.points);
  EXPECT_FALSE(c2.minimal);
  // a diamond blockage: a box round it in rectilinear, the diamond's own edges in the diagonals
  const Scene sd = normalized({{0, 0}, {100, 100}}, {poly({{50, 30}, {70, 50}, {50, 70}, {30, 50}})});
  const auto jd = judge(sd);
  ASSERT_TRUE(jd && jd->st.t.ok());
  const router::Tightener::Loop ld = jd->st.tight->tighten_loop(once);
  ASSERT_EQ(ld.status, router::TightenStatus::Ok);
  const std::vector<int> cd = cyclic_word(jd->h.word(once));
  for (const char* name : {"rectilinear", "c:45,135", "octilinear"}) {
    const router::CMinLinkLoop c = judge_loop(*jd, ld.points, cd, *geom::LatticeDirections::parse(name), name, tot, nullptr);
    EXPECT_EQ(c.links(), std::string(name) == "octilinear" ? 3u : 4u) << name << " " << qstr(c.points);
  }
  EXPECT_EQ(tot.none, 0);
}

TEST(CMinLinkLoop, RandomLoopsAgainstTheReferences) {
  LoopTotals tot;
  long long taut_loops = 0;
  const bool all_sets = std::getenv("TAUT_LOOP_SEARCH_ALL") != nullptr;
  const long long scenes = for_each_random_loop(
      // 20 seeds until 2026-12-06 (make test's time on CI: the slowest test of both trees); four
      // loops of each scene of one seed under the sanitizers, where its six took 33 s (9 s now)
      static_cast<int>(sanitized_share(14, 14)), kSanitized ? 4 : 6,
      [&](const Judged& j, const Path& pts, int t, const TautLoop& tl, const std::vector<int>& cyc,
          const std::string& where0) {
        ++taut_loops;
        const std::string where = where0 + " (" + scene_str(j.sc) + ")";
        for (unsigned mask = 1; mask < 16; ++mask) {
          const auto set = geom::LatticeDirections::from_mask(mask);
          if (!set) continue;
          // the search in rectilinear, and in octilinear on the first loop of each scene
          const bool search = all_sets || set->name() == "rectilinear" || (t == 0 && set->name() == "octilinear");
          judge_loop(j, tl.taut.points, cyc, *set, where, tot, search ? &pts : nullptr);
        }
      });
  std::printf("%lld scenes, %lld loops not contractible: %lld loops in lattice sets (%lld minimal, %lld above the lower "
              "bound; %lld starts), %lld with none; lattice search on %lld: as few links on %lld, fewer on %lld\n",
              scenes, taut_loops, tot.loops, tot.minimal, tot.open, tot.starts, tot.none, tot.searched,
              tot.search_equal, tot.search_beats);
  EXPECT_GE(tot.loops, kSanitized ? 25 : 850);  // 913 here (1,221 of 20 seeds; 33 under the sanitizers)
  EXPECT_EQ(tot.none, 0);
  EXPECT_GE(tot.searched, kSanitized ? 1 : 35);  // 38 here
  // the search is not vacuous: it finds a loop with as many links most of the time
  EXPECT_GE(tot.search_equal * 10, tot.searched * 8);
}

}  // namespace c_minlink_test
}  // namespace taut::test
