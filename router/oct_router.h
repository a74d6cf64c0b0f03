// Shortest OCTILINEAR wires among obstacles: OctRouter is the router of router/l1_router.h
// (BasicRouter) run with the octilinear wavefront (router/wavefront.h, OctWavefront), which finds
// the exact length a + b*sqrt2 and a polygonal shortest path; the staircase builder
// (router/staircase.h, octilinear()) turns each link into a staircase of the two orientations
// that bracket it (0, 45, 90, 135 degrees), with integer vertices, of the same octilinear length.
// Same statuses, same shape-pin rules (pin_shape_supported(): edges at 0, 45 and 90 degrees; the
// candidate points of a 45-degree edge add projections along the other diagonal: pin_shapes.h).
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

#include "geom/root2.h"
#include "router/l1_router.h"

namespace taut::router {

using OctRouter = BasicRouter<OctWavefront>;
using OctWire = BasicWire<geom::Root2>;

}  // namespace taut::router
