#include "render_job.h"

#include <algorithm>
#include <chrono>
#include <iostream>

#include "interrupts.h"
#include "option_parsing.h"
#include "output/output_set.h"
#include "shard_output.h"

namespace radiant::cli {

std::vector<NamedFile> render_job_outputs(const RenderJob& job) {
  std::vector<NamedFile> outputs = {{"-o", job.output}};
  if (!job.stats_path.empty()) outputs.push_back({"--stats", job.stats_path});
  return outputs;
}

std::string out_of_memory_message(const std::string& scene_path, const std::string& doing, const MemoryBudget& budget) {
  return scene_path + ": out of memory while " + doing + " (the memory limit is " + format_bytes(budget.limit()) +
         "; a --max-memory below what this machine can give refuses such work before it allocates)";
}

void check_render_job_outputs(const RenderJob& job) {
  check_image_output(job.output);
  for (const NamedFile& output : render_job_outputs(job)) check_output_place(output.path);
}

namespace {

// The image to write: what the film holds, marked partial when a signal stopped the render, and
// in a float format with the per-pixel sample counts, which say how far each pixel got.
OutputImage output_image(const RenderJob& job, const RenderResult& result) {
  std::vector<std::string> aovs = job.options.aovs;
  bool partial = result.stats.interrupted;
  if (partial && is_float_format(job.output) && std::find(aovs.begin(), aovs.end(), "spp") == aovs.end())
    aovs.push_back("spp");
  OutputImage image = film_to_image(result.film, aovs);
  if (partial) image.metadata.emplace_back("radiant:partial", std::string("interrupted by ") + signal_name(interrupt_signal()));
  return image;
}

}  // namespace

void run_render_job(const std::string& scene_path, PreparedScene& prepared, const RenderJob& job, PhaseTimes& times) {
  using Clock = std::chrono::steady_clock;
  DeferredInterrupts deferred;  // a signal stops the render; what it rendered is still written
  RenderOptions options = job.options;
  options.stop_request = &interrupt_signal();
  check_outputs_spare_scene_files(prepared.scene->input_files, render_job_outputs(job));
  prepare_view(prepared, job.options);
  times.build = prepared.build_seconds;
  if (job.skip_existing &&
      shard_already_rendered(job.output, make_shard_info(prepared, resolve_settings(prepared, options), options))) {
    if (!job.options.quiet) std::cerr << "radiant: " << job.output << " already holds this shard, complete; skipped\n";
    return;
  }
  RenderResult result = render_prepared(prepared, options);
  if (result.stats.interrupted && result.stats.samples == 0) throw_if_interrupted();  // nothing to save
  times.render = result.stats.render_seconds;
  const ResolvedSettings& s = result.settings;
  if (!job.options.quiet) {
    if (s.camera_framed) std::cerr << "radiant: the scene has no camera; using one that frames the whole scene\n";
    if (!s.mode_reason.empty()) std::cerr << "radiant: mode " << mode_name(s.mode) << ": " << s.mode_reason << "\n";
  }
  auto write_start = Clock::now();
  OutputSet outputs;
  if (writes_shard(options)) {
    ShardInfo info = make_shard_info(prepared, s, options);
    if (result.stats.interrupted) info.partial = std::string("interrupted by ") + signal_name(interrupt_signal());
    write_shard(outputs.create(job.output), result.film, info, options.memory);
  } else {
    write_image(outputs.create(job.output), output_image(job, result));
  }
  times.write = std::chrono::duration<double>(Clock::now() - write_start).count();
  if (!job.stats_path.empty())
    outputs.create(job.stats_path).write(render_stats_json(scene_path, job.output, result, times));
  outputs.commit();
  if (!job.options.quiet) std::cerr << "radiant: " << render_summary(job.output, result, times) << "\n";
  if (int signal = interrupt_signal())
    std::cerr << "radiant: interrupted by " << signal_name(signal) << "; wrote " << job.output
              << (result.stats.interrupted ? " with what was rendered, marked partial\n" : "\n");
  throw_if_interrupted();
}

}  // namespace radiant::cli
