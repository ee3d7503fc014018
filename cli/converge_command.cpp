// `radiant converge` — not built yet.
#include <iostream>

#include "commands.h"

namespace radiant::cli {

int converge_main(int, char**) {
  std::cerr << "radiant converge: not implemented yet\n";
  return exit_failure;
}

}  // namespace radiant::cli
