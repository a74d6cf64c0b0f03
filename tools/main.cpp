// taut: exact gridless wire routing. One binary, git-style subcommands (CLI.md).
#include <exception>
#include <iostream>
#include <stdexcept>
#include <new>

#include "router/version.h"
#include "tools/cli.h"
#include "tools/commands.h"

int main(int argc, char** argv) {
  using namespace taut::cli;
  CLI::App app{"taut: exact shortest wires among blockages (gridless VLSI routing)", "taut"};
  app.set_version_flag("--version", "taut " + std::string(taut::router::version()));
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 ran but something failed (check, unrouted, unreachable),\n"
      "2 usage error or invalid input (nothing written), 3 internal error, 4 resource limit.\n"
      "Run 'taut SUBCOMMAND --help' for the options of a subcommand.");
  int status = kOk;
  add_check(app, status);
  add_route(app, status);
  add_tighten(app, status);
  add_path(app, status);
  add_spm(app, status);
  add_voronoi(app, status);
  add_diameter(app, status);
  add_render(app, status);
  add_stats(app, status);
  add_gen(app, status);
  add_import(app, status);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_usage_error("CLI-0001", e.what());
    std::cerr << "Run 'taut --help' for usage.\n";
    return kInvalid;
  } catch (const std::bad_alloc&) {
    print_usage_error("CLI-0002", "out of memory");
    return kResource;
  } catch (const std::length_error& e) {  // a structure past its size limit (e.g. the map's 2^32 rays)
    print_usage_error("CLI-0002", std::string("size limit: ") + e.what());
    return kResource;
  } catch (const std::exception& e) {
    std::cerr << "taut: internal error: [CLI-0003] " << e.what() << " (a bug: please report it)\n";
    return kInternal;
  }
  return status;
}
