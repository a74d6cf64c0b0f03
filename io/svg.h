// SVG picture of a layout: boundary, blockages (holes cut out), pins, sketches and routes,
// scaled to fit, with a legend; readable at a glance.
#pragma once

#include <string>

#include "io/layout.h"

namespace taut::io {

struct SvgOptions {
  int width_px = 1200;        // longest side of the picture in pixels
  bool labels = true;         // blockage ids, net and pin names
  // Extra SVG elements in layout coordinates (y up, one unit per DBU): `underlay` is drawn over
  // the boundary and under the blockages (Voronoi regions), `overlay` over everything else.
  // A length written "@PX" in them (stroke-width="@1.5", r="@4") is PX pixels at any scale.
  std::string underlay, overlay;
  std::string caption;        // appended to the legend's summary line
};

std::string layout_to_svg(const Layout& layout, const SvgOptions& options = {});

}  // namespace taut::io
