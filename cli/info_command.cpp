// `radiant info` — not built yet.
#include <iostream>

#include "commands.h"

namespace radiant::cli {

int info_main(int, char**) {
  std::cerr << "radiant info: not implemented yet\n";
  return exit_failure;
}

}  // namespace radiant::cli
