// Reads a Moving AI grid map (.map: "type", "height H", "width W", "map", then H rows of W
// characters; '.', 'G', 'S' passable, anything else blocked) into a Layout for routing.
//
// Cell (c, r) (column c, row r from the top) becomes the square
// [c*scale, (c+1)*scale] x [(H-1-r)*scale, (H-r)*scale]; the blocked cells of a row are merged
// into maximal horizontal runs, one blockage with one <rect> per run, id "r<row>c<col>" (its
// first cell); the boundary is the whole map. Runs of neighbouring rows touch along edges and
// at corners, which normalize_obstacles() merges.
//
// Diagnostics (file:line, never a crash):
//   IO-0090 the file cannot be read
//   IO-0091 malformed header (missing or bad "type", "height", "width" or "map" line)
//   IO-0092 a row is missing or does not have exactly W characters
//   IO-0093 the map does not fit the coordinate range at this scale (or scale < 1)
//   IO-0094 non-empty text after the last row
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geom/diagnostic.h"
#include "io/layout.h"

namespace taut::io {

struct MovingAiResult {
  std::optional<Layout> layout;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
};

MovingAiResult load_movingai_map(const std::string& path, geom::Coord scale = 10);
// Same, from text in memory; `name` is the file name used in diagnostics.
MovingAiResult parse_movingai_map(std::string_view text, const std::string& name,
                                  geom::Coord scale = 10);

}  // namespace taut::io
