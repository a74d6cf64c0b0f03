// taut path FILE --from X,Y --to X,Y [--orientations rectilinear|octilinear]
// [--metric l1|combined|link] [--bend-cost C] [--json]: one exact shortest wire among the
// layout's blockages (rectilinear: L1 length; octilinear: the length a + b*sqrt2 of the shortest
// path in 0/45/90/135 degrees; combined: L1 length + C x bends; link: fewest bends, then
// shortest), with integer vertices; its cost, length, bends, points.
// taut path FILE --from-file F --to X,Y --metric combined|link [--json]: the best wire from each
// point of F (one X,Y per line) to one target, from router::BendTargetMap (a Dijkstra run from
// the target and eight slab trees, then O(log^2 n) per point).
// --to-pin NET PIN instead of --to: the wire ends anywhere on that pin of the layout (a point or
// a shape, as taut route takes it).
#include <functional>
#include <iostream>
#include <variant>

#include <nlohmann/json.hpp>

#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "router/bend_router.h"
#include "router/l1_router.h"
#include "router/net_router.h"
#include "router/oct_router.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {

namespace {

// The JSON of `path` when there is no wire (CLI.md: "cost":null and a reason).
void no_wire_json(nlohmann::ordered_json& j, const std::string& reason) {
  j["cost"] = nullptr;
  j["length"] = nullptr;
  j["bends"] = nullptr;
  j["points"] = nlohmann::ordered_json::array();
  j["reason"] = reason;
}

// A bend-aware wire's fields in `path --json`: cost, length, bends, points.
void wire_json(nlohmann::ordered_json& j, std::int64_t cost, const router::BendPath& p) {
  j["cost"] = cost;
  j["length"] = p.length;
  j["bends"] = p.bends;
  auto pts = nlohmann::ordered_json::array();
  for (const geom::Point q : p.points) pts.push_back({q.x, q.y});
  j["points"] = pts;
}
// "length L, B bends: x,y x,y ..." of a bend-aware wire.
std::string wire_text(const router::BendPath& p) {
  std::string s = "length " + std::to_string(p.length) + ", " + std::to_string(p.bends) + (p.bends == 1 ? " bend:" : " bends:");
  for (const geom::Point q : p.points) s += ' ' + point_text(q);
  return s;
}

// Where the wanted wires end: --to X,Y, or --to-pin NET PIN (a point or a shape of the layout).
struct Target {
  geom::Polygon pin;                 // a point pin for --to and for a point pin
  std::optional<geom::Point> point;  // set for a point
  std::string label;                 // "--to 5,5" or "pin "pad" of net "clk" (demo.xml:29)"
  std::string name;                  // "5,5" or "pin "pad" of net "clk""
  std::vector<geom::Point> vertices() const {
    std::vector<geom::Point> v(pin.outer.begin(), pin.outer.end());
    for (const geom::Ring& h : pin.holes) v.insert(v.end(), h.begin(), h.end());
    return v;
  }
  // Why the target is not free: the point's reason, or that no point of the shape is.
  std::string not_free(const std::function<std::string(geom::Point)>& why) const {
    return label + " " + (point ? why(*point) : "has no free point (its shape lies in blockages or outside the boundary)");
  }
};

// --to-pin NET PIN of the layout; CLI-0028 when there is no such pin.
std::optional<Target> pin_target(const io::Layout& layout, const std::string& net, const std::string& pin) {
  for (const io::Net& n : layout.nets) {
    if (n.name != net) continue;
    std::string names;
    for (const io::Pin& p : n.pins) {
      if (p.name != pin) {
        names += (names.empty() ? "\"" : ", \"") + p.name + "\"";
        continue;
      }
      Target t;
      if (p.point) t.pin.outer = {*p.point}, t.point = *p.point;
      else t.pin = io::pin_polygon(p);  // (a vertex written twice in a row taken once)
      t.name = "pin \"" + pin + "\" of net \"" + net + "\"";
      t.label = t.name + " (" + layout.file + ":" + std::to_string(p.line) + ")";
      return t;
    }
    print_usage_error("CLI-0028", "--to-pin: net \"" + net + "\" (" + layout.file + ":" + std::to_string(n.line) +
                                      ") has no pin \"" + pin + "\"" + (names.empty() ? "" : "; its pins: " + names));
    return std::nullopt;
  }
  print_usage_error("CLI-0028", "--to-pin: " + layout.file + " has no net \"" + net + "\"");
  return std::nullopt;
}

// What the routers reach of a target among `obstacles`: a point as it is, a shape as
// router::routable_pin takes it (the part outside the obstacles it lies partly under, or the
// staircase of one at another angle); or, when nothing is left, why (ROUTE-0005's words).
std::variant<geom::Polygon, std::string> reach_of(const Target& t, std::span<const geom::Polygon> obstacles,
                                                  const std::function<std::string()>& why_under) {
  if (t.point) return t.pin;
  const std::vector<geom::Polygon> under = router::obstacles_under(t.pin, obstacles);
  if (std::optional<geom::Polygon> reach = router::routable_pin(t.pin, under)) return std::move(*reach);
  return t.label + " " + (under.empty() ? std::string(kNoStaircase) : why_under());
}

// --metric combined / link: BendRouter among the rectilinear cover of the blockages.
int bend_path(const io::Layout& layout, const RoutingOptions& routing, geom::Point from, Target target,
              bool json, bool quiet) {
  const bool link = routing.metric == "link";
  const std::int64_t c = link ? 0 : routing_bend_cost(routing, layout);
  std::vector<geom::Point> ends = target.vertices();
  ends.push_back(from);
  const BendObstacles obs = bend_obstacles(layout, ends, routing.metric, quiet, static_cast<int>(routing.cover_pieces.value_or(router::kDefaultCoverPieces)));
  const geom::NormalizedObstacles& norm = obs.norm;
  const router::BendRouter router(norm.domain, norm.obstacles);
  const router::BendMetric metric = link ? router::BendMetric::Link : router::BendMetric::Combined;
  const auto reach = reach_of(target, obs.norm.obstacles, [&] { return obs.why_under(layout, target.pin); });
  if (const std::string* refused = std::get_if<std::string>(&reach)) {
    print_usage_error("ROUTE-0005", *refused);
    if (json) {
      nlohmann::ordered_json j;
      j["metric"] = routing.metric;
      if (!link) j["bend_cost"] = c;
      no_wire_json(j, *refused);
      std::cout << j.dump() << '\n';
    }
    return kIncomplete;
  }
  const router::BendPath p = target.point ? router.path(from, *target.point, metric, c)
                                          : router.path(geom::Polygon{{from}, {}}, std::get<geom::Polygon>(reach), metric, c);

  nlohmann::ordered_json j;
  j["metric"] = routing.metric;
  if (!link) j["bend_cost"] = c;
  std::string code, reason;
  auto not_free = [&](geom::Point q) { return obs.why_not_free(layout, q); };
  switch (p.status) {
    case router::WireStatus::Ok: break;
    case router::WireStatus::SourceNotFree:
      code = "ROUTE-0001", reason = "--from " + point_text(from) + " " + not_free(from);
      break;
    case router::WireStatus::TargetNotFree:
      code = "ROUTE-0001", reason = target.not_free(not_free);
      break;
    default:
      code = "ROUTE-0002", reason = target.name + " cannot be reached from " + point_text(from) +
                                    ": blockages wall one of them in";
      if (!obs.covered.empty()) reason += " (the rectilinear covers of sloped blockages count, ROUTE-0008)";
      break;
  }
  int status = kOk;
  if (p.status == router::WireStatus::Ok) {
    const __int128 cost = p.cost(link ? router::BendMetric::Link : router::BendMetric::Combined, c);
    const auto cost64 = static_cast<std::int64_t>(cost);  // length < 2^62 and C * bends < 2^62 here
    wire_json(j, cost64, p);
    if (!json) {
      std::cout << "cost " << cost64 << " (" << routing.metric;
      if (!link) std::cout << ", bend cost " << c;
      std::cout << "), " << wire_text(p) << '\n';
    }
  } else {
    no_wire_json(j, reason);
    print_usage_error(code, reason);
    status = kIncomplete;
  }
  if (json) std::cout << j.dump() << '\n';
  return status;
}

// --from-file with --metric combined / link: one line (or one JSON record) per source point,
// in the file's order; a source not free or walled in gets its reason, and the exit status 1.
int bend_paths_to(const io::Layout& layout, const RoutingOptions& routing, const std::vector<geom::Point>& from,
                  Target target, const std::vector<std::string>& to_pin, bool json, bool quiet) {
  const bool link = routing.metric == "link";
  const std::int64_t c = link ? 0 : routing_bend_cost(routing, layout);
  std::vector<geom::Point> ends = from;
  for (const geom::Point v : target.vertices()) ends.push_back(v);
  const BendObstacles obs = bend_obstacles(layout, ends, routing.metric, quiet,
                                           static_cast<int>(routing.cover_pieces.value_or(router::kDefaultCoverPieces)));
  const router::BendRouter router(obs.norm.domain, obs.norm.obstacles);
  const router::BendMetric metric = link ? router::BendMetric::Link : router::BendMetric::Combined;
  nlohmann::ordered_json j;
  j["metric"] = routing.metric;
  if (!link) j["bend_cost"] = c;
  if (to_pin.empty()) j["to"] = {target.point->x, target.point->y};
  else j["to_pin"] = {{"net", to_pin[0]}, {"pin", to_pin[1]}};
  const auto reach = reach_of(target, obs.norm.obstacles, [&] { return obs.why_under(layout, target.pin); });
  if (const std::string* refused = std::get_if<std::string>(&reach)) {  // no structure: every record says why
    print_usage_error("ROUTE-0005", *refused);
    auto paths = nlohmann::ordered_json::array();
    for (const geom::Point q : from) {
      nlohmann::ordered_json r;
      r["from"] = {q.x, q.y};
      no_wire_json(r, *refused);
      paths.push_back(std::move(r));
      if (!json) std::cout << point_text(q) << ": no wire (ROUTE-0005)\n";
    }
    j["paths"] = std::move(paths);
    if (json) std::cout << j.dump() << '\n';
    return kIncomplete;
  }
  const router::BendTargetMap map(router, std::get<geom::Polygon>(reach), metric, c);
  auto paths = nlohmann::ordered_json::array();
  int status = kOk;
  auto why = [&](geom::Point q) { return obs.why_not_free(layout, q); };
  if (map.status() != router::WireStatus::Ok) {
    print_usage_error("ROUTE-0001", target.not_free(why));
    status = kIncomplete;
  }
  for (const geom::Point q : from) {
    nlohmann::ordered_json r;
    r["from"] = {q.x, q.y};
    const router::BendPath p = map.status() == router::WireStatus::Ok ? map.path(q) : router::BendPath{};
    if (map.status() == router::WireStatus::Ok && p.status == router::WireStatus::Ok) {
      const auto cost = static_cast<std::int64_t>(p.cost(metric, c));
      wire_json(r, cost, p);
      if (!json) std::cout << point_text(q) << ": cost " << cost << ", " << wire_text(p) << '\n';
    } else {
      std::string code = "ROUTE-0001", reason;
      if (map.status() != router::WireStatus::Ok) {
        reason = target.not_free(why);
      } else if (p.status == router::WireStatus::SourceNotFree) {
        reason = point_text(q) + " " + obs.why_not_free(layout, q);
      } else {
        code = "ROUTE-0002";
        reason = target.name + " cannot be reached from " + point_text(q) + ": blockages wall one of them in";
      }
      no_wire_json(r, reason);
      if (map.status() == router::WireStatus::Ok) print_usage_error(code, reason);
      if (!json) std::cout << point_text(q) << ": no wire (" << code << ")\n";
      status = kIncomplete;
    }
    paths.push_back(std::move(r));
  }
  j["paths"] = std::move(paths);
  if (json) std::cout << j.dump() << '\n';
  return status;
}

}  // namespace

void add_path(CLI::App& app, int& status) {
  struct Args {
    std::string file, from, to, from_file;
    std::vector<std::string> to_pin;
    bool json = false;
    RoutingOptions routing;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("path", "One shortest wire between two points among the blockages");
  sub->add_option("--from", args->from, "start point X,Y");
  sub->add_option("--from-file", args->from_file,
                  "many start points to the one --to (one X,Y per line; blank lines and # comments skipped), "
                  "--metric combined or link: the best wire from each, from one structure for the target");
  sub->add_option("--to", args->to, "end point X,Y");
  sub->add_option("--to-pin", args->to_pin,
                  "end on a pin of the layout instead (NET PIN: a point, or anywhere on a shape)")
      ->expected(2);
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  add_routing_options(sub, args->routing);
  args->routing.allow_bends = true;
  add_input_options(sub, args->file, args->load, "do not print warnings");
  sub->callback([args, &status] {
    if (args->from.empty() == args->from_file.empty()) {
      print_usage_error("CLI-0022", "give --from X,Y or --from-file F (one of them)");
      status = kInvalid;
      return;
    }
    if (args->to.empty() && args->to_pin.empty()) {  // a missing option, as CLI11 reports one
      print_usage_error("CLI-0001", "--to X,Y or --to-pin NET PIN is required");
      status = kInvalid;
      return;
    }
    if (!args->to.empty() && !args->to_pin.empty()) {
      print_usage_error("CLI-0022", "give --to X,Y or --to-pin NET PIN, not both");
      status = kInvalid;
      return;
    }
    const bool many = !args->from_file.empty();
    if (many && args->routing.metric == "l1") {
      print_usage_error("CLI-0020", "--from-file takes --metric combined or link (for L1 distances from many "
                                    "points to one, taut spm --source TARGET --query-file F)");
      status = kInvalid;
      return;
    }
    std::vector<geom::Point> sources;
    const auto from = many ? std::optional<geom::Point>(geom::Point{}) : parse_point_option("--from", args->from);
    const bool by_pin = !args->to_pin.empty();
    const auto to = !from ? std::nullopt : by_pin ? std::optional<geom::Point>(geom::Point{}) : parse_point_option("--to", args->to);
    const auto layout = from && to && (!many || read_point_file(args->from_file, sources))
                            ? load_routing_layout(args->file, args->load, args->routing)
                            : std::nullopt;
    if (!layout) {
      status = kInvalid;
      return;
    }
    std::optional<Target> target;
    if (by_pin) {
      target = pin_target(*layout, args->to_pin[0], args->to_pin[1]);
    } else {
      target = Target{geom::Polygon{{*to}, {}}, *to, "--to " + point_text(*to), point_text(*to)};
    }
    if (!target) {
      status = kInvalid;
      return;
    }
    if (many) {
      status = bend_paths_to(*layout, args->routing, sources, *target, args->to_pin, args->json, args->load.quiet);
      return;
    }
    if (args->routing.metric != "l1") {
      status = bend_path(*layout, args->routing, *from, *target, args->json, args->load.quiet);
      return;
    }
    std::vector<geom::Point> ends = target->vertices();
    ends.push_back(*from);
    const geom::NormalizedObstacles norm = routing_obstacles(*layout, ends);
    const bool oct = routing_orientations(args->routing, *layout) == "octilinear";
    // One wire record for both orientations: the length exactly as a + b*sqrt2 (b = 0 for L1).
    router::BasicWire<geom::Root2> w;
    const geom::Polygon from_pin{{*from}, {}};
    auto refuse = [&](const std::string& reason) {
      print_usage_error("ROUTE-0005", reason);
      if (args->json) {
        nlohmann::ordered_json j;
        j["metric"] = "l1";
        if (oct) j["orientations"] = "octilinear";
        no_wire_json(j, reason);
        std::cout << j.dump() << '\n';
      }
      status = kIncomplete;
    };
    const std::string under = std::string("lies partly under a blockage") + kNothingOutside;  // (no other nets here)
    if (oct) {
      router::OctRouter r(norm.domain, norm.obstacles);
      const auto reach = reach_of(*target, norm.obstacles, [&] { return under; });
      if (const std::string* refused = std::get_if<std::string>(&reach)) return refuse(*refused);
      w = target->point ? r.shortest(*from, *target->point) : r.shortest(from_pin, std::get<geom::Polygon>(reach));
    } else {
      router::L1Router r(norm.domain, norm.obstacles);
      const auto reach = reach_of(*target, norm.obstacles, [&] { return under; });
      if (const std::string* refused = std::get_if<std::string>(&reach)) return refuse(*refused);
      router::L1Wire l = target->point ? r.shortest(*from, *target->point) : r.shortest(from_pin, std::get<geom::Polygon>(reach));
      w = {l.status, std::nullopt, std::move(l.polygonal), std::move(l.points)};
      if (l.length) w.length = geom::Root2{*l.length, 0};
    }
    const char* metric_word = oct ? "octilinear" : "L1";
    // JSON: an integer when b = 0, else a number with 17 significant digits (CLI.md: at least 9)
    auto length_json = [](const geom::Root2& r) -> nlohmann::ordered_json {
      if (r.b == 0) return r.a;
      return r.to_double();
    };

    nlohmann::ordered_json j;
    j["metric"] = "l1";
    if (oct) j["orientations"] = "octilinear";
    std::string code, reason;
    switch (w.status) {
      case router::WireStatus::Ok: break;
      case router::WireStatus::SourceNotFree:
        code = "ROUTE-0001", reason = "--from " + point_text(*from) + " " + why_not_free(*layout, *from);
        break;
      case router::WireStatus::TargetNotFree:
        code = "ROUTE-0001", reason = target->not_free([&](geom::Point q) { return why_not_free(*layout, q); });
        break;
      case router::WireStatus::Unreachable:
        code = "ROUTE-0002", reason = target->name + " cannot be reached from " + point_text(*from) +
                                      ": blockages wall one of them in";
        break;
      case router::WireStatus::NoIntegerStaircase:
        code = "ROUTE-0003",
        reason = std::string("the shortest ") + metric_word + " length is " + length_text(*w.length) +
                 ", but no " + (oct ? "octilinear" : "rectilinear") +
                 " wire with integer vertices has that length here (sloped blockages pinch every "
                 "lattice staircase of the shortest path)";
        break;
    }
    if (w.status == router::WireStatus::Ok) {
      const long bends = geom::count_bends(w.points);
      j["cost"] = length_json(*w.length);
      j["length"] = length_json(*w.length);
      if (oct) j["length_exact"] = {w.length->a, w.length->b};
      j["bends"] = bends;
      auto pts = nlohmann::ordered_json::array();
      for (const geom::Point p : w.points) pts.push_back({p.x, p.y});
      j["points"] = pts;
      status = kOk;
      if (!args->json) {
        std::cout << "cost " << length_text(*w.length) << (oct ? " (octilinear)" : " (l1)")
                  << ", length " << length_text(*w.length) << ", " << bends
                  << (bends == 1 ? " bend:" : " bends:");
        for (const geom::Point p : w.points) std::cout << ' ' << point_text(p);
        std::cout << '\n';
      }
    } else {
      no_wire_json(j, reason);
      if (w.status == router::WireStatus::NoIntegerStaircase) {
        j[oct ? "octilinear_distance" : "l1_distance"] = length_json(*w.length);
        if (oct) j["length_exact"] = {w.length->a, w.length->b};
        auto poly = nlohmann::ordered_json::array();
        for (const geom::Point p : w.polygonal) poly.push_back({p.x, p.y});
        j["polygonal"] = poly;
      }
      print_usage_error(code, reason);
      status = kIncomplete;
    }
    if (args->json) std::cout << j.dump() << '\n';
  });
}

}  // namespace taut::cli
