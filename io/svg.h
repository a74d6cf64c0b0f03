// SVG picture of a layout: boundary, blockages (holes cut out), pins, sketches and routes,
// scaled to fit, with a legend; readable at a glance.
#pragma once

#include <string>

#include "io/layout.h"

namespace taut::io {

struct SvgOptions {
  int width_px = 1200;        // longest side of the picture in pixels
  bool labels = true;         // blockage ids, net and pin names
};

std::string layout_to_svg(const Layout& layout, const SvgOptions& options = {});

}  // namespace taut::io
