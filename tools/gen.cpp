// taut gen KIND -o OUT [--size N] [--nets M] [--seed S]: seeded, reproducible layouts.
#include <iostream>

#include "io/generate.h"
#include "io/layout_writer.h"
#include "io/movingai.h"
#include "tools/cli.h"
#include "tools/commands.h"

namespace taut::cli {

void add_gen(CLI::App& app, int& status) {
  struct Args {
    std::string kind, out;
    std::int64_t size = 1000;
    int nets = 10;
    std::uint64_t seed = 1;
    std::string map;
    int scale = 10;
  };
  auto args = std::make_shared<Args>();
  std::string kinds;
  for (const auto& k : io::gen_kind_names()) kinds += (kinds.empty() ? "" : ", ") + k;
  CLI::App* sub = app.add_subcommand("gen", "Write a generated layout for tests and benchmarks");
  sub->add_option("KIND", args->kind, "one of: " + kinds + ", movingai (with --map)")->required();
  sub->add_option("-o,--output", args->out, "layout file to write")->required();
  sub->add_option("--size", args->size, "target number of blockage vertices")
      ->check(CLI::Range(std::int64_t{4}, std::int64_t{20'000'000}));
  sub->add_option("--nets", args->nets, "number of two-pin nets")->check(CLI::Range(0, 10'000'000));
  sub->add_option("--seed", args->seed, "random seed (same seed, same file)");
  CLI::Option* map_opt = sub->add_option("--map", args->map, "movingai: a Moving AI .map grid map");
  CLI::Option* scale_opt = sub->add_option("--scale", args->scale, "movingai: DBU per grid cell")
                               ->check(CLI::Range(1, 1'000'000));
  CLI::Option* size_opt = sub->get_option("--size");
  CLI::Option* nets_opt = sub->get_option("--nets");
  CLI::Option* seed_opt = sub->get_option("--seed");
  sub->callback([args, &status, map_opt, scale_opt, size_opt, nets_opt, seed_opt] {
    if (args->kind == "movingai") {
      // Blocked cells become rect blockages (one per horizontal run); no nets are made.
      if (args->map.empty()) {
        print_usage_error("CLI-0011", "gen movingai needs --map FILE");
        status = kInvalid;
        return;
      }
      for (CLI::Option* o : {size_opt, nets_opt, seed_opt}) {
        if (o->count() > 0) {
          print_usage_error("CLI-0012", "gen movingai does not take " + o->get_name());
          status = kInvalid;
          return;
        }
      }
      io::MovingAiResult r = io::load_movingai_map(args->map, args->scale);
      print_diagnostics(r.diagnostics);
      if (!r.layout) {
        status = kInvalid;
        return;
      }
      status = write_output(args->out, io::layout_to_xml(*r.layout)) ? kOk : kInvalid;
      return;
    }
    for (CLI::Option* o : {map_opt, scale_opt}) {
      if (o->count() > 0) {
        print_usage_error("CLI-0012", "gen " + args->kind + " does not take " + o->get_name());
        status = kInvalid;
        return;
      }
    }
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
