// taut check FILE [--json]: validates a layout (syntax, geometry, names, pins) and reports what
// the geometry pipeline makes of it.
#include <chrono>
#include <iostream>

#include <nlohmann/json.hpp>

#include "io/layout_geometry.h"
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
    bool json = false, lenient = false, quiet = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("check", "Validate a layout (and check its routes)");
  sub->add_option("FILE", args->file, "layout file")->required();
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  sub->add_flag("--lenient", args->lenient, "unknown elements/attributes are warnings");
  sub->add_flag("-q,--quiet", args->quiet, "do not print warnings or the summary");
  sub->callback([args, &status] {
    std::vector<Diagnostic> diags;
    auto layout = load_layout(args->file, {args->lenient, args->quiet}, &diags);
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
    if (args->json) {
      std::cout << j.dump(2) << '\n';
    } else if (layout && !args->quiet) {
      const auto& l = j["layout"];
      std::cout << args->file << ": ok: " << l["blockages"] << " blockages ("
                << l["blockage_vertices"] << " vertices), " << l["nets"] << " nets, "
                << l["pins"] << " pins";
      if (warnings) std::cout << ", " << warnings << " warning(s)";
      std::cout << '\n';
    }
  });
}

}  // namespace taut::cli
