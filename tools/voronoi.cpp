// taut voronoi FILE [--site X,Y ...] [--site-file F] [-o CELLS.xml] [--svg PIC] [--json]: the L1
// geodesic Voronoi diagram of the sites among the layout's blockages (router/voronoi.h): for
// each site, the free points no other site is nearer to, as polygons with holes and exact
// rational vertices. Sites default to every pin of every net: a point pin is a point site, a
// shape pin a shape site (its whole boundary is at distance 0, and its region holds the shape).
//
// Output: a summary on stdout (or one JSON document with --json), the regions as XML (-o, the
// format is in the README) and a picture (--svg): each site's region shaded in its own colour
// with the bisectors drawn, under the blockages, pins and sites.
#include <cmath>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/layout_geometry.h"
#include "io/svg.h"
#include "io/xml_text.h"
#include "router/spm.h"
#include "router/version.h"
#include "router/voronoi.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {

namespace {

using io::xml_escape;

// "n" or "n/d", exact (GMP's canonical form).
std::string rational_str(const router::Rational& r) { return r.str(); }

std::string ring_points(const std::vector<router::RPoint>& ring) {
  std::string s;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (i) s += ' ';
    s += rational_str(ring[i].x) + "," + rational_str(ring[i].y);
  }
  return s;
}

struct Site {
  geom::Point p;                       // a point site (for a shape: its first vertex)
  std::string net, pin;                // empty for --site / --site-file sites
  int line = 0;                        // the pin's line in the layout file
  std::optional<geom::Polygon> shape;  // a shape pin
};

std::string points_text(const geom::Ring& r) {
  std::string s;
  for (std::size_t i = 0; i < r.size(); ++i) s += (i ? " " : "") + std::to_string(r[i].x) + "," + std::to_string(r[i].y);
  return s;
}

std::string site_name(const Site& s, std::size_t i) {
  return s.net.empty() ? "site " + std::to_string(i) : s.net + "." + s.pin;
}

std::string cells_xml(const io::Layout& layout, const std::vector<Site>& sites,
                      const std::vector<router::VoronoiRegion>& regions) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o << "<voronoi version=\"1\" tool=\"taut " << router::version() << "\" metric=\"l1\" layout=\""
    << xml_escape(layout.name) << "\">\n";
  for (std::size_t i = 0; i < sites.size(); ++i) {
    if (sites[i].shape)
      o << "  <site index=\"" << i << "\" points=\"" << points_text(sites[i].shape->outer) << "\"";
    else
      o << "  <site index=\"" << i << "\" x=\"" << sites[i].p.x << "\" y=\"" << sites[i].p.y << "\"";
    if (!sites[i].net.empty()) o << " net=\"" << xml_escape(sites[i].net) << "\" pin=\"" << xml_escape(sites[i].pin) << "\"";
    o << "/>\n";
  }
  for (const auto& r : regions) {
    o << "  <region site=\"" << r.site << "\" area=\"" << rational_str(r.area) << "\">\n";
    for (const auto& poly : r.polygons) {
      o << "    <polygon points=\"" << ring_points(poly.outer) << "\"";
      if (poly.holes.empty()) {
        o << "/>\n";
        continue;
      }
      o << ">\n";
      for (const auto& h : poly.holes) o << "      <hole points=\"" << ring_points(h) << "\"/>\n";
      o << "    </polygon>\n";
    }
    o << "  </region>\n";
  }
  o << "</voronoi>\n";
  return o.str();
}

// A light colour per site: golden-angle hues, so neighbours in the site list differ.
std::string region_fill(std::size_t i) {
  const int hue = static_cast<int>(std::fmod(static_cast<double>(i) * 137.508, 360.0));
  return "hsl(" + std::to_string(hue) + ",70%,80%)";
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string regions_svg(const std::vector<router::VoronoiRegion>& regions) {
  std::string o = "<g class=\"voronoi\">\n";
  for (const auto& r : regions) {
    std::string d;
    auto ring = [&](const std::vector<router::RPoint>& pts) {
      for (std::size_t i = 0; i < pts.size(); ++i) {
        d += i ? 'L' : 'M';
        d += num(pts[i].x.convert_to<double>()) + " " + num(pts[i].y.convert_to<double>());
      }
      d += 'Z';
    };
    for (const auto& poly : r.polygons) {
      ring(poly.outer);
      for (const auto& h : poly.holes) ring(h);
    }
    // Outer rings run counter-clockwise and holes clockwise, so nonzero filling cuts the holes.
    o += "<path class=\"region\" data-site=\"" + std::to_string(r.site) + "\" d=\"" + d + "\" fill=\"" +
         region_fill(r.site) + "\" fill-rule=\"nonzero\" stroke=\"#2c3e50\" stroke-width=\"@0.9\"/>\n";
  }
  return o + "</g>\n";
}

}  // namespace

void add_voronoi(CLI::App& app, int& status) {
  struct Args {
    std::string file, out, svg, site_file;
    std::vector<std::string> sites;
    bool json = false;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "voronoi", "L1 geodesic Voronoi diagram of sites (default: every pin, points and shapes) among the blockages");
  sub->add_option("--site", args->sites, "a site X,Y (repeat the option for more); default: every pin");
  sub->add_option("--site-file", args->site_file,
                  "more sites: a text file with one X,Y per line (blank lines and # comments skipped)");
  sub->add_option("-o,--output", args->out, "write the regions as XML (exact rational coordinates)");
  sub->add_option("--svg", args->svg, "write a picture of the regions");
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  add_input_options(sub, args->file, args->load, "do not print warnings");
  sub->callback([args, &status, sub] {
    std::vector<Site> sites;
    for (const std::string& text : args->sites) {
      const auto p = parse_point_option("--site", text);
      if (!p) {
        status = kInvalid;
        return;
      }
      sites.push_back({*p, "", "", 0, std::nullopt});
    }
    if (sub->count("--site-file")) {
      if (args->site_file.empty()) {
        print_usage_error("CLI-0001", "--site-file \"\": needs a file name");
        status = kInvalid;
        return;
      }
      std::vector<geom::Point> pts;
      if (!read_point_file(args->site_file, pts)) {
        status = kInvalid;
        return;
      }
      for (geom::Point p : pts) sites.push_back({p, "", "", 0, std::nullopt});
    }
    for (const auto& [name, path] : {std::pair{"-o", &args->out}, std::pair{"--svg", &args->svg}})
      if (sub->count(name) && path->empty()) {
        print_usage_error("CLI-0001", std::string(name) + " \"\": needs a file name");
        status = kInvalid;
        return;
      }
    const auto layout = load_layout(args->file, args->load);
    if (!layout) {
      status = kInvalid;
      return;
    }
    const bool from_pins = sites.empty();
    if (from_pins) {
      for (const io::Net& n : layout->nets)
        for (const io::Pin& p : n.pins) {
          if (p.point) {
            sites.push_back({*p.point, n.name, p.name, p.line, std::nullopt});
          } else {
            geom::Polygon poly = io::pin_polygon(p);  // (a vertex written twice in a row taken once)
            const geom::Point first = poly.outer.front();
            sites.push_back({first, n.name, p.name, p.line, std::move(poly)});
          }
        }
      if (sites.empty()) {
        print_usage_error("VORONOI-0001", "no sites: the layout has no pins; give sites with --site or --site-file");
        status = kInvalid;
        return;
      }
    }
    std::vector<geom::Point> pts;
    for (const Site& s : sites) pts.push_back(s.p);
    const geom::NormalizedObstacles norm = routing_obstacles(*layout, pts);
    // The map's sources: the point sites, then the shape sites it can take (a shape must keep
    // off every blockage, the boundary and the other shapes; one that does not is named
    // (VORONOI-0002) and left out). map_site[k]: the site of the map's source k.
    std::vector<geom::Point> point_sites;
    std::vector<geom::Polygon> shape_sites;
    std::vector<std::size_t> map_site, shape_site;
    for (std::size_t i = 0; i < sites.size(); ++i)
      if (!sites[i].shape) {
        point_sites.push_back(sites[i].p);
        map_site.push_back(i);
      }
    std::vector<geom::Polygon> wanted;
    std::vector<std::size_t> wanted_site;
    for (std::size_t i = 0; i < sites.size(); ++i)
      if (sites[i].shape) {
        wanted.push_back(*sites[i].shape);
        wanted_site.push_back(i);
      }
    const auto why = router::L1Map::shape_problems(norm.domain, norm.obstacles, wanted, point_sites);
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      const std::size_t i = wanted_site[k];
      using Kind = router::L1Map::ShapeProblem::Kind;
      if (!why[k]) {
        shape_sites.push_back(wanted[k]);
        shape_site.push_back(i);
        continue;
      }
      auto pin_name = [&](std::size_t t) { return "pin \"" + sites[t].pin + "\" of net \"" + sites[t].net + "\""; };
      // The other pin by name: an earlier shape (wanted[other]) or a point site (map_site: the
      // point sites, in order).
      const std::string reason = why[k].kind == Kind::Shape   ? "it touches or overlaps " + pin_name(wanted_site[why[k].other])
                                 : why[k].kind == Kind::Point ? pin_name(map_site[why[k].other]) + " lies on or in it"
                                                              : why[k].text();
      if (!args->load.quiet)
        print_diagnostics({Diagnostic{Severity::Warning, "VORONOI-0002", args->file, sites[i].line, 0,
                                      pin_name(i) + " is a shape that cannot be a Voronoi site: " + reason + "; it is left out"}});
    }
    for (const std::size_t i : shape_site) map_site.push_back(i);
    const router::L1Map map(norm.domain, norm.obstacles, point_sites, shape_sites);
    // A site outside free space has no region: refused, naming it (nothing is written).
    bool bad = false;
    for (std::size_t i = 0; i < sites.size(); ++i)
      if (!sites[i].shape && !map.is_free(sites[i].p)) {
        const std::string what = site_name(sites[i], i) + " at " + point_text(sites[i].p) + " " + why_not_free(*layout, sites[i].p);
        if (sites[i].line)
          print_diagnostics({Diagnostic{Severity::Error, "ROUTE-0001", args->file, sites[i].line, 0, what}});
        else
          print_usage_error("ROUTE-0001", what);
        bad = true;
      }
    if (bad) {
      status = kInvalid;
      return;
    }
    std::vector<router::VoronoiRegion> regions = router::l1_voronoi(map);
    for (auto& r : regions) r.site = map_site[r.site];  // the map's source index -> the site's
    std::sort(regions.begin(), regions.end(), [](const auto& a, const auto& b) { return a.site < b.site; });
    std::vector<const router::VoronoiRegion*> of(sites.size(), nullptr);
    for (const auto& r : regions) of[r.site] = &r;
    // Sites sharing a point: the first has the region, the others are named.
    for (std::size_t i = 0; i < sites.size(); ++i)
      if (!of[i] && !args->load.quiet)
        for (std::size_t j = 0; j < i; ++j)
          if (!sites[i].shape && !sites[j].shape && sites[j].p == sites[i].p) {
            print_diagnostics({Diagnostic{Severity::Warning, "VORONOI-0003", sites[i].line ? args->file : "", sites[i].line, 0,
                                          site_name(sites[i], i) + " is at the same point as " + site_name(sites[j], j) +
                                              ", which has the region"}});
            break;
          }

    if (!args->out.empty() && !write_output(args->out, cells_xml(*layout, sites, regions))) {
      status = kInvalid;
      return;
    }
    if (!args->svg.empty()) {
      io::SvgOptions so;
      so.underlay = regions_svg(regions);
      if (!from_pins) {
        for (std::size_t i = 0; i < sites.size(); ++i)
          so.overlay += "<circle class=\"site\" cx=\"" + std::to_string(sites[i].p.x) + "\" cy=\"" + std::to_string(sites[i].p.y) +
                        "\" r=\"@4\" fill=\"#1d252c\" stroke=\"#ffffff\" stroke-width=\"@1.2\"/>\n";
      }
      so.caption = std::to_string(sites.size()) + " Voronoi sites, " + std::to_string(regions.size()) + " regions";
      if (!write_output(args->svg, io::layout_to_svg(*layout, so))) {
        status = kInvalid;
        return;
      }
    }

    router::Rational reached = 0;
    for (const auto& r : regions) reached += r.area;
    nlohmann::ordered_json j;
    j["metric"] = "l1";
    auto rows = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < sites.size(); ++i) {
      nlohmann::ordered_json s;
      s["site"] = i;
      if (sites[i].shape) {
        auto pts_json = nlohmann::ordered_json::array();
        for (const geom::Point v : sites[i].shape->outer) pts_json.push_back({v.x, v.y});
        s["points"] = pts_json;
      } else {
        s["point"] = {sites[i].p.x, sites[i].p.y};
      }
      if (!sites[i].net.empty()) {
        s["net"] = sites[i].net;
        s["pin"] = sites[i].pin;
      }
      const router::VoronoiRegion* r = of[i];
      s["area"] = r ? r->area.convert_to<double>() : 0.0;
      s["area_exact"] = r ? rational_str(r->area) : "0";
      std::size_t holes = 0;
      if (r)
        for (const auto& p : r->polygons) holes += p.holes.size();
      s["polygons"] = r ? r->polygons.size() : 0;
      s["holes"] = holes;
      rows.push_back(s);
      if (!args->json)
        std::cout << site_name(sites[i], i) << " (" << (sites[i].shape ? "shape " + points_text(sites[i].shape->outer) : point_text(sites[i].p)) << "): area "
                  << (r ? rational_str(r->area) : "0") << ", " << (r ? r->polygons.size() : 0) << " polygon(s), "
                  << holes << " hole(s)\n";
    }
    j["sites"] = rows;
    j["area"] = reached.convert_to<double>();
    if (args->json) std::cout << j.dump() << '\n';
    status = kOk;
  });
}

}  // namespace taut::cli
