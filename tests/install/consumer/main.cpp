// A project outside taut that uses the installed headers and libraries.
#include <geom/predicates.h>
#include <io/layout_reader.h>
#include <router/version.h>

#include <iostream>

int main() {
  using namespace taut;
  const int o = geom::orientation({0, 0}, {10, 0}, {0, 10});
  const auto r = io::parse_layout(
      "<layout name=\"t\" version=\"1\"><blockage id=\"b\"><rect x0=\"0\" y0=\"0\" x1=\"1\" "
      "y1=\"1\"/></blockage></layout>",
      "inline.xml");
  if (!r.layout) {
    for (const auto& d : r.diagnostics) std::cerr << format(d) << '\n';
    return 1;
  }
  std::cout << "taut " << router::version() << " orient=" << o
            << " blockages=" << r.layout->blockages.size() << '\n';
  return 0;
}
