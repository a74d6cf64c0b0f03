// The net router (issue #7; router::NetRouter, `taut route`'s default): m local nets of 2-5 point
// pins with width and spacing, routed together (grown blockages, the other nets' grown wires and
// pins, rip-up), against the same nets routed each alone on one router (`--independent`, the
// baseline, in the same run): completion, total length as a ratio to the independent wires' (a
// lower bound for what each net gets: routing among others only lengthens it), rip-ups, time and
// its ratio to the baseline, and how time grows with m (exponent between rows).
//
// With --threads T,..: each row is also routed with T threads (NetRouterOptions::threads), its
// time given as a ratio to the one-thread run of the row, and the outcomes compared with it (they
// must be the same: the run fails otherwise).
//
// --rounds R sets NetRouterOptions::max_rounds (0: the first pass only), --max-rips K
// NetRouterOptions::max_rips, --search-windows W NetRouterOptions::search_windows (0: no limit),
// --no-final-round NetRouterOptions::final_round false, --no-superset NetRouterOptions::superset
// false (the last pass without its superset of the nets' spaces, to measure what it saves).
//
// --tighten: each row's routed wires are then tightened together (router::NetsTightener, what
// `route --tighten` does: the clearance kept, rounds until no wire shortens), against a baseline
// in the same run: every wire tightened alone among the plain blockages on one triangulation
// (what `route --independent --tighten` does, no clearance); time, its ratio to the baseline,
// rounds, wires moved and kept, and the bends before and after.
//
// --metric combined|link [--bend-cost C] (default C = 1000): the bend-aware metrics routed
// together (NetRouter::bend_router, NetRouterOptions::cost), against each net alone on one
// router::BendRouter (the tree of optimal paths from the first pin); length and bends both
// compared. (--tighten applies to l1 only.)
//
// --exact-gaps: NetRouterOptions::exact_gaps (what `taut route` does since 2026-12-04: gaps of
// exactly the clearance open, the plane scaled by NetRouter::scale(), printed per row).
//
// --planted: instead of nets on spread free points, nets drawn with their wires first
// (bench/planted_nets.h: legs kept only where they keep the clearance, the whole routing then
// passed by the independent checker), so a legal routing of every net is known to exist: the
// completion target's instance. Their planted length is printed beside the routed length.
//
// --orientations SET (any, a lattice c: set such as c:45,135, or since 2026-12-07 a set at
// multiples of 30 degrees such as c:0,60,120, its wires rounded; l1 only): each row is then also
// routed as `taut route --orientations SET` does it (since 2026-12-06): octilinear, the gaps of
// exactly the clearance closed, each attempt tightened into a lattice set where it was routed
// (router::tighten_attempt), then every net tightened together into the set (NetsTightener);
// against a baseline in the same run, the same nets routed octilinear alone (no tightening):
// time and its ratio, nets routed each way, and nets left with a wire outside the set.
//
// --round-log: on stderr, when each phase and each rip-up round begins (wall clock from the
// run's start, at its first net tried) and how many nets are routed then
// (NetRouterOptions::progress), to see what each round gains for its time. The final round
// shows as the round after the last (its count taken before the best state was put back), the
// last pass not at all; the clock starts before the router is built.
//
//   bench_net_router [--sizes N,..] [--nets M,..] [--threads T,..] [--rounds R] [--max-rips K] [--search-windows W] [--no-final-round] [--no-superset] [--tighten] [--planted] [--exact-gaps] [--round-log] [--metric l1|combined|link] [--bend-cost C] [--orientations SET]
//   (--sizes: blockage vertices)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/free_points.h"
#include "bench/planted_nets.h"
#include "geom/directions.h"
#include "geom/root3_directions.h"
#include "router/bend_router.h"
#include "router/l1_router.h"
#include "router/net_router.h"
#include "router/tighten_nets.h"
#include "geom/predicates.h"

namespace {

using taut::bench::total_length;
using taut::geom::Point;
using taut::geom::Polygon;

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {1000}, net_counts = {10, 30, 100}, thread_counts;
  int rounds = taut::router::NetRouterOptions{}.max_rounds, max_rips = taut::router::NetRouterOptions{}.max_rips,
      search_windows = taut::router::NetRouterOptions{}.search_windows;
  bool final_round = true;
  bool superset = true;
  bool tighten = false, planted = false, exact_gaps = false, round_log = false;
  std::string metric = "l1";
  std::string set_word;  // --orientations: "" (none), "any" or a lattice c: set
  std::int64_t bend_cost = 1000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = taut::bench::parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--nets") && i + 1 < argc) net_counts = taut::bench::parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) thread_counts = taut::bench::parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc) rounds = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--max-rips") && i + 1 < argc) max_rips = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--search-windows") && i + 1 < argc) search_windows = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--no-final-round")) final_round = false;
    else if (!std::strcmp(argv[i], "--no-superset")) superset = false;
    else if (!std::strcmp(argv[i], "--tighten")) tighten = true;
    else if (!std::strcmp(argv[i], "--planted")) planted = true;
    else if (!std::strcmp(argv[i], "--exact-gaps")) exact_gaps = true;
    else if (!std::strcmp(argv[i], "--round-log")) round_log = true;
    else if (!std::strcmp(argv[i], "--metric") && i + 1 < argc) metric = argv[++i];
    else if (!std::strcmp(argv[i], "--bend-cost") && i + 1 < argc) bend_cost = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--orientations") && i + 1 < argc) set_word = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--sizes N,..] [--nets M,..] [--threads T,..] [--rounds R] [--max-rips K] [--search-windows W] [--no-final-round] [--no-superset] [--tighten] [--planted] [--exact-gaps] [--round-log] [--metric l1|combined|link] [--bend-cost C] [--orientations SET]\n", argv[0]);
      return 2;
    }
  }
  if (metric != "l1" && metric != "combined" && metric != "link") {
    std::fprintf(stderr, "--metric: l1, combined or link\n");
    return 2;
  }
  const bool bends = metric != "l1";
  if (bends) tighten = false;
  std::optional<taut::router::TightenOrientations> set_orient;
  if (!set_word.empty()) {
    const auto lattice = taut::geom::LatticeDirections::parse(set_word);
    const auto thirty = lattice ? std::nullopt : taut::geom::Root3Directions::parse_any(set_word);  // (since 2026-12-07)
    if (set_word != "any" && !lattice && !thirty) {
      std::fprintf(stderr, "--orientations: any or a c: set (Root3Directions::parse_any realizes directions at other angles)\n");
      return 2;
    }
    if (!bends) set_orient = taut::router::TightenOrientations{lattice, thirty};
  }
  const taut::router::BendMetric bm = metric == "link" ? taut::router::BendMetric::Link : taut::router::BendMetric::Combined;
  if (metric == "link") bend_cost = 0;
  auto route_fn = [&] { return bends ? taut::router::NetRouter::bend_router(bm, bend_cost) : taut::router::NetRouter::l1_router(false); };
  auto options = [&](int threads) {
    taut::router::NetRouterOptions o;
    o.threads = threads;
    o.max_rounds = rounds;
    o.max_rips = max_rips;
    o.search_windows = search_windows;
    o.final_round = final_round;
    o.superset = superset;
    o.cost = !bends ? taut::router::NetRouterOptions::Cost::Length
             : metric == "link" ? taut::router::NetRouterOptions::Cost::Link : taut::router::NetRouterOptions::Cost::Combined;
    o.bend_cost = bend_cost;
    o.exact_gaps = exact_gaps;
    if (round_log) {
      auto t0 = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
      auto last = std::make_shared<int>(-1);
      o.progress = [t0, last](const taut::router::NetRouterProgress& p) {
        const int key = p.phase == taut::router::NetRouterProgress::Phase::RipUp ? p.round : p.phase == taut::router::NetRouterProgress::Phase::FirstPass ? 0 : 1000;
        if (key != *last) {
          *last = key;
          const bool round = p.phase == taut::router::NetRouterProgress::Phase::RipUp;
          const char* what = round ? "rip-up round" : p.phase == taut::router::NetRouterProgress::Phase::FirstPass ? "first pass" : "explaining";
          std::fprintf(stderr, "    %8.3f s: %s%s%s, after its first net tried: %zu nets routed\n",
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - *t0).count(), what,
                       round ? " " : "", round ? std::to_string(p.round).c_str() : "", p.routed);
        }
      };
    }
    return o;
  };
  const taut::router::NetRules rules{10, 10, bends ? taut::router::kDefaultCoverPieces : 0};
  std::printf("net router vs each net alone (baseline), rects layouts, local nets of 2-5 point pins (pins 42 apart), w = s = 10, metric %s",
              metric.c_str());
  if (metric == "combined") std::printf(" (C = %lld)", static_cast<long long>(bend_cost));
  std::printf("\n");
  std::printf("%9s %6s | %8s %8s %7s | %9s %9s %8s %6s | %s\n", "vertices", "nets", "routed", "1st pass", "rips", "alone s",
              "together s", "/alone", "growth", "len/alone");
  for (const std::int64_t size : sizes) {
    const auto lay = taut::bench::bench_layout(taut::io::GenKind::Rects, size);
    const auto& dom = lay.norm.domain;
    // Pins as a placer would leave them: free points at least 2(w + s) + 2 apart (L-infinity), so
    // every pin can be reached; each used once. Nets are local: their pins within a square of a
    // twentieth of the layout's side round their first.
    const std::int64_t gap = 2 * 20 + 2, side = (std::int64_t{dom.hi.x} - dom.lo.x) / 20;
    std::vector<Point> pool;
    {
      std::map<std::pair<std::int64_t, std::int64_t>, std::vector<Point>> cells;
      for (const Point p : taut::bench::random_free_points(dom, lay.norm.obstacles, 200000, 17)) {
        const std::int64_t cx = p.x / gap, cy = p.y / gap;
        bool near = false;
        for (std::int64_t dx = -1; dx <= 1 && !near; ++dx)
          for (std::int64_t dy = -1; dy <= 1 && !near; ++dy)
            if (auto it = cells.find({cx + dx, cy + dy}); it != cells.end())
              for (const Point q : it->second) near = near || (std::abs(p.x - q.x) < gap && std::abs(p.y - q.y) < gap);
        if (near) continue;
        cells[{cx, cy}].push_back(p);
        pool.push_back(p);
      }
    }
    double last_t = 0, last_m = 0;
    for (const std::int64_t m : net_counts) {
      std::vector<taut::router::NetPins> nets;
      std::int64_t planted_length = -1;
      if (planted) {
        const taut::bench::PlantedNets pl = taut::bench::planted_nets(lay.norm, static_cast<std::size_t>(m), 10, 10, side / 2,
                                                                      static_cast<std::uint64_t>(size * 31 + m));
        nets = pl.nets;
        planted_length = 0;
        for (const auto& ws : pl.wires) planted_length += total_length(ws);
        std::printf("%18s planted: %zu nets with a legal routing (checked; %zu drawn, %zu dropped by the checker), its length %lld\n", "",
                    pl.nets.size(), pl.drawn, pl.checker_drops, static_cast<long long>(planted_length));
      }
      std::mt19937_64 rng(static_cast<std::uint64_t>(size * 31 + m));
      std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> buckets;  // unused pool points
      for (std::size_t i = 0; i < pool.size(); ++i) buckets[{pool[i].x / side, pool[i].y / side}].push_back(i);
      std::vector<char> used(pool.size(), 0);
      for (std::int64_t tries = 0; !planted && static_cast<std::int64_t>(nets.size()) < m && tries < 20 * m; ++tries) {
        const std::size_t c = rng() % pool.size();
        if (used[c]) continue;
        const std::size_t k = 2 + nets.size() % 4;
        std::vector<std::size_t> pick{c};
        const Point cp = pool[c];
        for (std::int64_t dx = -1; dx <= 1; ++dx)
          for (std::int64_t dy = -1; dy <= 1; ++dy)
            if (auto it = buckets.find({cp.x / side + dx, cp.y / side + dy}); it != buckets.end())
              for (const std::size_t j : it->second)
                if (pick.size() < k && !used[j] && j != c && std::abs(pool[j].x - cp.x) <= side / 2 && std::abs(pool[j].y - cp.y) <= side / 2 &&
                    rng() % 4 == 0)
                  pick.push_back(j);
        if (pick.size() < k) continue;
        taut::router::NetPins np;
        np.name = "n" + std::to_string(nets.size());
        for (const std::size_t j : pick) {
          used[j] = 1;
          np.pins.push_back(taut::bench::point_pin(pool[j]));
        }
        nets.push_back(std::move(np));
      }
      // baseline: each net alone on one router (what --independent does)
      std::vector<std::int64_t> alone_len(nets.size(), -1);
      std::size_t alone_ok = 0;
      std::int64_t alone_bends = 0;
      const double alone_s = taut::bench::seconds_of([&] {
        if (bends) {
          const taut::router::BendRouter r(dom, lay.norm.obstacles);
          for (std::size_t i = 0; i < nets.size(); ++i) {
            const auto& pins = nets[i].pins;
            const auto t = r.tree(pins[0], std::span<const Polygon>(pins).subspan(1), bm, bend_cost);
            if (t.status == taut::router::WireStatus::Ok) {
              alone_len[i] = total_length(t.wires);
              for (const auto& w : t.wires) alone_bends += taut::geom::count_bends(w);
            }
            alone_ok += alone_len[i] >= 0;
          }
          return;
        }
        taut::router::L1Router r(dom, lay.norm.obstacles);
        for (std::size_t i = 0; i < nets.size(); ++i) {
          const auto& pins = nets[i].pins;
          if (pins.size() == 2) {
            const auto w = r.shortest(pins[0], pins[1]);
            if (w.status == taut::router::WireStatus::Ok) alone_len[i] = total_length({w.points});
          } else {
            const auto t = r.tree(pins[0], std::span<const Polygon>(pins).subspan(1));
            if (t.status == taut::router::WireStatus::Ok) alone_len[i] = total_length(t.wires);
          }
          alone_ok += alone_len[i] >= 0;
        }
      }, 1);
      taut::router::NetRouter nr(dom, lay.norm.obstacles, nets, rules, options(1));
      const double together_s = taut::bench::seconds_of([&] { nr.run(route_fn()); }, 1);
      std::size_t routed = 0;
      std::int64_t len = 0, len_alone_same = 0, together_bends = 0;
      for (std::size_t i = 0; i < nets.size(); ++i) {
        routed += nr.outcomes()[i].routed;
        for (const auto& w : nr.outcomes()[i].wires) together_bends += taut::geom::count_bends(w);
        if (nr.outcomes()[i].routed && alone_len[i] >= 0) {
          len += total_length(nr.outcomes()[i].wires);
          len_alone_same += alone_len[i];
        }
      }
      const double growth = last_t > 0 ? std::log(together_s / last_t) / std::log(static_cast<double>(nets.size()) / last_m) : 0;
      std::printf("%9lld %6zu | %8zu %8zu %7lld | %9.3f %9.3f %8.1f %6.2f | %.3f  (alone: %zu routed)\n",
                  static_cast<long long>(lay.points.size()), nets.size(), routed, nr.stats().first_pass,
                  static_cast<long long>(nr.stats().rips), alone_s, together_s, together_s / alone_s, growth,
                  len_alone_same > 0 ? static_cast<double>(len) / static_cast<double>(len_alone_same) : 0.0, alone_ok);
      if (exact_gaps) std::printf("%18s exact gaps: the plane scaled by %lld\n", "", static_cast<long long>(nr.scale()));
      if (planted) {
        std::int64_t all_len = 0;
        for (const auto& o : nr.outcomes())
          if (o.routed) all_len += total_length(o.wires);
        std::printf("%18s planted nets routed: %zu of %zu (%.2f %%); routed length %lld, the planted routing's %lld\n", "", routed,
                    nets.size(), 100.0 * static_cast<double>(routed) / static_cast<double>(std::max<std::size_t>(1, nets.size())),
                    static_cast<long long>(all_len), static_cast<long long>(planted_length));
      }
      std::map<std::string, int> codes;
      for (const auto& o : nr.outcomes())
        if (!o.routed)  // ROUTE-0012 split by why ripping up did not help
          ++codes[o.code + (o.code != "ROUTE-0012"                                  ? ""
                            : o.reason.find("may not be ripped up") != std::string::npos ? " (rip limit)"
                            : o.reason.find("gap of width zero") != std::string::npos    ? " (zero gap)"
                                                                                         : " (no way after rip-up)")];
      std::printf("%18s after %d rip-up rounds, unrouted:", "", nr.stats().rounds);
      for (const auto& [c, k] : codes) std::printf(" %s %d", c.c_str(), k);
      std::printf("\n");
      if (bends)
        std::printf("%18s bends: %lld together, %lld alone (all nets each way); %lld windows checked by the relaxation\n", "",
                    static_cast<long long>(together_bends), static_cast<long long>(alone_bends),
                    static_cast<long long>(nr.stats().relaxed));
      std::printf("%18s nets tried %lld times in %lld windows (%lld whole): building spaces %.3f s, paths %.3f s (whole windows: %.3f s); %lld attempts stopped at the window limit, final round routed %zu of %zu, last pass %zu of %zu (%lld proven apart by its superset)\n", "",
                  static_cast<long long>(nr.stats().attempts), static_cast<long long>(nr.stats().windows),
                  static_cast<long long>(nr.stats().whole), nr.stats().space_seconds, nr.stats().route_seconds, nr.stats().whole_seconds,
                  static_cast<long long>(nr.stats().capped), nr.stats().final_round_routed, nr.stats().final_round,
                  nr.stats().last_pass_routed, nr.stats().last_pass, static_cast<long long>(nr.stats().superset_apart));
      {
        const auto& ph = nr.stats().phase_seconds;
        std::printf("%18s phases (wall clock): first pass %.3f s, rip-up rounds %.3f s, final round %.3f s, last pass %.3f s, explaining %.3f s\n", "",
                    ph.first_pass, ph.rounds, ph.final_round, ph.last_pass, ph.explain);
        std::printf("%18s taken again without routing (nothing changed in their windows): %lld failed attempts, %lld undone rip-ups\n", "",
                    static_cast<long long>(nr.stats().reused), static_cast<long long>(nr.stats().replayed));
      }
      if (tighten) {
        std::vector<taut::router::NetLines> wires;
        std::int64_t bends_before = 0, bends_after = 0, bends_alone = 0, pieces = 0;
        for (const auto& o : nr.outcomes()) {
          wires.push_back(o.routed ? o.wires : taut::router::NetLines{});
          for (const auto& w : wires.back()) bends_before += taut::geom::count_bends(w);
        }
        // baseline: every wire alone among the plain blockages, one triangulation
        const double alone_t = taut::bench::seconds_of([&] {
          const taut::router::SpaceTightener st(lay.norm, taut::router::TightenOrientations::Rectilinear);
          bends_alone = 0;
          for (const auto& ws : wires)
            for (const auto& w : ws) {
              const auto r = st.run(w);
              bends_alone += taut::geom::count_bends(r.points.empty() ? w : r.points);
            }
        }, 1);
        taut::router::NetSpace space(dom, lay.norm.obstacles, nets, {10, 10});
        taut::router::NetsTightener nt(space);
        const double together_t = taut::bench::seconds_of([&] { nt.run(wires); }, 1);
        for (const auto& ws : wires) {
          pieces += static_cast<std::int64_t>(ws.size());
          for (const auto& w : ws) bends_after += taut::geom::count_bends(w);
        }
        std::printf("%18s tighten together: %.3f s, %.1f x alone (%.3f s); %d rounds, %lld of %lld wires moved, %lld kept; "
                    "bends %lld -> %lld (alone, no clearance: %lld); %lld windows (%lld whole)\n", "",
                    together_t, together_t / alone_t, alone_t, nt.stats().rounds, static_cast<long long>(nt.stats().moved),
                    static_cast<long long>(pieces), static_cast<long long>(nt.stats().kept), static_cast<long long>(bends_before),
                    static_cast<long long>(bends_after), static_cast<long long>(bends_alone),
                    static_cast<long long>(nt.stats().windows), static_cast<long long>(nt.stats().whole));
      }
      if (set_orient) {
        // baseline: the same nets routed octilinear (gaps closed), nothing tightened
        taut::router::NetRouterOptions oo = options(1);
        oo.octilinear = true;
        oo.exact_gaps = false;
        taut::router::NetRouter oct(dom, lay.norm.obstacles, nets, rules, oo);
        const double oct_s = taut::bench::seconds_of([&] { oct.run(taut::router::NetRouter::oct_router()); }, 1);
        std::size_t oct_routed = 0;
        for (const auto& o : oct.outcomes()) oct_routed += o.routed;
        // as taut route --orientations SET: each attempt tightened into a lattice set (unframed
        // windows), then every net together
        const taut::router::TightenOrientations to = *set_orient;
        taut::router::NetRouter sr(dom, lay.norm.obstacles, nets, rules, oo);
        std::vector<taut::router::NetLines> wires;
        std::size_t set_routed = 0, outside = 0;
        taut::router::NetsTightenStats nts;
        const double set_s = taut::bench::seconds_of([&] {
          const taut::router::NetRouteFn base = taut::router::NetRouter::oct_router();
          if (to.c_oriented())
            sr.run([&](std::size_t i, const taut::router::NetPins& pins, const taut::geom::NormalizedObstacles& obs) {
              // c:45,135 keeps the parity of x + y: a net of point pins of both parities is not
              // routed (taut route fails it with ROUTE-0021 before routing, so it takes no room)
              if (to.set && to.set->keeps_parity())
                for (const Polygon& p : pins.pins)
                  if ((p.outer[0].x + p.outer[0].y - pins.pins[0].outer[0].x - pins.pins[0].outer[0].y) % 2 != 0) {
                    taut::router::NetAttempt no;
                    no.code = "ROUTE-0021";
                    no.reason = "parity";
                    return no;
                  }
              taut::router::NetAttempt a = base(i, pins, obs);
              taut::router::tighten_attempt(a, pins, obs, to);
              return a;
            });
          else
            sr.run(base);
          wires.clear();
          for (const auto& o : sr.outcomes()) wires.push_back(o.routed ? o.wires : taut::router::NetLines{});
          taut::router::NetSpace space(dom, lay.norm.obstacles, nets, {10, 10});
          taut::router::NetsTightenOptions no;
          no.orientations = to;
          taut::router::NetsTightener nt(space, no);
          (void)nt.run(wires);
          nts = nt.stats();
        }, 1);
        for (std::size_t i = 0; i < wires.size(); ++i) {
          if (wires[i].empty()) continue;
          bool in = true;
          for (const auto& w : wires[i]) in = in && to.runs_in(w);
          set_routed += in;
          outside += !in;
        }
        std::printf("%18s --orientations %s: %.3f s, %.2f x routing octilinear alone (%.3f s); %zu routed in the set "
                    "(%zu left outside it), %zu octilinear; tightening: %d rounds, %lld wires moved\n", "",
                    set_word.c_str(), set_s, set_s / oct_s, oct_s, set_routed, outside, oct_routed, nts.rounds,
                    static_cast<long long>(nts.moved));
      }
      for (const std::int64_t t : thread_counts) {
        taut::router::NetRouter par(dom, lay.norm.obstacles, nets, rules, options(static_cast<int>(t)));
        const double par_s = taut::bench::seconds_of([&] { par.run(route_fn()); }, 1);
        bool same = true;
        for (std::size_t i = 0; i < nets.size(); ++i) {
          const auto &x = nr.outcomes()[i], &y = par.outcomes()[i];
          same = same && x.routed == y.routed && x.wires == y.wires && x.code == y.code && x.reason == y.reason &&
                 x.blockers == y.blockers && x.rips == y.rips;
        }
        std::printf("%18s %lld threads: %.3f s, %.2f x one thread's time; %lld of %lld speculative attempts redone; "
                    "%lld of %lld rip-ups worked out ahead worked out again; "
                    "building spaces %.3f s, paths %.3f s (kept attempts, summed over threads); outcomes %s\n", "",
                    static_cast<long long>(t), par_s, par_s / together_s, static_cast<long long>(par.stats().redone),
                    static_cast<long long>(par.stats().speculated), static_cast<long long>(par.stats().rip_ups_redone),
                    static_cast<long long>(par.stats().rip_ups_ahead), par.stats().space_seconds, par.stats().route_seconds,
                    same ? "the same" : "DIFFERENT");
        const auto& ph = par.stats().phase_seconds;
        std::printf("%18s %lld threads, phases (wall clock): first pass %.3f s, rip-up rounds %.3f s, final round %.3f s, "
                    "last pass %.3f s, explaining %.3f s\n", "",
                    static_cast<long long>(t), ph.first_pass, ph.rounds, ph.final_round, ph.last_pass, ph.explain);
        if (!same) return 1;
      }
      std::fflush(stdout);
      last_t = together_s, last_m = static_cast<double>(nets.size());
    }
  }
  return 0;
}
