// taut gen KIND -o OUT [--size N] [--nets M] [--seed S]: seeded, reproducible layouts.
#include <iostream>

#include "io/generate.h"
#include "io/layout_writer.h"
#include "tools/cli.h"
#include "tools/commands.h"

namespace taut::cli {

void add_gen(CLI::App& app, int& status) {
  struct Args {
    std::string kind, out;
    std::int64_t size = 1000;
    int nets = 10;
    std::uint64_t seed = 1;
  };
  auto args = std::make_shared<Args>();
  std::string kinds;
  for (const auto& k : io::gen_kind_names()) kinds += (kinds.empty() ? "" : ", ") + k;
  CLI::App* sub = app.add_subcommand("gen", "Write a generated layout for tests and benchmarks");
  sub->add_option("KIND", args->kind, "one of: " + kinds)->required();
  sub->add_option("-o,--output", args->out, "layout file to write")->required();
  sub->add_option("--size", args->size, "target number of blockage vertices")
      ->check(CLI::Range(std::int64_t{4}, std::int64_t{20'000'000}));
  sub->add_option("--nets", args->nets, "number of two-pin nets")->check(CLI::Range(0, 10'000'000));
  sub->add_option("--seed", args->seed, "random seed (same seed, same file)");
  sub->callback([args, &status] {
    const auto kind = io::parse_gen_kind(args->kind);
    if (!kind) {
      print_usage_error("CLI-0010", "unknown layout kind \"" + args->kind + "\"");
      status = kInvalid;
      return;
    }
    io::GenOptions o;
    o.kind = *kind;
    o.size = args->size;
    o.nets = args->nets;
    o.seed = args->seed;
    status = write_output(args->out, io::layout_to_xml(io::generate_layout(o))) ? kOk : kInvalid;
  });
}

}  // namespace taut::cli
