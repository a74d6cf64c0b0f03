// Shared pieces of the taut subcommands: exit codes (CLI.md), loading a layout with every
// diagnostic printed, and writing outputs atomically. Only tools/ prints and picks exit codes.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>
#include <string_view>
#include <vector>

#include "geom/diagnostic.h"
#include "geom/types.h"
#include "io/layout.h"

namespace taut::cli {

enum Exit : int {
  kOk = 0,          // success
  kIncomplete = 1,  // ran to the end, but a check failed / a target is unreachable / unrouted
  kInvalid = 2,     // usage error or invalid input: nothing written
  kInternal = 3,    // a bug
  kResource = 4,    // time limit, memory, interrupted
};

struct LoadOptions {
  bool lenient = false;
  bool quiet = false;  // suppress warnings (errors are always printed)
};

// A short table of a layout statistics document (io::layout_stats_json) with "routes": the nets
// not routed first (with their reasons), then routed ones, at most max_rows rows, then the totals
// with the completion rate. For `taut stats` (stdout) and `taut route` (stderr).
void print_route_table(std::ostream& os, const nlohmann::ordered_json& stats, std::size_t max_rows);

// Prints diagnostics to stderr in the CLI.md format. Returns the number of errors.
int print_diagnostics(const std::vector<Diagnostic>& diagnostics, bool quiet = false);

// A usage or command-line problem, printed as `taut: error: [CLI-xxxx] message`.
void print_usage_error(std::string_view code, std::string_view message);

// Reads and validates a layout; prints every diagnostic; nullopt when there is an error.
// `diagnostics` (if not null) receives everything that was printed.
std::optional<io::Layout> load_layout(const std::string& path, const LoadOptions& options,
                                      std::vector<Diagnostic>* diagnostics = nullptr);

// "X,Y" with integers as FORMAT.md writes them (-?[0-9]+, |v| <= 2^30 - 1); nullopt otherwise.
std::optional<geom::Point> parse_point(const std::string& text);
// parse_point() of the value of option `name`; on failure prints CLI-0022 naming the option.
std::optional<geom::Point> parse_point_option(const std::string& name, const std::string& text);

// The routing options of `path` and `route` (CLI.md). This version routes the l1 metric with
// rectilinear or octilinear output, and (`path`) the combined and link metrics with rectilinear
// output; any other request is refused with a message naming what is missing (never silently
// routed another way).
struct RoutingOptions {
  std::string metric = "l1";
  std::string orientations;  // empty: from <rules> (default rectilinear)
  std::optional<std::int64_t> bend_cost;
  // --cover-pieces K (combined and link): each sloped blockage edge is covered by the boxes of K
  // pieces (router::rectilinear_cover; default router::kDefaultCoverPieces).
  std::optional<std::int64_t> cover_pieces;
  // `spm` only: orientations "any" is accepted (distances are then epsilon-approximate
  // Euclidean ones, from a fixed-orientation norm).
  bool allow_any = false;
  // `path` and `route`: --metric combined and link (rectilinear wires).
  bool allow_bends = false;
  // `route` only: orientations "any" and the lattice c: sets (geom/directions.h: directions at
  // multiples of 45 degrees, such as c:45,135; since 2026-12-06) and the sets at multiples of 30
  // degrees (geom/root3_directions.h, such as c:0,60,120; since 2026-12-07) and every other c:
  // set Root3Directions::parse_any realizes (c:0,10; since the twenty-first session, the same day)
  // are accepted; the nets are routed octilinear and then tightened together into them.
  bool allow_sets = false;
};
// The combined metric's C: --bend-cost, else <rules> bend-cost, else 0.
std::int64_t routing_bend_cost(const RoutingOptions& options, const io::Layout& layout);
// The largest bend cost accepted: what a layout file can hold (FORMAT.md's number limit, 2^30 - 1),
// so a routed file's <routes bend-cost> reads back.
inline constexpr std::int64_t kMaxBendCost = geom::kMaxCoord;
// Checks the options against what is implemented and the layout's <rules>; prints and returns
// false when routing must not start (exit status 2). A bend cost in <rules> is reported as a
// warning (it only matters to the combined metric).
bool check_routing_options(const RoutingOptions& options, const io::Layout& layout, bool quiet);

// The orientations to route in after check_routing_options() accepted them: --orientations,
// else <rules>, else "rectilinear"; "rectilinear" or "octilinear" (or "any" with allow_any, or
// "any" and a c: set as written with allow_sets).
std::string routing_orientations(const RoutingOptions& options, const io::Layout& layout);

// load_layout(), then check_routing_options(): the layout when routing may start, otherwise
// nullopt after everything was printed (exit status 2).
std::optional<io::Layout> load_routing_layout(const std::string& path, const LoadOptions& load,
                                              const RoutingOptions& routing);

// Points from a text file, one X,Y per line (blank lines and lines starting with # skipped),
// appended to `out`. A bad line: FILE:LINE: error: [CLI-0025], nothing added; an unreadable file:
// IO-0001; false then.
bool read_point_file(const std::string& path, std::vector<geom::Point>& out);

// Writes bytes atomically; prints the diagnostic and returns false on failure.
bool write_output(const std::string& path, std::string_view bytes);

}  // namespace taut::cli
