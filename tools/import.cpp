// taut import DESIGN.def --lef LIB.lef [--lef ..] --layer L [--nets "PAT .."] [--wire-width UM]
// [--spacing UM] -o OUT.xml: one routing layer of a placed DEF design as a taut layout
// (io/lefdef.h says what is read and how).
#include <iostream>
#include <sstream>

#include "io/layout_writer.h"
#include "io/lefdef.h"
#include "io/validate_layout.h"
#include "tools/cli.h"
#include "tools/commands.h"

namespace taut::cli {

void add_import(CLI::App& app, int& status) {
  struct Args {
    std::string def, out, layer, nets, width = "0", spacing = "0";
    std::vector<std::string> lefs;
    bool quiet = false, bump_to_pad = false, keep_wiring = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "import", "Write one routing layer of a placed DEF design (cells from LEF) as a layout: its nets' pin shapes, and every "
                "other shape on the layer as a blockage");
  sub->add_option("DEF", args->def, "the placed design (DEF)")->required();
  sub->add_option("--lef", args->lefs, "a LEF file with the design's macros (and vias); repeat for several")->required();
  sub->add_option("--layer", args->layer, "the routing layer, e.g. metal10")->required();
  sub->add_option("--nets", args->nets,
                  "the nets to route: glob patterns separated by spaces, e.g. \"VDD VSS p_*\" (default: every net; a "
                  "pattern that matches no net is an error)");
  sub->add_option("--wire-width", args->width, "wire width in microns (written as <rules wire-width> in DBU; must be whole DBU)");
  sub->add_option("--spacing", args->spacing, "spacing in microns (written as <rules spacing> in DBU; must be whole DBU)");
  sub->add_option("-o,--output", args->out, "layout file to write")->required();
  sub->add_flag("--bump-to-pad", args->bump_to_pad,
                "a net with bumps (CLASS COVER cells) and other pins becomes a net per bump, joined to one pad pin: the "
                "assignment of least total distance (a flip-chip RDL: the pad ring already joins a power net's pads)");
  sub->add_flag("--keep-wiring", args->keep_wiring,
                "write the selected nets' SPECIALNETS wiring on the layer as <routes> (centrelines), for taut check and taut "
                "stats to judge another router's result");
  sub->add_flag("-q,--quiet", args->quiet, "do not print warnings or the summary");
  sub->callback([args, &status] {
    if (args->keep_wiring && args->bump_to_pad) {
      print_usage_error("CLI-0032", "import: --keep-wiring and --bump-to-pad together are not supported (the kept wiring "
                                    "would have to be split among the bumps' nets)");
      status = kInvalid;
      return;
    }
    io::DefImportOptions o;
    o.layer = args->layer;
    std::istringstream in(args->nets);
    for (std::string p; in >> p;) o.nets.push_back(p);
    o.wire_width = args->width;
    o.spacing = args->spacing;
    o.bump_to_pad = args->bump_to_pad;
    o.keep_wiring = args->keep_wiring;
    io::DefImportResult r = io::import_def(args->def, args->lefs, o);
    if (r.layout) {  // what taut check would say of the file: refused here, not at route time
      r.layout->file = args->def;
      for (Diagnostic& d : io::validate_layout(*r.layout)) {
        d.message = "(imported) " + d.message;
        r.diagnostics.push_back(std::move(d));
      }
    }
    print_diagnostics(r.diagnostics, args->quiet);
    if (!r.layout || has_error(r.diagnostics)) {
      status = kInvalid;
      return;
    }
    if (!write_output(args->out, io::layout_to_xml(*r.layout))) {
      status = kInvalid;
      return;
    }
    if (!args->quiet)
      std::cerr << "imported layer " << o.layer << " of " << r.layout->name << ": " << r.stats.nets << " nets with "
                << r.stats.pins << " pin shapes, " << r.stats.blockages << " blockages (" << r.stats.components
                << " components)\n";
    status = kOk;
  });
}

}  // namespace taut::cli
