// The Euclidean geodesic distance among obstacles by brute force: a visibility graph on the two
// ends and every free obstacle vertex, an edge wherever oracle::L1Reference says a segment is
// allowed (VisibilityGraph::visible: in the closed free space), and a dense Dijkstra in long
// double. O(n^2) visibility tests of O(n) each: for small instances only. A pinch vertex (two
// wedges) is not modelled: a path may not turn through the pinch there, which plain visibility
// does not see, so callers skip instances with pinches.
#pragma once

#include <optional>
#include <vector>

#include "geom/types.h"
#include "oracle/l1_oracle.h"

namespace taut::oracle {

struct EuclidPath {
  long double length = 0;
  std::vector<geom::Point> points;  // from s to t
};

// Shortest Euclidean path from s to t through free obstacle vertices (`vertices`, repeats
// allowed); nullopt when t is unreachable.
std::optional<EuclidPath> euclid_shortest(const L1Reference& ref, const std::vector<geom::Point>& vertices,
                                          geom::Point s, geom::Point t);

long double euclid(geom::Point a, geom::Point b);

}  // namespace taut::oracle
