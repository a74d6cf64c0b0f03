// Text for XML written by hand (SVG pictures, Voronoi cells): escapes the five XML specials and
// turns other control characters into spaces, so any name is safe in an attribute or element.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace taut::io {

// Length of the well-formed UTF-8 sequence starting at s[i] (a byte >= 0x80), 0 if invalid
// (overlong forms, surrogates, beyond U+10FFFF, truncated, and U+FFFE / U+FFFF, which are not
// XML characters either).
inline std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned lead = b(i);
  std::size_t n;
  unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    n = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    n = 3;
    if (lead == 0xE0) lo = 0xA0;
    if (lead == 0xED) hi = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    n = 4;
    if (lead == 0xF0) lo = 0x90;
    if (lead == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  if (n == 3 && lead == 0xEF && b(i + 1) == 0xBF && b(i + 2) >= 0xBE) return 0;
  return n;
}

// The offset of the first byte of s that an XML attribute cannot carry as written (a control
// character other than tab, newline and carriage return, or a byte of no well-formed UTF-8
// character), or npos when there is none.
inline std::size_t first_non_xml_byte(std::string_view s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto u = static_cast<unsigned char>(s[i]);
    if (u >= 0x80) {
      const std::size_t n = utf8_length(s, i);
      if (n == 0) return i;
      i += n - 1;
    } else if (u < 0x20 && u != '\t' && u != '\n' && u != '\r') {
      return i;
    }
  }
  return std::string_view::npos;
}

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
