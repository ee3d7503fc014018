// The subcommands of `radiant`; each lives in its own file and parses its own arguments.
#pragma once

#include <vector>

namespace radiant::cli {

// Exit codes of DESIGN.md.
constexpr int exit_ok = 0;
constexpr int exit_failure = 1;  // scene or render failed, or `compare` found a difference
constexpr int exit_usage = 2;    // bad command line (and `compare`'s unreadable input)

// argv[0] is the command name itself.
int render_main(int argc, char** argv);
int info_main(int argc, char** argv);
int compare_main(int argc, char** argv);
int converge_main(int argc, char** argv);
int batch_main(int argc, char** argv);
int session_main(int argc, char** argv);
int merge_main(int argc, char** argv);
int denoise_main(int argc, char** argv);

struct Command {
  const char* name;
  int (*run)(int argc, char** argv);
};
inline const std::vector<Command>& commands() {
  static const std::vector<Command> list = {{"render", render_main},     {"info", info_main},
                                            {"compare", compare_main},   {"converge", converge_main},
                                            {"batch", batch_main},       {"merge", merge_main},
                                            {"session", session_main},   {"denoise", denoise_main}};
  return list;
}

}  // namespace radiant::cli
