// L1Wavefront with segment sources (router/wavefront.h: wires and pin edges as sources along
// their whole length) against the brute-force reference (tests/oracle/l1_oracle.h): the distance
// from a segment is the least reference distance over every integer point of it (the least is at
// an integer point: an end or a projection of an integer point, wavefront.h), and, on instances
// scaled by 2 (so the half-integer points of the original are lattice points too), over every
// one of those as well: a better point off the lattice would show there.
//
// Instances: support/wavefront_cases.h (every `taut gen` kind and the hand-made degenerate
// families); per instance 1-3 segments walked from free candidate points in one of the eight
// directions, one unit step at a time while the step is free (so they run along blockage edges,
// end on them and touch pinches' neighbourhoods), 0-2 point sources, and 40 queries. Checks:
// the distance (exactly; null exactly when no source reaches the query), the named source is
// at that distance (the point sources first, then the segments), the path runs from a point of
// that source to the query, is free and has exactly that length.
// TAUT_SEGMENT_SOURCE_SEED=N runs only seed N.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <sstream>
#include <type_traits>

#include "geom/index.h"
#include "oracle/l1_oracle.h"
#include "oracle/oct_oracle.h"
#include "router/wavefront.h"
#include "support/sanitized.h"
#include "support/spm_check.h"
#include "support/wavefront_cases.h"

namespace taut::test {
namespace segment_source_test {

using geom::Point;
using i64 = std::int64_t;

bool on_segment(Point p, const geom::Segment& s) {
  const i64 cross = (i64{s.b.x} - s.a.x) * (i64{p.y} - s.a.y) - (i64{s.b.y} - s.a.y) * (i64{p.x} - s.a.x);
  return cross == 0 && std::min(s.a.x, s.b.x) <= p.x && p.x <= std::max(s.a.x, s.b.x) &&
         std::min(s.a.y, s.b.y) <= p.y && p.y <= std::max(s.a.y, s.b.y);
}

// Every integer point of a segment (horizontal, vertical or diagonal).
std::vector<Point> lattice_points(const geom::Segment& s) {
  const int dx = (s.b.x > s.a.x) - (s.b.x < s.a.x), dy = (s.b.y > s.a.y) - (s.b.y < s.a.y);
  std::vector<Point> out{s.a};
  while (out.back() != s.b) out.push_back({out.back().x + dx, out.back().y + dy});
  return out;
}

struct Tally {
  i64 instances = 0, skipped = 0, queries = 0, reached = 0, from_segment = 0, inside_segment = 0, scaled = 0;
};

// Ref, Wavefront: L1Reference and L1Wavefront, or OctilinearReference and OctWavefront. The
// octilinear segment's sources are its lattice points only (wavefront.h), so the scaled check
// (half-integer points) is for L1.
template <class Ref, class Wavefront>
std::string check_seed(std::uint64_t seed, Tally& tally) {
  constexpr bool kL1 = std::is_same_v<Wavefront, router::L1Wavefront>;
  WavefrontCase c;
  try {
    c = make_wavefront_case(seed);
  } catch (const std::exception&) {
    ++tally.skipped;
    return "";
  }
  const Ref ref(c.domain, c.obstacles);
  if (!ref.problems().empty()) {
    ++tally.skipped;
    return "";
  }
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 41);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  std::vector<Point> free_pts;
  for (Point p : c.candidates)
    if (ref.is_free(p)) free_pts.push_back(p);
  if (free_pts.empty()) {
    ++tally.skipped;
    return "";
  }
  // Segments: from a free point, unit steps in one direction while each step is free.
  std::vector<geom::Segment> segs;
  const std::size_t nseg = 1 + pick(3);
  for (std::size_t k = 0; k < nseg; ++k) {
    const Point a = free_pts[pick(free_pts.size())];
    const Point d = geom::step(geom::kAllDirections[pick(8)]);
    const std::size_t len = 1 + pick(kSanitized ? 8 : 16);
    Point b = a;
    for (std::size_t i = 0; i < len; ++i) {
      const Point n{b.x + d.x, b.y + d.y};
      const std::vector<Point> step{b, n};
      if (!ref.check_path(step)) break;
      b = n;
    }
    segs.push_back({a, b});  // may be a single point
  }
  std::vector<Point> points;
  for (std::size_t k = pick(3); k > 0; --k) points.push_back(free_pts[pick(free_pts.size())]);
  std::vector<Point> queries;
  const geom::Box& D = c.domain;
  while (queries.size() < 40) {
    if (queries.size() < 25) {
      queries.push_back(c.candidates[pick(c.candidates.size())]);
      continue;
    }
    const i64 x = D.lo.x + static_cast<i64>(rng() % static_cast<std::uint64_t>(i64{D.hi.x} - D.lo.x + 1));
    const i64 y = D.lo.y + static_cast<i64>(rng() % static_cast<std::uint64_t>(i64{D.hi.y} - D.lo.y + 1));
    queries.push_back({static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)});
  }
  // The reference: every lattice point of each source.
  using Len = typename decltype(ref.distances(Point{}, std::vector<Point>{}))::value_type::value_type;
  auto text = [](const std::optional<Len>& d) {
    if (!d) return std::string("none");
    std::ostringstream o;
    o << *d;
    return o.str();
  };
  std::vector<std::vector<std::optional<Len>>> per_source;  // [source][query]
  for (const Point p : points) per_source.push_back(least_distances(ref, {p}, queries));
  for (const auto& s : segs) per_source.push_back(least_distances(ref, lattice_points(s), queries));

  std::string head = "seed " + std::to_string(seed) + " (family " + c.family + ")\n  segments";
  for (const auto& s : segs) head += " " + spm_pt(s.a) + "-" + spm_pt(s.b);
  head += "\n  point sources";
  for (const Point p : points) head += " " + spm_pt(p);
  head += "\n";

  Wavefront wf(c.domain, c.obstacles);
  wf.run(points, segs, queries, router::WavefrontStop::AllTargets);
  ++tally.instances;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Point q = queries[i];
    const std::string where = head + "  query " + spm_pt(q) + ": ";
    ++tally.queries;
    std::optional<Len> best;
    for (const auto& d : per_source)
      if (d[i] && (!best || *d[i] < *best)) best = d[i];
    const auto got = wf.target_distance(i);
    if (got != best)
      return where + "distance " + text(got) + ", reference " + text(best) + "\n";
    if (!best) continue;
    ++tally.reached;
    const auto src = wf.target_source(i);
    if (!src || *src >= per_source.size() || per_source[*src][i] != best)
      return where + "the named source is not at the least distance\n";
    const auto path = wf.target_path(i);
    if (path.empty() || path.back() != q) return where + "the path does not end at the query\n";
    if (*src < points.size()) {
      if (path.front() != points[*src]) return where + "the path does not start at its point source\n";
    } else {
      const geom::Segment& s = segs[*src - points.size()];
      if (!on_segment(path.front(), s)) return where + "the path starts at " + spm_pt(path.front()) + ", off its segment\n";
      ++tally.from_segment;
      tally.inside_segment += path.front() != s.a && path.front() != s.b;
    }
    const auto len = ref.check_path(path);
    if (!len || *len != *best) return where + "the path is " + (len ? "of length " + text(*len) : std::string("not free")) + "\n";
  }
  // Scaled by 2: the half-integer points of the segments become lattice points; none may be
  // nearer (every distance doubles).
  if (kL1 && !c.huge && pick(4) == 0) {
    auto twice = [](Point p) { return Point{2 * p.x, 2 * p.y}; };
    std::vector<geom::Polygon> obs2;
    for (const auto& p : c.obstacles) {
      geom::Polygon q;
      for (const Point v : p.outer) q.outer.push_back(twice(v));
      for (const auto& h : p.holes) {
        q.holes.emplace_back();
        for (const Point v : h) q.holes.back().push_back(twice(v));
      }
      obs2.push_back(std::move(q));
    }
    const Ref ref2({twice(D.lo), twice(D.hi)}, obs2);
    std::vector<Point> q2;
    for (const Point q : queries) q2.push_back(twice(q));
    for (std::size_t k = 0; k < segs.size(); ++k) {
      const auto d2 = least_distances(ref2, lattice_points({twice(segs[k].a), twice(segs[k].b)}), q2);
      for (std::size_t i = 0; i < queries.size(); ++i) {
        const auto& d1 = per_source[points.size() + k][i];
        if (d2[i].has_value() != d1.has_value() || (d1 && *d2[i] != *d1 + *d1))
          return head + "  query " + spm_pt(queries[i]) + ": scaled by 2, segment " + std::to_string(k) +
                 " is " + text(d2[i]) + " away, not twice " + text(d1) + "\n";
      }
    }
    ++tally.scaled;
  }
  return "";
}

TEST(SegmentSources, MatchTheReferenceOnRandomLayouts) {
  Tally t;
  if (!run_seed_range("TAUT_SEGMENT_SOURCE_SEED", 1000,
                      [&](std::uint64_t seed) { return check_seed<oracle::L1Reference, router::L1Wavefront>(seed, t); }))
    return;
  std::cout << "instances " << t.instances << " (skipped " << t.skipped << ", scaled " << t.scaled << "), queries "
            << t.queries << ": reached " << t.reached << ", from a segment " << t.from_segment
            << " (leaving it between its ends " << t.inside_segment << ")\n";
  EXPECT_GE(t.instances, sanitized_share(950, 4));
  EXPECT_GE(t.reached, sanitized_share(25000, 4));
  EXPECT_GE(t.inside_segment, kSanitized ? 50 : 1000);  // (segments are half as long there)
  EXPECT_GE(t.scaled, sanitized_share(150, 4));
}

// OctWavefront with segment sources: the distance from a segment is the least octilinear
// reference distance over its lattice points (the sources of wavefront.h's octilinear run),
// with the same instances and checks (not scaled: a half-integer point of a diagonal segment
// may be nearer, and no wire can leave from there).
TEST(SegmentSources, OctilinearMatchTheReferenceOnRandomLayouts) {
  Tally t;
  if (!run_seed_range("TAUT_OCT_SEGMENT_SOURCE_SEED", 1000,
                      [&](std::uint64_t seed) { return check_seed<oracle::OctilinearReference, router::OctWavefront>(seed, t); }))
    return;
  std::cout << "instances " << t.instances << " (skipped " << t.skipped << "), queries " << t.queries << ": reached "
            << t.reached << ", from a segment " << t.from_segment << " (leaving it between its ends "
            << t.inside_segment << ")\n";
  EXPECT_GE(t.instances, sanitized_share(950, 4));
  EXPECT_GE(t.reached, sanitized_share(25000, 4));
  EXPECT_GE(t.inside_segment, kSanitized ? 50 : 1000);
}

// Worked by hand (octilinear): a diagonal wire from (0, 0) to (10, 10), no blockages. To (6, 0):
// from (3, 3), where the other diagonal through (6, 0) meets the wire: 3 sqrt2. To (7, 0): that
// diagonal meets the wire at (3.5, 3.5), no lattice point; from (3, 3) or (4, 4) it is
// d8(4, -3) = d8(3, -4) = 1 + 3 sqrt2, less than 7 from the end (0, 0) (and more than the
// 3.5 sqrt2 from (3.5, 3.5), where no wire can start). To (5, 5) on the wire: 0. To (15, 10):
// from the end (10, 10), 5.
TEST(SegmentSources, OctilinearDiagonalWire) {
  const geom::Box dom{{-5, -5}, {20, 20}};
  router::OctWavefront wf(dom, {});
  const std::vector<geom::Segment> wire = {{{10, 10}, {0, 0}}};
  const std::vector<Point> q = {{6, 0}, {7, 0}, {5, 5}, {15, 10}};
  wf.run({}, wire, q, router::WavefrontStop::AllTargets);
  EXPECT_EQ(wf.target_distance(0), (geom::Root2{0, 3}));
  EXPECT_EQ(wf.target_distance(1), (geom::Root2{1, 3}));
  EXPECT_EQ(wf.target_distance(2), (geom::Root2{0, 0}));
  EXPECT_EQ(wf.target_distance(3), (geom::Root2{5, 0}));
  EXPECT_EQ(wf.target_source(1), 0u);
  const auto path = wf.target_path(1);
  ASSERT_FALSE(path.empty());
  EXPECT_TRUE(path.front() == Point(3, 3) || path.front() == Point(4, 4)) << spm_pt(path.front());
  const std::vector<geom::Segment> sloped = {{{0, 0}, {2, 1}}};
  EXPECT_THROW(wf.run({}, sloped, q, router::WavefrontStop::AllTargets), std::invalid_argument);
}

// Worked by hand: a horizontal wire below a bar. Wire y = 0, x in [0, 100]; bar x in [20, 80],
// y in [10, 20]. To (50, 30): up beside the bar from (20, 0) (or (80, 0)): 30 across + 30 up = 60.
// To (50, 5), under the bar: straight up from (50, 0): 5. To (120, 0): from the end: 20.
TEST(SegmentSources, WireBelowABar) {
  const geom::Box dom{{-10, -10}, {130, 40}};
  const std::vector<geom::Polygon> obs = {{{{20, 10}, {80, 10}, {80, 20}, {20, 20}}, {}}};
  router::L1Wavefront wf(dom, obs);
  const std::vector<geom::Segment> wire = {{{100, 0}, {0, 0}}};
  const std::vector<Point> q = {{50, 30}, {50, 5}, {120, 0}, {50, 0}};
  wf.run({}, wire, q, router::WavefrontStop::AllTargets);
  EXPECT_EQ(wf.target_distance(0), 60);
  EXPECT_EQ(wf.target_distance(1), 5);
  EXPECT_EQ(wf.target_distance(2), 20);
  EXPECT_EQ(wf.target_distance(3), 0);
  EXPECT_EQ(wf.target_source(1), 0u);
  EXPECT_EQ(wf.target_path(1), (std::vector<Point>{{50, 0}, {50, 5}}));
  // A sloped segment is refused.
  const std::vector<geom::Segment> sloped = {{{0, 0}, {2, 1}}};
  EXPECT_THROW(wf.run({}, sloped, q, router::WavefrontStop::AllTargets), std::invalid_argument);
}

}  // namespace segment_source_test
}  // namespace taut::test
