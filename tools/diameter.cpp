// taut diameter FILE [--json] [--svg PIC] [--method auto|bounds|cut-tree|approx]: the rectilinear link diameter of a layout
// whose free space is one simple rectilinear polygon (de Berg, seeds/002): the most links (axis-parallel
// segments) a wire between two points of free space can need, the two points, and such a wire
// (fewest links, L1-shortest); with approx, only an estimate within 3 links (section 4.2).
#include <cstdint>
#include <iostream>

#include <nlohmann/json.hpp>

#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "io/svg.h"
#include "router/link_approx.h"
#include "router/link_polygon.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {

namespace {

Diagnostic diameter_error(const io::Layout& layout, const std::string& code, int line, const std::string& message) {
  return Diagnostic{Severity::Error, code, layout.file, line, 0, message};
}

// The free space of the layout as a simple rectilinear polygon; prints why not (exit 2).
std::optional<geom::Ring> diameter_free_space(const io::Layout& layout) {
  if (!layout.boundary) {
    print_diagnostics({diameter_error(layout, "DIAM-0001", layout.line,
                             "the layout has no <boundary>: free space is unbounded and has no link diameter")});
    return std::nullopt;
  }
  std::vector<std::size_t> owner;
  const std::vector<geom::Polygon> polys = io::blockage_polygons(layout, &owner);
  const router::FreeSpacePolygon f = router::free_space_polygon(layout.boundary->box, polys);
  using S = router::FreeSpacePolygon::Status;
  auto shape_index = [&](std::size_t i) {  // the polygon's shape within its blockage
    std::size_t first = i;
    while (first > 0 && owner[first - 1] == owner[i]) --first;
    return i - first;
  };
  switch (f.status) {
    case S::Ok: return f.ring;
    case S::Sloped: {
      const io::Blockage& b = layout.blockages[owner[f.blockage]];
      const io::Shape& shape = b.shapes[shape_index(f.blockage)];
      const int line = f.sloped_ring >= 0 && static_cast<std::size_t>(f.sloped_ring) < shape.hole_lines.size()
                           ? shape.hole_lines[static_cast<std::size_t>(f.sloped_ring)]
                           : shape.line;
      print_diagnostics({diameter_error(
          layout, "DIAM-0002", line,
          "blockage \"" + b.id + "\" gives free space an edge that is neither horizontal nor vertical (at " +
              point_text(f.at) + "): the link diameter is defined for rectilinear free space")});
      return std::nullopt;
    }
    case S::Island: {
      const io::Blockage& b = layout.blockages[owner[f.blockage]];
      print_diagnostics({diameter_error(
          layout, "DIAM-0003", b.shapes[shape_index(f.blockage)].line,
          std::string(b.shapes.size() > 1 ? "a shape of blockage \"" : "blockage \"") + b.id +
              "\" does not reach the boundary (nor does a blockage touching it): free space has a hole around it, "
              "and the link diameter needs a simple polygon")});
      return std::nullopt;
    }
    case S::Pieces: {
      std::string at;
      for (std::size_t k = 0; k < f.pieces.size() && k < 4; ++k) at += (k ? ", " : "") + point_text(f.pieces[k]);
      if (f.pieces.size() > 4) at += ", ...";
      const std::string what = f.pieces.size() == 1
                                   ? "free space touches itself at " + at + ", where blockages meet"
                                   : "free space falls into " + std::to_string(f.pieces.size()) +
                                         " pieces (their lowest vertices: " + at + ")";
      print_diagnostics({diameter_error(layout, "DIAM-0004", layout.boundary->line,
                               what + ": the link diameter needs one simple polygon")});
      return std::nullopt;
    }
    case S::Empty:
      print_diagnostics({diameter_error(layout, "DIAM-0005", layout.boundary->line,
                               "the blockages cover the whole boundary: there is no free space")});
      return std::nullopt;
  }
  return std::nullopt;
}

std::size_t convex_count(const geom::Ring& ring) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    k += geom::orientation(ring[(i + ring.size() - 1) % ring.size()], ring[i], ring[(i + 1) % ring.size()]) > 0;
  return k;
}

// --method approx: de Berg's MAXDIST (router/link_approx.h), no wire and no pair of points.
template <class Args>
int print_estimate(const io::Layout& layout, const geom::Ring& ring, const Args& args) {
  const router::LinkDiameterEstimate e = router::approximate_link_diameter(ring);
  const std::string range = "[" + std::to_string(e.lo) + ", " + std::to_string(e.hi) + "]";
  if (!args.svg.empty()) {
    io::SvgOptions so;
    so.caption = "link diameter " + range + " (estimate " + std::to_string(e.estimate) + ", within 3)";
    if (!write_output(args.svg, io::layout_to_svg(layout, so))) return kInvalid;
  }
  if (args.json) {
    nlohmann::ordered_json j;
    j["metric"] = "link";
    j["method"] = "approx";
    j["estimate"] = e.estimate;
    j["bounds"] = {e.lo, e.hi};
    j["vertices"] = ring.size();
    j["convex_vertices"] = convex_count(ring);
    j["cells"] = e.cells;
    std::cout << j.dump() << '\n';
  } else {
    std::cout << "link diameter " << range << ": de Berg's estimate " << e.estimate
              << ", within 3 links (no wire: use --method auto for the exact diameter and a wire)\n"
              << "free space: a simple rectilinear polygon of " << ring.size() << " vertices (" << convex_count(ring)
              << " convex), " << e.cells << " cells in its horizontal decomposition\n";
  }
  return kOk;
}

}  // namespace

void add_diameter(CLI::App& app, int& status) {
  struct Args {
    std::string file, svg, method = "auto";
    bool json = false;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "diameter",
      "Rectilinear link diameter of a layout whose free space (boundary minus blockages) is one simple "
      "rectilinear polygon: the most links a wire between two free points can need (nets are not used)");
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  sub->add_option("--svg", args->svg, "also draw the layout with the diameter's wire");
  sub->add_option("--method", args->method,
                  "auto (default: link searches pruned by eccentricity bounds, de Berg's divide and conquer once 32 "
                  "searches have not settled it), bounds (the searches only), cut-tree (the divide and conquer only) or "
                  "approx (de Berg's estimate within 3 links, one sweep: for polygons too large for the others)");
  add_input_options(sub, args->file, args->load, "do not print warnings");
  sub->callback([args, &status] {
    const std::size_t budget = args->method == "auto" ? 32 : args->method == "bounds" ? SIZE_MAX : 0;
    if (args->method != "auto" && args->method != "bounds" && args->method != "cut-tree" && args->method != "approx") {
      print_usage_error("CLI-0029", "diameter: --method " + args->method + ": use auto, bounds, cut-tree or approx");
      status = kInvalid;
      return;
    }
    const auto layout = load_layout(args->file, args->load);
    if (!layout) {
      status = kInvalid;
      return;
    }
    const std::optional<geom::Ring> ring = diameter_free_space(*layout);
    if (!ring) {
      status = kInvalid;
      return;
    }
    if (args->method == "approx") {
      status = print_estimate(*layout, *ring, *args);
      return;
    }
    const router::LinkPolygon poly(*ring);
    const router::LinkDiameter d = poly.diameter(budget);
    const int bends = d.links - 1;
    if (!args->svg.empty()) {
      io::SvgOptions so;
      std::string pts;
      for (const geom::Point p : d.path.points) pts += (pts.empty() ? "" : " ") + point_text(p);
      so.overlay += "<polyline class=\"diameter\" points=\"" + pts +
                    "\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"@2.5\"/>\n";
      for (const geom::Point p : {d.from, d.to})
        so.overlay += "<circle class=\"diameter-end\" cx=\"" + std::to_string(p.x) + "\" cy=\"" + std::to_string(p.y) +
                      "\" r=\"@5\" fill=\"#c0392b\"/>\n";
      so.caption = "link diameter " + std::to_string(d.links) + " (red: a wire with that many links)";
      if (!write_output(args->svg, io::layout_to_svg(*layout, so))) {
        status = kInvalid;
        return;
      }
    }
    if (args->json) {
      nlohmann::ordered_json j;
      j["metric"] = "link";
      j["diameter"] = d.links;
      j["bends"] = bends;
      j["from"] = {d.from.x, d.from.y};
      j["to"] = {d.to.x, d.to.y};
      j["length"] = d.path.length;
      auto pts = nlohmann::ordered_json::array();
      for (const geom::Point q : d.path.points) pts.push_back({q.x, q.y});
      j["points"] = pts;
      j["vertices"] = d.vertices;
      j["convex_vertices"] = d.convex_vertices;
      j["method"] = d.cut_tree ? "cut-tree" : "bounds";
      j["searches"] = d.searches;
      std::cout << j.dump() << '\n';
    } else {
      std::cout << "link diameter " << d.links << " (" << bends << (bends == 1 ? " bend" : " bends") << "), from "
                << point_text(d.from) << " to " << point_text(d.to) << "; a wire of length " << d.path.length << ":";
      for (const geom::Point q : d.path.points) std::cout << ' ' << point_text(q);
      std::cout << "\nfree space: a simple rectilinear polygon of " << d.vertices << " vertices ("
                << d.convex_vertices << " convex); found by "
                << (d.cut_tree ? "de Berg's divide and conquer on the cut tree (after " + std::to_string(d.searches) + " searches)"
                               : std::to_string(d.searches) + " link searches pruned by eccentricity bounds")
                << "\n";
    }
    status = kOk;
  });
}

}  // namespace taut::cli
