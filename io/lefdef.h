// Reads one routing layer of a placed design in DEF, with its cells from LEF, into a Layout:
// `taut import`. The subset a planar (one-layer) routing problem needs, such as a flip-chip
// redistribution layer (bumps joined to pad cells):
//
//   DEF  UNITS DISTANCE MICRONS, DESIGN, DIEAREA (a rectangle: the boundary), COMPONENTS (macro,
//        placement point, orientation N S E W FN FS FE FW), PINS (ports: LAYER rectangles and
//        POLYGONs, each port with its own placement), NETS and SPECIALNETS (connections
//        `( comp pin )`, `( PIN name )`, `( * pin )`, `+ USE`; SPECIALNETS wiring on the layer:
//        `+ ROUTED|FIXED|COVER|SHIELD layer width [+ SHAPE ..] ( x y ) ( x|* y|* ) [via] NEW ..`),
//        BLOCKAGES (`- LAYER l .. RECT|POLYGON`). Every other section and statement is skipped
//        whole (it says nothing about the layer's metal or connectivity).
//   LEF  MACRO: ORIGIN, SIZE, PIN .. PORT (LAYER, RECT [MASK n], POLYGON [MASK n]), OBS. Every
//        other statement and block is skipped whole. Lengths are in microns and must be whole
//        DBU at the DEF's units (checked exactly, no floating point).
//
// What the layout holds, all on the chosen layer:
//   - <boundary>: the die area; <rules>: the wire width and spacing given (DBU).
//   - one <net> per selected net (glob patterns, default every net) with two or more pin
//     shapes; its pins are the shapes of its terminals: a component pin's port shapes placed
//     and oriented, a DEF pin's port shapes. A power or ground net (`+ USE POWER|GROUND`) also
//     takes every component pin of its own name with a shape on the layer, as `( * name )`
//     does (the global connection that a flow's `add_global_connection` makes). Identical shapes
//     of one net (a DEF pin drawn on its bump) are one pin. A terminal with several shapes gives
//     one pin per shape (the router joins them all: longer, never wrong).
//   - one <blockage> per other metal: cell obstructions (OBS) of every instance, component pins
//     and DEF pins on the layer that belong to no selected net, DEF BLOCKAGES on the layer, and
//     the SPECIALNETS wiring on the layer of nets not selected (each segment as the rectangle
//     it covers: half the width to each side, and along the wire to its points and their
//     extension values, as OpenDB reads a special wire).
//
// Vias: LEF and DEF (VIAS) vias are placed with their orientation (and arrays, DO .. BY .. STEP);
// after a via a wire goes on on the via's other routing layer (by the LEF layer TYPEs, else its
// first and last layers), as OpenDB reads it. A terminal a net names explicitly is never taken by
// another net's `( * pin )` or global connection, whichever nets are selected.
//
// Diagnostics (file:line, never a crash; errors leave no layout):
//   IO-0120 a file cannot be read
//   IO-0121 a syntax error (an unexpected token or end of file) in LEF or DEF
//   IO-0122 a construct outside the subset above that would change the layer's metal (LEF
//           ITERATE or PATH on the layer, a generated via on the layer, a non-rectangular
//           DIEAREA, regular NETS wiring on the layer of a net not written, a wiring segment that
//           is not axis-parallel or of odd width, a via after which the layer is unknown, an
//           unplaced cell or a cell without SIZE turned, with shapes on the layer, SUBNET,
//           MUSTJOIN)
//   IO-0123 a number that is malformed, not whole DBU, or beyond the coordinate range (or a
//           MACRO SIZE that is not positive)
//   IO-0124 a reference to an undefined macro, component, macro pin, DEF pin or via
//   IO-0125 a --nets pattern that matches no net, or a layer no shape is on
//   IO-0126 warning: a selected net with fewer than two pin shapes on the layer (not written as
//           a net; its shape, if any, is a blockage), or an explicit terminal with no shape on
//           the layer
//   IO-0127 warning: the wiring a selected net already has in the DEF is not kept (taut routes
//           the net)
//   IO-0128 warning: --bump-to-pad joined no bump to some of a net's pad pins (more pads than
//           bumps); they are written as blockages
//   IO-0129 a component or DEF pin defined twice, or a terminal in two nets
//   IO-0130 a name written to the layout (design, net, pin, blockage id) with a byte XML cannot carry
//           (no UTF-8 character, or a control character): two such names could become one
//   IO-0131 warning: a LEF MACRO defined again, in one LEF or across --lef files (the later
//           definition is used)
// Every object written carries the DEF line it comes from (a component's, a pin's, a net's), so
// validating the layout names it. Numbers of shapes off the layer are not converted (they need
// not be whole DBU).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geom/diagnostic.h"
#include "io/layout.h"

namespace taut::io {

struct DefImportOptions {
  std::string layer;                  // the routing layer, e.g. "metal10"
  std::vector<std::string> nets;      // glob patterns (* ? [..]); empty: every net
  std::string wire_width = "0";       // microns, as written (exact decimal)
  std::string spacing = "0";          // microns, as written
  // A net with bumps (pins of CLASS COVER cells) and other pins becomes one net per bump, joined
  // to one of the other pins: the assignment of least total L1 distance between the shapes' box
  // centres. With more bumps than pads each pad is offered ceil(bumps / pads) times and takes its
  // bumps in one net (named by the first), so no pad is a pin of two nets. As a flip-chip
  // redistribution layer is routed: a power net's pads are already joined by the pad ring, so
  // each bump needs one.
  bool bump_to_pad = false;
  // The selected nets' SPECIALNETS wiring on the layer is written as <routes> (each segment a
  // 2-point wire on its centreline, taken back to the corner where it was drawn past one), so
  // `taut check` and `taut stats` judge another router's result. Not with bump_to_pad.
  bool keep_wiring = false;
};

struct DefImportStats {
  std::size_t nets = 0, pins = 0, blockages = 0, components = 0;
};

struct DefImportResult {
  std::optional<Layout> layout;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
  DefImportStats stats;
};

DefImportResult import_def(const std::string& def_path, const std::vector<std::string>& lef_paths,
                           const DefImportOptions& options);

// The same from text in memory: each pair is (name used in diagnostics, text).
DefImportResult import_def_text(const std::pair<std::string, std::string>& def,
                                const std::vector<std::pair<std::string, std::string>>& lefs,
                                const DefImportOptions& options);

}  // namespace taut::io
