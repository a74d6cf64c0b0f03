// Semantic validation of a layout that parsed: geometry validity of every rect, polygon and
// hole (via geom/validate.h), duplicate blockage ids / net names / pin names, pins inside a
// blockage's interior or outside the boundary, nets with fewer than two pins (warning), sketch
// endpoints. Every diagnostic names the file, line and object.
#pragma once

#include <vector>

#include "geom/diagnostic.h"
#include "io/layout.h"

namespace taut::io {

std::vector<Diagnostic> validate_layout(const Layout& layout);

}  // namespace taut::io
