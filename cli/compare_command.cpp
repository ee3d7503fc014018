// `radiant compare` — not built yet.
#include <iostream>

#include "commands.h"

namespace radiant::cli {

int compare_main(int, char**) {
  std::cerr << "radiant compare: not implemented yet\n";
  return exit_failure;
}

}  // namespace radiant::cli
