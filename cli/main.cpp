// radiant's entry point: dispatches `radiant COMMAND ...` to the command's own parser.
#include <cerrno>
#include <cstdio>
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
         "  radiant info SCENE|IMAGE [--json]       scene statistics and effects, or how an image was made\n"
         "  radiant compare A B [options]           compare images for CI (exit 0 pass, 1 fail)\n"
         "  radiant converge SCENE [--out DIR]      accuracy-versus-time report\n"
         "  radiant batch FILE|-                    render many views of one loaded scene\n"
         "  radiant merge SHARD... -o OUT           combine shards (render --shard) into one image\n"
         "  radiant session [SCENE] -o OUT          render while taking commands (move, turn, set, ...)\n"
         "  radiant denoise IN.exr -o OUT           denoise an EXR with albedo, normal, depth and halves\n"
         "  radiant --version\n";
}

// What a command prints is part of its result (`radiant compare --json > report.json`): a write
// to standard output that failed, at the final flush too, fails the command.
int check_standard_output(int code) {
  std::cout.flush();
  errno = 0;
  bool flushed = std::fflush(stdout) == 0;
  if (flushed && !std::ferror(stdout) && std::cout.good()) return code;
  std::cerr << "radiant: cannot write to standard output: " << (!flushed && errno ? std::strerror(errno) : "a write failed")
            << "\n";
  return code == 0 ? 1 : code;
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
      return check_standard_output(c.run(argc - 1, argv + 1));
    } catch (const radiant::cli::Interrupted& interrupted) {
      return interrupted.exit_code();
    }
  }
  std::cerr << "radiant: unknown command '" << command << "'\n";
  print_usage(std::cerr);
  return 2;
}
