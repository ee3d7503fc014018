// The golden image cases of golden/cases.txt and the command lines that check them, shared by
// the golden tests (scripts/update-goldens.sh reads the same file; golden/README.md).
#pragma once

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace radiant::golden {

// One line of golden/cases.txt.
struct GoldenCase {
  std::string name;   // the reference is golden/NAME.exr
  std::string check;  // "threshold" (deterministic Whitted) or "z-test" (Monte Carlo)
  std::string scene;  // relative to the repository root
  std::string flags;  // render flags shared by the golden and the test render
  int golden_spp = 0;
  int test_spp = 0;
};

// The golden is rendered with this seed; a z-test render uses another one so that its noise is
// independent of the golden's (the same seed would repeat the golden's first samples).
constexpr int golden_seed = 1;
constexpr int z_test_seed = 2;

// Whitted renders are deterministic: only cross-build float differences (FMA contraction, libm)
// may move a value, by far less than 1e-3; a few pixels may flip at a shadow or silhouette edge.
inline const char* threshold_compare_flags =
    "--no-mc --fail 0.003 --fail-percent 0.1 --fail-relative 0.002 "
    "--warn 0.001 --warn-percent 1 --warn-relative 0.0005";
// Monte Carlo: compare's per-value z-test with the test render's own variance and the golden's.
// No --mc-bias: at low spp a pixel's variance estimate grows with its mean (skewed path-tracing
// noise), so Σz/√N of two correct renders sits far below zero (golden/README.md).
inline const char* z_test_compare_flags = "--mc";

inline std::string trimmed(const std::string& text) {
  size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") + 1 - first);
}

inline std::vector<std::string> split_columns(const std::string& line) {
  std::vector<std::string> columns;
  std::stringstream stream(line);
  for (std::string column; std::getline(stream, column, '|');) columns.push_back(trimmed(column));
  return columns;
}

// Every case of golden/cases.txt; a malformed line fails the calling test with its number.
inline std::vector<GoldenCase> read_golden_cases() {
  std::ifstream file(test::source_path("golden/cases.txt"));
  REQUIRE_MESSAGE(file, "cannot read golden/cases.txt");
  std::vector<GoldenCase> cases;
  int line_number = 0;
  for (std::string line; std::getline(file, line);) {
    ++line_number;
    std::string content = trimmed(line);
    if (content.empty() || content[0] == '#') continue;
    std::vector<std::string> columns = split_columns(content);
    INFO("golden/cases.txt:" << line_number);
    REQUIRE(columns.size() == 6);
    GoldenCase golden{columns[0], columns[1], columns[2], columns[3],
                      std::stoi(columns[4]), std::stoi(columns[5])};
    REQUIRE((golden.check == "threshold" || golden.check == "z-test"));
    if (golden.check == "threshold") REQUIRE(golden.golden_spp == golden.test_spp);
    cases.push_back(golden);
  }
  return cases;
}

using test::quoted;

// `radiant render` arguments of the test render of `golden` for `scene` (the asset itself or a
// deliberately changed copy), written to `output` with `threads` worker threads.
inline std::string test_render_args(const GoldenCase& golden, const std::filesystem::path& scene,
                                    const std::filesystem::path& output, int threads) {
  bool z_test = golden.check == "z-test";
  return "render " + quoted(scene) + " -o " + quoted(output) + " " + golden.flags +
         " --spp " + std::to_string(golden.test_spp) +
         " --seed " + std::to_string(z_test ? z_test_seed : golden_seed) +
         (z_test ? " --aov variance" : "") + " --threads " + std::to_string(threads) + " --quiet";
}

// `radiant compare` arguments checking `render` against the golden of `golden`.
inline std::string compare_args(const GoldenCase& golden, const std::filesystem::path& render) {
  return "compare " + quoted(render) + " " +
         quoted(test::source_path("golden/" + golden.name + ".exr")) + " " +
         (golden.check == "z-test" ? z_test_compare_flags : threshold_compare_flags);
}

}  // namespace radiant::golden
