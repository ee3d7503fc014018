// The golden tolerances catch real regressions: a copy of an asset with a light moved or a
// material 10% darker, rendered with its case's test command line, fails `radiant compare`.
#include <doctest/doctest.h>

#include "golden/golden_cases.h"
#include "support/test_support.h"

namespace radiant::golden {

namespace {

// The case called `name` in golden/cases.txt.
GoldenCase find_case(const std::string& name) {
  for (const GoldenCase& golden : read_golden_cases())
    if (golden.name == name) return golden;
  FAIL("no golden case " << name);
  return {};
}

// `text` with the first occurrence of `from` at or after `start` replaced by `to`.
std::string replaced(const std::string& text, const std::string& from, const std::string& to,
                     size_t start = 0) {
  size_t at = text.find(from, start);
  REQUIRE_MESSAGE(at != std::string::npos, "'" << from << "' not found");
  return text.substr(0, at) + to + text.substr(at + from.size());
}

// Renders `changed_text` (a changed copy of the case's scene) with the case's test command
// line and returns what compare says against the case's golden.
test::CommandResult compare_changed_scene(const std::string& case_name,
                                          const std::string& changed_text) {
  GoldenCase golden = find_case(case_name);
  test::ScratchDir dir("golden-regression");
  std::string file_name = std::filesystem::path(golden.scene).filename().string();
  std::filesystem::path scene = dir.write(file_name, changed_text);
  std::filesystem::path render = dir.file("render.exr");
  test::CommandResult rendered = test::run_radiant(test_render_args(golden, scene, render, 2));
  REQUIRE_MESSAGE(rendered.exit_code == 0, rendered.err);
  return test::run_radiant(compare_args(golden, render));
}

std::string asset_text(const std::string& relative) {
  return test::read_bytes(test::source_path(relative));
}

}  // namespace

TEST_CASE("a Whitted render with the spot light moved 20 units fails its golden") {
  std::string scene =
      replaced(asset_text("assets/first-render.scene"), "position 60 50 0", "position 80 50 0");
  test::CommandResult compared = compare_changed_scene("first-render-whitted", scene);
  CHECK_MESSAGE(compared.exit_code == 1, compared.out << compared.err);
  CHECK(compared.out.find("verdict: fail (thresholds)") != std::string::npos);
}

TEST_CASE("a Whitted render with the floor's kd 10% lower fails its golden") {
  std::string scene =
      replaced(asset_text("assets/showcase.scene"), "kd 0.6 0.57 0.5", "kd 0.54 0.513 0.45");
  test::CommandResult compared = compare_changed_scene("showcase-whitted", scene);
  CHECK_MESSAGE(compared.exit_code == 1, compared.out << compared.err);
  CHECK(compared.out.find("verdict: fail (thresholds)") != std::string::npos);
}

TEST_CASE("a path-traced room with its glowing sphere moved 0.4 m fails the z-test") {
  std::string scene =
      replaced(asset_text("assets/room-older-format.scene"), "p 0 1.45 -1.6", "p 0.4 1.45 -1.6");
  test::CommandResult compared = compare_changed_scene("room-path", scene);
  CHECK_MESSAGE(compared.exit_code == 1, compared.out << compared.err);
  CHECK(compared.out.find("verdict: fail (Monte Carlo z-test)") != std::string::npos);
}

TEST_CASE("a path-traced Cornell box with its white walls 10% darker fails the z-test") {
  std::string gltf = asset_text("assets/cornell.gltf");
  size_t white = gltf.find("\"name\": \"white\"");
  REQUIRE(white != std::string::npos);
  for (int channel = 0; channel < 3; ++channel) gltf = replaced(gltf, "0.73,", "0.657,", white);
  test::CommandResult compared = compare_changed_scene("cornell-path", gltf);
  CHECK_MESSAGE(compared.exit_code == 1, compared.out << compared.err);
  CHECK(compared.out.find("verdict: fail (Monte Carlo z-test)") != std::string::npos);
}

}  // namespace radiant::golden
