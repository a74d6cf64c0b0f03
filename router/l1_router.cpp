#include "router/l1_router.h"

namespace taut::router {

L1Router::L1Router(const geom::Box& domain, std::span<const geom::Polygon> obstacles)
    : wavefront_(domain, obstacles), staircase_(domain, obstacles) {}

L1Wire L1Router::shortest(geom::Point from, geom::Point to) {
  L1Wire w;
  if (!wavefront_.is_free(from)) {
    w.status = WireStatus::SourceNotFree;
    return w;
  }
  if (!wavefront_.is_free(to)) {
    w.status = WireStatus::TargetNotFree;
    return w;
  }
  wavefront_.run({&from, 1}, {&to, 1}, /*stop_early=*/true);
  w.length = wavefront_.target_distance(0);
  if (!w.length) {
    w.status = WireStatus::Unreachable;
    return w;
  }
  w.polygonal = wavefront_.target_path(0);
  auto stairs = staircase_.rectilinear(w.polygonal, &staircase_stats_);
  if (!stairs) {
    w.status = WireStatus::NoIntegerStaircase;
    return w;
  }
  w.points = std::move(*stairs);
  w.status = WireStatus::Ok;
  return w;
}

const char* to_string(WireStatus status) {
  switch (status) {
    case WireStatus::Ok: return "ok";
    case WireStatus::SourceNotFree: return "source not free";
    case WireStatus::TargetNotFree: return "target not free";
    case WireStatus::Unreachable: return "unreachable";
    case WireStatus::NoIntegerStaircase: return "no integer staircase";
  }
  return "?";
}

}  // namespace taut::router
