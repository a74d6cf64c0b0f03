// router::L1Router::steiner (rectilinear Steiner trees among blockages, issue #7) against the
// exact Steiner minimal length of tests/oracle/steiner_oracle.h (Dreyfus-Wagner on the extended
// Hanan grid), on random layouts of rectangles that stay apart (the oracle's domain) and without
// blockages, 2 to 7 pins: every tree is legal by the independent checker (router/check.h: in
// free space, joining every pin, no stray wire), its length is what its wires measure, at least
// the minimum, equal to it for two pins, and at most twice it (Prim's rule never exceeds the
// terminals' minimum spanning tree, itself at most twice the Steiner minimum); unreachable pins
// exactly when the oracle finds no tree. The mean and worst excess over the minimum are printed
// and held to the target (mean under 2 %, worst under 10 %); the improvement pass never
// lengthens a tree (against the same search without it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>

#include "geom/normalize.h"
#include "oracle/oct_oracle.h"
#include "oracle/oct_steiner_oracle.h"
#include "oracle/steiner_oracle.h"
#include "router/check.h"
#include "router/l1_router.h"
#include "router/oct_router.h"
#include "router/pin_shapes.h"
#include "support/random_shapes.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"

namespace taut::test {
namespace steiner_test {

using geom::Point;

// The first thing wrong with tree `t` of the net whose pins are `pins` (checker pins, each a
// point or a shape): a problem of the independent checker, a segment in another orientation than
// the router's (L1Router: horizontal and vertical; OctRouter: diagonal too), or a length other
// than its wires'.
template <class Steiner>
std::optional<std::string> tree_problem(const geom::NormalizedObstacles& norm, std::vector<router::CheckPin> pins,
                                        const Steiner& t) {
  constexpr bool kOct = std::is_same_v<Steiner, router::OctRouter::Steiner>;
  router::CheckNet net;
  net.name = "n";
  net.routed = true;
  net.pins = std::move(pins);
  for (const auto& w : t.wires) net.wires.push_back({w, 100});
  const router::CheckResult check = router::check_routes(norm, std::vector<router::CheckNet>{net});
  if (!check.problems.empty()) return check.problems[0].message;
  decltype(t.length) measured{};
  for (const auto& w : t.wires)
    for (std::size_t i = 1; i < w.size(); ++i) {
      const std::int64_t dx = std::int64_t{w[i].x} - w[i - 1].x, dy = std::int64_t{w[i].y} - w[i - 1].y;
      if (kOct ? !oracle::is_octilinear(w[i - 1], w[i]) : dx != 0 && dy != 0) return "a segment in another orientation";
      if constexpr (kOct) measured += geom::octilinear_length(dx, dy);
      else measured += std::abs(dx) + std::abs(dy);
    }
  if (measured != t.length) {
    std::ostringstream o;
    o << "length " << t.length << ", wires " << measured;
    return o.str();
  }
  return std::nullopt;
}

TEST(SteinerTree, LegalAndNearTheMinimum) {
  int failed = 0, trees = 0, optimal = 0, with_blockages = 0, improved = 0, plain_optimal = 0;
  double excess_sum = 0, worst = 0, single_sum = 0, plain_sum = 0, plain_worst = 0;
  int worst_seed = 0;
  for (int seed = 1; seed <= (kSanitized ? 150 : 1500); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(91000 + seed));
    const int want_boxes = seed % 4 == 0 ? 0 : static_cast<int>(rng() % 7);
    const std::vector<geom::Box> boxes = random_boxes_apart(rng, want_boxes, 1, 34, 8);
    const std::vector<geom::Polygon> polys = box_polygons(boxes);
    const geom::Box domain{{0, 0}, {44, 44}};
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(polys, domain);
    router::L1Router router(norm.domain, norm.obstacles);
    std::vector<Point> pins;
    const std::size_t k = 2 + rng() % 6;
    while (pins.size() < k) {
      const Point p{static_cast<geom::Coord>(rng() % 45), static_cast<geom::Coord>(rng() % 45)};
      if (router.is_free(p)) pins.push_back(p);
    }
    const auto best = oracle::steiner_minimal_length(norm.domain, norm.obstacles, pins);
    const auto t = router.steiner(pins);
    const auto single = router.steiner(pins, 1);  // grown from the first pin only (printed)
    const auto plain = router.steiner(pins, 8, false);  // without the improvement pass
    if (single.status == router::WireStatus::Ok) single_sum += *best > 0 ? static_cast<double>(single.length - *best) / static_cast<double>(*best) : 0.0;
    const std::string at = "seed " + std::to_string(seed);
    if (!best) {
      if (t.status != router::WireStatus::Unreachable && failed++ < 8) ADD_FAILURE() << at << ": the oracle finds no tree";
      continue;
    }
    if (t.status != router::WireStatus::Ok) {
      if (failed++ < 8) ADD_FAILURE() << at << ": " << router::to_string(t.status);
      continue;
    }
    ++trees;
    with_blockages += !boxes.empty();
    // legal, by the independent checker
    std::vector<router::CheckPin> check_pins;
    for (std::size_t i = 0; i < pins.size(); ++i) check_pins.push_back({"p" + std::to_string(i), pins[i], std::nullopt, static_cast<int>(i)});
    if (const auto problem = tree_problem(norm, std::move(check_pins), t); problem && failed++ < 8) ADD_FAILURE() << at << ": " << *problem;
    if ((t.length < *best || t.length > 2 * *best || (k == 2 && t.length != *best)) && failed++ < 8)
      ADD_FAILURE() << at << ": " << k << " pins, length " << t.length << ", minimum " << *best;
    const double excess = *best > 0 ? static_cast<double>(t.length - *best) / static_cast<double>(*best) : 0.0;
    excess_sum += excess;
    optimal += t.length == *best;
    if (excess > worst) worst = excess, worst_seed = seed;
    // the improvement pass never lengthens the tree (the best start's tree, improved or not, is
    // at most the best unimproved one) and says when it changed it
    if (plain.status != router::WireStatus::Ok || t.length > plain.length) {
      if (failed++ < 8) ADD_FAILURE() << at << ": improved " << t.length << ", without the pass " << plain.length;
      continue;
    }
    improved += t.length < plain.length;
    if (t.length < plain.length && t.improved == 0 && failed++ < 8) ADD_FAILURE() << at << ": shorter, but no change counted";
    const double plain_excess = *best > 0 ? static_cast<double>(plain.length - *best) / static_cast<double>(*best) : 0.0;
    plain_sum += plain_excess;
    plain_worst = std::max(plain_worst, plain_excess);
    plain_optimal += plain.length == *best;
  }
  std::printf("%d trees (%d among blockages): %d minimal, mean excess %.2f%%, worst %.2f%% (seed %d); grown from the first pin "
              "only: mean excess %.2f%%; without the improvement pass: %d minimal, mean excess %.2f%%, worst %.2f%% (the "
              "pass shortened %d)\n",
              trees, with_blockages, optimal, 100 * excess_sum / std::max(trees, 1), 100 * worst, worst_seed,
              100 * single_sum / std::max(trees, 1), plain_optimal, 100 * plain_sum / std::max(trees, 1), 100 * plain_worst,
              improved);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(trees, kSanitized ? 100 : 1000);
  // The target: a mean excess under 2 % and a worst under 10 %. With the Steiner point
  // moves, ten sets of 1,500 nets (this one and nine other seed bases) gave means of 0.03-0.07 %
  // and worsts of 3.7-7.7 % (before them: 0.10 % and 11.1 % here, 15.7 % on one other set).
  EXPECT_LT(excess_sum / std::max(trees, 1), 0.02);
  EXPECT_LT(worst, 0.10);
  EXPECT_GT(improved, kSanitized ? 5 : 100);
}

// Shape pins (rectangular pads, which may touch blockages, mixed with point pins): every tree is
// legal by the independent checker (free, every pin joined: a wire ending anywhere on a pad joins
// it), never shorter than the exact minimum with pads as terminals (oracle::steiner_minimal_length
// with boxes: Dreyfus-Wagner with every grid node of a pad in its terminal), and near it.
// Adds pin g (a point or a pad) to a net being drawn when its box stays within [0, limit], keeps
// a gap from every pin so far (pins do not touch one another), and the router takes it there
// (a free point; a pad that meets no blockage's interior and has a candidate point).
template <class Router>
bool add_pin_apart(const Router& router, const geom::Polygon& g, geom::Coord limit, std::vector<geom::Box>& terms,
                   std::vector<geom::Polygon>& pins) {
  geom::Box b{g.outer[0], g.outer[0]};
  for (const Point v : g.outer) b = {{std::min(b.lo.x, v.x), std::min(b.lo.y, v.y)}, {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y)}};
  if (b.hi.x > limit || b.hi.y > limit) return false;
  for (const geom::Box& o : terms)
    if (geom::boxes_meet(geom::grown_box(b, 1), o)) return false;
  const bool pad = g.outer.size() > 1;
  if (pad ? router.pin_meets_obstacle(g).has_value() : !router.is_free(g.outer[0])) return false;
  if (pad && router.pin_candidates(g, g).empty()) return false;
  terms.push_back(b);
  pins.push_back(g);
  return true;
}

// A tree of pins that may be pads, judged against the oracle's minimum `best`: none when the
// oracle finds no tree (then the router must not either), a failure for a status other than Ok,
// then legality (tree_problem, the pads as shape pins) and never below the minimum. Returns the
// relative excess over the minimum when the tree counts.
template <class Len, class Steiner>
std::optional<double> judge_pad_tree(const geom::NormalizedObstacles& norm, const std::vector<geom::Polygon>& pins,
                                     const std::optional<Len>& best, const Steiner& t, const std::string& at, int& failed) {
  if (!best) {
    if (t.status == router::WireStatus::Ok && failed++ < 8) ADD_FAILURE() << at << ": the oracle finds no tree";
    return std::nullopt;
  }
  if (t.status != router::WireStatus::Ok) {
    if (failed++ < 8) ADD_FAILURE() << at << ": " << router::to_string(t.status);
    return std::nullopt;
  }
  std::vector<router::CheckPin> check_pins;
  for (std::size_t i = 0; i < pins.size(); ++i) {
    if (pins[i].outer.size() == 1) check_pins.push_back({"p" + std::to_string(i), pins[i].outer[0], std::nullopt, static_cast<int>(i)});
    else check_pins.push_back({"p" + std::to_string(i), std::nullopt, pins[i], static_cast<int>(i)});
  }
  if (const auto problem = tree_problem(norm, std::move(check_pins), t); problem && failed++ < 8) ADD_FAILURE() << at << ": " << *problem;
  if (t.length < *best && failed++ < 8) ADD_FAILURE() << at << ": length " << t.length << " below the minimum " << *best;
  auto as_double = [](const Len& l) {
    if constexpr (std::is_same_v<Len, geom::Root2>) return l.to_double();
    else return static_cast<double>(l);
  };
  const double b = as_double(*best);
  return b > 0 ? (as_double(t.length) - b) / b : 0.0;
}

TEST(SteinerTree, PadsLegalAndNearTheMinimum) {
  int failed = 0, trees = 0, optimal = 0, pads_total = 0, improved = 0;
  double excess_sum = 0, worst = 0, spt_sum = 0, plain_sum = 0, plain_worst = 0;
  int worst_seed = 0;
  for (int seed = 1; seed <= (kSanitized ? 60 : 600); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(57000 + seed));
    const int want_boxes = seed % 4 == 0 ? 0 : static_cast<int>(rng() % 6);
    const std::vector<geom::Box> boxes = random_boxes_apart(rng, want_boxes, 1, 34, 8);
    const geom::Box domain{{0, 0}, {44, 44}};
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(box_polygons(boxes), domain);
    router::L1Router router(norm.domain, norm.obstacles);
    std::vector<geom::Box> terms;  // each pin's box (a point: a box of one point)
    std::vector<geom::Polygon> pins;
    const std::size_t k = 3 + rng() % 5;
    for (int tries = 0; tries < 400 && pins.size() < k; ++tries) {
      const Point p{static_cast<geom::Coord>(rng() % 42), static_cast<geom::Coord>(rng() % 42)};
      const bool pad = rng() % 2 == 0;
      const geom::Box b{p, pad ? Point{static_cast<geom::Coord>(p.x + 1 + static_cast<int>(rng() % 4)),
                                       static_cast<geom::Coord>(p.y + 1 + static_cast<int>(rng() % 4))}
                               : p};
      add_pin_apart(router, pad ? box_polygons(std::vector<geom::Box>{b})[0] : geom::Polygon{{p}, {}}, 44, terms, pins);
    }
    if (pins.size() < 3) continue;
    const auto best = oracle::steiner_minimal_length(norm.domain, norm.obstacles, std::span<const geom::Box>(terms));
    const auto t = router.steiner(std::span<const geom::Polygon>(pins));
    const std::string at = "seed " + std::to_string(seed);
    const std::optional<double> judged = judge_pad_tree(norm, pins, best, t, at, failed);
    if (!judged) continue;
    ++trees;
    for (const geom::Polygon& pin : pins) pads_total += pin.outer.size() > 1;
    const double excess = *judged;
    excess_sum += excess;
    optimal += t.length == *best;
    if (excess > worst) worst = excess, worst_seed = seed;
    // without the improvement pass (the path re-embedding with the pads as metal)
    const auto plain = router.steiner(std::span<const geom::Polygon>(pins), 8, false);
    if (plain.status != router::WireStatus::Ok || plain.length < t.length) {
      if (failed++ < 8) ADD_FAILURE() << at << ": improved " << t.length << ", without the pass " << plain.length;
    } else {
      improved += plain.length > t.length;
      const double e = *best > 0 ? static_cast<double>(plain.length - *best) / static_cast<double>(*best) : 0.0;
      plain_sum += e;
      plain_worst = std::max(plain_worst, e);
    }
    // against the shortest-path tree from the first pin (what these nets got before)
    const auto spt = router.tree(pins[0], std::span<const geom::Polygon>(pins).subspan(1));
    if (spt.status == router::WireStatus::Ok) {
      std::int64_t l = 0;
      for (const auto& w : spt.wires)
        for (std::size_t i = 1; i < w.size(); ++i) l += std::abs(w[i].x - w[i - 1].x) + std::abs(w[i].y - w[i - 1].y);
      spt_sum += *best > 0 ? static_cast<double>(l - *best) / static_cast<double>(*best) : 0.0;
    }
  }
  std::printf("%d trees with %d pads: %d minimal, mean excess %.2f%%, worst %.2f%% (seed %d); without the improvement "
              "pass mean %.2f%%, worst %.2f%% (the pass shortened %d); the shortest-path tree from the first pin: mean "
              "excess %.2f%%\n",
              trees, pads_total, optimal, 100 * excess_sum / std::max(trees, 1), 100 * worst, worst_seed,
              100 * plain_sum / std::max(trees, 1), 100 * plain_worst, improved, 100 * spt_sum / std::max(trees, 1));
  EXPECT_EQ(failed, 0);
  EXPECT_GE(trees, kSanitized ? 40 : 400);
  EXPECT_GE(pads_total, kSanitized ? 40 : 400);
  // the target, as for point pins: a mean excess under 2 % and a worst under 10 %
  EXPECT_LT(excess_sum / std::max(trees, 1), 0.02);
  EXPECT_LT(worst, 0.10);
  EXPECT_GT(improved, kSanitized ? 1 : 20);
}

// OCTILINEAR Steiner trees (OctRouter::steiner) against the exact minimum among octilinear
// trees with integer vertices (oracle::oct_steiner_minimal_length: Dreyfus-Wagner on the
// 8-connected lattice), on random layouts of rectangles that stay apart and without blockages,
// 2 to 6 point pins: every tree is legal by the independent checker, every segment horizontal,
// vertical or diagonal, its length (a + b sqrt2, exact) is what its wires measure, at least the
// minimum, equal to it for two pins (a shortest octilinear path), and at most twice it (Prim's
// rule with exact distances: at most the terminals' minimum spanning tree); unreachable exactly
// when the oracle finds no tree; the improvement pass (path re-embedding and Steiner point moves)
// never lengthens a tree. Printed: the mean and worst excess, without the pass too, and the
// shortest-path tree's (what octilinear nets got before). Held to the target for trees
// (mean under 2 %, worst under 10 %).
TEST(SteinerTree, OctilinearLegalAndNearTheMinimum) {
  int failed = 0, trees = 0, optimal = 0, with_blockages = 0, spt_trees = 0, improved = 0;
  double excess_sum = 0, worst = 0, spt_sum = 0, plain_sum = 0, plain_worst = 0;
  int worst_seed = 0;
  for (int seed = 1; seed <= (kSanitized ? 100 : 1000); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(73000 + seed));
    const int want_boxes = seed % 4 == 0 ? 0 : static_cast<int>(rng() % 6);
    const std::vector<geom::Box> boxes = random_boxes_apart(rng, want_boxes, 1, 22, 7);
    const geom::Box domain{{0, 0}, {30, 30}};
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(box_polygons(boxes), domain);
    router::OctRouter router(norm.domain, norm.obstacles);
    std::vector<Point> pins;
    const std::size_t k = 2 + rng() % 5;
    while (pins.size() < k) {
      const Point p{static_cast<geom::Coord>(rng() % 31), static_cast<geom::Coord>(rng() % 31)};
      if (router.is_free(p)) pins.push_back(p);
    }
    const auto best = oracle::oct_steiner_minimal_length(norm.domain, norm.obstacles, pins);
    const auto t = router.steiner(pins);
    const std::string at = "seed " + std::to_string(seed);
    if (!best) {
      if (t.status != router::WireStatus::Unreachable && failed++ < 8) ADD_FAILURE() << at << ": the oracle finds no tree";
      continue;
    }
    if (t.status != router::WireStatus::Ok) {
      if (failed++ < 8) ADD_FAILURE() << at << ": " << router::to_string(t.status);
      continue;
    }
    ++trees;
    with_blockages += !boxes.empty();
    std::vector<router::CheckPin> check_pins;
    for (std::size_t i = 0; i < pins.size(); ++i) check_pins.push_back({"p" + std::to_string(i), pins[i], std::nullopt, static_cast<int>(i)});
    if (const auto problem = tree_problem(norm, std::move(check_pins), t); problem && failed++ < 8) ADD_FAILURE() << at << ": " << *problem;
    if ((t.length < *best || t.length > *best + *best || (k == 2 && t.length != *best)) && failed++ < 8)
      ADD_FAILURE() << at << ": " << k << " pins, length " << t.length << ", minimum " << *best;
    const double b = best->to_double();
    const double excess = b > 0 ? (t.length.to_double() - b) / b : 0.0;
    excess_sum += excess;
    optimal += t.length == *best;
    if (excess > worst) worst = excess, worst_seed = seed;
    // without the improvement pass: never shorter
    const auto plain = router.steiner(pins, 8, false);
    if (plain.status != router::WireStatus::Ok || t.length > plain.length) {
      if (failed++ < 8) ADD_FAILURE() << at << ": improved " << t.length << ", without the pass " << plain.length;
    } else {
      improved += t.length < plain.length;
      if (t.length < plain.length && t.improved == 0 && failed++ < 8) ADD_FAILURE() << at << ": shorter, but no change counted";
      const double e = b > 0 ? (plain.length.to_double() - b) / b : 0.0;
      plain_sum += e;
      plain_worst = std::max(plain_worst, e);
    }
    // the shortest-path tree from the first pin (what octilinear nets got before)
    const auto spt = router.tree(geom::Polygon{{pins[0]}, {}}, [&] {
      std::vector<geom::Polygon> sinks;
      for (std::size_t i = 1; i < pins.size(); ++i) sinks.push_back({{pins[i]}, {}});
      return sinks;
    }());
    if (spt.status == router::WireStatus::Ok) {
      geom::Root2 l{};
      for (const auto& w : spt.wires)
        for (std::size_t i = 1; i < w.size(); ++i) l += geom::octilinear_length(std::int64_t{w[i].x} - w[i - 1].x, std::int64_t{w[i].y} - w[i - 1].y);
      spt_sum += b > 0 ? (l.to_double() - b) / b : 0.0;
      ++spt_trees;
    }
  }
  std::printf("%d octilinear trees (%d among blockages): %d minimal, mean excess %.2f%%, worst %.2f%% (seed %d); "
              "without the improvement pass: mean excess %.2f%%, worst %.2f%% (the pass shortened %d); shortest-path "
              "trees from the first pin: mean excess %.2f%%\n",
              trees, with_blockages, optimal, 100 * excess_sum / std::max(trees, 1), 100 * worst, worst_seed,
              100 * plain_sum / std::max(trees, 1), 100 * plain_worst, improved, 100 * spt_sum / std::max(spt_trees, 1));
  EXPECT_EQ(failed, 0);
  EXPECT_GE(trees, kSanitized ? 70 : 700);
  EXPECT_LT(excess_sum / std::max(trees, 1), 0.02);
  EXPECT_LT(worst, 0.10);
  EXPECT_GT(improved, kSanitized ? 5 : 50);
}

// OCTILINEAR Steiner trees with pads (shape pins with edges at 0, 45 and 90 degrees: rectangles,
// diamonds, 45-degree triangles, boxes with a cut corner; pads taken by octilinear wires since
// 2026-12-03) and point pins, 3 to 6 pins, against oracle::oct_steiner_minimal_length with shape
// terminals (a pad is metal: joined at no cost to each of its lattice points): every tree legal
// by the independent checker, octilinear, its length what its wires measure, at least the
// minimum; the mean and worst excess printed and held to the target.
TEST(SteinerTree, OctilinearPadsLegalAndNearTheMinimum) {
  int failed = 0, trees = 0, optimal = 0, pads_total = 0, diagonal_pads = 0;
  double excess_sum = 0, worst = 0;
  int worst_seed = 0;
  for (int seed = 1; seed <= (kSanitized ? 40 : 400); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(91000 + seed));
    const int want_boxes = seed % 4 == 0 ? 0 : static_cast<int>(rng() % 5);
    const std::vector<geom::Box> boxes = random_boxes_apart(rng, want_boxes, 1, 22, 7);
    const geom::Box domain{{0, 0}, {30, 30}};
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(box_polygons(boxes), domain);
    router::OctRouter router(norm.domain, norm.obstacles);
    std::vector<geom::Box> terms;  // each pin's box
    std::vector<geom::Polygon> pins;
    const std::size_t k = 3 + rng() % 4;
    for (int tries = 0; tries < 400 && pins.size() < k; ++tries) {
      const geom::Coord x = static_cast<geom::Coord>(rng() % 27), y = static_cast<geom::Coord>(rng() % 27);
      const geom::Coord r = static_cast<geom::Coord>(1 + rng() % 2), c = static_cast<geom::Coord>(2 * r);
      geom::Polygon g;
      switch (rng() % 5) {
        case 0: g = geom::Polygon{{{x, y}}, {}}; break;
        case 1: g = box_polygons(std::vector<geom::Box>{{{x, y}, {x + c, y + r}}})[0]; break;
        case 2: g = geom::Polygon{{{x + r, y}, {x + c, y + r}, {x + r, y + c}, {x, y + r}}, {}}; break;  // diamond
        case 3: g = geom::Polygon{{{x, y}, {x + c, y}, {x, y + c}}, {}}; break;  // 45-degree triangle
        default: g = geom::Polygon{{{x, y}, {x + c + 1, y}, {x + c + 1, y + r}, {x + r + 1, y + c}, {x, y + c}}, {}};  // a cut corner
      }
      add_pin_apart(router, g, 30, terms, pins);
    }
    if (pins.size() < 3) continue;
    const auto best = oracle::oct_steiner_minimal_length(norm.domain, norm.obstacles, std::span<const geom::Polygon>(pins));
    const auto t = router.steiner(std::span<const geom::Polygon>(pins));
    const std::string at = "seed " + std::to_string(seed);
    const std::optional<double> judged = judge_pad_tree(norm, pins, best, t, at, failed);
    if (!judged) continue;
    ++trees;
    for (const geom::Polygon& pin : pins) {
      if (pin.outer.size() == 1) continue;
      ++pads_total;
      bool diagonal = false;
      router::for_each_pin_edge(pin, [&](Point a, Point b) { diagonal = diagonal || (a.x != b.x && a.y != b.y); });
      diagonal_pads += diagonal;
    }
    const double excess = *judged;
    excess_sum += excess;
    optimal += t.length == *best;
    if (excess > worst) worst = excess, worst_seed = seed;
  }
  std::printf("%d octilinear trees with %d pads (%d with a 45-degree edge): %d minimal, mean excess %.2f%%, worst %.2f%% "
              "(seed %d)\n",
              trees, pads_total, diagonal_pads, optimal, 100 * excess_sum / std::max(trees, 1), 100 * worst, worst_seed);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(trees, kSanitized ? 25 : 250);
  EXPECT_GE(diagonal_pads, kSanitized ? 20 : 200);
  EXPECT_LT(excess_sum / std::max(trees, 1), 0.02);
  EXPECT_LT(worst, 0.10);
}

// A pin inside a ring of blockage (its hole) cannot be joined: Unreachable, naming that pin,
// from any start; a pin inside the blockage itself is not free.
TEST(SteinerTree, WalledInAndBlockedPins) {
  const std::vector<geom::Polygon> ring{{{{20, 20}, {30, 20}, {30, 30}, {20, 30}}, {{{22, 22}, {22, 28}, {28, 28}, {28, 22}}}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(ring, geom::Box{{0, 0}, {50, 50}});
  router::L1Router router(norm.domain, norm.obstacles);
  const std::vector<Point> pins{{5, 5}, {40, 5}, {25, 25}, {5, 40}};
  EXPECT_EQ(oracle::steiner_minimal_length(norm.domain, norm.obstacles, pins), std::nullopt);
  const auto t = router.steiner(pins);
  EXPECT_EQ(t.status, router::WireStatus::Unreachable);
  // the walled-in pin, or (grown from it) another one: either way a pin on the other side
  ASSERT_TRUE(t.failed.has_value());
  const std::vector<Point> inside{{5, 5}, {21, 25}, {40, 5}};
  const auto u = router.steiner(inside);
  EXPECT_EQ(u.status, router::WireStatus::TargetNotFree);
  EXPECT_EQ(u.failed, std::optional<std::size_t>(1));
}

// A net that needs a Steiner point move to reach its minimum (the two tests below).
template <class Len>
struct HardNet {
  std::vector<geom::Box> boxes;
  std::vector<Point> pins;
  Len minimum;
};
// Each net on the domain [0, side]^2: the oracle gives the minimum, the search without the
// improvement pass is longer, the improved tree is the minimum, legal (tree_problem).
template <class Router, class Len, class Oracle>
void expect_hard_nets_reach_minimum(const std::vector<HardNet<Len>>& cases, geom::Coord side, Oracle minimal_length) {
  for (const HardNet<Len>& c : cases) {
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(box_polygons(c.boxes), geom::Box{{0, 0}, {side, side}});
    Router router(norm.domain, norm.obstacles);
    EXPECT_EQ(minimal_length(norm, c.pins), std::optional<Len>(c.minimum));
    const auto plain = router.steiner(c.pins, 8, false);
    const auto t = router.steiner(c.pins);
    ASSERT_EQ(t.status, router::WireStatus::Ok);
    EXPECT_GT(plain.length, c.minimum);
    EXPECT_EQ(t.length, c.minimum);
    std::vector<router::CheckPin> check_pins;
    for (std::size_t i = 0; i < c.pins.size(); ++i) check_pins.push_back({"p" + std::to_string(i), c.pins[i], std::nullopt, static_cast<int>(i)});
    EXPECT_EQ(tree_problem(norm, std::move(check_pins), t), std::nullopt);
  }
}

// The two nets that decided the worst excess before the Steiner point moves (seed 1135 of this
// file's set and seed 1037 of another): no single path of the improved tree gains, but moving a
// branch point does. 1135: the point joining the pin at (27,10), the trunk from the left and the
// pin at (39,20) moves from (27,12) to (27,20) (80 -> 72); 1037: the pin at (27,18), of degree
// two, is joined to a trunk at x = 19 that the pin at (19,7) now climbs (59 -> 52; a path then
// re-leaves the trunk: 51). Both are the exact minima.
TEST(SteinerTree, PointMovesReachTheMinimumOfTwoHardNets) {
  const std::vector<HardNet<std::int64_t>> cases{
      {{{{3, 24}, {11, 31}}, {{12, 5}, {18, 12}}, {{5, 10}, {7, 18}}, {{33, 27}, {34, 32}}, {{32, 9}, {39, 12}}, {{33, 13}, {34, 19}}},
       {{3, 37}, {0, 24}, {6, 24}, {27, 10}, {12, 30}, {39, 20}},
       72},
      {{{{19, 21}, {26, 28}}, {{27, 13}, {35, 16}}, {{25, 3}, {26, 6}}, {{9, 12}, {13, 20}}},
       {{27, 18}, {20, 36}, {12, 35}, {19, 42}, {19, 7}},
       51},
  };
  expect_hard_nets_reach_minimum<router::L1Router>(cases, 44, [](const geom::NormalizedObstacles& n, const std::vector<Point>& p) {
    return oracle::steiner_minimal_length(n.domain, n.obstacles, p);
  });
}

// The two octilinear nets that decided the worst excess before octilinear trees got Steiner point
// moves (seeds 774 and 82 of OctilinearLegalAndNearTheMinimum's set): with the path re-embedding
// alone they stayed at 55 + 7 sqrt2 (7.9 % over the minimum) and 32 + 10 sqrt2 (7.0 %); moving a
// branch point, to a candidate where a node's diagonal meets another node's line, reaches the
// exact minimum of the oracle (Dreyfus-Wagner on the 8-connected lattice).
TEST(SteinerTree, OctilinearPointMovesReachTheMinimumOfTwoHardNets) {
  const std::vector<HardNet<geom::Root2>> cases{
      {{{{14, 15}, {21, 18}}, {{14, 8}, {15, 13}}, {{10, 22}, {17, 29}}},
       {{12, 4}, {28, 4}, {5, 6}, {26, 4}, {18, 24}, {3, 30}},
       {46, 10}},
      {{{{7, 10}, {8, 17}}, {{22, 1}, {27, 7}}, {{1, 13}, {3, 17}}, {{11, 19}, {14, 23}}},
       {{15, 1}, {2, 24}, {27, 5}, {7, 22}},
       {12, 22}},
  };
  expect_hard_nets_reach_minimum<router::OctRouter>(cases, 30, [](const geom::NormalizedObstacles& n, const std::vector<Point>& p) {
    return oracle::oct_steiner_minimal_length(n.domain, n.obstacles, p);
  });
}

// The independent checker's problems with one net of point pins routed by `wires` (no rules).
std::vector<router::CheckProblem> tree_problems(const geom::NormalizedObstacles& norm, std::span<const Point> pins,
                                                const std::vector<std::vector<Point>>& wires) {
  router::CheckNet net;
  net.name = "n";
  net.routed = true;
  for (std::size_t i = 0; i < pins.size(); ++i) net.pins.push_back({"p" + std::to_string(i), pins[i], std::nullopt, static_cast<int>(i)});
  for (const auto& w : wires) net.wires.push_back({w, 100});
  return router::check_routes(norm, std::vector<router::CheckNet>{net}).problems;
}

// Two blockages touching at a corner (a pinch, which no wire may pass): pins on both sides of it
// near the touching point. A Steiner point move must not put the branch point on the pinch (the
// moves' candidate grid holds it: it is an obstacle vertex); the tree goes round a blockage, and
// the independent checker passes it. (Found by the tightening tests' random touching layouts,
// seed 900645: a tree through a pinch.)
TEST(SteinerTree, NoBranchPointAtAPinch) {
  const std::vector<geom::Box> boxes{{{10, 10}, {20, 20}}, {{20, 20}, {30, 30}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(box_polygons(boxes), geom::Box{{0, 0}, {40, 40}});
  router::L1Router router(norm.domain, norm.obstacles);
  for (const std::vector<Point>& pins : {std::vector<Point>{{18, 22}, {22, 18}, {12, 28}, {28, 12}},
                                         std::vector<Point>{{16, 24}, {24, 16}, {19, 21}}}) {
    const auto t = router.steiner(pins);
    ASSERT_EQ(t.status, router::WireStatus::Ok);
    const auto problems = tree_problems(norm, pins, t.wires);
    EXPECT_TRUE(problems.empty()) << problems.front().message;
  }
}

// A way round a pinch that comes back to it: blockage a (x <= 100, 0 <= y <= 100) touches b
// (100..200 x 100..300) at its corner (100, 100), a pin lies on a's top edge left of the
// pinch and the others below a. The path to the top pin goes up a's right side to the pinch and
// round b back to it, then left (legal: each pass through the pinch stays in one free wedge).
// The improvement pass took the tree as a graph of its metal, joined at the pinch, and dropped
// the way round b as a redundant cycle, leaving a wire that crossed the pinch (seed 3070 of a
// search over `taut gen` layouts, 2026-12-05: `route --tree steiner` failed taut check,
// CHECK-0003). A tree with a node at a pinch is now left as the wavefront grew it.
TEST(SteinerTree, NoCycleDroppedAtAPinch) {
  const std::vector<geom::Box> boxes{{{-1000, 0}, {100, 100}}, {{100, 100}, {200, 300}}};
  const geom::NormalizedObstacles norm =
      geom::normalize_obstacles(box_polygons(boxes), geom::Box{{-2000, -2000}, {2000, 2000}});
  router::L1Router router(norm.domain, norm.obstacles);
  const std::vector<Point> pins{{50, -400}, {-300, -300}, {50, 100}};
  const auto t = router.steiner(pins);
  ASSERT_EQ(t.status, router::WireStatus::Ok);
  const auto problems = tree_problems(norm, pins, t.wires);
  EXPECT_TRUE(problems.empty()) << problems.front().message;
}

// Steiner trees on the wavefront tests' degenerate layouts (rectangles touching at corners and
// along edges, rings closed by pinches, holes touching their shells, diamonds, coordinates near
// 2^30; support/wavefront_cases.h), 3 to 6 pins among each case's free candidates: every tree
// the router returns passes the independent checker's free-space and connectivity tests (the
// random tests above draw blockages apart, so no tree there meets a pinch). With the improvement
// pass that dropped ways round a pinch (before 2026-12-05, NoCycleDroppedAtAPinch) seeds 66 and
// 544 fail here: a wire through a point where blockages touch.
TEST(SteinerTree, LegalOnDegenerateLayouts) {
  int failed = 0, trees = 0, seeds = 0;
  for (int seed = 1; seed <= (kSanitized ? 60 : 600); ++seed) {
    const WavefrontCase c = make_wavefront_case(static_cast<std::uint64_t>(seed));
    if (c.huge) continue;  // (the Steiner moves' grid is the obstacles' coordinates: fine, but slow there)
    ++seeds;
    geom::NormalizedObstacles norm;
    norm.domain = c.domain;
    norm.obstacles = c.obstacles;
    const router::FreeSpaceChecker free(norm);
    std::vector<Point> cand;
    for (const Point p : c.candidates)
      if (free.point_free(p) && std::find(cand.begin(), cand.end(), p) == cand.end()) cand.push_back(p);
    if (cand.size() < 3) continue;
    std::mt19937 rng(static_cast<unsigned>(97000 + seed));
    std::shuffle(cand.begin(), cand.end(), rng);
    cand.resize(std::min<std::size_t>(cand.size(), 3 + rng() % 4));
    router::L1Router router(norm.domain, norm.obstacles);
    const auto t = router.steiner(cand);
    if (t.status != router::WireStatus::Ok) continue;  // walled in: WalledInAndBlockedPins
    ++trees;
    for (const auto& pr : tree_problems(norm, cand, t.wires))
      if (failed++ < 8) ADD_FAILURE() << "seed " << seed << " (" << c.family << "): " << pr.message;
  }
  std::printf("%d Steiner trees on %d degenerate layouts passed the checker\n", trees, seeds);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(trees, seeds / 3);
}

}  // namespace steiner_test
}  // namespace taut::test
