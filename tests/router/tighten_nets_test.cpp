// router::NetsTightener (issue #5, "Clearance": every net tightened together, keeping the
// clearance of <rules>) judged by references that share only geom with it:
//   - the independent checker (router/check.h): the tightened layout is free, connected and clear
//     (w/2 + s from blockages, w + s between nets, no shorts);
//   - the homotopy words (tests/oracle/homotopy.h): every wire piece keeps its class among the
//     plain blockages;
//   - the local-tautness check (tests/support/taut_check.h), with `any` orientations: at the end
//     every wire is locally taut among the blockages grown by a and the other nets' wires and pins
//     grown by b (so no wire can get shorter: the rounds have ended);
//   - never longer in the output's metric; tightening the result again moves nothing; windows
//     give what the whole domain gives, bit for bit.
// On random layouts routed by the net router (rectangles that touch and pinch, sloped triangles,
// pads, trees, odd widths, zero rules), rectilinear, octilinear and any.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <random>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "geom/root2.h"
#include "geom/root3_directions.h"
#include "oracle/homotopy.h"
#include "oracle/qroot3.h"
#include "router/check.h"
#include "router/net_router.h"
#include "router/tighten_nets.h"
#include "support/net_layouts.h"
#include "support/q3_of.h"
#include "support/sanitized.h"
#include "support/taut_check.h"

namespace taut::test {
namespace tighten_nets_test {

using geom::Point;
using geom::Polygon;
using router::NetLines;

std::int64_t l1_of(const NetLines& ws) {
  std::int64_t n = 0;
  for (const auto& w : ws) n += l1_length(w);
  return n;
}
geom::Root2 oct_of(const NetLines& ws) {
  geom::Root2 n{0, 0};
  for (const auto& w : ws) {
    const auto [a, b] = oct_length(w);
    n += geom::Root2{a, b};
  }
  return n;
}

// Each net's wires as a set of undirected polylines (join_at_twos may start a wire at either end).
std::vector<NetLines> as_sets(std::vector<NetLines> nets) {
  for (NetLines& ws : nets) {
    for (auto& w : ws) {
      std::vector<Point> r(w.rbegin(), w.rend());
      if (r < w) w = r;
    }
    std::sort(ws.begin(), ws.end());
  }
  return nets;
}

TEST(CutAtJoints, PiecesRejoinAndEndAtJoints) {
  // a tree: a trunk with a branch starting mid-segment, a point pin passed mid-wire, a pad reached
  // at a vertex, and a pad touched mid-segment only (its wire is kept whole)
  const NetLines wires{{{0, 0}, {10, 0}, {10, 10}}, {{5, 0}, {5, -8}}};
  const std::vector<Polygon> pins{Polygon{{{0, 0}}, {}}, Polygon{{{10, 4}}, {}}, Polygon{{{5, -8}}, {}}};
  std::vector<char> frozen;
  const NetLines cut = router::cut_at_joints(wires, pins, &frozen);
  const NetLines want{{{0, 0}, {5, 0}}, {{5, 0}, {10, 0}, {10, 4}}, {{10, 4}, {10, 10}}, {{5, 0}, {5, -8}}};
  EXPECT_EQ(cut, want);
  EXPECT_EQ(frozen, std::vector<char>(4, 0));
  const std::vector<Polygon> pad{Polygon{{{3, 1}, {6, 1}, {6, 3}, {3, 3}}, {}}};  // no wire vertex on it
  const NetLines touch{{{0, 0}, {0, 1}, {8, 1}, {8, 5}}};
  const NetLines kept = router::cut_at_joints(touch, pad, &frozen);
  EXPECT_EQ(kept, touch);
  EXPECT_EQ(frozen, std::vector<char>{1});
  // a wire frozen so is still cut at a point pin it passes, and both pieces are frozen
  const std::vector<Polygon> pad_and_pin{pad[0], Polygon{{{8, 3}}, {}}};
  EXPECT_EQ(router::cut_at_joints(touch, pad_and_pin, &frozen), (NetLines{{{0, 0}, {0, 1}, {8, 1}, {8, 3}}, {{8, 3}, {8, 5}}}));
  EXPECT_EQ(frozen, (std::vector<char>{1, 1}));
  const std::vector<Polygon> pad2{Polygon{{{7, 0}, {9, 0}, {9, 2}, {7, 2}}, {}}};  // the vertex (8, 1) lies on it
  EXPECT_EQ(router::cut_at_joints(touch, pad2, &frozen), (NetLines{{{0, 0}, {0, 1}, {8, 1}}, {{8, 1}, {8, 5}}}));
}

TEST(JoinAtTwos, JoinsWhereExactlyTwoEnd) {
  // two pieces meeting at (5,0) (a pin passed) join; three meeting at (10,0) stay apart; a loop stays
  const NetLines cut{{{0, 0}, {5, 0}}, {{5, 0}, {10, 0}}, {{10, 0}, {10, 10}}, {{10, 0}, {20, 0}}, {{30, 0}, {30, 5}, {35, 5}, {30, 0}}};
  const NetLines want{{{0, 0}, {5, 0}, {10, 0}}, {{10, 0}, {10, 10}}, {{10, 0}, {20, 0}}, {{30, 0}, {30, 5}, {35, 5}, {30, 0}}};
  EXPECT_EQ(router::join_at_twos(cut), want);
  // a piece given backwards is turned round; a chain of three joins into one
  EXPECT_EQ(router::join_at_twos(NetLines{{{5, 0}, {0, 0}}, {{5, 0}, {5, 5}}, {{9, 5}, {5, 5}}}),
            (NetLines{{{9, 5}, {5, 5}, {5, 0}, {0, 0}}}));
}

// For every point pin after the first (a point too), the way between them along the wires before
// and after: each pin still joined, in the same class (the homotopy words); ways through a pad
// before are skipped. Returns how many ways were compared; `fail` gets each problem.
std::int64_t same_ways(const std::vector<Polygon>& pins, const NetLines& before, const NetLines& after,
                       const oracle::HomotopyWords& words, const std::function<void(const std::string&)>& fail) {
  const NetLines in_graph = router::cut_at_joints(before, pins), out_graph = router::cut_at_joints(after, pins);
  const Polygon& p0 = pins[0];
  std::int64_t compared = 0;
  for (std::size_t j = 1; j < pins.size() && p0.outer.size() == 1; ++j) {
    const Polygon& pj = pins[j];
    if (pj.outer.size() != 1) continue;
    const auto way_in = way_between(in_graph, p0.outer[0], pj.outer[0]);
    if (!way_in) continue;  // joined through a pad
    const auto way_out = way_between(out_graph, p0.outer[0], pj.outer[0]);
    if (!way_out) {
      fail("pin " + std::to_string(j) + " is no longer joined to the first along the wires");
      continue;
    }
    ++compared;
    if (words.word(*way_in) != words.word(*way_out))
      fail("the way from the first pin to pin " + std::to_string(j) + " changed its class");
  }
  return compared;
}

// The net router's wires on a random layout (net i's, empty when not routed).
std::vector<NetLines> routed_wires(const RandomLayout& L, int seed, bool octilinear) {
  router::NetRouterOptions opt;
  opt.octilinear = octilinear;
  router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
  nr.run(octilinear ? router::NetRouter::oct_router(seed % 3 == 0) : router::NetRouter::l1_router(seed % 3 == 0));
  std::vector<NetLines> wires;
  for (const auto& o : nr.outcomes()) wires.push_back(o.routed ? o.wires : NetLines{});
  return wires;
}

// Free, connected and clear: the checker's problems, each a failure.
void check_clear(const RandomLayout& L, const std::vector<NetLines>& wires, const std::function<void(const std::string&)>& fail) {
  router::CheckRules rules;
  rules.wire_width = L.rules.wire_width;
  rules.spacing = L.rules.spacing;
  for (const auto& p : router::check_routes(L.norm, check_nets(L.nets, wires), rules).problems) fail(p.message);
}

// Every net of L tightened together (wires: in, then out).
std::pair<std::vector<router::NetTightenOutcome>, router::NetsTightenStats> tighten_layout(
    const RandomLayout& L, const router::NetsTightenOptions& to, std::vector<NetLines>& wires) {
  router::NetSpace space(L.norm.domain, L.norm.obstacles, L.nets, L.rules);
  router::NetsTightener nt(space, to);
  auto outcomes = nt.run(wires);
  return {std::move(outcomes), nt.stats()};
}

struct Totals {
  int layouts = 0, failed = 0, later_rounds = 0;
  std::int64_t nets = 0, pieces = 0, moved = 0, kept = 0, kept_not_free = 0, kept_shape = 0, shorter = 0, windows = 0, whole = 0, words = 0;
};

void check_layout(int seed, router::TightenOrientations orient, Totals& t) {
  const RandomLayout L = random_layout(seed);
  const bool octilinear = orient == router::TightenOrientations::Octilinear;
  const std::vector<NetLines> before = routed_wires(L, seed, octilinear);
  const std::string at = "seed " + std::to_string(seed) + " (" +
                         (orient == router::TightenOrientations::Any ? "any" : octilinear ? "octilinear" : "rectilinear") +
                         ", w " + std::to_string(L.rules.wire_width) + ", s " + std::to_string(L.rules.spacing) + ")";
  auto fail = [&](const std::string& what) {
    if (t.failed++ < 10) ADD_FAILURE() << at << ": " << what;
  };

  std::vector<NetLines> after = before;
  router::NetSpace space(L.norm.domain, L.norm.obstacles, L.nets, L.rules);  // (asked for each net's obstacles below)
  router::NetsTightenOptions to;
  to.orientations = orient;
  router::NetsTightener nt(space, to);
  const auto outcomes = nt.run(after);
  ++t.layouts;
  t.moved += nt.stats().moved;
  t.windows += nt.stats().windows;
  t.whole += nt.stats().whole;
  t.later_rounds += nt.stats().rounds > 2;
  if (nt.stats().capped) fail("the rounds were capped");
  t.kept += nt.stats().kept;
  t.kept_not_free += nt.stats().kept_not_free;
  t.kept_shape += nt.stats().kept_shape_pin;
  for (std::size_t i = 0; i < outcomes.size(); ++i)
    if (outcomes[i].status == router::NetTightenOutcome::Status::Contractible)
      fail("net " + std::to_string(i) + " was called a contractible loop");

  check_clear(L, after, fail);

  const oracle::HomotopyWords words(L.norm.domain, L.norm.obstacles);
  for (std::size_t i = 0; i < L.nets.size(); ++i) {
    if (before[i].empty()) continue;
    ++t.nets;
    // the outcome's length is the written wires' (after they are joined: two pieces pulled onto one
    // track are one metal)
    double written = 0;
    for (const auto& w : after[i]) written += router::euclidean_length(w);
    if (outcomes[i].length_after != written) fail("net " + std::to_string(i) + "'s length_after is not its wires' length");
    // never longer in the output's metric
    if (octilinear ? oct_of(after[i]) > oct_of(before[i]) : l1_of(after[i]) > l1_of(before[i]))
      fail("net " + std::to_string(i) + " got longer");
    t.shorter += octilinear ? oct_of(after[i]) < oct_of(before[i]) : l1_of(after[i]) < l1_of(before[i]);
    // the class of the way between the first pin and every other point pin, along the wires, is
    // the same as along the routed wires (the homotopy words among the plain blockages)
    t.pieces += static_cast<std::int64_t>(after[i].size());
    t.words += same_ways(L.nets[i].pins, before[i], after[i], words, [&](const std::string& w) { fail("net " + std::to_string(i) + ": " + w); });
    // at the end every wire is taut among the blockages and the other nets as they are
    if (orient == router::TightenOrientations::Any) {
      const geom::NormalizedObstacles full = space.obstacles(i, router::NetSpaceLevel::Full);
      const NetLines& pieces_now = outcomes[i].pieces;  // as tightened, before join_at_twos
      for (std::size_t k = 0; k < pieces_now.size(); ++k)
        if (outcomes[i].kept[k] == 0)
          if (const std::string why = taut_problem(pieces_now[k], full.domain, full.obstacles); !why.empty())
          fail("net " + std::to_string(i) + " piece " + std::to_string(k) + " is not taut among the others: " + why);
    }
  }
  // tightening the result again moves nothing
  {
    std::vector<NetLines> again = after;
    router::NetSpace s2(L.norm.domain, L.norm.obstacles, L.nets, L.rules);
    router::NetsTightener n2(s2, to);
    n2.run(again);
    if (n2.stats().moved != 0 || as_sets(again) != as_sets(after)) fail("tightening the result again moved " + std::to_string(n2.stats().moved) + " wires");
  }
  // the windows decide what the whole domain decides
  if (seed % 4 == 0) {
    std::vector<NetLines> whole = before;
    router::NetSpace s3(L.norm.domain, L.norm.obstacles, L.nets, L.rules);
    router::NetsTightenOptions wo = to;
    wo.windows = false;
    router::NetsTightener n3(s3, wo);
    n3.run(whole);
    if (whole != after) fail("the whole domain gives other wires than the windows");
  }
}

TEST(NetsTightener, KeepsClearanceClassesAndEndsTaut) {
  Totals t;
  const int n = sanitized_share(700, 20);  // 1,500 until 2026-12-02, 1,000 until 2026-12-06; / 11 under the sanitizers until 2026-12-04 (make test's time on CI)
  for (int seed = 1; seed <= n; ++seed) {
    const auto orient = seed % 3 == 0   ? router::TightenOrientations::Any
                        : seed % 5 == 4 ? router::TightenOrientations::Octilinear
                                        : router::TightenOrientations::Rectilinear;
    try {
      check_layout(900000 + seed, orient, t);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "seed " << 900000 + seed << ": " << e.what();
      ++t.failed;
    }
  }
  std::printf("%d layouts, %lld routed nets, %lld wires (%lld pin-to-pin ways' homotopy words compared): %lld moved, %lld nets shorter; "
              "%d layouts moved wires after round 2; %lld windows (%lld whole); %lld pieces kept (%lld not free in their space), %lld at shape pins\n",
              t.layouts, static_cast<long long>(t.nets), static_cast<long long>(t.pieces), static_cast<long long>(t.words),
              static_cast<long long>(t.moved), static_cast<long long>(t.shorter), t.later_rounds,
              static_cast<long long>(t.windows), static_cast<long long>(t.whole), static_cast<long long>(t.kept), static_cast<long long>(t.kept_not_free), static_cast<long long>(t.kept_shape));
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.moved, n / 4);
  EXPECT_GT(t.nets, n);
  EXPECT_LT(t.kept * 10, t.pieces);  // gaps of exactly the clearance are rare (5.5 % of the pieces)
}

// taut tighten --clearance in the scaled plane (since 2026-12-05): the routed wires of a layout
// routed with exact gaps (NetRouterOptions::exact_gaps: wires in gaps of exactly the clearance,
// which are legal) given as the command gives a file's routed wires, Input::CheckedWires (on odd
// seeds every two-pin net's wire as a sketch, Input::Sketch), to router::tighten_scaled in the
// router's scaled plane. Every such wire lies in its space there (none fails as given, as many do
// in the layout's units, where those gaps are closed); the result, when taken (as the command
// takes it: not snapped from afar, and the checker passes it), joins every pin to the first along
// the wires in the same class (homotopy words among the plain blockages, an oracle that shares
// nothing with the tightener) and is never longer in the output's metric. Given as sketches
// (each line tightened whole), a tree's branch ending on another wire's segment was left behind:
// seeds 910017 and 910169 failed so.
struct ScaledTotals {
  int layouts = 0, scaled = 0, taken = 0, failed = 0, units_refused = 0;
  std::int64_t nets = 0, sketches = 0, shorter = 0, words = 0;
};

void check_scaled_sketches(int seed, router::TightenOrientations orient, ScaledTotals& t) {
  const RandomLayout L = random_layout(seed);
  const bool octilinear = orient == router::TightenOrientations::Octilinear;
  router::NetRouterOptions opt;
  opt.octilinear = octilinear;
  opt.exact_gaps = true;
  router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
  nr.run(octilinear ? router::NetRouter::oct_router() : router::NetRouter::l1_router(false));
  ++t.layouts;
  const std::int64_t k = nr.scale();
  if (k == 1) return;
  ++t.scaled;
  const std::string at = "seed " + std::to_string(seed) + (octilinear ? " (octilinear)" : " (rectilinear)");
  auto fail = [&](const std::string& what) {
    if (t.failed++ < 10) ADD_FAILURE() << at << ": " << what;
  };
  std::vector<NetLines> before;
  for (const auto& o : nr.outcomes()) before.push_back(o.routed ? o.wires : NetLines{});
  // as taut tighten --clearance gives them: routed wires as CheckedWires, sketches as Sketch (here
  // every two-pin net's wire on odd seeds)
  std::vector<router::NetsTightener::Input> kind(L.nets.size(), router::NetsTightener::Input::CheckedWires);
  for (std::size_t i = 0; i < L.nets.size(); ++i)
    if (seed % 2 == 1 && L.nets[i].pins.size() == 2 && before[i].size() == 1) kind[i] = router::NetsTightener::Input::Sketch;
  router::NetsTightenOptions to;
  to.orientations = orient;
  // in the layout's units, for the count: legal wires in gaps of exactly the clearance fail as given
  {
    std::vector<NetLines> u = before;
    router::NetSpace space(L.norm.domain, L.norm.obstacles, L.nets, L.rules);
    router::NetsTightener nt(space, to);
    const auto out = nt.run(u, kind);
    t.units_refused += std::any_of(out.begin(), out.end(), [](const router::NetTightenOutcome& o) {
      return o.status == router::NetTightenOutcome::Status::NotFree && o.round == 0;
    });
  }
  std::vector<router::NetTightenOutcome> out;
  const auto back = router::tighten_scaled(L.norm.domain, L.norm.obstacles, L.nets, L.rules, k, before, kind, to, nullptr, &out);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i].status == router::NetTightenOutcome::Status::NotFree && out[i].round == 0)
      fail("net " + std::to_string(i) + "'s legal wire is not free in the scaled plane as given");
  if (!back) return;
  router::CheckRules rules;
  rules.wire_width = L.rules.wire_width;
  rules.spacing = L.rules.spacing;
  if (!router::check_routes(L.norm, check_nets(L.nets, *back), rules).problems.empty()) return;  // not taken
  ++t.taken;
  const std::vector<NetLines>& after = *back;
  const oracle::HomotopyWords words(L.norm.domain, L.norm.obstacles);
  for (std::size_t i = 0; i < L.nets.size(); ++i) {
    if (before[i].empty()) continue;
    ++t.nets;
    t.sketches += kind[i] == router::NetsTightener::Input::Sketch;
    if (octilinear ? oct_of(after[i]) > oct_of(before[i]) : l1_of(after[i]) > l1_of(before[i]))
      fail("net " + std::to_string(i) + " got longer");
    t.shorter += octilinear ? oct_of(after[i]) < oct_of(before[i]) : l1_of(after[i]) < l1_of(before[i]);
    t.words += same_ways(L.nets[i].pins, before[i], after[i], words, [&](const std::string& w) { fail("net " + std::to_string(i) + ": " + w); });
  }
}

TEST(NetsTightener, ScaledPlaneTakesLegalSketchesInExactGaps) {
  ScaledTotals t;
  const int n = sanitized_share(400, 10);
  for (int seed = 1; seed <= n; ++seed) {
    const auto orient = seed % 4 == 3 ? router::TightenOrientations::Octilinear : router::TightenOrientations::Rectilinear;
    try {
      check_scaled_sketches(910000 + seed, orient, t);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "seed " << 910000 + seed << ": " << e.what();
      ++t.failed;
    }
  }
  std::printf("%d layouts (%d scaled): %d taken in the scaled plane; %lld routed nets (%lld given as sketches), %lld shorter, "
              "%lld ways' words compared; %d layouts with a legal wire refused as given in the layout's units\n",
              t.layouts, t.scaled, t.taken, static_cast<long long>(t.nets), static_cast<long long>(t.sketches),
              static_cast<long long>(t.shorter), static_cast<long long>(t.words), t.units_refused);
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.taken * 10, t.scaled * 9);  // the scaled plane's result is taken for nearly every layout
  EXPECT_GT(t.words, t.nets / 2);
  if (n >= 100) {
    EXPECT_GT(t.units_refused, 0);  // the layout's units refuse some legal wires, the scaled plane none
  }
}

// Sets at multiples of 30 degrees (since 2026-12-07): the net router's octilinear wires tightened
// together into c:0,60,120 and the other such sets, their exact wires rounded
// (router/root3_staircase.h). Judged as above, by references that share nothing with the
// builder: the checker (free, connected, clear), the homotopy words (every pin-to-pin way keeps
// its class), every wire written within the rounding rule of the set (Root3Directions::fits,
// itself tested against angles in tests/geom/root3_test.cpp), and tightening the result again
// moves nothing. A net may keep a piece as routed (no wire in the set: a pinch, H&S §6; or a
// gap of exactly the clearance): such nets are counted, and must be few.
struct Totals30 {
  int layouts = 0, failed = 0;
  std::int64_t nets = 0, in_set = 0, kept_nets = 0, moved = 0, words = 0, rect_nets = 0, rect_shorter = 0, rect_pieces = 0;
};

void check_layout30(int seed, const geom::Root3Directions& set, Totals30& t) {
  const RandomLayout L = random_layout(seed);
  const std::vector<NetLines> before = routed_wires(L, seed, true);
  const std::string at = "seed " + std::to_string(seed) + " (" + set.name() + ", w " + std::to_string(L.rules.wire_width) +
                         ", s " + std::to_string(L.rules.spacing) + ")";
  auto fail = [&](const std::string& what) {
    if (t.failed++ < 10) ADD_FAILURE() << at << ": " << what;
  };
  router::NetsTightenOptions to;
  to.orientations = router::TightenOrientations::Any;  // (the default is rectilinear)
  to.orientations.set30 = set;
  std::vector<NetLines> after = before;
  const auto [outcomes, stats] = tighten_layout(L, to, after);
  ++t.layouts;
  t.moved += stats.moved;
  if (stats.capped) fail("the rounds were capped");
  check_clear(L, after, fail);

  const oracle::HomotopyWords words(L.norm.domain, L.norm.obstacles);
  for (std::size_t i = 0; i < L.nets.size(); ++i) {
    if (before[i].empty()) continue;
    ++t.nets;
    t.words += same_ways(L.nets[i].pins, before[i], after[i], words, [&](const std::string& w) { fail("net " + std::to_string(i) + ": " + w); });
    // every piece as tightened outside the set was kept as it was (not free, no wire, or frozen)
    const NetLines& pieces = outcomes[i].pieces;
    bool kept = false;
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (!set.runs_within(pieces[k])) {
        kept = true;
        if (k >= outcomes[i].kept.size() || outcomes[i].kept[k] == 0)
          fail("net " + std::to_string(i) + " piece " + std::to_string(k) + " runs outside " + set.name() + " and was not kept");
      }
    const bool fits = std::all_of(after[i].begin(), after[i].end(), [&](const auto& w) { return set.runs_within(w); });
    if (fits != !kept) fail("net " + std::to_string(i) + ": its written wires and its pieces disagree on the set");
    if (fits)
      ++t.in_set;
    else
      ++t.kept_nets;
  }
  // Wires already in the set (rectilinear ones, under a set with 0 and 90 degrees) are a router's
  // wires: a result replaces one only when it is no longer in the set's convex distance (summed
  // over its rounded segments, exact in Z[sqrt3]) and has no more bends, so no net gets longer.
  if (set.step_along(1, 0) >= 0 && set.step_along(0, 1) >= 0) {
    const std::vector<NetLines> rect = routed_wires(L, seed, false);
    std::vector<NetLines> r2 = rect;
    const auto outcomes2 = tighten_layout(L, to, r2).first;
    // (the references' own lengths in the set, oracle::SetLengths: sums of square roots in
    // Q(sqrt3), compared exactly; not the router's set_length, which NetsTightener decides with)
    std::vector<oracle::Q3Point> steps;
    for (const auto& st : set.steps()) steps.push_back(q3of(st));
    const oracle::SetLengths lengths(steps);
    auto length_of = [&](const NetLines& ws) {
      oracle::SetLengths::Len s;
      for (const auto& w : ws) s = oracle::SetLengths::plus(s, lengths.length(std::span<const Point>(w)));
      return s;
    };
    auto longer = [](const oracle::SetLengths::Len& a, const oracle::SetLengths::Len& b) {
      return oracle::SetLengths::compare(a, b) > 0;
    };
    using Ends = std::pair<Point, Point>;
    auto ends = [](const std::vector<Point>& l) { return l.front() < l.back() ? Ends{l.front(), l.back()} : Ends{l.back(), l.front()}; };
    for (std::size_t i = 0; i < rect.size(); ++i) {
      if (rect[i].empty()) continue;
      ++t.rect_nets;
      const oracle::SetLengths::Len l0 = length_of(rect[i]), l1 = length_of(r2[i]);
      if (longer(l1, l0)) fail("net " + std::to_string(i) + "'s rectilinear wires got longer in " + set.name());
      t.rect_shorter += longer(l0, l1);
      // per piece, where the tightener's pieces are the input cut at its joints (as
      // NetsTightener cuts them; no re-cut changed them): none gained a bend or got longer
      const NetLines in_pieces = router::join_at_twos(router::cut_at_joints(rect[i], L.nets[i].pins), L.nets[i].pins);
      std::map<Ends, std::vector<const std::vector<Point>*>> by_ends;
      for (const auto& w : in_pieces)
        if (w.size() >= 2) by_ends[ends(w)].push_back(&w);
      for (const auto& w : outcomes2[i].pieces) {
        if (w.size() < 2) continue;
        const auto it = by_ends.find(ends(w));
        if (it == by_ends.end() || it->second.size() != 1) continue;
        const std::vector<Point>& was = *it->second[0];
        ++t.rect_pieces;
        if (geom::count_bends(w) > geom::count_bends(was))
          fail("net " + std::to_string(i) + ": a rectilinear piece gained bends in " + set.name());
        if (longer(length_of({w}), length_of({was}))) fail("net " + std::to_string(i) + ": a rectilinear piece got longer in " + set.name());
      }
    }
  }
  // tightening the result again moves nothing
  std::vector<NetLines> again = after;
  const std::int64_t moved_again = tighten_layout(L, to, again).second.moved;
  if (moved_again != 0 || as_sets(again) != as_sets(after)) {
    std::string d;
    const auto A = as_sets(again), B = as_sets(after);
    for (std::size_t i = 0; i < A.size(); ++i)
      if (A[i] != B[i]) {
        d += " net " + std::to_string(i) + ":";
        for (const auto& w : B[i]) { d += " was"; for (Point p : w) d += " " + std::to_string(p.x) + "," + std::to_string(p.y); }
        for (const auto& w : A[i]) { d += " now"; for (Point p : w) d += " " + std::to_string(p.x) + "," + std::to_string(p.y); }
      }
    fail("tightening the result again moved " + std::to_string(moved_again) + " wires" + d);
  }
}

void run_sets30(const std::vector<const char*>& names, int n, int first_seed) {
  Totals30 t;
  for (int seed = first_seed; seed < first_seed + n; ++seed) {
    const char* name = names[static_cast<std::size_t>(seed) % names.size()];
    const auto set = geom::Root3Directions::parse_any(name);
    ASSERT_TRUE(set);
    try {
      check_layout30(930000 + seed, *set, t);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "seed " << 930000 + seed << " (" << name << "): " << e.what();
      ++t.failed;
    }
  }
  std::printf("%d layouts, %lld routed nets (%lld pin-to-pin ways' words compared): %lld written in the set, %lld with a "
              "piece kept as routed; %lld wires moved; rectilinear wires given in a set with 0 and 90 degrees: %lld "
              "nets, %lld shorter, none longer; %lld pieces compared, none longer or with more bends\n",
              t.layouts, static_cast<long long>(t.nets), static_cast<long long>(t.words), static_cast<long long>(t.in_set),
              static_cast<long long>(t.kept_nets), static_cast<long long>(t.moved), static_cast<long long>(t.rect_nets),
              static_cast<long long>(t.rect_shorter), static_cast<long long>(t.rect_pieces));
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.nets, n);
  EXPECT_LT(t.kept_nets * 10, t.nets);  // nearly every net is written in the set
  if (n >= 50) {
    EXPECT_GT(t.rect_shorter * 4, t.rect_nets);  // (the rule does take results: a quarter of the nets at least)
    EXPECT_GT(t.rect_pieces, t.rect_nets);
  }
}

TEST(NetsTightener, SetsAtMultiplesOf30DegreesKeepClearanceAndClasses) {
  run_sets30({"c:0,60,120", "c:30,90,150", "c:0,30,60,90,120,150", "c:0,60", "c:0,90,150"}, sanitized_share(150, 6), 1);
}

// Sets at other angles (Root3Directions::parse_any, since 2026-12-07): the same, their lengths
// sums of square roots (router::RadicalSum).
TEST(NetsTightener, SetsAtOtherAnglesKeepClearanceAndClasses) {
  run_sets30({"c:0,10,90", "c:0,45,60,90", "c:22.5,90,157.5", "c:0,72,144"}, sanitized_share(80, 4), 1001);
}

}  // namespace tighten_nets_test
}  // namespace taut::test
