#include "oracle/oct_oracle.h"

#include <cstdlib>

namespace taut::oracle {

bool is_octilinear(geom::Point a, geom::Point b) {
  const std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
  return dx == 0 || dy == 0 || std::abs(dx) == std::abs(dy);
}

std::optional<geom::Root2> OctilinearReference::check_octilinear_path(
    std::span<const geom::Point> path) const {
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!is_octilinear(path[i], path[i + 1])) return std::nullopt;
  return check_path(path);
}

}  // namespace taut::oracle
