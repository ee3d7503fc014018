// The batch target: the bytes as a `radiant batch` script in the fuzz folder, parsed by the
// command's own parser (CLI11 converts its numbers, under UBSan here), then run as the command
// runs it (cli::run_script), each view shrunk to a tiny render whose outputs stay in the folder.
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

}  // namespace

FuzzOutcome run_batch_target(const fs::path& folder, const std::string& bytes) {
  InputFiles files(folder);
  fs::path script = files.write("fuzz.batch", bytes);
  fs::path outputs = files.output_folder("batch-outputs");
  return outcome_of([&] {
    std::ifstream in(script);
    cli::BatchSettings settings;
    settings.log_level = cli::LogLevel::error;
    settings.max_memory_bytes = fuzz_memory_limit;
    settings.adjust_job = [&](cli::RenderJob job) { return tiny_job(std::move(job), outputs); };
    cli::run_script(cli::parse_script(in, script.string(), folder), script.string(), settings);
  });
}

}  // namespace radiant::fuzz
