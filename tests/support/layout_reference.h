// A brute-force reference (oracle::L1Reference or OctilinearReference) on a layout file's
// obstacles, normalized in the routing domain the commands use (io::routing_domain with the
// extra query points), so command-line tests can judge what `taut path/route/spm` printed.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "io/layout_geometry.h"
#include "io/layout_reader.h"

namespace taut::test {

template <class Ref>
struct LayoutReference {
  geom::NormalizedObstacles norm;
  std::unique_ptr<Ref> ref;  // null when the file does not read (a test failure is recorded)
};

// The file's obstacles normalized in the routing domain, without a reference (building one costs
// a visibility graph: most of a test's time under the sanitizers when only the obstacles are used).
// nullopt when the file does not read (a test failure is recorded).
inline std::optional<geom::NormalizedObstacles> read_normalized(const std::string& file,
                                                               const std::vector<geom::Point>& extra) {
  io::ReadResult rr = io::read_layout(file);
  EXPECT_TRUE(rr.layout.has_value()) << file;
  if (!rr.layout) return std::nullopt;
  return geom::normalize_obstacles(io::blockage_polygons(*rr.layout), io::routing_domain(*rr.layout, extra));
}
inline geom::NormalizedObstacles normalized_for(const std::string& file, const std::vector<geom::Point>& extra = {}) {
  return read_normalized(file, extra).value_or(geom::NormalizedObstacles{});
}

template <class Ref>
LayoutReference<Ref> reference_for(const std::string& file, const std::vector<geom::Point>& extra = {}) {
  LayoutReference<Ref> r;
  std::optional<geom::NormalizedObstacles> norm = read_normalized(file, extra);
  if (!norm) return r;
  r.norm = std::move(*norm);
  r.ref = std::make_unique<Ref>(r.norm.domain, r.norm.obstacles);
  return r;
}

}  // namespace taut::test
