// `taut import --bump-to-pad`'s assignment (io/lefdef.h, DefImportOptions::bump_to_pad): a DEF
// held in memory with one net of N bumps (45 um diamonds on a 100 um grid) and N pads (a cell's
// pin at random places over the same area; the tests' LEF, tests/support/small_lef.h), imported
// with the option against the same import without it (the baseline: the same text read, the net
// written whole), measured in the same run. The difference is the assignment of least total L1
// distance (the Hungarian method, O(N^3) at worst). Printed per size: N, the two times (best of
// 3), their ratio, and the growth exponent of the difference, log(d2 / d1) / log(N2 / N1).
//
//   bench_import [--sizes N,N,...]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "io/lefdef.h"
#include "support/small_lef.h"

namespace {

using taut::test::kLef;

std::string design(int n) {
  std::mt19937 rng(42);
  const int side = static_cast<int>(std::ceil(std::sqrt(2.0 * n))) + 1;
  const int extent = 100000 * side;
  std::string comps, terms;
  for (int i = 0; i < n; ++i) {
    comps += " - b" + std::to_string(i) + " BUMP + FIXED ( " + std::to_string(100000 + 100000 * (i % side)) + " " +
             std::to_string(100000 + 100000 * (i / side)) + " ) N ;\n";
    terms += " ( b" + std::to_string(i) + " PAD )";
  }
  for (int j = 0; j < n; ++j) {
    comps += " - c" + std::to_string(j) + " CELL + FIXED ( " + std::to_string(1000 * static_cast<int>(rng() % (extent / 1000))) +
             " " + std::to_string(1000 * static_cast<int>(rng() % (extent / 1000))) + " ) N ;\n";
    terms += " ( c" + std::to_string(j) + " P )";
  }
  return "VERSION 5.8 ;\nDIVIDERCHAR \"/\" ;\nDESIGN top ;\nUNITS DISTANCE MICRONS 1000 ;\nDIEAREA ( 0 0 ) ( " +
         std::to_string(extent + 200000) + " " + std::to_string(extent + 200000) + " ) ;\nCOMPONENTS " + std::to_string(2 * n) +
         " ;\n" + comps + "END COMPONENTS\nNETS 1 ;\n - n" + terms + " ;\nEND NETS\nEND DESIGN\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {250, 500, 1000, 2000};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
      sizes.clear();
      for (char* tok = std::strtok(argv[++i], ","); tok; tok = std::strtok(nullptr, ",")) sizes.push_back(std::atoi(tok));
    } else {
      std::fprintf(stderr, "usage: %s [--sizes N,N,...]\n", argv[0]);
      return 2;
    }
  }
  std::printf("taut import --bump-to-pad: one net of N bumps and N pads, against the same import without the option\n");
  std::printf("%7s | %10s %10s %8s | %s\n", "N", "plain s", "bump s", "ratio", "growth of the difference");
  double last_n = 0, last_d = 0;
  for (const int n : sizes) {
    if (n < 1) continue;
    const std::string def = design(n);
    taut::io::DefImportOptions plain;
    plain.layer = "m2";
    taut::io::DefImportOptions bumps = plain;
    bumps.bump_to_pad = true;
    std::size_t nets = 0;
    auto import = [&](const taut::io::DefImportOptions& o) {
      const taut::io::DefImportResult r = taut::io::import_def_text({"bench.def", def}, {{"bench.lef", kLef}}, o);
      if (!r.layout) {
        std::fprintf(stderr, "bench_import: the generated design was refused\n");
        std::exit(1);
      }
      nets = r.layout->nets.size();
    };
    const double tp = taut::bench::seconds_of([&] { import(plain); }, 3);
    const double tb = taut::bench::seconds_of([&] { import(bumps); }, 3);
    if (nets != static_cast<std::size_t>(n)) {
      std::fprintf(stderr, "bench_import: %zu nets written for %d bumps\n", nets, n);
      return 1;
    }
    const double d = std::max(tb - tp, 1e-9);
    std::printf("%7d | %10.4f %10.4f %8.1f | ", n, tp, tb, tb / tp);
    if (last_n > 0) std::printf("%.2f", std::log(d / last_d) / std::log(n / last_n));
    std::printf("\n");
    last_n = n;
    last_d = d;
  }
  return 0;
}
