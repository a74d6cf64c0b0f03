// taut check FILE [--json]: validates a layout (syntax, geometry, names, pins) and reports what
// the geometry pipeline makes of it.
#include <chrono>
#include <iostream>

#include <nlohmann/json.hpp>

#include "geom/normalize.h"
#include "geom/triangulation.h"
#include "io/layout_geometry.h"
#include "io/stats_json.h"
#include "tools/cli.h"
#include "tools/commands.h"

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
        // What can be checked today: the length and bends written for each routed net equal
        // those recomputed from its wires, and with <routes orientations="rectilinear"> or
        // "octilinear" every wire segment runs in those directions (CHECK-0002, the first
        // offending segment of each route). Connectivity and clearance come with the
        // independent checker (router/check, issue #7) and are not claimed here.
        int mismatches = 0, off_orientation = 0;
        const std::string& orientations = layout->routes->orientations;
        const bool check_directions = orientations == "rectilinear" || orientations == "octilinear";
        for (const io::Route& r : layout->routes->routes) {
          if (r.status != "routed") continue;
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
              const bool ok = dx == 0 || dy == 0 || (orientations == "octilinear" && (dx == dy || dx == -dy));
              if (ok) continue;
              reported = true;
              ++off_orientation;
              Diagnostic d{Severity::Error, "CHECK-0002", args->file, r.line, 0,
                           "route \"" + r.net + "\": the wire segment " + std::to_string(a.x) + "," +
                               std::to_string(a.y) + " " + std::to_string(b.x) + "," + std::to_string(b.y) +
                               " is not " + (orientations == "octilinear" ? "at 0, 45, 90 or 135 degrees"
                                                                            : "horizontal or vertical") +
                               " (<routes orientations=\"" + orientations + "\">)"};
              diags.push_back(d);
              std::cerr << format(d) << '\n';
            }
        }
        j["routes_check"] = {{"lengths_and_bends", mismatches == 0 ? "ok" : "failed"},
                             {"mismatches", mismatches},
                             {"orientations", !check_directions        ? "not checked"
                                              : off_orientation == 0 ? "ok"
                                                                     : "failed"},
                             {"connectivity_and_clearance", "not checked yet"}};
        j["diagnostics"] = diagnostics_json(diags);
        j["errors"] = errors + mismatches + off_orientation;
        if (mismatches || off_orientation) status = kIncomplete;
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
                  << "; connectivity and clearance are not checked yet\n";
    }
  });
}

}  // namespace taut::cli
