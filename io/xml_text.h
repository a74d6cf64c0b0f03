// Text for XML written by hand (SVG pictures, Voronoi cells): escapes the five XML specials and
// turns other control characters into spaces, so any name is safe in an attribute or element.
#pragma once

#include <string>
#include <string_view>

namespace taut::io {

inline std::string xml_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
          out += ' ';
        else
          out += c;
    }
  }
  return out;
}

}  // namespace taut::io
