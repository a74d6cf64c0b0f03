// Helpers for the hand-worked wavefront cases of tests/router/wavefront_test.cpp (L1) and
// oct_wavefront_test.cpp (octilinear): a normalized scene, rectangles, and expect_run(), which
// runs a wavefront and checks every target against the hand-worked answer and the brute-force
// reference (which must agree with the answer too), with paths checked as in the random test:
// from the reported source to the target, distinct consecutive points, and a length by the
// reference's check_path() equal to the distance.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "router/wavefront.h"

namespace taut::test {

struct Scene {
  geom::Box domain;
  std::vector<geom::Polygon> obstacles;
};

inline geom::Ring rect_ring(int x0, int y0, int x1, int y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
inline geom::Polygon rect(int x0, int y0, int x1, int y1) { return {rect_ring(x0, y0, x1, y1), {}}; }

inline Scene normalized(const geom::Box& domain, const std::vector<geom::Polygon>& inputs) {
  const auto n = geom::normalize_obstacles(inputs, domain);
  return {n.domain, n.obstacles};
}

inline std::string str(const std::vector<geom::Point>& path) {
  std::string s;
  for (const geom::Point p : path) s += "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
  return s;
}

// Wavefront: router::L1Wavefront or OctWavefront; Reference: oracle::L1Reference or
// OctilinearReference; Dist: the distance type both return.
template <class Reference, class Wavefront, class Dist>
void expect_run(const Scene& sc, Wavefront& wf, const std::vector<geom::Point>& sources,
                const std::vector<geom::Point>& targets, const std::vector<Dist>& want,
                router::WavefrontStop stop = router::WavefrontStop::AllTargets) {
  ASSERT_EQ(targets.size(), want.size());
  SCOPED_TRACE("sources " + str(sources) + " targets " + str(targets));
  const Reference ref(sc.domain, sc.obstacles);
  wf.run(sources, targets, stop);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const geom::Point t = targets[i];
    SCOPED_TRACE("target (" + std::to_string(t.x) + "," + std::to_string(t.y) + ")");
    Dist best;
    for (const geom::Point s : sources) {
      const Dist d = ref.distance(s, t);
      if (d && (!best || *d < *best)) best = d;
    }
    EXPECT_EQ(best, want[i]) << "the reference disagrees with the hand-worked answer";
    EXPECT_EQ(wf.target_distance(i), want[i]);
    const std::vector<geom::Point> path = wf.target_path(i);
    const auto src = wf.target_source(i);
    if (!want[i]) {
      EXPECT_TRUE(path.empty()) << str(path);
      EXPECT_FALSE(src.has_value());
      continue;
    }
    ASSERT_TRUE(src.has_value());
    ASSERT_LT(*src, sources.size());
    EXPECT_EQ(ref.distance(sources[*src], t), want[i]) << "source " << *src;
    ASSERT_FALSE(path.empty());
    EXPECT_EQ(path.front(), sources[*src]) << str(path);
    EXPECT_EQ(path.back(), t) << str(path);
    for (std::size_t k = 0; k + 1 < path.size(); ++k) EXPECT_NE(path[k], path[k + 1]) << str(path);
    EXPECT_EQ(ref.check_path(path), want[i]) << str(path);
  }
  const auto& st = wf.stats();
  EXPECT_LE(st.labelled, st.entities)
      << "vertices " << st.vertices << " events " << st.events << " wavelets " << st.wavelets;
  if (stop == router::WavefrontStop::Never && !sc.obstacles.empty() && !sources.empty() &&
      ref.is_free(sources[0])) {
    EXPECT_GT(st.events, 0);
    EXPECT_GT(st.labelled, 0);
  }
}

}  // namespace taut::test
