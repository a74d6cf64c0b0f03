// taut route FILE -o OUT [--svg PIC] [--stats S.json] [--orientations rectilinear|octilinear] [--tighten]
// [--independent]: routes every net by shortest wires with integer vertices, the nets together
// (router::NetRouter: each among the blockages grown by the clearance of <rules> and the other
// nets' grown wires and pins, shortest first, then rip-up and reroute; --independent: each net
// alone, exact shortest among the blockages), and writes the layout with <routes>. A two-pin net
// gets the shortest wire between its pins; a net with more pins gets a shortest-path tree from
// its first pin (BasicRouter::tree: every other pin is reached along the wires by its exact
// shortest distance from the first; the total length is not minimised). Rectilinear: point
// pins and shape pins whose edges are horizontal, vertical or at 45 degrees. Octilinear: the
// shortest wires in 0/45/90/135 degrees, point pins and shape pins whose edges are horizontal
// or vertical. Nets this version cannot route are written as failed with a reason and reported
// on stderr; the exit status is then 1. --tighten then pulls every routed wire taut in its
// class and writes it with the fewest links; a net with a <sketch> gets its sketch tightened
// (tools/route_common.h: WireTightener, as `taut tighten` does).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <set>
#include <cstdio>
#include <iostream>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "geom/directions.h"
#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "io/layout_writer.h"
#include "io/stats_json.h"
#include "io/svg.h"
#include "router/bend_router.h"
#include "router/l1_router.h"
#include "router/net_router.h"
#include "router/oct_router.h"
#include "router/tighten_nets.h"
#include "router/version.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {
namespace {

// The signal that asked taut route to stop: an atomic, as the net router's threads read it (a
// lock-free atomic may be written in a signal handler).
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
extern "C" void on_signal(int sig) { g_signal.store(sig); }

struct NetResult {
  io::Route route;
  std::string code;  // ROUTE-xxxx when failed
  std::optional<geom::Root2> radius;  // a shortest-path tree's: router::NetAttempt::radius
  std::vector<geom::Root2> sink_distances;  // its sinks': router::NetAttempt::sink_distances
  std::optional<geom::Root2> distance;  // two pins by a shortest path: router::NetAttempt::distance
  bool shortest = false;  // router::NetOutcome::shortest
  std::vector<std::pair<std::int64_t, std::int64_t>> sink_costs;  // bend metrics: router::NetAttempt::sink_costs
  bool claims = true;  // router::NetAttempt::claims (false: a pin was cut by the obstacles)
};

// A net written as failed, with the code and reason that stderr names.
NetResult failed(const io::Net& net, const char* code, std::string reason) {
  NetResult r;
  r.route.net = net.name;
  r.route.status = "failed";
  r.route.reason = std::move(reason);
  r.code = code;
  return r;
}
// ROUTE-0006 for a net of fewer than two pins, else nothing.
std::optional<NetResult> too_few_pins(const io::Net& net) {
  if (net.pins.size() >= 2) return std::nullopt;
  return failed(net, "ROUTE-0006", "the net has " + std::to_string(net.pins.size()) + " pin(s); a wire needs two");
}

// Router: router::L1Router (rectilinear wires) or router::OctRouter (octilinear).
// With --tree steiner: why this net of three or more pins does not get a Steiner tree (they are
// built for L1 wires, rectilinear and octilinear, between point pins and shape pins), or nullopt
// when it does or needs no tree.
std::optional<std::string> no_steiner_tree(const io::Net& net, const std::string& metric) {
  if (net.pins.size() <= 2) return std::nullopt;
  if (metric != "l1") return "--metric " + metric + " gives it the tree of best paths from its first pin";
  return std::nullopt;
}

// Says (ROUTE-0009) that the net does not get the Steiner tree --tree steiner asked for.
void warn_no_steiner_tree(const io::Layout& layout, const io::Net& net, const std::string& why, bool quiet) {
  print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0009", layout.file, net.line, 0,
                                "net \"" + net.name + "\": Steiner trees are built for --metric l1 wires (rectilinear and octilinear) only in this "
                                "version; " + why}},
                    quiet);
}

// steiner: the net (three or more pins, L1 rectilinear or octilinear: no_steiner_tree() is nullopt) gets
// a Steiner tree; otherwise a net of three or more pins gets the shortest-path tree from its
// first pin.
template <class Router>
// `obstacles`: the router's (a shape pin partly under them is reached as its part outside them).
NetResult route_net(const io::Layout& layout, const io::Net& net, Router& router, bool steiner,
                    std::span<const geom::Polygon> obstacles) {
  constexpr bool oct = Router::kOctilinear;
  NetResult r;
  r.route.net = net.name;
  auto fail = [&](const char* code, std::string reason) { return failed(net, code, std::move(reason)); };
  if (auto few = too_few_pins(net)) return *few;
  std::vector<geom::Polygon> shapes;
  for (const io::Pin& pin : net.pins) shapes.push_back(io::pin_polygon(pin));
  // a pin cut by the obstacles (in the net router's windows, by other nets' grown wires and pins
  // too): no claim of the shortest (NetResult::claims), as the cut of a sloped obstacle takes whole
  // cells and a pin cut in pieces is reached at its largest
  router::ReachedPins reached =
      router::reach_pins(shapes, obstacles, [&](const geom::Polygon& p) { return bool(router.pin_meets_obstacle(p)); });
  if (reached.failed)
    return fail("ROUTE-0005", "pin \"" + net.pins[*reached.failed].name + "\" " +
                                  (reached.failed_under ? std::string(kPartlyUnder) + kNothingOutside : std::string(kNoStaircase)));
  const bool cut = reached.cut;
  const std::vector<geom::Polygon>& geometry = reached.pins;
  const io::Pin& a = net.pins[0];
  const io::Pin& b = net.pins[1];
  const geom::Polygon& ga = geometry[0];
  const geom::Polygon& gb = geometry[1];
  auto where = [&](const io::Pin& pin) {
    return pin.point ? "at " + point_text(*pin.point) + " " + why_not_free(layout, *pin.point)
                     : std::string("has no free point (its shape lies in blockages or outside the boundary)");
  };
  auto text = [](const auto& len) {
    if constexpr (oct) return length_text(len); else return std::to_string(len);
  };
  auto finish = [&](std::vector<io::Wire> wires) {
    for (io::Wire& wire : wires)
      if (wire.points.size() == 1) wire.points.push_back(wire.points[0]);  // pins at one point
    std::vector<std::vector<geom::Point>> lines;
    long bends = 0;
    for (const io::Wire& wire : wires) {
      lines.push_back(wire.points);
      bends += geom::count_bends(wire.points);
    }
    r.route.status = "routed";
    r.route.length = io::format_total_length(lines);
    r.route.bends = bends;
    r.route.wires = std::move(wires);
    r.claims = !cut;
    return r;
  };
  {
    if (net.pins.size() > 2 && steiner) {
      // A rectilinear (octilinear) Steiner tree (router::BasicRouter::steiner): short total length.
      const typename Router::Steiner t = router.steiner(std::span<const geom::Polygon>(geometry));
      const io::Pin* bad = t.failed ? &net.pins[*t.failed] : nullptr;
      switch (t.status) {
        case router::WireStatus::Ok: break;
        case router::WireStatus::SourceNotFree:
        case router::WireStatus::TargetNotFree:
          return fail("ROUTE-0001", "pin \"" + bad->name + "\" " + where(*bad));
        case router::WireStatus::Unreachable:
          return fail("ROUTE-0002", "pin \"" + bad->name + "\" is in another part of free space than pin \"" + a.name +
                                        "\": blockages wall one of them in");
        case router::WireStatus::NoIntegerStaircase:
          return fail("ROUTE-0003", "pin \"" + bad->name + "\" is joined to the tree by a shortest path with no " +
                                        std::string(oct ? "octilinear" : "rectilinear") +
                                        " wire of integer vertices of its length (sloped blockages pinch every "
                                        "lattice staircase)");
      }
      std::vector<io::Wire> wires;
      for (const auto& pts : t.wires) wires.push_back(io::Wire{pts});
      return finish(std::move(wires));
    }
  }
  if (net.pins.size() > 2) {
    // A shortest-path tree from the first pin (the net's source): every other pin is reached
    // along the wires by its exact shortest distance from the first.
    const typename Router::Tree t =
        router.tree(geometry[0], std::span<const geom::Polygon>(geometry).subspan(1));
    const io::Pin* sink = t.failed ? &net.pins[*t.failed + 1] : nullptr;
    switch (t.status) {
      case router::WireStatus::Ok: break;
      case router::WireStatus::SourceNotFree:
        return fail("ROUTE-0001", "pin \"" + a.name + "\" " + where(a));
      case router::WireStatus::TargetNotFree:
        return fail("ROUTE-0001", "pin \"" + sink->name + "\" " + where(*sink));
      case router::WireStatus::Unreachable:
        return fail("ROUTE-0002", "pins \"" + a.name + "\" and \"" + sink->name +
                                      "\" are in different parts of free space: blockages wall "
                                      "one of them in");
      case router::WireStatus::NoIntegerStaircase:
        return fail("ROUTE-0003", std::string("the shortest ") + (oct ? "octilinear" : "L1") +
                                      " length from pin \"" + a.name + "\" to pin \"" +
                                      sink->name + "\" is " + text(*t.distance[*t.failed]) +
                                      ", but no " + (oct ? "octilinear" : "rectilinear") +
                                      " wire with integer vertices has that length (sloped "
                                      "blockages pinch every lattice staircase)");
    }
    std::vector<io::Wire> wires;
    for (const auto& pts : t.wires) wires.push_back(io::Wire{pts});
    NetResult done = finish(std::move(wires));
    if (done.route.status == "routed") {
      if (auto d = router::tree_sink_distances(t)) {
        done.radius = router::greatest_distance(*d);
        done.sink_distances = std::move(*d);
      }
    }
    return done;
  }
  const typename Router::Wire w = router.shortest(ga, gb);
  switch (w.status) {
    case router::WireStatus::Ok: break;
    case router::WireStatus::SourceNotFree:
      return fail("ROUTE-0001", "pin \"" + a.name + "\" " + where(a));
    case router::WireStatus::TargetNotFree:
      return fail("ROUTE-0001", "pin \"" + b.name + "\" " + where(b));
    case router::WireStatus::Unreachable:
      return fail("ROUTE-0002", "pins \"" + a.name + "\" and \"" + b.name +
                                    "\" are in different parts of free space: blockages wall one "
                                    "of them in");
    case router::WireStatus::NoIntegerStaircase:
      return fail("ROUTE-0003", std::string("the shortest ") + (oct ? "octilinear" : "L1") +
                                    " length is " + text(*w.length) + ", but no " +
                                    (oct ? "octilinear" : "rectilinear") +
                                    " wire with integer vertices has that length (sloped "
                                    "blockages pinch every lattice staircase)");
  }
  NetResult done = finish({io::Wire{w.points}});
  if (done.route.status == "routed" && !cut) done.distance = w.root2_length();
  return done;
}

// A net as the net router left it: its wires with their length and bends, or failed with its reason.
NetResult outcome_result(const io::Net& net, const router::NetOutcome& o) {
  if (!o.routed) return failed(net, o.code.c_str(), o.reason);
  NetResult r;
  r.route.net = net.name;
  long bends = 0;
  for (const auto& w : o.wires) {
    r.route.wires.push_back(io::Wire{w});
    bends += geom::count_bends(w);
  }
  r.route.status = "routed";
  r.route.length = io::format_total_length(o.wires);
  r.route.bends = bends;
  r.shortest = o.shortest;
  return r;
}

// The net (its pins and sketch) in the net router's plane scaled by k (router::NetRouter::scale(): exact gaps).
io::Net scaled_net(const io::Net& net, std::int64_t k) {
  if (k == 1) return net;
  io::Net s = net;
  auto sc = [k](geom::Point& p) { p = geom::Point{static_cast<geom::Coord>(p.x * k), static_cast<geom::Coord>(p.y * k)}; };
  for (io::Pin& pin : s.pins) {
    if (pin.point) sc(*pin.point);
    if (pin.shape) {
      sc(pin.shape->rect.lo);
      sc(pin.shape->rect.hi);
      for (geom::Point& q : pin.shape->polygon.outer) sc(q);
      for (geom::Ring& h : pin.shape->polygon.holes)
        for (geom::Point& q : h) sc(q);
    }
  }
  if (s.sketch)
    for (geom::Point& q : s.sketch->points) sc(q);
  return s;
}

// The net's pins the net router passes (NetPins::index: some of them only, one of each group of
// pins that meet, in that order; all of them, in net.pins' order, when the index is empty).
io::Net selected_pins(io::Net net, const router::NetPins& pins) {
  if (pins.index.empty()) return net;
  std::vector<io::Pin> some;
  for (const std::size_t j : pins.index) some.push_back(net.pins.at(j));
  net.pins = std::move(some);
  return net;
}

// The net with the pins the net router routes it to (selected_pins, and
// router::NetSpace::reach: a pad with a 45-degree edge in the clearance of a blockage as its
// staircase under the bend-aware metrics), in the order of pins.pins.
io::Net with_pins(io::Net net, const router::NetPins& pins) {
  net = selected_pins(std::move(net), pins);
  for (std::size_t j = 0; j < net.pins.size() && j < pins.pins.size(); ++j) {
    io::Pin& pin = net.pins[j];
    if (!pin.shape || io::pin_polygon(pin) == pins.pins[j]) continue;
    pin.shape->kind = io::Shape::Kind::Polygon;
    pin.shape->polygon = pins.pins[j];
  }
  return net;
}

// The reasons the net router gives from the route function among the plain blockages (the net
// fails even alone there), whose texts may name points: with exact gaps those were scaled, so
// such a net is tried again in the layout's own units for its message.
bool plain_reason(const std::string& code) {
  return code != "ROUTE-0010" && code != "ROUTE-0011" && code != "ROUTE-0012" && code != "ROUTE-0018";
}

std::vector<router::CheckProblem> route_problems(const io::Layout& layout, const geom::Box& domain,
                                                 const std::vector<geom::Polygon>& obstacles,
                                                 const std::vector<NetResult>& results) {
  std::vector<router::NetLines> wires(layout.nets.size());
  for (std::size_t i = 0; i < layout.nets.size(); ++i)
    if (results[i].route.status == "routed")
      for (const io::Wire& w : results[i].route.wires) wires[i].push_back(w.points);
  return wire_problems(layout, domain, obstacles, wires);
}

// --metric combined / link (router::BendRouter): nets of point and shape pins. Two pins: the
// best wire; more: the tree of best paths from the first pin (router::BendTree).
// `obstacles`: the router's (a shape pin partly under them is reached as its part outside them).
NetResult route_net_bends(const io::Layout& layout, const io::Net& net, const BendObstacles& obs,
                          const router::BendRouter& router, std::span<const geom::Polygon> obstacles,
                          router::BendMetric metric, std::int64_t bend_cost) {
  auto fail = [&](const char* code, std::string reason) { return failed(net, code, std::move(reason)); };
  if (auto few = too_few_pins(net)) return *few;
  std::vector<geom::Polygon> shapes;
  for (const io::Pin& pin : net.pins) shapes.push_back(io::pin_polygon(pin));
  router::ReachedPins reached =  // (as in route_net)
      router::reach_pins(shapes, obstacles, [&](const geom::Polygon& p) { return bool(router.pin_meets_obstacle(p)); });
  if (reached.failed)
    return fail("ROUTE-0005", "pin \"" + net.pins[*reached.failed].name + "\" " +
                                  (reached.failed_under ? obs.why_under(layout, shapes[*reached.failed]) : std::string(kNoStaircase)));
  const bool cut = reached.cut;
  const std::vector<geom::Polygon>& geometry = reached.pins;
  const router::BendTree t =
      router.tree(geometry[0], std::span<const geom::Polygon>(geometry).subspan(1), metric, bend_cost);
  const io::Pin& a = net.pins[0];
  const io::Pin& b = net.pins[t.status == router::WireStatus::SourceNotFree ? 0 : t.failed + 1];
  switch (t.status) {
    case router::WireStatus::Ok: break;
    case router::WireStatus::SourceNotFree:
    case router::WireStatus::TargetNotFree:
      if (b.point)
        return fail("ROUTE-0001", "pin \"" + b.name + "\" at " + point_text(*b.point) + " " + obs.why_not_free(layout, *b.point));
      return fail("ROUTE-0001", "pin \"" + b.name + "\" has no free point (its shape lies in blockages, their rectilinear "
                                                  "covers or outside the boundary)");
    default:
      return fail("ROUTE-0002", "pins \"" + a.name + "\" and \"" + b.name +
                                    "\" are in different parts of free space: blockages (or the rectilinear "
                                    "covers of sloped ones) wall one of them in");
  }
  NetResult r;
  r.route.net = net.name;
  r.claims = !cut;
  std::vector<std::vector<geom::Point>> lines;
  long bends = 0;
  for (std::vector<geom::Point> w : t.wires) {
    if (w.size() == 1) w.push_back(w[0]);  // pins at one point
    bends += geom::count_bends(w);
    r.route.wires.push_back(io::Wire{w});
    lines.push_back(std::move(w));
  }
  for (const std::vector<geom::Point>& p : t.paths) {
    std::int64_t length = 0;
    for (std::size_t i = 1; i < p.size(); ++i) length += std::abs(std::int64_t{p[i].x} - p[i - 1].x) + std::abs(std::int64_t{p[i].y} - p[i - 1].y);
    r.sink_costs.push_back({length, geom::count_bends(p)});
  }
  r.route.status = "routed";
  r.route.length = io::format_total_length(lines);
  r.route.bends = bends;
  return r;
}


// route --tighten: a two-pin net with a <sketch>, or a net with a loop sketch, is routed by its
// sketch pulled taut in its class among the obstacles the net router gives (so the other nets
// make room for it, ripped up when they are in its way). A sketch that leaves the window asks for a larger one (ROUTE-0002, the
// one code the net router widens the window for; the whole domain holds every sketch).
router::NetAttempt sketch_attempt(const io::Layout& layout, const io::Net& net, const geom::NormalizedObstacles& obs,
                                  const std::string& orientations, const geom::Box& whole, std::int64_t k = 1) {
  router::NetAttempt a;
  // (net, obs and whole in the net router's plane, scaled by k: exact gaps, scaled_net; the
  // reason's point is given back in the layout's units, rounded to the nearest)
  const std::vector<geom::Point>& sk = net.sketch->points;
  auto unscaled = [k](std::int64_t v) {  // the nearest integer to v / k (halves away from zero)
    return static_cast<geom::Coord>(v >= 0 ? (v + k / 2) / k : -((-v + k / 2) / k));
  };
  const geom::Box b = geom::bounding_box(sk), d = obs.domain;
  // a loop sketch is taken on the whole domain only (the net router's window proofs are for wires
  // between pins)
  if (b.lo.x < d.lo.x || b.lo.y < d.lo.y || b.hi.x > d.hi.x || b.hi.y > d.hi.y ||
      (WireTightener::is_loop(sk) && !(d == whole))) {
    a.code = "ROUTE-0002";
    a.reason = "the sketch leaves the window";
    return a;
  }
  const WireTightener wt(obs, orientations);
  WireTightener::Result r = wt.run(sk);
  if (r.taut.status != router::TightenStatus::Ok) {
    a.code = "ROUTE-0018";
    a.reason = "its <sketch> (" + layout.file + ":" + std::to_string(net.sketch->line) +
               ") comes within the clearance of a blockage or of another net's wire or pin: its segment " +
               std::to_string(r.taut.segment + 1) + " at or after " +
               point_text(geom::Point{unscaled(r.taut.where.x), unscaled(r.taut.where.y)});
    return a;
  }
  if (r.no_staircase) {
    a.code = "TIGHTEN-0004";
    a.reason = no_staircase_reason(orientations, r.why) + " (the net's <sketch>)";
    return a;
  }
  a.routed = true;
  a.wires.push_back(std::move(r.points));
  return a;
}

// Why a net routed octilinear could not be written in a c: set, lattice or at multiples of 30 degrees (route --orientations
// c:…, ROUTE-0021): a piece of its wires was kept as routed by the tightening. Two point pins
// whose x + y differ in parity are named first when the set has only the two diagonals, whose
// steps keep that parity, and the net has no shape pin: no wire of the set joins them at all.
std::optional<std::string> parity_reason(const io::Net& net, const geom::LatticeDirections& set) {
  // (a shape pin is metal holding points of both parities, through which such pins may join)
  const bool points = std::all_of(net.pins.begin(), net.pins.end(), [](const io::Pin& p) { return p.point.has_value(); });
  if (set.keeps_parity() && points)
    for (const io::Pin& p : net.pins)
      for (const io::Pin& q : net.pins)
        if (p.point && q.point && &p < &q &&
            ((std::int64_t{p.point->x} + p.point->y) - (std::int64_t{q.point->x} + q.point->y)) % 2 != 0)
          return "pins \"" + p.name + "\" (" + std::to_string(p.point->x) + "," + std::to_string(p.point->y) +
                 ") and \"" + q.name + "\" (" + std::to_string(q.point->x) + "," + std::to_string(q.point->y) + ") differ in the parity of x + y, which " +
                 set.name() + " wires keep (each step moves x and y by one): no wire in " + set.name() +
                 " joins them; route it rectilinear or octilinear";
  return std::nullopt;
}

// `status`: the tightening's outcome for the net (NoStaircase, NotFree), when known.
// (a set at multiples of 30 degrees since 2026-12-07: `why`, its builder's reason for no wire)
std::string off_set_reason(const io::Net& net, const router::TightenOrientations& set,
                           std::optional<router::NetTightenOutcome::Status> status, const std::string& why = "") {
  if (set.set)
    if (auto p = parity_reason(net, *set.set)) return *p;
  const std::string name = set.name();
  const std::string head = "its octilinear route could not be tightened into " + name + ": ";
  using S = router::NetTightenOutcome::Status;
  if (status == S::NoStaircase) return head + no_staircase_reason(name, why);
  if (status == S::NotFree)
    return head + "a piece of it lies where the other nets' wires leave no room to move it (at exactly the "
                  "clearance on both sides), so it stays in octilinear directions the set lacks; route it octilinear";
  return head + "a piece of it was kept as routed (it touches a shape pin only along a segment, or no staircase of "
                "the set follows it), in octilinear directions the set lacks; route it octilinear";
}

}  // namespace

void add_route(CLI::App& app, int& status) {
  struct Args {
    std::string file, out, svg, stats;
    RoutingOptions routing;
    LoadOptions load;
    bool tighten = false;
    bool independent = false;
    std::string tree = "spt";
    double time_limit = 0;  // seconds; 0: none
    unsigned threads = 1;   // 0: every hardware thread
    int max_rips = router::NetRouterOptions{}.max_rips;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("route", "Route every net (shortest wires; a shortest-path tree from the first pin, or with --tree steiner a Steiner tree, for nets of three or more pins) and write the routed layout");
  sub->add_option("-o,--output", args->out, "routed layout to write (the input with <routes>)")->required();
  sub->add_option("--svg", args->svg, "also draw the routed layout as SVG");
  sub->add_option("--stats", args->stats, "also write statistics as JSON");
  add_routing_options(sub, args->routing);
  args->routing.allow_bends = true;
  args->routing.allow_sets = true;
  sub->add_flag("--tighten", args->tighten,
                "then pull every wire taut in its class and write it with the fewest links (a net with a "
                "<sketch> follows its sketch), as taut tighten does");
  sub->add_flag("--independent", args->independent,
                "route each net alone among the blockages, as if no other net existed and without the clearance "
                "of <rules> (exact shortest wires per net; wires of different nets may cross)");
  sub->add_option("--time-limit", args->time_limit,
                  "stop after SEC seconds with exit status 4, writing nothing (the previous output files stay as they "
                  "were); SIGINT and SIGTERM stop the same way")
      ->check(CLI::PositiveNumber);
  sub->add_option("--threads", args->threads,
                  "nets tried at once by the net router (default 1; 0: one per hardware thread); the output is the "
                  "same byte for byte whatever N")
      ->check(CLI::Range(0u, 1024u));
  CLI::Option* max_rips_opt = sub->add_option("--max-rips", args->max_rips,
                  "rip-up: each net is ripped up at most N times (default 3; fewer makes fewer attempts and may "
                  "leave more nets unrouted, see docs/PERFORMANCE.md; 0: no rip-up, a net blocked by others is only routed round "
                  "their wires); the final round may rip any net")
      ->check(CLI::Range(0, 1000));
  sub->add_option("--tree", args->tree,
                  "nets of three or more pins: spt (default: a shortest-path tree from the first pin, every pin at its "
                  "shortest distance) or steiner (short total length; L1 wires, rectilinear or octilinear, point and shape pins)");
  add_input_options(sub, args->file, args->load, "do not print warnings or the summary");
  sub->callback([args, max_rips_opt, &status] {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    // --time-limit, SIGINT, SIGTERM: checked between nets (and between a net's windows); the run
    // then ends with exit status 4 and writes nothing (outputs are written only at the end).
    g_signal = 0;
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    const std::optional<Clock::time_point> deadline =
        args->time_limit > 0 ? std::optional<Clock::time_point>(t0 + std::chrono::duration_cast<Clock::duration>(
                                                                          std::chrono::duration<double>(args->time_limit)))
                             : std::nullopt;
    auto stop = [&] { return g_signal.load() != 0 || (deadline && Clock::now() > *deadline); };
    // A progress line on stderr when it is a terminal, from one second on.
    const bool bar = !args->load.quiet && ::isatty(2);
    bool bar_shown = false;
    auto bar_last = t0;
    auto progress = [&](const router::NetRouterProgress& p) {
      const auto now = Clock::now();
      if (!bar || now - t0 < std::chrono::seconds(1) || now - bar_last < std::chrono::milliseconds(200)) return;
      bar_last = now;
      bar_shown = true;
      const char* phase = p.phase == router::NetRouterProgress::Phase::FirstPass ? "first pass"
                          : p.phase == router::NetRouterProgress::Phase::RipUp   ? "rip-up round"
                                                                                 : "explaining";
      std::cerr << "\r" << args->file << ": " << phase;
      if (p.phase == router::NetRouterProgress::Phase::RipUp) std::cerr << " " << p.round;
      std::cerr << ", " << p.tried << " nets tried, " << p.routed << " of " << p.nets << " routed   " << std::flush;
    };
    auto end_bar = [&] {
      if (bar_shown) std::cerr << "\r\033[K" << std::flush;
      bar_shown = false;
    };
    try {
    [&] {
    if (args->tree != "steiner" && args->tree != "spt") {
      print_usage_error("CLI-0030", "route: --tree " + args->tree + ": use steiner or spt");
      status = kInvalid;
      return;
    }
    const auto layout = load_routing_layout(args->file, args->load, args->routing);
    if (!layout) {
      status = kInvalid;
      return;
    }
    const bool bends = args->routing.metric != "l1";
    // --orientations any, or a lattice c: set other than rectilinear and octilinear (since
    // 2026-12-06), or a set at multiples of 30 degrees (since 2026-12-07: c:0,60,120, written
    // with its exact vertices rounded, router/root3_staircase.h), or any other c: set (since the
    // twenty-first session, the same day: c:0,10, each direction at its step,
    // geom::Root3Directions::parse_any, the steps in --stats): the nets are routed octilinear
    // with the gaps of exactly the clearance closed, then tightened together into those
    // directions (--tighten is implied), and a net whose wires cannot be written in them is failed
    // (ROUTE-0021). `target` is what the wires are written in.
    const std::string target = routing_orientations(args->routing, *layout);
    const bool reshaped = !bends && target != "rectilinear" && target != "octilinear";
    // the set the wires are written in when reshaped (neither kind: any, or not reshaped)
    const router::TightenOrientations target_orient =
        reshaped ? tighten_orientations(target) : router::TightenOrientations::Any;
    const bool target_set = target_orient.c_oriented();
    if (reshaped) args->tighten = true;
    if (bends && args->tighten) {
      print_usage_error("CLI-0020", "--tighten makes every wire shortest in L1 in its class; it does not apply "
                                    "to --metric " + args->routing.metric);
      status = kInvalid;
      return;
    }
    if (args->threads != 1 && args->independent)  // said, not dropped silently
      print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0017", layout->file, 0, 0,
                                    "--threads applies to the nets routed together; --independent routes the nets one "
                                    "after another on one thread"}},
                        args->load.quiet);
    if (max_rips_opt->count() > 0 && args->independent)  // said, not dropped silently
      print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0017", layout->file, 0, 0,
                                    "--max-rips applies to the nets routed together; --independent routes each net "
                                    "alone and rips up nothing"}},
                        args->load.quiet);
    io::Routes routes;
    routes.tool = "taut " + std::string(router::version());
    std::size_t routed = 0;
    std::optional<router::NetRouterStats> net_stats;
    // per net routed by the net router: router::NetOutcome::shortest (--stats routes.<net>.shortest)
    std::vector<std::optional<bool>> shortest_of(layout->nets.size());
    std::unique_ptr<router::NetRouter> net_router;  // the last run of the nets together
    std::optional<router::NetsTightenStats> tighten_stats;
    std::int64_t tighten_scale = 1;  // --tighten: the plane's scale it ran in (the net router's, or 1)
    int net_threads = 1;
    // the net router's scale for exact gaps (router::NetRouter::scale; 1: closed), and the
    // problems router::check_routes found with it, when it then routed again without
    std::int64_t gap_scale = 1;
    std::size_t gap_problems = 0;
    std::int64_t gap_snap_far = 0;  // NetRouterStats::snap_far of the run with the scale
    // After a run of the net router: whether its result stands (no scale, or nothing snapped
    // from afar and nothing the checker finds with the real rules); else it is routed again
    // without exact gaps.
    auto gaps_stand = [&](const router::NetRouter& nr, const geom::Box& domain, const std::vector<geom::Polygon>& obstacles,
                          const std::vector<NetResult>& results) {
      gap_scale = nr.scale();
      if (gap_scale == 1) return true;
      gap_snap_far = nr.stats().snap_far;
      gap_problems = route_problems(*layout, domain, obstacles, results).size();
      return gap_problems == 0 && gap_snap_far == 0;
    };
    auto t1 = Clock::now();
    if (bends) {
      const BendObstacles obs = bend_obstacles(*layout, {}, args->routing.metric, args->load.quiet,
                                               static_cast<int>(args->routing.cover_pieces.value_or(router::kDefaultCoverPieces)));
      const geom::NormalizedObstacles& norm = obs.norm;
      const bool link = args->routing.metric == "link";
      const router::BendMetric metric = link ? router::BendMetric::Link : router::BendMetric::Combined;
      const std::int64_t c = link ? 0 : routing_bend_cost(args->routing, *layout);
      routes.metric = args->routing.metric;
      routes.orientations = "rectilinear";
      if (!link) routes.bend_cost = c;
      for (const io::Net& net : layout->nets)
        if (args->tree == "steiner")  // said, not dropped silently
          if (const auto why = no_steiner_tree(net, args->routing.metric)) warn_no_steiner_tree(*layout, net, *why, args->load.quiet);
      std::vector<NetResult> results(layout->nets.size());
      if (args->independent) {  // each net alone among the blockages (their rectilinear covers)
        const router::BendRouter br(norm.domain, norm.obstacles);
        t1 = Clock::now();
        for (std::size_t i = 0; i < layout->nets.size(); ++i) {
          if (stop()) throw router::NetRouterStopped();
          results[i] = route_net_bends(*layout, layout->nets[i], obs, br, norm.obstacles, metric, c);
        }
      } else {
        // Together (router::NetRouter, as for --metric l1): each net among the covers grown by
        // ceil(w/2) + s and the other nets' wires and pins grown by w + s, with rip-up; every
        // window's answer is kept only when no path out of it can cost less (net_router.h).
        router::NetRules rules;
        if (layout->rules) rules = {layout->rules->wire_width, layout->rules->spacing};
        rules.cover_pieces = obs.pieces;  // other nets' sloped shape pins by their covers, as the blockages
        geom::Box domain = norm.domain;
        if (!layout->boundary) {  // room to go round a grown blockage in the unbounded plane
          const std::int64_t grow = router::blockage_rule(rules) + router::net_rule(rules);
          domain = geom::grown_box(norm.domain, grow);
        }
        t1 = Clock::now();
        try {
          // exact gaps (NetRouter::scale), checked; routed again without them if the check fails
          for (const bool exact : {true, false}) {
            router::NetRouterOptions nro;
            nro.cost = link ? router::NetRouterOptions::Cost::Link : router::NetRouterOptions::Cost::Combined;
            nro.bend_cost = c;
            nro.stop = stop;
            nro.progress = progress;
            nro.threads = static_cast<int>(args->threads ? args->threads : std::max(1u, std::thread::hardware_concurrency()));
            nro.max_rips = args->max_rips;
            nro.exact_gaps = exact;
            nro.blockages_covered = !obs.covered.empty();  // (no claim of shortest cost then)
            net_threads = nro.threads;
            router::NetRouter nr(domain, norm.obstacles, net_pins(*layout), rules, nro);
            const std::int64_t k = nr.scale();
            nr.run([&](std::size_t i, const router::NetPins& pins, const geom::NormalizedObstacles& w) {
              const router::BendRouter br(w.domain, w.obstacles);
              NetResult r = route_net_bends(*layout, with_pins(scaled_net(layout->nets[i], pins.scale), pins), obs, br,
                                            w.obstacles, metric, c * pins.scale);
              router::NetAttempt a;
              a.routed = r.route.status == "routed";
              for (const io::Wire& wire : r.route.wires) a.wires.push_back(wire.points);
              a.code = r.code;
              a.reason = r.route.reason.value_or("");
              a.sink_costs = std::move(r.sink_costs);
              a.claims = r.claims;
              return a;
            });
            net_stats = nr.stats();
            std::optional<router::BendRouter> plain;
            for (std::size_t i = 0; i < layout->nets.size(); ++i) {
              results[i] = outcome_result(layout->nets[i], nr.outcomes()[i]);
              if (k > 1 && results[i].route.status != "routed" && plain_reason(results[i].code)) {
                if (!plain) plain.emplace(norm.domain, norm.obstacles);
                NetResult real = route_net_bends(*layout, layout->nets[i], obs, *plain, norm.obstacles, metric, c);
                if (real.route.status != "routed") results[i] = std::move(real);
              }
            }
            if (gaps_stand(nr, domain, norm.obstacles, results)) break;
          }
        } catch (const std::domain_error& e) {
          print_diagnostics({Diagnostic{Severity::Error, "ROUTE-0014", layout->file, layout->rules ? layout->rules->line : 0, 0,
                                        std::string("the clearance of <rules>: ") + e.what()}});
          status = kInvalid;
          return;
        }
      }
      for (std::size_t i = 0; i < layout->nets.size(); ++i) {
        const io::Net& net = layout->nets[i];
        NetResult& r = results[i];
        if (r.route.status == "routed") {
          ++routed;
          if (!args->independent) shortest_of[i] = r.shortest;  // (the net router's claim, since 2026-12-05)
          if (net.sketch)
            print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0007", layout->file, net.sketch->line, 0,
                                          "net \"" + net.name + "\": the wire is the best of any homotopy class "
                                          "under --metric " + args->routing.metric + " and does not follow the <sketch>"}},
                              args->load.quiet);
        } else {
          print_diagnostics({Diagnostic{Severity::Warning, r.code, layout->file, net.line, 0,
                                        "net \"" + net.name + "\" not routed: " + *r.route.reason}},
                            args->load.quiet);
        }
        routes.routes.push_back(std::move(r.route));
      }
    } else {
      std::vector<geom::Point> sketch_points;  // --tighten: sketches must fit in the domain
      if (args->tighten)
        for (const io::Net& net : layout->nets)
          if (net.sketch) sketch_points.insert(sketch_points.end(), net.sketch->points.begin(), net.sketch->points.end());
      const geom::NormalizedObstacles norm = routing_obstacles(*layout, sketch_points);
      const bool octilinear = reshaped || target == "octilinear";
      std::optional<router::L1Router> l1;
      std::optional<router::OctRouter> oct;
      if (octilinear)
        oct.emplace(norm.domain, norm.obstacles);
      else
        l1.emplace(norm.domain, norm.obstacles);
      t1 = Clock::now();

      const std::string orient_word = octilinear ? "octilinear" : "rectilinear";
      // the directions the wires are tightened into and written in: the routing's, or the target's
      const std::string tighten_word = reshaped ? target_orient.name() : orient_word;
      routes.metric = target_set || !reshaped ? "l1" : "euclidean";  // (as taut tighten writes them)
      routes.orientations = tighten_word;
      // A net whose tightened wires still leave the set, lattice or 30-degree (a piece kept as routed, in
      // octilinear directions the set lacks) is written as failed, ROUTE-0021 (the caller counts it).
      auto fail_off_set = [&](const io::Net& net, io::Route& route,
                              std::optional<router::NetTightenOutcome::Status> status, const std::string& why = "") {
        route = io::Route{};
        route.net = net.name;
        route.status = "failed";
        route.reason = off_set_reason(net, target_orient, status, why);
        print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0021", layout->file, net.line, 0,
                                      "net \"" + net.name + "\" not routed: " + *route.reason}},
                          args->load.quiet);
      };
      // With --tighten a two-pin net's sketch, or a loop sketch on any net, is what gets tightened.
      // (A two-pin net's open sketch that misses a pin is not followed: the net is routed without
      // it, ROUTE-0020, since its tightened sketch would join nothing.)
      // per net: why its open sketch misses a pin ("": it joins them, or there is none), found once
      std::vector<std::string> off_pins(layout->nets.size());
      for (std::size_t i = 0; i < layout->nets.size() && args->tighten; ++i)
        if (layout->nets[i].sketch && !WireTightener::is_loop(layout->nets[i].sketch->points))
          off_pins[i] = io::sketch_off_pins(layout->nets[i]);
      auto follows_sketch = [&](const io::Net& net) {  // (net: an element of layout->nets)
        return args->tighten && net.sketch &&
               (WireTightener::is_loop(net.sketch->points) ||
                (net.pins.size() == 2 && off_pins[static_cast<std::size_t>(&net - layout->nets.data())].empty()));
      };
      // Together (the default): every net among the others' wires and pins, with the clearance of
      // <rules> (router::NetRouter); --independent: each net alone among the blockages.
      std::vector<NetResult> together;
      std::set<std::string> contractible_loop;  // --tighten: loop sketches that wind around no blockage
      geom::Box net_domain = norm.domain;  // the net router's (grown when there is no boundary)
      if (args->tighten && !args->independent) {
        // A sketch that leaves free space is an input error, found before routing (nothing written).
        std::optional<WireTightener> plain;
        std::vector<Diagnostic> errors;
        for (const io::Net& net : layout->nets) {
          if (!follows_sketch(net)) continue;
          if (!plain) plain.emplace(norm, "any");  // only the lift and the loop's class are read
          const auto res = plain->run(net.sketch->points);
          if (res.contractible) contractible_loop.insert(net.name);  // out of the together tightening
          if (res.taut.status != router::TightenStatus::Ok)
            errors.push_back(Diagnostic{Severity::Error, "TIGHTEN-0001", layout->file, net.sketch->line, 0,
                                        WireTightener::failure_text(*layout, net.name, "sketch", net.sketch->points, res.taut)});
        }
        if (!errors.empty()) {
          print_diagnostics(errors);
          status = kInvalid;
          return;
        }
      }
      if (!args->independent) {
        std::vector<router::NetPins> pins = net_pins(*layout);
        router::NetRules rules;
        if (layout->rules) rules = {layout->rules->wire_width, layout->rules->spacing};
        geom::NormalizedObstacles space = norm;
        if (!layout->boundary) {  // room to go round a grown blockage in the unbounded plane
          const std::int64_t grow = router::blockage_rule(rules) + router::net_rule(rules);
          space.domain = geom::grown_box(norm.domain, grow);
        }
        net_domain = space.domain;
        std::vector<bool> steiner_ok(layout->nets.size());
        for (std::size_t i = 0; i < layout->nets.size(); ++i) {
          const io::Net& net = layout->nets[i];
          const std::optional<std::string> why = args->tree == "steiner" ? no_steiner_tree(net, "l1") : std::nullopt;
          if (why) warn_no_steiner_tree(*layout, net, *why, args->load.quiet);  // said, not dropped silently
          steiner_ok[i] = args->tree == "steiner" && !why;
        }
        try {
          // exact gaps (NetRouter::scale), checked; routed again without them if the check
          // fails. With --tighten too (a wire in such a gap is kept as routed: the tightening's
          // triangulated space closes it; a net that follows its sketch has it tightened in the
          // router's scaled plane, and snapped back as every wire is).
          for (const bool exact : {true, false}) {
          // (under a set, lattice or 30-degree, a wire in such a gap would stay as routed, outside its directions;
          // under any it is written as it is)
          if (exact && target_set) continue;
          router::NetRouterOptions nro;
          nro.octilinear = octilinear;
          nro.stop = stop;
          nro.progress = progress;
          // the nets routed by L1Router or OctRouter alone take framed windows (a sketch's
          // tightening reads the obstacles itself)
          // (and with the wires tightened into a set, lattice or 30-degree, which reads them: router::tighten_attempt)
          nro.framed = [&](std::size_t i) { return !(reshaped && target_set) && !follows_sketch(layout->nets[i]); };
          nro.threads = static_cast<int>(args->threads ? args->threads : std::max(1u, std::thread::hardware_concurrency()));
          nro.max_rips = args->max_rips;
          nro.exact_gaps = exact;
          net_threads = nro.threads;
          net_router = std::make_unique<router::NetRouter>(space.domain, space.obstacles, pins, rules, nro);
          router::NetRouter& nr = *net_router;
          const std::int64_t k = nr.scale();
          nr.run([&](std::size_t i, const router::NetPins& pins, const geom::NormalizedObstacles& obs) {
            const io::Net& net = layout->nets[i];
            if (follows_sketch(net)) {
              if (contractible_loop.count(net.name)) {
                router::NetAttempt a;
                a.code = "TIGHTEN-0005";
                a.reason = "the loop sketch winds around no blockage: it can be pulled to a point";
                return a;
              }
              return sketch_attempt(*layout, scaled_net(net, pins.scale), obs, reshaped ? tighten_word : orient_word,
                                    nr.space().domain(), pins.scale);
            }
            if (reshaped && target_orient.set)
              if (auto why = parity_reason(net, *target_orient.set)) {  // never routed, so it takes no room
                router::NetAttempt a;
                a.code = "ROUTE-0021";
                a.reason = *why;
                return a;
              }
            NetResult r;
            const io::Net sn = with_pins(scaled_net(net, pins.scale), pins);  // (a sloped pin: its staircase)
            if (octilinear) {
              router::OctRouter rt(obs.domain, obs.obstacles);
              rt.set_lattice(pins.scale);  // no vertex half way between the plane's multiples
              r = route_net(*layout, sn, rt, steiner_ok[i], obs.obstacles);
            } else {
              router::L1Router rt(obs.domain, obs.obstacles);
              r = route_net(*layout, sn, rt, steiner_ok[i], obs.obstacles);
            }
            router::NetAttempt a;
            a.routed = r.route.status == "routed";
            for (const io::Wire& w : r.route.wires) a.wires.push_back(w.points);
            a.code = r.code;
            a.reason = r.route.reason.value_or("");
            a.radius = r.radius;
            a.sink_distances = r.sink_distances;
            a.distance = r.distance;
            a.claims = r.claims;
            // (a set, lattice or 30-degree: the wires placed are already in it; router/tighten_nets.h)
            if (reshaped && target_set) router::tighten_attempt(a, pins, obs, target_orient, stop);
            return a;
          });
          net_stats = nr.stats();
          together.clear();
          for (std::size_t i = 0; i < layout->nets.size(); ++i) {
            together.push_back(outcome_result(layout->nets[i], nr.outcomes()[i]));
            if (k > 1 && together[i].route.status != "routed" && plain_reason(together[i].code)) {
              NetResult real = l1 ? route_net(*layout, layout->nets[i], *l1, steiner_ok[i], norm.obstacles)
                                  : route_net(*layout, layout->nets[i], *oct, steiner_ok[i], norm.obstacles);
              if (real.route.status != "routed") together[i] = std::move(real);
            }
          }
          if (gaps_stand(nr, space.domain, space.obstacles, together)) break;
          }
        } catch (const std::domain_error& e) {
          print_diagnostics({Diagnostic{Severity::Error, "ROUTE-0014", layout->file, layout->rules ? layout->rules->line : 0, 0,
                                        std::string("the clearance of <rules>: ") + e.what()}});
          status = kInvalid;
          return;
        }
      } else if (args->tighten && (!reshaped || (layout->rules && (layout->rules->wire_width > 0 || layout->rules->spacing > 0)))) {
        // (under a set the tightening is implied: said only when there is a clearance to break)
        print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0013", layout->file, 0, 0,
                                      std::string(reshaped ? "--orientations " + target : "--tighten") +
                                          " with --independent pulls each wire taut among the blockages alone: "
                                      "tightened wires may come closer to other nets or to blockages than <rules> "
                                      "allows (taut check finds where)"}},
                          args->load.quiet);
      }
      for (std::size_t ni = 0; ni < layout->nets.size(); ++ni) {
        const io::Net& net = layout->nets[ni];
        NetResult r;
        if (args->independent) {
          if (stop()) throw router::NetRouterStopped();
          const std::optional<std::string> why = args->tree == "steiner" ? no_steiner_tree(net, "l1") : std::nullopt;
          if (why) warn_no_steiner_tree(*layout, net, *why, args->load.quiet);  // said, not dropped silently
          const bool steiner = args->tree == "steiner" && !why;
          r = l1 ? route_net(*layout, net, *l1, steiner, norm.obstacles) : route_net(*layout, net, *oct, steiner, norm.obstacles);
        } else {
          r = std::move(together[ni]);
          if (r.route.status == "routed") shortest_of[ni] = r.shortest;
        }
        if (!off_pins[ni].empty())  // said, not dropped silently
          print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0020", layout->file, net.sketch->line, 0,
                                        "net \"" + net.name + "\": its <sketch> " + off_pins[ni] +
                                            ", so it is not followed: the net is routed as if it had none"}},
                            args->load.quiet);
        if (r.route.status == "routed") {
          ++routed;
          if (net.sketch && !follows_sketch(net) && off_pins[ni].empty())  // said, not dropped silently
            print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0007", layout->file, net.sketch->line, 0,
                                          "net \"" + net.name + "\": the wire is the shortest of any "
                                          "homotopy class and does not follow the <sketch> (--tighten or "
                                          "taut tighten pull the sketch taut in its class)"}},
                              args->load.quiet);
        } else if (!(follows_sketch(net) && WireTightener::is_loop(net.sketch->points) &&
                     (args->independent || contractible_loop.count(net.name)))) {  // said below
          print_diagnostics({Diagnostic{Severity::Warning, r.code, layout->file, net.line, 0,
                                        "net \"" + net.name + "\" not routed: " + *r.route.reason}},
                            args->load.quiet);
        }
        routes.routes.push_back(std::move(r.route));
      }
      if (args->tighten && !args->independent) {
        // Every net tightened together with the clearance of <rules> (router::NetsTightener): each
        // wire pulled taut in its class among the grown blockages and the other nets' grown wires
        // and pins, round after round until no wire shortens; loop sketches join in.
        router::NetRules rules;
        if (layout->rules) rules = {layout->rules->wire_width, layout->rules->spacing};
        std::vector<router::NetLines> wires(layout->nets.size());
        using Input = router::NetsTightener::Input;
        std::vector<Input> kind(layout->nets.size(), Input::Wires);
        for (std::size_t i = 0; i < layout->nets.size(); ++i) {
          const io::Net& net = layout->nets[i];
          if (follows_sketch(net) && WireTightener::is_loop(net.sketch->points)) {
            kind[i] = Input::TautSketch;  // the net router's wire is its tightened loop (it may wind twice)
            if (routes.routes[i].status == "routed")
              for (const io::Wire& w : routes.routes[i].wires) wires[i].push_back(w.points);
          } else if (routes.routes[i].status == "routed") {
            for (const io::Wire& w : routes.routes[i].wires) wires[i].push_back(w.points);
            if (follows_sketch(net)) kind[i] = Input::TautSketch;  // its tightened sketch, which may run along itself
          }
        }
        router::NetsTightenOptions o;
        std::vector<router::NetTightenOutcome> tighten_outcomes;  // in the layout's units (empty: scaled)
        o.orientations = tighten_orientations(tighten_word);
        o.stop = stop;
        // In the net router's scaled plane first (since 2026-12-05), where gaps of exactly the
        // clearance are open (net_router.h), so a wire there is pulled taut too; then snapped back
        // to the layout's integers and kept only when no vertex was a quarter of the scale or more
        // from its multiple, every net passes the check with the rules, and no net's wires got
        // longer (what tightening promises); else tightened in the layout's units, where a wire in
        // such a gap is kept as routed.
        const std::int64_t k = net_router ? net_router->scale() : 1;
        if (k > 1) {
          router::NetsTightenStats kst;
          std::optional<std::vector<router::NetLines>> back =
              router::tighten_scaled(net_domain, norm.obstacles, net_pins(*layout), rules, k, wires, kind, o, &kst);
          if (back && wire_problems(*layout, net_domain, norm.obstacles, *back).empty()) {
            // (a net whose wires got neither shorter nor fewer bends keeps its routed ones, when
            // the layout then still passes the check: it then takes no claim of shortest length
            // from the other nets (NetRouter::withdraw_claims, below), and a wire that would run
            // on through the corner where it ends on another gains no bend)
            std::vector<router::NetLines> mixed = *back;
            for (std::size_t i = 0; i < wires.size() && !reshaped; ++i) {  // (in a set, its wires are asked for)
              if (wires[i].empty()) continue;
              const auto [l0, b0] = router::length_and_bends(wires[i]);
              const auto [l1, b1] = router::length_and_bends((*back)[i]);
              if (!(l1 < l0) && b1 >= b0) mixed[i] = wires[i];
            }
            if (mixed != *back && wire_problems(*layout, net_domain, norm.obstacles, mixed).empty()) back = std::move(mixed);
            wires = std::move(*back);
            tighten_stats = kst;
            tighten_scale = k;
          }
        }
        if (tighten_scale == 1) {
          router::NetSpace ts(net_domain, norm.obstacles, net_pins(*layout), rules);
          router::NetsTightener nt(ts, o);
          tighten_outcomes = nt.run(wires, kind);
          tighten_stats = nt.stats();
        }
        // A claim of shortest length stands only while no other net's wire left its proof window
        // (router::NetRouter::withdraw_claims): tightening moves wires.
        if (net_router) {
          for (std::size_t i = 0; i < layout->nets.size(); ++i) {
            if (routes.routes[i].status != "routed" || wires[i].empty()) continue;
            router::NetLines before;
            for (const io::Wire& w : routes.routes[i].wires) before.push_back(w.points);
            if (before != wires[i]) net_router->withdraw_claims(i, before, wires[i]);
          }
          for (std::size_t i = 0; i < layout->nets.size(); ++i)
            if (shortest_of[i]) shortest_of[i] = net_router->outcomes()[i].shortest && !reshaped;
          net_stats = net_router->stats();
          // (claims are of the octilinear routing's length, not of the set's: none under --orientations any or c:)
          if (reshaped) net_stats->shortest = net_stats->shortest_withdrawn = 0;
        }
        for (std::size_t i = 0; i < layout->nets.size(); ++i) {
          const io::Net& net = layout->nets[i];
          io::Route& route = routes.routes[i];
          const bool was_routed = route.status == "routed";
          const bool loop_net = follows_sketch(net) && WireTightener::is_loop(net.sketch->points);
          if (loop_net && contractible_loop.count(net.name)) {  // the net router was told so: said here
            const std::string code = "TIGHTEN-0005";
            const std::string reason = "the loop sketch winds around no blockage: it can be pulled to a point";
            if (was_routed) --routed;
            route = io::Route{};
            route.net = net.name;
            route.status = "failed";
            route.reason = reason;
            print_diagnostics({Diagnostic{Severity::Warning, code, layout->file, net.sketch->line, 0,
                                          "net \"" + net.name + "\": " + reason}},
                              args->load.quiet);
            continue;
          }
          if (wires[i].empty()) continue;
          if (reshaped && target_set &&
              !std::all_of(wires[i].begin(), wires[i].end(), [&](const auto& w) { return target_orient.runs_in(w); })) {
            if (was_routed) --routed;
            shortest_of[i].reset();
            fail_off_set(net, route, i < tighten_outcomes.size() ? std::optional(tighten_outcomes[i].status) : std::nullopt,
                         i < tighten_outcomes.size() ? tighten_outcomes[i].why : std::string());
            continue;
          }
          if (!was_routed) ++routed;
          route = io::Route{};
          route.net = net.name;
          route.status = "routed";
          route.length = io::format_total_length(wires[i]);
          long bends = 0;
          for (const auto& w : wires[i]) {
            bends += geom::count_bends(w);
            route.wires.push_back(io::Wire{w});
          }
          route.bends = bends;
        }
      } else if (args->tighten) {
        // --independent: every routed wire pulled taut in its class and written with the fewest links (its L1 or
        // octilinear length cannot grow: the routed wire is a staircase of the class); a net with a
        // sketch gets its sketch tightened instead, which fixes its class.
        const WireTightener wt(norm, tighten_word);
        std::vector<Diagnostic> errors;
        for (std::size_t i = 0; i < layout->nets.size(); ++i) {
          const io::Net& net = layout->nets[i];
          io::Route& route = routes.routes[i];
          const bool was_routed = route.status == "routed";
          std::vector<io::Wire> wires;
          bool no_staircase = false;  // a piece has no staircase in the set
          std::string no_staircase_why;  // (a set at multiples of 30 degrees: the builder's reason)
          if (follows_sketch(net)) {
            const auto res = wt.run(net.sketch->points);
            if (res.taut.status != router::TightenStatus::Ok) {
              errors.push_back(Diagnostic{Severity::Error, "TIGHTEN-0001", layout->file, net.sketch->line, 0,
                                          WireTightener::failure_text(*layout, net.name, "sketch", net.sketch->points,
                                                                      res.taut)});
              continue;
            }
            if (res.no_staircase || res.contractible) {
              if (route.status == "routed") --routed;
              route = io::Route{};
              route.net = net.name;
              route.status = "failed";
              route.reason = res.contractible
                                 ? std::string("the loop sketch winds around no blockage: it can be pulled to a point")
                                 : no_staircase_reason(tighten_word, res.why) + " (the net's <sketch>)";
              print_diagnostics({Diagnostic{Severity::Warning, res.contractible ? "TIGHTEN-0005" : "TIGHTEN-0004",
                                            layout->file, net.sketch->line, 0, "net \"" + net.name + "\": " + *route.reason}},
                                args->load.quiet);
              continue;
            }
            wires.push_back(io::Wire{res.points});
            if (route.status != "routed") ++routed;
          } else if (route.status == "routed") {
            // cut at the tree's joints first (branch points, pins passed), which stay where they are
            router::NetLines lines;
            for (const io::Wire& w : route.wires) lines.push_back(w.points);
            std::vector<geom::Polygon> pins;
            for (const io::Pin& pin : net.pins) pins.push_back(io::pin_polygon(pin));
            std::vector<char> frozen;
            lines = router::cut_at_joints(lines, pins, &frozen);
            for (std::size_t k = 0; k < lines.size(); ++k) {
              const auto res = frozen[k] ? WireTightener::Result{} : wt.run(lines[k]);
              no_staircase = no_staircase || res.no_staircase;
              if (res.no_staircase && no_staircase_why.empty()) no_staircase_why = res.why;
              // a routed wire is in free space; when no staircase is found, or the one found has
              // more bends (its fewest links not proven), the routed one stays (not when the wires
              // are written in other directions than routed: then any result is taken)
              const bool better = !res.points.empty() &&
                                  (reshaped || geom::count_bends(res.points) <= geom::count_bends(lines[k]));
              wires.push_back(io::Wire{better ? res.points : lines[k]});
            }
          } else {
            continue;
          }
          if (reshaped && target_set &&
              !std::all_of(wires.begin(), wires.end(), [&](const io::Wire& w) { return target_orient.runs_in(w.points); })) {
            if (was_routed || follows_sketch(net)) --routed;  // (a sketch net was counted above)
            shortest_of[i].reset();
            fail_off_set(net, route, no_staircase ? std::optional(router::NetTightenOutcome::Status::NoStaircase) : std::nullopt,
                         no_staircase_why);
            continue;
          }
          std::vector<std::vector<geom::Point>> lines;
          long bends = 0;
          for (const io::Wire& w : wires) {
            lines.push_back(w.points);
            bends += geom::count_bends(w.points);
          }
          route = io::Route{};
          route.net = net.name;
          route.status = "routed";
          route.length = io::format_total_length(lines);
          route.bends = bends;
          route.wires = std::move(wires);
        }
        if (!errors.empty()) {
          print_diagnostics(errors);
          status = kInvalid;
          return;
        }
      }
    }  // the l1 metric
    end_bar();
    if (gap_problems || gap_snap_far)  // said, not hidden: the run stands, with those gaps closed
      print_diagnostics({Diagnostic{Severity::Warning, "ROUTE-0019", layout->file, 0, 0,
                                    "routed with gaps of exactly the clearance open, " +
                                        (gap_snap_far ? std::to_string(gap_snap_far) +
                                                            " wire(s) could not be mapped back to the layout's integers safely"
                                                      : std::to_string(gap_problems) + " place(s) failed the check") +
                                        "; routed again with those gaps closed, as written"}},
                        args->load.quiet);
    if (stop()) throw router::NetRouterStopped();
    const auto t2 = Clock::now();
    io::Layout out = *layout;
    out.routes = std::move(routes);

    // Every output is made before any is written, so a failure leaves nothing half done.
    const std::string xml = io::layout_to_xml(out);
    std::string svg, stats;
    if (!args->svg.empty()) svg = io::layout_to_svg(out);
    auto j = nlohmann::ordered_json::parse(io::layout_stats_json(out));
    const auto t3 = Clock::now();
    const double prepare_s = std::chrono::duration<double>(t1 - t0).count(), route_s = std::chrono::duration<double>(t2 - t1).count(),
                 output_s = std::chrono::duration<double>(t3 - t2).count();
    j["route_seconds"] = {{"prepare", prepare_s}, {"route", route_s}, {"output", output_s}};
    for (std::size_t i = 0; i < shortest_of.size(); ++i)
      if (shortest_of[i] && j["routes"].contains(layout->nets[i].name)) j["routes"][layout->nets[i].name]["shortest"] = *shortest_of[i];
    if (net_stats)
      j["net_router"] = {{"first_pass_routed", net_stats->first_pass},
                         {"proven_shortest", net_stats->shortest},
                         {"shortest_withdrawn", net_stats->shortest_withdrawn},
                         {"rip_up_rounds", net_stats->rounds},
                         {"rip_ups", net_stats->rips},
                         {"attempts", net_stats->attempts},
                         {"windows", net_stats->windows},
                         {"whole_domain_windows", net_stats->whole},
                         {"window_limit_stops", net_stats->capped},
                         {"last_pass_nets", net_stats->last_pass},
                         {"last_pass_routed", net_stats->last_pass_routed},
                         {"last_pass_proven_apart", net_stats->superset_apart},
                         {"proven_apart_among_blockages", net_stats->blockages_apart},
                         {"group_choice_routes", net_stats->group_choices},
                         {"final_round_nets", net_stats->final_round},
                         {"final_round_routed", net_stats->final_round_routed},
                         {"relaxed_windows", net_stats->relaxed},
                         {"threads", net_threads},
                         {"speculative_attempts", net_stats->speculated},
                         {"speculative_redone", net_stats->redone},
                         {"rip_ups_ahead", net_stats->rip_ups_ahead},
                         {"rip_ups_ahead_redone", net_stats->rip_ups_redone},
                         {"reused_attempts", net_stats->reused},
                         {"replayed_rip_ups", net_stats->replayed},
                         {"space_seconds", net_stats->space_seconds},
                         {"path_seconds", net_stats->route_seconds},
                         {"phase_seconds",
                          {{"first_pass", net_stats->phase_seconds.first_pass},
                           {"rip_up_rounds", net_stats->phase_seconds.rounds},
                           {"final_round", net_stats->phase_seconds.final_round},
                           {"last_pass", net_stats->phase_seconds.last_pass},
                           {"explain", net_stats->phase_seconds.explain}}},
                         {"exact_gaps", {{"scale", gap_scale}, {"snap_far", gap_snap_far}, {"check_problems", gap_problems}}}};
    if (tighten_stats) {
      j["tighten"] = together_stats_json(*tighten_stats);
      j["tighten"]["scale"] = tighten_scale;  // (since 2026-12-05)
    }
    // a set at other angles: the integer steps its directions were taken as (since 2026-12-07)
    if (const auto steps = realized_steps_json(target_orient); !steps.is_null()) j["orientation_steps"] = steps;
    if (!args->stats.empty()) stats = j.dump(2) + "\n";
    if (!write_output(args->out, xml) || (!args->svg.empty() && !write_output(args->svg, svg)) ||
        (!args->stats.empty() && !write_output(args->stats, stats))) {
      status = kInvalid;
      return;
    }
    const std::size_t failed = layout->nets.size() - routed;
    if (!args->load.quiet) {
      // the short table on stderr: nets not routed first, the totals, the time of each phase
      print_route_table(std::cerr, j, 10);
      char times[200];
      std::snprintf(times, sizeof times, "time: prepare %.2f s, route %.2f s, output %.2f s", prepare_s, route_s, output_s);
      std::cerr << times;
      if (net_stats) {
        std::snprintf(times, sizeof times, " (building spaces %.2f s, paths %.2f s; %lld windows, %d rip-up rounds, %lld rip-ups)",
                      net_stats->space_seconds, net_stats->route_seconds, static_cast<long long>(net_stats->windows),
                      net_stats->rounds, static_cast<long long>(net_stats->rips));
        std::cerr << times;
      }
      std::cerr << '\n';
      if (tighten_stats)
        std::cerr << "tightened together: " << tighten_stats->moved << " wires moved in " << tighten_stats->rounds
                  << " rounds" << (tighten_stats->capped ? " (capped)" : "") << ", " << tighten_stats->kept
                  << " kept as routed (in a gap of exactly the clearance, or no staircase)\n";
      std::cerr << args->file << ": routed " << routed << " of " << layout->nets.size() << " nets"
                << (failed ? " (" + std::to_string(failed) + " not routed, see above)" : std::string())
                << "; wrote " << args->out << '\n';
      if (const std::string steps = realized_steps_text(target_orient); !steps.empty())
        std::cerr << "  " << target_orient.name() << ": " << steps << " (every wire exact for these steps, then rounded)\n";
    }
    status = failed ? kIncomplete : kOk;
    }();
    } catch (const router::NetRouterStopped&) {
      end_bar();
      const double el = std::chrono::duration<double>(Clock::now() - t0).count();
      char secs[32], limit[32];
      std::snprintf(secs, sizeof secs, "%.1f", el);
      std::snprintf(limit, sizeof limit, "%g", args->time_limit);
      print_diagnostics({Diagnostic{Severity::Error, "ROUTE-0016", args->file, 0, 0,
                                    std::string("stopped by ") +
                                        (g_signal == SIGINT    ? "SIGINT"
                                         : g_signal == SIGTERM ? "SIGTERM"
                                                               : "--time-limit " + std::string(limit) + " s") +
                                        " after " + secs + " s: nothing written (" + args->out + " keeps what it held)"}});
      status = kResource;
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  });
}

}  // namespace taut::cli
