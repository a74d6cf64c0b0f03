#include "io/movingai.h"

#include <charconv>
#include <fstream>
#include <sstream>

namespace taut::io {

namespace {

Diagnostic error(const std::string& code, const std::string& file, int line, std::string msg) {
  Diagnostic d;
  d.code = code;
  d.file = file;
  d.line = line;
  d.message = std::move(msg);
  return d;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  return s;
}

bool passable(char c) { return c == '.' || c == 'G' || c == 'S'; }

}  // namespace

MovingAiResult parse_movingai_map(std::string_view text, const std::string& name,
                                  geom::Coord scale) {
  MovingAiResult result;
  auto fail = [&](const std::string& code, int line, std::string msg) {
    result.diagnostics.push_back(error(code, name, line, std::move(msg)));
    return result;
  };
  // Split into lines (keeping the 1-based number of each).
  std::vector<std::string_view> lines;
  for (std::size_t pos = 0; pos <= text.size();) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) {
      if (pos < text.size()) lines.push_back(text.substr(pos));
      break;
    }
    lines.push_back(text.substr(pos, nl - pos));
    pos = nl + 1;
  }
  long long height = -1, width = -1;
  bool type_seen = false;
  std::size_t k = 0;
  for (;; ++k) {
    if (k >= lines.size()) return fail("IO-0091", static_cast<int>(k), "header ends before the \"map\" line");
    const std::string_view l = trim(lines[k]);
    const int ln = static_cast<int>(k) + 1;
    if (l == "map") break;
    const std::size_t sp = l.find(' ');
    const std::string_view key = l.substr(0, sp);
    const std::string_view val = sp == std::string_view::npos ? std::string_view{} : trim(l.substr(sp + 1));
    if (key == "type") {
      if (val.empty()) return fail("IO-0091", ln, "\"type\" without a value");
      type_seen = true;
    } else if (key == "height" || key == "width") {
      long long v = 0;
      const auto [p, ec] = std::from_chars(val.data(), val.data() + val.size(), v);
      if (ec != std::errc{} || p != val.data() + val.size() || v < 1 || v > (1 << 30))
        return fail("IO-0091", ln, "bad " + std::string(key) + " \"" + std::string(val) + "\"");
      (key == "height" ? height : width) = v;
    } else {
      return fail("IO-0091", ln, "unexpected header line \"" + std::string(l.substr(0, 40)) + "\"");
    }
  }
  const int map_line = static_cast<int>(k) + 1;
  if (!type_seen) return fail("IO-0091", map_line, "missing \"type\" line");
  if (height < 0 || width < 0) return fail("IO-0091", map_line, "missing \"height\" or \"width\" line");
  if (scale < 1 || width * scale > geom::kMaxCoord || height * scale > geom::kMaxCoord)
    return fail("IO-0093", map_line,
                "map " + std::to_string(width) + "x" + std::to_string(height) + " at scale " +
                    std::to_string(scale) + " exceeds the coordinate range");
  if (lines.size() - (k + 1) < static_cast<std::size_t>(height))
    return fail("IO-0092", static_cast<int>(lines.size()),
                "expected " + std::to_string(height) + " rows, found " +
                    std::to_string(lines.size() - (k + 1)));

  Layout layout;
  layout.file = name;
  layout.name = name.substr(name.find_last_of('/') + 1);
  const geom::Coord w = static_cast<geom::Coord>(width * scale);
  const geom::Coord h = static_cast<geom::Coord>(height * scale);
  layout.boundary = Boundary{{{0, 0}, {w, h}}, map_line};
  for (long long r = 0; r < height; ++r) {
    std::string_view row = lines[k + 1 + static_cast<std::size_t>(r)];
    if (!row.empty() && row.back() == '\r') row.remove_suffix(1);
    const int ln = static_cast<int>(k + 2 + static_cast<std::size_t>(r));
    if (static_cast<long long>(row.size()) != width)
      return fail("IO-0092", ln,
                  "row " + std::to_string(r) + " has " + std::to_string(row.size()) +
                      " characters, expected " + std::to_string(width));
    const geom::Coord y0 = static_cast<geom::Coord>((height - 1 - r) * scale);
    for (long long c = 0; c < width;) {
      if (passable(row[static_cast<std::size_t>(c)])) {
        ++c;
        continue;
      }
      long long e = c;
      while (e < width && !passable(row[static_cast<std::size_t>(e)])) ++e;
      Blockage b;
      b.id = "r" + std::to_string(r) + "c" + std::to_string(c);
      b.line = ln;
      Shape s;
      s.kind = Shape::Kind::Rect;
      s.rect = {{static_cast<geom::Coord>(c * scale), y0},
                {static_cast<geom::Coord>(e * scale), static_cast<geom::Coord>(y0 + scale)}};
      s.line = ln;
      b.shapes.push_back(s);
      layout.blockages.push_back(std::move(b));
      c = e;
    }
  }
  for (std::size_t i = k + 1 + static_cast<std::size_t>(height); i < lines.size(); ++i)
    if (!trim(lines[i]).empty())
      return fail("IO-0094", static_cast<int>(i) + 1, "text after the last map row");
  result.layout = std::move(layout);
  return result;
}

MovingAiResult load_movingai_map(const std::string& path, geom::Coord scale) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    MovingAiResult r;
    r.diagnostics.push_back(error("IO-0090", path, 0, "cannot open the map file"));
    return r;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) {
    MovingAiResult r;
    r.diagnostics.push_back(error("IO-0090", path, 0, "cannot read the map file"));
    return r;
  }
  return parse_movingai_map(ss.str(), path, scale);
}

}  // namespace taut::io
