// Every input that once crashed a fuzzer (tests/fuzz/regressions/TARGET/, docs/hardening.md) runs
// again through its target's own entry point, in a folder set up like the harnesses': it is
// accepted or refused with one line, and a load error names a file in that folder. The seeds run
// too, so a harness that no longer reaches past its first error is noticed here, not in CI's
// fuzz phase.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/fuzz_folder.h"
#include "fuzz/fuzz_targets.h"
#include "support/test_support.h"

using namespace radiant;

namespace {

// The files of `folder` (none if it does not exist), sorted so failures read the same on every run.
std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(folder))
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Runs `input` through `target` in a fresh fuzz folder and checks the outcome's message.
fuzz::FuzzOutcome replay(const fuzz::FuzzTarget& target, const std::filesystem::path& input) {
  test::ScratchDir folder("fuzz-replay");
  fuzz::fill_fuzz_folder(folder.path, RADIANT_SOURCE_DIR);
  fuzz::FuzzOutcome outcome = target.run(folder.path, test::read_bytes(input));
  INFO(target.name << " target, " << input.filename().string() << ": " << outcome.message);
  CHECK(outcome.message.find('\n') == std::string::npos);
  if (outcome.refusal == fuzz::Refusal::load) CHECK(outcome.message.rfind(folder.path.string() + "/", 0) == 0);
  return outcome;
}

}  // namespace

TEST_CASE("inputs that once crashed a fuzzer are accepted or refused in one line by their target") {
  std::filesystem::path regressions = test::source_path("tests/fuzz/regressions");
  size_t replayed = 0;
  for (const fuzz::FuzzTarget& target : fuzz::fuzz_targets())
    for (const std::filesystem::path& input : files_in(regressions / target.name)) replay(target, input), ++replayed;
  CHECK(replayed > 0);
  // Every folder there is named for a target, so no regression input is silently skipped.
  for (const auto& entry : std::filesystem::directory_iterator(regressions))
    if (entry.is_directory())
      CHECK_MESSAGE(fuzz::find_fuzz_target(entry.path().filename().string()),
                    entry.path().filename().string() << " names no fuzz target");
}

TEST_CASE("every fuzz target accepts some of its seeds and survives all of them") {
  for (const fuzz::FuzzTarget& target : fuzz::fuzz_targets()) {
    std::vector<std::filesystem::path> seeds = files_in(test::source_path("tests/fuzz/corpus") / target.name);
    CHECK_MESSAGE(!seeds.empty(), target.name << " has no seeds");
    size_t accepted = 0;
    for (const std::filesystem::path& seed : seeds) accepted += replay(target, seed).refusal == fuzz::Refusal::none;
    CHECK_MESSAGE(accepted > 0, target.name << " accepts none of its seeds");
  }
}
