// Seeded random instances for checking router::L1Wavefront against the brute-force reference
// oracle::L1Reference (tests/oracle/l1_oracle.h), shared by tests/router/wavefront_test.cpp
// (a few thousand instances, runs in make test) and tests/router/wavefront_long_test.cpp
// (tens of thousands, label "long"); and, with WaveMetric::Octilinear, router::OctWavefront
// against oracle::OctilinearReference (tests/oracle/oct_oracle.h), by
// tests/router/oct_wavefront_test.cpp and tests/router/oct_wavefront_long_test.cpp.
//
// Both metrics run the same generator, the same queries (a seed means the same instance and the
// same queries in either metric) and the same checks, written once over a small metric-traits
// struct in wavefront_cases.cpp. Only these differ: distances are int64 for L1 and exact
// geom::Root2 numbers a + b*sqrt2 for the octilinear metric (compared exactly, printed as
// "a+b*sqrt2 (~value)"); target paths are measured by the reference's check_path in its metric
// (the octilinear paths have links of any direction, each measured by d8); a stop_early run is
// Stop::AllTargets for OctWavefront, a full run Stop::Never; and the check of
// router::l1_distance is L1 only.
//
// One seed is one instance: make_wavefront_case(seed) draws a layout from one of the families
// below with std::mt19937_64(seed) (hand-written range mapping, no std distributions, so a seed
// means the same instance everywhere), normalizes it with geom::normalize_obstacles, and lists
// query candidates (free or not). check_wavefront_seed(seed) then runs single- and multi-source
// queries on it and compares everything the wavefront promises (wavefront.h) with the reference:
// is_free, target distances (exactly), target_source, target paths (valid in free space per
// L1Reference::check_path, of the reported length, from the reported source to the target,
// bending only at obstacle vertices; a bend at a domain corner is allowed and counted),
// vertex_distance, and plausible WavefrontStats (reported apart, so they never hide a wrong
// distance).
//
// Families (seed % 9): the four `taut gen` kinds at small sizes (rects, polygons, maze,
// degenerate; sometimes with the domain cut down so obstacles are clipped by or flush with the
// domain side), and five hand-made ones on a coarse grid (multiples of 10 in a ~0..100 box) with
// heavy degeneracy: grid-rects (rectangles touching at corners, along edges, flush with the
// domain side, rings), grid-diagonal (diamonds, 45-degree triangles, octagons, sloped triangles
// and parallelograms, tips touching vertices, the domain side and a domain corner), rings
// (sources and targets walled in, C-shaped rings with and without a gap, rings closed only by
// pinches, a hole touching its shell or another hole at one point, things nested in holes),
// pinches (checkerboards, corner-touching walls and diamond chains across the domain:
// unreachable halves) and fine (arbitrary small integer coordinates, sloped crossings that
// normalize rounds). Each instance is then turned or mirrored by one of the eight symmetries of
// the square (7 in 8), and one in ten is scaled up towards the coordinate limit 2^30 - 1 and
// moved off the origin. Seeds >= kLargeSeedBase draw the same families with about three times as
// many shapes.
//
// On a mismatch the report names the seed, the family, the instance (domain and obstacle rings
// as C++ initializers), the query and both answers, then the same mismatch on an instance shrunk
// by dropping obstacles, holes, sources and targets while it still fails: paste it into a
// hand-written test, or add the seed to the regression table of wavefront_test.cpp
// (oct_wavefront_test.cpp for the octilinear metric).
// TAUT_WAVEFRONT_SEED=N runs only seed N of the L1 test and TAUT_OCT_SEED=N only seed N of the
// octilinear test, printing every query and answer (wavefront_seed_from_env(metric));
// TAUT_WAVEFRONT_TRACE=1 prints each seed before it runs (either metric). A crash (signal)
// prints the seed being checked; a sanitizer report does not (use the trace).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geom/types.h"

namespace taut::test {

inline constexpr std::uint64_t kLargeSeedBase = 1'000'000'000'000ULL;

// Which engine and reference the checks compare: L1Wavefront with L1Reference, or OctWavefront
// with OctilinearReference.
// Farey2..Farey4: router::NormWavefront of that order with oracle::NormReference.
enum class WaveMetric { L1, Octilinear, Farey2, Farey3, Farey4 };

struct WavefrontCase {
  std::uint64_t seed = 0;
  std::string family;
  geom::Box domain;
  std::vector<geom::Polygon> obstacles;  // as geom::normalize_obstacles() returns them
  std::vector<geom::Point> candidates;   // query candidates, free or not
  std::size_t special = 0;   // the first `special` candidates are points of interest (inside
                             // holes, pins of generated layouts), preferred as sources
  bool transformed = false;  // turned and/or mirrored
  bool huge = false;         // scaled up towards the coordinate limit
  int invalid_inputs = 0;    // generated polygons geom::validate_polygon rejected (dropped)
};

WavefrontCase make_wavefront_case(std::uint64_t seed);

// What the checks covered (so the tests can insist the generator exercises what it should).
struct WavefrontTally {
  std::int64_t instances = 0;
  std::int64_t obstacle_vertices = 0;  // summed over instances
  std::int64_t max_vertices = 0;       // largest instance
  std::int64_t free_checks = 0;        // is_free comparisons
  std::int64_t not_free = 0;           // ... of points that are not free
  std::int64_t runs = 0;
  std::int64_t multi_source_runs = 0;
  std::int64_t comparisons = 0;  // target distances compared
  std::int64_t reachable = 0;
  std::int64_t unreachable = 0;      // free target, no path
  std::int64_t paths = 0;            // target paths checked
  std::int64_t bends = 0;            // interior path points
  std::int64_t vertex_checks = 0;    // vertex_distance comparisons
  std::int64_t pinch_points = 0;     // free query points with >= 2 wedges
  std::int64_t boundary_points = 0;  // free query points on a wall (one partial wedge)
  std::int64_t source_is_target = 0;
  std::int64_t split_runs = 0;           // runs from a free source with a free unreachable target
  std::int64_t domain_corner_bends = 0;  // path points at a domain corner (allowed, counted)
  std::int64_t pinch_sources = 0;        // sources at a pinch (>= 2 wedges)
  std::int64_t boundary_sources = 0;     // sources on a wall
  std::int64_t transformed = 0;          // instances turned or mirrored
  std::int64_t huge = 0;                 // instances with coordinates near the limit
  std::int64_t invalid_inputs = 0;       // generator slips (should stay 0)
  std::int64_t generator_errors = 0;     // seeds whose layout could not be made (normalize threw)
  std::int64_t stats_issue_seeds = 0;    // seeds where WavefrontStats were implausible
  std::string first_stats_issue;         // the report of the first one
  double reference_seconds = 0, wavefront_seconds = 0;  // in distance queries and runs
  std::map<std::string, std::int64_t> families;         // instances per family
  void add(const WavefrontTally& o);
  std::string summary() const;
};

// Runs every check on the instance of `seed`; returns "" when everything agrees, else a report
// (seed, instance, query, both answers, and with shrink_failures a shrunk instance that still
// fails). Implausible stats do not count here: they go to tally.stats_issue_seeds and
// tally.first_stats_issue. verbose: print the instance and every answer to stdout.
std::string check_wavefront_seed(std::uint64_t seed, WavefrontTally& tally, bool verbose = false,
                                 bool shrink_failures = true, WaveMetric metric = WaveMetric::L1);

struct WavefrontSweep {
  WavefrontTally tally;
  std::vector<std::uint64_t> failed_seeds;
  std::vector<std::string> reports;  // of the first max_reports failing seeds
  double seconds = 0;
};

// Reports every failure of a sweep as a gtest failure: the per-seed reports, the failing seed
// list, invalid generated inputs and implausible stats.
void expect_clean_sweep(const WavefrontSweep& sw);

// Seeds first, first + 1, ..., first + count - 1.
WavefrontSweep run_wavefront_sweep(std::uint64_t first, std::int64_t count,
                                   std::size_t max_reports = 3, WaveMetric metric = WaveMetric::L1);
// Any list of seeds (the regression table).
WavefrontSweep run_wavefront_seeds(const std::vector<std::uint64_t>& seeds,
                                   std::size_t max_reports = 3, WaveMetric metric = WaveMetric::L1);

// TAUT_WAVEFRONT_SEED (L1) or TAUT_OCT_SEED (Octilinear), when set to a number.
std::optional<std::uint64_t> wavefront_seed_from_env(WaveMetric metric = WaveMetric::L1);

// The body of the random tests of wavefront_test.cpp and oct_wavefront_test.cpp: with the
// metric's seed variable set (wavefront_seed_from_env), that one seed verbosely; otherwise seeds
// 1..2000 (the same instances and queries for both metrics), every failure reported, and the
// generator's coverage (families, multi-source runs, unreachable targets, pinches, walls, ...)
// required to reach fixed floors.
void run_random_wavefront_test(WaveMetric metric);

}  // namespace taut::test
