// The octilinear distance as an approximation of the Euclidean geodesic distance (Mitchell's
// fixed-orientation metrics with k = 4 evenly spaced orientations, 0/45/90/135 degrees):
//   d_E <= d_8 <= sec(pi/8) d_E  (sec(pi/8) = 1.0823922...: epsilon = 8.24 %),
// which `taut spm --orientations octilinear` reports as "euclidean_bounds". d_8 comes from
// router::OctWavefront (exact in Z[sqrt2]); d_E from an independent Euclidean visibility graph
// (tests/oracle/euclid_oracle.h: obstacle vertices and the two ends, an edge wherever oracle::L1Reference says a
// segment is allowed, Dijkstra in long double). Instances with a pinch vertex (two wedges) are
// skipped: there a path may not turn through the pinch, which plain visibility does not see.
// The comparison of two irrational numbers is the only inexact step: each side gets a relative
// slack of 1e-12, far below the 8 % the bound allows and far above long double's rounding
// (squares of coordinate differences below 2^62 are exact in its 64-bit mantissa).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <queue>
#include <random>
#include <set>

#include "geom/fixed_norm.h"
#include "oracle/euclid_oracle.h"
#include "oracle/l1_oracle.h"
#include "router/wavefront.h"
#include "support/reach.h"
#include "support/wavefront_cases.h"

namespace taut::test {
namespace euclid_approx_test {

using geom::Point;

// Euclidean geodesic distance from s to t; nullopt when t is unreachable.
std::optional<long double> euclid_distance(const oracle::L1Reference& ref, const std::vector<Point>& vertices, Point s,
                                           Point t) {
  const auto p = oracle::euclid_shortest(ref, vertices, s, t);
  if (!p) return std::nullopt;
  return p->length;
}

// One seeded instance with its reference, obstacle vertices and free candidate points; pinch:
// some vertex has two wedges (such instances are skipped: plain visibility would squeeze through
// the pinch). nullopt when the seed makes no usable instance (or fewer than two free points).
struct Instance {
  WavefrontCase c;
  std::unique_ptr<oracle::L1Reference> ref;
  std::vector<Point> vertices, free_pts;
  bool pinch = false;
};
std::optional<Instance> instance(std::uint64_t seed) {
  Instance in;
  try {
    in.c = make_wavefront_case(seed);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  in.ref = std::make_unique<oracle::L1Reference>(in.c.domain, in.c.obstacles);
  if (!in.ref->problems().empty()) return std::nullopt;
  in.vertices = obstacle_vertices(in.c.obstacles);
  for (Point v : in.vertices) in.pinch = in.pinch || in.ref->wedges_at(v).size() > 1;
  for (Point p : in.c.candidates)
    if (in.ref->is_free(p)) in.free_pts.push_back(p);
  if (in.free_pts.size() < 2) return std::nullopt;
  return in;
}

TEST(EuclidApprox, OctilinearDistanceBoundsTheEuclideanOne) {
  const long double sec = 1.0L / std::cos(3.14159265358979323846264338327950288L / 8);
  const long double slack = 1e-12L;
  int instances = 0, pairs = 0, skipped_pinch = 0, loose = 0;
  long double worst = 1;
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    const auto inst = instance(seed);
    if (!inst) continue;
    if (inst->pinch) {
      ++skipped_pinch;
      continue;
    }
    const WavefrontCase& c = inst->c;
    const oracle::L1Reference& ref = *inst->ref;
    const std::vector<Point>& vertices = inst->vertices;
    const std::vector<Point>& free_pts = inst->free_pts;
    ++instances;
    std::mt19937_64 rng(seed);
    router::OctWavefront wf(c.domain, c.obstacles);
    for (int k = 0; k < 3; ++k) {
      const Point s = free_pts[rng() % free_pts.size()], t = free_pts[rng() % free_pts.size()];
      wf.run(std::vector<Point>{s}, std::vector<Point>{t}, router::WavefrontStop::AllTargets);
      const auto d8 = wf.target_distance(0);
      const auto de = euclid_distance(ref, vertices, s, t);
      ASSERT_EQ(d8.has_value(), de.has_value()) << "seed " << seed << ": reachability differs";
      if (!d8) continue;
      ++pairs;
      const long double v8 = static_cast<long double>(d8->a) + static_cast<long double>(d8->b) * std::sqrt(2.0L);
      EXPECT_LE(*de, v8 * (1 + slack)) << "seed " << seed << " (" << c.family << "): the octilinear path is shorter than the Euclidean one: " << s.x << "," << s.y << " -> " << t.x << "," << t.y << " d8 " << static_cast<double>(v8) << " dE " << static_cast<double>(*de);
      EXPECT_LE(v8, sec * *de * (1 + slack)) << "seed " << seed << ": beyond sec(pi/8)";
      if (*de > 0) {
        worst = std::max(worst, v8 / *de);
        loose += v8 > *de * 1.02L;
      }
    }
  }
  std::printf("instances %d (skipped with pinches %d), pairs %d, worst d8/dE %.6Lf (bound %.6Lf), %d pairs over 2 %%\n",
              instances, skipped_pinch, pairs, worst, sec, loose);
  EXPECT_GE(instances, 400);
  EXPECT_GE(pairs, 1000);
  EXPECT_GE(loose, 500);  // the bound is exercised, not only met by axis-parallel answers
}

// The Farey norms (geom/fixed_norm.h, router::NormWavefront, orders 2-4: 16, 32, 48
// directions): S d_E <= d_N <= Lambda d_E, i.e. d_E in [d_N / Lambda, d_N / S], which
// `taut spm --orientations any` reports. Same instances and reference as above; the worst ratio
// (d_N / S) / d_E per order is printed, and order 2's must use more than half its epsilon (the
// interval is exercised, not only met by straight answers).
TEST(EuclidApprox, NormDistancesBoundTheEuclideanOne) {
  const long double slack = 1e-12L;
  const long double S = static_cast<long double>(geom::kNormScale);
  int instances = 0, pairs = 0;
  long double worst[5] = {1, 1, 1, 1, 1};
  for (std::uint64_t seed = 1; seed <= 600; ++seed) {
    const auto inst = instance(seed);
    if (!inst || inst->pinch) continue;
    const WavefrontCase& c = inst->c;
    const oracle::L1Reference& ref = *inst->ref;
    const std::vector<Point>& vertices = inst->vertices;
    const std::vector<Point>& free_pts = inst->free_pts;
    ++instances;
    std::mt19937_64 rng(seed);
    const Point s = free_pts[rng() % free_pts.size()], t = free_pts[rng() % free_pts.size()];
    const auto de = euclid_distance(ref, vertices, s, t);
    for (int order = 2; order <= 4; ++order) {
      router::NormWavefront wf(c.domain, c.obstacles, order);
      wf.run(std::vector<Point>{s}, std::vector<Point>{t}, router::WavefrontStop::AllTargets);
      const auto dn = wf.target_distance(0);
      ASSERT_EQ(dn.has_value(), de.has_value()) << "seed " << seed << " order " << order;
      if (!dn) continue;
      if (order == 2) ++pairs;
      const long double lambda = std::sqrt(static_cast<long double>(geom::fixed_norm_lambda_max_sq(order)));
      const long double v = static_cast<long double>(*dn);
      EXPECT_LE(*de, v / S * (1 + slack)) << "seed " << seed << " order " << order << ": below d_N / S";
      EXPECT_LE(v / lambda, *de * (1 + slack)) << "seed " << seed << " order " << order << ": above d_N / Lambda";
      if (*de > 0) worst[order] = std::max(worst[order], v / S / *de);
    }
  }
  std::printf("instances %d, pairs %d; worst (d_N / S) / d_E: order 2 %.6Lf (1 + eps = %.6Lf), order 3 %.6Lf "
              "(%.6Lf), order 4 %.6Lf (%.6Lf)\n",
              instances, pairs, worst[2], 1 + geom::fixed_norm_epsilon(2), worst[3],
              1 + geom::fixed_norm_epsilon(3), worst[4], 1 + geom::fixed_norm_epsilon(4));
  EXPECT_GE(instances, 200);
  EXPECT_GE(pairs, 150);
  // the approximation is exercised: some pair is off by more than half of order 2's epsilon
  EXPECT_GT(worst[2], 1 + geom::fixed_norm_epsilon(2) / 2);
}

}  // namespace euclid_approx_test
}  // namespace taut::test
