// Statistics of a layout as JSON (nlohmann-json): counts of blockages, vertices, nets, pins;
// per net (pins, and for routed layouts length, bends, status, reason) and totals.
#pragma once

#include <string>

#include "io/layout.h"

namespace taut::io {

// Exact Euclidean length of a polyline as FORMAT.md writes it: an integer when every segment
// is axis-parallel, otherwise a decimal with 3 fractional digits.
std::string format_length(const std::vector<Point>& polyline);
// The same for the total length of several polylines (the wires of a net), rounded once.
std::string format_total_length(const std::vector<std::vector<Point>>& polylines);
// Direction changes inside a polyline (collinear continuations do not count).
long count_bends(const std::vector<Point>& polyline);

std::string layout_stats_json(const Layout& layout, int indent = 2);

}  // namespace taut::io
