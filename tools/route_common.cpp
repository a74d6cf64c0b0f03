#include "tools/route_common.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "geom/directions.h"
#include "geom/root3_directions.h"
#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "router/bend_router.h"
#include "router/net_router.h"
#include "router/pin_shapes.h"
#include "tools/cli.h"

namespace taut::cli {

geom::NormalizedObstacles routing_obstacles(const io::Layout& layout,
                                            std::span<const geom::Point> extra) {
  const geom::Box domain = io::routing_domain(layout, extra);
  return geom::normalize_obstacles(io::blockage_polygons(layout), domain);
}

BendObstacles bend_obstacles(const io::Layout& layout, std::span<const geom::Point> extra, const std::string& metric,
                             bool quiet, int pieces) {
  BendObstacles b;
  b.pieces = pieces;
  b.polygons = io::blockage_polygons(layout, &b.owner);
  const std::vector<geom::Polygon> cover = router::rectilinear_cover(b.polygons, &b.covered, pieces);
  std::size_t last = layout.blockages.size();
  for (const std::size_t i : b.covered) {
    if (b.owner[i] == last) continue;  // shapes of one blockage are consecutive
    last = b.owner[i];
    const io::Blockage& blk = layout.blockages[last];
    print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0008", layout.file, blk.line, 0,
                                  "blockage \"" + blk.id + "\" has sloped edges: --metric " + metric +
                                      " routes around its rectilinear cover (every sloped edge cut into " +
                                      std::to_string(pieces) + " pieces, the bounding box of each added to it; "
                                      "--cover-pieces sets how many)"}},
                      quiet);
  }
  b.norm = geom::normalize_obstacles(cover, io::routing_domain(layout, extra));
  return b;
}

std::string BendObstacles::why_not_free(const io::Layout& layout, geom::Point q) const {
  // a blockage or the boundary first (as for l1); the cover only when neither explains it
  const std::string plain = cli::why_not_free(layout, q);
  if (plain.rfind("is not in free space", 0) != 0) return plain;
  for (const std::size_t i : covered) {
    const geom::Polygon only[1] = {polygons[i]};
    for (const geom::Polygon& box : router::rectilinear_cover(only, nullptr, pieces))
      if (geom::locate(q, box) != geom::Location::Outside) {
        const io::Blockage& blk = layout.blockages[owner[i]];
        return "lies in the rectilinear cover of sloped blockage \"" + blk.id + "\" (" + layout.file + ":" +
               std::to_string(blk.line) + "; ROUTE-0008)";
      }
  }
  return plain;
}

std::string BendObstacles::why_under(const io::Layout& layout, const geom::Polygon& pin) const {
  auto at = [&](std::size_t i) {
    const io::Blockage& blk = layout.blockages[owner[i]];
    return "\"" + blk.id + "\" (" + layout.file + ":" + std::to_string(blk.line) + ")";
  };
  auto ccw = [](geom::Polygon p) {  // PinShapes wants outer rings counter-clockwise, holes clockwise
    if (geom::twice_area(p.outer) < 0) std::reverse(p.outer.begin(), p.outer.end());
    for (geom::Ring& h : p.holes)
      if (geom::twice_area(h) > 0) std::reverse(h.begin(), h.end());
    return p;
  };
  const std::string rest = kNothingOutside;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const geom::Polygon only[1] = {ccw(polygons[i])};
    if (router::PinShapes(only).meets_obstacle(pin)) return "lies partly under blockage " + at(i) + rest;
  }
  for (const std::size_t i : covered) {
    const geom::Polygon only[1] = {polygons[i]};
    std::vector<geom::Polygon> cover;
    for (const geom::Polygon& p : router::rectilinear_cover(only, nullptr, pieces)) cover.push_back(ccw(p));
    if (router::PinShapes(cover).meets_obstacle(pin))
      return "lies partly under the rectilinear cover of sloped blockage " + at(i) +
             " (these metrics route around boxes along its sloped edges; ROUTE-0008)" + rest;
  }
  return "lies partly under a blockage" + rest;
}

std::string point_text(geom::Point p) { return std::to_string(p.x) + "," + std::to_string(p.y); }

const char* const kPartlyUnder =
    "lies partly under a blockage (or, among the other nets, within the clearance of their wires and pins)";
const char* const kNothingOutside =
    ", and no cell of the unit lattice lies in its part outside them (a pin partly covered so is reached as that part)";

const char* const kNoStaircase =
    "has an edge at an angle other than 0, 45 or 90 degrees, and no cell of the unit lattice lies inside it: wire "
    "vertices are integers, and such a pin is reached as the union of those cells (a thinner pin is not routed yet)";

std::string length_text(const geom::Root2& length) {
  if (length.b == 0) return std::to_string(length.a);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", length.to_double());
  return std::string(buf) + " (" + std::to_string(length.a) + (length.b < 0 ? "-" : "+") +
         std::to_string(length.b < 0 ? -length.b : length.b) + "*sqrt2)";
}

std::string why_not_free(const io::Layout& layout, geom::Point p) {
  const std::string where = " (" + layout.file + ":";
  if (layout.boundary) {
    const geom::Box& b = layout.boundary->box;
    if (p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y)
      return "lies outside the boundary" + where + std::to_string(layout.boundary->line) + ")";
  }
  for (const io::Blockage& blk : layout.blockages)
    for (const io::Shape& s : blk.shapes)
      if (geom::locate(p, io::shape_polygon(s)) == geom::Location::Inside)
        return "lies inside blockage \"" + blk.id + "\"" + where + std::to_string(s.line) + ")";
  return "is not in free space: it is enclosed where blockages touch or overlap, or lies on a "
         "blockage edge flush with the boundary";
}

nlohmann::ordered_json together_stats_json(const router::NetsTightenStats& s) {
  return {{"rounds", s.rounds},         {"capped", s.capped},
          {"wires_tightened", s.tightenings}, {"moved", s.moved},
          {"kept", s.kept},             {"kept_shape_pin", s.kept_shape_pin},
          {"windows", s.windows},       {"whole_domain_windows", s.whole}};
}

router::TightenOrientations tighten_orientations(const std::string& orientations) {
  const auto lattice = geom::LatticeDirections::parse(orientations);
  return {lattice, lattice ? std::nullopt : geom::Root3Directions::parse_any(orientations)};
}

std::vector<RealizedStep> realized_steps(const geom::Root3Directions& set) {
  std::vector<RealizedStep> out;
  const std::vector<std::string> texts = set.orientation_texts();
  for (std::size_t k = 0; k < texts.size(); ++k)
    if (!set.orientation_exact(k))  // (else a multiple of 30 or 45 degrees)
      out.push_back({texts[k], set.steps()[k].x.a, set.steps()[k].y.a, static_cast<double>(set.off_radians(k))});
  return out;
}

std::string RealizedStep::phrase() const {
  return degrees + " degrees as the step (" + std::to_string(x) + "," + std::to_string(y) + ")";
}

nlohmann::ordered_json realized_steps_json(const router::TightenOrientations& o) {
  if (!o.set30 || o.set30->exact()) return nullptr;
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const RealizedStep& r : realized_steps(*o.set30))
    out.push_back({{"degrees", r.degrees}, {"step", {r.x, r.y}}, {"off_radians", r.off}});
  return out;
}

std::string realized_steps_text(const router::TightenOrientations& o) {
  if (!o.set30) return "";
  std::string s;
  for (const RealizedStep& r : realized_steps(*o.set30)) {
    char off[32];
    std::snprintf(off, sizeof off, "%.2g", r.off);
    s += (s.empty() ? "" : "; ") + r.phrase() + ", " + off + " radians off";
  }
  return s;
}

WireTightener::WireTightener(const geom::NormalizedObstacles& norm, const std::string& orientations)
    : st_(norm, tighten_orientations(orientations)) {}

std::string WireTightener::failure_text(const io::Layout& layout, const std::string& net, const std::string& what,
                                        std::span<const geom::Point> line, const router::Tightened& r,
                                        std::int64_t clearance) {
  std::string text = "net \"" + net + "\": the " + what;
  const std::string within = "within the clearance of a blockage (" + std::to_string(clearance) +
                             " DBU: half the wire width plus the spacing)";
  if (r.status == router::TightenStatus::StartNotFree) {
    const std::string why = why_not_free(layout, line.front());
    const bool specific = why.rfind("lies inside", 0) == 0 || why.rfind("lies outside", 0) == 0;
    return text + " starts at " + point_text(line.front()) + ", which " +
           (clearance > 0 && !specific ? "lies " + within : why);
  }
  text += "'s segment " + std::to_string(r.segment + 1) + " (" + point_text(line[r.segment]) + " to " +
          point_text(line[r.segment + 1]) + ") " + router::tighten_status_text(r.status) + " at or after " +
          point_text(r.where);
  if (clearance > 0) text += ", or comes " + within;
  return text;
}

router::CheckNet check_net(const io::Net& net) {
  router::CheckNet c;
  c.name = net.name;
  c.line = net.line;
  c.loop = net.sketch && WireTightener::is_loop(net.sketch->points);
  for (const io::Pin& p : net.pins) {
    router::CheckPin cp;
    cp.name = p.name;
    cp.line = p.line;
    if (p.point) cp.point = *p.point;
    else if (p.shape) cp.shape = io::shape_polygon(*p.shape);
    c.pins.push_back(std::move(cp));
  }
  return c;
}

// Every net's pins as the net router takes them.
std::vector<router::NetPins> net_pins(const io::Layout& layout) {
  std::vector<router::NetPins> pins;
  for (const io::Net& net : layout.nets) {
    router::NetPins np;
    np.name = net.name;
    for (const io::Pin& pin : net.pins) np.pins.push_back(io::pin_polygon(pin));
    pins.push_back(std::move(np));
  }
  return pins;
}

std::string no_staircase_reason(const std::string& orientations, const std::string& why) {
  if (!why.empty()) return why;
  if (geom::Root3Directions::parse_any(orientations))  // (the builder's own reason is said where there is one)
    return "no " + orientations + " wire with integer vertices follows the taut wire's class at its length (a blockage "
           "edge at an angle outside the set pinches it past 256 runs, or no rounding of its vertices to integers "
           "stays free); --orientations any writes it";
  const auto set = geom::LatticeDirections::parse(orientations);
  // both diagonals, and not both axes: a cone between the diagonals, whose steps keep x + y's parity
  const bool parity = set && (set->mask() & 0b1010) == 0b1010 && (set->mask() & 0b0101) != 0b0101;
  return "no " + orientations + " wire with integer vertices follows the taut wire's class at its length "
         "(sloped blockages pinch every lattice staircase, or an end sits in a sloped corner that no direction "
         "of the set leaves" +
         std::string(parity ? ", or a stretch of the taut wire between two points every shortest wire passes through "
                              "lies between the two diagonals and its ends differ in the parity of x + y, which "
                              "steps along the diagonals keep"
                            : "") +
         "); --orientations any writes it";
}

std::vector<router::CheckProblem> wire_problems(const io::Layout& layout, const geom::Box& domain,
                                                const std::vector<geom::Polygon>& obstacles,
                                                const std::vector<router::NetLines>& wires) {
  geom::NormalizedObstacles space;
  space.domain = domain;
  space.obstacles = obstacles;
  std::vector<router::CheckNet> nets;
  for (std::size_t i = 0; i < layout.nets.size(); ++i) {
    router::CheckNet c = check_net(layout.nets[i]);
    c.routed = !wires[i].empty();
    for (const auto& w : wires[i]) c.wires.push_back({w, 0});
    nets.push_back(std::move(c));
  }
  router::CheckRules rules;
  if (layout.rules) rules = {layout.rules->wire_width, layout.rules->spacing};
  return router::check_routes(space, nets, rules).problems;
}

}  // namespace taut::cli
