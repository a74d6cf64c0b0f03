#include "router/oct_router.h"

namespace taut::router {

OctRouter::OctRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles)
    : wavefront_(domain, obstacles), staircase_(domain, obstacles) {}

OctWire OctRouter::shortest(geom::Point from, geom::Point to) {
  OctWire w;
  if (!wavefront_.is_free(from)) {
    w.status = WireStatus::SourceNotFree;
    return w;
  }
  if (!wavefront_.is_free(to)) {
    w.status = WireStatus::TargetNotFree;
    return w;
  }
  wavefront_.run({&from, 1}, {&to, 1}, WavefrontStop::AllTargets);
  w.length = wavefront_.target_distance(0);
  if (!w.length) {
    w.status = WireStatus::Unreachable;
    return w;
  }
  w.polygonal = wavefront_.target_path(0);
  auto stairs = staircase_.octilinear(w.polygonal, &staircase_stats_);
  if (!stairs) {
    w.status = WireStatus::NoIntegerStaircase;
    return w;
  }
  w.points = std::move(*stairs);
  w.status = WireStatus::Ok;
  return w;
}

}  // namespace taut::router
