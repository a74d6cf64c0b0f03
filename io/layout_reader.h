// Reads a layout file (FORMAT.md) securely with libxml2.
//
// Secure by construction: the bytes are read here with a size cap; gzip/zlib/xz/bzip2/zstd
// magic is refused; libxml2 parses from memory with XML_PARSE_NONET only (never NOENT, DTDLOAD,
// HUGE or RECOVER); any DOCTYPE is refused; an external entity loader that loads nothing is
// installed; every libxml2 error is a failure. Numbers are parsed strictly (-?[0-9]+, within
// 2^30 - 1) with std::from_chars.
//
//   ReadOptions opt; opt.lenient = false;
//   ReadResult r = read_layout("designs/demo.xml", opt);
//   for (auto& d : r.diagnostics) std::cerr << format(d) << '\n';
//   if (!r.layout) return 2;
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geom/diagnostic.h"
#include "io/layout.h"

namespace taut::io {

struct ReadOptions {
  bool lenient = false;  // unknown elements/attributes become warnings (IO code kept)
  std::size_t max_bytes = std::size_t{1} << 30;  // 1 GiB cap on the file size
};

struct ReadResult {
  std::optional<Layout> layout;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
};

// Reads and checks the syntax of a file (elements, attributes, numbers). Semantic checks
// (geometry validity, duplicate names, pins in blockages) are validate_layout()'s job.
ReadResult read_layout(const std::string& path, const ReadOptions& options = {});
// Same, from bytes in memory; `name` is used as the file name in diagnostics.
ReadResult parse_layout(std::string_view bytes, const std::string& name,
                        const ReadOptions& options = {});

// A coordinate as FORMAT.md writes it: the whole text is -?[0-9]+ with |value| <= 2^30 - 1
// (the reader's own rule, for numbers given on a command line); nullopt otherwise.
std::optional<std::int64_t> parse_coordinate(std::string_view text);

}  // namespace taut::io
