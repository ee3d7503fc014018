// What stderr shows at each log level: -q keeps warnings, -qq, --quiet and --log-level error
// keep errors only.
#include <doctest/doctest.h>

#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("log levels: -q hides the informational lines and keeps warnings, -qq and --quiet keep errors only") {
  ScratchDir dir("log-levels");
  // No camera and no light: the framing and studio lines, auto mode's reason and the summary.
  std::string plain = "render " + quoted(source_path("assets/models/instanced-boxes.glb")) + " -o " +
                      quoted(dir.file("a.png")) + " --width 16 --spp 1 --camera frame ";
  CommandResult loud = run_radiant(plain);
  REQUIRE(loud.exit_code == 0);
  CHECK(has(loud.err, "radiant: mode "));
  CHECK(has(loud.err, "radiant: wrote "));
  for (const char* flag : {"-q", "--log-level warning"}) {
    CAPTURE(flag);
    CommandResult r = run_radiant(plain + flag);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
  }
  // A mode that drops light the scene has: a warning, kept by -q.
  std::string whitted = "render " + quoted(source_path("assets/cornell.gltf")) + " -o " + quoted(dir.file("b.png")) +
                        " --width 16 --spp 1 --mode whitted ";
  CommandResult warned = run_radiant(whitted + "-q");
  REQUIRE(warned.exit_code == 0);
  CHECK(warned.err == "radiant: warning: mode whitted: emissive surfaces are only seen, they light nothing\n");
  for (const char* flag : {"-qq", "--quiet", "--log-level error", "-q --log-level error"}) {
    CAPTURE(flag);
    CommandResult r = run_radiant(whitted + flag);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
  }
  CommandResult bad = run_radiant(whitted + "--log-level loud");
  CHECK(bad.exit_code == 2);
  CHECK(has(bad.err, "--log-level: expected info, warning or error, not 'loud'"));
}
