// Image regression: every case of golden/cases.txt rendered afresh and checked against its
// reference in golden/ by `radiant compare`, as CI would (golden/README.md).
#include <doctest/doctest.h>

#include "golden/golden_cases.h"
#include "support/test_support.h"

namespace radiant::golden {

namespace {

// Renders `golden`'s test image of its own scene and compares it with the reference; each
// failure names the case and carries compare's report.
void check_against_golden(const GoldenCase& golden, int threads) {
  INFO("golden case " << golden.name << " (--threads " << threads << ")");
  test::ScratchDir dir("golden");
  std::filesystem::path render = dir.file(golden.name + ".exr");
  test::CommandResult rendered =
      test::run_radiant(test_render_args(golden, test::source_path(golden.scene), render, threads));
  CHECK_MESSAGE(rendered.exit_code == 0, rendered.err);
  if (rendered.exit_code != 0) return;  // the other cases still run
  test::CommandResult compared = test::run_radiant(compare_args(golden, render));
  CHECK_MESSAGE(compared.exit_code == 0, compared.out << compared.err);  // pass, or warn
}

// Checks every case rendered with `mode`, alternating one and two threads over the file's
// cases, since the thread count must never change an image.
void check_goldens_of_mode(const std::string& mode) {
  std::vector<GoldenCase> cases = read_golden_cases();
  int checked = 0;
  for (size_t index = 0; index < cases.size(); ++index) {
    if ((cases[index].flags + " ").find("--mode " + mode + " ") == std::string::npos) continue;
    check_against_golden(cases[index], 1 + int(index % 2));
    ++checked;
  }
  CHECK(checked > 0);
}

}  // namespace

TEST_CASE("Whitted renders match their goldens within cross-build float tolerance") {
  check_goldens_of_mode("whitted");
}

TEST_CASE("path-traced renders at low spp pass the z-test against their goldens") {
  check_goldens_of_mode("path");
}

TEST_CASE("naive path-traced renders at low spp pass the z-test against their goldens") {
  check_goldens_of_mode("naive");
}

}  // namespace radiant::golden
