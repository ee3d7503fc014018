// `radiant render` — not built yet.
#include <iostream>

#include "commands.h"

namespace radiant::cli {

int render_main(int, char**) {
  std::cerr << "radiant render: not implemented yet\n";
  return exit_failure;
}

}  // namespace radiant::cli
