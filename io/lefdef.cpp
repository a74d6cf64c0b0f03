// import_def: see lefdef.h. A token reader (LEF and DEF are whitespace-separated tokens, `;`
// ending statements, `#` comments), one recursive-descent pass per file that keeps only what the
// layer needs, then the layout is assembled: placed and oriented shapes, nets, blockages.
//
// (By hand: Debian packages no LEF/DEF parser; Si2's reference parser is not in Debian, and the
// subset a planar layer needs is small.)
#include "io/lefdef.h"

#include "io/xml_text.h"

#include "geom/normalize.h"
#include "io/stats_json.h"

#include <fnmatch.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace taut::io {
namespace {

struct Tok {
  std::string_view s;
  int line = 0;
};

struct Failure {
  std::string code;
  std::string file;
  int line = 0;
  std::string message;
};

std::vector<Tok> tokenize(std::string_view text) {
  std::vector<Tok> out;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; };
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (space(c)) {
      ++i;
    } else if (c == '#') {  // a comment, to the end of the line
      while (i < n && text[i] != '\n') ++i;
    } else if (c == '"') {  // a quoted string is one token
      std::size_t j = i + 1;
      const int l0 = line;
      while (j < n && text[j] != '"') line += text[j++] == '\n';
      j = std::min(j + 1, n);
      out.push_back({text.substr(i, j - i), l0});
      i = j;
    } else {
      std::size_t j = i;
      while (j < n && !space(text[j])) ++j;
      const std::string_view t = text.substr(i, j - i);
      if (t.size() > 1 && t.back() == ';') {  // "N;" as "N" ";"
        out.push_back({t.substr(0, t.size() - 1), line});
        out.push_back({t.substr(t.size() - 1), line});
      } else {
        out.push_back({t, line});
      }
      i = j;
    }
  }
  return out;
}

// s with every byte outside printable ASCII as \xNN, for a message
std::string shown(std::string_view s) {
  std::string out;
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    if (u >= 0x20 && u < 0x7F) {
      out += ch;
    } else {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\x%02X", static_cast<unsigned>(u));
      out += esc;
    }
  }
  return out;
}

class Cursor {
 public:
  Cursor(std::vector<Tok> toks, std::string file) : t_(std::move(toks)), file_(std::move(file)) {}
  bool done() const { return k_ >= t_.size(); }
  int line() const { return done() ? (t_.empty() ? 0 : t_.back().line) : t_[k_].line; }
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& code, const std::string& msg, int line = -1) const {
    throw Failure{code, file_, line < 0 ? this->line() : line, msg};
  }
  const Tok& peek() const {
    if (done()) fail("IO-0121", "unexpected end of file");
    return t_[k_];
  }
  // the token after the next one ("" at the end)
  std::string_view peek2() const { return k_ + 1 < t_.size() ? t_[k_ + 1].s : std::string_view{}; }
  Tok next() {
    const Tok t = peek();
    ++k_;
    return t;
  }
  bool accept(std::string_view s) {
    if (!done() && t_[k_].s == s) {
      ++k_;
      return true;
    }
    return false;
  }
  void expect(std::string_view s) {
    const Tok t = next();
    if (t.s != s) fail("IO-0121", "expected \"" + std::string(s) + "\", found \"" + std::string(t.s) + "\"", t.line);
  }
  void skip_statement() {
    while (next().s != ";") {
    }
  }
  // k is END: the block `kind` `name` ends here (its END must name it)
  bool ends(const Tok& k, std::string_view kind, std::string_view name) {
    if (k.s != "END") return false;
    const Tok e = next();
    if (e.s != name)
      fail("IO-0121", std::string(kind) + " " + std::string(name) + " ends with END " + std::string(e.s), e.line);
    return true;
  }
  // k is END and the next token is `name` (consumed): a block that may hold other ENDs closes
  bool closes(const Tok& k, std::string_view name) { return k.s == "END" && !done() && t_[k_].s == name && (++k_, true); }
  // past the tokens "END <name>" (a block whose inner ENDs name other things)
  void skip_block(std::string_view name) {
    for (;;) {
      const Tok t = next();
      if (t.s == "END" && !done() && t_[k_].s == name) {
        ++k_;
        return;
      }
    }
  }

 private:
  std::vector<Tok> t_;
  std::string file_;
  std::size_t k_ = 0;
};

std::int64_t def_int(const Cursor& c, const Tok& t) {
  std::int64_t v = 0;
  const char* b = t.s.data();
  const char* e = b + t.s.size();
  if (!t.s.empty() && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec != std::errc() || p != e || b == e) c.fail("IO-0123", "\"" + std::string(t.s) + "\" is not an integer", t.line);
  if (!geom::in_range(v)) c.fail("IO-0123", std::string(t.s) + " is beyond the coordinate range (|v| <= 2^30 - 1)", t.line);
  return v;
}

// microns as written, times `units` DBU per micron: exact, or an error naming what was written
std::optional<std::int64_t> exact_dbu(std::string_view s, std::int64_t units) {
  bool neg = false;
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
    neg = s[0] == '-';
    s.remove_prefix(1);
  }
  __int128 mant = 0;
  int frac = -1, digits = 0;
  for (const char ch : s) {
    if (ch == '.') {
      if (frac >= 0) return std::nullopt;
      frac = 0;
      continue;
    }
    if (ch < '0' || ch > '9') return std::nullopt;
    if (++digits > 18) return std::nullopt;
    mant = mant * 10 + (ch - '0');
    if (frac >= 0) ++frac;
  }
  if (digits == 0) return std::nullopt;
  __int128 v = mant * units, div = 1;
  for (int k = 0; k < std::max(frac, 0); ++k) div *= 10;
  if (v % div != 0) return std::nullopt;
  v /= div;
  if (neg) v = -v;
  if (v < -geom::kMaxCoord || v > geom::kMaxCoord) return std::nullopt;
  return static_cast<std::int64_t>(v);
}

std::int64_t lef_dbu(const Cursor& c, const Tok& t, std::int64_t units) {
  const auto v = exact_dbu(t.s, units);
  if (!v)
    c.fail("IO-0123", "\"" + std::string(t.s) + "\" microns is not a whole number of DBU at " + std::to_string(units) +
                          " DBU per micron (or is malformed, or beyond the coordinate range)", t.line);
  return *v;
}

// A shape on the layer: a rectangle (two corners) or a polygon's vertices.
struct Geo {
  bool rect = true;
  std::vector<Point> pts;
  int line = 0;
};

struct Via {
  std::vector<Geo> shapes;   // on the layer, relative to the via's origin
  bool generated_on_layer = false;  // a VIARULE-generated via whose LAYERS name the layer
  std::vector<std::string> layers;  // every layer it has a shape on, in order (generated: bottom, top)
};

struct MacroPin {
  std::vector<Geo> shapes;
};

struct Macro {
  std::int64_t w = 0, h = 0;
  std::map<std::string, MacroPin, std::less<>> pins;
  std::vector<std::string> pin_order;
  std::vector<Geo> obs;
  bool cover = false;  // CLASS COVER (a bump)
  bool has_size = false;
};

struct Lib {
  std::map<std::string, Macro, std::less<>> macros;
  std::map<std::string, std::pair<std::string, int>, std::less<>> macro_at;  // where each was defined (file, line)
  std::vector<Diagnostic> warnings;  // (IO-0131)
  std::map<std::string, Via, std::less<>> vias;
  std::map<std::string, std::string, std::less<>> layer_type;  // LEF LAYER .. TYPE (ROUTING, CUT, ..)
};

// The layer a wire continues on after via v, from layer `cur`: the via's other routing layer (by
// the LEF layer types when known, else its first and last layers). nullopt when cur is not one
// of them or there is no single other one.
std::optional<std::string> via_exit(const Via& v, std::string_view cur, const Lib& lib) {
  std::vector<std::string> routing;
  for (const std::string& l : v.layers) {
    const auto t = lib.layer_type.find(l);
    if (t != lib.layer_type.end() ? t->second == "ROUTING" : true) routing.push_back(l);
  }
  if (routing.size() > 2 && std::none_of(v.layers.begin(), v.layers.end(), [&](const std::string& l) { return lib.layer_type.count(l); }))
    routing = {routing.front(), routing.back()};
  if (routing.size() != 2 || (routing[0] != cur && routing[1] != cur)) return std::nullopt;
  return routing[0] == cur ? routing[1] : routing[0];
}

Point pt(std::int64_t x, std::int64_t y) { return Point{static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)}; }

// A rectangle's two corners, lower-left first, from any two opposite ones.
std::vector<Point> corners(Point a, Point b) {
  return {Point{std::min(a.x, b.x), std::min(a.y, b.y)}, Point{std::max(a.x, b.x), std::max(a.y, b.y)}};
}

// The next number of a LEF point, which may be written "( x y )".
Tok lef_number(Cursor& c) {
  while (c.peek().s == "(" || c.peek().s == ")") c.next();
  return c.next();
}

// RECT/POLYGON/VIA/PATH/ITERATE statement bodies inside LEF geometry (after the keyword).
void lef_rect(Cursor& c, const Tok& kw, std::int64_t units, bool on_layer, std::vector<Geo>& out) {
  if (c.accept("MASK")) c.next();
  if (c.peek().s == "ITERATE") c.fail("IO-0122", "RECT ITERATE is not supported", kw.line);
  if (!on_layer) {  // numbers off the layer are not converted: they need not be whole DBU here
    for (int k = 0; k < 4; ++k) lef_number(c);
    while (c.peek().s == ")") c.next();
    c.expect(";");
    return;
  }
  std::int64_t v[4];
  for (auto& x : v) x = lef_dbu(c, lef_number(c), units);
  while (c.peek().s == ")") c.next();
  c.expect(";");
  if (v[0] == v[2] || v[1] == v[3]) c.fail("IO-0121", "a RECT with no area", kw.line);
  out.push_back({true, corners(pt(v[0], v[1]), pt(v[2], v[3])), kw.line});
}

void lef_polygon(Cursor& c, const Tok& kw, std::int64_t units, bool on_layer, std::vector<Geo>& out) {
  if (c.accept("MASK")) c.next();
  if (c.peek().s == "ITERATE") c.fail("IO-0122", "POLYGON ITERATE is not supported", kw.line);
  if (!on_layer) {
    c.skip_statement();
    return;
  }
  std::vector<Point> p;
  while (c.peek().s != ";") {
    const std::int64_t x = lef_dbu(c, lef_number(c), units);
    if (c.peek().s == ";") c.fail("IO-0121", "a POLYGON with an odd number of coordinates", kw.line);
    p.push_back(pt(x, lef_dbu(c, lef_number(c), units)));
    while (c.peek().s == ")") c.next();
  }
  c.expect(";");
  if (p.size() < 3) c.fail("IO-0121", "a POLYGON with fewer than three vertices", kw.line);
  out.push_back({false, std::move(p), kw.line});
}

// LEF geometry (PORT, OBS, VIA bodies) up to its END (not consumed when `until_end` is false:
// a VIA body ends with END <name>, handled by the caller).
void lef_geometry(Cursor& c, std::int64_t units, const std::string& layer, const Lib& lib, std::vector<Geo>& out,
                  const std::string& where) {
  bool on = false;
  for (;;) {
    const Tok t = c.peek();
    if (t.s == "END") return;
    c.next();
    if (t.s == "LAYER") {
      on = c.next().s == layer;
      c.skip_statement();
    } else if (t.s == "RECT") {
      lef_rect(c, t, units, on, out);
    } else if (t.s == "POLYGON") {
      lef_polygon(c, t, units, on, out);
    } else if (t.s == "PATH") {
      if (on) c.fail("IO-0122", "PATH on layer " + layer + " (in " + where + ") is not supported", t.line);
      c.skip_statement();
    } else if (t.s == "VIA") {
      if (c.accept("MASK")) c.next();
      if (c.peek().s == "ITERATE") c.fail("IO-0122", "VIA ITERATE is not supported", t.line);
      const Tok tx = c.next(), ty = c.next();
      const Tok name = c.next();
      c.expect(";");
      const auto v = lib.vias.find(name.s);
      if (v == lib.vias.end()) c.fail("IO-0124", "via " + std::string(name.s) + " (in " + where + ") is not defined before it is used", name.line);
      if (v->second.generated_on_layer) c.fail("IO-0122", "generated via " + std::string(name.s) + " on layer " + layer + " is not supported", name.line);
      if (v->second.shapes.empty()) continue;  // nothing on the layer: its place need not be whole DBU
      const std::int64_t x = lef_dbu(c, tx, units), y = lef_dbu(c, ty, units);
      for (Geo g : v->second.shapes) {
        for (Point& p : g.pts) {
          if (!geom::in_range(std::int64_t{p.x} + x) || !geom::in_range(std::int64_t{p.y} + y))
            c.fail("IO-0123", "via " + std::string(name.s) + " (in " + where + ") placed beyond the coordinate range", t.line);
          p = pt(std::int64_t{p.x} + x, std::int64_t{p.y} + y);
        }
        g.line = t.line;
        out.push_back(std::move(g));
      }
    } else {
      c.skip_statement();
    }
  }
}

// A LEF "VIA name .. END name" block after its keyword: its shapes on the layer and its layers.
void lef_via(Cursor& c, std::int64_t units, const std::string& layer, Lib& lib) {
  const Tok name = c.next();
  Via v;
  bool on = false;
  for (;;) {
    const Tok k = c.next();
    if (c.closes(k, name.s)) break;
    if (k.s == "LAYER") {
      const Tok ln = c.next();
      on = ln.s == layer;
      if (std::find(v.layers.begin(), v.layers.end(), ln.s) == v.layers.end()) v.layers.emplace_back(ln.s);
      c.skip_statement();
    } else if (k.s == "RECT") {
      lef_rect(c, k, units, on, v.shapes);
    } else if (k.s == "POLYGON") {
      lef_polygon(c, k, units, on, v.shapes);
    } else if (k.s == "LAYERS") {  // a generated via: LAYERS bottom cut top ;
      std::vector<std::string> ls;
      while (c.peek().s != ";") ls.emplace_back(c.next().s);
      c.next();
      for (const std::string& l : ls) v.generated_on_layer = v.generated_on_layer || l == layer;
      if (ls.size() == 3) v.layers = {ls[0], ls[2]};
    } else if (k.s != "DEFAULT" && k.s != "GENERATED") {
      if (k.s != ";") c.skip_statement();
    }
  }
  lib.vias[std::string(name.s)] = std::move(v);
}

void parse_lef(Cursor& c, std::int64_t units, const std::string& layer, Lib& lib) {
  while (!c.done()) {
    const Tok t = c.next();
    if (t.s == "MACRO") {
      const Tok name = c.next();
      Macro m;
      std::optional<std::pair<Tok, Tok>> origin_t, size_tok;  // converted below only if the macro has shapes on the layer
      for (;;) {
        const Tok k = c.next();
        if (c.ends(k, "MACRO", name.s)) break;
        if (k.s == "ORIGIN") {
          const Tok x = c.next(), y = c.next();
          origin_t = {x, y};
          c.expect(";");
        } else if (k.s == "SIZE") {
          const Tok w = c.next();
          c.expect("BY");
          size_tok = {w, c.next()};
          c.expect(";");
        } else if (k.s == "PIN") {
          const Tok pn = c.next();
          MacroPin& mp = m.pins[std::string(pn.s)];
          if (std::find(m.pin_order.begin(), m.pin_order.end(), pn.s) == m.pin_order.end()) m.pin_order.emplace_back(pn.s);
          for (;;) {
            const Tok q = c.next();
            if (c.ends(q, "PIN", pn.s)) break;
            if (q.s == "PORT") {
              lef_geometry(c, units, layer, lib, mp.shapes, "PIN " + std::string(pn.s) + " of MACRO " + std::string(name.s));
              c.expect("END");
            } else {
              c.skip_statement();
            }
          }
        } else if (k.s == "OBS") {
          lef_geometry(c, units, layer, lib, m.obs, "OBS of MACRO " + std::string(name.s));
          c.expect("END");
        } else if (k.s == "CLASS") {
          m.cover = c.peek().s == "COVER";
          c.skip_statement();
        } else if (k.s == "DENSITY") {
          while (c.next().s != "END") {  // DENSITY .. END: no END <name>; skip to the bare END
          }
        } else {
          c.skip_statement();
        }
      }
      bool on = !m.obs.empty();
      for (const auto& [n, p] : m.pins) on = on || !p.shapes.empty();
      Point origin{0, 0};
      if (on && origin_t) origin = pt(lef_dbu(c, origin_t->first, units), lef_dbu(c, origin_t->second, units));
      if (on && size_tok) {
        m.w = lef_dbu(c, size_tok->first, units);
        m.h = lef_dbu(c, size_tok->second, units);
        m.has_size = true;
        // (a SIZE of no area flips the cell's shapes out of its footprint; found by fuzzing,
        // 2026-12-06, when it was accepted)
        if (m.w <= 0 || m.h <= 0)
          c.fail("IO-0123", "MACRO " + std::string(name.s) + ": SIZE " + std::string(size_tok->first.s) + " BY " +
                                std::string(size_tok->second.s) + " is not positive",
                 size_tok->first.line);
      }
      auto shift = [&](std::vector<Geo>& gs) {
        for (Geo& g : gs)
          for (Point& p : g.pts) {
            const std::int64_t x = std::int64_t{p.x} + origin.x, y = std::int64_t{p.y} + origin.y;
            if (!geom::in_range(x) || !geom::in_range(y))
              c.fail("IO-0123", "MACRO " + std::string(name.s) + ": a shape beyond the coordinate range with its ORIGIN", g.line);
            p = pt(x, y);
          }
      };
      for (auto& [n, p] : m.pins) shift(p.shapes);
      shift(m.obs);
      // a macro defined again (in this LEF or an earlier one): the later definition is used, as
      // before, but said (IO-0131, since 2026-12-06; found by fuzzing)
      if (const auto at = lib.macro_at.find(name.s); at != lib.macro_at.end())
        lib.warnings.push_back(Diagnostic{Severity::Warning, "IO-0131", c.file(), name.line, 0,
                                          "MACRO " + std::string(name.s) + " is defined again (first at " + at->second.first + ":" +
                                              std::to_string(at->second.second) + "): this definition is used"});
      lib.macro_at[std::string(name.s)] = {c.file(), name.line};
      lib.macros[std::string(name.s)] = std::move(m);
    } else if (t.s == "VIA") {
      lef_via(c, units, layer, lib);
    } else if (t.s == "LAYER") {  // its TYPE only (which layers a via joins)
      const Tok name = c.next();
      for (;;) {
        const Tok k = c.next();
        if (c.closes(k, name.s)) break;
        if (k.s == "TYPE") lib.layer_type[std::string(name.s)] = std::string(c.next().s);
        if (k.s != ";") c.skip_statement();
      }
    } else if (t.s == "NONDEFAULTRULE") {  // its vias are defined for the design to use
      const Tok name = c.next();
      for (;;) {
        const Tok k = c.next();
        if (c.closes(k, name.s)) break;
        if (k.s == "VIA") {
          lef_via(c, units, layer, lib);
        } else if (k.s == "LAYER") {
          c.skip_block(c.next().s);
        } else if (k.s != ";") {
          c.skip_statement();
        }
      }
    } else if (t.s == "SITE" || t.s == "VIARULE" || t.s == "ARRAY") {
      c.skip_block(c.next().s);
    } else if (t.s == "UNITS" || t.s == "PROPERTYDEFINITIONS" || t.s == "SPACING") {
      c.skip_block(t.s);
    } else if (t.s == "BEGINEXT") {
      while (c.next().s != "ENDEXT") {
      }
    } else if (t.s == "END") {
      c.expect("LIBRARY");
      return;
    } else {
      c.skip_statement();
    }
  }
}

// ---- DEF ----

enum class Orient { N, S, E, W, FN, FS, FE, FW };

std::optional<Orient> parse_orient(std::string_view s) {
  static const std::pair<std::string_view, Orient> k[] = {{"N", Orient::N},   {"S", Orient::S},   {"E", Orient::E},
                                                         {"W", Orient::W},   {"FN", Orient::FN}, {"FS", Orient::FS},
                                                         {"FE", Orient::FE}, {"FW", Orient::FW}};
  for (const auto& [n, o] : k)
    if (n == s) return o;
  return std::nullopt;
}

// The rotation or reflection of an orientation about the origin.
std::pair<std::int64_t, std::int64_t> turn(Orient o, std::int64_t x, std::int64_t y) {
  switch (o) {
    case Orient::N: return {x, y};
    case Orient::S: return {-x, -y};
    case Orient::W: return {-y, x};
    case Orient::E: return {y, -x};
    case Orient::FN: return {-x, y};
    case Orient::FS: return {x, -y};
    case Orient::FW: return {y, x};
    case Orient::FE: return {-y, -x};
  }
  return {x, y};
}

struct Placement {
  bool placed = false;
  std::int64_t x = 0, y = 0;
  Orient orient = Orient::N;
};

struct Component {
  std::string name, macro;
  int line = 0;
  Placement at;
};

struct DefPort {
  std::vector<Geo> shapes;  // relative to the port's placement
  Placement at;
  int line = 0;
};

struct DefPin {
  std::string name, net;
  int line = 0;
  std::vector<DefPort> ports;
};

struct Terminal {
  std::string comp, pin;  // comp "PIN": a DEF pin; "*": every component with the pin
  int line = 0;
};

struct WireSeg {
  std::int64_t w = 0;
  Point a, b;
};

struct DefNet {
  std::string name, use;
  int line = 0;
  bool special = false;
  std::vector<Terminal> terms;
  std::vector<Geo> wiring;  // on the layer (special nets), absolute
  std::vector<WireSeg> segs;  // the same wiring's segments (centrelines)
  bool regular_wiring_on_layer = false;
  int wiring_line = 0;
  int special_line = 0;  // the first point of special wiring on the layer
};

struct Def {
  std::string design;
  int design_line = 0;
  std::int64_t units = 0;
  int units_line = 0;
  std::optional<Box> die;
  std::vector<Component> comps;
  std::vector<DefPin> pins;
  std::vector<DefNet> nets;
  std::vector<Geo> blockages;
  std::map<std::string, Via, std::less<>> vias;  // DEF VIAS section (on the layer)
  std::vector<Diagnostic> warnings;               // IO-0132: a section's count differs from its items
};

// "( x y [ext] )", "*" repeating the previous point's coordinate; *ext gets ext, or 0
std::pair<std::int64_t, std::int64_t> def_point(Cursor& c, std::optional<std::pair<std::int64_t, std::int64_t>> prev = std::nullopt,
                                                std::int64_t* ext = nullptr) {
  c.expect("(");
  const Tok tx = c.next();
  const Tok ty = c.next();
  std::int64_t x = 0, y = 0;
  if (tx.s == "*") {
    if (!prev) c.fail("IO-0121", "\"*\" with no previous point", tx.line);
    x = prev->first;
  } else {
    x = def_int(c, tx);
  }
  if (ty.s == "*") {
    if (!prev) c.fail("IO-0121", "\"*\" with no previous point", ty.line);
    y = prev->second;
  } else {
    y = def_int(c, ty);
  }
  const std::int64_t e = c.peek().s != ")" ? def_int(c, c.next()) : 0;  // an extension value
  if (e < 0) c.fail("IO-0123", "a negative extension", ty.line);
  if (ext) *ext = e;
  c.expect(")");
  return {x, y};
}

Placement def_placement(Cursor& c) {
  Placement p;
  p.placed = true;
  std::tie(p.x, p.y) = def_point(c);
  const Tok o = c.next();
  const auto orient = parse_orient(o.s);
  if (!orient) c.fail("IO-0121", "unknown orientation \"" + std::string(o.s) + "\"", o.line);
  p.orient = *orient;
  return p;
}

// skips the tokens of one "+ OPTION ..." up to the next "+" or ";" (not consumed)
void skip_option(Cursor& c) {
  while (c.peek().s != "+" && c.peek().s != ";") c.next();
}

Geo def_rect_geo(Cursor& c, int line) {
  const auto a = def_point(c);
  const auto b = def_point(c);
  if (a.first == b.first || a.second == b.second) c.fail("IO-0121", "a rectangle with no area", line);
  return Geo{true, corners(pt(a.first, a.second), pt(b.first, b.second)), line};
}

Geo def_polygon_geo(Cursor& c, int line) {
  Geo g{false, {}, line};
  std::optional<std::pair<std::int64_t, std::int64_t>> prev;
  while (c.peek().s == "(") {
    prev = def_point(c, prev);
    g.pts.push_back(pt(prev->first, prev->second));
  }
  if (g.pts.size() < 3) c.fail("IO-0121", "a POLYGON with fewer than three points", line);
  return g;
}

// One net's wiring after ROUTED/FIXED/COVER/SHIELD: statements separated by NEW. Special nets:
// "layer width [+ SHAPE s] [+ MASK n] [+ STYLE n] pts [via]"; regular nets: "layer [TAPER |
// TAPERRULE r] [STYLE n] pts [via] [RECT ..] [VIRTUAL ..]". Adds the special wiring on the layer
// to net.wiring; marks regular wiring on the layer.
// Via v's shapes on the layer, turned by orientation o and placed at (x, y).
std::vector<Geo> place_via(const Cursor& c, const Via& v, Orient o, std::int64_t x, std::int64_t y, int line) {
  std::vector<Geo> out;
  for (Geo g : v.shapes) {
    for (Point& q : g.pts) {
      const auto [tx, ty] = turn(o, q.x, q.y);
      if (!geom::in_range(tx + x) || !geom::in_range(ty + y)) c.fail("IO-0123", "a via placed beyond the coordinate range", line);
      q = pt(tx + x, ty + y);
    }
    if (g.rect) g.pts = corners(g.pts[0], g.pts[1]);
    g.line = line;
    out.push_back(std::move(g));
  }
  return out;
}

const Via* find_via(const Cursor& c, std::string_view name, const std::map<std::string, Via, std::less<>>& def_vias, const Lib& lib,
                    const std::string& layer, int line, const std::string& whose) {
  const Via* v = nullptr;
  if (const auto d = def_vias.find(name); d != def_vias.end()) v = &d->second;
  else if (const auto l = lib.vias.find(name); l != lib.vias.end()) v = &l->second;
  if (!v) c.fail("IO-0124", "via " + std::string(name) + whose + " is not defined", line);
  if (v->generated_on_layer) c.fail("IO-0122", "generated via " + std::string(name) + " on layer " + layer + " is not supported", line);
  return v;
}

// "viaName [orient] [DO n BY m STEP dx dy]" after the point (x, y): the via's shapes on the
// layer, each copy of an array.
std::vector<Geo> via_here(Cursor& c, const Via& v, std::int64_t x, std::int64_t y, int line) {
  Orient o = Orient::N;
  if (const auto po = parse_orient(c.peek().s)) {
    o = *po;
    c.next();
  }
  std::int64_t nx = 1, ny = 1, dx = 0, dy = 0;
  if (c.accept("DO")) {
    nx = def_int(c, c.next());
    c.expect("BY");
    ny = def_int(c, c.next());
    c.expect("STEP");
    dx = def_int(c, c.next());
    dy = def_int(c, c.next());
    if (nx < 1 || ny < 1) c.fail("IO-0123", "a via array with no copies", line);
  }
  std::vector<Geo> out;
  if (v.shapes.empty()) return out;
  if (nx * ny > 100000) c.fail("IO-0122", "a via array of more than 100,000 copies on the layer", line);
  for (std::int64_t i = 0; i < nx; ++i)
    for (std::int64_t j = 0; j < ny; ++j)
      for (Geo& g : place_via(c, v, o, x + i * dx, y + j * dy, line)) out.push_back(std::move(g));
  return out;
}

void def_wiring(Cursor& c, const std::string& layer, const std::map<std::string, Via, std::less<>>& def_vias, const Lib& lib,
                DefNet& net) {
  for (;;) {
    const Tok lt = c.next();
    std::string cur(lt.s);  // the layer the path is on (a via takes it to another)
    bool on = cur == layer;
    std::int64_t width = 0;
    if (net.special) width = def_int(c, c.next());
    if (width < 0) c.fail("IO-0123", "a negative wire width of net " + net.name, lt.line);
    for (;;) {  // options before the points
      if (c.peek().s == "+" ) {
        // "+ SHAPE x", "+ MASK n", "+ STYLE n" continue the wire; any other "+" ends the wiring
        const std::string_view k = c.peek2();
        if (k != "SHAPE" && k != "MASK" && k != "STYLE") return;
        c.next();
        c.next();
        c.next();
      } else if (c.peek().s == "TAPER") {
        c.next();
      } else if (c.peek().s == "TAPERRULE" || c.peek().s == "STYLE" || c.peek().s == "MASK") {
        c.next();
        c.next();
      } else {
        break;
      }
    }
    std::optional<std::pair<std::int64_t, std::int64_t>> prev;
    std::int64_t prev_ext = 0;
    for (;;) {
      const Tok t = c.peek();
      if (t.s == "(") {
        std::int64_t ext = 0;
        const auto p = def_point(c, prev, &ext);
        if (on && net.special && prev) {
          if (p.first != prev->first && p.second != prev->second)
            c.fail("IO-0122", "a wiring segment of net " + net.name + " that is not axis-parallel", t.line);
          const std::int64_t h = width / 2;
          if (width % 2 != 0) c.fail("IO-0122", "odd wire width " + std::to_string(width) + " of net " + net.name + " (its half is not whole DBU)", t.line);
          // the metal: half the width to each side, and along the wire only as far as the points
          // and their extension values (a special wire has no other extension: as OpenDB reads it)
          const bool horizontal = p.second == prev->second;
          const auto lo_end = horizontal ? (p.first < prev->first ? ext : prev_ext) : (p.second < prev->second ? ext : prev_ext);
          const auto hi_end = horizontal ? (p.first < prev->first ? prev_ext : ext) : (p.second < prev->second ? prev_ext : ext);
          const std::int64_t x0 = std::min(p.first, prev->first) - (horizontal ? lo_end : h),
                             x1 = std::max(p.first, prev->first) + (horizontal ? hi_end : h);
          const std::int64_t y0 = std::min(p.second, prev->second) - (horizontal ? h : lo_end),
                             y1 = std::max(p.second, prev->second) + (horizontal ? h : hi_end);
          if (!geom::in_range(x0) || !geom::in_range(x1) || !geom::in_range(y0) || !geom::in_range(y1))
            c.fail("IO-0123", "a wiring segment of net " + net.name + " beyond the coordinate range", t.line);
          if (width > 0 && p != *prev) net.wiring.push_back(Geo{true, {pt(x0, y0), pt(x1, y1)}, t.line});
          if (width > 0 && p != *prev) net.segs.push_back(WireSeg{width, pt(prev->first, prev->second), pt(p.first, p.second)});
        }
        if (on && !net.special) {
          net.regular_wiring_on_layer = true;
          net.wiring_line = net.wiring_line ? net.wiring_line : t.line;
        }
        if (on && net.special && !net.wiring_line) net.wiring_line = t.line;
        if (on && net.special && !net.special_line) net.special_line = t.line;
        prev = p;
        prev_ext = ext;
      } else if (t.s == "NEW") {
        c.next();
        break;
      } else if (t.s == "+" || t.s == ";") {
        return;
      } else if (t.s == "RECT" || t.s == "VIRTUAL") {  // regular-net patches and virtual points
        c.next();
        if (t.s == "RECT") {  // RECT ( dx1 dy1 dx2 dy2 ), relative to the previous point
          c.expect("(");
          for (int k = 0; k < 4; ++k) def_int(c, c.next());
          c.expect(")");
          if (on) net.regular_wiring_on_layer = true;
        } else {
          def_point(c);
        }
      } else if (t.s == "MASK") {
        c.next();
        c.next();
      } else {  // a via at the previous point, with an optional orientation (or DO .. BY .. STEP ..)
        c.next();
        if (!prev) c.fail("IO-0121", "via " + std::string(t.s) + " with no point", t.line);
        const Via* v = find_via(c, t.s, def_vias, lib, layer, t.line, " of net " + net.name);
        for (Geo& g : via_here(c, *v, prev->first, prev->second, t.line)) {
          if (net.special) net.wiring.push_back(std::move(g));
          else net.regular_wiring_on_layer = true;
          if (!net.wiring_line) net.wiring_line = t.line;
        }
        // the path goes on from the via's other layer (as OpenDB reads it)
        if (const auto next = via_exit(*v, cur, lib)) {
          cur = *next;
        } else if (std::find(v->layers.begin(), v->layers.end(), layer) != v->layers.end() || cur == layer) {
          c.fail("IO-0122", "cannot tell which layer the wiring of net " + net.name + " continues on after via " + std::string(t.s) +
                                " (from layer " + cur + ")", t.line);
        }
        on = cur == layer;
        prev_ext = 0;
      }
    }
  }
}

void parse_def(Cursor& c, const std::string& layer, const Lib& lib, Def& d) {
  auto section_end = [&](std::string_view name) {
    if (c.peek().s == "END") {
      c.next();
      const Tok e = c.next();
      if (e.s != name) c.fail("IO-0121", "section " + std::string(name) + " ends with END " + std::string(e.s), e.line);
      return true;
    }
    return false;
  };
  std::size_t items = 0;  // the items of the section being read
  auto item_start = [&]() {
    c.expect("-");
    ++items;
  };
  // "NAME n ;", the head of a section: the number of items it declares (a whole number)
  auto section_start = [&](const Tok& name) {
    const Tok n = c.next();
    std::size_t v = 0;
    const auto [p, ec] = std::from_chars(n.s.data(), n.s.data() + n.s.size(), v);
    if (ec != std::errc() || p != n.s.data() + n.s.size())
      c.fail("IO-0121", "section " + std::string(name.s) + " declares its number of items, not \"" + std::string(n.s) + "\"", n.line);
    c.expect(";");
    items = 0;
    return v;
  };
  // after END NAME: a count that differs from the items read is named (a file cut or edited by
  // hand; what was read is used)
  auto section_read = [&](const Tok& name, std::size_t declared) {
    if (items != declared)
      d.warnings.push_back(Diagnostic{Severity::Warning, "IO-0132", c.file(), name.line, 0,
                                      "section " + std::string(name.s) + " declares " + std::to_string(declared) + " item" +
                                          (declared == 1 ? "" : "s") + " and holds " + std::to_string(items)});
  };
  while (!c.done()) {
    const Tok t = c.next();
    if (t.s == "DESIGN") {
      d.design_line = t.line;
      d.design = std::string(c.next().s);
      c.skip_statement();
    } else if (t.s == "UNITS") {
      c.expect("DISTANCE");
      c.expect("MICRONS");
      const Tok u = c.next();
      if (d.units != 0) c.fail("IO-0121", "a second UNITS statement", t.line);
      d.units = def_int(c, u);
      d.units_line = u.line;
      if (d.units <= 0) c.fail("IO-0123", "UNITS DISTANCE MICRONS must be positive", u.line);
      c.expect(";");
    } else if (t.s == "DIEAREA") {
      std::vector<Point> p;
      while (c.peek().s == "(") {
        const auto q = def_point(c);
        p.push_back(pt(q.first, q.second));
      }
      c.expect(";");
      if (p.empty()) c.fail("IO-0121", "a DIEAREA with no points", t.line);
      const Box b = geom::bounding_box(p);
      bool rect = p.size() == 2;
      if (p.size() == 4) {  // four corners of a rectangle, in order
        rect = true;
        for (std::size_t i = 0; i < 4; ++i) {
          const Point u = p[i], v = p[(i + 1) % 4];
          rect = rect && (u.x == v.x) != (u.y == v.y) && (u.x == b.lo.x || u.x == b.hi.x) && (u.y == b.lo.y || u.y == b.hi.y);
        }
      }
      if (!rect) c.fail("IO-0122", "a DIEAREA that is not a rectangle is not supported", t.line);
      if (b.lo.x == b.hi.x || b.lo.y == b.hi.y) c.fail("IO-0121", "a DIEAREA with no area", t.line);
      d.die = b;
    } else if (t.s == "VIAS") {
      const std::size_t declared = section_start(t);
      while (!section_end("VIAS")) {
        item_start();
        const Tok name = c.next();
        Via v;
        while (c.peek().s != ";") {
          c.expect("+");
          const Tok k = c.next();
          if (k.s == "RECT" || k.s == "POLYGON") {
            const Tok ln = c.next();
            const bool on = ln.s == layer;
            if (std::find(v.layers.begin(), v.layers.end(), ln.s) == v.layers.end()) v.layers.emplace_back(ln.s);
            if (c.accept("+")) {  // + MASK n
              c.next();
              c.next();
            }
            Geo g = k.s == "RECT" ? def_rect_geo(c, k.line) : def_polygon_geo(c, k.line);
            if (on) v.shapes.push_back(g);
          } else if (k.s == "LAYERS") {  // a generated via: bottom cut top
            const Tok b = c.next(), cut = c.next(), top = c.next();
            v.generated_on_layer = b.s == layer || cut.s == layer || top.s == layer;
            v.layers = {std::string(b.s), std::string(top.s)};
          } else {
            skip_option(c);
          }
        }
        c.next();
        d.vias[std::string(name.s)] = std::move(v);
      }
      section_read(t, declared);
    } else if (t.s == "COMPONENTS") {
      const std::size_t declared = section_start(t);
      while (!section_end("COMPONENTS")) {
        item_start();
        Component comp;
        const Tok n = c.next();
        comp.name = std::string(n.s);
        comp.line = n.line;
        comp.macro = std::string(c.next().s);
        while (c.peek().s != ";") {
          c.expect("+");
          const Tok k = c.next();
          if (k.s == "PLACED" || k.s == "FIXED" || k.s == "COVER") comp.at = def_placement(c);
          else skip_option(c);
        }
        c.next();
        d.comps.push_back(std::move(comp));
      }
      section_read(t, declared);
    } else if (t.s == "PINS") {
      const std::size_t declared = section_start(t);
      while (!section_end("PINS")) {
        item_start();
        DefPin p;
        const Tok n = c.next();
        p.name = std::string(n.s);
        p.line = n.line;
        p.ports.push_back(DefPort{{}, {}, n.line});
        bool explicit_port = false;
        while (c.peek().s != ";") {
          c.expect("+");
          const Tok k = c.next();
          if (k.s == "NET") {
            p.net = std::string(c.next().s);
          } else if (k.s == "PORT") {
            if (explicit_port) p.ports.push_back(DefPort{{}, {}, k.line});
            explicit_port = true;
            p.ports.back().line = k.line;
          } else if (k.s == "LAYER" || k.s == "POLYGON") {
            const bool on = c.next().s == layer;
            while (c.peek().s != "(") c.next();  // MASK n, SPACING d, DESIGNRULEWIDTH d
            Geo g = k.s == "LAYER" ? def_rect_geo(c, k.line) : def_polygon_geo(c, k.line);
            if (on) p.ports.back().shapes.push_back(std::move(g));
          } else if (k.s == "VIA") {
            const Tok vn = c.next();
            if (c.accept("MASK")) c.next();
            const auto at = def_point(c);
            const Via* v = find_via(c, vn.s, d.vias, lib, layer, vn.line, " of pin " + p.name);
            for (Geo& g : place_via(c, *v, Orient::N, at.first, at.second, vn.line)) p.ports.back().shapes.push_back(std::move(g));
          } else if (k.s == "PLACED" || k.s == "FIXED" || k.s == "COVER") {
            p.ports.back().at = def_placement(c);
          } else {
            skip_option(c);
          }
        }
        c.next();
        d.pins.push_back(std::move(p));
      }
      section_read(t, declared);
    } else if (t.s == "NETS" || t.s == "SPECIALNETS") {
      const bool special = t.s == "SPECIALNETS";
      const std::size_t declared = section_start(t);
      while (!section_end(t.s)) {
        item_start();
        DefNet net;
        net.special = special;
        const Tok n = c.next();
        net.name = std::string(n.s);
        net.line = n.line;
        if (n.s == "MUSTJOIN") c.fail("IO-0122", "MUSTJOIN nets are not supported", n.line);
        while (c.peek().s == "(") {
          const Tok open = c.next();
          Terminal term;
          term.comp = std::string(c.next().s);
          term.pin = std::string(c.next().s);
          term.line = open.line;
          while (c.peek().s != ")") c.next();  // + SYNTHESIZED
          c.next();
          net.terms.push_back(std::move(term));
        }
        while (c.peek().s != ";") {
          c.expect("+");
          const Tok k = c.next();
          if (k.s == "USE") {
            net.use = std::string(c.next().s);
          } else if (k.s == "ROUTED" || k.s == "FIXED" || k.s == "COVER" || k.s == "NOSHIELD") {
            def_wiring(c, layer, d.vias, lib, net);
          } else if (k.s == "SHIELD" && special) {
            c.next();  // the shielded net's name
            def_wiring(c, layer, d.vias, lib, net);
          } else if (special && k.s == "VIA") {  // + VIA viaName [orient] ( x y ) ..: the via at each point
            const Tok vn = c.next();
            const Via* v = find_via(c, vn.s, d.vias, lib, layer, vn.line, " of net " + net.name);
            Orient o = Orient::N;
            if (const auto po = parse_orient(c.peek().s)) {
              o = *po;
              c.next();
            }
            std::optional<std::pair<std::int64_t, std::int64_t>> prev;
            while (c.peek().s == "(") {
              prev = def_point(c, prev);
              for (Geo& g : place_via(c, *v, o, prev->first, prev->second, vn.line)) {
                net.wiring.push_back(std::move(g));
                if (!net.wiring_line) net.wiring_line = vn.line;
              }
            }
          } else if (special && (k.s == "RECT" || k.s == "POLYGON")) {
            const bool on = c.next().s == layer;
            if (c.accept("+")) {  // + MASK n
              c.next();
              c.next();
            }
            Geo g = k.s == "RECT" ? def_rect_geo(c, k.line) : def_polygon_geo(c, k.line);
            if (on) {
              net.wiring.push_back(std::move(g));
              if (!net.wiring_line) net.wiring_line = k.line;
            }
          } else if (k.s == "SUBNET") {
            c.fail("IO-0122", "SUBNET in net " + net.name + " is not supported", k.line);
          } else {
            skip_option(c);
          }
        }
        c.next();
        d.nets.push_back(std::move(net));
      }
      section_read(t, declared);
    } else if (t.s == "BLOCKAGES" || t.s == "FILLS") {  // metal fill on the layer blocks as a blockage does
      const std::string_view section = t.s;
      const std::size_t declared = section_start(t);
      while (!section_end(section)) {
        item_start();
        const Tok k = c.next();
        bool on = false;
        if (k.s == "LAYER") {
          on = c.next().s == layer;
        } else if (k.s != "PLACEMENT" && k.s != "VIA") {
          c.fail("IO-0121", "an item of " + std::string(section) + " is LAYER, PLACEMENT or VIA, not \"" + std::string(k.s) + "\"", k.line);
        }
        std::optional<Tok> via;  // FILLS: "- VIA name [+ MASK n] [+ OPC] pts"
        if (k.s == "VIA") via = c.next();
        for (;;) {
          const Tok q = c.peek();
          if (q.s == ";") {
            c.next();
            break;
          }
          if (q.s == "(" && via) {
            const auto at = def_point(c);
            const Via* v = find_via(c, via->s, d.vias, lib, layer, via->line, "");
            for (Geo& g : place_via(c, *v, Orient::N, at.first, at.second, q.line)) d.blockages.push_back(std::move(g));
            continue;
          }
          c.next();
          if (q.s == "RECT") {
            Geo g = def_rect_geo(c, q.line);
            if (on) d.blockages.push_back(std::move(g));
          } else if (q.s == "POLYGON") {
            Geo g = def_polygon_geo(c, q.line);
            if (on) d.blockages.push_back(std::move(g));
          }
        }
      }
      section_read(t, declared);
    } else if (t.s == "END") {
      c.expect("DESIGN");
      return;
    } else if (t.s == "PROPERTYDEFINITIONS") {
      c.skip_block("PROPERTYDEFINITIONS");
    } else if (t.s == "BEGINEXT") {
      while (c.next().s != "ENDEXT") {
      }
    } else if (t.s == "REGIONS" || t.s == "GROUPS" || t.s == "NONDEFAULTRULES" || t.s == "SCANCHAINS" || t.s == "STYLES" ||
               t.s == "SLOTS" || t.s == "PINPROPERTIES") {
      // nothing on the layer, but its count is checked as a read section's (since 2026-12-06):
      // an item is a statement that begins with "-"
      const std::size_t declared = section_start(t);
      for (bool at_start = true;;) {
        const Tok k = c.next();
        if (c.closes(k, t.s)) break;
        if (at_start && k.s == "-") ++items;
        at_start = k.s == ";";
      }
      section_read(t, declared);
    } else if (t.s == "VERSION" || t.s == "NAMESCASESENSITIVE" || t.s == "DIVIDERCHAR" || t.s == "BUSBITCHARS" ||
               t.s == "TECHNOLOGY" || t.s == "HISTORY" || t.s == "ROW" || t.s == "TRACKS" || t.s == "GCELLGRID" ||
               t.s == "COMPONENTMASKSHIFT" || t.s == "FIXEDMASK") {  // DEF 5.8's other statements: nothing on the layer
      c.skip_statement();
    } else {  // (since 2026-12-06: before, skipped to the next ';' unseen, junk before VERSION included)
      c.fail("IO-0121", "\"" + shown(t.s) + "\" begins no DEF statement", t.line);
    }
  }
  c.fail("IO-0121", "the DEF ends without END DESIGN (is the file cut short?)");
}

// A shape as the layout holds it, with `line` the DEF line of the object it comes from.
Shape to_shape(const Geo& g, int line) {
  Shape s;
  s.line = line;
  if (g.rect) {
    s.kind = Shape::Kind::Rect;
    s.rect = Box{g.pts[0], g.pts[1]};
  } else {
    s.kind = Shape::Kind::Polygon;
    s.polygon.outer = g.pts;
    if (s.polygon.outer.size() > 3 && s.polygon.outer.front() == s.polygon.outer.back()) s.polygon.outer.pop_back();
  }
  return s;
}

// A shape moved by orientation o about the origin, then by (dx, dy); `what` and `line` name the
// placing object (a component, a pin) in the DEF.
Geo moved(const Geo& g, Orient o, std::int64_t dx, std::int64_t dy, const Cursor& c, const std::string& what, int line) {
  Geo out = g;
  for (Point& p : out.pts) {
    const auto [x, y] = turn(o, p.x, p.y);
    if (!geom::in_range(x + dx) || !geom::in_range(y + dy))
      c.fail("IO-0123", what + ": a shape placed beyond the coordinate range (|v| <= 2^30 - 1)", line);
    p = pt(x + dx, y + dy);
  }
  if (out.rect) out.pts = corners(out.pts[0], out.pts[1]);
  return out;
}

// The box centre of a pin's shape, doubled (integer).
Point centre2(const Pin& p) {
  const Box b = p.shape->kind == Shape::Kind::Rect ? p.shape->rect : geom::bounding_box(p.shape->polygon.outer);
  return Point{b.lo.x + b.hi.x, b.lo.y + b.hi.y};  // (fits: |coordinates| < 2^30)
}

// --bump-to-pad: each bump gets one pad pin, the assignment of least total L1 distance between
// box centres (the Hungarian method, O(n^2 m)); with more bumps than pads each pad is offered
// ceil(bumps / pads) times. Integer costs: the same answer on every machine.
std::vector<std::size_t> assign_bumps(const std::vector<Pin>& pins, const std::vector<std::size_t>& bumps,
                                      const std::vector<std::size_t>& pads) {
  const std::size_t n = bumps.size(), reps = (n + pads.size() - 1) / pads.size(), m = pads.size() * reps;
  // the centres once (1-based, as the rows and columns): a cost is then two subtractions (taking
  // them from the shapes for every cost, 2,000 bumps and pads took 12.6 s)
  std::vector<std::int64_t> ax(n + 1), ay(n + 1), bx(m + 1), by(m + 1);
  for (std::size_t i = 1; i <= n; ++i) {
    const Point a = centre2(pins[bumps[i - 1]]);
    ax[i] = a.x, ay[i] = a.y;
  }
  for (std::size_t j = 1; j <= m; ++j) {
    const Point b = centre2(pins[pads[(j - 1) % pads.size()]]);
    bx[j] = b.x, by[j] = b.y;
  }
  auto cost = [&](std::size_t i, std::size_t j) {  // 1-based row i (bump), column j (pad copy)
    return std::abs(ax[i] - bx[j]) + std::abs(ay[i] - by[j]);
  };
  const std::int64_t inf = std::numeric_limits<std::int64_t>::max() / 4;
  std::vector<std::int64_t> u(n + 1, 0), v(m + 1, 0);
  std::vector<std::size_t> p(m + 1, 0), way(m + 1, 0);
  for (std::size_t i = 1; i <= n; ++i) {
    p[0] = i;
    std::size_t j0 = 0;
    std::vector<std::int64_t> minv(m + 1, inf);
    std::vector<char> used(m + 1, 0);
    do {
      used[j0] = 1;
      const std::size_t i0 = p[j0];
      std::int64_t delta = inf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const std::int64_t cur = cost(i0, j) - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (std::size_t j = 0; j <= m; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const std::size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<std::size_t> to(n);
  for (std::size_t j = 1; j <= m; ++j)
    if (p[j] != 0) to[p[j] - 1] = pads[(j - 1) % pads.size()];
  return to;
}

struct NetInfo {
  std::string name, use;
  int line = 0;
  std::vector<Terminal> terms;
  std::vector<Geo> wiring;
  std::vector<WireSeg> segs;
  bool regular_wiring_on_layer = false;
  int wiring_line = 0;
  int special_line = 0;
};

// --keep-wiring: a net's special wiring as 2-point wires on their centrelines. A segment drawn
// out by half its width past a corner (as OpenROAD writes them, so that the rectangles overlap)
// is taken back to the corner when the other segment's centreline passes exactly there, so the
// wires meet end to end.
std::vector<Wire> centre_wires(const std::vector<WireSeg>& segs) {
  std::vector<Wire> out;
  auto on = [](const WireSeg& s, Point r) {
    return std::min(s.a.x, s.b.x) <= r.x && r.x <= std::max(s.a.x, s.b.x) && std::min(s.a.y, s.b.y) <= r.y &&
           r.y <= std::max(s.a.y, s.b.y) && (s.a.x == s.b.x ? r.x == s.a.x : r.y == s.a.y);
  };
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const WireSeg& s = segs[k];
    const std::int64_t h = s.w / 2;
    auto pull = [&](Point p, Point q) {
      const std::int64_t len = std::abs(std::int64_t{q.x} - p.x) + std::abs(std::int64_t{q.y} - p.y);
      if (len <= h) return p;
      const Point r{static_cast<geom::Coord>(p.x + (q.x > p.x) * h - (q.x < p.x) * h),
                    static_cast<geom::Coord>(p.y + (q.y > p.y) * h - (q.y < p.y) * h)};
      for (std::size_t j = 0; j < segs.size(); ++j)
        if (j != k && (segs[j].a.x == segs[j].b.x) != (s.a.x == s.b.x) && on(segs[j], r)) return r;
      return p;
    };
    Wire w;
    w.points = {pull(s.a, s.b), pull(s.b, s.a)};
    out.push_back(std::move(w));
  }
  return out;
}

Layout assemble(const Def& d, const Lib& lib, const DefImportOptions& o, const Cursor& dc, std::vector<Diagnostic>& diags,
                DefImportStats& stats) {
  auto warn = [&](const std::string& code, int line, const std::string& msg) {
    diags.push_back(Diagnostic{Severity::Warning, code, dc.file(), line, 0, msg});
  };
  // components and their macros
  std::map<std::string, std::size_t, std::less<>> comp_index;
  for (std::size_t i = 0; i < d.comps.size(); ++i) {
    const Component& cp = d.comps[i];
    if (!comp_index.try_emplace(cp.name, i).second)
      dc.fail("IO-0129", "component " + cp.name + " is defined twice (first on line " + std::to_string(d.comps[comp_index[cp.name]].line) + ")",
              cp.line);
    const auto m = lib.macros.find(cp.macro);
    if (m == lib.macros.end())
      dc.fail("IO-0124", "component " + cp.name + ": macro " + cp.macro + " is not in the LEF files", cp.line);
    if (!cp.at.placed) {
      bool on = !m->second.obs.empty();
      for (const auto& [n, p] : m->second.pins) on = on || !p.shapes.empty();
      if (on) dc.fail("IO-0122", "component " + cp.name + " is not placed but its macro " + cp.macro + " has shapes on layer " + o.layer, cp.line);
    }
  }
  auto macro_of = [&](std::size_t i) -> const Macro& { return lib.macros.find(d.comps[i].macro)->second; };
  auto place = [&](std::size_t i, const Geo& g) {
    const Component& cp = d.comps[i];
    const Macro& m = macro_of(i);
    if (!m.has_size && cp.at.orient != Orient::N)
      dc.fail("IO-0122", "component " + cp.name + ": macro " + cp.macro + " has no SIZE, so orientation other than N cannot be placed",
              cp.line);
    const auto [ax, ay] = turn(cp.at.orient, 0, 0);
    const auto [bx, by] = turn(cp.at.orient, m.w, m.h);
    return moved(g, cp.at.orient, cp.at.x - std::min(ax, bx), cp.at.y - std::min(ay, by), dc, "component " + cp.name, cp.line);
  };
  std::map<std::string, std::size_t, std::less<>> pin_index;
  for (std::size_t i = 0; i < d.pins.size(); ++i)
    if (!pin_index.try_emplace(d.pins[i].name, i).second)
      dc.fail("IO-0129", "pin " + d.pins[i].name + " is defined twice (first on line " + std::to_string(d.pins[pin_index[d.pins[i].name]].line) + ")",
              d.pins[i].line);
  auto def_pin_shapes = [&](std::size_t i) {
    std::vector<Geo> out;
    for (const DefPort& port : d.pins[i].ports)
      for (const Geo& g : port.shapes) {
        if (!port.at.placed) dc.fail("IO-0122", "pin " + d.pins[i].name + " has shapes on layer " + o.layer + " but is not placed", port.line);
        out.push_back(moved(g, port.at.orient, port.at.x, port.at.y, dc, "pin " + d.pins[i].name, d.pins[i].line));
      }
    return out;
  };

  // nets: NETS and SPECIALNETS entries of one name are one net
  std::vector<NetInfo> nets;
  std::map<std::string, std::size_t, std::less<>> net_index;
  for (const DefNet& dn : d.nets) {
    auto [it, fresh] = net_index.try_emplace(dn.name, nets.size());
    if (fresh) nets.push_back(NetInfo{dn.name, dn.use, dn.line, {}, {}, {}, false, 0, 0});
    NetInfo& n = nets[it->second];
    if (n.use.empty()) n.use = dn.use;
    n.terms.insert(n.terms.end(), dn.terms.begin(), dn.terms.end());
    n.wiring.insert(n.wiring.end(), dn.wiring.begin(), dn.wiring.end());
    n.segs.insert(n.segs.end(), dn.segs.begin(), dn.segs.end());
    n.regular_wiring_on_layer = n.regular_wiring_on_layer || dn.regular_wiring_on_layer;
    if (!n.wiring_line) n.wiring_line = dn.wiring_line;
    if (!n.special_line) n.special_line = dn.special_line;
  }
  std::vector<char> selected(nets.size(), o.nets.empty() ? 1 : 0);
  for (const std::string& pat : o.nets) {
    bool any = false;
    for (std::size_t i = 0; i < nets.size(); ++i)
      if (fnmatch(pat.c_str(), nets[i].name.c_str(), 0) == 0) selected[i] = any = true;
    if (!any) dc.fail("IO-0125", "--nets pattern \"" + pat + "\" matches no net of the DEF", 0);
  }

  // which selected net owns each terminal: explicit ones first, then `( * pin )` and the global
  // connection of power and ground nets, where no explicit one claimed it
  std::map<std::pair<std::size_t, std::string>, std::size_t> owner;  // (component, pin) -> net
  std::map<std::size_t, std::size_t> pin_owner;                       // DEF pin -> net
  for (std::size_t i = 0; i < nets.size(); ++i) {
    if (!selected[i]) continue;
    for (const Terminal& t : nets[i].terms) {
      if (t.comp == "*") continue;
      if (t.comp == "PIN") {
        const auto p = pin_index.find(t.pin);
        if (p == pin_index.end()) dc.fail("IO-0124", "net " + nets[i].name + ": pin " + t.pin + " is not in PINS", t.line);
        pin_owner.try_emplace(p->second, i);
        continue;
      }
      const auto ci = comp_index.find(t.comp);
      if (ci == comp_index.end()) dc.fail("IO-0124", "net " + nets[i].name + ": component " + t.comp + " is not in COMPONENTS", t.line);
      const Macro& m = macro_of(ci->second);
      if (!m.pins.count(t.pin))
        dc.fail("IO-0124", "net " + nets[i].name + ": component " + t.comp + " (macro " + d.comps[ci->second].macro + ") has no pin " + t.pin, t.line);
      const auto [it, fresh] = owner.try_emplace({ci->second, t.pin}, i);
      if (!fresh && it->second != i)
        dc.fail("IO-0129", "terminal " + t.comp + "/" + t.pin + " is in nets " + nets[it->second].name + " and " + nets[i].name, t.line);
    }
  }
  for (std::size_t i = 0; i < d.pins.size(); ++i)
    if (const auto n = net_index.find(d.pins[i].net); n != net_index.end() && selected[n->second]) pin_owner.try_emplace(i, n->second);
  std::vector<std::vector<std::pair<std::size_t, std::string>>> wild(nets.size());  // per net, in component order
  {
    // a terminal any net names explicitly, selected or not, is that net's: a wildcard or a global
    // connection of another net does not take it (the result must not depend on the selection)
    std::set<std::pair<std::size_t, std::string>> named;
    for (const NetInfo& n : nets)
      for (const Terminal& t : n.terms)
        if (t.comp != "*" && t.comp != "PIN")
          if (const auto ci = comp_index.find(t.comp); ci != comp_index.end()) named.insert({ci->second, t.pin});
    std::vector<std::pair<std::size_t, std::string>> wants;  // (net, pin name)
    for (std::size_t i = 0; i < nets.size(); ++i) {
      if (!selected[i]) continue;
      for (const Terminal& t : nets[i].terms)
        if (t.comp == "*") wants.push_back({i, t.pin});
      if (nets[i].use == "POWER" || nets[i].use == "GROUND") wants.push_back({i, nets[i].name});
    }
    for (std::size_t c = 0; c < d.comps.size(); ++c) {
      if (!d.comps[c].at.placed) continue;
      const Macro& m = macro_of(c);
      for (const auto& [i, pin] : wants) {
        const auto mp = m.pins.find(pin);
        if (mp == m.pins.end() || mp->second.shapes.empty() || named.count({c, pin})) continue;
        if (owner.try_emplace({c, pin}, i).second) wild[i].push_back({c, pin});
      }
    }
  }

  Layout out;
  out.name = d.design.empty() ? "imported" : d.design;
  out.dbu_per_micron = d.units;
  if (d.die) out.boundary = Boundary{*d.die, 0};
  Rules rules;
  const auto w = exact_dbu(o.wire_width, d.units), s = exact_dbu(o.spacing, d.units);
  if (!w || *w < 0) dc.fail("IO-0123", "--wire-width " + o.wire_width + " microns is not a whole, non-negative number of DBU at " + std::to_string(d.units) + " DBU per micron", 0);
  if (!s || *s < 0) dc.fail("IO-0123", "--spacing " + o.spacing + " microns is not a whole, non-negative number of DBU at " + std::to_string(d.units) + " DBU per micron", 0);
  rules.wire_width = *w;
  rules.spacing = *s;
  out.rules = rules;

  std::vector<Blockage> extra;  // shapes of selected nets that are not written as nets
  std::vector<Route> kept;      // --keep-wiring
  std::vector<char> written(nets.size(), 0);  // written as a net (or nets)
  std::size_t pins_written = 0;
  for (std::size_t i = 0; i < nets.size(); ++i) {
    if (!selected[i]) continue;
    const NetInfo& ni = nets[i];
    Net net;
    net.name = ni.name;
    net.line = ni.line;
    std::vector<char> cover;  // per pin: a bump's (a CLASS COVER cell's) shape
    // each shape's pin, by the shape's kind, box and vertices (a map: the linear search it
    // replaces made a power net of 80,000 pin shapes take 14.5 s; found by fuzzing, 2026-12-06)
    std::map<std::vector<std::int64_t>, std::size_t> pin_of_shape;
    auto shape_key = [](const Shape& sh) {
      std::vector<std::int64_t> key{static_cast<std::int64_t>(sh.kind), sh.rect.lo.x, sh.rect.lo.y, sh.rect.hi.x, sh.rect.hi.y};
      auto ring = [&](const geom::Ring& r) {
        key.push_back(static_cast<std::int64_t>(r.size()));
        for (const Point q : r) key.insert(key.end(), {q.x, q.y});
      };
      ring(sh.polygon.outer);
      for (const geom::Ring& h : sh.polygon.holes) ring(h);
      return key;
    };
    auto add = [&](const std::string& name, const std::vector<Geo>& shapes, bool is_cover, int line) {
      for (std::size_t k = 0; k < shapes.size(); ++k) {
        Shape sh = to_shape(shapes[k], line);
        const std::string pn = shapes.size() == 1 ? name : name + "#" + std::to_string(k + 1);
        const auto [at, fresh] = pin_of_shape.try_emplace(shape_key(sh), net.pins.size());
        const std::size_t j = at->second;
        if (!fresh) {  // the same shape twice: one pin, named by the bump if one is
          if (is_cover && !cover[j]) net.pins[j].name = pn;
          cover[j] = cover[j] || is_cover;
          continue;
        }
        Pin p;
        p.name = pn;
        p.line = line;
        p.shape = std::move(sh);
        net.pins.push_back(std::move(p));
        cover.push_back(is_cover);
      }
    };
    std::vector<std::pair<int, std::string>> off_layer;  // explicit terminals with no shape on the layer
    std::set<std::size_t> pins_done;
    std::set<std::pair<std::size_t, std::string>> comps_done;
    auto add_def_pin = [&](std::size_t p) {
      if (!pins_done.insert(p).second) return;
      add("PIN/" + d.pins[p].name, def_pin_shapes(p), false, d.pins[p].line);
    };
    for (const Terminal& t : ni.terms) {
      if (t.comp == "*") continue;
      if (t.comp == "PIN") {
        const std::size_t p = pin_index.find(t.pin)->second;
        const std::vector<Geo> g = def_pin_shapes(p);
        if (g.empty()) off_layer.push_back({t.line, "PIN " + t.pin});
        add_def_pin(p);
        continue;
      }
      const std::size_t c = comp_index.find(t.comp)->second;
      if (!comps_done.insert({c, t.pin}).second) continue;
      std::vector<Geo> g;
      for (const Geo& x : macro_of(c).pins.find(t.pin)->second.shapes) g.push_back(place(c, x));
      if (g.empty()) off_layer.push_back({t.line, t.comp + "/" + t.pin});
      add(t.comp + "/" + t.pin, g, macro_of(c).cover, d.comps[c].line);
    }
    for (std::size_t p = 0; p < d.pins.size(); ++p)
      if (const auto po = pin_owner.find(p); po != pin_owner.end() && po->second == i) add_def_pin(p);
    for (const auto& [c, pin] : wild[i]) {
      if (!comps_done.insert({c, pin}).second) continue;
      std::vector<Geo> g;
      for (const Geo& x : macro_of(c).pins.find(pin)->second.shapes) g.push_back(place(c, x));
      add(d.comps[c].name + "/" + pin, g, macro_of(c).cover, d.comps[c].line);
    }
    if (!off_layer.empty())  // one line per net: a power net lists hundreds of cells' pins on other layers
      warn("IO-0126", off_layer[0].first,
           "net " + ni.name + ": " + std::to_string(off_layer.size()) + " of its terminals have no shape on layer " + o.layer +
               " (the first: " + off_layer[0].second + "); they are not pins here");
    if (net.pins.size() < 2) {  // its shape and its wiring (below) are blockages
      warn("IO-0126", ni.line, "net " + ni.name + " has " + std::to_string(net.pins.size()) + " pin shape(s) on layer " + o.layer +
                                   ": not written as a net" +
                                   (net.pins.empty() && ni.wiring.empty() ? "" : " (its shape and wiring there are blockages)"));
      if (!net.pins.empty()) {
        Blockage b;
        b.id = ni.name + "/" + net.pins[0].name;
        b.line = net.pins[0].line;
        b.shapes.push_back(*net.pins[0].shape);
        extra.push_back(std::move(b));
      }
      continue;
    }
    if (o.keep_wiring ? ni.regular_wiring_on_layer || ni.wiring.size() != ni.segs.size()
                      : !ni.wiring.empty() || ni.regular_wiring_on_layer)
      warn("IO-0127", ni.wiring_line,
           "net " + ni.name + " already has wiring on layer " + o.layer +
               (o.keep_wiring ? ": its regular wiring and vias are not kept (only special wires are)" : ": not kept (taut routes the net)"));
    std::size_t covers = 0;
    for (const char x : cover) covers += x;
    if (o.bump_to_pad && covers > 0 && covers < net.pins.size() && net.pins.size() > 2) {
      // a net per pad the assignment gives bumps to: the pad and its bumps (one bump unless
      // there are more bumps than pads), named by its first bump
      std::vector<std::size_t> bumps, pads;
      for (std::size_t k = 0; k < net.pins.size(); ++k) (cover[k] ? bumps : pads).push_back(k);
      const std::vector<std::size_t> to = assign_bumps(net.pins, bumps, pads);
      std::vector<char> used(net.pins.size(), 0);
      for (std::size_t b = 0; b < bumps.size(); ++b) {
        if (used[to[b]]) continue;  // joined to the net of this pad's first bump
        Net part;
        part.name = net.name + "/" + net.pins[bumps[b]].name;
        part.line = net.line;
        for (std::size_t c = b; c < bumps.size(); ++c)
          if (to[c] == to[b]) part.pins.push_back(net.pins[bumps[c]]);
        part.pins.push_back(net.pins[to[b]]);
        used[to[b]] = 1;
        pins_written += part.pins.size();
        out.nets.push_back(std::move(part));
      }
      written[i] = 1;
      std::size_t unused = 0;
      for (const std::size_t k : pads) {
        if (used[k]) continue;
        ++unused;
        Blockage b;
        b.id = net.name + "/" + net.pins[k].name;
        b.line = net.pins[k].line;
        b.shapes.push_back(*net.pins[k].shape);
        extra.push_back(std::move(b));
      }
      if (unused > 0)
        warn("IO-0128", ni.line, "net " + ni.name + ": " + std::to_string(unused) + " of its " + std::to_string(pads.size()) +
                                     " pad pins are joined to no bump (more pads than bumps); they are blockages");
      continue;
    }
    pins_written += net.pins.size();
    written[i] = 1;
    if (o.keep_wiring) {
      Route rt;
      rt.net = net.name;
      rt.wires = centre_wires(ni.segs);
      if (rt.wires.empty()) {
        rt.status = "failed";
        // (since 2026-12-06 a net with special wiring there but no segment of it, only points
        // or segments of no length or width, says so: before, "no special wiring")
        rt.reason = ni.special_line ? "its special wiring on layer " + o.layer + " in the DEF has no segment of both length and width (line " +
                                          std::to_string(ni.special_line) + ")"
                                    : "no special wiring on layer " + o.layer + " in the DEF";
      } else {
        rt.status = "routed";
        std::vector<std::vector<Point>> lines;
        for (const Wire& w : rt.wires) lines.push_back(w.points);
        rt.length = format_total_length(lines);
        rt.bends = 0;
      }
      kept.push_back(std::move(rt));
    }
    out.nets.push_back(std::move(net));
  }

  // blockages: every other shape on the layer
  for (std::size_t c = 0; c < d.comps.size(); ++c) {
    if (!d.comps[c].at.placed) continue;
    const Macro& m = macro_of(c);
    for (const std::string& pin : m.pin_order) {
      const auto& shapes = m.pins.find(pin)->second.shapes;
      if (shapes.empty() || owner.count({c, pin})) continue;
      Blockage b;
      b.id = d.comps[c].name + "/" + pin;
      b.line = d.comps[c].line;
      for (const Geo& g : shapes) b.shapes.push_back(to_shape(place(c, g), b.line));
      out.blockages.push_back(std::move(b));
    }
    if (!m.obs.empty()) {
      Blockage b;
      b.id = d.comps[c].name + "/OBS";
      b.line = d.comps[c].line;
      for (const Geo& g : m.obs) b.shapes.push_back(to_shape(place(c, g), b.line));
      out.blockages.push_back(std::move(b));
    }
  }
  for (std::size_t p = 0; p < d.pins.size(); ++p) {
    if (pin_owner.count(p)) continue;
    const std::vector<Geo> g = def_pin_shapes(p);
    if (g.empty()) continue;
    Blockage b;
    b.id = "PIN/" + d.pins[p].name;
    b.line = d.pins[p].line;
    for (const Geo& x : g) b.shapes.push_back(to_shape(x, b.line));
    out.blockages.push_back(std::move(b));
  }
  for (std::size_t k = 0; k < d.blockages.size(); ++k) {
    Blockage b;
    b.id = "BLOCKAGE/" + std::to_string(k + 1);
    b.line = d.blockages[k].line;
    b.shapes.push_back(to_shape(d.blockages[k], b.line));
    out.blockages.push_back(std::move(b));
  }
  for (std::size_t i = 0; i < nets.size(); ++i) {
    if (written[i]) continue;  // (a selected net not written, with fewer than two pins: its wiring blocks too)
    if (nets[i].regular_wiring_on_layer)
      dc.fail("IO-0122", "net " + nets[i].name + (selected[i] ? " (not written)" : " (not selected)") + " has regular wiring on layer " + o.layer +
                             ": not supported (select the net, or remove its wiring)", nets[i].wiring_line);
    if (nets[i].wiring.empty()) continue;
    Blockage b;
    b.id = nets[i].name + "/wiring";
    b.line = nets[i].wiring_line;
    for (const Geo& g : nets[i].wiring) b.shapes.push_back(to_shape(g, g.line));
    out.blockages.push_back(std::move(b));
  }
  for (Blockage& b : extra) out.blockages.push_back(std::move(b));
  if (o.keep_wiring) {
    Routes rs;
    rs.tool = "DEF wiring (taut import --keep-wiring)";
    rs.orientations = "rectilinear";
    rs.routes = std::move(kept);
    out.routes = std::move(rs);
  }
  // Names are written as XML text: a byte XML cannot carry (Latin-1 letters, control characters)
  // would be written as U+FFFD, and two names differing there would become one (since
  // 2026-12-06: import wrote such a layout, which taut check then refused, LAYOUT-0001/0002;
  // found by fuzzing)
  auto text_name = [&](const std::string& what, const std::string& name, int line) {
    const std::size_t k = first_non_xml_byte(name);
    if (k == std::string::npos) return;
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(name[k])));
    dc.fail("IO-0130", what + " \"" + shown(name) + "\" has byte " + byte + " at " + std::to_string(k + 1) +
                           ", which is no UTF-8 character XML can carry: taut writes names as UTF-8 XML (rename it in the DEF or LEF)",
            line);
  };
  text_name("design", out.name, d.design_line);  // (the layout's name)
  for (const Net& n : out.nets) {
    text_name("net", n.name, n.line);
    for (const Pin& p : n.pins) text_name("pin of net " + n.name, p.name, p.line);
  }
  for (const Blockage& b : out.blockages) text_name("blockage", b.id, b.line);
  if (out.nets.empty() && out.blockages.empty()) dc.fail("IO-0125", "no shape of the design is on layer " + o.layer, 0);
  stats.nets = out.nets.size();
  stats.pins = pins_written;
  stats.blockages = out.blockages.size();
  stats.components = d.comps.size();
  return out;
}

// the first "UNITS DISTANCE MICRONS n": n (-1 when it is not an integer from 1 to 10^6), 0 when
// there is none, and its line
std::pair<std::int64_t, int> scan_units(const std::vector<Tok>& t) {
  for (std::size_t i = 0; i + 3 < t.size(); ++i)
    if (t[i].s == "UNITS" && t[i + 1].s == "DISTANCE" && t[i + 2].s == "MICRONS") {
      std::int64_t v = 0;
      auto [p, ec] = std::from_chars(t[i + 3].s.data(), t[i + 3].s.data() + t[i + 3].s.size(), v);
      if (ec == std::errc() && p == t[i + 3].s.data() + t[i + 3].s.size() && v > 0 && v <= 1'000'000) return {v, t[i].line};
      return {-1, t[i].line};
    }
  return {0, 1};
}

}  // namespace

DefImportResult import_def_text(const std::pair<std::string, std::string>& def,
                                const std::vector<std::pair<std::string, std::string>>& lefs,
                                const DefImportOptions& options) {
  DefImportResult r;
  try {
    std::vector<Tok> toks = tokenize(def.second);
    const auto [units, units_line] = scan_units(toks);
    Cursor dc(std::move(toks), def.first);
    {
      if (units == 0) dc.fail("IO-0121", "no UNITS DISTANCE MICRONS statement", 1);
      if (units < 0) dc.fail("IO-0123", "UNITS DISTANCE MICRONS is not an integer from 1 to 10^6", units_line);
      Lib lib;
      for (const auto& [name, text] : lefs) {
        Cursor lc(tokenize(text), name);
        parse_lef(lc, units, options.layer, lib);
      }
      r.diagnostics.insert(r.diagnostics.end(), lib.warnings.begin(), lib.warnings.end());
      Def d;
      parse_def(dc, options.layer, lib, d);
      if (d.units == 0)  // scanned but not read as a statement: swallowed by a statement missing its ';'
        dc.fail("IO-0121", "UNITS DISTANCE MICRONS is not read as a statement (is a ';' missing before it?)", units_line);
      r.diagnostics.insert(r.diagnostics.end(), d.warnings.begin(), d.warnings.end());
      r.layout = assemble(d, lib, options, dc, r.diagnostics, r.stats);
    }
  } catch (const Failure& f) {
    r.layout.reset();
    r.diagnostics.push_back(Diagnostic{Severity::Error, f.code, f.file, f.line, 0, f.message});
  }
  return r;
}

DefImportResult import_def(const std::string& def_path, const std::vector<std::string>& lef_paths,
                           const DefImportOptions& options) {
  auto read = [](const std::string& path) -> std::optional<std::string> {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return ss.str();
  };
  DefImportResult r;
  std::vector<std::pair<std::string, std::string>> lefs;
  for (const std::string& p : lef_paths) {
    auto t = read(p);
    if (!t) {
      r.diagnostics.push_back(Diagnostic{Severity::Error, "IO-0120", p, 0, 0, "cannot read the LEF file"});
      return r;
    }
    lefs.emplace_back(p, std::move(*t));
  }
  auto t = read(def_path);
  if (!t) {
    r.diagnostics.push_back(Diagnostic{Severity::Error, "IO-0120", def_path, 0, 0, "cannot read the DEF file"});
    return r;
  }
  return import_def_text({def_path, std::move(*t)}, lefs, options);
}

}  // namespace taut::io
