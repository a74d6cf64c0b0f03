#include "tools/cli.h"

#include <algorithm>
#include <cstdio>
#include <ostream>

#include <nlohmann/json.hpp>

#include "tools/commands.h"

#include <fstream>
#include <iostream>

#include "geom/directions.h"
#include "geom/root3_directions.h"
#include "io/atomic_file.h"
#include "io/layout_reader.h"
#include "io/validate_layout.h"
#include "router/bend_router.h"

namespace taut::cli {

int print_diagnostics(const std::vector<Diagnostic>& diagnostics, bool quiet) {
  int errors = 0;
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error) ++errors;
    if (d.severity == Severity::Warning && quiet) continue;
    std::cerr << format(d) << '\n';
  }
  return errors;
}

void print_usage_error(std::string_view code, std::string_view message) {
  std::cerr << "taut: error: [" << code << "] " << message << '\n';
}

std::optional<io::Layout> load_layout(const std::string& path, const LoadOptions& options,
                                      std::vector<Diagnostic>* diagnostics) {
  io::ReadOptions ro;
  ro.lenient = options.lenient;
  io::ReadResult r = io::read_layout(path, ro);
  std::vector<Diagnostic> all = std::move(r.diagnostics);
  if (r.layout && !has_error(all)) {
    std::vector<Diagnostic> v = io::validate_layout(*r.layout);
    all.insert(all.end(), v.begin(), v.end());
  }
  print_diagnostics(all, options.quiet);
  const bool ok = r.layout.has_value() && !has_error(all);
  if (diagnostics) *diagnostics = std::move(all);
  if (!ok) return std::nullopt;
  return std::move(r.layout);
}

void add_input_options(CLI::App* sub, std::string& file, LoadOptions& options,
                       const std::string& quiet_help) {
  sub->add_option("FILE", file, "layout file")->required();
  sub->add_flag("--lenient", options.lenient, "unknown elements/attributes are warnings");
  sub->add_flag("-q,--quiet", options.quiet, quiet_help);
}

std::optional<geom::Point> parse_point(const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  const auto x = io::parse_coordinate(std::string_view(text).substr(0, comma));
  const auto y = io::parse_coordinate(std::string_view(text).substr(comma + 1));
  if (!x || !y) return std::nullopt;
  return geom::Point{static_cast<geom::Coord>(*x), static_cast<geom::Coord>(*y)};
}

std::optional<geom::Point> parse_point_option(const std::string& name, const std::string& text) {
  auto p = parse_point(text);
  if (!p)
    print_usage_error("CLI-0022", name + " \"" + text +
                                      "\": expected X,Y with integers of at most 2^30 - 1 in absolute value");
  return p;
}

void add_routing_options(CLI::App* sub, RoutingOptions& options) {
  sub->add_option("--metric", options.metric,
                  "l1 (default: shortest), combined (length + C x bends, C from --bend-cost or <rules> "
                  "bend-cost) or link (fewest bends, then shortest); combined and link: rectilinear "
                  "wires (route: nets of point pins)");
  sub->add_option("--orientations", options.orientations,
                  "rectilinear or octilinear (spm also: any, epsilon-approximate Euclidean distances); "
                  "default: orientations of <rules>, else rectilinear; c: sets only as another name of those "
                  "two (c:0,90 or c:0,45,90,135)");
  sub->add_option("--bend-cost", options.bend_cost,
                  "C >= 0 of --metric combined (an integer in DBU per bend, at most 2^30 - 1; default: "
                  "<rules> bend-cost, else 0)");
  sub->add_option("--cover-pieces", options.cover_pieces,
                  "K of --metric combined and link: a blockage with sloped edges is routed around its "
                  "rectilinear cover, the blockage plus the bounding boxes of K equal pieces of every "
                  "sloped edge (1 to 4096; default 16; 1: one box per edge)");
}

std::int64_t routing_bend_cost(const RoutingOptions& options, const io::Layout& layout) {
  if (options.bend_cost) return *options.bend_cost;
  return layout.rules ? layout.rules->bend_cost : 0;
}

bool check_routing_options(const RoutingOptions& options, const io::Layout& layout, bool quiet) {
  const bool bends = options.metric == "combined" || options.metric == "link";
  if (options.metric != "l1" && !bends) {
    print_usage_error("CLI-0020", "--metric " + options.metric + ": expected l1, combined or link");
    return false;
  }
  if (bends && !options.allow_bends) {
    print_usage_error("CLI-0020", "--metric " + options.metric + ": this command takes --metric l1 only");
    return false;
  }
  if (options.bend_cost && options.metric != "combined") {
    print_usage_error("CLI-0020", "--bend-cost applies to --metric combined (this run: --metric " +
                                      options.metric + ")");
    return false;
  }
  if (options.bend_cost && (*options.bend_cost < 0 || *options.bend_cost > kMaxBendCost)) {
    print_usage_error("CLI-0020", "--bend-cost " + std::to_string(*options.bend_cost) +
                                      ": expected an integer from 0 to 2^30 - 1");
    return false;
  }
  if (options.cover_pieces && !bends) {
    print_usage_error("CLI-0020", "--cover-pieces applies to --metric combined and link (this run: --metric " +
                                      options.metric + ")");
    return false;
  }
  if (options.cover_pieces && (*options.cover_pieces < 1 || *options.cover_pieces > router::kMaxCoverPieces)) {
    print_usage_error("CLI-0020", "--cover-pieces " + std::to_string(*options.cover_pieces) +
                                      ": expected an integer from 1 to " + std::to_string(router::kMaxCoverPieces));
    return false;
  }
  auto available = [&](const std::string& text) {
    const std::string o = io::canonical_orientations(text);
    return o == "rectilinear" || o == "octilinear" || ((options.allow_any || options.allow_sets) && o == "any") ||
           (options.allow_sets && (geom::LatticeDirections::parse(o) || geom::Root3Directions::parse_any(o)));
  };
  // what is available, said in the refusal
  const std::string offered = options.allow_sets
                                  ? "rectilinear, octilinear, any and c: sets of two orientations at least modulo "
                                    "180 degrees are available (e.g. c:45,135, c:0,60,120, c:0,10; a direction at a "
                                    "multiple of neither 45 nor 30 degrees is taken as the integer step of at most "
                                    "2^24 nearest it, which must lie within 2^-36 radians of it: one about 10^-6 "
                                    "degrees off a slope of small integers, such as 0.000001 or 45.000001, does not)"
                                  : "only rectilinear and octilinear wires are available in this version";
  // what is wrong with a c: set that parse_any refuses, said first
  auto why_not = [&](const std::string& text) {
    std::string why;
    if (options.allow_sets && text.rfind("c:", 0) == 0 && !geom::Root3Directions::parse_any(io::canonical_orientations(text), why) &&
        !why.empty())
      return why + "; ";
    return std::string();
  };
  if (!options.orientations.empty() && !available(options.orientations)) {
    print_usage_error("CLI-0021", "--orientations " + options.orientations + ": " + why_not(options.orientations) + offered);
    return false;
  }
  if (options.orientations.empty() && layout.rules && !available(layout.rules->orientations)) {
    print_diagnostics({Diagnostic{Severity::Error, "CLI-0021", layout.file, layout.rules->line, 0,
                                  "<rules> orientations=\"" + layout.rules->orientations + "\": " +
                                      why_not(layout.rules->orientations) + offered +
                                      "; pass --orientations rectilinear or --orientations octilinear to route "
                                      "anyway"}});
    return false;
  }
  if (bends && routing_orientations(options, layout) != "rectilinear") {
    const std::string why = "--metric " + options.metric +
                            " routes rectilinear wires only (bends of wires in other directions are not weighed yet)";
    if (options.orientations.empty() && layout.rules)  // the orientations come from the file
      print_diagnostics({Diagnostic{Severity::Error, "CLI-0021", layout.file, layout.rules->line, 0,
                                    why + ": <rules> orientations=\"" + layout.rules->orientations +
                                        "\"; pass --orientations rectilinear to route anyway"}});
    else
      print_usage_error("CLI-0021", why + "; pass --orientations rectilinear");
    return false;
  }
  if (!bends && layout.rules && layout.rules->bend_cost > 0)
    print_diagnostics({Diagnostic{Severity::Warning, "CLI-0024", layout.file, layout.rules->line, 0,
                                  "<rules> bend-cost=" + std::to_string(layout.rules->bend_cost) +
                                      " is not weighed by the l1 metric: wires are shortest in L1 "
                                      "(taut path --metric combined weighs it)"}},
                      quiet);
  return true;
}

std::string routing_orientations(const RoutingOptions& options, const io::Layout& layout) {
  if (!options.orientations.empty()) return io::canonical_orientations(options.orientations);
  return layout.rules ? io::canonical_orientations(layout.rules->orientations) : std::string("rectilinear");
}

std::optional<io::Layout> load_routing_layout(const std::string& path, const LoadOptions& load,
                                              const RoutingOptions& routing) {
  auto layout = load_layout(path, load);
  if (!layout || !check_routing_options(routing, *layout, load.quiet)) return std::nullopt;
  return layout;
}

// Points from a text file, one X,Y per line; blank lines and lines starting with # are skipped.
// A bad line: FILE:LINE: error: [CLI-0025], nothing added; an unreadable file: IO-0001.
bool read_point_file(const std::string& path, std::vector<geom::Point>& out) {
  std::ifstream in(path);
  if (!in) {
    print_diagnostics({Diagnostic{Severity::Error, "IO-0001", path, 0, 0, "cannot open the file for reading"}});
    return false;
  }
  std::vector<geom::Point> got;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    const auto e = line.find_last_not_of(" \t\r");
    const std::string text = line.substr(b, e - b + 1);
    const auto p = parse_point(text);
    if (!p) {
      print_diagnostics({Diagnostic{Severity::Error, "CLI-0025", path, n, 0,
                                    "\"" + text + "\": expected X,Y with integers of at most 2^30 - 1 in absolute value"}});
      return false;
    }
    got.push_back(*p);
  }
  if (in.bad()) {
    print_diagnostics({Diagnostic{Severity::Error, "IO-0001", path, 0, 0, "read error"}});
    return false;
  }
  out.insert(out.end(), got.begin(), got.end());
  return true;
}

bool write_output(const std::string& path, std::string_view bytes) {
  if (auto d = io::write_file_atomically(path, bytes)) {
    print_diagnostics({*d});
    return false;
  }
  return true;
}

void print_route_table(std::ostream& os, const nlohmann::ordered_json& stats, std::size_t max_rows) {
  if (!stats.contains("routes")) return;
  struct Row {
    std::string net, status, length, bends, reason;
    std::size_t pins = 0;
  };
  std::vector<Row> rows;
  for (const auto& [name, e] : stats["routes"].items()) {
    Row r;
    r.net = name;
    r.status = e.value("status", "");
    r.pins = e.value("pins", std::size_t{0});
    r.length = e.contains("length") ? (e["length"].is_string() ? e["length"].get<std::string>() : e["length"].dump()) : "-";
    r.bends = e.contains("bends") ? e["bends"].dump() : "-";
    r.reason = e.value("reason", "");
    rows.push_back(std::move(r));
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return (a.status != "routed") > (b.status != "routed"); });
  std::size_t width = 3;
  for (std::size_t i = 0; i < rows.size() && i < max_rows; ++i) width = std::max(width, rows[i].net.size());
  char line[160];
  std::snprintf(line, sizeof line, "%-*s  %-8s %5s %12s %6s  %s\n", static_cast<int>(width), "net", "status", "pins", "length", "bends",
                "reason");
  os << line;
  for (std::size_t i = 0; i < rows.size() && i < max_rows; ++i) {
    const Row& r = rows[i];
    std::snprintf(line, sizeof line, "%-*s  %-8s %5zu %12s %6s  ", static_cast<int>(width), r.net.c_str(), r.status.c_str(), r.pins,
                  r.length.c_str(), r.bends.c_str());
    os << line << r.reason << '\n';
  }
  if (rows.size() > max_rows) os << "... " << rows.size() - max_rows << " more nets (--json for every one)\n";
  if (stats.contains("totals")) {
    const auto& t = stats["totals"];
    const std::int64_t routed = t.value("routed", std::int64_t{0});
    const std::int64_t all = routed + t.value("failed", std::int64_t{0}) + t.value("missing", std::int64_t{0});
    std::snprintf(line, sizeof line, "%.1f", 100.0 * t.value("completion", 1.0));
    os << "total: " << routed << " of " << all << " nets routed (" << line << " %), length "
       << (t["length"].is_string() ? t["length"].get<std::string>() : t["length"].dump()) << ", " << t.value("bends", std::int64_t{0})
       << " bends, " << t.value("wires", std::int64_t{0}) << " wires\n";
  }
}

}  // namespace taut::cli
