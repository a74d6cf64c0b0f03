// Secure layout reader (FORMAT.md) on libxml2; see layout_reader.h for the guarantees.
//
// Diagnostic codes issued here (stable; message always names file, line and the object):
//   IO-0001  the file cannot be opened or read (message carries the OS error)
//   IO-0002  the file is larger than ReadOptions::max_bytes (or than libxml2 can take, 2 GiB)
//   IO-0003  compressed input (gzip, zlib, xz, bzip2, zstd, lz4 magic) is refused: decompress it
//   IO-0004  the file is empty
//   IO-0005  XML is not well-formed or not valid UTF-8 (any libxml2 error; line:col from libxml2;
//            includes nesting deeper than libxml2's limit of 256 and undeclared entities)
//   IO-0006  a DOCTYPE (internal or external DTD, entity declarations) is refused
//   IO-0007  the root element is not <layout>
//   IO-0008  unknown element (warning with --lenient: the element and its content are skipped)
//   IO-0009  unknown attribute (warning with --lenient: the attribute is ignored)
//   IO-0010  a required attribute is missing
//   IO-0011  text content where only whitespace is allowed
//   IO-0012  an attribute that must be an integer is not -?[0-9]+
//   IO-0013  an integer attribute is outside [-(2^30-1), 2^30-1] or outside the attribute's range
//            (wire-width, spacing, bend-cost, bends >= 0; dbu-per-micron >= 1)
//   IO-0014  a points list is not "x,y x,y ..." (integers as IO-0012/IO-0013, whitespace between)
//   IO-0015  orientations is not rectilinear | octilinear | any | c:<deg>,<deg>,... (0 <= deg < 360)
//   IO-0016  an element that may appear at most once appears again (boundary, rules, routes,
//            sketch, a pin's shape)
//   IO-0017  a pin is not exactly one of: a point (x and y) or a shape (<rect> or <polygon>)
//   IO-0018  unsupported format version (only version="1")
//   IO-0019  route status is not routed|failed, or length is not an integer or decimal with 3
//            fractional digits
//   IO-0020  a blockage has no <rect> or <polygon>
//   IO-0021  a polyline (sketch, wire) has fewer than 2 points, or a ring fewer than 1
//   IO-0022  an id or name is empty
//   IO-0023  <routes metric> is not l1 | euclidean | combined | link (<routes orientations>: IO-0015,
//            also for a c: set with fewer than 2 directions modulo 180 degrees)
//   GEOM-0008 a rect or the boundary is empty (x0 >= x1 or y0 >= y1)
#include "io/layout_reader.h"

#include <libxml/parser.h>
#include <libxml/parserInternals.h>
#include <libxml/tree.h>
#include <libxml/xmlerror.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <utility>

namespace taut::io {
namespace {

constexpr int kMaxXmlErrors = 10;  // libxml2 may report a cascade; the first ones are enough
constexpr const char* kEmptyBox = "GEOM-0010";  // same code in validate_layout.cpp

// ---------------------------------------------------------------------------------------------
// libxml2 plumbing: per-parse state hangs off ctxt->_private, so concurrent parses on different
// threads never share anything but libxml2's own (thread-safe) globals.

struct ParseState {
  std::string file;
  std::vector<Diagnostic>* diagnostics = nullptr;
  int xml_errors = 0;
  bool doctype = false;
  startElementNsSAX2Func sax2_start = nullptr;  // libxml2's own tree builder ...
  charactersSAXFunc sax2_characters = nullptr;
  cdataBlockSAXFunc sax2_cdata = nullptr;
};

Diagnostic make_diag(Severity severity, std::string code, const std::string& file, int line,
                     std::string message, int column = 0) {
  Diagnostic d;
  d.severity = severity;
  d.code = std::move(code);
  d.file = file;
  d.line = line;
  d.column = column;
  d.message = std::move(message);
  return d;
}

ParseState* state_of(void* user) {
  auto* ctxt = static_cast<xmlParserCtxtPtr>(user);
  return ctxt ? static_cast<ParseState*>(ctxt->_private) : nullptr;
}

// Structured error handler: every libxml2 error or warning of this parse is a failure.
void on_xml_error(void* user, xmlErrorPtr error) {
  ParseState* st = state_of(user);
  if (!st || !error || st->doctype) return;  // after a refused DOCTYPE the rest is noise
  if (++st->xml_errors > kMaxXmlErrors) return;
  std::string msg = error->message ? error->message : "XML error";
  while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
  for (std::size_t i = 0; (i = msg.find('\n', i)) != std::string::npos;) msg.replace(i, 1, "; ");
  st->diagnostics->push_back(make_diag(Severity::Error, "IO-0005", st->file, error->line,
                                       "XML: " + msg, error->int2));
}

void refuse_doctype(void* user, const char* what) {
  auto* ctxt = static_cast<xmlParserCtxtPtr>(user);
  ParseState* st = state_of(user);
  if (!st) return;
  if (!st->doctype) {
    const int line = ctxt->input ? ctxt->input->line : 0;
    st->diagnostics->push_back(make_diag(
        Severity::Error, "IO-0006", st->file, line,
        std::string(what) + " refused: layout files may not contain a DOCTYPE, DTD or entities"));
  }
  st->doctype = true;
  xmlStopParser(ctxt);  // before a single declaration of the internal subset is read
}

void on_internal_subset(void* user, const xmlChar*, const xmlChar*, const xmlChar*) {
  refuse_doctype(user, "DOCTYPE");
}
void on_external_subset(void* user, const xmlChar*, const xmlChar*, const xmlChar*) {
  refuse_doctype(user, "external DTD");
}
void on_entity_decl(void* user, const xmlChar*, int, const xmlChar*, const xmlChar*, xmlChar*) {
  refuse_doctype(user, "entity declaration");
}

// Wraps libxml2's tree builder to keep each element's full line number in node->_private
// (node->line saturates at 65535 in libxml2 2.9).
void on_start_element(void* user, const xmlChar* localname, const xmlChar* prefix,
                      const xmlChar* uri, int nb_namespaces, const xmlChar** namespaces,
                      int nb_attributes, int nb_defaulted, const xmlChar** attributes) {
  auto* ctxt = static_cast<xmlParserCtxtPtr>(user);
  ParseState* st = state_of(user);
  st->sax2_start(user, localname, prefix, uri, nb_namespaces, namespaces, nb_attributes,
                 nb_defaulted, attributes);
  if (!ctxt->node || !ctxt->input) return;
  // The parser is just past the start tag's '>'; a raw '<' cannot occur inside a tag, so the
  // newlines between the tag's '<' and here give the line the tag starts on.
  int line = ctxt->input->line;
  const xmlChar* base = ctxt->input->base;
  const xmlChar* c = ctxt->input->cur;
  while (c > base && *(c - 1) != '<') {
    --c;
    line -= *c == '\n';
  }
  if (c == base) line = ctxt->input->line;  // tag start no longer buffered: use its end
  ctxt->node->_private = reinterpret_cast<void*>(static_cast<std::intptr_t>(line));
}

// Text nodes: libxml2 stamps them with the line where their first chunk ends; keep the line
// where they start instead, so "text is not allowed" points at the text.
void stamp_text(xmlParserCtxtPtr ctxt, xmlNode* before, const xmlChar* ch, int len) {
  if (!ctxt->node || !ctxt->input) return;
  xmlNode* last = ctxt->node->last;
  if (!last || last == before) return;  // appended to an existing text node
  int line = ctxt->input->line;
  for (int i = 0; i < len; ++i) line -= ch[i] == '\n';
  last->_private = reinterpret_cast<void*>(static_cast<std::intptr_t>(line));
}
void on_characters(void* user, const xmlChar* ch, int len) {
  auto* ctxt = static_cast<xmlParserCtxtPtr>(user);
  xmlNode* before = ctxt->node ? ctxt->node->last : nullptr;
  state_of(user)->sax2_characters(user, ch, len);
  stamp_text(ctxt, before, ch, len);
}
void on_cdata(void* user, const xmlChar* ch, int len) {
  auto* ctxt = static_cast<xmlParserCtxtPtr>(user);
  xmlNode* before = ctxt->node ? ctxt->node->last : nullptr;
  state_of(user)->sax2_cdata(user, ch, len);
  stamp_text(ctxt, before, ch, len);
}

// Loads nothing, ever: no file, no network, no catalog.
xmlParserInputPtr no_external_entities(const char*, const char*, xmlParserCtxtPtr) {
  return nullptr;
}

void silent_generic_error(void*, const char*, ...) {}

void init_libxml_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    xmlInitParser();
    xmlSetExternalEntityLoader(no_external_entities);
  });
}

// ---------------------------------------------------------------------------------------------
// Strict scalar parsing.

bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

enum class IntError { None, Syntax, Range };

// Strictly -?[0-9]+, the whole text, within [-kMaxCoord, kMaxCoord].
IntError parse_int(std::string_view s, std::int64_t& value) {
  std::size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
  if (i == s.size()) return IntError::Syntax;
  for (std::size_t j = i; j < s.size(); ++j)
    if (s[j] < '0' || s[j] > '9') return IntError::Syntax;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec == std::errc::result_out_of_range) return IntError::Range;
  if (ec != std::errc() || end != s.data() + s.size()) return IntError::Syntax;
  return geom::in_range(value) ? IntError::None : IntError::Range;
}

std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 60;  // keep messages readable for huge attributes
  std::string q = "\"";
  q += s.size() > kMax ? std::string(s.substr(0, kMax)) + "..." : std::string(s);
  q += "\"";
  return q;
}

// ---------------------------------------------------------------------------------------------
// The tree walk.

int line_of(const xmlNode* n) {
  const auto l = static_cast<int>(reinterpret_cast<std::intptr_t>(n->_private));
  return l > 0 ? l : static_cast<int>(xmlGetLineNo(n));
}

std::string_view name_of(const xmlNode* n) {
  return reinterpret_cast<const char*>(n->name);
}

// The value of an attribute without copying when it is one text node (the usual case).
std::string_view attr_value(const xmlAttr* a, std::string& scratch) {
  const xmlNode* c = a->children;
  if (!c) return {};
  if (!c->next && c->type == XML_TEXT_NODE && c->content)
    return reinterpret_cast<const char*>(c->content);
  scratch.clear();
  for (; c; c = c->next)
    if (c->content) scratch += reinterpret_cast<const char*>(c->content);
  return scratch;
}

constexpr int kMaxAttrs = 8;

// The attributes of one element that the format knows, looked up by position in `names`.
struct Attrs {
  std::array<std::string_view, kMaxAttrs> value{};
  std::array<bool, kMaxAttrs> present{};
  std::array<std::string, kMaxAttrs> scratch;
};

// The object a message is about, e.g. `blockage "ram0" rect`; built into a string only when a
// message is written (reading 10^6 vertices must not build 10^6 strings).
struct Ctx {
  Ctx(const std::string& b, const char* s = nullptr) : base(&b), suffix(s) {}
  Ctx(const char* literal) : literal(literal) {}
  Ctx(const Ctx& c, const char* s) : base(c.base), literal(c.literal), suffix(s) {}
  std::string str() const {
    std::string s = base ? *base : std::string(literal);
    if (suffix) s += suffix;
    return s;
  }
  const std::string* base = nullptr;
  const char* literal = "";
  const char* suffix = nullptr;
};
std::string operator+(const Ctx& c, const char* s) { return c.str() + s; }

class Reader {
 public:
  Reader(std::string file, const ReadOptions& options, std::vector<Diagnostic>& diagnostics)
      : file_(std::move(file)), options_(options), diagnostics_(diagnostics) {}

  void read_layout(const xmlNode* root, Layout& layout) {
    layout.line = line_of(root);
    Attrs a;
    if (!attrs(root, "layout", {"name", "version", "dbu-per-micron"}, a)) return;
    if (a.present[0]) layout.name = std::string(a.value[0]);
    if (a.present[1]) {
      std::int64_t v = 0;
      if (integer(root, "layout", "version", a.value[1], v) && v != 1)
        error("IO-0018", line_of(root),
              "layout: version " + quoted(a.value[1]) + " is not supported (only version 1)");
      layout.version = static_cast<int>(v);
    }
    if (a.present[2]) integer(root, "layout", "dbu-per-micron", a.value[2], layout.dbu_per_micron, 1);

    for (const xmlNode* c = root->children; c; c = c->next) {
      if (!is_element(c, "layout")) continue;
      const std::string_view n = name_of(c);
      if (n == "boundary") {
        if (layout.boundary) once_error(c, "layout", layout.boundary->line);
        Boundary b;
        read_boundary(c, b);
        if (!layout.boundary) layout.boundary = b;
      } else if (n == "rules") {
        if (layout.rules) once_error(c, "layout", layout.rules->line);
        Rules r;
        read_rules(c, r);
        if (!layout.rules) layout.rules = std::move(r);
      } else if (n == "blockage") {
        layout.blockages.emplace_back();
        read_blockage(c, layout.blockages.back());
      } else if (n == "net") {
        layout.nets.emplace_back();
        read_net(c, layout.nets.back());
      } else if (n == "routes") {
        if (layout.routes) once_error(c, "layout", layout.routes->line);
        Routes r;
        read_routes(c, r);
        if (!layout.routes) layout.routes = std::move(r);
      } else {
        unknown_element(c, "layout");
      }
    }
  }

 private:
  void error(const char* code, int line, std::string message) {
    diagnostics_.push_back(make_diag(Severity::Error, code, file_, line, std::move(message)));
  }
  void lenient_error(const char* code, int line, std::string message) {
    diagnostics_.push_back(make_diag(options_.lenient ? Severity::Warning : Severity::Error, code,
                                     file_, line, std::move(message)));
  }

  void unknown_element(const xmlNode* n, const Ctx& ctx) {
    std::string name(name_of(n));
    if (n->ns && n->ns->href)
      name = "{" + std::string(reinterpret_cast<const char*>(n->ns->href)) + "}" + name;
    lenient_error("IO-0008", line_of(n),
                  ctx + ": unknown element <" + name + ">" +
                      (options_.lenient ? " skipped" : ""));
  }

  void once_error(const xmlNode* n, const Ctx& ctx, int first_line) {
    error("IO-0016", line_of(n),
          ctx + ": <" + std::string(name_of(n)) + "> may appear only once (first on line " +
              std::to_string(first_line) + ")");
  }

  // True for an element to interpret. Text must be whitespace; comments and processing
  // instructions are ignored; an element in a namespace is unknown.
  bool is_element(const xmlNode* n, const Ctx& ctx) {
    switch (n->type) {
      case XML_ELEMENT_NODE:
        if (n->ns) {
          unknown_element(n, ctx);
          return false;
        }
        return true;
      case XML_TEXT_NODE:
      case XML_CDATA_SECTION_NODE: {
        const char* s = reinterpret_cast<const char*>(n->content);
        for (; s && *s; ++s)
          if (!is_xml_space(*s)) {
            // Text nodes start where the text starts; report the first non-space line.
            int line = line_of(n);
            for (const char* t = reinterpret_cast<const char*>(n->content); t < s; ++t)
              line += *t == '\n';
            error("IO-0011", line, ctx + ": text " + quoted(std::string_view(s).substr(0, 20)) +
                                       " is not allowed here");
            return false;
          }
        return false;
      }
      default:
        return false;  // comments, processing instructions
    }
  }

  // Elements with no children of their own (rect, hole, boundary, rules, sketch, wire).
  void no_children(const xmlNode* n, const Ctx& ctx) {
    for (const xmlNode* c = n->children; c; c = c->next)
      if (is_element(c, ctx)) unknown_element(c, ctx);
  }

  // Collects known attributes; unknown ones are IO-0009. Returns false on a hard error.
  bool attrs(const xmlNode* n, const Ctx& ctx, std::initializer_list<const char*> names,
             Attrs& out) {
    bool ok = true;
    for (const xmlAttr* a = n->properties; a; a = a->next) {
      const std::string_view an = reinterpret_cast<const char*>(a->name);
      int k = 0, found = -1;
      for (const char* known : names) {
        if (!a->ns && an == known) found = k;
        ++k;
      }
      if (found < 0) {
        std::string full(an);
        if (a->ns && a->ns->prefix)
          full = std::string(reinterpret_cast<const char*>(a->ns->prefix)) + ":" + full;
        lenient_error("IO-0009", line_of(n),
                      ctx + ": unknown attribute " + full + (options_.lenient ? " ignored" : ""));
        ok = ok && options_.lenient;
        continue;
      }
      out.value[found] = attr_value(a, out.scratch[found]);
      out.present[found] = true;
    }
    return ok;
  }

  bool require(const xmlNode* n, const Ctx& ctx, const Attrs& a,
               std::initializer_list<std::pair<int, const char*>> required) {
    bool ok = true;
    for (const auto& [k, name] : required)
      if (!a.present[k]) {
        error("IO-0010", line_of(n), ctx + ": missing attribute " + name);
        ok = false;
      }
    return ok;
  }

  bool integer(const xmlNode* n, const Ctx& ctx, const char* attr, std::string_view text,
               std::int64_t& value, std::int64_t min = -geom::kMaxCoord) {
    switch (parse_int(text, value)) {
      case IntError::Syntax:
        error("IO-0012", line_of(n),
              ctx + ": attribute " + attr + ": " + quoted(text) + " is not an integer");
        return false;
      case IntError::Range:
        error("IO-0013", line_of(n),
              ctx + ": attribute " + attr + ": " + quoted(text) + " is out of range [" +
                  std::to_string(min) + ", " + std::to_string(geom::kMaxCoord) + "]");
        return false;
      case IntError::None:
        break;
    }
    if (value < min) {
      error("IO-0013", line_of(n),
            ctx + ": attribute " + attr + ": " + quoted(text) + " is out of range [" +
                std::to_string(min) + ", " + std::to_string(geom::kMaxCoord) + "]");
      return false;
    }
    return true;
  }

  bool coord(const xmlNode* n, const Ctx& ctx, const char* attr, std::string_view text,
             geom::Coord& c) {
    std::int64_t v = 0;
    if (!integer(n, ctx, attr, text, v)) return false;
    c = static_cast<geom::Coord>(v);
    return true;
  }

  // "x,y x,y ...": pairs separated by XML whitespace, optional whitespace at both ends.
  bool points(const xmlNode* n, const Ctx& ctx, std::string_view text,
              std::vector<Point>& out) {
    const char* p = text.data();
    const char* const end = p + text.size();
    auto fail = [&](const std::string& why) {
      error("IO-0014", line_of(n), ctx + ": attribute points: " + quoted(text) + ": " + why);
      return false;
    };
    auto number = [&](geom::Coord& c, char stop) {
      const char* q = p;
      while (q < end && *q != stop && !is_xml_space(*q) && (stop != ' ' || *q != ',')) ++q;
      std::int64_t v = 0;
      const std::string_view tok(p, static_cast<std::size_t>(q - p));
      switch (parse_int(tok, v)) {
        case IntError::Syntax:
          return fail("vertex " + std::to_string(out.size() + 1) + ": " + quoted(tok) +
                      " is not an integer");
        case IntError::Range:
          return fail("vertex " + std::to_string(out.size() + 1) + ": " + quoted(tok) + " is out of range [" +
                      std::to_string(-geom::kMaxCoord) + ", " + std::to_string(geom::kMaxCoord) + "]");
        case IntError::None:
          break;
      }
      c = static_cast<geom::Coord>(v);
      p = q;
      return true;
    };
    out.clear();
    while (p < end && is_xml_space(*p)) ++p;
    while (p < end) {
      Point pt;
      if (!number(pt.x, ',')) return false;
      if (p == end || *p != ',')
        return fail("vertex " + std::to_string(out.size() + 1) + " is not x,y");
      ++p;
      if (!number(pt.y, ' ')) return false;
      out.push_back(pt);
      if (p < end && !is_xml_space(*p))
        return fail("vertex " + std::to_string(out.size()) + " is not x,y");
      while (p < end && is_xml_space(*p)) ++p;
    }
    if (out.empty()) return fail("no vertices");
    return true;
  }

  bool box(const xmlNode* n, const Ctx& ctx, Box& b) {
    Attrs a;
    bool ok = attrs(n, ctx, {"x0", "y0", "x1", "y1"}, a);
    ok = require(n, ctx, a, {{0, "x0"}, {1, "y0"}, {2, "x1"}, {3, "y1"}}) && ok;
    if (!ok) return false;
    ok = coord(n, ctx, "x0", a.value[0], b.lo.x) && ok;
    ok = coord(n, ctx, "y0", a.value[1], b.lo.y) && ok;
    ok = coord(n, ctx, "x1", a.value[2], b.hi.x) && ok;
    ok = coord(n, ctx, "y1", a.value[3], b.hi.y) && ok;
    if (ok && (b.lo.x >= b.hi.x || b.lo.y >= b.hi.y)) {
      error(kEmptyBox, line_of(n),
            ctx + " (" + std::to_string(b.lo.x) + "," + std::to_string(b.lo.y) +
                ")-(" + std::to_string(b.hi.x) + "," + std::to_string(b.hi.y) +
                ") is empty: needs x0 < x1 and y0 < y1");
      ok = false;
    }
    no_children(n, ctx);
    return ok;
  }

  void read_boundary(const xmlNode* n, Boundary& b) {
    b.line = line_of(n);
    box(n, "boundary", b.box);
  }

  void read_rules(const xmlNode* n, Rules& r) {
    r.line = line_of(n);
    const std::string ctx = "rules";
    Attrs a;
    attrs(n, ctx, {"wire-width", "spacing", "bend-cost", "orientations"}, a);
    if (a.present[0]) integer(n, ctx, "wire-width", a.value[0], r.wire_width, 0);
    if (a.present[1]) integer(n, ctx, "spacing", a.value[1], r.spacing, 0);
    if (a.present[2]) integer(n, ctx, "bend-cost", a.value[2], r.bend_cost, 0);
    if (a.present[3]) orientations(n, ctx, a.value[3], r);
    no_children(n, ctx);
  }

  // rectilinear | octilinear | any | c:<deg>,<deg>,...  with <deg> = [0-9]+(.[0-9]+)?, < 360.
  void orientations(const xmlNode* n, const Ctx& ctx, std::string_view text, Rules& r) {
    r.orientations = std::string(text);
    r.orientation_degrees.clear();
    if (text == "rectilinear" || text == "octilinear" || text == "any") return;
    auto fail = [&](const std::string& why) {
      error("IO-0015", line_of(n),
            ctx + ": attribute orientations: " + quoted(text) + ": " + why +
                " (expected rectilinear, octilinear, any or c:<deg>,<deg>,...)");
    };
    if (text.substr(0, 2) != "c:") return fail("unknown orientation set");
    std::string_view rest = text.substr(2);
    while (true) {
      const std::size_t comma = rest.find(',');
      const std::string_view tok = rest.substr(0, comma);
      // Digits, optionally one '.' followed by digits: no sign, exponent, inf or nan.
      std::size_t dot = tok.find('.');
      const std::string_view ip = tok.substr(0, dot);
      const std::string_view fp = dot == std::string_view::npos ? "" : tok.substr(dot + 1);
      auto digits = [](std::string_view s) {
        if (s.empty()) return false;
        for (char c : s)
          if (c < '0' || c > '9') return false;
        return true;
      };
      if (!digits(ip) || (dot != std::string_view::npos && !digits(fp)))
        return fail("direction " + quoted(tok) + " is not a number of degrees");
      double deg = 0;
      const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), deg);
      if (ec != std::errc() || end != tok.data() + tok.size() || !(deg < 360.0))
        return fail("direction " + quoted(tok) + " is not in [0, 360)");
      r.orientation_degrees.push_back(deg);
      if (comma == std::string_view::npos) break;
      rest = rest.substr(comma + 1);
    }
  }

  bool name_attr(const xmlNode* n, const Ctx& ctx, const Attrs& a, int k, const char* attr,
                 std::string& out) {
    if (!a.present[k]) {
      error("IO-0010", line_of(n), ctx + ": missing attribute " + attr);
      return false;
    }
    out = std::string(a.value[k]);
    if (out.empty()) {
      error("IO-0022", line_of(n), ctx + ": attribute " + attr + " is empty");
      return false;
    }
    return true;
  }

  // A <rect> or <polygon> (with <hole>s) child; ctx names the owner.
  bool read_shape(const xmlNode* n, const Ctx& ctx, Shape& s) {
    s.line = line_of(n);
    const std::string_view name = name_of(n);
    if (name == "rect") {
      s.kind = Shape::Kind::Rect;
      return box(n, Ctx(ctx, " rect"), s.rect);
    }
    s.kind = Shape::Kind::Polygon;
    const std::string pctx = ctx + " polygon";
    Attrs a;
    bool ok = attrs(n, pctx, {"points"}, a);
    ok = require(n, pctx, a, {{0, "points"}}) && ok;
    if (ok) ok = ring(n, pctx, a.value[0], s.polygon.outer);
    for (const xmlNode* c = n->children; c; c = c->next) {
      if (!is_element(c, pctx)) continue;
      if (name_of(c) != "hole") {
        unknown_element(c, pctx);
        continue;
      }
      const std::string hctx = pctx + " hole";
      Attrs h;
      bool hok = attrs(c, hctx, {"points"}, h);
      hok = require(c, hctx, h, {{0, "points"}}) && hok;
      geom::Ring hole;
      if (hok) hok = ring(c, hctx, h.value[0], hole);
      no_children(c, hctx);
      s.polygon.holes.push_back(std::move(hole));
      s.hole_lines.push_back(line_of(c));
      ok = ok && hok;
    }
    return ok;
  }

  // A ring's closing vertex (equal to the first) is dropped; validity is validate_layout's job.
  bool ring(const xmlNode* n, const Ctx& ctx, std::string_view text, geom::Ring& r) {
    if (!points(n, ctx, text, r)) return false;
    if (r.size() >= 2 && r.front() == r.back()) r.pop_back();
    return true;
  }

  void read_blockage(const xmlNode* n, Blockage& b) {
    b.line = line_of(n);
    Attrs a;
    attrs(n, "blockage", {"id"}, a);
    name_attr(n, "blockage", a, 0, "id", b.id);
    const std::string ctx = b.id.empty() ? std::string("blockage") : "blockage \"" + b.id + "\"";
    for (const xmlNode* c = n->children; c; c = c->next) {
      if (!is_element(c, ctx)) continue;
      const std::string_view cn = name_of(c);
      if (cn == "rect" || cn == "polygon") {
        Shape s;
        read_shape(c, ctx, s);
        b.shapes.push_back(std::move(s));
      } else {
        unknown_element(c, ctx);
      }
    }
    if (b.shapes.empty()) error("IO-0020", b.line, ctx + ": has no <rect> or <polygon>");
  }

  bool polyline(const xmlNode* n, const Ctx& ctx, std::vector<Point>& pts) {
    Attrs a;
    bool ok = attrs(n, ctx, {"points"}, a);
    ok = require(n, ctx, a, {{0, "points"}}) && ok;
    if (ok) ok = points(n, ctx, a.value[0], pts);
    if (ok && pts.size() < 2) {
      error("IO-0021", line_of(n), ctx + ": needs at least 2 points");
      ok = false;
    }
    no_children(n, ctx);
    return ok;
  }

  void read_net(const xmlNode* n, Net& net) {
    net.line = line_of(n);
    Attrs a;
    attrs(n, "net", {"name"}, a);
    name_attr(n, "net", a, 0, "name", net.name);
    const std::string ctx = net.name.empty() ? std::string("net") : "net \"" + net.name + "\"";
    for (const xmlNode* c = n->children; c; c = c->next) {
      if (!is_element(c, ctx)) continue;
      const std::string_view cn = name_of(c);
      if (cn == "pin") {
        net.pins.emplace_back();
        read_pin(c, ctx, net.pins.back());
      } else if (cn == "sketch") {
        if (net.sketch) once_error(c, ctx, net.sketch->line);
        Sketch s;
        s.line = line_of(c);
        polyline(c, ctx + " sketch", s.points);
        if (!net.sketch) net.sketch = std::move(s);
      } else {
        unknown_element(c, ctx);
      }
    }
  }

  void read_pin(const xmlNode* n, const std::string& net_ctx, Pin& pin) {
    pin.line = line_of(n);
    Attrs a;
    attrs(n, net_ctx + " pin", {"name", "x", "y"}, a);
    name_attr(n, net_ctx + " pin", a, 0, "name", pin.name);
    const std::string ctx =
        net_ctx + (pin.name.empty() ? std::string(" pin") : " pin \"" + pin.name + "\"");
    for (const xmlNode* c = n->children; c; c = c->next) {
      if (!is_element(c, ctx)) continue;
      const std::string_view cn = name_of(c);
      if (cn == "rect" || cn == "polygon") {
        if (pin.shape) {
          once_error(c, ctx, pin.shape->line);
          continue;
        }
        Shape s;
        read_shape(c, ctx, s);
        pin.shape = std::move(s);
      } else {
        unknown_element(c, ctx);
      }
    }
    if (a.present[1] != a.present[2] || a.present[1] == pin.shape.has_value()) {
      error("IO-0017", pin.line,
            ctx + ": a pin is either a point (x and y) or a shape (<rect> or <polygon>)");
      return;
    }
    if (a.present[1]) {
      Point p;
      const bool ok = coord(n, ctx, "x", a.value[1], p.x);
      if (coord(n, ctx, "y", a.value[2], p.y) && ok) pin.point = p;
    }
  }

  void read_routes(const xmlNode* n, Routes& r) {
    r.line = line_of(n);
    Attrs a;
    attrs(n, "routes", {"tool", "metric", "orientations", "bend-cost"}, a);
    if (a.present[0]) r.tool = std::string(a.value[0]);
    // (since 2026-12-06 the values are checked: before, a typo such as orientations="rectilniear"
    // made taut check skip the wires' directions without a word; found by fuzzing)
    if (a.present[1]) {
      r.metric = std::string(a.value[1]);
      if (r.metric != "l1" && r.metric != "euclidean" && r.metric != "combined" && r.metric != "link")
        error("IO-0023", line_of(n), "routes: attribute metric: " + quoted(r.metric) + " is not l1, euclidean, combined or link");
    }
    if (a.present[2]) {
      Rules syntax;  // the same values as <rules orientations> (IO-0015)
      const std::size_t before = diagnostics_.size();
      orientations(n, Ctx("routes"), a.value[2], syntax);
      r.orientations = std::string(a.value[2]);
      // and, as LAYOUT-0014 asks of <rules>, two directions at least modulo 180 degrees
      if (diagnostics_.size() == before && !syntax.orientation_degrees.empty() && distinct_orientations(syntax.orientation_degrees) < 2)
        error("IO-0015", line_of(n),
              "routes: attribute orientations: " + quoted(r.orientations) + " has fewer than 2 distinct directions modulo 180 degrees");
    }
    std::int64_t c = 0;
    if (a.present[3] && integer(n, Ctx("routes"), "bend-cost", a.value[3], c, 0)) r.bend_cost = c;
    for (const xmlNode* c = n->children; c; c = c->next) {
      if (!is_element(c, "routes")) continue;
      if (name_of(c) != "route") {
        unknown_element(c, "routes");
        continue;
      }
      r.routes.emplace_back();
      read_route(c, r.routes.back());
    }
  }

  void read_route(const xmlNode* n, Route& r) {
    r.line = line_of(n);
    Attrs a;
    attrs(n, "route", {"net", "status", "length", "bends", "reason"}, a);
    name_attr(n, "route", a, 0, "net", r.net);
    const std::string ctx = r.net.empty() ? std::string("route") : "route \"" + r.net + "\"";
    if (!a.present[1]) {
      error("IO-0010", r.line, ctx + ": missing attribute status");
    } else {
      r.status = std::string(a.value[1]);
      if (r.status != "routed" && r.status != "failed")
        error("IO-0019", r.line,
              ctx + ": attribute status: " + quoted(r.status) + " is not routed or failed");
    }
    if (a.present[2]) {
      // An integer, or a decimal with exactly 3 fractional digits; never negative.
      const std::string_view s = a.value[2];
      const std::size_t dot = s.find('.');
      const std::string_view ip = s.substr(0, dot);
      const std::string_view fp = dot == std::string_view::npos ? "" : s.substr(dot + 1);
      auto digits = [](std::string_view t) {
        for (char c : t)
          if (c < '0' || c > '9') return false;
        return !t.empty();
      };
      if (!digits(ip) || (dot != std::string_view::npos && (fp.size() != 3 || !digits(fp))))
        error("IO-0019", r.line,
              ctx + ": attribute length: " + quoted(s) +
                  " is not an integer or a decimal with 3 fractional digits");
      else
        r.length = std::string(s);
    }
    if (a.present[3]) {
      std::int64_t b = 0;
      if (integer(n, ctx, "bends", a.value[3], b, 0)) r.bends = b;
    }
    if (a.present[4]) r.reason = std::string(a.value[4]);
    for (const xmlNode* c = n->children; c; c = c->next) {
      if (!is_element(c, ctx)) continue;
      if (name_of(c) != "wire") {
        unknown_element(c, ctx);
        continue;
      }
      Wire w;
      w.line = line_of(c);
      polyline(c, ctx + " wire", w.points);
      r.wires.push_back(std::move(w));
    }
  }

  std::string file_;
  const ReadOptions& options_;
  std::vector<Diagnostic>& diagnostics_;
};

// The magic numbers of compressed formats; a layout must be plain XML.
const char* compression_of(std::string_view b) {
  auto starts = [&](std::initializer_list<unsigned char> m) {
    if (b.size() < m.size()) return false;
    std::size_t i = 0;
    for (unsigned char c : m)
      if (static_cast<unsigned char>(b[i++]) != c) return false;
    return true;
  };
  if (starts({0x1f, 0x8b})) return "gzip";
  if (starts({0xfd, '7', 'z', 'X', 'Z', 0x00})) return "xz";
  if (starts({'B', 'Z', 'h'})) return "bzip2";
  if (starts({0x28, 0xb5, 0x2f, 0xfd})) return "zstd";
  if (starts({0x04, 0x22, 0x4d, 0x18})) return "lz4";
  if (b.size() >= 2) {
    // zlib (RFC 1950): CM = 8, CINFO <= 7, and the header is a multiple of 31.
    const unsigned c0 = static_cast<unsigned char>(b[0]), c1 = static_cast<unsigned char>(b[1]);
    if ((c0 & 0x0f) == 8 && (c0 >> 4) <= 7 && (c0 * 256 + c1) % 31 == 0) return "zlib";
  }
  return nullptr;
}

}  // namespace

ReadResult parse_layout(std::string_view bytes, const std::string& name,
                        const ReadOptions& options) {
  ReadResult result;
  auto& diags = result.diagnostics;
  if (bytes.empty()) {
    diags.push_back(make_diag(Severity::Error, "IO-0004", name, 0, "the file is empty"));
    return result;
  }
  if (bytes.size() > options.max_bytes || bytes.size() > static_cast<std::size_t>(INT_MAX)) {
    diags.push_back(make_diag(Severity::Error, "IO-0002", name, 0,
                              "the input has " + std::to_string(bytes.size()) +
                                  " bytes, more than the limit of " +
                                  std::to_string(std::min<std::size_t>(options.max_bytes, INT_MAX))));
    return result;
  }
  if (const char* z = compression_of(bytes)) {
    diags.push_back(make_diag(Severity::Error, "IO-0003", name, 0,
                              std::string(z) +
                                  "-compressed input is refused: decompress the layout first"));
    return result;
  }

  init_libxml_once();
  // libxml2's generic error channel is thread-local: silence it for this parse, then restore.
  xmlGenericErrorFunc saved_generic = xmlGenericError;
  void* saved_generic_ctx = xmlGenericErrorContext;
  xmlSetGenericErrorFunc(nullptr, silent_generic_error);

  ParseState st;
  st.file = name;
  st.diagnostics = &diags;
  xmlParserCtxtPtr ctxt = xmlNewParserCtxt();
  if (!ctxt) {
    xmlSetGenericErrorFunc(saved_generic_ctx, saved_generic);
    diags.push_back(make_diag(Severity::Error, "IO-0005", name, 0, "XML: out of memory"));
    return result;
  }
  ctxt->_private = &st;
  st.sax2_start = ctxt->sax->startElementNs;
  ctxt->sax->startElementNs = on_start_element;
  st.sax2_characters = ctxt->sax->characters;
  st.sax2_cdata = ctxt->sax->cdataBlock;
  ctxt->sax->characters = on_characters;
  ctxt->sax->ignorableWhitespace = on_characters;
  ctxt->sax->cdataBlock = on_cdata;
  ctxt->sax->serror = on_xml_error;
  ctxt->sax->internalSubset = on_internal_subset;
  ctxt->sax->externalSubset = on_external_subset;
  ctxt->sax->entityDecl = on_entity_decl;
  ctxt->sax->error = nullptr;
  ctxt->sax->warning = nullptr;

  // XML_PARSE_NONET only: no entity substitution, no DTD loading, no huge documents (which
  // keeps libxml2's 256-level depth limit), no recovery, no XInclude.
  xmlDocPtr doc = xmlCtxtReadMemory(ctxt, bytes.data(), static_cast<int>(bytes.size()),
                                    name.c_str(), nullptr, XML_PARSE_NONET);
  const bool well_formed = ctxt->wellFormed != 0;
  const int err_no = ctxt->errNo;
  xmlFreeParserCtxt(ctxt);
  xmlSetGenericErrorFunc(saved_generic_ctx, saved_generic);

  if (doc && !st.doctype && (doc->intSubset || doc->extSubset)) {
    st.doctype = true;
    diags.push_back(make_diag(Severity::Error, "IO-0006", name, 0,
                              "DOCTYPE refused: layout files may not contain a DTD"));
  }
  if (!st.doctype && st.xml_errors == 0 && (!doc || !well_formed)) {
    diags.push_back(make_diag(Severity::Error, "IO-0005", name, 0,
                              "XML: not well-formed (libxml2 error " + std::to_string(err_no) +
                                  ")"));
  }
  if (has_error(diags) || !doc) {
    if (doc) xmlFreeDoc(doc);
    return result;
  }

  const xmlNode* root = xmlDocGetRootElement(doc);
  Layout layout;
  layout.file = name;
  if (!root || root->ns || name_of(root) != "layout") {
    diags.push_back(make_diag(Severity::Error, "IO-0007", name, root ? line_of(root) : 0,
                              "the root element is <" +
                                  std::string(root ? name_of(root) : "") +
                                  ">, expected <layout>"));
  } else {
    Reader(name, options, diags).read_layout(root, layout);
  }
  xmlFreeDoc(doc);
  if (!has_error(diags)) result.layout = std::move(layout);
  return result;
}

ReadResult read_layout(const std::string& path, const ReadOptions& options) {
  ReadResult result;
  auto fail = [&](const char* code, std::string message) {
    result.diagnostics.push_back(make_diag(Severity::Error, code, path, 0, std::move(message)));
    return result;
  };
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return fail("IO-0001", std::string("cannot open: ") + std::strerror(errno));
  // Read in chunks up to the cap (+1 byte to detect "larger"): works for pipes and growing
  // files too, and never allocates more than the cap.
  std::string bytes;
  const std::size_t cap = options.max_bytes;
  std::array<char, 1 << 16> buf;
  bool too_big = false, read_error = false;
  int saved_errno = 0;
  while (true) {
    const std::size_t n = std::fread(buf.data(), 1, buf.size(), f);
    if (n > 0) {
      if (bytes.size() + n > cap) {
        too_big = true;
        break;
      }
      bytes.append(buf.data(), n);
    }
    if (n < buf.size()) {
      if (std::ferror(f)) {
        read_error = true;
        saved_errno = errno;
      }
      break;
    }
  }
  std::fclose(f);
  if (read_error) return fail("IO-0001", std::string("cannot read: ") + std::strerror(saved_errno));
  if (too_big)
    return fail("IO-0002", "the file is larger than the limit of " + std::to_string(cap) +
                               " bytes");
  return parse_layout(bytes, path, options);
}

std::optional<std::int64_t> parse_coordinate(std::string_view text) {
  std::int64_t v = 0;
  if (parse_int(text, v) != IntError::None) return std::nullopt;
  return v;
}

}  // namespace taut::io
