// Every input the fuzzers once crashed on (tests/fuzz/regressions/, docs/hardening.md) now loads
// or fails with one LoadError naming the file, in the same folder the harnesses fuzz in.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/fuzz_folder.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;

// The regression inputs, sorted so failures read the same on every run.
static std::vector<std::filesystem::path> regression_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("tests/fuzz/regressions")))
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// "(loaded)" or the LoadError message; anything else thrown escapes and fails the test.
static std::string load_outcome(const std::filesystem::path& file) {
  LoadOptions options;
  options.max_memory_bytes = fuzz::fuzz_memory_limit;
  try {
    load_scene(file.string(), options);
  } catch (const LoadError& error) {
    return error.what();
  }
  return "(loaded)";
}

TEST_CASE("inputs that once crashed a fuzzer load or fail with a LoadError naming the file") {
  std::vector<std::filesystem::path> files = regression_files();
  REQUIRE(!files.empty());
  for (const std::filesystem::path& original : files) {
    test::ScratchDir folder("fuzz-regression");
    fuzz::fill_fuzz_folder(folder.path, RADIANT_SOURCE_DIR);
    std::filesystem::path file = folder.file(original.filename().string());
    std::filesystem::copy_file(original, file);
    std::string outcome = load_outcome(file);
    INFO(original.filename().string() << ": " << outcome);
    bool names_the_file = outcome.rfind(file.string() + ":", 0) == 0;
    CHECK((outcome == "(loaded)" || names_the_file));
  }
}
