// What the fuzz targets share: the files one input writes, turning radiant's errors into an
// outcome, and the tiny render that sends a loaded scene through Embree and both integrators.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_targets.h"
#include "scene/scene_desc.h"

namespace radiant::fuzz {

// The files one input writes into the fuzz folder, removed when it is done, so that no input
// sees what another left behind and every finding replays alone.
class InputFiles {
 public:
  explicit InputFiles(std::filesystem::path folder) : folder_(std::move(folder)) {}
  InputFiles(const InputFiles&) = delete;
  InputFiles& operator=(const InputFiles&) = delete;
  ~InputFiles();
  // Writes `bytes` to `name` in the folder; returns its path.
  std::filesystem::path write(const std::string& name, std::string_view bytes);
  // A fresh empty folder `name` for outputs, removed with the rest.
  std::filesystem::path output_folder(const std::string& name);

 private:
  std::filesystem::path folder_;
  std::vector<std::filesystem::path> written_;
};

// Runs `attempt`; the errors the CLI reports in one line become the outcome, anything else escapes.
FuzzOutcome outcome_of(const std::function<void()>& attempt);

// The image size and samples of every fuzzed render: enough to trace every kind of ray.
constexpr int tiny_image_size = 8;

// Renders `scene` at 8x8, 1 sample per pixel, on one thread, once with the Whitted and once with
// the path integrator, with every AOV, under `environment_map` when not empty.
void render_tiny(const SceneDesc& scene, const std::string& environment_map = "");

}  // namespace radiant::fuzz
