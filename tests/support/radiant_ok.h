// A radiant command a test needs to succeed before it can check anything else.
#pragma once

#include <doctest/doctest.h>

#include <string>

#include "support/test_support.h"

namespace radiant::test {

// Runs `radiant ARGS` and requires exit 0; on failure the command and its stderr are logged.
inline CommandResult radiant_ok(const std::string& args) {
  CommandResult r = run_radiant(args);
  INFO(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return r;
}

}  // namespace radiant::test
