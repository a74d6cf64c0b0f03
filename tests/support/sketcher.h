// Random sketches for tests of tightening and of minimum-link paths: walks through given free
// points (consecutive ones visible to each other), and loops of their own that wind one to three
// times around obstacles.
#pragma once

#include <random>
#include <vector>

#include "geom/types.h"
#include "oracle/homotopy.h"
#include "oracle/l1_oracle.h"

namespace taut::test {

struct Sketcher {
  const oracle::L1Reference& ref;
  const oracle::HomotopyWords& h;
  const std::vector<geom::Point>& pts;
  std::mt19937_64& rng;
  geom::Point pick() { return pts[rng() % pts.size()]; }
  std::vector<geom::Point> walk(int max_points) {
    std::vector<geom::Point> path{pick()};
    for (int tries = 0; tries < 200 && static_cast<int>(path.size()) < max_points; ++tries) {
      const geom::Point q = pick();
      if (q != path.back() && ref.visible(path.back(), q)) path.push_back(q);
    }
    return path;
  }
  bool add_loops(std::vector<geom::Point>& path) {
    const geom::Point s = path.back();
    for (int tries = 0; tries < 400; ++tries) {
      std::vector<geom::Point> loop{s};
      const int stops = 2 + static_cast<int>(rng() % 3);
      for (int t1 = 0; t1 < 40 && static_cast<int>(loop.size()) <= stops; ++t1) {
        const geom::Point p = pick();
        if (p != loop.back() && ref.visible(loop.back(), p)) loop.push_back(p);
      }
      if (loop.size() < 3 || !ref.visible(loop.back(), s)) continue;
      loop.push_back(s);
      if (h.word(loop).empty()) continue;
      const int turns = 1 + static_cast<int>(rng() % 3);
      for (int k = 0; k < turns; ++k) path.insert(path.end(), loop.begin() + 1, loop.end());
      // and on to a last point
      for (int t2 = 0; t2 < 50; ++t2) {
        const geom::Point q = pick();
        if (q != s && ref.visible(s, q)) {
          path.push_back(q);
          break;
        }
      }
      return true;
    }
    return false;
  }
};

}  // namespace taut::test
