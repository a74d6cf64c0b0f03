// Shortest OCTILINEAR wires between two points among obstacles: the octilinear wavefront
// (router/wavefront.h, OctWavefront) finds the exact length a + b*sqrt2 and a polygonal shortest
// path, the staircase builder (router/staircase.h, octilinear()) turns each link into a staircase
// of the two orientations that bracket it (0, 45, 90, 135 degrees), with integer vertices, of
// the same octilinear length. The octilinear counterpart of L1Router (router/l1_router.h), with
// the same statuses; point pins only (shape pins: L1Router).
//
//   OctRouter router(normalized.domain, normalized.obstacles);
//   OctWire w = router.shortest({500, 500}, {8000, 9000});
//   if (w.status == WireStatus::Ok) { use(w.points, *w.length); }   // *w.length: geom::Root2
//
// Why the wire is shortest among octilinear wires (Mitchell, Theorem 3): OctWavefront's length
// is the least d8 length over all paths in free space, d8 being the octilinear length of a
// vector; a wire in the four orientations has d8 length equal to its Euclidean length and can
// be no shorter; the staircase has exactly the polygonal path's d8 length.
//
// NoIntegerStaircase: the exact length is known (`length`, `polygonal`) but no octilinear wire
// with integer vertices through the polygonal path's bends has that length, e.g. when a sloped
// blockage edge pinches every lattice staircase (staircase.h, Limitation). The caller reports
// it; a longer wire is never returned silently.
#pragma once

#include <optional>
#include <vector>

#include "geom/root2.h"
#include "geom/types.h"
#include "router/l1_router.h"
#include "router/staircase.h"
#include "router/wavefront.h"

namespace taut::router {

struct OctWire {
  WireStatus status = WireStatus::Unreachable;
  std::optional<geom::Root2> length;   // exact octilinear distance (Ok, NoIntegerStaircase)
  std::vector<geom::Point> polygonal;  // the wavefront's shortest path (Ok, NoIntegerStaircase)
  std::vector<geom::Point> points;     // the octilinear wire: bends only, integer (Ok)
};

class OctRouter {
 public:
  // Obstacles as geom::normalize_obstacles() returns them.
  OctRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles);

  // The shortest octilinear wire from `from` to `to` (points {from} when they are equal).
  OctWire shortest(geom::Point from, geom::Point to);

  bool is_free(geom::Point p) const { return wavefront_.is_free(p); }
  const OctWavefront& wavefront() const { return wavefront_; }
  const StaircaseStats& staircase_stats() const { return staircase_stats_; }

 private:
  OctWavefront wavefront_;
  StaircaseBuilder staircase_;
  StaircaseStats staircase_stats_;
};

}  // namespace taut::router
