// Diagnostics: what libraries return instead of printing. Only tools/ prints them.
//
// Format when printed (CLI.md): "file:line[:col]: error|warning: [CODE] message".
// Codes are stable: IO-xxxx (reading/writing files), GEOM-xxxx (geometry of the input),
// LAYOUT-xxxx (meaning of the layout: names, pins), CHECK-xxxx (routes that fail a check),
// CLI-xxxx (command line). Every code used
// in the sources is listed in the README (a test checks it).
#pragma once

#include <string>
#include <vector>

namespace taut {

enum class Severity { Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string code;     // e.g. "IO-0003"
  std::string file;     // may be empty for in-memory input
  int line = 0;         // 1-based; 0 when unknown
  int column = 0;       // 1-based; 0 when unknown
  std::string message;  // names the object (id, net, pin) and what is wrong
};

inline std::string format(const Diagnostic& d) {
  std::string s = d.file.empty() ? std::string("<input>") : d.file;
  if (d.line > 0) s += ":" + std::to_string(d.line);
  if (d.line > 0 && d.column > 0) s += ":" + std::to_string(d.column);
  s += d.severity == Severity::Error ? ": error: [" : ": warning: [";
  s += d.code + "] " + d.message;
  return s;
}

inline bool has_error(const std::vector<Diagnostic>& ds) {
  for (const auto& d : ds)
    if (d.severity == Severity::Error) return true;
  return false;
}

}  // namespace taut
