// taut check FILE [--json]: validates a layout (syntax, geometry, names, pins) and reports what
// the geometry pipeline makes of it.
#include <chrono>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "geom/directions.h"
#include "geom/root3_directions.h"
#include "geom/normalize.h"
#include "geom/triangulation.h"
#include "io/layout_geometry.h"
#include "io/stats_json.h"
#include "router/check.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {
namespace {

nlohmann::ordered_json diagnostics_json(const std::vector<Diagnostic>& ds) {
  auto arr = nlohmann::ordered_json::array();
  for (const auto& d : ds) {
    arr.push_back({{"severity", d.severity == Severity::Error ? "error" : "warning"},
                   {"code", d.code},
                   {"file", d.file},
                   {"line", d.line},
                   {"column", d.column},
                   {"message", d.message}});
  }
  return arr;
}

// The independent part (router/check.h): free space, connectivity, shorts, clearance. Adds a
// diagnostic per problem (CHECK-0003 ... 0008) and returns the counts per kind.
struct RouteProblems {
  int not_free = 0, disconnected = 0, stray = 0, shorts = 0, blockage_clearance = 0, net_clearance = 0;
  std::size_t wires = 0;
  int total() const { return not_free + disconnected + stray + shorts + blockage_clearance + net_clearance; }
};
RouteProblems check_independently(const io::Layout& layout, const std::string& file, const geom::NormalizedObstacles& bounded,
                                  std::vector<Diagnostic>& diags) {
  std::vector<router::CheckNet> nets;
  std::vector<geom::Point> wire_points;
  std::map<std::string, const io::Route*> by_net;
  for (const io::Route& r : layout.routes->routes) by_net.emplace(r.net, &r);
  for (const io::Net& n : layout.nets) {
    router::CheckNet c = check_net(n);
    const auto it = by_net.find(n.name);
    if (it != by_net.end() && it->second->status == "routed") {
      c.routed = true;
      c.line = it->second->line;
      for (const io::Wire& w : it->second->wires) {
        c.wires.push_back({w.points, w.line});
        wire_points.insert(wire_points.end(), w.points.begin(), w.points.end());
      }
    }
    nets.push_back(std::move(c));
  }
  // Without a <boundary> the plane is unbounded: the domain only has to hold every wire.
  std::vector<std::size_t> owner;
  const auto polys = io::blockage_polygons(layout, &owner);
  const geom::NormalizedObstacles norm =
      layout.boundary ? bounded : geom::normalize_obstacles(polys, io::routing_domain(layout, wire_points));
  router::CheckRules rules;
  if (layout.rules) {
    rules.wire_width = layout.rules->wire_width;
    rules.spacing = layout.rules->spacing;
  }
  const router::CheckResult result = router::check_routes(norm, nets, rules);
  RouteProblems counts;
  counts.wires = result.wires;
  for (const router::CheckProblem& p : result.problems) {
    std::string code, message = p.message;
    switch (p.kind) {
      case router::CheckProblem::Kind::NotFree:
      case router::CheckProblem::Kind::BlockageClearance:
        code = p.kind == router::CheckProblem::Kind::NotFree ? "CHECK-0003" : "CHECK-0007";
        ++(p.kind == router::CheckProblem::Kind::NotFree ? counts.not_free : counts.blockage_clearance);
        if (p.obstacle && *p.obstacle < norm.sources.size()) {
          std::string ids;
          for (const std::size_t src : norm.sources[*p.obstacle]) {
            const std::string& id = layout.blockages[owner[src]].id;
            if (ids.find("\"" + id + "\"") == std::string::npos) ids += (ids.empty() ? "\"" : ", \"") + id + "\"";
          }
          message += " (blockage " + ids + ")";
        }
        break;
      case router::CheckProblem::Kind::Disconnected:
        code = "CHECK-0004";
        ++counts.disconnected;
        break;
      case router::CheckProblem::Kind::StrayWire:
        code = "CHECK-0005";
        ++counts.stray;
        break;
      case router::CheckProblem::Kind::Short:
        code = "CHECK-0006";
        ++counts.shorts;
        break;
      case router::CheckProblem::Kind::NetClearance:
        code = "CHECK-0008";
        ++counts.net_clearance;
        break;
    }
    Diagnostic d{Severity::Error, code, file, p.line, 0, message};
    diags.push_back(d);
    std::cerr << format(d) << '\n';
  }
  return counts;
}

}  // namespace

void add_check(CLI::App& app, int& status) {
  struct Args {
    std::string file;
    bool json = false;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("check", "Validate a layout (and check its routes)");
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  add_input_options(sub, args->file, args->load, "do not print warnings or the summary");
  sub->callback([args, &status] {
    std::vector<Diagnostic> diags;
    auto layout = load_layout(args->file, args->load, &diags);
    int errors = 0, warnings = 0;
    for (const auto& d : diags) (d.severity == Severity::Error ? errors : warnings)++;
    nlohmann::ordered_json j;
    j["file"] = args->file;
    j["valid"] = layout.has_value();
    j["errors"] = errors;
    j["warnings"] = warnings;
    j["diagnostics"] = diagnostics_json(diags);
    if (layout) {
      std::size_t pins = 0;
      for (const auto& n : layout->nets) pins += n.pins.size();
      j["layout"] = {{"name", layout->name},
                     {"blockages", layout->blockages.size()},
                     {"blockage_vertices", io::blockage_vertex_count(*layout)},
                     {"nets", layout->nets.size()},
                     {"pins", pins},
                     {"routes", layout->routes ? layout->routes->routes.size() : 0}};
    }
    status = layout ? kOk : kInvalid;
    if (layout) {
      // The geometry pipeline every router runs: union of the blockages, then free space.
      using Clock = std::chrono::steady_clock;
      auto t0 = Clock::now();
      std::optional<geom::Box> boundary;
      if (layout->boundary) boundary = layout->boundary->box;
      const auto polys = io::blockage_polygons(*layout);
      const geom::NormalizedObstacles norm = geom::normalize_obstacles(polys, boundary);
      auto t1 = Clock::now();
      std::size_t obstacle_vertices = 0, holes = 0;
      for (const auto& o : norm.obstacles) {
        obstacle_vertices += o.outer.size();
        holes += o.holes.size();
        for (const auto& h : o.holes) obstacle_vertices += h.size();
      }
      j["obstacles"] = {{"count", norm.obstacles.size()},
                        {"vertices", obstacle_vertices},
                        {"holes", holes},
                        {"merged", norm.stats.merges},
                        {"crossings", norm.stats.crossings},
                        {"rounded", norm.stats.rounded},
                        {"removed_repeated", norm.stats.removed_repeated},
                        {"removed_collinear", norm.stats.removed_collinear},
                        {"domain", {norm.domain.lo.x, norm.domain.lo.y, norm.domain.hi.x, norm.domain.hi.y}}};
      const bool has_area = norm.domain.lo.x < norm.domain.hi.x && norm.domain.lo.y < norm.domain.hi.y;
      std::size_t triangles = 0;
      if (has_area) {
        const geom::FreeSpaceTriangulation tri = geom::triangulate_free_space(norm.domain, norm.obstacles);
        if (!tri.ok()) {
          // The union's output always meets the triangulation's contract: this is a bug.
          for (const auto& d : tri.diagnostics()) std::cerr << args->file << ": internal error: " << format(d) << '\n';
          status = kInternal;
          return;
        }
        triangles = tri.triangles().size();
      }
      auto t2 = Clock::now();
      if (layout->routes) {
        // The length and bends written for each routed net equal those recomputed from its
        // wires, and with <routes orientations="rectilinear">, "octilinear" or another lattice c:
        // set (geom/directions.h) every wire segment runs in those directions, and with a c: set
        // at multiples of 30 degrees such as c:0,60,120 (geom/root3_directions.h, since
        // 2026-12-07) in them within the rounding of its ends (CHECK-0002, the first offending
        // segment of each route); then
        // the independent checker (router/check.h): free space, connectivity, shorts and the
        // clearance of <rules>.
        int mismatches = 0, off_orientation = 0, failed_with_wires = 0;
        const std::string& orientations = layout->routes->orientations;
        // rectilinear, octilinear and the other lattice c: sets (multiples of 45 degrees)
        const std::optional<geom::LatticeDirections> set = geom::LatticeDirections::parse(orientations);
        // c:0,60,120 and the other sets at multiples of 30 degrees: integer vertices cannot follow
        // them exactly, so within the rounding of each end (half a unit in x and y)
        // (and since the twenty-first session, the same day, any other c: set, each direction at
        // its step: Root3Directions::parse_any)
        const std::optional<geom::Root3Directions> set30 = set ? std::nullopt : geom::Root3Directions::parse_any(orientations);
        const bool check_directions = set || set30;
        std::string set_words;  // "horizontal or vertical", "at 0, 45, 90 or 135 degrees", ...
        if (set && set->is_rectilinear()) {
          set_words = "horizontal or vertical";
        } else if (check_directions) {
          std::vector<std::string> deg;
          if (set)
            for (const int d : set->degrees()) deg.push_back(std::to_string(d));
          else
            deg = set30->orientation_texts();
          set_words = "at ";
          for (std::size_t k = 0; k < deg.size(); ++k)
            set_words += (k == 0 ? "" : k + 1 == deg.size() ? " or " : ", ") + deg[k];
          set_words += " degrees";
          if (set30) {
            set_words += " within the rounding of its ends (half a unit in x and in y each)";
            for (const RealizedStep& r : realized_steps(*set30)) set_words += ", " + r.phrase();  // judged against its step
          }
        }
        for (const io::Route& r : layout->routes->routes) {
          if (r.status != "routed") {
            // FORMAT.md: a failed route gives a reason and no wires; wires kept on one are checked
            // by nothing below (neither free space nor clearance), so the file is refused
            // (CHECK-0009; since 2026-12-06: before, taut check passed such a file whatever the
            // wires were, one inside a blockage included; found by fuzzing hand-edited routes)
            if (!r.wires.empty()) {
              ++failed_with_wires;
              Diagnostic d{Severity::Error, "CHECK-0009", args->file, r.line, 0,
                           "route \"" + r.net + "\": status is " + r.status + " but it has " + std::to_string(r.wires.size()) +
                               " <wire>" + (r.wires.size() == 1 ? "" : "s") +
                               " (first at line " + std::to_string(r.wires[0].line) +
                               "): a failed route has none; write status=\"routed\" to have them checked, or remove them"};
              diags.push_back(d);
              std::cerr << format(d) << '\n';
            }
            continue;
          }
          std::vector<std::vector<geom::Point>> wires;
          long bends = 0;
          for (const io::Wire& w : r.wires) {
            wires.push_back(w.points);
            bends += io::count_bends(w.points);
          }
          const std::string length = io::format_total_length(wires);
          auto mismatch = [&](const std::string& what, const std::string& written, const std::string& actual) {
            ++mismatches;
            Diagnostic d{Severity::Error, "CHECK-0001", args->file, r.line, 0,
                         "route \"" + r.net + "\": " + what + " is written as " + written +
                             " but the wires give " + actual};
            diags.push_back(d);
            std::cerr << format(d) << '\n';
          };
          if (r.length && *r.length != length) mismatch("length", *r.length, length);
          if (r.bends && *r.bends != bends) mismatch("bends", std::to_string(*r.bends), std::to_string(bends));
          if (!check_directions) continue;
          bool reported = false;
          for (const io::Wire& w : r.wires)
            for (std::size_t i = 1; i < w.points.size() && !reported; ++i) {
              const geom::Point a = w.points[i - 1], b = w.points[i];
              const std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
              if (dx == 0 && dy == 0) continue;
              if (set ? set->along(dx, dy) : set30->fits(dx, dy)) continue;
              reported = true;
              ++off_orientation;
              Diagnostic d{Severity::Error, "CHECK-0002", args->file, r.line, 0,
                           "route \"" + r.net + "\": the wire segment " + std::to_string(a.x) + "," +
                               std::to_string(a.y) + " " + std::to_string(b.x) + "," + std::to_string(b.y) +
                               " is not " + set_words +
                               " (<routes orientations=\"" + orientations + "\">)"};
              diags.push_back(d);
              std::cerr << format(d) << '\n';
            }
        }
        const RouteProblems rp = check_independently(*layout, args->file, norm, diags);
        auto verdict = [](int n) { return n == 0 ? "ok" : "failed"; };
        j["routes_check"] = {{"lengths_and_bends", mismatches == 0 ? "ok" : "failed"},
                             {"mismatches", mismatches},
                             {"failed_with_wires", failed_with_wires},
                             {"orientations", !check_directions        ? "not checked"
                                              : off_orientation == 0 ? "ok"
                                                                     : "failed"},
                             {"free_space", verdict(rp.not_free)},
                             {"connectivity", verdict(rp.disconnected + rp.stray)},
                             {"shorts", verdict(rp.shorts)},
                             {"clearance", !layout->rules || (layout->rules->wire_width == 0 && layout->rules->spacing == 0)
                                               ? "not required"
                                               : verdict(rp.blockage_clearance + rp.net_clearance)},
                             {"problems", {{"not_free", rp.not_free},
                                           {"disconnected_pins", rp.disconnected},
                                           {"stray_wires", rp.stray},
                                           {"shorts", rp.shorts},
                                           {"blockage_clearance", rp.blockage_clearance},
                                           {"net_clearance", rp.net_clearance}}},
                             {"wires", rp.wires}};
        j["diagnostics"] = diagnostics_json(diags);
        j["errors"] = errors + mismatches + off_orientation + failed_with_wires + rp.total();
        if (mismatches || off_orientation || failed_with_wires || rp.total()) status = kIncomplete;
      }
      j["free_space"] = {{"triangles", triangles}};
      j["seconds"] = {{"normalize", std::chrono::duration<double>(t1 - t0).count()},
                      {"triangulate", std::chrono::duration<double>(t2 - t1).count()}};
    }
    if (args->json) {
      std::cout << j.dump(2) << '\n';
    } else if (layout && !args->load.quiet) {
      const auto& l = j["layout"];
      std::cout << args->file << (status == kOk ? ": ok: " : ": FAILED: ") << l["blockages"] << " blockages ("
                << l["blockage_vertices"] << " vertices), " << l["nets"] << " nets, "
                << l["pins"] << " pins; " << j["obstacles"]["count"] << " obstacles after union ("
                << j["obstacles"]["merged"] << " merged, " << j["obstacles"]["rounded"]
                << " rounded crossings), " << j["free_space"]["triangles"] << " free-space triangles";
      if (warnings) std::cout << ", " << warnings << " warning(s)";
      std::cout << '\n';
      if (j.contains("routes_check"))
        std::cout << args->file << ": routes: lengths and bends "
                  << j["routes_check"]["lengths_and_bends"].get<std::string>() << "; "
                  << (j["routes_check"]["orientations"] == "not checked"
                          ? std::string("orientations not checked")
                          : layout->routes->orientations + " orientations " +
                                j["routes_check"]["orientations"].get<std::string>())
                  << "; free space " << j["routes_check"]["free_space"].get<std::string>() << "; connectivity "
                  << j["routes_check"]["connectivity"].get<std::string>() << "; shorts between nets "
                  << (j["routes_check"]["shorts"] == "ok" ? std::string("none") : std::string("found"))
                  << "; clearance " << j["routes_check"]["clearance"].get<std::string>()
                  << (j["routes_check"]["failed_with_wires"].get<int>() > 0
                          ? "; failed routes with wires: " + std::to_string(j["routes_check"]["failed_with_wires"].get<int>())
                          : std::string())
                  << "\n";
    }
  });
}

}  // namespace taut::cli
