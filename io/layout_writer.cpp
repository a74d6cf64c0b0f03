// layout_to_xml: FORMAT.md XML, 2-space indentation, attributes in FORMAT.md's order.
//
// Built by appending to one string with std::to_chars (no DOM): a generated layout with 10^6
// vertices is written in well under a second.
#include "io/layout_writer.h"

#include "io/xml_text.h"

#include <charconv>

namespace taut::io {
namespace {

class XmlOut {
 public:
  static constexpr const char* kReplacement = "\xEF\xBF\xBD";  // U+FFFD

  std::string& str() { return out_; }

  void indent(int level) { out_.append(static_cast<std::size_t>(2 * level), ' '); }

  void number(std::int64_t v) {
    char buf[24];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    out_.append(buf, end);
  }

  // Attribute value: escapes the five XML specials, and tab/newline/CR as character references
  // (a parser would otherwise normalize them to spaces, breaking the round trip). Bytes that
  // XML 1.0 cannot carry (other control characters, invalid UTF-8) become U+FFFD, so the output
  // is always well-formed; names read from a layout file never contain them (taut import refuses
  // DEF and LEF names with them, IO-0130).
  void escaped(std::string_view s) {
    for (std::size_t i = 0; i < s.size(); ++i) {
      const char c = s[i];
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x80) {
        const std::size_t n = utf8_length(s, i);
        if (n == 0) {
          out_ += kReplacement;
        } else {
          out_.append(s.substr(i, n));
          i += n - 1;
        }
        continue;
      }
      switch (c) {
        case '&': out_ += "&amp;"; break;
        case '<': out_ += "&lt;"; break;
        case '>': out_ += "&gt;"; break;
        case '"': out_ += "&quot;"; break;
        case '\'': out_ += "&apos;"; break;
        case '\t': out_ += "&#9;"; break;
        case '\n': out_ += "&#10;"; break;
        case '\r': out_ += "&#13;"; break;
        default:
          if (u < 0x20)
            out_ += kReplacement;
          else
            out_ += c;
      }
    }
  }

  void attr(const char* name, std::string_view value) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    escaped(value);
    out_ += '"';
  }
  void attr(const char* name, std::int64_t value) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    number(value);
    out_ += '"';
  }
  void points(const char* name, const std::vector<Point>& pts) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (i) out_ += ' ';
      number(pts[i].x);
      out_ += ',';
      number(pts[i].y);
    }
    out_ += '"';
  }
  void box(const Box& b) {
    attr("x0", b.lo.x);
    attr("y0", b.lo.y);
    attr("x1", b.hi.x);
    attr("y1", b.hi.y);
  }

 private:
  std::string out_;
};

bool is_one_liner(const Shape& s) {
  return s.kind == Shape::Kind::Rect || s.polygon.holes.empty();
}

// A <rect> or <polygon> (with <hole> children on their own lines at level + 1). Leaves the
// cursor right after the closing '>' without a newline.
void write_shape(XmlOut& o, const Shape& s, int level) {
  std::string& out = o.str();
  if (s.kind == Shape::Kind::Rect) {
    out += "<rect";
    o.box(s.rect);
    out += "/>";
    return;
  }
  out += "<polygon";
  o.points("points", s.polygon.outer);
  if (s.polygon.holes.empty()) {
    out += "/>";
    return;
  }
  out += ">\n";
  for (const auto& hole : s.polygon.holes) {
    o.indent(level + 1);
    out += "<hole";
    o.points("points", hole);
    out += "/>\n";
  }
  o.indent(level);
  out += "</polygon>";
}

// Children of a <blockage> or shape <pin>: on the same line when there is a single simple
// shape (as in FORMAT.md's example), one per line otherwise.
void write_shapes(XmlOut& o, const std::vector<const Shape*>& shapes, int level,
                  const char* close_tag) {
  std::string& out = o.str();
  if (shapes.size() == 1 && is_one_liner(*shapes[0])) {
    out += '>';
    write_shape(o, *shapes[0], level);
  } else {
    out += ">\n";
    for (const Shape* s : shapes) {
      o.indent(level + 1);
      write_shape(o, *s, level + 1);
      out += '\n';
    }
    o.indent(level);
  }
  out += close_tag;
  out += '\n';
}

}  // namespace

std::string layout_to_xml(const Layout& layout) {
  XmlOut o;
  std::string& out = o.str();
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<layout";
  o.attr("name", layout.name);
  o.attr("version", layout.version);
  o.attr("dbu-per-micron", layout.dbu_per_micron);
  out += ">\n";

  if (layout.boundary) {
    o.indent(1);
    out += "<boundary";
    o.box(layout.boundary->box);
    out += "/>\n";
  }
  if (layout.rules) {
    const Rules& r = *layout.rules;
    o.indent(1);
    out += "<rules";
    o.attr("wire-width", r.wire_width);
    o.attr("spacing", r.spacing);
    o.attr("bend-cost", r.bend_cost);
    o.attr("orientations", r.orientations);
    out += "/>\n";
  }

  if (!layout.blockages.empty()) out += '\n';
  for (const Blockage& b : layout.blockages) {
    o.indent(1);
    out += "<blockage";
    o.attr("id", b.id);
    if (b.shapes.empty()) {
      out += "/>\n";
      continue;
    }
    std::vector<const Shape*> shapes;
    for (const Shape& s : b.shapes) shapes.push_back(&s);
    write_shapes(o, shapes, 1, "</blockage>");
  }

  for (const Net& n : layout.nets) {
    out += '\n';
    o.indent(1);
    out += "<net";
    o.attr("name", n.name);
    if (n.pins.empty() && !n.sketch) {
      out += "/>\n";
      continue;
    }
    out += ">\n";
    for (const Pin& p : n.pins) {
      o.indent(2);
      out += "<pin";
      o.attr("name", p.name);
      if (p.point) {
        o.attr("x", p.point->x);
        o.attr("y", p.point->y);
      }
      if (p.shape) {
        write_shapes(o, {&*p.shape}, 2, "</pin>");
      } else {
        out += "/>\n";
      }
    }
    if (n.sketch) {
      o.indent(2);
      out += "<sketch";
      o.points("points", n.sketch->points);
      out += "/>\n";
    }
    o.indent(1);
    out += "</net>\n";
  }

  if (layout.routes) {
    const Routes& rs = *layout.routes;
    out += '\n';
    o.indent(1);
    out += "<routes";
    o.attr("tool", rs.tool);
    if (!rs.metric.empty()) o.attr("metric", rs.metric);
    if (!rs.orientations.empty()) o.attr("orientations", rs.orientations);
    if (rs.bend_cost) o.attr("bend-cost", *rs.bend_cost);
    if (rs.routes.empty()) {
      out += "/>\n";
    } else {
      out += ">\n";
      for (const Route& r : rs.routes) {
        o.indent(2);
        out += "<route";
        o.attr("net", r.net);
        o.attr("status", r.status);
        if (r.length) o.attr("length", *r.length);
        if (r.bends) o.attr("bends", *r.bends);
        if (r.reason) o.attr("reason", *r.reason);
        if (r.wires.empty()) {
          out += "/>\n";
          continue;
        }
        out += ">\n";
        for (const Wire& w : r.wires) {
          o.indent(3);
          out += "<wire";
          o.points("points", w.points);
          out += "/>\n";
        }
        o.indent(2);
        out += "</route>\n";
      }
      o.indent(1);
      out += "</routes>\n";
    }
  }
  out += "</layout>\n";
  return std::move(out);
}

}  // namespace taut::io
