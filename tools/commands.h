// The subcommands of `taut`. Each add_X registers its CLI11 subcommand on the app; its
// callback stores the exit status in `status`.
#pragma once

#include <CLI/CLI.hpp>

#include "tools/cli.h"

namespace taut::cli {

// Registers the input options every layout-reading subcommand shares: FILE, --lenient, -q.
void add_input_options(CLI::App* sub, std::string& file, LoadOptions& options,
                       const std::string& quiet_help = "do not print warnings");

// Registers --metric, --orientations and --bend-cost.
void add_routing_options(CLI::App* sub, RoutingOptions& options);

void add_check(CLI::App& app, int& status);
void add_path(CLI::App& app, int& status);
void add_route(CLI::App& app, int& status);
void add_spm(CLI::App& app, int& status);
void add_voronoi(CLI::App& app, int& status);
void add_render(CLI::App& app, int& status);
void add_stats(CLI::App& app, int& status);
void add_gen(CLI::App& app, int& status);
void add_tighten(CLI::App& app, int& status);
void add_diameter(CLI::App& app, int& status);
void add_import(CLI::App& app, int& status);

}  // namespace taut::cli
