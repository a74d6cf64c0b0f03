// Seeded, reproducible layout generators for tests and benchmarks (`taut gen`).
// The same kind, size, nets and seed give the same layout byte for byte on every machine
// (std::mt19937_64 with hand-written integer range mapping, no std::uniform_*_distribution).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/layout.h"

namespace taut::io {

enum class GenKind {
  Rects,       // "rects": random axis-parallel rectangles, may overlap and touch
  Polygons,    // "polygons": random simple polygons (star-shaped), may overlap
  Maze,        // "maze": rectilinear maze walls on a grid (blockages touch along edges)
  Degenerate,  // "degenerate": coarse-grid rectangles/polygons sharing x, y, collinear edges,
               // touching at corners and along edges
  Channel,     // "channel": teeth cutting into the boundary from below and above (rectangles and
               // steps on a 100-DBU grid, neighbours on one side may touch), so free space is one
               // simple rectilinear polygon: a winding channel (`taut diameter`); the boundary is
               // the teeth's box, with no margin
};
std::optional<GenKind> parse_gen_kind(const std::string& name);
std::string gen_kind_name(GenKind kind);
std::vector<std::string> gen_kind_names();

struct GenOptions {
  GenKind kind = GenKind::Rects;
  std::int64_t size = 1000;   // target number of blockage vertices (up to 10^6 and beyond)
  int nets = 10;              // nets with point pins in free space
  std::uint64_t seed = 1;
  // Pins per net, drawn uniformly from [min_pins, max_pins] (2..1000). With more than two pins
  // (max_pins > 2) every pin after a net's first lies within a square of a tenth of the layout's
  // side round the first (nets of placed cells are local); two-pin nets keep the default
  // sequence, so the same options give the same file as before pins could be chosen.
  int min_pins = 2, max_pins = 2;
  // <rules wire-width spacing> written when either is > 0; pins of different nets are then kept
  // at least 2(w + s) + 2 apart (L-infinity) so each can be reached.
  std::int64_t wire_width = 0, spacing = 0;
};

// The generated layout is valid: validate_layout() reports no error on it.
Layout generate_layout(const GenOptions& options);

}  // namespace taut::io
