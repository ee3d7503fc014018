// The batch target: the bytes as a `radiant batch` script in the fuzz folder, parsed by the
// command's own parser (CLI11 converts its numbers, under UBSan here), then run as the command
// runs it, each view shrunk to a tiny render whose outputs stay in the folder.
#include <algorithm>
#include <fstream>
#include <memory>

#include "batch_script.h"
#include "fuzz_folder.h"
#include "fuzz_support.h"
#include "image/image_io.h"
#include "load_scene.h"

namespace radiant::fuzz {

namespace {

namespace fs = std::filesystem;

// The script's view at 8x8 (or smaller), 1 sample per pixel, one thread, writing into `outputs`
// whatever paths the script named; every other setting as the script says.
cli::RenderJob tiny_job(cli::RenderJob job, const fs::path& outputs) {
  RenderOptions& options = job.options;
  options.width = std::min(options.width.value_or(tiny_image_size), tiny_image_size);
  options.height = std::min(options.height.value_or(tiny_image_size), tiny_image_size);
  options.spp = 1;
  options.threads = 1;
  options.quiet = true;
  job.output = (outputs / ("image" + lowercase_extension(job.output))).string();
  if (!job.stats_path.empty()) job.stats_path = (outputs / "stats.json").string();
  return job;
}

// The steps as batch_main runs them: a scene line loads, a render line renders the last scene.
void run_steps(const std::vector<cli::BatchStep>& steps, const fs::path& outputs) {
  std::unique_ptr<SceneDesc> scene;
  std::unique_ptr<PreparedScene> prepared;
  std::string scene_path;
  for (const cli::BatchStep& step : steps) {
    if (!step.scene.empty()) {
      LoadOptions options;
      options.max_memory_bytes = fuzz_memory_limit;
      prepared.reset();
      scene = std::make_unique<SceneDesc>(load_scene(step.scene, options));
      prepared = std::make_unique<PreparedScene>(prepare_scene(*scene));
      scene_path = step.scene;
      continue;
    }
    cli::PhaseTimes times;
    cli::run_render_job(scene_path, *prepared, tiny_job(step.job, outputs), times);
  }
}

}  // namespace

FuzzOutcome run_batch_target(const fs::path& folder, const std::string& bytes) {
  InputFiles files(folder);
  fs::path script = files.write("fuzz.batch", bytes);
  fs::path outputs = files.output_folder("batch-outputs");
  return outcome_of([&] {
    std::ifstream in(script);
    run_steps(cli::parse_script(in, script.string(), folder), outputs);
  });
}

}  // namespace radiant::fuzz
