// The folder a fuzzed input sits in, holding the files the seed corpora refer to (an OBJ for
// `@mesh file mesh.obj`, a glTF buffer and a PNG texture, and two scenes for batch scripts and
// environment maps) so fuzzing gets past "no such file". The harnesses and the regression tests
// both use it, so a finding reproduces the same way.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <string>

namespace radiant::fuzz {

// Copies the referenced files from the source tree `source_dir` into `folder`.
inline void fill_fuzz_folder(const std::filesystem::path& folder, const std::filesystem::path& source_dir) {
  const auto overwrite = std::filesystem::copy_options::overwrite_existing;
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(source_dir / "tests/fuzz/mesh.obj", folder / "mesh.obj", overwrite);
  std::filesystem::copy_file(source_dir / "assets/models/checker-cube.bin", folder / "checker-cube.bin", overwrite);
  std::filesystem::copy_file(source_dir / "assets/models/checker.png", folder / "checker.png", overwrite);
  std::filesystem::copy_file(source_dir / "assets/models/checker-cube.gltf", folder / "checker-cube.gltf", overwrite);
  std::filesystem::copy_file(source_dir / "assets/first-render.scene", folder / "first-render.scene", overwrite);
}

// A filled per-process temp folder, removed at exit.
struct FuzzFolder {
  std::filesystem::path path;
  explicit FuzzFolder(const std::string& tag)
      : path(std::filesystem::temp_directory_path() / ("radiant-fuzz-" + tag + "-" + std::to_string(getpid()))) {
    fill_fuzz_folder(path, RADIANT_SOURCE_DIR);
  }
  ~FuzzFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

// Loads are limited far below libFuzzer's 2 GB RSS limit, so a large declared size is refused,
// not an out-of-memory finding.
constexpr size_t fuzz_memory_limit = size_t(64) << 20;

}  // namespace radiant::fuzz
