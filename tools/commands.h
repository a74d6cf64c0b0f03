// The subcommands of `taut`. Each add_X registers its CLI11 subcommand on the app; its
// callback stores the exit status in `status`.
#pragma once

#include <CLI/CLI.hpp>

namespace taut::cli {

void add_check(CLI::App& app, int& status);
void add_render(CLI::App& app, int& status);
void add_stats(CLI::App& app, int& status);
void add_gen(CLI::App& app, int& status);

}  // namespace taut::cli
