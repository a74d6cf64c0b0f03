// taut render FILE -o PIC.svg: a picture of a layout, with its routes if it has any.
#include "io/svg.h"
#include "tools/cli.h"
#include "tools/commands.h"

namespace taut::cli {

void add_render(CLI::App& app, int& status) {
  struct Args {
    std::string file, out;
    int width = 1200;
    bool no_labels = false;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("render", "Draw a layout (and its routes) as SVG");
  sub->add_option("-o,--output", args->out, "SVG file to write")->required();
  sub->add_option("--width", args->width, "longest side in pixels")->check(CLI::Range(100, 20000));
  sub->add_flag("--no-labels", args->no_labels, "omit names of blockages, nets and pins");
  add_input_options(sub, args->file, args->load, "do not print warnings");
  sub->callback([args, &status] {
    auto layout = load_layout(args->file, args->load);
    if (!layout) {
      status = kInvalid;
      return;
    }
    io::SvgOptions so;
    so.width_px = args->width;
    so.labels = !args->no_labels;
    status = write_output(args->out, io::layout_to_svg(*layout, so)) ? kOk : kInvalid;
  });
}

}  // namespace taut::cli
