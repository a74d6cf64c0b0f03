// taut gen KIND -o OUT [--size N] [--nets M] [--pins K|LO-HI] [--width W] [--spacing S] [--seed S]:
// seeded, reproducible layouts.
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
    std::string pins = "2";
    std::int64_t width = 0, spacing = 0;
  };
  auto args = std::make_shared<Args>();
  std::string kinds;
  for (const auto& k : io::gen_kind_names()) kinds += (kinds.empty() ? "" : ", ") + k;
  CLI::App* sub = app.add_subcommand("gen", "Write a generated layout for tests and benchmarks");
  sub->add_option("KIND", args->kind, "one of: " + kinds + ", movingai (with --map)")->required();
  sub->add_option("-o,--output", args->out, "layout file to write")->required();
  sub->add_option("--size", args->size, "target number of blockage vertices")
      ->check(CLI::Range(std::int64_t{4}, std::int64_t{20'000'000}));
  sub->add_option("--nets", args->nets, "number of nets")->check(CLI::Range(0, 10'000'000));
  sub->add_option("--pins", args->pins,
                  "pins per net: K, or LO-HI drawn uniformly (2 to 1000; with more than two, a net's pins lie within a "
                  "tenth of the layout's side of its first)");
  sub->add_option("--width", args->width, "write <rules wire-width> (and keep pins of different nets 2(w + s) + 2 apart)")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{1'000'000}));
  sub->add_option("--spacing", args->spacing, "write <rules spacing>")->check(CLI::Range(std::int64_t{0}, std::int64_t{1'000'000}));
  sub->add_option("--seed", args->seed, "random seed (same seed, same file)");
  CLI::Option* map_opt = sub->add_option("--map", args->map, "movingai: a Moving AI .map grid map");
  CLI::Option* scale_opt = sub->add_option("--scale", args->scale, "movingai: DBU per grid cell")
                               ->check(CLI::Range(1, 1'000'000));
  CLI::Option* size_opt = sub->get_option("--size");
  CLI::Option* nets_opt = sub->get_option("--nets");
  CLI::Option* seed_opt = sub->get_option("--seed");
  CLI::Option* pins_opt = sub->get_option("--pins");
  CLI::Option* width_opt = sub->get_option("--width");
  CLI::Option* spacing_opt = sub->get_option("--spacing");
  sub->callback([args, &status, map_opt, scale_opt, size_opt, nets_opt, seed_opt, pins_opt, width_opt, spacing_opt] {
    if (args->kind == "movingai") {
      // Blocked cells become rect blockages (one per horizontal run); no nets are made.
      if (args->map.empty()) {
        print_usage_error("CLI-0011", "gen movingai needs --map FILE");
        status = kInvalid;
        return;
      }
      for (CLI::Option* o : {size_opt, nets_opt, seed_opt, pins_opt, width_opt, spacing_opt}) {
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
    {
      // --pins K or LO-HI
      const std::string& t = args->pins;
      const auto dash = t.find('-');
      auto number = [](const std::string& w) -> int {
        if (w.empty() || w.size() > 4 || w.find_first_not_of("0123456789") != std::string::npos) return -1;
        return std::stoi(w);
      };
      const int lo = number(t.substr(0, dash)), hi = dash == std::string::npos ? lo : number(t.substr(dash + 1));
      if (lo < 2 || hi < lo || hi > 1000) {
        print_usage_error("CLI-0031", "gen --pins " + t + ": give K or LO-HI with 2 <= LO <= HI <= 1000");
        status = kInvalid;
        return;
      }
      o.min_pins = lo;
      o.max_pins = hi;
    }
    o.wire_width = args->width;
    o.spacing = args->spacing;
    o.kind = *kind;
    o.size = args->size;
    o.nets = args->nets;
    o.seed = args->seed;
    status = write_output(args->out, io::layout_to_xml(io::generate_layout(o))) ? kOk : kInvalid;
  });
}

}  // namespace taut::cli
