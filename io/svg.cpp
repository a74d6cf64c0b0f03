// layout_to_svg: world coordinates are written as the integers they are, inside one group whose
// transform scales to pixels and flips y (the layout's y axis points up). Stroke widths and
// radii are converted from pixels to world units so lines look the same at every scale. Text
// is drawn outside the flipped group (else it would be upside down), at transformed positions.
// Floating point here only places ink; it never decides anything about the geometry.
#include "io/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "geom/predicates.h"
#include "io/xml_text.h"

namespace taut::io {
namespace {

constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                    "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

std::string net_color(std::size_t i) {
  if (i < 10) return kPalette[i];
  // Golden-angle hues beyond the palette: distinct enough for neighbours in the list.
  const int hue = static_cast<int>((i * 137) % 360);
  return "hsl(" + std::to_string(hue) + ",70%,42%)";
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
std::string px(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

void append_ring_path(std::string& d, const std::vector<Point>& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    d += i == 0 ? 'M' : 'L';
    d += std::to_string(ring[i].x);
    d += ' ';
    d += std::to_string(ring[i].y);
  }
  d += 'Z';
}

std::string points_attr(const std::vector<Point>& pts) {
  std::string s;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i) s += ' ';
    s += std::to_string(pts[i].x) + "," + std::to_string(pts[i].y);
  }
  return s;
}

// One <rect> or <path> (outer ring plus holes, even-odd so holes are cut out).
std::string shape_element(const Shape& s, const std::string& style) {
  if (s.kind == Shape::Kind::Rect) {
    const Box& b = s.rect;
    return "<rect x=\"" + std::to_string(b.lo.x) + "\" y=\"" + std::to_string(b.lo.y) +
           "\" width=\"" + std::to_string(std::int64_t{b.hi.x} - b.lo.x) + "\" height=\"" +
           std::to_string(std::int64_t{b.hi.y} - b.lo.y) + "\" " + style + "/>";
  }
  std::string d;
  append_ring_path(d, s.polygon.outer);
  for (const auto& h : s.polygon.holes) append_ring_path(d, h);
  return "<path d=\"" + d + "\" fill-rule=\"evenodd\" " + style + "/>";
}

struct Bounds {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty = true;
  void add(double x, double y) {
    if (empty) {
      x0 = x1 = x;
      y0 = y1 = y;
      empty = false;
      return;
    }
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
  }
  void add(const Shape& s) {
    if (s.kind == Shape::Kind::Rect) {
      add(s.rect.lo.x, s.rect.lo.y);
      add(s.rect.hi.x, s.rect.hi.y);
    } else {
      for (Point p : s.polygon.outer) add(p.x, p.y);
    }
  }
};

// A round scale-bar length (1, 2 or 5 times a power of ten) near `target` world units.
double nice_length(double target) {
  if (!(target > 0)) return 1;
  double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return std::max(1.0, m * p);
  return std::max(1.0, p);
}

bool inside(const Shape& s, Point p) {
  if (s.kind == Shape::Kind::Rect)
    return s.rect.lo.x < p.x && p.x < s.rect.hi.x && s.rect.lo.y < p.y && p.y < s.rect.hi.y;
  return geom::locate(p, s.polygon) == geom::Location::Inside;
}

// Where to write a blockage's label: its bounding-box centre when that is inside it, else the
// inside point of a 7x7 lattice over the box nearest the centre (an L or a ring has an empty
// centre, and a ring's centre is where an island inside it is labelled).
Point label_spot(const Blockage& b, const Bounds& bb) {
  const double cx = (bb.x0 + bb.x1) / 2, cy = (bb.y0 + bb.y1) / 2;
  Point best{static_cast<geom::Coord>(std::llround(cx)), static_cast<geom::Coord>(std::llround(cy))};
  double best_d = -1;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double x = bb.x0 + (bb.x1 - bb.x0) * i / 8, y = bb.y0 + (bb.y1 - bb.y0) * j / 8;
      const Point p{static_cast<geom::Coord>(std::llround(x)),
                    static_cast<geom::Coord>(std::llround(y))};
      bool in = false;
      for (const Shape& s : b.shapes) in = in || inside(s, p);
      if (!in) continue;
      const double d = (x - cx) * (x - cx) + (y - cy) * (y - cy);
      if (best_d < 0 || d < best_d) best_d = d, best = p;
    }
  return best;
}

}  // namespace

std::string layout_to_svg(const Layout& layout, const SvgOptions& options) {
  // World extent: the boundary, else everything drawn.
  Bounds w;
  if (layout.boundary) {
    w.add(layout.boundary->box.lo.x, layout.boundary->box.lo.y);
    w.add(layout.boundary->box.hi.x, layout.boundary->box.hi.y);
  } else {
    for (const Blockage& b : layout.blockages)
      for (const Shape& s : b.shapes) w.add(s);
    for (const Net& n : layout.nets) {
      for (const Pin& p : n.pins) {
        if (p.point) w.add(p.point->x, p.point->y);
        if (p.shape) w.add(*p.shape);
      }
      if (n.sketch)
        for (Point p : n.sketch->points) w.add(p.x, p.y);
    }
    if (layout.routes)
      for (const Route& r : layout.routes->routes)
        for (const Wire& wire : r.wires)
          for (Point p : wire.points) w.add(p.x, p.y);
  }
  if (w.empty) w.add(0, 0);
  if (w.x1 - w.x0 < 1 && w.y1 - w.y0 < 1) {
    w.add(w.x0 - 1000, w.y0 - 1000);
    w.add(w.x1 + 1000, w.y1 + 1000);
  }
  const double world_w = std::max(1.0, w.x1 - w.x0), world_h = std::max(1.0, w.y1 - w.y0);

  const double longest = std::max(200, options.width_px);
  const double margin = std::max(12.0, longest * 0.03);
  const double s = (longest - 2 * margin) / std::max(world_w, world_h);  // px per DBU
  const double draw_w = world_w * s, draw_h = world_h * s;
  const double font = std::clamp(longest / 90.0, 9.0, 16.0);

  const bool labels = options.labels;
  const bool blockage_labels = labels && layout.blockages.size() <= 300;
  const bool net_labels = labels && layout.nets.size() <= 100;
  const std::size_t legend_nets = std::min<std::size_t>(layout.nets.size(), 24);
  const int legend_cols = std::max(1, static_cast<int>((draw_w + 2 * margin) / (font * 12)));
  const int legend_rows =
      1 + static_cast<int>((legend_nets + (layout.nets.size() > legend_nets ? 1 : 0) +
                            legend_cols - 1) / legend_cols);
  const double legend_h = legend_rows * font * 1.6 + font;

  const double pic_w = draw_w + 2 * margin;
  const double pic_h = draw_h + 2 * margin + legend_h;
  auto sx = [&](double x) { return margin + (x - w.x0) * s; };
  auto sy = [&](double y) { return margin + (w.y1 - y) * s; };
  auto world = [&](double pixels) { return num(pixels / s); };

  std::map<std::string, std::size_t> net_index;
  for (std::size_t i = 0; i < layout.nets.size(); ++i) net_index.emplace(layout.nets[i].name, i);

  std::string o;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(pic_w) + "\" height=\"" +
       px(pic_h) + "\" viewBox=\"0 0 " + px(pic_w) + " " + px(pic_h) + "\" font-family=\"" +
       "DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
  o += "<title>" + xml_escape(layout.name) + "</title>\n";
  o += "<rect x=\"0\" y=\"0\" width=\"" + px(pic_w) + "\" height=\"" + px(pic_h) +
       "\" fill=\"#ffffff\"/>\n";

  // Flipped world group: screen = (margin - x0*s + x*s, margin + y1*s - y*s).
  o += "<g transform=\"matrix(" + num(s) + " 0 0 " + num(-s) + " " + num(margin - w.x0 * s) +
       " " + num(margin + w.y1 * s) + ")\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";

  if (layout.boundary) {
    Shape b;
    b.rect = layout.boundary->box;
    o += "<g class=\"boundary\">" +
         shape_element(b, "fill=\"#f7f9fc\" stroke=\"#34495e\" stroke-width=\"" + world(1.5) +
                              "\"") +
         "</g>\n";
  }

  // "@PX" stroke widths in the caller's layers become world units.
  auto scaled = [&](std::string layer) {
    for (std::size_t at = layer.find("\"@"); at != std::string::npos; at = layer.find("\"@", at + 1)) {
      const std::size_t end = layer.find('"', at + 2);
      if (end == std::string::npos) break;
      const double pixels = std::atof(layer.substr(at + 2, end - at - 2).c_str());
      layer.replace(at + 1, end - at - 1, world(pixels));
    }
    return layer;
  };
  o += scaled(options.underlay);

  const std::string blockage_style = "fill=\"#8d99a6\" fill-opacity=\"0.75\" stroke=\"#3d4852\" "
                                     "stroke-width=\"" + world(0.8) + "\"";
  for (const Blockage& b : layout.blockages) {
    o += "<g class=\"blockage\" data-id=\"" + xml_escape(b.id) + "\">";
    for (const Shape& shape : b.shapes) o += shape_element(shape, blockage_style);
    o += "</g>\n";
  }

  // Routes under the pins so pins stay visible on top of their wires.
  if (layout.routes) {
    const double wire_px =
        std::max(2.5, layout.rules ? static_cast<double>(layout.rules->wire_width) * s : 0.0);
    for (const Route& r : layout.routes->routes) {
      auto it = net_index.find(r.net);
      const std::string color = net_color(it == net_index.end() ? 0 : it->second);
      for (const Wire& wire : r.wires)
        o += "<polyline class=\"wire\" data-net=\"" + xml_escape(r.net) + "\" points=\"" +
             points_attr(wire.points) + "\" fill=\"none\" stroke=\"" + color +
             "\" stroke-opacity=\"0.85\" stroke-width=\"" + world(wire_px) + "\"/>\n";
    }
  }

  for (std::size_t i = 0; i < layout.nets.size(); ++i) {
    const Net& n = layout.nets[i];
    const std::string color = net_color(i);
    if (n.sketch)
      o += "<polyline class=\"sketch\" data-net=\"" + xml_escape(n.name) + "\" points=\"" +
           points_attr(n.sketch->points) + "\" fill=\"none\" stroke=\"" + color +
           "\" stroke-width=\"" + world(1.5) + "\" stroke-dasharray=\"" + world(6) + " " +
           world(4) + "\"/>\n";
    for (const Pin& p : n.pins) {
      if (p.point) {
        o += "<circle class=\"pin\" data-net=\"" + xml_escape(n.name) + "\" cx=\"" +
             std::to_string(p.point->x) + "\" cy=\"" + std::to_string(p.point->y) + "\" r=\"" +
             world(4) + "\" fill=\"" + color + "\" stroke=\"#ffffff\" stroke-width=\"" +
             world(1) + "\"/>\n";
      } else if (p.shape) {
        o += "<g class=\"pin\" data-net=\"" + xml_escape(n.name) + "\">" +
             shape_element(*p.shape, "fill=\"" + color + "\" fill-opacity=\"0.25\" stroke=\"" +
                                         color + "\" stroke-width=\"" + world(2) + "\"") +
             "</g>\n";
      }
    }
  }
  o += scaled(options.overlay);
  o += "</g>\n";

  // Labels (screen coordinates).
  if (blockage_labels) {
    o += "<g class=\"labels\" font-size=\"" + px(font * 0.85) +
         "\" fill=\"#1d252c\" text-anchor=\"middle\" dominant-baseline=\"middle\">\n";
    for (const Blockage& b : layout.blockages) {
      Bounds bb;
      for (const Shape& shape : b.shapes) bb.add(shape);
      if (bb.empty) continue;
      const Point spot = label_spot(b, bb);
      o += "<text x=\"" + px(sx(spot.x)) + "\" y=\"" + px(sy(spot.y)) + "\">" + xml_escape(b.id) +
           "</text>\n";
    }
    o += "</g>\n";
  }
  if (net_labels) {
    o += "<g class=\"labels\" font-size=\"" + px(font * 0.8) +
         "\" paint-order=\"stroke\" stroke=\"#ffffff\" stroke-width=\"3\">\n";
    for (std::size_t i = 0; i < layout.nets.size(); ++i) {
      const Net& n = layout.nets[i];
      for (const Pin& p : n.pins) {
        double x, y;
        if (p.point) {
          x = p.point->x, y = p.point->y;
        } else if (p.shape) {
          Bounds bb;
          bb.add(*p.shape);
          x = bb.x1, y = bb.y1;
        } else {
          continue;
        }
        o += "<text x=\"" + px(sx(x) + 6) + "\" y=\"" + px(sy(y) - 6) + "\" fill=\"" +
             net_color(i) + "\">" + xml_escape(n.name) + "." + xml_escape(p.name) + "</text>\n";
      }
    }
    o += "</g>\n";
  }

  // Legend and scale bar, under the drawing.
  const double ly = margin + draw_h + margin * 0.6 + font;
  o += "<g class=\"legend\" font-size=\"" + px(font) + "\" fill=\"#1d252c\">\n";
  const double bar_world = nice_length(world_w / 5);
  const double bar_px = bar_world * s;
  const double dbu = static_cast<double>(std::max<std::int64_t>(1, layout.dbu_per_micron));
  char bar_label[64];
  if (bar_world >= dbu)
    std::snprintf(bar_label, sizeof bar_label, "%g µm", bar_world / dbu);
  else
    std::snprintf(bar_label, sizeof bar_label, "%g DBU", bar_world);
  o += "<line x1=\"" + px(margin) + "\" y1=\"" + px(ly) + "\" x2=\"" + px(margin + bar_px) +
       "\" y2=\"" + px(ly) + "\" stroke=\"#1d252c\" stroke-width=\"2\"/>\n";
  o += "<line x1=\"" + px(margin) + "\" y1=\"" + px(ly - 4) + "\" x2=\"" + px(margin) +
       "\" y2=\"" + px(ly + 4) + "\" stroke=\"#1d252c\" stroke-width=\"2\"/>\n";
  o += "<line x1=\"" + px(margin + bar_px) + "\" y1=\"" + px(ly - 4) + "\" x2=\"" +
       px(margin + bar_px) + "\" y2=\"" + px(ly + 4) + "\" stroke=\"#1d252c\" stroke-width=\"2\"/>\n";
  std::string summary = std::string(bar_label) + "  \u2022  " + xml_escape(layout.name) + ": " +
                        std::to_string(layout.blockages.size()) + " blockages, " +
                        std::to_string(layout.nets.size()) + " nets";
  if (layout.routes) {
    std::size_t routed = 0;
    for (const Route& r : layout.routes->routes) routed += r.status == "routed";
    summary += ", " + std::to_string(routed) + " routed";
  }
  if (!options.caption.empty()) summary += ", " + xml_escape(options.caption);
  o += "<text x=\"" + px(margin + bar_px + 10) + "\" y=\"" + px(ly + font * 0.35) + "\">" +
       summary + "</text>\n";
  const double col_w = (pic_w - 2 * margin) / legend_cols;
  for (std::size_t i = 0; i <= legend_nets; ++i) {
    const bool more = i == legend_nets;
    if (more && layout.nets.size() <= legend_nets) break;
    const int row = 1 + static_cast<int>(i) / legend_cols, col = static_cast<int>(i) % legend_cols;
    const double x = margin + col * col_w, y = ly + row * font * 1.6;
    if (more) {
      o += "<text x=\"" + px(x) + "\" y=\"" + px(y + font * 0.35) + "\">… and " +
           std::to_string(layout.nets.size() - legend_nets) + " more nets</text>\n";
      break;
    }
    o += "<line x1=\"" + px(x) + "\" y1=\"" + px(y) + "\" x2=\"" + px(x + font * 1.8) +
         "\" y2=\"" + px(y) + "\" stroke=\"" + net_color(i) + "\" stroke-width=\"4\"/>\n";
    o += "<text x=\"" + px(x + font * 2.3) + "\" y=\"" + px(y + font * 0.35) + "\">" +
         xml_escape(layout.nets[i].name) + " (" + std::to_string(layout.nets[i].pins.size()) +
         " pins)</text>\n";
  }
  o += "</g>\n</svg>\n";
  return o;
}

}  // namespace taut::io
