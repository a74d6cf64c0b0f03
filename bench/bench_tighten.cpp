// Benchmark of homotopic tightening (router/tighten.h): the lift into the triangulation (the
// sleeve) and the funnel, on generated layouts of 10^3 .. 10^5 blockage vertices.
//
// Sketches: W wires, each the concatenation of 1 to 4 legs of exact L1 shortest paths through
// one source in the middle of the layout (router::L1Map paths, bends at obstacle vertices):
// q1 -> s -> q2 [-> s -> q3 ...], so a sketch crosses the layout up to 8 times and its class is
// whatever those paths make it. Every sketch is tightened; times are the best of R runs.
//
// Printed per size: the triangles, the sketches' edge crossings and sleeve triangles in total,
// the time to tighten all W (lift + funnel), the funnel alone (on the stored sleeves) in
// sleeve triangles per second, and the ratio of each to a baseline measured in the same run on
// the same data: `pass` = one pass over every sleeve's triangles reading their three vertex
// indices (the memory traffic any linear algorithm on the sleeve must pay). Then, for the
// largest size, the time per sleeve triangle bucketed by sleeve length (growth against sleeve
// length: flat means linear). `online_s`: the same sketches fed point by point to
// router::OnlineTightener with the current path read after every point (a path per point, so
// it is expected to cost more than one tightening at the end). Then the time to write every taut
// wire in rectilinear, octilinear, c:0,45 and c:45,135 directions (router::c_oriented: the fewest-link
// staircases of the class, best of R, as a ratio to tightening them), the same in c:0,60,120
// (router::Root3StaircaseBuilder: exact in Q(sqrt3), rounded, each tightened back as the CLI
// checks it; one run, as a ratio to tightening and to the rectilinear output), and the minimum-link paths
// of the first 1,000 (router::MinLinker: time, links against the shortest wire's, and
// the longest exact coordinate written out), minimum-link octilinear and c:0,45,90 paths of the
// same wires (router::CMinLinker, section 6.3: time, links against the shortest wire's in that
// set, sweeps and pieces per wire, and the time per wire by the taut wire's vertices), and minimum-link loops (MinLinker::loop) of up to 300
// shortest loops of random closed walks among nearby free points (time as a ratio to tightening
// those loops again, links, how many are proven minimal), and the same loops in rectilinear and
// octilinear (CMinLinker::loop: time, links, lower bound, proven, starts). Targets (issue #5): funnel >= 10^7 triangles/s; 10^4 wires on a
// 10^5-vertex layout under 10 s.
//
//   bench_tighten [--sizes N,N,..] [--wires W] [--kind rects|polygons|maze|degenerate] [--reps R]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/free_points.h"
#include "geom/root3_directions.h"
#include "geom/triangulation.h"
#include "router/root3_staircase.h"
#include "router/spm.h"
#include "router/c_minlink.h"
#include "router/minlink.h"
#include "router/tighten.h"

namespace {

using taut::bench::seconds_of;
using taut::geom::Point;

std::vector<std::int64_t> parse_list(const char* s) {
  std::vector<std::int64_t> v;
  for (const char* p = s; *p;) {
    v.push_back(std::atoll(p));
    while (*p && *p != ',') ++p;
    if (*p == ',') ++p;
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {1000, 10000, 100000};
  int wires = 10000, reps = 3;
  std::string kind_name = "rects";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--wires") && i + 1 < argc) wires = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind_name = argv[++i];
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--sizes N,N,..] [--wires W] [--kind K] [--reps R]\n", argv[0]);
      return 2;
    }
  }
  const auto kind = taut::io::parse_gen_kind(kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", kind_name.c_str());
    return 2;
  }
  std::printf("bench_tighten: %d wires per layout, kind %s, best of %d\n", wires, kind_name.c_str(), reps);
  std::printf("%9s %9s | %10s %10s | %9s %7s | %9s %11s %7s | %9s %8s | %8s\n", "vertices", "triangles", "crossings",
              "sleeve", "tighten_s", "/pass", "funnel_s", "tri/s", "/pass", "online_s", "/tighten", "failures");
  std::map<int, std::pair<double, std::int64_t>> buckets;  // log4(sleeve) -> (seconds, triangles)
  int failures_total = 0;
  for (std::size_t si = 0; si < sizes.size(); ++si) {
    const auto b = taut::bench::bench_layout(*kind, sizes[si]);
    const auto tri = taut::geom::triangulate_free_space(b.norm.domain, b.norm.obstacles);
    if (!tri.ok()) {
      std::printf("%9zu: triangulation failed\n", b.points.size());
      return 1;
    }
    const taut::router::Tightener tight(tri);
    const auto& D = b.norm.domain;
    const std::vector<Point> pts = taut::bench::random_free_points(D, b.norm.obstacles, static_cast<std::size_t>(4 * wires + 1), 7);
    // the source: the free point nearest the middle
    const Point mid{static_cast<taut::geom::Coord>((std::int64_t{D.lo.x} + D.hi.x) / 2),
                    static_cast<taut::geom::Coord>((std::int64_t{D.lo.y} + D.hi.y) / 2)};
    Point src = pts[0];
    for (Point p : pts)
      if (std::llabs(std::int64_t{p.x} - mid.x) + std::llabs(std::int64_t{p.y} - mid.y) <
          std::llabs(std::int64_t{src.x} - mid.x) + std::llabs(std::int64_t{src.y} - mid.y))
        src = p;
    const taut::router::L1Map map(D, b.norm.obstacles, std::span<const Point>(&src, 1));
    std::mt19937_64 rng(11);
    std::vector<std::vector<Point>> sketches;
    std::size_t next = 1;
    for (int w = 0; w < wires; ++w) {
      const int legs = 1 + static_cast<int>(rng() % 4);
      std::vector<Point> sk;
      for (int l = 0; l < legs + 1 && next < pts.size(); ++l) {
        std::vector<Point> p = map.path(pts[next++]);
        if (p.empty()) continue;
        if (sk.empty()) {
          std::reverse(p.begin(), p.end());  // q1 -> s
          sk = p;
        } else {
          sk.insert(sk.end(), p.begin() + 1, p.end());  // s -> q
          if (l < legs) sk.insert(sk.end(), p.rbegin() + 1, p.rend());  // and back to s
        }
      }
      if (sk.size() >= 2) sketches.push_back(std::move(sk));
    }
    // lift once to keep the sleeves for the funnel-only timing
    std::vector<taut::router::Sleeve> sleeves(sketches.size());
    std::int64_t crossings = 0, sleeve_tris = 0;
    int failures = 0;
    for (std::size_t i = 0; i < sketches.size(); ++i) {
      if (tight.lift(sketches[i], sleeves[i]) != taut::router::TightenStatus::Ok) ++failures;
      crossings += static_cast<std::int64_t>(sleeves[i].crossings);
      sleeve_tris += static_cast<std::int64_t>(sleeves[i].triangles.size());
    }
    volatile std::int64_t sink = 0;
    const double t_tighten = seconds_of(
        [&] {
          for (const auto& sk : sketches) sink = sink + static_cast<std::int64_t>(tight.tighten(sk).points.size());
        },
        reps);
    const double t_funnel = seconds_of(
        [&] {
          for (std::size_t i = 0; i < sketches.size(); ++i)
            sink = sink + static_cast<std::int64_t>(tight.funnel(sketches[i].front(), sketches[i].back(), sleeves[i]).size());
        },
        reps);
    // on-line: each sketch fed point by point, its path read after every point
    const double t_online = seconds_of(
        [&] {
          for (const auto& sk : sketches) {
            taut::router::OnlineTightener on(tight, sk.front());
            for (std::size_t k = 1; k < sk.size(); ++k) {
              on.extend(sk[k]);
              sink = sink + static_cast<std::int64_t>(on.path().size());
            }
          }
        },
        reps);
    // rectilinear and octilinear output: each taut wire written as the fewest-link staircase of
    // the class's shortest c-oriented paths (StaircaseBuilder::staircase_in_class; its search
    // budget is not used)
    const taut::router::StaircaseBuilder sb(D, b.norm.obstacles);
    std::vector<std::vector<Point>> taut_paths;
    for (const auto& sk : sketches) taut_paths.push_back(tight.tighten(sk).points);
    // and two other lattice direction sets: one axis and one diagonal (c:0,45: cones up to 135
    // degrees wide), and the two diagonals (c:45,135: pieces only between points of one parity)
    const taut::geom::LatticeDirections c_sets[4] = {
        taut::geom::LatticeDirections::rectilinear(), taut::geom::LatticeDirections::octilinear(),
        *taut::geom::LatticeDirections::parse("c:0,45"), *taut::geom::LatticeDirections::parse("c:45,135")};
    int c_missing[4] = {0, 0, 0, 0};
    long long c_links[4] = {0, 0, 0, 0};
    double t_c[4] = {0, 0, 0, 0};
    for (int o = 0; o < 4; ++o)
      t_c[o] = seconds_of(
          [&] {
            c_missing[o] = 0;
            c_links[o] = 0;
            for (const auto& t : taut_paths) {
              const auto c = taut::router::c_oriented(tight, sb, t, c_sets[o]);
              c_missing[o] += c.points.empty();
              if (!c.points.empty()) c_links[o] += static_cast<long long>(c.points.size()) - 1;
              sink = sink + static_cast<std::int64_t>(c.points.size());
            }
          },
          reps);
    // a set at multiples of 30 degrees (router/root3_staircase.h: exact in Q(sqrt3), rounded, each
    // rounded wire tightened back to check it, as the CLI does)
    // and (since 2026-12-07) a set at other angles, c:0,10,90 (Root3Directions::parse_any: 10
    // degrees as an integer step of about 2^24, points rational)
    const taut::geom::Root3Directions hex = *taut::geom::Root3Directions::parse("c:0,60,120");
    const taut::router::Root3StaircaseBuilder sb30(D, b.norm.obstacles);
    struct SetOutput {
      taut::geom::Root3Directions set;
      double seconds = 0;
      int missing = 0, pinched = 0, unrounded = 0;
      long long links = 0, moved = 0;
    };
    std::vector<SetOutput> outs{{hex}, {*taut::geom::Root3Directions::parse_any("c:0,10,90")}};
    for (SetOutput& so : outs)
      so.seconds = seconds_of(
          [&] {
            so.missing = so.pinched = so.unrounded = 0;
            so.links = so.moved = 0;
            for (const auto& t : taut_paths) {
              const auto w = taut::router::c_oriented(tight, sb30, t, so.set);
              const bool ok = w.ok();
              so.missing += !ok;
              so.pinched += !w.ok() && w.why.rfind("no staircase", 0) == 0;
              so.unrounded += !w.ok() && w.why.rfind("rounded to integer vertices, every wire", 0) == 0;
              if (ok) so.links += static_cast<long long>(w.points.size()) - 1, so.moved += w.moved;
            }
          },
          1);
    taut_paths.resize(std::min<std::size_t>(taut_paths.size(), 1000));  // min-link: the first 1,000
    // minimum-link paths of the same taut wires (router::MinLinker, exact rationals)
    const taut::router::MinLinker ml(tri);
    long long ml_links = 0, taut_links = 0;
    std::size_t ml_digits = 0;
    const double t_minlink = seconds_of(
        [&] {
          ml_links = taut_links = 0;
          ml_digits = 0;
          for (const auto& t : taut_paths) {
            const auto m = ml.path(t);
            ml_links += static_cast<long long>(m.links());
            taut_links += static_cast<long long>(t.size()) - 1;
            for (const auto& p : m.points) ml_digits = std::max({ml_digits, p.x.str().size(), p.y.str().size()});
          }
        },
        1);
    // minimum-link octilinear and c:0,45,90 paths of the same taut wires (router::CMinLinker, H&S
    // section 6.3, exact rationals), against the links of the shortest wire in those directions
    // (router::c_oriented); per wire the time, bucketed by the taut wire's vertices (growth)
    const taut::router::CMinLinker cml(tri);
    const taut::geom::LatticeDirections m_sets[2] = {taut::geom::LatticeDirections::octilinear(),
                                                     *taut::geom::LatticeDirections::parse("c:0,45,90")};
    struct MStats {
      double seconds = 0;
      long long links = 0, shortest_links = 0, fewer = 0, none = 0, sweeps = 0, pieces = 0;
      std::map<int, std::pair<double, long long>> by_vertices;  // log2(vertices) -> (seconds, wires)
    } ms[2];
    for (int o = 0; o < 2; ++o) {
      for (const auto& t : taut_paths) {
        const auto c = taut::router::c_oriented(tight, sb, t, m_sets[o]);
        taut::router::CMinLinkPath m;
        const double tw = seconds_of([&] { m = cml.path(t, m_sets[o]); }, 1);
        ms[o].seconds += tw;
        auto& bk = ms[o].by_vertices[static_cast<int>(std::log2(static_cast<double>(t.size())))];
        bk.first += tw;
        ++bk.second;
        if (!m.ok()) {
          ++ms[o].none;
          continue;
        }
        ms[o].links += static_cast<long long>(m.links());
        ms[o].sweeps += static_cast<long long>(m.sweeps);
        ms[o].pieces += static_cast<long long>(m.pieces);
        if (!c.points.empty()) {
          ms[o].shortest_links += static_cast<long long>(taut::geom::count_bends(c.points)) + 1;
          ms[o].fewer += static_cast<long long>(m.links()) < static_cast<long long>(taut::geom::count_bends(c.points)) + 1;
        }
      }
    }
    // the same in c:0,60,120 (CMinLinker over Q(sqrt3), since 2026-12-07): per wire the time
    // (growth as above), links against the exact staircase's of the same wire
    MStats m3;
    long long m3_staircase_links = 0, m3_staircases = 0;
    for (const auto& t : taut_paths) {
      taut::router::CMinLinkPath3 m;
      const double tw = seconds_of([&] { m = cml.path(t, hex); }, 1);
      m3.seconds += tw;
      auto& bk = m3.by_vertices[static_cast<int>(std::log2(static_cast<double>(t.size())))];
      bk.first += tw;
      ++bk.second;
      if (!m.ok()) {
        ++m3.none;
        continue;
      }
      m3.links += static_cast<long long>(m.links());
      m3.sweeps += static_cast<long long>(m.sweeps);
      const auto w = sb30.staircase(t, hex, [&](Point p, Point q) { return tight.free(p, q); });
      if (w.ok()) {
        ++m3_staircases;
        m3_staircase_links += static_cast<long long>(w.exact.size()) - 1;
        m3.fewer += m.links() + 1 < w.exact.size();
        m3.shortest_links += static_cast<long long>(m.links());  // (the same wires' own links)
      }
    }
    // minimum-link loops (MinLinker::loop): closed walks of six free segments between random free
    // points near each other, tightened to their shortest loops (the contractible ones dropped)
    std::vector<std::vector<Point>> loops;
    {
      std::mt19937_64 lr(23);
      const std::int64_t radius = (std::int64_t{D.hi.x} - D.lo.x) / 6;
      auto near = [&](Point a, Point q) {
        return std::llabs(std::int64_t{a.x} - q.x) + std::llabs(std::int64_t{a.y} - q.y) <= radius;
      };
      auto free_segment = [&](Point a, Point q) {
        const auto r = tight.tighten(std::vector<Point>{a, q});
        return r.status == taut::router::TightenStatus::Ok && r.points.size() == 2;
      };
      for (int tries = 0; tries < 200000 && loops.size() < 300; ++tries) {
        std::vector<Point> w{pts[lr() % pts.size()]};
        for (int k = 0; k < 4000 && w.size() < 6; ++k) {
          const Point q = pts[lr() % pts.size()];
          if (q != w.back() && near(w.front(), q) && free_segment(w.back(), q)) w.push_back(q);
        }
        if (w.size() < 6 || !free_segment(w.back(), w.front())) continue;
        w.push_back(w.front());
        const auto l = tight.tighten_loop(w);
        if (l.status == taut::router::TightenStatus::Ok && !l.contractible) loops.push_back(l.points);
      }
    }
    long long loop_links = 0, loop_vertices = 0, loop_proven = 0, loop_inflection = 0;
    const double t_loops = seconds_of(
        [&] {
          loop_links = loop_vertices = loop_proven = loop_inflection = 0;
          for (const auto& l : loops) {
            const auto m = ml.loop(l);
            loop_links += static_cast<long long>(m.links());
            loop_vertices += static_cast<long long>(l.size()) - 1;
            loop_proven += m.minimal;
            loop_inflection += m.inflection;
          }
        },
        1);
    const double t_tighten_loops = seconds_of(
        [&] {
          for (const auto& l : loops) sink = sink + static_cast<std::int64_t>(tight.tighten_loop(l).points.size());
        },
        reps);
    // the same loops in rectilinear and octilinear (CMinLinker::loop)
    struct CLoops {
      double seconds = 0;
      long long links = 0, proven = 0, none = 0, starts = 0, bound = 0;
    };
    CLoops cl[2];
    for (int o = 0; o < 2; ++o) {
      const taut::geom::LatticeDirections set =
          o == 0 ? taut::geom::LatticeDirections::rectilinear() : taut::geom::LatticeDirections::octilinear();
      cl[o].seconds = seconds_of(
          [&] {
            cl[o] = CLoops{};
            for (const auto& l : loops) {
              const auto m = cml.loop(l, set);
              cl[o].none += !m.ok();
              cl[o].links += static_cast<long long>(m.links());
              cl[o].proven += m.minimal;
              cl[o].starts += static_cast<long long>(m.starts);
              cl[o].bound += static_cast<long long>(m.at_least);
            }
          },
          1);
    }
    const auto& tris = tri.triangles();
    const double t_pass = seconds_of(
        [&] {
          std::int64_t s = 0;
          for (const auto& sl : sleeves)
            for (std::int32_t t : sl.triangles) {
              const auto& tr = tris[static_cast<std::size_t>(t)];
              s += tr.v[0] + tr.v[1] + tr.v[2];
            }
          sink = sink + s;
        },
        reps);
    std::printf("%9zu %9zu | %10lld %10lld | %9.3f %7.1f | %9.4f %11.3g %7.1f | %9.3f %8.2f | %8d\n", b.points.size(),
                tris.size(), static_cast<long long>(crossings), static_cast<long long>(sleeve_tris), t_tighten,
                t_tighten / t_pass, t_funnel, static_cast<double>(sleeve_tris) / t_funnel, t_funnel / t_pass, t_online,
                t_online / t_tighten, failures);
    for (int o = 0; o < 4; ++o)
      std::printf("%9s %s output of the %zu taut wires: %.3f s (%.3f ms per wire, %.1f x tightening one), "
                  "%d without a lattice staircase in the class, %.2f links per wire\n",
                  "", c_sets[o].name().c_str(), sketches.size(), t_c[o],
                  t_c[o] / static_cast<double>(sketches.size()) * 1e3, t_c[o] / t_tighten, c_missing[o],
                  static_cast<double>(c_links[o]) / static_cast<double>(sketches.size() - static_cast<std::size_t>(c_missing[o])));
    for (const SetOutput& so : outs)
      std::printf("%9s %s output of the %zu taut wires: %.3f s (%.3f ms per wire, %.1f x tightening one, %.1f x "
                  "rectilinear output), %d without a wire in the set (%d pinched, %d no free rounding, the rest not "
                  "tightened back), %.2f links per wire, %lld vertices off their nearest integer point\n",
                  "", so.set.name().c_str(), sketches.size(), so.seconds,
                  so.seconds / static_cast<double>(sketches.size()) * 1e3, so.seconds / t_tighten, so.seconds / t_c[0],
                  so.missing, so.pinched, so.unrounded,
                  static_cast<double>(so.links) / static_cast<double>(sketches.size() - static_cast<std::size_t>(so.missing)),
                  so.moved);
    std::printf("%9s minimum-link paths of the first %zu wires: %.3f s (%.2f ms per wire, %.1f x tightening one), "
                "%.2f links per wire against %.2f for the shortest, longest coordinate %zu characters\n",
                "", taut_paths.size(), t_minlink, t_minlink / static_cast<double>(taut_paths.size()) * 1e3,
                t_minlink / static_cast<double>(taut_paths.size()) / (t_tighten / static_cast<double>(sketches.size())),
                static_cast<double>(ml_links) / static_cast<double>(taut_paths.size()),
                static_cast<double>(taut_links) / static_cast<double>(taut_paths.size()), ml_digits);
    for (int o = 0; o < 2; ++o) {
      const double n = static_cast<double>(taut_paths.size());
      std::printf("%9s minimum-link %s paths of the first %zu wires: %.3f s (%.2f ms per wire, %.1f x tightening one), "
                  "%.2f links per wire against %.2f for the shortest %s wire (fewer on %lld), %lld with none, %.1f "
                  "sweeps and %.0f pieces per wire\n",
                  "", m_sets[o].name().c_str(), taut_paths.size(), ms[o].seconds, ms[o].seconds / n * 1e3,
                  ms[o].seconds / n / (t_tighten / static_cast<double>(sketches.size())),
                  static_cast<double>(ms[o].links) / (n - static_cast<double>(ms[o].none)),
                  static_cast<double>(ms[o].shortest_links) / (n - static_cast<double>(ms[o].none)),
                  m_sets[o].name().c_str(), ms[o].fewer, ms[o].none,
                  static_cast<double>(ms[o].sweeps) / (n - static_cast<double>(ms[o].none)),
                  static_cast<double>(ms[o].pieces) / (n - static_cast<double>(ms[o].none)));
      std::printf("%9s   growth: taut vertices", "");
      for (const auto& [k, v] : ms[o].by_vertices) std::printf(" | %d..%d: %.2f ms", 1 << k, (2 << k) - 1, v.first / static_cast<double>(v.second) * 1e3);
      std::printf("\n");
    }
    {
      const double n = static_cast<double>(taut_paths.size()), found = n - static_cast<double>(m3.none);
      std::printf("%9s minimum-link %s paths of the first %zu wires: %.3f s (%.2f ms per wire, %.1f x tightening one, "
                  "%.2f x the %s ones), %.2f links per wire, %.2f against %.2f for the exact shortest wire where "
                  "there is one (%lld wires, fewer on %lld), %lld with none, %.1f sweeps per wire\n",
                  "", hex.name().c_str(), taut_paths.size(), m3.seconds, m3.seconds / n * 1e3,
                  m3.seconds / n / (t_tighten / static_cast<double>(sketches.size())), m3.seconds / ms[0].seconds,
                  m_sets[0].name().c_str(), static_cast<double>(m3.links) / found,
                  static_cast<double>(m3.shortest_links) / static_cast<double>(std::max(1LL, m3_staircases)),
                  static_cast<double>(m3_staircase_links) / static_cast<double>(std::max(1LL, m3_staircases)),
                  m3_staircases, m3.fewer, m3.none, static_cast<double>(m3.sweeps) / found);
      std::printf("%9s   growth: taut vertices", "");
      for (const auto& [k, v] : m3.by_vertices) std::printf(" | %d..%d: %.2f ms", 1 << k, (2 << k) - 1, v.first / static_cast<double>(v.second) * 1e3);
      std::printf("\n");
    }
    if (!loops.empty())
      std::printf("%9s minimum-link loops of %zu shortest loops: %.3f s (%.2f ms per loop, %.1f x tightening one), %.2f "
                  "links per loop against %.2f vertices of the shortest, %lld proven minimal (%lld by an inflection edge)\n",
                  "", loops.size(), t_loops, t_loops / static_cast<double>(loops.size()) * 1e3,
                  t_loops / (t_tighten_loops > 0 ? t_tighten_loops : 1e-9),
                  static_cast<double>(loop_links) / static_cast<double>(loops.size()),
                  static_cast<double>(loop_vertices) / static_cast<double>(loops.size()), loop_proven, loop_inflection);
    for (int o = 0; o < 2 && !loops.empty(); ++o) {
      const double n = static_cast<double>(loops.size()), found = n - static_cast<double>(cl[o].none);
      std::printf("%9s minimum-link %s loops of the same loops: %.3f s (%.2f ms per loop, %.1f x tightening one), "
                  "%.2f links per loop (lower bound %.2f), %lld proven minimal, %lld with none, %.1f starts per loop\n",
                  "", o == 0 ? "rectilinear" : "octilinear", cl[o].seconds, cl[o].seconds / n * 1e3,
                  cl[o].seconds / (t_tighten_loops > 0 ? t_tighten_loops : 1e-9), static_cast<double>(cl[o].links) / found,
                  static_cast<double>(cl[o].bound) / found, cl[o].proven, cl[o].none, static_cast<double>(cl[o].starts) / n);
    }
    std::fflush(stdout);
    failures_total += failures;
    if (si + 1 == sizes.size()) {
      for (std::size_t i = 0; i < sketches.size(); ++i) {
        const std::int64_t n = static_cast<std::int64_t>(sleeves[i].triangles.size());
        if (n < 4) continue;
        const double t = seconds_of([&] { sink = sink + static_cast<std::int64_t>(tight.tighten(sketches[i]).points.size()); }, 1);
        auto& bk = buckets[static_cast<int>(std::log(static_cast<double>(n)) / std::log(4.0))];
        bk.first += t;
        bk.second += n;
      }
      std::printf("\ngrowth against sleeve length (largest size; lift + funnel per wire, summed per bucket)\n");
      std::printf("%18s %8s %12s\n", "sleeve triangles", "wires", "ns/triangle");
      for (const auto& [k, v] : buckets) {
        std::int64_t count = 0;
        for (const auto& sl : sleeves) {
          const std::int64_t n = static_cast<std::int64_t>(sl.triangles.size());
          count += n >= 4 && static_cast<int>(std::log(static_cast<double>(n)) / std::log(4.0)) == k;
        }
        std::printf("%8.0f .. %7.0f %8lld %12.1f\n", std::pow(4.0, k), std::pow(4.0, k + 1) - 1,
                    static_cast<long long>(count), v.first / static_cast<double>(v.second) * 1e9);
      }
    }
  }
  return failures_total ? 1 : 0;
}
