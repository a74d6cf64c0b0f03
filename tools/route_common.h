// What `taut path` and `taut route` share: the obstacles of a layout for the router, and the
// words a person reads when a wire cannot be made.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geom/normalize.h"
#include "geom/root2.h"
#include "io/layout.h"
#include "geom/triangulation.h"
#include "router/bend_router.h"
#include "router/check.h"
#include "router/l1_router.h"
#include "router/tighten.h"
#include "router/tighten_nets.h"

namespace taut::cli {

// Normalized obstacles of the layout's blockages inside io::routing_domain(layout, extra).
geom::NormalizedObstacles routing_obstacles(const io::Layout& layout,
                                            std::span<const geom::Point> extra = {});

// --metric combined / link route rectilinear wires among rectilinear obstacles: every blockage
// with a sloped edge is replaced by its rectilinear cover (router::rectilinear_cover), with a
// warning naming it (ROUTE-0008, once per blockage; not printed when quiet), then everything is
// normalized inside io::routing_domain(layout, extra).
struct BendObstacles {
  geom::NormalizedObstacles norm;
  std::vector<geom::Polygon> polygons;  // the blockage shapes (io::blockage_polygons)
  std::vector<std::size_t> owner;       // blockage index of each shape
  std::vector<std::size_t> covered;     // shapes with a sloped edge
  int pieces = router::kDefaultCoverPieces;  // of each sloped edge, in the cover
  // Why p is not free for these metrics: why_not_free(), or the cover of a sloped blockage.
  std::string why_not_free(const io::Layout& layout, geom::Point p) const;
  // Why a shape pin is refused when its interior meets an obstacle: "lies partly under blockage
  // "ram0" (demo.xml:19); ...", or under the rectilinear cover of a sloped one.
  std::string why_under(const io::Layout& layout, const geom::Polygon& pin) const;
};
BendObstacles bend_obstacles(const io::Layout& layout, std::span<const geom::Point> extra, const std::string& metric,
                             bool quiet, int pieces = router::kDefaultCoverPieces);

// Why point p (an end of a wanted wire) is not in free space, naming the blockage or the
// boundary: "lies inside blockage "ram0" (demo.xml:19)".
std::string why_not_free(const io::Layout& layout, geom::Point p);

// "x,y" of a point.
std::string point_text(geom::Point p);

// Why router::routable_pin() (router::reach_pins) has none, after "pin "p" ", for a pin under no obstacle.
extern const char* const kNoStaircase;
// The words for a pin under obstacles that routable_pin() leaves nothing of: kPartlyUnder (or a
// blockage named), then kNothingOutside.
extern const char* const kPartlyUnder;
extern const char* const kNothingOutside;

// A length a + b*sqrt2 for people: "23000" when b = 0, else "15.8994949366 (6+7*sqrt2)" (the
// value to 12 significant digits, then the exact form).
std::string length_text(const geom::Root2& length);

// Tightening as `tighten` and `route --tighten` do it (router::SpaceTightener), with the
// orientations named as on the command line, and the words of TIGHTEN-0001.
class WireTightener {
 public:
  // orientations: "any", "rectilinear", "octilinear", a lattice c: set or a set at multiples of 30
  // degrees (tighten_orientations).
  WireTightener(const geom::NormalizedObstacles& norm, const std::string& orientations);
  using Result = router::SpaceTightener::Result;
  Result run(std::span<const geom::Point> line) const { return st_.run(line); }
  static bool is_loop(std::span<const geom::Point> line) { return router::SpaceTightener::is_loop(line); }
  // The TIGHTEN-0001 message for a failed lift of `line` (what: "sketch" or "wire").
  // clearance: the growth of the blockages (0: none), named in the message.
  static std::string failure_text(const io::Layout& layout, const std::string& net, const std::string& what,
                                  std::span<const geom::Point> line, const router::Tightened& r,
                                  std::int64_t clearance = 0);
  const geom::FreeSpaceTriangulation& triangulation() const { return st_.triangulation(); }
  const router::Tightener& tightener() const { return st_.tightener(); }

 private:
  router::SpaceTightener st_;
};

// The statistics of tightening the nets together, as --stats writes them.
nlohmann::ordered_json together_stats_json(const router::NetsTightenStats& s);

// "any", "rectilinear", "octilinear", a lattice c: set (geom::LatticeDirections::parse) or any
// other c: set (geom::Root3Directions::parse_any: at multiples of 30 degrees since 2026-12-07, at
// other angles since the twenty-first session, the same day) as router::TightenOrientations;
// anything else (such as a direction parse_any cannot realize) is taken as any.
router::TightenOrientations tighten_orientations(const std::string& orientations);

// A set whose steps are not all exactly along their written angles (Root3Directions::parse_any):
// each such orientation's step and how far it is off, for --stats, as
// [{"degrees": "10", "step": [966687, 170453], "off_radians": 1.3e-14}]; null for any other
// orientations.
nlohmann::ordered_json realized_steps_json(const router::TightenOrientations& o);
// One such orientation: as written, its integer step, how far off (radians).
struct RealizedStep {
  std::string degrees;
  std::int64_t x = 0, y = 0;
  double off = 0;
  std::string phrase() const;  // "10 degrees as the step (966687,170453)"
};
std::vector<RealizedStep> realized_steps(const geom::Root3Directions& set);
// The same in words for stderr ("10 degrees as the step (966687,170453), 1.3e-14 radians off"),
// "" for any other orientations.
std::string realized_steps_text(const router::TightenOrientations& o);

// Every net's pins as the net router takes them.
std::vector<router::NetPins> net_pins(const io::Layout& layout);

// A net as the independent checker takes it (router/check.h): its name, line and pins, no wires.
router::CheckNet check_net(const io::Net& net);

// The problems router::check_routes finds in the nets' wires (one entry per net of the layout, in
// its order; a net with none is not routed), with the clearance of <rules>, among `obstacles` (the
// layout's blockages as routed among) in `domain`.
std::vector<router::CheckProblem> wire_problems(const io::Layout& layout, const geom::Box& domain,
                                                const std::vector<geom::Polygon>& obstacles,
                                                const std::vector<router::NetLines>& wires);

// The reason written for a net with no lattice staircase in its class (TIGHTEN-0004).
// why: the builder's own reason (a set at multiples of 30 degrees, SpaceTightener::Result::why),
// said instead when there is one.
std::string no_staircase_reason(const std::string& orientations, const std::string& why = "");

}  // namespace taut::cli
