// The fuzz targets (docs/hardening.md): each takes one input's bytes, writes them as files into
// a fuzz folder (fuzz_folder.h) and runs them through radiant as the CLI would. libFuzzer
// (fuzz_main.cpp) and the regression test (tests/fuzz_regressions/) call the same functions, so a
// finding replays exactly as it was found.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace radiant::fuzz {

// How radiant answered an input. A crash, a sanitizer report or an exception other than those
// the CLI reports as an error escapes instead: that is a finding.
enum class Refusal {
  none,  // accepted (loaded, rendered, read)
  load,  // a LoadError, which names the file and the place
  other  // any other error the CLI reports in one line (render settings, image files, scripts)
};
struct FuzzOutcome {
  Refusal refusal = Refusal::none;
  std::string message;
};

struct FuzzTarget {
  const char* name;  // the harness is fuzz_NAME; seeds in corpus/NAME, findings in regressions/NAME
  FuzzOutcome (*run)(const std::filesystem::path& folder, const std::string& bytes);
};

// The obj target's input is up to three files, in this order, split at this line: fuzz.obj,
// fuzz.mtl and texture.png (whatever image bytes follow; the readers go by content).
constexpr std::string_view obj_part_separator = "\n#--8<--\n";

// The targets (one file each under tests/fuzz/); `folder` is filled by fill_fuzz_folder.
FuzzOutcome run_scene_target(const std::filesystem::path& folder, const std::string& bytes);
FuzzOutcome run_gltf_target(const std::filesystem::path& folder, const std::string& bytes);
FuzzOutcome run_render_target(const std::filesystem::path& folder, const std::string& bytes);
FuzzOutcome run_obj_target(const std::filesystem::path& folder, const std::string& bytes);
FuzzOutcome run_batch_target(const std::filesystem::path& folder, const std::string& bytes);
FuzzOutcome run_image_target(const std::filesystem::path& folder, const std::string& bytes);
// The page target's input is a raw HTTP request stream to --serve's page.
FuzzOutcome run_page_target(const std::filesystem::path& folder, const std::string& bytes);

// Every target, in the order scripts/fuzz.sh runs them.
const std::vector<FuzzTarget>& fuzz_targets();

// The target called `name`, or null.
const FuzzTarget* find_fuzz_target(const std::string& name);

}  // namespace radiant::fuzz
