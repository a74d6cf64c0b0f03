// taut path FILE --from X,Y --to X,Y [--orientations rectilinear|octilinear] [--json]: one exact
// shortest wire among the layout's blockages (rectilinear: L1 length; octilinear: the length
// a + b*sqrt2 of the shortest path in 0/45/90/135 degrees), with integer vertices; its cost,
// length, bends, points.
#include <iostream>

#include <nlohmann/json.hpp>

#include "geom/predicates.h"
#include "router/l1_router.h"
#include "router/oct_router.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {

void add_path(CLI::App& app, int& status) {
  struct Args {
    std::string file, from, to;
    bool json = false;
    RoutingOptions routing;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("path", "One shortest wire between two points among the blockages");
  sub->add_option("--from", args->from, "start point X,Y")->required();
  sub->add_option("--to", args->to, "end point X,Y")->required();
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  add_routing_options(sub, args->routing);
  add_input_options(sub, args->file, args->load, "do not print warnings");
  sub->callback([args, &status] {
    const auto from = parse_point_option("--from", args->from);
    const auto to = from ? parse_point_option("--to", args->to) : std::nullopt;
    if (!from || !to) {
      status = kInvalid;
      return;
    }
    const auto layout = load_routing_layout(args->file, args->load, args->routing);
    if (!layout) {
      status = kInvalid;
      return;
    }
    const geom::Point ends[2] = {*from, *to};
    const geom::NormalizedObstacles norm = routing_obstacles(*layout, ends);
    const bool oct = routing_orientations(args->routing, *layout) == "octilinear";
    // One wire record for both orientations: the length exactly as a + b*sqrt2 (b = 0 for L1).
    router::BasicWire<geom::Root2> w;
    if (oct) {
      w = router::OctRouter(norm.domain, norm.obstacles).shortest(*from, *to);
    } else {
      router::L1Wire l = router::L1Router(norm.domain, norm.obstacles).shortest(*from, *to);
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
        code = "ROUTE-0001", reason = "--to " + point_text(*to) + " " + why_not_free(*layout, *to);
        break;
      case router::WireStatus::Unreachable:
        code = "ROUTE-0002", reason = point_text(*to) + " cannot be reached from " + point_text(*from) +
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
      j["cost"] = nullptr;
      j["length"] = nullptr;
      j["bends"] = nullptr;
      j["points"] = nlohmann::ordered_json::array();
      j["reason"] = reason;
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
