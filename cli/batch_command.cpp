// `radiant batch` — not built yet.
#include <iostream>

#include "commands.h"

namespace radiant::cli {

int batch_main(int, char**) {
  std::cerr << "radiant batch: not implemented yet\n";
  return exit_failure;
}

}  // namespace radiant::cli
