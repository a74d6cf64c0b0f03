// taut tighten FILE -o OUT [--svg PIC] [--stats S.json] [--orientations rectilinear|octilinear|any]:
// pulls each net's <sketch> (or, for a net without one, each of its routed wires) taut in its
// homotopy class (router/tighten.h: the sleeve in the free-space triangulation and the funnel),
// then writes it in the chosen directions (--orientations, else <rules>, else rectilinear):
// `any` keeps the Euclidean shortest wire; rectilinear, octilinear and the other lattice c: sets
// (directions at multiples of 45 degrees: c:0,45, c:45,135, c:0,45,90, ...; geom/directions.h)
// write the shortest wire of the class in those directions with the fewest links
// (router::c_oriented). The ends stay where they are and every vertex is an integer. A sketch or wire that leaves free space is an input
// error (TIGHTEN-0001, file:line, nothing written); a net with nothing to tighten (TIGHTEN-0002)
// or with no integer staircase in its class (TIGHTEN-0004) is written as failed (exit status 1).
// `c:0,90` and `c:0,45,90,135` name rectilinear and octilinear. A set at multiples of 30 degrees
// (c:0,60,120, ...; since 2026-12-07) writes the shortest wire of the class in it built exactly in
// Q(sqrt3) with its vertices rounded to integers (router/root3_staircase.h; with --clearance
// and --min-link since 2026-12-07). Since the twenty-first session (the same day) any other c: set
// too, such as c:0,10 or c:0,45,60: each direction at a multiple of 30 or 45 degrees is an exact
// step, any other the integer step of at most 2^24 nearest it (geom::Root3Directions::parse_any;
// within 2^-36 radians, the steps reported in --stats and on stderr), and the wire is built exactly
// for those steps and rounded the same way. A direction no such step comes near enough is refused
// (CLI-0027) or, from <rules>, replaced by `any` (TIGHTEN-0003).
// --min-link adds each wire's minimum-link path of its class (router/minlink.h, any angle, exact
// rational bends; for a loop its minimum-link loop, section 5.2, proven minimal unless its
// shortest loop is convex and the loop found is above the winding bound) to --stats and --svg,
// and in a direction set also its minimum-link path in those directions (router/c_minlink.h,
// section 6.3: exact rational bends in a lattice set, bends in Q(sqrt3) in a set at multiples of
// 30 degrees, since 2026-12-07; for a loop, a loop with few links); they are not written as
// wires (FORMAT.md coordinates are integers, and these bends are not).
#include <algorithm>
#include <chrono>
#include <optional>
#include <set>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "geom/directions.h"
#include "geom/root3_directions.h"
#include "geom/triangulation.h"
#include "io/layout_geometry.h"
#include "io/layout_writer.h"
#include "io/stats_json.h"
#include "io/svg.h"
#include "router/c_minlink.h"
#include "router/minlink.h"
#include "router/tighten.h"
#include "router/tighten_nets.h"
#include "geom/predicates.h"
#include "router/version.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {
namespace {

// The taut wire (or shortest loop) of a written wire's class, for --min-link; throws with where
// its lift fails, or when a loop winds around nothing.
std::vector<geom::Point> taut_of(const router::Tightener& t, const std::vector<geom::Point>& w) {
  if (WireTightener::is_loop(w)) {
    router::Tightener::Loop l = t.tighten_loop(w);
    if (l.status != router::TightenStatus::Ok)
      throw std::runtime_error(std::string(router::tighten_status_text(l.status)) + " at or after " + point_text(l.where));
    if (l.contractible) throw std::runtime_error("the loop winds around no blockage");
    return std::move(l.points);
  }
  router::Tightened r = t.tighten(w);
  if (r.status != router::TightenStatus::Ok)
    throw std::runtime_error(std::string(router::tighten_status_text(r.status)) + " at or after " + point_text(r.where));
  return std::move(r.points);
}

// Exact coordinates as text: "p/q" (or "p"), and a + b sqrt3 as "A+B*sqrt3" or "A-B*sqrt3" with A
// and B so written (A always there, "0" too).
std::string exact_text(const router::Rational& v) { return v.str(); }
std::string exact_text(const router::RationalRoot3& v) {
  if (v.b.sign() == 0) return v.a.str();
  return v.a.str() + (v.b.sign() < 0 ? "-" : "+") + router::Rational(abs(v.b)).str() + "*sqrt3";
}
double to_double(const router::Rational& v) { return v.convert_to<double>(); }
double to_double(const router::RationalRoot3& v) { return v.to_double(); }

struct NetTightening {
  std::string source;  // "sketch" or "wires"
  double before = 0, taut = 0, after = 0;
  long bends_before = 0, bends_after = 0;
  std::size_t sleeve = 0, crossings = 0;
  // --min-link: the minimum-link path of each open wire's class (exact rational bends)
  std::size_t min_links = 0;
  std::size_t min_links_at_least = 0;  // a lower bound (= min_links when proven)
  std::vector<router::MinLinkPath> min_link;
  // false when some loop's shortest loop is convex and the loop found has more links than the
  // winding bound (router::MinLinkLoop::minimal), so min_links is only an upper bound
  bool min_links_proven = true;
  bool min_link_failed = false;  // TIGHTEN-0008
  // --min-link in a direction set: the minimum-link path of each wire's class in those
  // directions (section 6.3), a loop's closed; exact bends as text, and as doubles to draw
  std::size_t oriented_min_links = 0;
  std::size_t oriented_at_least = 0;  // a lower bound (= oriented_min_links when proven)
  bool oriented_proven = true;        // false when some loop's count is only an upper bound
  struct OrientedPath {
    std::vector<std::array<std::string, 2>> exact;
    std::vector<std::array<double, 2>> drawn;
  };
  std::vector<OrientedPath> oriented_min_link;
  std::string oriented_none;  // a wire or loop with no path in the set (why)
  // adds the minimum-link path of a taut line, or the minimum-link loop when is_loop; and with a
  // direction set, the minimum-link path in it
  void add_min_link(const router::MinLinker& ml, std::span<const geom::Point> taut, bool is_loop,
                    const geom::FreeSpaceTriangulation& t, const router::TightenOrientations& set) {
    std::optional<router::MinLinkLoop> any_loop;  // the any-angle loop: also the bound of the set's
    if (is_loop) any_loop = ml.loop(taut);
    if (set.set) add_oriented(t, taut, is_loop, *set.set, any_loop ? &*any_loop : nullptr);
    if (set.set30) add_oriented(t, taut, is_loop, *set.set30, any_loop ? &*any_loop : nullptr);
    if (is_loop) {
      router::MinLinkLoop& l = *any_loop;
      min_links_proven = min_links_proven && l.minimal;
      min_links_at_least += l.minimal ? l.links() : l.at_least;
      min_link.push_back(router::MinLinkPath{std::move(l.points)});
    } else {
      min_link.push_back(ml.path(taut));
      min_links_at_least += min_link.back().links();
    }
    min_links += min_link.back().links();
  }
  template <class Set>
  void add_oriented(const geom::FreeSpaceTriangulation& t, std::span<const geom::Point> taut, bool is_loop,
                    const Set& set, const router::MinLinkLoop* any_loop);
};

template <class Set>
void NetTightening::add_oriented(const geom::FreeSpaceTriangulation& t, std::span<const geom::Point> taut, bool is_loop,
                                 const Set& set, const router::MinLinkLoop* any_loop) {
  auto keep = [&](const auto& points) {
    OrientedPath o;
    for (const auto& p : points) {
      o.exact.push_back({exact_text(p.x), exact_text(p.y)});
      o.drawn.push_back({to_double(p.x), to_double(p.y)});
    }
    oriented_min_link.push_back(std::move(o));
  };
  if (is_loop) {
    const auto c = router::CMinLinker(t).loop(taut, set, any_loop);
    if (!c.ok()) oriented_none = c.why;
    oriented_min_links += c.links();
    oriented_at_least += c.minimal ? c.links() : c.at_least;
    oriented_proven = oriented_proven && c.minimal;
    keep(c.points);
  } else {
    const auto c = router::CMinLinker(t).path(taut, set);
    if (!c.ok()) oriented_none = c.why;
    oriented_min_links += c.links();
    oriented_at_least += c.links();
    keep(c.points);
  }
}

std::string fixed3(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

// Where a piece of a net's input lines (routed wires are cut at their joints before they are
// tightened) fails, said of the lines as written: the input line that holds the piece's failing
// segment, and the lift with that line's segment; a piece that fails at its start, where the line
// does not start (a joint), is said to leave free space on the line's segment there, at or after
// that point. nullopt when no input line holds it (not seen: every piece lies on its line; the
// piece is then named as it is).
std::optional<std::pair<std::size_t, router::Tightened>> said_of(const std::vector<std::vector<geom::Point>>& given,
                                                                 std::span<const geom::Point> piece, const router::Tightened& r) {
  if (piece.empty()) return std::nullopt;
  const std::size_t seg = r.status == router::TightenStatus::StartNotFree ? 0 : r.segment;
  const geom::Point a = piece[std::min(seg, piece.size() - 1)], b = piece[std::min(seg + 1, piece.size() - 1)];
  for (std::size_t c = 0; c < given.size(); ++c)
    for (std::size_t g = 0; g + 1 < given[c].size(); ++g)
      if (geom::on_segment(a, given[c][g], given[c][g + 1]) && geom::on_segment(b, given[c][g], given[c][g + 1])) {
        router::Tightened said = r;
        said.segment = g;
        if (r.status == router::TightenStatus::StartNotFree && piece.front() != given[c].front()) {
          said.status = router::TightenStatus::LeavesFreeSpace;
          said.where = piece.front();
        }
        return std::pair{c, said};
      }
  return std::nullopt;
}

}  // namespace

void add_tighten(CLI::App& app, int& status) {
  struct Args {
    std::string file, out, svg, stats, orientations;
    LoadOptions load;
    bool clearance = false, min_link = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "tighten",
      "Pull each net's sketch (or its routed wires) taut without changing how it winds around the "
      "blockages: the shortest wire of its homotopy class");
  sub->add_option("-o,--output", args->out, "layout to write (the input with <routes> of the tightened wires)")
      ->required();
  sub->add_option("--svg", args->svg, "also draw the result as SVG (input sketches and wires dashed)");
  sub->add_option("--stats", args->stats, "also write statistics as JSON (lengths before and after)");
  sub->add_option("--orientations", args->orientations,
                  "directions of the output: rectilinear, octilinear, a c: set of multiples of 45 degrees "
                  "such as c:0,45 or c:45,135 (the shortest wire of the class in those directions, fewest "
                  "links), any other c: set such as c:0,60,120 or c:0,10 (the same, its vertices rounded "
                  "to integers; a direction at a multiple of neither 30 nor 45 degrees taken as the integer "
                  "step of at most 2^24 nearest it) or any (the Euclidean shortest); default: <rules>");
  sub->add_flag("--clearance", args->clearance,
                "keep half the wire width plus the spacing of <rules> from every blockage (tighten against "
                "blockages grown by that much)");
  sub->add_flag("--min-link", args->min_link,
                "also find each wire's minimum-link path of its class (any angle, exact rational bends) "
                "and, with rectilinear, octilinear or a c: set, its minimum-link path in those directions "
                "(exact bends: rationals, or numbers a+b*sqrt3 with directions at multiples of 30 degrees) "
                "(for a loop, a closed loop with few links, proven minimal or given as a range): "
                "their link counts and bends go to --stats, their drawings to --svg; the written wires "
                "are still the shortest ones");
  add_input_options(sub, args->file, args->load, "do not print warnings or the summary");
  sub->callback([args, &status] {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    // The output's directions: any, a lattice direction set by its name (c:0,90 is rectilinear),
    // or (since 2026-12-07) any other c: set such as c:0,60,120 or c:0,10, written with its exact
    // vertices rounded (router/root3_staircase.h, geom::Root3Directions::parse_any).
    std::string o = args->orientations;
    if (!o.empty() && o != "any") {
      if (const router::TightenOrientations to = tighten_orientations(o); to.c_oriented()) {
        o = to.name();
      } else {
        std::string why;
        if (o.rfind("c:", 0) == 0) geom::Root3Directions::parse_any(o, why);
        print_usage_error("CLI-0027", "tighten: --orientations " + o + ": " + (why.empty() ? "" : why + "; ") +
                                          "expected rectilinear, octilinear, any, or a c: set of two orientations "
                                          "at least modulo 180 degrees such as c:0,60,120 or c:0,10 (a direction "
                                          "at a multiple of neither 45 nor 30 degrees is taken as the integer step "
                                          "of at most 2^24 nearest it, which must lie within 2^-36 radians of it: "
                                          "one about 10^-6 degrees off a slope of small integers, such as 0.000001 "
                                          "or 45.000001, does not)");
        status = kInvalid;
        return;
      }
    }
    const auto layout = load_layout(args->file, args->load);
    if (!layout) {
      status = kInvalid;
      return;
    }
    std::string orientations = o;
    if (orientations.empty()) {
      orientations = layout->rules ? layout->rules->orientations : "rectilinear";
      if (orientations != "any") {
        if (const router::TightenOrientations to = tighten_orientations(orientations); to.c_oriented()) {
          orientations = to.name();
        } else {
          std::string why;
          geom::Root3Directions::parse_any(orientations, why);
          print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0003", layout->file, layout->rules->line, 0,
                                        "<rules orientations=\"" + orientations + "\">: " + (why.empty() ? "" : why + "; ") +
                                            "no integer step of at most 2^24 lies within 2^-36 radians of a direction "
                                            "(one about 10^-6 degrees off a slope of small integers, such as 0.000001 "
                                            "or 45.000001), or the set is not one of two orientations at least; "
                                            "tightened wires are written at any angle"}},
                            args->load.quiet);
          orientations = "any";
        }
      }
    }
    const bool c_oriented = orientations != "any";

    // What each net tightens: its sketch, else its routed wires.
    struct Input {
      std::vector<std::vector<geom::Point>> lines;
      std::vector<int> line_numbers;
      std::string source;
      std::string off_pins;  // a two-pin net's open sketch that does not join its pins: why (TIGHTEN-0012)
      bool ignored_sketch = false;  // a sketch on a net without two pins, not a loop (LAYOUT-0009: ignored)
    };
    std::vector<Input> inputs(layout->nets.size());
    const std::vector<router::NetPins> all_pins = net_pins(*layout);
    std::vector<geom::Point> extra;
    for (std::size_t i = 0; i < layout->nets.size(); ++i) {
      const io::Net& net = layout->nets[i];
      Input& in = inputs[i];
      // A sketch is taken when it is a loop, or joins a two-pin net's pins; one that misses a pin
      // would be written as a wire that joins nothing (TIGHTEN-0012: the net's routed wires are
      // taken instead, else it is failed), and one on a net without two pins is ignored, as
      // LAYOUT-0009 says (its routed wires, if any, are taken).
      const bool loop = net.sketch && WireTightener::is_loop(net.sketch->points);
      in.ignored_sketch = net.sketch && !loop && net.pins.size() != 2;
      if (net.sketch && !loop && !in.ignored_sketch) in.off_pins = io::sketch_off_pins(net);
      if (net.sketch && !in.ignored_sketch && in.off_pins.empty()) {
        in.source = "sketch";
        in.lines.push_back(net.sketch->points);
        in.line_numbers.push_back(net.sketch->line);
      } else if (layout->routes) {
        for (const io::Route& r : layout->routes->routes)
          if (r.net == net.name && r.status == "routed" && !r.wires.empty()) {
            in.source = "wires";
            for (const io::Wire& w : r.wires) {
              in.lines.push_back(w.points);
              in.line_numbers.push_back(w.line ? w.line : r.line);
            }
            break;
          }
      }
      if (!in.off_pins.empty() && in.lines.empty()) in.source = "sketch";  // failed (TIGHTEN-0012)
      for (const auto& l : in.lines) extra.insert(extra.end(), l.begin(), l.end());
    }

    // Routed wires in directions the output lacks, by default (no --orientations): said, since
    // the default (<rules orientations>, else rectilinear) may not be the directions the file was
    // routed in (route --orientations octilinear over rectilinear rules), and their staircases
    // are longer (TIGHTEN-0014, since 2026-12-05).
    // (per input: routed wires with a segment outside the output's directions; `any` has none)
    const router::TightenOrientations out_orientations = tighten_orientations(orientations);
    // --min-link in a direction set also finds the minimum-link paths in it (in a set at
    // multiples of 30 degrees since 2026-12-07: before, the one at any angle alone, TIGHTEN-0015)
    const router::TightenOrientations min_link_set = args->min_link ? out_orientations : router::TightenOrientations{};
    const std::optional<geom::Root3Directions>& out_set30 = out_orientations.set30;
    // A staircase in a cone of two steps that do not bracket the link's box, as in c:0,45 (NE and
    // W round north) or c:45,135 (NE and SE round east), leaves the box of its ends: (0,0) to
    // (0,1000) in c:0,45 is (0,0) (1000,1000) (0,1000). Without a <boundary> the plane is
    // unbounded, so the domain must hold those staircases, or the fewest links are lost to its
    // walls (a zigzag of one bend per 128 DBU there, millions on a long wire; found by fuzzing,
    // 2026-12-06). Each lies in the parallelogram of its link, within |dx| + |dy| of the link's
    // box; the box is grown by its width plus its height on each side (clamped), times
    // TightenOrientations::box_growth in a set with a cone over 135 degrees (c:0,30, c:0,10;
    // since 2026-12-07: a cone of angle phi reaches |v| / sin phi). (A larger
    // domain lowers the scale --clearance can tighten in, router::exact_gaps_scale: on a layout
    // over about 10^7 DBU across, such a set tightens in the layout's units, gaps of exactly the
    // clearance closed.)
    if (!layout->boundary && out_orientations.cones_leave_box()) {
      const geom::Box b = io::routing_domain(*layout, extra);
      const geom::Box grown = geom::grown_box(
          b, out_orientations.box_growth() * ((std::int64_t{b.hi.x} - b.lo.x) + (std::int64_t{b.hi.y} - b.lo.y)));
      extra.push_back(grown.lo);
      extra.push_back(grown.hi);
    }
    std::vector<char> off_directions(inputs.size(), 0);
    for (std::size_t i = 0; i < inputs.size(); ++i)
      off_directions[i] = inputs[i].source == "wires" &&
                          !std::all_of(inputs[i].lines.begin(), inputs[i].lines.end(),
                                       [&](const auto& l) { return out_orientations.runs_in(l); });
    if (o.empty() && layout->routes) {
      std::size_t off = 0, first = 0;
      for (std::size_t i = 0; i < inputs.size(); ++i)
        if (off_directions[i] && off++ == 0) first = i;
      if (off > 0)
        print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0014", layout->file, layout->routes->line, 0,
                                      std::to_string(off) + " net" + (off == 1 ? "'s" : "s'") + " routed wires (net \"" +
                                          layout->nets[first].name + "\"" + (off > 1 ? " and others" : "") +
                                          ") run in directions outside " + orientations + ", the output's (" +
                                          (layout->rules ? "from <rules orientations>, rectilinear by default" : "the default") +
                                          "): they are written as " + orientations + " staircases, which may be longer; "
                                          "--orientations " + (layout->routes->orientations.empty() ? "SET" : layout->routes->orientations) +
                                          " keeps their directions"}},
                          args->load.quiet);
    }

    // Clearance: half the wire width (rounded up) plus the spacing, kept by growing every
    // blockage by a square of that half-side (so at least that far in Euclidean distance).
    const std::int64_t width = layout->rules ? layout->rules->wire_width : 0;
    const std::int64_t spacing = layout->rules ? layout->rules->spacing : 0;
    const std::int64_t grow = args->clearance ? (width + 1) / 2 + spacing : 0;
    if (!args->clearance && width + spacing > 0)
      print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0006", layout->file, layout->rules->line, 0,
                                    "<rules> wire-width and spacing are not kept: tightened wires may touch "
                                    "blockages (--clearance keeps them)"}},
                        args->load.quiet);
    geom::NormalizedObstacles norm;
    if (grow > 0) {
      geom::Box domain = io::routing_domain(*layout, extra);
      if (!layout->boundary) {  // room to go round a grown blockage in the unbounded plane
        domain = geom::grown_box(domain, grow);
      }
      try {
        norm = geom::normalize_obstacles(
            geom::square_grown(io::blockage_polygons(*layout), static_cast<geom::Coord>(std::min<std::int64_t>(grow, geom::kMaxCoord))),
            domain);
      } catch (const std::domain_error& e) {
        print_diagnostics({Diagnostic{Severity::Error, "TIGHTEN-0007", layout->file, layout->rules->line, 0,
                                      std::string("--clearance: ") + e.what() + " (" + std::to_string(grow) +
                                          " DBU round every blockage)"}});
        status = kInvalid;
        return;
      }
    } else {
      norm = routing_obstacles(*layout, extra);
    }
    const WireTightener wt(norm, orientations);
    std::unique_ptr<router::MinLinker> min_linker;  // made on the first open wire under --min-link

    // --clearance: every net tightened together (router::NetsTightener), each among the blockages
    // grown by ceil(w/2) + s and the other nets' wires and pins grown by max(w + s, 1), round after
    // round until no wire shortens: no crossing is made and the clearance is kept between nets.
    std::vector<router::NetLines> together(layout->nets.size());
    std::vector<router::NetTightenOutcome> together_out;
    std::optional<router::NetsTightenStats> together_stats;
    std::int64_t together_scale = 1;  // the plane's scale --clearance tightened in (1: the layout's units)
    // per net: its input is not in its space as given in the scaled plane (all, when that did not
    // run): only those are refused (TIGHTEN-0001) when the layout's units refuse more
    std::vector<char> scaled_refused(layout->nets.size(), 1);
    // --clearance: routed wires the tightener refuses that pass taut check's test, 1 in the
    // output's directions, 2 not (TIGHTEN-0013, below)
    std::vector<char> legal_as_given(layout->nets.size(), 0);
    std::unique_ptr<router::NetSpace> net_space;
    if (args->clearance) {
      router::NetRules rules{width, spacing};
      geom::Box domain = io::routing_domain(*layout, extra);
      if (!layout->boundary) domain = geom::grown_box(domain, grow + std::max<std::int64_t>(width + spacing, 1));
      const geom::NormalizedObstacles plain = routing_obstacles(*layout, extra);
      try {
        net_space = std::make_unique<router::NetSpace>(domain, plain.obstacles, net_pins(*layout), rules);
      } catch (const std::domain_error& e) {
        print_diagnostics({Diagnostic{Severity::Error, "TIGHTEN-0007", layout->file, layout->rules->line, 0,
                                      std::string("--clearance: ") + e.what() + " (" + std::to_string(grow) +
                                          " DBU round every blockage, " + std::to_string(width + spacing) +
                                          " round every wire and pin)"}});
        status = kInvalid;
        return;
      }
      for (std::size_t i = 0; i < layout->nets.size(); ++i) together[i] = inputs[i].lines;
      router::NetsTightenOptions o;
      o.orientations = out_orientations;
      // (routed wires read from the file are wires: cut at their joints, so a tree stays joined,
      // and checked as given, as sketches are; since 2026-12-05, before which they were taken as
      // sketches, whose lines are tightened one by one, and a branch could be left behind)
      std::vector<router::NetsTightener::Input> kind(layout->nets.size(), router::NetsTightener::Input::Sketch);
      for (std::size_t i = 0; i < layout->nets.size(); ++i)
        if (inputs[i].source == "wires") kind[i] = router::NetsTightener::Input::CheckedWires;
      // First in the plane scaled as the net router's exact gaps scale it (since 2026-12-05), where
      // a gap of exactly the clearance is open (net_router.h): a sketch or wire through one is
      // free there, and pulled taut. Snapped back (router::tighten_scaled), the result is taken
      // when no vertex lay a quarter of the scale or more from its multiple, no net's input failed
      // or was left untightened there, and router::check_routes finds no wire leaving free space
      // or coming within the clearance; else everything is tightened in the layout's units, where
      // such a gap is closed.
      // (On a layout with an edge at another angle than a multiple of 45 degrees the scaled plane
      // is not exact, net_router.h: its result is still taken when the check passes it, but a net
      // it takes as given and the layout's units refuse is then refused, TIGHTEN-0001.)
      // (Not when a routed wire runs in directions the output does not have, as octilinear wires
      // tightened into rectilinear: such a piece is replaced whatever its result, and along a 45
      // degree corridor at exactly the clearance its staircase steps at the lattice's unit, K
      // times as many steps in the scaled plane: degenerate seed 11 of Tighten.OctilinearRoutesTightened
      // grew past 1.5 GB there.)
      const bool off_set = std::find(off_directions.begin(), off_directions.end(), 1) != off_directions.end();
      // (Nor in a set at multiples of 30 degrees: its wires are rounded to the scaled plane's
      // integers, which snapping back moves again, off the rounding rule and from afar.)
      const std::int64_t k = off_set || out_set30 ? 1 : router::exact_gaps_scale(domain, plain.obstacles, all_pins, rules, true);
      const bool exact_plane = router::exact_gaps_scale(domain, plain.obstacles, all_pins, rules) > 1;
      if (k > 1) {
        router::NetsTightenStats kst;
        std::vector<router::NetTightenOutcome> kout;
        std::optional<std::vector<router::NetLines>> back;
        try {
          back = router::tighten_scaled(domain, plain.obstacles, all_pins, rules, k, together, kind, o, &kst, &kout);
        } catch (const std::exception&) {  // (not seen: the scale keeps every coordinate within 2^29) the layout's units decide
          back.reset();
          kout.clear();
        }
        for (std::size_t i = 0; i < kout.size(); ++i)
          scaled_refused[i] = !exact_plane || (kout[i].status == router::NetTightenOutcome::Status::NotFree && kout[i].round == 0);
        const bool clean = !kout.empty() && std::none_of(kout.begin(), kout.end(), [](const router::NetTightenOutcome& oc) {
          return (oc.status == router::NetTightenOutcome::Status::NotFree && oc.round == 0) || oc.untightened;
        });
        using K = router::CheckProblem::Kind;
        auto joins = [](const router::CheckProblem& p) { return p.kind == K::Disconnected || p.kind == K::StrayWire; };
        if (back && clean) {
          // no wire leaving free space or within the clearance, and no net joined worse than as given
          // (sketches need not join their pins: their nets may be disconnected as given already)
          const std::vector<router::CheckProblem> problems = wire_problems(*layout, domain, plain.obstacles, *back);
          bool ok = std::all_of(problems.begin(), problems.end(), joins);
          if (ok && !problems.empty()) {
            std::set<std::size_t> before;
            for (const router::CheckProblem& p : wire_problems(*layout, domain, plain.obstacles, together))
              if (joins(p)) before.insert(p.net);
            ok = std::all_of(problems.begin(), problems.end(), [&](const router::CheckProblem& p) { return before.count(p.net) > 0; });
          }
          if (ok) {
            // (the layout's units' space gets the wires too: --min-link works among them)
            for (std::size_t i = 0; i < back->size(); ++i) net_space->set_wires(i, (*back)[i]);
            together = std::move(*back);
            together_out = std::move(kout);
            together_stats = kst;
            together_scale = k;
          }
        }
      }
      if (together_scale == 1) {
        router::NetsTightener nt(*net_space, o);
        together_out = nt.run(together, kind);
        together_stats = nt.stats();
      }
      // Routed wires refused as given in both planes, which keep the clearance as taut check
      // measures it (the Euclidean distance of FORMAT.md; the tightener's space grows every
      // blockage by a square, which keeps more, so a wire the octilinear router ran diagonally
      // past a sloped edge can be legal and still not lie in it): written as they are
      // (TIGHTEN-0013), not refused, when in the output's directions. The others were tightened
      // round them as they are. Those in other directions are written as failed.
      bool any_refused = false;
      for (std::size_t i = 0; i < together_out.size(); ++i)
        any_refused = any_refused || (inputs[i].source == "wires" && scaled_refused[i] &&
                                      together_out[i].status == router::NetTightenOutcome::Status::NotFree &&
                                      together_out[i].round == 0);
      if (any_refused) {
        std::vector<router::NetLines> given(layout->nets.size());
        for (std::size_t i = 0; i < given.size(); ++i)
          if (inputs[i].source == "wires") given[i] = inputs[i].lines;
        std::vector<char> bad(given.size(), 0);
        using K = router::CheckProblem::Kind;
        for (const router::CheckProblem& p : wire_problems(*layout, domain, plain.obstacles, given))
          if (p.kind == K::NotFree || p.kind == K::BlockageClearance || p.kind == K::NetClearance || p.kind == K::Short ||
              p.kind == K::Disconnected || p.kind == K::StrayWire) {
            bad[p.net] = 1;
            if (p.other_net) bad[*p.other_net] = 1;
          }
        for (std::size_t i = 0; i < given.size(); ++i)
          legal_as_given[i] = inputs[i].source == "wires" && !bad[i] ? (off_directions[i] ? 2 : 1) : 0;
      }
    }
    const auto t1 = Clock::now();

    io::Routes routes;
    routes.tool = "taut " + std::string(router::version());
    routes.metric = c_oriented ? "l1" : "euclidean";
    routes.orientations = orientations;
    std::vector<Diagnostic> errors;
    std::vector<NetTightening> stats(layout->nets.size());
    bool refused_somewhere = false;  // --clearance: a net's input is refused (TIGHTEN-0001) in both planes
    for (std::size_t i = 0; i < together_out.size(); ++i)
      refused_somewhere = refused_somewhere || (scaled_refused[i] && !legal_as_given[i] &&
                                                together_out[i].status == router::NetTightenOutcome::Status::NotFree &&
                                                together_out[i].round == 0);
    std::size_t done = 0;
    for (std::size_t i = 0; i < layout->nets.size(); ++i) {
      const io::Net& net = layout->nets[i];
      const Input& in = inputs[i];
      io::Route route;
      route.net = net.name;
      if (!in.off_pins.empty()) {
        const bool wires = in.source == "wires";
        const std::string why = "its <sketch> " + in.off_pins + ": tightened, it would join nothing";
        print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0012", layout->file, net.sketch->line, 0,
                                      "net \"" + net.name + "\": " + why +
                                          (wires ? "; its routed wires are tightened instead" : "")}},
                          args->load.quiet);
        if (!wires) {
          route.status = "failed";
          route.reason = why;
          routes.routes.push_back(std::move(route));
          continue;
        }
      }
      if (in.lines.empty()) {
        route.status = "failed";
        route.reason = in.ignored_sketch ? "nothing to tighten: the net has no routed wire, and its <sketch> is ignored (a "
                                           "sketch is for a net of two pins, or a loop)"
                                         : "nothing to tighten: the net has no <sketch> and no routed wire";
        print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0002", layout->file, net.line, 0,
                                      "net \"" + net.name + "\": " + *route.reason}},
                          args->load.quiet);
        routes.routes.push_back(std::move(route));
        continue;
      }
      NetTightening& st = stats[i];
      auto no_min_link = [&](int line, const std::exception& e) {  // TIGHTEN-0008: an optional statistic left null
        st.min_link_failed = true;
        print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0008", layout->file, line, 0,
                                      "net \"" + net.name + "\": no minimum-link path was found (" + e.what() +
                                          "); its min_links is null"}},
                          args->load.quiet);
      };
      st.source = in.source;
      // the net's routed wires written as they are, not tightened (TIGHTEN-0011, TIGHTEN-0013)
      auto written_as_given = [&] {
        for (const auto& l : in.lines) {
          st.before += router::euclidean_length(l);
          st.bends_before += io::count_bends(l);
        }
        st.after = st.taut = st.before;
        st.bends_after = st.bends_before;
        route.status = "routed";
        route.length = io::format_total_length(in.lines);
        route.bends = st.bends_after;
        for (const auto& l : in.lines) route.wires.push_back(io::Wire{l});
        routes.routes.push_back(std::move(route));
        ++done;
      };
      // route.reason said as the warning `code`; then the routed wires written as they are
      // (`write`), or the net written as failed
      auto not_tightened = [&](const char* code, bool write) {
        print_diagnostics({Diagnostic{Severity::Warning, code, layout->file, in.line_numbers[0], 0,
                                      "net \"" + net.name + "\": " + *route.reason}},
                          args->load.quiet);
        if (!write) {
          route.status = "failed";
          routes.routes.push_back(std::move(route));
          return;
        }
        route.reason.reset();
        written_as_given();
      };
      std::vector<std::vector<geom::Point>> out_lines;
      bool ok = true, no_staircase = false, contractible = false;
      std::string no_staircase_why;  // a set at multiples of 30 degrees: why it has no wire
      if (args->clearance) {
        using St = router::NetTightenOutcome::Status;
        const router::NetTightenOutcome& oc = together_out[i];
        if (oc.status == St::NotFree && oc.round == 0 && !scaled_refused[i]) {
          // legal as given (free in the exact scaled plane), but not in the layout's units, which
          // close a gap of exactly the clearance; the scaled plane's result was not taken: another
          // net was refused there (its error is said, and nothing is written), or it did not pass
          // the check. Routed wires are written as they are (the others were tightened round them
          // as given); a sketch is no wire: failed.
          if (refused_somewhere) continue;
          const bool wires = in.source == "wires";
          route.reason = wires ? "its wires keep exactly the clearance somewhere (a gap that only the scaled plane opens), "
                                 "and the scaled plane's result was not taken: written as they are, not tightened"
                               : "its sketch could not be tightened: it keeps exactly the clearance somewhere (a gap that "
                                 "only the scaled plane opens), and the scaled plane's result was not taken";
          not_tightened("TIGHTEN-0011", wires);
          continue;
        }
        if (oc.status == St::NotFree && oc.round == 0 && legal_as_given[i]) {
          if (refused_somewhere) continue;  // (nothing is written)
          const bool in_set = legal_as_given[i] == 1;
          route.reason = std::string("its wires keep the clearance as taut check measures it (Euclidean), but not as the "
                                     "tightener grows the blockages and the other nets' wires (by squares): ") +
                         (in_set ? "written as they are, not tightened"
                                 : "not tightened, and they run in directions the output does not have: failed");
          not_tightened("TIGHTEN-0013", in_set);
          continue;
        }
        if (oc.status == St::NotFree && oc.round == 0) {
          // the input is not in its net's space: the piece that failed, and the input line it is on
          const std::vector<geom::Point>& piece = together[i][oc.wire];
          // (a sketch is one line, tightened whole; routed wires were cut at their joints)
          const auto said = in.source == "wires" ? said_of(in.lines, piece, oc.lift) : std::nullopt;
          const std::size_t k = said ? said->first : 0;
          const router::Tightened lift = said ? said->second : oc.lift;
          const std::vector<geom::Point>& line = said || in.source != "wires" ? in.lines[k] : piece;
          const std::string what = in.source == "sketch" ? "sketch" : "wire";
          std::string text = WireTightener::failure_text(*layout, net.name, what, line, lift, grow);
          if (!oc.wire_blockers.empty() || !oc.pin_blockers.empty()) {  // the other nets it comes near
            std::string others;
            for (const std::size_t j : oc.wire_blockers)
              others += (others.empty() ? "" : ", ") + ("net \"" + layout->nets[j].name + "\"'s " + (inputs[j].source == "sketch" ? "sketch" : "wire"));
            for (const std::size_t j : oc.pin_blockers)
              others += (others.empty() ? "" : ", ") + ("net \"" + layout->nets[j].name + "\"'s pin");
            const std::string within = "within the clearance of " + others + " (w + s = " +
                                       std::to_string(net_space->net_clearance()) + " DBU)";
            text = "net \"" + net.name + "\": the " + what +
                   (lift.status == router::TightenStatus::StartNotFree
                        ? " starts at " + point_text(line.front()) + ", which lies " + within
                        : "'s segment " + std::to_string(lift.segment + 1) + " (" + point_text(line[lift.segment]) +
                              " to " + point_text(line[lift.segment + 1]) + ") comes " + within + " at or after " +
                              point_text(lift.where)) +
                   (what == "sketch" ? ": sketches of different nets must keep that apart, as they say which way each passes the other"
                                     : ": wires of different nets must keep that apart (taut check: CHECK-0008)");
          }
          errors.push_back(Diagnostic{Severity::Error, "TIGHTEN-0001", layout->file, in.line_numbers[k], 0, text});
          continue;
        }
        contractible = oc.status == St::Contractible;
        no_staircase = oc.untightened && oc.wire < oc.kept.size() && oc.kept[oc.wire] == 2;
        if (no_staircase) no_staircase_why = oc.why;  // (a set at multiples of 30 degrees)
        if (oc.untightened && !no_staircase) {
          route.status = "failed";
          route.reason = in.source == "wires"
                             ? "its wires run in directions the output does not have, and a piece of them could not be "
                               "pulled taut into them (the other nets' wires came to exactly the clearance on both sides "
                               "of it, or it is kept as it is: a closed piece, or one that touches a shape pin only "
                               "mid-segment)"
                             : "its sketch could not be pulled taut: the other nets' wires came to exactly the clearance "
                               "on both sides of it (at or after " + point_text(oc.lift.where) + "), leaving it no room";
          print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0010", layout->file, in.line_numbers[0], 0,
                                        "net \"" + net.name + "\": " + *route.reason}},
                            args->load.quiet);
          routes.routes.push_back(std::move(route));
          continue;
        }
        st.before = oc.length_before;
        st.after = oc.length_after;
        st.taut = oc.length_taut;
        st.bends_before = oc.bends_before;
        st.bends_after = oc.bends_after;
        st.sleeve = oc.sleeve;
        st.crossings = oc.crossings;
        if (!contractible && !no_staircase) out_lines = together[i];
        if (args->min_link && !contractible && !no_staircase) {
          // the minimum-link path of each wire's class among what its net was tightened among
          try {
            const router::SpaceTightener sp(net_space->obstacles(i, router::NetSpaceLevel::Full),
                                            router::TightenOrientations::Any);
            const router::MinLinker ml(sp.triangulation());
            // (A wire that another net's wire has come to exactly the clearance of runs in a gap
            // of width zero in this space: its lift fails, and TIGHTEN-0008 says where.)
            for (const auto& w : out_lines)
              st.add_min_link(ml, taut_of(sp.tightener(), w), WireTightener::is_loop(w), sp.triangulation(), min_link_set);
          } catch (const std::exception& e) {
            no_min_link(in.line_numbers[0], e);
          }
        }
      }
      // Without --clearance, routed wires are cut at their joints (their ends on one another, the
      // pins: router::cut_at_joints), each piece is tightened alone between its fixed ends, and
      // they are joined again where exactly two meet (router::join_at_twos), so a tree stays
      // joined; a piece that touches a shape pin mid-segment only is kept as it is. (Before
      // 2026-12-05 each line was tightened whole, and a branch that ended on another line's
      // segment could be left behind.) A sketch is one line, tightened whole.
      std::vector<std::vector<geom::Point>> lines = in.lines;
      std::vector<int> numbers = in.line_numbers;
      std::vector<std::size_t> origin(lines.size());  // the input line a piece is of
      for (std::size_t k = 0; k < origin.size(); ++k) origin[k] = k;
      std::vector<char> as_is(lines.size(), 0);
      const bool wires_in = in.source == "wires" && !args->clearance;
      if (wires_in) {
        std::vector<geom::Polygon> joints = all_pins[i].pins;
        for (const auto& l : in.lines)
          if (!l.empty()) joints.push_back(geom::Polygon{{l.front()}, {}}), joints.push_back(geom::Polygon{{l.back()}, {}});
        lines.clear(), numbers.clear(), origin.clear(), as_is.clear();
        for (std::size_t k = 0; k < in.lines.size(); ++k) {
          std::vector<char> frozen;
          router::NetLines cut = router::cut_at_joints({in.lines[k]}, joints, &frozen);
          for (std::size_t j = 0; j < cut.size(); ++j) {
            lines.push_back(std::move(cut[j]));
            numbers.push_back(in.line_numbers[k]);
            origin.push_back(k);
            as_is.push_back(frozen[j] || WireTightener::is_loop(lines.back()));  // a closed wire stays (as route --tighten keeps it)
          }
        }
      }
      std::vector<int> said_line(in.lines.size(), 0);
      for (std::size_t k = 0; k < lines.size() && !args->clearance; ++k) {
        const auto& line = lines[k];
        if (as_is[k] || router::one_point(line)) {
          st.before += router::euclidean_length(line);
          st.after += router::euclidean_length(line);
          st.taut += router::euclidean_length(line);
          out_lines.push_back(line);
          continue;
        }
        WireTightener::Result res = wt.run(line);
        const router::Tightened& r = res.taut;
        if (r.status != router::TightenStatus::Ok) {
          ok = false;
          if (wires_in && said_line[origin[k]]++) continue;  // one error per <wire> (its next piece starts where this failed)
          const auto said = wires_in ? said_of({in.lines[origin[k]]}, line, r) : std::nullopt;
          errors.push_back(Diagnostic{Severity::Error, "TIGHTEN-0001", layout->file, numbers[k], 0,
                                      WireTightener::failure_text(*layout, net.name, in.source == "sketch" ? "sketch" : "wire",
                                                                  said ? in.lines[origin[k]] : line, said ? said->second : r, grow)});
          continue;
        }
        if (res.contractible) {  // the other lines are still lifted: their errors are said
          contractible = true;
          continue;
        }
        st.taut += router::euclidean_length(r.points);
        if (args->min_link && !st.min_link_failed && !wires_in) {  // (routed wires: below, per wire written)
          // an optional statistic: a failure here must not cost the tightened layout
          try {
            if (!min_linker) min_linker = std::make_unique<router::MinLinker>(wt.triangulation());
            st.add_min_link(*min_linker, r.points, res.loop, wt.triangulation(), min_link_set);
          } catch (const std::exception& e) {
            no_min_link(numbers[k], e);
          }
        }
        if (res.no_staircase) {
          no_staircase = true;
          if (no_staircase_why.empty()) no_staircase_why = res.why;  // (a set at multiples of 30 degrees)
          continue;
        }
        std::vector<geom::Point> pts = std::move(res.points);
        st.before += router::euclidean_length(line);
        st.after += router::euclidean_length(pts);
        st.bends_before += io::count_bends(line);
        st.bends_after += io::count_bends(pts);
        st.sleeve += r.sleeve;
        st.crossings += r.crossings;
        out_lines.push_back(std::move(pts));
      }
      if (wires_in && ok && !contractible && !no_staircase) {  // joined again; bends counted on the lines as given and written
        out_lines = router::join_at_twos(out_lines, all_pins[i].pins);
        st.bends_before = st.bends_after = 0;
        for (const auto& l : in.lines) st.bends_before += io::count_bends(l);
        for (const auto& l : out_lines) st.bends_after += io::count_bends(l);
        // --min-link per wire written: each pulled taut again in its class (the pieces' ends were fixed)
        for (std::size_t k = 0; k < out_lines.size() && args->min_link && !st.min_link_failed; ++k) {
          const auto& w = out_lines[k];
          if (router::one_point(w)) continue;
          try {
            // (the taut wire only: not written in the set again, which in a set at multiples of 30
            // degrees costs its exact staircase)
            const std::vector<geom::Point> taut = taut_of(wt.tightener(), w);
            if (!min_linker) min_linker = std::make_unique<router::MinLinker>(wt.triangulation());
            st.add_min_link(*min_linker, taut, WireTightener::is_loop(w), wt.triangulation(), min_link_set);
          } catch (const std::exception& e) {
            no_min_link(in.line_numbers[0], e);
          }
        }
      }
      if (!ok) continue;
      if (contractible) {
        route.status = "failed";
        route.reason = "the loop sketch winds around no blockage: it can be pulled to a point";
        print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0005", layout->file, in.line_numbers[0], 0,
                                      "net \"" + net.name + "\": " + *route.reason}},
                          args->load.quiet);
        routes.routes.push_back(std::move(route));
        continue;
      }
      if (no_staircase) {
        route.status = "failed";
        route.reason = no_staircase_reason(orientations, no_staircase_why);
        print_diagnostics({Diagnostic{Severity::Warning, "TIGHTEN-0004", layout->file, in.line_numbers[0], 0,
                                      "net \"" + net.name + "\": " + *route.reason}},
                          args->load.quiet);
        routes.routes.push_back(std::move(route));
        continue;
      }
      route.status = "routed";
      route.length = io::format_total_length(out_lines);
      route.bends = st.bends_after;
      for (auto& l : out_lines) route.wires.push_back(io::Wire{std::move(l)});
      routes.routes.push_back(std::move(route));
      ++done;
    }
    if (!errors.empty()) {
      print_diagnostics(errors);
      status = kInvalid;
      return;
    }
    const auto t2 = Clock::now();
    io::Layout out = *layout;
    out.routes = std::move(routes);

    // Every output is made before any is written, so a failure leaves nothing half done.
    const std::string xml = io::layout_to_xml(out);
    std::string svg, stats_text;
    if (!args->svg.empty()) {
      io::SvgOptions so;
      for (std::size_t i = 0; i < layout->nets.size(); ++i)
        if (inputs[i].source == "wires")
          for (const auto& l : inputs[i].lines) {
            std::string pts;
            for (geom::Point p : l) pts += (pts.empty() ? "" : " ") + point_text(p);
            so.overlay += "<polyline class=\"input-wire\" points=\"" + pts +
                          "\" fill=\"none\" stroke=\"#555555\" stroke-width=\"@1.5\" stroke-dasharray=\"@6 @4\"/>\n";
          }
      for (const NetTightening& st : stats)
        for (const router::MinLinkPath& m : st.min_link) {
          std::string pts;
          for (const router::RPoint& p : m.points)
            pts += (pts.empty() ? "" : " ") + fixed3(p.x.convert_to<double>()) + "," + fixed3(p.y.convert_to<double>());
          so.overlay += "<polyline class=\"min-link\" points=\"" + pts +
                        "\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"@1.5\" stroke-dasharray=\"@2 @3\"/>\n";
        }
      for (const NetTightening& st : stats)
        for (const NetTightening::OrientedPath& m : st.oriented_min_link) {
          std::string pts;
          for (const auto& [x, y] : m.drawn) pts += (pts.empty() ? "" : " ") + fixed3(x) + "," + fixed3(y);
          if (!pts.empty())
            so.overlay += "<polyline class=\"oriented-min-link\" points=\"" + pts +
                          "\" fill=\"none\" stroke=\"#111111\" stroke-width=\"@1.5\" stroke-dasharray=\"@5 @2 @1 @2\"/>\n";
        }
      so.caption = !args->min_link ? "tightened (input dashed)"
                   : min_link_set.c_oriented() ? "tightened (input dashed, minimum-link dotted red, minimum-link in " + orientations +
                                        " dash-dotted black)"
                                  : "tightened (input dashed, minimum-link dotted red)";
      svg = io::layout_to_svg(out, so);
    }
    auto stats_failed = [&](std::size_t i) {
      for (const io::Route& r : out.routes->routes)
        if (r.net == layout->nets[i].name) return r.status != "routed";
      return true;
    };
    double before = 0, after = 0;
    for (const NetTightening& s : stats) {
      before += s.before;
      after += s.after;
    }
    if (!args->stats.empty()) {
      auto j = nlohmann::ordered_json::parse(io::layout_stats_json(out));
      nlohmann::ordered_json nets = nlohmann::ordered_json::array();
      for (std::size_t i = 0; i < layout->nets.size(); ++i) {
        if (inputs[i].lines.empty()) continue;
        const NetTightening& s = stats[i];
        nets.push_back({{"net", layout->nets[i].name},
                        {"source", s.source},
                        {"length_before", std::stod(fixed3(s.before))},
                        {"length_taut", std::stod(fixed3(s.taut))},
                        {"length_after", std::stod(fixed3(s.after))},
                        {"bends_before", s.bends_before},
                        {"bends_after", s.bends_after},
                        {"sleeve_triangles", s.sleeve},
                        {"crossings", s.crossings},
                        {"fewest_links", true}});  // always: kept for scripts that read it
        if (args->min_link) {
          // exact bends as "p/q" strings (a double would not be the point)
          nlohmann::ordered_json paths = nlohmann::ordered_json::array();
          for (const router::MinLinkPath& m : s.min_link) {
            nlohmann::ordered_json pts = nlohmann::ordered_json::array();
            for (const router::RPoint& p : m.points) pts.push_back({p.x.str(), p.y.str()});
            paths.push_back(pts);
          }
          // null: not found (TIGHTEN-0008), nothing to count (a failed net), or not proven (a range)
          const bool counted = !s.min_link_failed && !s.min_link.empty() && !stats_failed(i);
          nets.back()["min_links"] =
              counted && s.min_links_proven ? nlohmann::ordered_json(s.min_links) : nlohmann::ordered_json();
          if (counted && !s.min_links_proven) {
            nets.back()["min_links_at_least"] = s.min_links_at_least;
            nets.back()["min_links_at_most"] = s.min_links;
          }
          nets.back()["min_link_wires"] = paths;
          if (min_link_set.c_oriented()) {
            // the same in the output's directions (section 6.3); null when some wire has none
            nlohmann::ordered_json opaths = nlohmann::ordered_json::array();
            for (const NetTightening::OrientedPath& m : s.oriented_min_link) {
              nlohmann::ordered_json pts = nlohmann::ordered_json::array();
              for (const auto& [x, y] : m.exact) pts.push_back({x, y});
              opaths.push_back(pts);
            }
            const bool ocounted = counted && s.oriented_none.empty();
            nets.back()["oriented_min_links"] =
                ocounted && s.oriented_proven ? nlohmann::ordered_json(s.oriented_min_links) : nlohmann::ordered_json();
            if (ocounted && !s.oriented_proven) {
              nets.back()["oriented_min_links_at_least"] = s.oriented_at_least;
              nets.back()["oriented_min_links_at_most"] = s.oriented_min_links;
            }
            if (!s.oriented_none.empty()) nets.back()["oriented_min_links_none"] = s.oriented_none;
            nets.back()["oriented_min_link_wires"] = opaths;
          }
        }
      }
      j["tighten"] = {{"orientations", orientations},
                      {"nets", nets},
                      {"length_before", std::stod(fixed3(before))},
                      {"length_after", std::stod(fixed3(after))},
                      {"triangles", wt.triangulation().triangles().size()},
                      {"seconds", {{"prepare", std::chrono::duration<double>(t1 - t0).count()},
                                   {"tighten", std::chrono::duration<double>(t2 - t1).count()}}}};
      // a set at other angles: the integer steps its directions were taken as (since 2026-12-07)
      if (const auto steps = realized_steps_json(out_orientations); !steps.is_null()) j["tighten"]["orientation_steps"] = steps;
      if (together_stats) {
        j["tighten"]["together"] = together_stats_json(*together_stats);
        j["tighten"]["together"]["scale"] = together_scale;  // (since 2026-12-05)
      }
      stats_text = j.dump(2) + "\n";
    }
    if (!write_output(args->out, xml) || (!args->svg.empty() && !write_output(args->svg, svg)) ||
        (!args->stats.empty() && !write_output(args->stats, stats_text))) {
      status = kInvalid;
      return;
    }
    if (!args->load.quiet) {
      for (std::size_t i = 0; i < layout->nets.size(); ++i) {
        if (inputs[i].lines.empty()) continue;
        const NetTightening& s = stats[i];
        if (stats_failed(i)) continue;
        std::cerr << "  " << layout->nets[i].name << " (" << s.source << "): length " << fixed3(s.before) << " -> "
                  << fixed3(s.after);
        if (c_oriented) std::cerr << " " << orientations << " (taut " << fixed3(s.taut) << ")";
        std::cerr << ", bends " << s.bends_before << " -> " << s.bends_after;
        if (!s.min_link.empty() && !s.min_link_failed) {
          if (s.min_links_proven)
            std::cerr << ", minimum links " << s.min_links;
          else
            std::cerr << ", minimum links " << s.min_links_at_least << " to " << s.min_links
                      << " (a convex loop's minimum is not proven)";
          if (min_link_set.c_oriented() && s.oriented_none.empty()) {
            std::cerr << " (" << orientations << ": ";
            if (!s.oriented_proven) std::cerr << s.oriented_at_least << " to ";
            std::cerr << s.oriented_min_links << ")";
          }
        }
        std::cerr << '\n';
      }
      std::cerr << args->file << ": tightened " << done << " of " << layout->nets.size() << " nets, length "
                << fixed3(before) << " -> " << fixed3(after) << "; wrote " << args->out << '\n';
      if (const std::string steps = realized_steps_text(out_orientations); !steps.empty())
        std::cerr << "  " << orientations << ": " << steps << " (every wire exact for these steps, then rounded)\n";
    }
    status = done == layout->nets.size() ? kOk : kIncomplete;
  });
}

}  // namespace taut::cli
