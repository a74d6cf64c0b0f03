// Writes a layout back as FORMAT.md XML (with <routes> when present). Reading what it writes
// gives the same document (same_document in layout.h).
#pragma once

#include <string>

#include "io/layout.h"

namespace taut::io {

std::string layout_to_xml(const Layout& layout);

}  // namespace taut::io
