// The seeded check shared by tests/router/spm_test.cpp (router::L1Map against
// oracle::L1Reference) and tests/router/oct_spm_test.cpp (router::OctMap against
// oracle::OctilinearReference): one instance of support/wavefront_cases.h per seed, 1-20 sources
// (repeats allowed: ties; one instance in four also gets a source that may not be free, which
// the map ignores while the others keep their indices) and 100 queries (candidates: vertices,
// points on edges, points of interest; then random points in the domain, free or not), and
// every query checked:
//   - is_free agrees with the reference;
//   - the distance is the least reference distance over the sources, exactly; null exactly when
//     no source reaches the query;
//   - the named source is at that distance (ties: any nearest source);
//   - the path runs from that source to the query, bending only at obstacle vertices (or domain
//     corners), every link free and the whole of exactly that length (the reference's
//     check_path, in its metric), and its last link starts at the answer's root.
// The map itself is built by the caller (which may check more of it); distances are whatever
// the map and the reference return (int64 for L1, geom::Root2 for octilinear).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geom/normalize.h"
#include "geom/root2.h"
#include "geom/types.h"
#include "io/layout_geometry.h"
#include "io/movingai.h"
#include "router/wavefront.h"
#include "support/run.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"

namespace taut::test {

inline std::string spm_pt(geom::Point p) { return "{" + std::to_string(p.x) + ", " + std::to_string(p.y) + "}"; }
inline std::string spm_num(std::int64_t d) { return std::to_string(d); }
inline std::string spm_num(const geom::Root2& r) { return std::to_string(r.a) + "+" + std::to_string(r.b) + "*sqrt2"; }

struct SpmTally {
  std::int64_t instances = 0, queries = 0, reachable = 0, unreachable = 0, not_free = 0, paths = 0, multi_source = 0,
               ties = 0, skipped = 0, blocked_sources = 0;
  std::int64_t diagonal = 0;  // reachable queries whose distance has a sqrt2 part (octilinear)
};

// One instance with its sources and queries, and its text for a failure report.
struct SpmInstance {
  WavefrontCase c;
  std::vector<geom::Point> sources, queries;
  std::set<geom::Point> vertices;  // obstacle vertices and domain corners: where paths may bend
  std::string head;                // seed, family, the instance as C++ initializers
};

// nullopt (counted as skipped) when the generator fails, the reference reports problems or no
// candidate is free. `salt` varies the sources and queries between the tests.
template <class Ref>
std::optional<SpmInstance> make_spm_instance(std::uint64_t seed, std::uint64_t salt, SpmTally& tally,
                                             std::optional<Ref>& ref) {
  SpmInstance in;
  try {
    in.c = make_wavefront_case(seed);
  } catch (const std::exception&) {
    ++tally.skipped;  // the generator's own failure (counted by the wavefront tests)
    return std::nullopt;
  }
  const WavefrontCase& c = in.c;
  ref.emplace(c.domain, c.obstacles);
  if (!ref->problems().empty()) {
    ++tally.skipped;
    return std::nullopt;
  }
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + salt);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  std::vector<geom::Point> free_pts;
  for (geom::Point p : c.candidates)
    if (ref->is_free(p)) free_pts.push_back(p);
  if (free_pts.empty()) {
    ++tally.skipped;
    return std::nullopt;
  }
  const std::size_t ns = 1 + pick(std::min<std::size_t>(20, free_pts.size() + 3));
  for (std::size_t i = 0; i < ns; ++i) in.sources.push_back(free_pts[pick(free_pts.size())]);
  if (pick(4) == 0) {
    const geom::Point extra = c.candidates[pick(c.candidates.size())];
    in.sources.insert(in.sources.begin() + static_cast<std::ptrdiff_t>(pick(in.sources.size() + 1)), extra);
    tally.blocked_sources += !ref->is_free(extra);
  }
  for (std::size_t i = 0; i < c.candidates.size() && in.queries.size() < 60; ++i)
    in.queries.push_back(c.candidates[pick(c.candidates.size())]);
  const geom::Box& D = c.domain;
  while (in.queries.size() < 100) {
    const std::int64_t x = D.lo.x + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(std::int64_t{D.hi.x} - D.lo.x + 1));
    const std::int64_t y = D.lo.y + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(std::int64_t{D.hi.y} - D.lo.y + 1));
    in.queries.push_back({static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)});
  }
  for (const auto& p : c.obstacles) {
    in.vertices.insert(p.outer.begin(), p.outer.end());
    for (const auto& h : p.holes) in.vertices.insert(h.begin(), h.end());
  }
  for (geom::Point corner : {D.lo, D.hi, geom::Point{D.lo.x, D.hi.y}, geom::Point{D.hi.x, D.lo.y}}) in.vertices.insert(corner);
  std::ostringstream os;
  os << "seed " << seed << " (family " << c.family << ")\n  domain {" << spm_pt(D.lo) << ", " << spm_pt(D.hi)
     << "}\n  obstacles {";
  for (const auto& p : c.obstacles) {
    os << "{{";
    for (std::size_t i = 0; i < p.outer.size(); ++i) os << (i ? ", " : "") << spm_pt(p.outer[i]);
    os << "}, {";
    for (std::size_t h = 0; h < p.holes.size(); ++h) {
      os << (h ? ", {" : "{");
      for (std::size_t i = 0; i < p.holes[h].size(); ++i) os << (i ? ", " : "") << spm_pt(p.holes[h][i]);
      os << "}";
    }
    os << "}}, ";
  }
  os << "}\n  sources {";
  for (geom::Point s : in.sources) os << spm_pt(s) << ", ";
  os << "}\n";
  in.head = os.str();
  return in;
}

// Every query of `in` against the reference; "" when all pass, else the report.
template <class Map, class Ref>
std::string check_spm_queries(const SpmInstance& in, const Map& map, const Ref& ref, SpmTally& tally) {
  using D = std::remove_cvref_t<decltype(map.locate(geom::Point{})->distance)>;
  std::vector<std::vector<std::optional<D>>> ref_d;  // [source][query]
  for (geom::Point s : in.sources) ref_d.push_back(ref.distances(s, in.queries));
  for (std::size_t i = 0; i < in.queries.size(); ++i) {
    const geom::Point q = in.queries[i];
    const std::string where = in.head + "  query " + spm_pt(q) + ": ";
    ++tally.queries;
    const bool rf = ref.is_free(q);
    if (map.is_free(q) != rf) return where + "is_free " + std::to_string(!rf) + ", reference " + std::to_string(rf) + "\n";
    std::optional<D> best;
    int at_best = 0;
    for (std::size_t s = 0; s < in.sources.size(); ++s)
      if (const auto d = ref_d[s][i]) {
        if (!best || *d < *best) {
          best = d;
          at_best = 0;
        }
        if (*d == *best) ++at_best;
      }
    const auto a = map.locate(q);
    if (!rf) {
      ++tally.not_free;
      if (a) return where + "not free, but the map answers " + spm_num(a->distance) + "\n";
      continue;
    }
    if (!best) {
      ++tally.unreachable;
      if (a) return where + "unreachable, but the map answers " + spm_num(a->distance) + "\n";
      if (!map.path(q).empty()) return where + "unreachable, but the map gives a path\n";
      continue;
    }
    if (!a) return where + "the map finds no source, reference distance " + spm_num(*best) + "\n";
    if (a->distance != *best) return where + "distance " + spm_num(a->distance) + ", reference " + spm_num(*best) + "\n";
    ++tally.reachable;
    tally.ties += at_best > 1;
    if constexpr (std::is_same_v<D, geom::Root2>) tally.diagonal += best->b != 0;
    if (a->source >= in.sources.size() || ref_d[a->source][i] != best)
      return where + "source " + std::to_string(a->source) + " is not at the least distance\n";
    const std::vector<geom::Point> path = map.path(q);
    if (path.empty() || path.front() != in.sources[a->source] || path.back() != q)
      return where + "the path does not run from the named source to the query\n";
    const geom::Point root = path.size() >= 2 ? path[path.size() - 2] : path.front();
    if (root != a->root && a->root != q) return where + "the path's last link does not start at the root " + spm_pt(a->root) + "\n";
    for (std::size_t k = 1; k + 1 < path.size(); ++k)
      if (!in.vertices.count(path[k])) return where + "the path bends at " + spm_pt(path[k]) + ", not an obstacle vertex\n";
    const auto len = ref.check_path(path);
    if (!len || *len != *best)
      return where + "the path is " + (len ? "of length " + spm_num(*len) : std::string("not free")) + "\n";
    ++tally.paths;
  }
  return "";
}

// Every answer of `map` and `plain` (the same map without its grid) the same; "" when so.
template <class Map>
std::string compare_spm_grid(const SpmInstance& in, const Map& map, const Map& plain) {
  for (const geom::Point q : in.queries) {
    const auto a = map.locate(q), b = plain.locate(q);
    if (a.has_value() != b.has_value() ||
        (a && (a->distance != b->distance || a->source != b->source || a->root != b->root || a->root_id != b->root_id)))
      return in.head + "  at " + spm_pt(q) + ": the grid and the persistent search answer differently\n";
  }
  return "";
}

// A Moving AI grid map (shared/data/movingai/NAME.map, cells of 10 DBU: blockages that touch and
// pinch everywhere) with n random query points, a quarter of them on grid lines, and 1-8 free
// sources among them. The map is checked against one Wave run (which the wavefront tests check
// against the reference): is_free and every distance equal. The map takes its vertex distances
// from the wavefront, so this checks the decomposition and its staircases.
struct GridMapCase {
  geom::NormalizedObstacles norm;
  std::vector<geom::Point> queries, sources;
  int reached = 0, mismatches = 0;
};
template <class Map, class Wave>
GridMapCase check_map_on_grid_map(const std::string& name, std::uint64_t seed, std::size_t n) {
  GridMapCase g;
  const auto r = io::load_movingai_map(shared_data_dir() + "/movingai/" + name + ".map", 10);
  if (!r.layout || !r.layout->boundary) {
    ADD_FAILURE() << name << " did not load";
    return g;
  }
  g.norm = geom::normalize_obstacles(io::blockage_polygons(*r.layout), r.layout->boundary->box);
  const geom::Box& dom = g.norm.domain;
  std::mt19937_64 rng(seed);
  Wave wf(dom, g.norm.obstacles);
  while (g.queries.size() < n) {
    geom::Point p{static_cast<geom::Coord>(dom.lo.x + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(dom.hi.x - dom.lo.x + 1))),
                  static_cast<geom::Coord>(dom.lo.y + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(dom.hi.y - dom.lo.y + 1)))};
    if (rng() % 4 == 0) p.x -= p.x % 10;
    if (rng() % 4 == 0) p.y -= p.y % 10;
    g.queries.push_back(p);
  }
  const std::size_t k = 1 + rng() % 8;
  for (const geom::Point q : g.queries)
    if (g.sources.size() < k && wf.is_free(q) && rng() % 50 == 0) g.sources.push_back(q);
  const Map map(dom, g.norm.obstacles, g.sources);
  wf.run(g.sources, g.queries, router::WavefrontStop::AllTargets);
  for (std::size_t i = 0; i < g.queries.size(); ++i) {
    const auto d = wf.target_distance(i);
    const auto a = map.locate(g.queries[i]);
    if (map.is_free(g.queries[i]) != wf.is_free(g.queries[i]) || d.has_value() != a.has_value() || (d && *d != a->distance)) {
      if (g.mismatches++ < 3)
        ADD_FAILURE() << name << " query " << spm_pt(g.queries[i]) << ": wavefront " << (d ? spm_num(*d) : "none")
                      << ", map " << (a ? spm_num(a->distance) : "none");
      continue;
    }
    g.reached += d.has_value();
  }
  return g;
}

// The same case's queries against the brute-force reference (small maps only): how many differ.
template <class Map, class Ref>
int grid_map_reference_mismatches(const GridMapCase& g) {
  const Ref ref(g.norm.domain, g.norm.obstacles);
  using D = std::remove_cvref_t<decltype(*ref.distance(geom::Point{}, geom::Point{}))>;
  std::vector<std::optional<D>> best(g.queries.size());
  for (const geom::Point s : g.sources) {
    const auto d = ref.distances(s, g.queries);
    for (std::size_t i = 0; i < g.queries.size(); ++i)
      if (d[i] && (!best[i] || *d[i] < *best[i])) best[i] = d[i];
  }
  const Map map(g.norm.domain, g.norm.obstacles, g.sources);
  int mismatches = 0;
  for (std::size_t i = 0; i < g.queries.size(); ++i) {
    const auto a = map.locate(g.queries[i]);
    if (a.has_value() != best[i].has_value() || (a && a->distance != *best[i])) ++mismatches;
  }
  return mismatches;
}

// The least reference distance from any of the points (free ones) to each target; nullopt: none
// reaches it.
// The distance type is the reference's (int64 for L1Reference, Root2 for OctilinearReference).
template <class Ref>
auto least_distances(const Ref& ref, const std::vector<geom::Point>& from, const std::vector<geom::Point>& targets) {
  std::vector<typename decltype(ref.distances(geom::Point{}, targets))::value_type> best(targets.size());
  for (const geom::Point p : from) {
    if (!ref.is_free(p)) continue;
    const auto d = ref.distances(p, targets);
    for (std::size_t i = 0; i < targets.size(); ++i)
      if (d[i] && (!best[i] || *d[i] < *best[i])) best[i] = d[i];
  }
  return best;
}

// The seeds of the random tests: 1..1000 and 100 of the larger instances (an eighth of each
// under the sanitizers, support/sanitized.h).
inline std::vector<std::uint64_t> spm_seed_list() {
  std::vector<std::uint64_t> seeds;
  for (std::int64_t s = 1; s <= sanitized_share(1000, 4); ++s) seeds.push_back(static_cast<std::uint64_t>(s));
  for (std::int64_t s = 0; s < sanitized_share(100, 4); ++s) seeds.push_back(kLargeSeedBase + static_cast<std::uint64_t>(s));
  return seeds;
}

// check(seed) over the seeds: the first three failures in full, then every failing seed (up to
// 30) with the variable that reruns one.
inline void run_spm_seeds(const std::vector<std::uint64_t>& seeds, const std::function<std::string(std::uint64_t)>& check,
                          const char* env) {
  int reported = 0;
  std::vector<std::uint64_t> failed;
  for (std::uint64_t seed : seeds) {
    const std::string r = check(seed);
    if (r.empty()) continue;
    failed.push_back(seed);
    if (reported++ < 3) ADD_FAILURE() << r;
  }
  if (!failed.empty()) {
    std::string list;
    for (std::size_t i = 0; i < failed.size() && i < 30; ++i) list += std::to_string(failed[i]) + " ";
    ADD_FAILURE() << failed.size() << " failing seeds: " << list << "(" << env << "=N reruns one)";
  }
}

// Seeds 1..n (sanitized_share(n, sanitized_divisor) of them under the sanitizers) through
// check, or only the seed the environment variable `env` names. False when it named one (the
// caller's totals then mean nothing and its thresholds are skipped).
inline bool run_seed_range(const char* env, std::int64_t n, const std::function<std::string(std::uint64_t)>& check,
                           std::int64_t sanitized_divisor = 4) {
  if (const char* s = std::getenv(env)) {
    run_spm_seeds({std::strtoull(s, nullptr, 10)}, check, env);
    return false;
  }
  std::vector<std::uint64_t> seeds;
  for (std::int64_t s = 1; s <= sanitized_share(n, sanitized_divisor); ++s) seeds.push_back(static_cast<std::uint64_t>(s));
  run_spm_seeds(seeds, check, env);
  return true;
}

}  // namespace taut::test
