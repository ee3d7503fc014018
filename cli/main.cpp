// radiant's entry point: dispatches `radiant COMMAND ...` to the command's own parser.
#include <cstring>
#include <iostream>
#include <string>

#include "commands.h"
#include "interrupts.h"

namespace {

void print_usage(std::ostream& out) {
  out << "radiant " RADIANT_VERSION " — a batch renderer for glTF 2.0, OBJ and .scene files\n\n"
         "Usage:\n"
         "  radiant render SCENE -o OUT [options]   render an image (radiant render --help)\n"
         "  radiant info SCENE [--json]             scene statistics, warnings and effects\n"
         "  radiant compare A B [options]           compare images for CI (exit 0 pass, 1 fail)\n"
         "  radiant converge SCENE [--out DIR]      accuracy-versus-time report\n"
         "  radiant batch FILE|-                    render many views of one loaded scene\n"
         "  radiant --version\n";
}

}  // namespace

int main(int argc, char** argv) {
  radiant::cli::install_signal_handlers();
  if (argc < 2) {
    print_usage(std::cerr);
    return 2;
  }
  std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    print_usage(std::cout);
    return 0;
  }
  if (command == "--version") {
    std::cout << "radiant " RADIANT_VERSION "\n";
    return 0;
  }
  for (const radiant::cli::Command& c : radiant::cli::commands()) {
    if (command != c.name) continue;
    try {
      return c.run(argc - 1, argv + 1);
    } catch (const radiant::cli::Interrupted& interrupted) {
      return interrupted.exit_code();
    }
  }
  std::cerr << "radiant: unknown command '" << command << "'\n";
  print_usage(std::cerr);
  return 2;
}
