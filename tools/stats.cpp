// taut stats FILE [--json] [-o S.json]: wirelength and bend statistics of a (routed) layout: a
// table of the nets (those not routed first, with their reasons; at most 20 rows) and the
// totals, or with --json the whole document (io/stats_json.h).
#include <iostream>

#include <nlohmann/json.hpp>

#include "io/stats_json.h"
#include "tools/cli.h"
#include "tools/commands.h"

namespace taut::cli {

void add_stats(CLI::App& app, int& status) {
  struct Args {
    std::string file, out;
    bool json = false;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("stats", "Wirelength and bend statistics, per net and total");
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  sub->add_option("-o,--output", args->out, "also write the JSON document to this file");
  add_input_options(sub, args->file, args->load, "do not print warnings");
  sub->callback([args, &status] {
    auto layout = load_layout(args->file, args->load);
    if (!layout) {
      status = kInvalid;
      return;
    }
    const std::string doc = io::layout_stats_json(*layout) + "\n";
    if (!args->out.empty() && !write_output(args->out, doc)) {
      status = kInvalid;
      return;
    }
    if (args->json) {
      std::cout << doc;
    } else {
      const auto j = nlohmann::ordered_json::parse(doc);
      std::cout << args->file << ": " << j.value("blockages", 0) << " blockages ("
                << j.value("blockage_vertices", 0) << " vertices), " << j.value("nets", 0)
                << " nets, " << j.value("pins", 0) << " pins\n";
      if (j.contains("routes")) print_route_table(std::cout, j, 20);
    }
    status = kOk;
  });
}

}  // namespace taut::cli
