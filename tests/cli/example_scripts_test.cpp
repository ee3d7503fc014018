// The scripts in examples/ as a user without their tools meets them.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("example scripts: the GNU parallel recipe without parallel installed says so and exits 2") {
  ScratchDir dir("no-parallel");
  fs::create_directory(dir.file("empty-path"));  // a PATH where no parallel can be found
  std::string run = "env -i PATH='" + dir.file("empty-path").string() + "' /bin/bash '" +
                    source_path("examples/parallel/render.sh").string() + "' scene.gltf 4 '" + dir.file("shards").string() +
                    "' image.png 2> '" + dir.file("err").string() + "'";
  int status = std::system(run.c_str());
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(read_bytes(dir.file("err")).find("GNU parallel is not installed") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("shards")));  // nothing made before the check
}
