// same_document: structural equality of two layouts, ignoring where they came from (file name
// and source line numbers), so a layout read back from the writer's output compares equal.
// canonical_orientations: c: sets that name the rectilinear or octilinear directions.
#include "io/layout.h"

#include "geom/directions.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

namespace taut::io {
namespace {

// Copies with every line number zeroed; the defaulted operator== then compares the rest.
Shape strip(Shape s) {
  s.line = 0;
  s.hole_lines.clear();
  return s;
}
Blockage strip(Blockage b) {
  b.line = 0;
  for (Shape& s : b.shapes) s = strip(s);
  return b;
}
Net strip(Net n) {
  n.line = 0;
  for (Pin& p : n.pins) {
    p.line = 0;
    if (p.shape) p.shape = strip(*p.shape);
  }
  if (n.sketch) n.sketch->line = 0;
  return n;
}
Routes strip(Routes r) {
  r.line = 0;
  for (Route& route : r.routes) {
    route.line = 0;
    for (Wire& w : route.wires) w.line = 0;
  }
  return r;
}

template <class T, class F>
bool same_vector(const std::vector<T>& a, const std::vector<T>& b, F strip_one) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(strip_one(a[i]) == strip_one(b[i]))) return false;
  return true;
}

}  // namespace

bool same_document(const Layout& a, const Layout& b) {
  if (a.name != b.name || a.version != b.version || a.dbu_per_micron != b.dbu_per_micron)
    return false;
  if (a.boundary.has_value() != b.boundary.has_value()) return false;
  if (a.boundary && a.boundary->box != b.boundary->box) return false;
  if (a.rules.has_value() != b.rules.has_value()) return false;
  if (a.rules) {
    Rules ra = *a.rules, rb = *b.rules;
    ra.line = rb.line = 0;
    if (!(ra == rb)) return false;
  }
  if (!same_vector(a.blockages, b.blockages, [](const Blockage& x) { return strip(x); }))
    return false;
  if (!same_vector(a.nets, b.nets, [](const Net& x) { return strip(x); })) return false;
  if (a.routes.has_value() != b.routes.has_value()) return false;
  if (a.routes && !(strip(*a.routes) == strip(*b.routes))) return false;
  return true;
}

std::string canonical_orientations(std::string_view text) {
  // the one reading of c: directions (geom/directions.h): exact decimals, modulo 180 degrees
  if (text.substr(0, 2) != "c:") return std::string(text);
  const std::optional<geom::LatticeDirections> set = geom::LatticeDirections::parse(text);
  if (set && (set->is_rectilinear() || set->is_octilinear())) return set->name();
  return std::string(text);
}

std::size_t distinct_orientations(const std::vector<double>& degrees) {
  std::vector<double> mod;
  for (const double d : degrees) mod.push_back(std::fmod(std::fmod(d, 180.0) + 180.0, 180.0));
  std::sort(mod.begin(), mod.end());
  mod.erase(std::unique(mod.begin(), mod.end()), mod.end());
  return mod.size();
}

}  // namespace taut::io
