// Test support: random layouts of many nets with rules (the net router's and the tightening of
// nets together's tests), and the nets as the independent checker (router/check.h) takes them.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "router/check.h"
#include "router/net_router.h"

namespace taut::test {

struct RandomLayout {
  geom::NormalizedObstacles norm;
  std::vector<router::NetPins> nets;
  router::NetRules rules;
};

// Rectangles that touch and pinch (and, for some seeds, sloped triangles) on 120 x 120, 1-6 nets
// of 2-4 point pins (rectangular pads for some seeds), some pins on blockage edges and corners;
// wire width 0-3 and spacing 0-2.
RandomLayout random_layout(int seed);

// One of the bend-aware metrics' random runs: the layout's blockages by their rectilinear covers,
// the link metric for every fifth seed, else Combined with C in {0, 1, 7, 1000} by seed % 4, the
// layout's rules with kDefaultCoverPieces, and the matching route function; `label` names the
// metric for messages.
struct BendRun {
  geom::NormalizedObstacles covered;
  router::NetRouterOptions options;
  router::NetRules rules;
  router::NetRouteFn route;
  std::string label;
};
BendRun bend_run(const RandomLayout& layout, int seed);

// The nets with their wires as the checker takes them (a wire's line: its net's index); a net is
// routed when it has a wire.
std::vector<router::CheckNet> check_nets(std::span<const router::NetPins> ns,
                                         std::span<const std::vector<std::vector<geom::Point>>> wires);
// ... with the router's outcomes.
std::vector<router::CheckNet> check_nets(std::span<const router::NetPins> ns, const router::NetRouter& nr);

// The L1 length of a net router outcome's wires.
std::int64_t l1_len(const router::NetOutcome& o);

// The way from a to b along a tree of pieces (polylines, each joining its two end points; a and b
// must be ends of pieces, as router::cut_at_joints makes them), as one polyline; nullopt when
// the pieces do not join a and b.
std::optional<std::vector<geom::Point>> way_between(const std::vector<std::vector<geom::Point>>& pieces, geom::Point a,
                                                    geom::Point b);

}  // namespace taut::test
