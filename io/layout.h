// The in-memory layout: exactly what FORMAT.md describes, with the source line of every object
// so diagnostics can point at it. Plain data; readers and writers live beside it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geom/types.h"

namespace taut::io {

using geom::Box;
using geom::Point;
using geom::Polygon;

// A <rect> or <polygon> (with <hole>s) as written; `rect` is set for <rect>.
struct Shape {
  enum class Kind { Rect, Polygon } kind = Kind::Rect;
  Box rect;            // Kind::Rect
  Polygon polygon;     // Kind::Polygon, vertices as written (closing vertex dropped)
  int line = 0;
  std::vector<int> hole_lines;  // line of each <hole>, same order as polygon.holes
  friend bool operator==(const Shape&, const Shape&) = default;
};

struct Boundary {
  Box box;
  int line = 0;
  friend bool operator==(const Boundary&, const Boundary&) = default;
};

struct Rules {
  std::int64_t wire_width = 0;
  std::int64_t spacing = 0;
  std::int64_t bend_cost = 0;
  std::string orientations = "rectilinear";  // rectilinear | octilinear | any | c:a,b,...
  std::vector<double> orientation_degrees;   // parsed directions for c: sets (else empty)
  int line = 0;
  friend bool operator==(const Rules&, const Rules&) = default;
};

struct Blockage {
  std::string id;
  std::vector<Shape> shapes;  // their union is the blockage
  int line = 0;
  friend bool operator==(const Blockage&, const Blockage&) = default;
};

struct Pin {
  std::string name;
  std::optional<Point> point;  // a point pin ...
  std::optional<Shape> shape;  // ... or a shape pin (exactly one is set)
  int line = 0;
  friend bool operator==(const Pin&, const Pin&) = default;
};

struct Sketch {
  std::vector<Point> points;
  int line = 0;
  friend bool operator==(const Sketch&, const Sketch&) = default;
};

struct Net {
  std::string name;
  std::vector<Pin> pins;
  std::optional<Sketch> sketch;
  int line = 0;
  friend bool operator==(const Net&, const Net&) = default;
};

struct Wire {
  std::vector<Point> points;
  int line = 0;
  friend bool operator==(const Wire&, const Wire&) = default;
};

struct Route {
  std::string net;
  std::string status;               // "routed" | "failed"
  std::optional<std::string> length;  // as written: integer or decimal with 3 digits
  std::optional<std::int64_t> bends;
  std::optional<std::string> reason;
  std::vector<Wire> wires;
  int line = 0;
  friend bool operator==(const Route&, const Route&) = default;
};

struct Routes {
  std::string tool;
  std::string metric;        // attribute as written (may be empty)
  std::string orientations;  // attribute as written (may be empty)
  std::vector<Route> routes;
  int line = 0;
  // metric="combined": the C the wires were routed with (the last field, so that aggregate
  // initialisation written before it existed still compiles)
  std::optional<std::int64_t> bend_cost;
  friend bool operator==(const Routes&, const Routes&) = default;
};

struct Layout {
  std::string name;
  int version = 1;
  std::int64_t dbu_per_micron = 1000;
  std::optional<Boundary> boundary;
  std::optional<Rules> rules;
  std::vector<Blockage> blockages;
  std::vector<Net> nets;
  std::optional<Routes> routes;
  std::string file;  // where it was read from (for diagnostics); not part of the document
  int line = 0;
};

// The same document: equal in every field except `file` and the source line numbers (a layout
// read back from what the writer wrote has other line numbers).
bool same_document(const Layout& a, const Layout& b);

// An orientations value with a c: set written by its name when it is one: the directions modulo
// 180 degrees exactly {0, 90} are "rectilinear", exactly {0, 45, 90, 135} "octilinear" (e.g.
// c:90,0 or c:0,45,90,135,180). Anything else is returned unchanged.
std::string canonical_orientations(std::string_view text);

// How many distinct directions modulo 180 degrees a c: set's degrees give (LAYOUT-0014 for
// <rules>, IO-0015 for <routes>: fewer than 2 cannot connect points in the plane).
std::size_t distinct_orientations(const std::vector<double>& degrees);

}  // namespace taut::io
