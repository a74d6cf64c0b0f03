// Shortest rectilinear wires between two points among obstacles, exact in L1: the wavefront
// (router/wavefront.h) finds the length and a polygonal shortest path, the staircase builder
// (router/staircase.h) turns it into a rectilinear wire of the same length with integer
// vertices. One object serves many queries (`taut route` routes every two-pin net with one).
//
//   L1Router router(normalized.domain, normalized.obstacles);
//   L1Wire w = router.shortest({500, 500}, {8000, 9000});
//   if (w.status == WireStatus::Ok) { use(w.points, *w.length); }
//
// When no wire is returned the status says why, so callers can tell the user:
//   - SourceNotFree / TargetNotFree: the point is outside the domain, inside an obstacle, or
//     on an obstacle edge that lies flush on the domain side;
//   - Unreachable: both are free but in different parts of free space (`length` empty);
//   - NoIntegerStaircase: the exact L1 distance is known (`length`, `polygonal`), but no
//     rectilinear path with integer vertices of that length exists through the polygonal
//     path's bends, e.g. when sloped blockages pinch every lattice staircase (staircase.h,
//     Limitation). Returning a longer wire would break "provably shortest" silently, so the
//     caller reports it instead (a wire of another route of equal length is not searched).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geom/types.h"
#include "router/staircase.h"
#include "router/wavefront.h"

namespace taut::router {

enum class WireStatus { Ok, SourceNotFree, TargetNotFree, Unreachable, NoIntegerStaircase };

struct L1Wire {
  WireStatus status = WireStatus::Unreachable;
  std::optional<std::int64_t> length;  // exact L1 distance (Ok, NoIntegerStaircase)
  std::vector<geom::Point> polygonal;  // the wavefront's shortest path (Ok, NoIntegerStaircase)
  std::vector<geom::Point> points;     // the rectilinear wire: bends only, integer (Ok)
};

class L1Router {
 public:
  // Obstacles as geom::normalize_obstacles() returns them.
  L1Router(const geom::Box& domain, std::span<const geom::Polygon> obstacles);

  // The shortest rectilinear wire from `from` to `to` (points {from} when they are equal).
  L1Wire shortest(geom::Point from, geom::Point to);

  bool is_free(geom::Point p) const { return wavefront_.is_free(p); }
  const L1Wavefront& wavefront() const { return wavefront_; }
  const StaircaseStats& staircase_stats() const { return staircase_stats_; }

 private:
  L1Wavefront wavefront_;
  StaircaseBuilder staircase_;
  StaircaseStats staircase_stats_;
};

const char* to_string(WireStatus status);

}  // namespace taut::router
