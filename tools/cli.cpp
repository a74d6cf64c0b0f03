#include "tools/cli.h"

#include "tools/commands.h"

#include <iostream>

#include "io/atomic_file.h"
#include "io/layout_reader.h"
#include "io/validate_layout.h"

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

bool write_output(const std::string& path, std::string_view bytes) {
  if (auto d = io::write_file_atomically(path, bytes)) {
    print_diagnostics({*d});
    return false;
  }
  return true;
}

}  // namespace taut::cli
