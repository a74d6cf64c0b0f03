// Atomic output: write to a temporary file in the destination's folder, fsync, then rename
// over the destination. An interrupted run leaves the previous file intact.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "geom/diagnostic.h"

namespace taut::io {

// Returns a diagnostic (code IO-xxxx) on failure; nothing is left behind on failure.
std::optional<Diagnostic> write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace taut::io
