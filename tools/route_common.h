// What `taut path` and `taut route` share: the obstacles of a layout for the router, and the
// words a person reads when a wire cannot be made.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "geom/root2.h"
#include "io/layout.h"
#include "router/l1_router.h"

namespace taut::cli {

// Normalized obstacles of the layout's blockages inside io::routing_domain(layout, extra).
geom::NormalizedObstacles routing_obstacles(const io::Layout& layout,
                                            std::span<const geom::Point> extra = {});

// Why point p (an end of a wanted wire) is not in free space, naming the blockage or the
// boundary: "lies inside blockage "ram0" (demo.xml:19)".
std::string why_not_free(const io::Layout& layout, geom::Point p);

// "x,y" of a point.
std::string point_text(geom::Point p);

// A length a + b*sqrt2 for people: "23000" when b = 0, else "15.8994949366 (6+7*sqrt2)" (the
// value to 12 significant digits, then the exact form).
std::string length_text(const geom::Root2& length);

}  // namespace taut::cli
